//! The workbench in real terminals under Xvfb: kitty (its graphics protocol) and xterm as a
//! VT340 (sixel), each screenshot with xwd; the picture found on the screen is compared with a
//! still of the same view. tmux without passthrough gets blocks and says why. Skipped, with the
//! reason printed, where the programs are missing (`.ci/run` installs them).

use crate::graphics_support::psnr;
use crate::tmux_support::{Tmux, missing};
use std::path::Path;
use std::process::Command;

const COLS: usize = 100;
const ROWS: usize = 30;
const SCENE: &str = "sphere-on-plane-dimples";

/// A screenshot: width, height and RGB.
struct Shot {
    width: usize,
    height: usize,
    rgb: Vec<u8>,
}

/// Reads an xwd dump (ZPixmap, 24 or 32 bits a pixel, as Xvfb makes them).
fn read_xwd(bytes: &[u8]) -> Shot {
    let field = |i: usize| u32::from_be_bytes(bytes[i * 4..i * 4 + 4].try_into().unwrap()) as usize;
    let (header, width, height) = (field(0), field(4), field(5));
    let (bits_per_pixel, bytes_per_line, colours) = (field(11), field(12), field(19));
    let little_endian = field(7) == 0;
    let start = header + colours * 12;
    let step = bits_per_pixel / 8;
    let mut rgb = Vec::with_capacity(width * height * 3);
    for y in 0..height {
        for x in 0..width {
            let at = start + y * bytes_per_line + x * step;
            let px = &bytes[at..at + step];
            let (r, g, b) = match little_endian {
                true => (px[2], px[1], px[0]),
                false => (px[step - 3], px[step - 2], px[step - 1]),
            };
            rgb.extend_from_slice(&[r, g, b]);
        }
    }
    Shot { width, height, rgb }
}

impl Shot {
    /// The terminal window: the box of every pixel that is not the root window's black.
    fn window(&self) -> (usize, usize) {
        let lit = |x: usize, y: usize| {
            let at = (y * self.width + x) * 3;
            self.rgb[at..at + 3] != [0, 0, 0]
        };
        let right = (0..self.width)
            .rev()
            .find(|&x| (0..self.height).any(|y| lit(x, y)));
        let bottom = (0..self.height)
            .rev()
            .find(|&y| (0..self.width).any(|x| lit(x, y)));
        (right.map_or(0, |x| x + 1), bottom.map_or(0, |y| y + 1))
    }

    fn crop(&self, width: usize, height: usize) -> Vec<u8> {
        (0..height)
            .flat_map(|y| self.rgb[y * self.width * 3..(y * self.width + width) * 3].to_vec())
            .collect()
    }
}

/// Runs `terminal` (a shell command that starts the workbench in a window at the top left)
/// under Xvfb, waits `seconds` for the picture to settle and takes a screenshot.
fn screenshot(terminal: &str, seconds: u32, dir: &Path) -> Shot {
    let shot = dir.join("shot.xwd");
    let script = format!(
        "{terminal} & sleep {seconds}; xwd -root -silent > {}; kill $! 2>/dev/null; wait",
        shot.display()
    );
    let output = Command::new("timeout")
        .args([
            "120",
            "xvfb-run",
            "-a",
            "-s",
            "-screen 0 1280x800x24",
            "sh",
            "-c",
            &script,
        ])
        .env("LIBGL_ALWAYS_SOFTWARE", "1")
        .env_remove("TMUX")
        .output()
        .unwrap();
    let bytes = std::fs::read(&shot).unwrap_or_else(|e| {
        panic!(
            "no screenshot ({e}): {}",
            String::from_utf8_lossy(&output.stderr)
        )
    });
    read_xwd(&bytes)
}

/// The picture on `shot` (all rows of the window but the status line's) against a still of
/// the same view at its size: PSNR in dB.
fn picture_against_still(shot: &Shot) -> f64 {
    let (width, height) = shot.window();
    assert!(
        width >= COLS && height >= ROWS,
        "a window of {width}x{height}"
    );
    let (cell_w, cell_h) = (width / COLS, height / ROWS);
    let picture = (COLS * cell_w, (ROWS - 1) * cell_h);
    let expected = crate::graphics_support::settled_still(SCENE, picture);
    psnr(&expected, &shot.crop(picture.0, picture.1))
}

/// With `BUMPWORK_SAVE_SHOTS=DIR`, writes the terminal window of `shot` to
/// `DIR/workbench-NAME.png` (how the README's picture of the workbench in pixels is made).
fn save_if_asked(shot: &Shot, name: &str) {
    let Some(dir) = std::env::var_os("BUMPWORK_SAVE_SHOTS") else {
        return;
    };
    let (width, height) = shot.window();
    let slug: String = name
        .chars()
        .map(|c| if c.is_ascii_alphanumeric() { c } else { '-' })
        .collect();
    let path = Path::new(&dir).join(format!("workbench-{slug}.png"));
    let file = std::fs::File::create(&path).unwrap();
    let mut encoder = png::Encoder::new(std::io::BufWriter::new(file), width as u32, height as u32);
    encoder.set_color(png::ColorType::Rgb);
    let mut writer = encoder.write_header().unwrap();
    writer.write_image_data(&shot.crop(width, height)).unwrap();
}

/// The workbench in the terminal `command` starts (it names the binary with `{bumpwork}`),
/// when `tools` are there: its settled picture against the still, at least `bound` dB.
fn shows_the_picture(name: &str, tools: &[&str], command: &str, bound: f64) {
    if let Some(reason) = missing(tools) {
        eprintln!("skipped: {reason}");
        return;
    }
    let dir = tempfile::tempdir().unwrap();
    let command = command.replace("{bumpwork}", env!("CARGO_BIN_EXE_bumpwork"));
    let shot = screenshot(&format!("{command} view {SCENE}"), 8, dir.path());
    save_if_asked(&shot, name);
    let db = picture_against_still(&shot);
    eprintln!("{name}: {db:.1} dB against the still");
    assert!(db >= bound, "{name}'s picture is {db:.1} dB from the still");
}

#[test]
fn kitty_shows_the_picture_in_its_own_pixels() {
    let kitty = format!(
        "kitty --config NONE -o font_size=10 -o remember_window_size=no \
         -o initial_window_width={COLS}c -o initial_window_height={ROWS}c \
         -o window_padding_width=0 -o placement_strategy=top-left -o enable_audio_bell=no \
         {{bumpwork}}"
    );
    shows_the_picture("kitty", &["xvfb-run", "kitty", "xwd"], &kitty, 40.0);
}

#[test]
fn xterm_as_a_vt340_shows_the_picture_in_sixels() {
    let xterm = format!(
        "xterm -ti vt340 -xrm 'XTerm*numColorRegisters: 256' -geometry {COLS}x{ROWS}+0+0 \
         -bw 0 -b 0 -fa Monospace -fs 10 -e {{bumpwork}}"
    );
    shows_the_picture("xterm sixel", &["xvfb-run", "xterm", "xwd"], &xterm, 30.0);
}

#[test]
fn kitty_through_tmux_with_passthrough_shows_the_picture_in_pixels() {
    let dir = tempfile::tempdir().unwrap();
    let conf = dir.path().join("tmux.conf");
    std::fs::write(&conf, "set -g allow-passthrough on\nset -g status off\n").unwrap();
    let socket = format!("bumpwork-kitty-{}", std::process::id());
    let _server = TmuxServer(socket.clone());
    let kitty = format!(
        "kitty --config NONE -o font_size=10 -o remember_window_size=no \
         -o initial_window_width={COLS}c -o initial_window_height={ROWS}c \
         -o window_padding_width=0 -o placement_strategy=top-left -o enable_audio_bell=no \
         tmux -L {socket} -f {} new-session {{bumpwork}}",
        conf.display()
    );
    let tools = ["xvfb-run", "kitty", "xwd", "tmux"];
    shows_the_picture("kitty through tmux", &tools, &kitty, 40.0);
}

/// A tmux server of the test's own socket, ended however the test ends.
struct TmuxServer(String);

impl Drop for TmuxServer {
    fn drop(&mut self) {
        let _ = Command::new("tmux")
            .args(["-L", &self.0, "kill-server"])
            .output();
    }
}

#[test]
fn tmux_without_passthrough_gets_blocks_and_says_why() {
    if let Some(reason) = missing(&["tmux"]) {
        eprintln!("skipped: {reason}");
        return;
    }
    let command = format!("{} view {SCENE}", env!("CARGO_BIN_EXE_bumpwork"));
    let tmux = Tmux::start("graphics", 160, 30, &command);
    tmux.run(&["set-option", "-g", "allow-passthrough", "off"]);
    let screen = tmux.wait_for("the first frame", |s| s.contains("blocks"));
    assert!(
        screen.contains("blocks (inside tmux without allow-passthrough"),
        "{screen}"
    );
    assert!(screen.contains('▀'), "the picture in half blocks");
}
