//! The workbench's pixel pictures at 100×30 cells of 10×20 pixels (a 1000×580 picture): an orbit
//! step (the preview the terminal scales, or sixel's one pass) against the frame budget, the
//! settled picture's time and bytes per protocol, the encoders alone, and chafa's kitty and sixel
//! output of the same settled pixels, measured in the same run.
//! Run: `cargo bench --bench pixel_graphics`.

use base64::Engine;
use bumpwork::measure::Timing;
use bumpwork::term::ColorMode;
use bumpwork::term::graphics::Protocol;
use bumpwork::tui::{Action, App, PixelRoute, Screen, WorkbenchOptions};
use std::io::Read;
use std::process::Command;

const COLS: u16 = 100;
const ROWS: u16 = 30;
const CELL: (u32, u32) = (10, 20);
const SCENE: &str = "sphere-on-plane-dimples";
const RUNS: usize = 15;
/// The workbench's animation frame interval at its default 30 frames a second.
const FRAME_BUDGET_MS: f64 = 1000.0 / 30.0;

fn app(protocol: Protocol) -> (App, Screen) {
    let options = WorkbenchOptions {
        scenes: vec![SCENE.into()],
        watch: false,
        ..WorkbenchOptions::default()
    };
    let mut app = App::new(&options, ColorMode::TrueColor).expect("built-in scene");
    app.set_graphics(Some(protocol));
    let mut screen = Screen::new(COLS, ROWS);
    screen.set_pixel_route(route(false), &mut app);
    (app, screen)
}

/// Draws and refines until settled; returns the bytes of the last picture sent.
fn settle(app: &mut App, screen: &mut Screen) -> Vec<u8> {
    let mut out = Vec::new();
    screen.draw(app, &mut out).unwrap();
    let mut last = Vec::new();
    while screen.refining(app) {
        let mut pass = Vec::new();
        screen.refine(app, &mut pass).unwrap();
        if !pass.is_empty() {
            last = pass;
        }
    }
    last
}

fn ms(t: &Timing) -> String {
    let f = |d: std::time::Duration| d.as_secs_f64() * 1e3;
    format!("{:.1} ms ({:.1}–{:.1})", f(t.median), f(t.min), f(t.max))
}

fn main() {
    let (w, h) = (COLS as u32 * CELL.0, (ROWS as u32 - 1) * CELL.1);
    println!(
        "{SCENE}, {COLS}x{ROWS} cells of {}x{} px: a {w}x{h} picture, {RUNS} runs",
        CELL.0, CELL.1
    );
    let mut settled_rgb = Vec::new();
    for &protocol in Protocol::ALL {
        let (mut app, mut screen) = app(protocol);
        settle(&mut app, &mut screen);
        let mut step_bytes = Vec::new();
        let step = Timing::measure(2, RUNS, || {
            app.apply(Action::Orbit(10.0, 0.0));
            let mut out = Vec::new();
            screen.draw(&mut app, &mut out).unwrap();
            step_bytes.push(out.len());
        });
        step_bytes.sort();
        let mut settled = Vec::new();
        let settling = Timing::measure(0, 5, || {
            app.apply(Action::Orbit(10.0, 0.0));
            settled = settle(&mut app, &mut screen);
        });
        let within = step.median.as_secs_f64() * 1e3 <= FRAME_BUDGET_MS;
        println!(
            "{:<7} orbit step {} {:>8} B ({} the {FRAME_BUDGET_MS:.0} ms frame budget); settled in {} (render and encode of 64 passes), {} B",
            protocol.name(),
            ms(&step),
            step_bytes[step_bytes.len() / 2],
            if within { "within" } else { "over" },
            ms(&settling),
            settled.len()
        );
        if protocol == Protocol::Kitty {
            settled_rgb = kitty_rgb(&settled);
        }
    }
    encoders(&settled_rgb, (w, h));
    chafa(&settled_rgb, (w, h));
}

/// The last kitty image in `bytes`, decoded.
fn kitty_rgb(bytes: &[u8]) -> Vec<u8> {
    let text = String::from_utf8_lossy(bytes);
    let payload: String = text
        .split("\x1b_G")
        .skip(1)
        .filter_map(|c| {
            c.split("\x1b\\")
                .next()?
                .split_once(';')
                .map(|(_, p)| p.to_string())
        })
        .collect();
    let compressed = base64::engine::general_purpose::STANDARD
        .decode(payload)
        .unwrap();
    let mut rgb = Vec::new();
    flate2::read::ZlibDecoder::new(&compressed[..])
        .read_to_end(&mut rgb)
        .unwrap();
    rgb
}

/// Each encoder alone on the settled picture.
fn encoders(rgb: &[u8], size: (u32, u32)) {
    for &protocol in Protocol::ALL {
        let mut bytes = 0;
        let time = Timing::measure(1, RUNS, || {
            bytes = protocol
                .encode(rgb, size, (COLS, ROWS - 1))
                .iter()
                .map(Vec::len)
                .sum();
        });
        let per_pixel = bytes as f64 / f64::from(size.0 * size.1);
        println!(
            "encode  {:<7} {} {bytes:>8} B: {per_pixel:.2} B a pixel",
            protocol.name(),
            ms(&time)
        );
    }
}

/// chafa's kitty and sixel output of the same pixels stretched over the same cells (wall time,
/// process start and PNG decoding included; chafa picks its own pixel size for the cells).
fn chafa(rgb: &[u8], (w, h): (u32, u32)) {
    let temp = tempfile::tempdir().expect("a temporary directory");
    let path = temp.path().join("picture.png");
    let file = std::fs::File::create(&path).unwrap();
    let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), w, h);
    encoder.set_color(png::ColorType::Rgb);
    encoder
        .write_header()
        .unwrap()
        .write_image_data(rgb)
        .unwrap();
    for format in ["kitty", "sixels"] {
        let mut bytes = 0;
        let mut size = String::new();
        let mut failed = None;
        let time = Timing::measure(1, 5, || {
            let output = Command::new("chafa")
                .args(["-f", format, "--animate", "off", "--stretch", "--size"])
                .arg(format!("{COLS}x{}", ROWS - 1))
                .arg(&path)
                .output();
            match output {
                Ok(o) if o.status.success() => {
                    bytes = o.stdout.len();
                    size = picture_size(&o.stdout);
                }
                Ok(o) => failed = Some(String::from_utf8_lossy(&o.stderr).into_owned()),
                Err(e) => failed = Some(e.to_string()),
            }
        });
        match failed {
            None => println!(
                "chafa   {format:<7} {} {bytes:>8} B, a {size} picture: {:.2} B a pixel",
                ms(&time),
                bytes as f64 / pixels_of(&size)
            ),
            Some(why) => println!("chafa   {format:<7} not measured: {}", why.trim()),
        }
    }
}

/// The picture size a kitty (`s=`, `v=`) or sixel (`"1;1;W;H`) sequence declares.
fn picture_size(bytes: &[u8]) -> String {
    let text = String::from_utf8_lossy(bytes);
    let key = |name: &str| {
        text.split([',', ';'])
            .find_map(|kv| kv.strip_prefix(name))
            .map(str::to_string)
    };
    if let (Some(w), Some(h)) = (key("s="), key("v=")) {
        return format!("{w}x{h}");
    }
    let raster = text.split('"').nth(1).unwrap_or("");
    let numbers: Vec<&str> = raster.split(';').take(4).collect();
    match numbers[..] {
        [_, _, w, h] => format!(
            "{w}x{}",
            h.split(|c: char| !c.is_ascii_digit()).next().unwrap_or("")
        ),
        _ => "unknown-size".into(),
    }
}

fn pixels_of(size: &str) -> f64 {
    let mut sides = size
        .split('x')
        .map(|s| s.parse::<f64>().unwrap_or(f64::NAN));
    sides.next().unwrap_or(f64::NAN) * sides.next().unwrap_or(f64::NAN)
}

/// Pixels of `CELL` a cell, through tmux or not.
fn route(through_tmux: bool) -> PixelRoute {
    PixelRoute {
        through_tmux,
        cell_pixels: CELL,
        sixel_limit: None,
    }
}
