//! Real pixels: the workbench's kitty and sixel pictures decoded back to pixels and compared with
//! what was rendered (kitty exactly, sixel within a PSNR bound) and with a still of the same view;
//! detection answered in a pseudo-terminal, its replies never taken for keys.

use crate::graphics_support::{Rgb, kitty_images, psnr, sixel_images};
use crate::pty_support::{QUIT_DEADLINE, Session, status_contains};
use bumpwork::term::ColorMode;
use bumpwork::term::graphics::Protocol;
use bumpwork::tui::{App, PixelRoute, Screen, WorkbenchOptions};
use std::time::Duration;

const COLS: u16 = 60;
const ROWS: u16 = 20;
const CELL: (u32, u32) = (8, 16);
/// The picture's pixels: the cells' pixels, the status line's row left to text.
const PICTURE: (usize, usize) = (60 * 8, 19 * 16);

fn app(scene: &str) -> App {
    let options = WorkbenchOptions {
        scenes: vec![scene.into()],
        watch: false,
        ..WorkbenchOptions::default()
    };
    App::new(&options, ColorMode::TrueColor).unwrap()
}

/// A workbench in `protocol` and everything it writes until its picture has settled, in
/// process.
fn settled(scene: &str, protocol: Protocol) -> (App, Screen, Vec<u8>) {
    let mut app = app(scene);
    app.set_graphics(Some(protocol));
    let mut screen = Screen::new(COLS, ROWS);
    screen.set_pixel_route(route(false), &mut app);
    let mut out = Vec::new();
    screen.draw(&mut app, &mut out).unwrap();
    while screen.refining(&app) {
        screen.refine(&mut app, &mut out).unwrap();
    }
    (app, screen, out)
}

/// What a workbench in `protocol` writes until its picture has settled.
fn settled_output(scene: &str, protocol: Protocol) -> Vec<u8> {
    settled(scene, protocol).2
}

/// A still of the scene's own view at the picture's size.
fn still(scene: &str) -> Vec<u8> {
    crate::graphics_support::settled_still(scene, PICTURE)
}

#[test]
fn kitty_sends_a_scaled_preview_then_the_settled_picture_exactly_as_rendered() {
    let out = settled_output("sphere-on-plane-dimples", Protocol::Kitty);
    let images = kitty_images(&out);
    assert_eq!(images.len(), 2, "a preview and the settled picture");
    assert_eq!(
        (images[0].width, images[0].height),
        (PICTURE.0 / 2, PICTURE.1 / 2)
    );
    let settled = &images[1];
    assert_eq!((settled.width, settled.height), PICTURE);
    let db = psnr(&still("sphere-on-plane-dimples"), &settled.pixels);
    eprintln!("kitty: {db:.1} dB against the still");
    assert!(
        db >= 40.0,
        "the settled kitty picture is {db:.1} dB from the still"
    );
    // Each chunk is at most 4096 bytes (checked while decoding) and the image id is one.
    let text = String::from_utf8_lossy(&out);
    assert_eq!(text.matches("a=T,").count(), 2, "two transmissions");
    assert_eq!(
        text.matches(",i=31,").count(),
        2,
        "both under the one image id"
    );
}

#[test]
fn sixel_dithers_onto_256_colours_within_its_bound() {
    let scene = "sphere-on-plane-dimples";
    let kitty = kitty_images(&settled_output(scene, Protocol::Kitty))
        .pop()
        .unwrap();
    let out = settled_output(scene, Protocol::Sixel);
    let images = sixel_images(&out);
    assert_eq!(
        images.len(),
        2,
        "one pass at full size, then the settled picture"
    );
    let settled: &Rgb = &images[1];
    assert_eq!((settled.width, settled.height), PICTURE);
    let db = psnr(&kitty.pixels, &settled.pixels);
    assert!(db >= 30.0, "sixel is {db:.1} dB from the exact picture");
    let registers = String::from_utf8_lossy(&out).matches(";2;").count();
    assert!(
        registers <= 2 * 256,
        "{registers} colour registers in two images"
    );
    let still_db = psnr(&still(scene), &settled.pixels);
    eprintln!("sixel: {db:.1} dB against the exact picture, {still_db:.1} dB against the still");
    assert!(still_db >= 30.0, "sixel is {still_db:.1} dB from the still");
}

#[test]
fn an_idle_pixel_picture_sends_nothing_and_leaving_kitty_deletes_its_image() {
    let (mut app, mut screen, _) = settled("plane-dimples", Protocol::Kitty);
    let mut idle = Vec::new();
    screen.draw(&mut app, &mut idle).unwrap();
    screen.refine(&mut app, &mut idle).unwrap();
    assert!(idle.is_empty(), "an idle screen wrote {} bytes", idle.len());
    app.set_graphics(None);
    let mut blocks = Vec::new();
    screen.draw(&mut app, &mut blocks).unwrap();
    let text = String::from_utf8_lossy(&blocks);
    assert!(
        text.starts_with("\x1b_Ga=d,d=I,i=31"),
        "{:?}",
        &text[..40.min(text.len())]
    );
    assert!(text.contains('▀'), "then the picture in blocks");
}

/// The workbench in a pseudo-terminal that answers the graphics queries as `replies`.
fn answered_session(args: &[&str], replies: &[u8]) -> Session {
    let mut command = portable_pty::CommandBuilder::new(env!("CARGO_BIN_EXE_bumpwork"));
    command.args(args);
    command.env("TERM", "xterm-256color");
    command.env_remove("TMUX");
    let mut session = Session::spawn(command, COLS, ROWS);
    let asked = std::time::Instant::now();
    while !String::from_utf8_lossy(&session.output()).contains("\x1b[c") {
        assert!(
            asked.elapsed() < Duration::from_secs(30),
            "no graphics query"
        );
        std::thread::sleep(Duration::from_millis(5));
    }
    session.send(&String::from_utf8_lossy(replies));
    session
}

#[test]
fn auto_takes_the_terminals_answer_and_its_replies_never_reach_the_keys() {
    let kitty_reply = b"\x1b_Gi=32;OK\x1b\\\x1b[6;16;8t\x1b[?62;4;22c";
    let mut session = answered_session(&["view", "plane-dimples"], kitty_reply);
    session.wait_for("kitty chosen", status_contains("kitty"));
    session.wait_for("the settled picture", |_| {
        kitty_images(&session.output()).len() >= 2
    });
    let images = kitty_images(&session.output());
    let settled = images.last().unwrap();
    assert_eq!(
        (settled.width, settled.height),
        PICTURE,
        "the reported cell size"
    );
    assert_eq!(
        settled,
        kitty_images(&settled_output("plane-dimples", Protocol::Kitty))
            .last()
            .unwrap()
    );
    // The reply's escape characters were not taken for Esc (which quits).
    assert_eq!(session.exit_within(Duration::from_millis(300)), None);
    let sixel_reply = b"\x1b[6;16;8t\x1b[?62;4c";
    let mut session = answered_session(&["view", "plane-dimples"], sixel_reply);
    session.wait_for("sixel chosen", status_contains("sixel"));
    session.wait_for("the settled sixel picture", |_| {
        sixel_images(&session.output()).len() >= 2
    });
    let in_process = sixel_images(&settled_output("plane-dimples", Protocol::Sixel));
    let sent = sixel_images(&session.output());
    assert_eq!(
        sent.last(),
        in_process.last(),
        "the same sixels as rendered in process"
    );
    let exact = kitty_images(&settled_output("plane-dimples", Protocol::Kitty));
    let db = psnr(&exact.last().unwrap().pixels, &sent.last().unwrap().pixels);
    assert!(
        db >= 30.0,
        "the sixel picture sent is {db:.1} dB from the exact one"
    );
    session.send("q");
    assert_eq!(session.exit_within(QUIT_DEADLINE), Some(0));
    // A reply that comes a moment after DA1's (as the outer terminal's do through tmux) is
    // read with the replies: its `i` does not invert the bump.
    let plain = b"\x1b[?1;2c";
    let mut session = answered_session(&["view", "plane-dimples"], plain);
    std::thread::sleep(Duration::from_millis(10));
    session.send("\x1b_Gi=32;ENOENT:late\x1b\\");
    session.wait_for("blocks", status_contains("blocks, "));
    session.send("M");
    session.wait_for("why, in the log", |s| {
        s.contents()
            .contains("picture: blocks (the terminal answered")
    });
    session.send("\x1b");
    session.wait_for("the log closed", |s| !s.contents().contains("messages:"));
    session.wait_for("the bump as the file has it", status_contains("×1.00"));
    session.send("q");
    assert_eq!(session.exit_within(QUIT_DEADLINE), Some(0));
}

#[test]
fn a_kitty_session_deletes_its_image_when_it_quits() {
    let mut session = answered_session(
        &[
            "view",
            "plane-dimples",
            "--graphics",
            "kitty",
            "--cell-size",
            "10x20",
        ],
        b"\x1b[?62c",
    );
    session.wait_for("a picture", |_| !kitty_images(&session.output()).is_empty());
    let first = kitty_images(&session.output()).remove(0);
    let scaled = first.width == 60 * 10 / 2 && first.height == 19 * 20 / 2;
    assert!(
        scaled,
        "--cell-size 10x20: half of 600x380, not {}x{}",
        first.width, first.height
    );
    session.send("q");
    assert_eq!(session.exit_within(QUIT_DEADLINE), Some(0));
    let output = session.output();
    let text = String::from_utf8_lossy(&output);
    let deleted = text.rfind("\x1b_Ga=d,d=I,i=31").expect("the image deleted");
    let left = text
        .rfind("\x1b[?1049l")
        .expect("the alternate screen left");
    assert!(
        deleted < left,
        "deleted before leaving the alternate screen"
    );
}

#[test]
fn iterm2_sends_the_same_pixels_as_a_png_and_tmux_passes_sequences_through() {
    use base64::Engine;
    let exact = kitty_images(&settled_output("plane-dimples", Protocol::Kitty))
        .pop()
        .unwrap();
    let out = settled_output("plane-dimples", Protocol::Iterm2);
    let text = String::from_utf8_lossy(&out);
    let last = text.rsplit("\x1b]1337;File=").next().unwrap();
    let (keys, rest) = last.split_once(':').unwrap();
    assert!(
        keys.contains("inline=1") && keys.contains(&format!("width={COLS}")),
        "{keys}"
    );
    let payload = rest.split('\x07').next().unwrap();
    let png = base64::engine::general_purpose::STANDARD
        .decode(payload)
        .unwrap();
    let (width, height, pixels) = crate::cli_support::decode_png_bytes(&png);
    assert_eq!((width as usize, height as usize), PICTURE);
    assert_eq!(pixels, exact.pixels, "iTerm2's PNG holds the exact picture");
    // Through tmux: each kitty sequence wrapped, its escapes doubled, the picture the same.
    let mut app = app("plane-dimples");
    app.set_graphics(Some(Protocol::Kitty));
    let mut screen = Screen::new(COLS, ROWS);
    screen.set_pixel_route(route(true), &mut app);
    let mut wrapped = Vec::new();
    screen.draw(&mut app, &mut wrapped).unwrap();
    let text = String::from_utf8_lossy(&wrapped);
    assert!(text.contains("\x1bPtmux;\x1b\x1b_Ga=T"), "wrapped for tmux");
    let unwrapped = text.replace("\x1bPtmux;", "").replace("\x1b\x1b", "\x1b");
    let images = kitty_images(unwrapped.as_bytes());
    assert_eq!(
        (images[0].width, images[0].height),
        (PICTURE.0 / 2, PICTURE.1 / 2)
    );
}

/// Pixels of `CELL` a cell, through tmux or not.
fn route(through_tmux: bool) -> PixelRoute {
    PixelRoute {
        through_tmux,
        cell_pixels: CELL,
        sixel_limit: None,
    }
}

#[test]
fn a_new_cell_size_with_the_window_gives_a_picture_of_the_new_size() {
    let mut session = answered_session(
        &["view", "plane-dimples", "--graphics", "kitty"],
        b"\x1b[?62c",
    );
    session.wait_for("a picture at the usual 10x20 cells", |_| {
        kitty_images(&session.output())
            .iter()
            .any(|i| (i.width, i.height) == (600, 380))
    });
    // The same cells, a smaller font: 8x16 pixels a cell.
    session.resize(COLS, ROWS, COLS * 8, ROWS * 16);
    session.wait_for("a picture at 8x16 cells", |_| {
        kitty_images(&session.output())
            .last()
            .is_some_and(|i| (i.width, i.height) == PICTURE)
    });
    session.send("q");
    assert_eq!(session.exit_within(QUIT_DEADLINE), Some(0));
}

#[test]
fn a_terminal_of_no_size_gets_no_picture_until_it_tells_one_and_the_status_line_says_so() {
    let mut command = portable_pty::CommandBuilder::new(env!("CARGO_BIN_EXE_bumpwork"));
    command.args(["view", "plane-dimples", "--graphics", "kitty"]);
    command.env("TERM", "xterm-256color");
    command.env_remove("TMUX");
    let mut session = Session::spawn(command, 0, 0);
    session.wait_for("the status line", status_contains("0×0"));
    let before = session.output();
    assert!(
        kitty_images(&before).is_empty(),
        "an image for a terminal of no size"
    );
    assert!(
        !String::from_utf8_lossy(&before).contains("s=0"),
        "a zero-size kitty image"
    );
    session.resize(COLS, ROWS, 0, 0);
    session.wait_for("the picture once the size is known", |_| {
        !kitty_images(&session.output()).is_empty()
    });
    // A size lost again deletes the image, and a size told again brings it back.
    let shown = session.output().len();
    session.resize(0, 0, 0, 0);
    session.wait_for("the image deleted", |_| {
        String::from_utf8_lossy(&session.output()[shown..]).contains("\x1b_Ga=d")
    });
    let deleted = session.output().len();
    session.resize(COLS, ROWS, 0, 0);
    session.wait_for("the picture again", |_| {
        !kitty_images(&session.output()[deleted..]).is_empty()
    });
    session.send("q");
    assert_eq!(session.exit_within(QUIT_DEADLINE), Some(0));
}
