//! The workbench in real terminals under Xvfb: kitty (its graphics protocol) and xterm as a
//! VT340 (sixel), each screenshot with xwd every second until the picture has settled; the
//! picture found on the screen is compared with a still of the same view. tmux without
//! passthrough gets blocks and says why; inside tmux the colours are what tmux says. Skipped,
//! with the reason printed, where the programs are require (`.ci/run` installs them).

use crate::graphics_support::psnr;
use crate::pty_support::Session;
use crate::tmux_support::{Tmux, require};
use portable_pty::CommandBuilder;
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

/// How long a terminal may take to show a settled picture (software OpenGL on a loaded
/// machine is slow); a screenshot is taken every second until then.
const LONGEST_SECONDS: u32 = 60;

/// Held while an X server runs: `xvfb-run -a` picks a free display number by looking, so two
/// started at once can pick the same one and each screenshot then shows both terminals.
static ONE_X_SERVER_AT_A_TIME: std::sync::Mutex<()> = std::sync::Mutex::new(());

/// Runs `terminal` (a shell command that starts the workbench in a window at the top left)
/// under Xvfb and takes a screenshot every second until one is the same as the one before and
/// `good` accepts it, or `LONGEST_SECONDS` pass: the last screenshot taken.
fn screenshot_until(terminal: &str, dir: &Path, good: impl Fn(&Shot) -> bool) -> Shot {
    let _x_server = ONE_X_SERVER_AT_A_TIME
        .lock()
        .unwrap_or_else(|poisoned| poisoned.into_inner());
    let (stop, shots) = (dir.join("stop"), dir.join("shots"));
    std::fs::create_dir_all(&shots).unwrap();
    let script = format!(
        "{terminal} & i=0; while [ ! -e {stop} ] && [ $i -lt {LONGEST_SECONDS} ]; do sleep 1; \
         i=$((i+1)); xwd -root -silent > {shots}/next && mv {shots}/next {shots}/$i.xwd; done; \
         kill $! 2>/dev/null; wait",
        stop = stop.display(),
        shots = shots.display(),
    );
    let stderr = std::fs::File::create(dir.join("stderr")).unwrap();
    let mut xvfb = Command::new("timeout")
        .args(["120", "xvfb-run", "-a", "-s", "-screen 0 1280x800x24"])
        .args(["sh", "-c", &script])
        .env("LIBGL_ALWAYS_SOFTWARE", "1")
        .env_remove("TMUX")
        .stdout(std::process::Stdio::null())
        .stderr(stderr)
        .spawn()
        .unwrap();
    let mut last = None;
    for taken in 1.. {
        let path = shots.join(format!("{taken}.xwd"));
        while !path.exists() && xvfb.try_wait().unwrap().is_none() {
            std::thread::sleep(std::time::Duration::from_millis(100));
        }
        let Ok(bytes) = std::fs::read(&path) else {
            break;
        };
        let _ = std::fs::remove_file(&path);
        let shot = read_xwd(&bytes);
        let unchanged = last
            .as_ref()
            .is_some_and(|last: &Shot| last.rgb == shot.rgb);
        let done = unchanged && good(&shot);
        last = Some(shot);
        if done {
            break;
        }
    }
    std::fs::write(&stop, "").unwrap();
    let _ = xvfb.wait();
    last.unwrap_or_else(|| {
        let stderr = std::fs::read_to_string(dir.join("stderr")).unwrap_or_default();
        panic!("no screenshot: {stderr}")
    })
}

/// The picture on `shot` (all rows of the window but the status line's) against `still`, a
/// still of the same view at its size (rendered once, for the first open window): PSNR in dB,
/// or `None` while the window is not yet open.
fn picture_against_still(shot: &Shot, still: &std::cell::OnceCell<Vec<u8>>) -> Option<f64> {
    let (width, height) = shot.window();
    if width < COLS || height < ROWS {
        return None;
    }
    let (cell_w, cell_h) = (width / COLS, height / ROWS);
    let picture = (COLS * cell_w, (ROWS - 1) * cell_h);
    let expected = still.get_or_init(|| crate::graphics_support::settled_still(SCENE, picture));
    Some(psnr(expected, &shot.crop(picture.0, picture.1)))
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
/// which needs `tools`: its picture against the still, at least `bound` dB once settled.
fn shows_the_picture(name: &str, tools: &[&str], command: &str, bound: f64) {
    require(tools);
    let dir = tempfile::tempdir().unwrap();
    let command = command.replace("{bumpwork}", env!("CARGO_BIN_EXE_bumpwork"));
    let still = std::cell::OnceCell::new();
    let good = |shot: &Shot| picture_against_still(shot, &still).is_some_and(|db| db >= bound);
    let shot = screenshot_until(&format!("{command} view {SCENE}"), dir.path(), good);
    save_if_asked(&shot, name);
    let db = picture_against_still(&shot, &still);
    let (width, height) = shot.window();
    let db = db.unwrap_or_else(|| panic!("{name}: a window of {width}x{height}"));
    eprintln!("{name}: {db:.1} dB against the still");
    assert!(db >= bound, "{name}'s picture is {db:.1} dB from the still");
}

#[test]
#[ignore = "needs a real terminal under Xvfb (kitty, xterm, xwd); bash .ci/run installs them and runs the ignored tests"]
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
#[ignore = "needs a real terminal under Xvfb (kitty, xterm, xwd); bash .ci/run installs them and runs the ignored tests"]
fn xterm_as_a_vt340_shows_the_picture_in_sixels() {
    let xterm = format!(
        "xterm -ti vt340 -xrm 'XTerm*numColorRegisters: 256' -geometry {COLS}x{ROWS}+0+0 \
         -bw 0 -b 0 -fa Monospace -fs 10 -e {{bumpwork}}"
    );
    shows_the_picture("xterm sixel", &["xvfb-run", "xterm", "xwd"], &xterm, 40.0);
}

#[test]
#[ignore = "needs a real terminal under Xvfb (kitty, xterm, xwd); bash .ci/run installs them and runs the ignored tests"]
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
#[ignore = "needs tmux; bash .ci/run installs it and runs the ignored tests"]
fn tmux_without_passthrough_gets_blocks_and_says_why() {
    require(&["tmux"]);
    let command = format!("{} view {SCENE}", env!("CARGO_BIN_EXE_bumpwork"));
    let tmux = Tmux::start("graphics", 160, 30, &command);
    tmux.run(&["set-option", "-g", "allow-passthrough", "off"]);
    let screen = tmux.wait_for("the first frame", |s| s.contains("blocks, "));
    assert!(screen.contains('▀'), "the picture in half blocks");
    tmux.run(&["send-keys", "M"]);
    tmux.wait_for("why, in the message log", |s| {
        s.contains("picture: blocks (inside tmux without allow-passthrough")
    });
}

/// The workbench in tmux, whose client runs in a test pseudo-terminal that answers no queries,
/// so tmux knows of its terminal only what `TERM`'s terminfo and the tmux setting `conf_text`
/// say; the workbench's colours follow what tmux says.
fn colours_inside_tmux(name: &str, conf_text: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let conf = dir.path().join("tmux.conf");
    std::fs::write(&conf, format!("set -g remain-on-exit on\n{conf_text}")).unwrap();
    let socket = format!("bumpwork-{name}-{}", std::process::id());
    let _server = TmuxServer(socket.clone());
    let bumpwork = format!("{} view {SCENE}", env!("CARGO_BIN_EXE_bumpwork"));
    let mut command = CommandBuilder::new("tmux");
    command.args(["-L", &socket, "-f", &conf.display().to_string()]);
    command.args(["new-session", &bumpwork]);
    command.env("TERM", "xterm-256color");
    command.env_remove("TMUX");
    command.env_remove("COLORTERM");
    let mut session = Session::spawn(command, 250, 30);
    session.wait_for("the first frame", |s| {
        s.contents().contains(" colours; M says why")
    });
    session.send("M");
    session.wait_for("the colour mode in the log", |s| {
        s.contents().contains("colours: ")
    });
    session.contents()
}

#[test]
#[ignore = "needs tmux; bash .ci/run installs it and runs the ignored tests"]
fn inside_tmux_the_colours_are_what_tmux_knows_of_the_outer_terminal() {
    require(&["tmux"]);
    let rgb = colours_inside_tmux(
        "rgb",
        "set -g status off\nset -as terminal-features 'xterm*:RGB'\n",
    );
    assert!(
        rgb.contains("colours: truecolor (tmux says the terminal outside it has RGB"),
        "{rgb}"
    );
    let plain = colours_inside_tmux("no-rgb", "set -g status off\n");
    assert!(
        plain.contains("colours: 256 (tmux says the terminal outside it lacks RGB, so tmux shows at most its 256"),
        "{plain}"
    );
}
