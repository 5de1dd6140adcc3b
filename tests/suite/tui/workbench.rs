//! The workbench as a user meets it, in a pseudo-terminal read back by a terminal emulator:
//! it settles and stays quiet, keeps each scene's edits, and answers every key visibly.
//!
//! Every wait polls the screen for a condition with a generous deadline; the few checks that
//! something does *not* happen watch for a while and can only pass wrongly, never fail wrongly,
//! on a slow machine.

#![cfg(unix)]

use crate::pty_support::{QUIT_DEADLINE, Session, status_contains};
use std::time::{Duration, Instant};

/// The status line's samples per pixel, once the picture has them.
fn settled(screen: &vt100::Screen) -> bool {
    status_contains("64 spp")(screen)
}

/// Bytes the program writes over `window`, the screen left alone.
fn bytes_written_over(session: &Session, window: Duration) -> usize {
    let before = session.output().len();
    let start = Instant::now();
    while start.elapsed() < window {
        std::thread::sleep(Duration::from_millis(50));
    }
    session.output().len() - before
}

/// A ripple whose speed is 0 settles like any still scene and then writes nothing.
#[test]
fn a_scene_whose_pattern_reads_t_at_speed_zero_settles_and_goes_quiet() {
    let mut session = Session::bumpwork(&["view", "plane-ripple"], None, (200, 30), "plane-ripple");
    session.wait_for("the picture to settle", settled);
    assert_eq!(bytes_written_over(&session, Duration::from_millis(1500)), 0);
    session.send("q");
    assert_eq!(session.exit_within(QUIT_DEADLINE), Some(0));
}

/// Edits to one scene (the bump's strength, the camera) are there again after Tab and Shift-Tab.
#[test]
fn each_scene_keeps_its_edits_across_tab() {
    let args = ["view", "plane-dimples", "sphere-on-plane-ripple"];
    let mut session = Session::bumpwork(&args, None, (160, 30), "plane-dimples");
    session.send("bb");
    session.wait_for("the stronger bump", status_contains("×1.56"));
    session.send("\t");
    session.wait_for(
        "the second scene",
        status_contains("2/2 sphere-on-plane-ripple"),
    );
    session.send("\x1b[Z");
    session.wait_for(
        "the first scene again",
        status_contains("1/2 plane-dimples"),
    );
    assert!(
        session.status_line().contains("×1.56"),
        "{}",
        session.status_line()
    );
    session.send("q");
    assert_eq!(session.exit_within(QUIT_DEADLINE), Some(0));
}

/// `/` lists every scene, narrows as letters are typed, and Enter goes to the one marked; Esc
/// closes the picker without going anywhere.
#[test]
fn the_picker_goes_straight_to_a_scene_typed() {
    let mut session =
        Session::bumpwork(&["view", "plane-dimples"], None, (100, 30), "plane-dimples");
    session.send("/");
    session.wait_for("the picker", |s| s.contents().contains("scene: ▏"));
    session.send("xyz");
    session.wait_for("no match", |s| s.contents().contains("no scene matches"));
    session.send("\x7f\x7f\x7fcone-ripples");
    session.wait_for("one scene", |s| s.contents().contains("▸ cone-ripples"));
    session.send("\r");
    session.wait_for("the scene picked", status_contains("2/2 cone-ripples"));
    session.send("/");
    session.wait_for("the picker again", |s| s.contents().contains("scene: ▏"));
    session.send("\x1b");
    session.wait_for("the picker closed", |s| !s.contents().contains("scene: ▏"));
    assert!(session.status_line().contains("2/2 cone-ripples"));
    session.send("q");
    assert_eq!(session.exit_within(QUIT_DEADLINE), Some(0));
}

/// In the panel, Enter types a value: one in range is taken exactly and saved in its shortest
/// form; one out of range is refused in the panel and changes nothing.
#[test]
fn a_typed_value_is_taken_exactly_and_saved_as_typed() {
    let dir = tempfile::tempdir().unwrap();
    let mut session = Session::bumpwork(
        &["view", "plane-ripple"],
        Some(dir.path()),
        (160, 30),
        "plane-ripple",
    );
    session.send("]]");
    session.wait_for("wavelength selected", status_contains("wavelength=["));
    session.send("m\r5000\r");
    session.wait_for("the refusal", |s| {
        s.contents().contains("expected 2..400, found 5000")
    });
    session.send("\r199.2\r");
    session.wait_for("the value typed", status_contains("wavelength=[199.200]"));
    session.send("\x1b");
    session.wait_for("the panel closed", |s| {
        !s.contents().contains("parameters (m closes)")
    });
    session.send("s");
    session.wait_for("the saved scene", status_contains("saved the view"));
    let saved = std::fs::read_dir(dir.path())
        .unwrap()
        .filter_map(|e| e.ok())
        .find(|e| e.path().extension().is_some_and(|x| x == "toml"))
        .expect("a scene file");
    let text = std::fs::read_to_string(saved.path()).unwrap();
    assert!(text.contains("wavelength = 199.2\n"), "{text}");
    session.send("q");
    assert_eq!(session.exit_within(QUIT_DEADLINE), Some(0));
}

/// The colour of the status line's first cell.
fn status_colour(screen: &vt100::Screen) -> vt100::Color {
    let (rows, _) = screen.size();
    screen
        .cell(rows.get() - 1, 0)
        .map_or(vt100::Color::Default, |c| c.fgcolor())
}

/// `? help` is on the status line at 40 columns; every mode key says what it changed; Esc
/// with nothing open does not quit; an error is red; `M` shows every message of the run, the
/// start-up note included.
#[test]
fn the_status_line_says_what_each_key_did_and_the_log_keeps_it() {
    let dir = tempfile::tempdir().unwrap();
    let pattern = dir.path().join("live.pat");
    std::fs::write(&pattern, "height = sin(u / 9)\n").unwrap();
    let mut session =
        Session::bumpwork(&["view", "live.pat"], Some(dir.path()), (40, 12), "? help");
    for (key, says) in [
        ("Q", "quality: high"),
        ("g", "picture: quad"),
        ("c", "colours: "),
    ] {
        session.send(key);
        session.wait_for(says, status_contains(says));
        assert!(
            session.status_line().ends_with("? help"),
            "{}",
            session.status_line()
        );
    }
    session.send("\x1b");
    session.wait_for("Esc's note", status_contains("nothing to"));
    assert!(session.child.try_wait().unwrap().is_none(), "Esc quit");
    std::fs::write(&pattern, "height = sin(u / )\n").unwrap();
    session.wait_for("the error in red", |s| {
        status_contains("expected")(s) && status_colour(s) == vt100::Color::Idx(9)
    });
    session.send("M");
    session.wait_for("the log, newest last", |s| {
        let text = s.contents();
        text.contains("messages:") && text.contains("quality: high")
    });
    session.send("\x1b[H");
    session.wait_for("the start-up note at the log's top", |s| {
        s.contents().contains("blocks (")
    });
    session.send("q");
    assert_eq!(session.exit_within(QUIT_DEADLINE), Some(0));
}

/// The picture as it looks: each cell's upper and lower colour (half blocks, spaces and full
/// blocks, however the writer chose to draw a cell), the status line left out.
fn picture(screen: &vt100::Screen) -> Vec<(vt100::Color, vt100::Color)> {
    let (rows, cols) = screen.size();
    (0..rows.get() - 1)
        .flat_map(|row| (0..cols.get()).map(move |col| (row, col)))
        .filter_map(|(row, col)| screen.cell(row, col))
        .map(|cell| {
            let (fg, bg) = (cell.fgcolor(), cell.bgcolor());
            match cell.contents() {
                "▀" => (fg, bg),
                "▄" => (bg, fg),
                "█" => (fg, fg),
                _ => (bg, bg),
            }
        })
        .collect()
}

/// `o` names the object it moves to and draws its edges over the picture for a moment, then
/// the picture is as it was.
#[test]
fn the_object_key_names_the_object_and_marks_it_for_a_moment() {
    let args = ["view", "sphere-on-plane-dimples"];
    let mut session = Session::bumpwork(&args, None, (220, 40), "sphere-on-plane-dimples");
    session.wait_for("the picture to settle", settled);
    let before = picture(session.screen.lock().unwrap().screen());
    session.send("o");
    session.wait_for("the object named", |s| {
        let status = s.contents();
        let last = status.lines().last().unwrap_or("").to_string();
        last.contains("editing object 2 sphere")
    });
    session.wait_for("its edges drawn", |s| picture(s) != before);
    session.wait_for("the picture as it was", |s| {
        picture(s) == before && settled(s)
    });
    session.send("q");
    assert_eq!(session.exit_within(QUIT_DEADLINE), Some(0));
}

/// A pattern with spots where it has no finite value says how many the status line drew flat.
#[test]
fn non_finite_spots_are_counted_in_the_status_line() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("holes.pat"), "height = sqrt(u - 200)\n").unwrap();
    let mut session = Session::bumpwork(
        &["view", "holes.pat"],
        Some(dir.path()),
        (200, 30),
        "holes.pat",
    );
    session.wait_for("the count", status_contains("non-finite spots drawn flat"));
    session.send("q");
    assert_eq!(session.exit_within(QUIT_DEADLINE), Some(0));
}

/// At 80×24 the help shows every key at once, from the top, Esc and q included.
#[test]
fn the_help_fits_80_by_24() {
    let mut session =
        Session::bumpwork(&["view", "plane-dimples"], None, (80, 24), "plane-dimples");
    session.send("?");
    session.wait_for("the whole help", |s| {
        let text = s.contents();
        [
            "keys (Esc closes)",
            "Tab S-Tab",
            "Esc",
            "q ",
            "C-z",
            "C-l",
            "drag",
            "type a value",
        ]
        .iter()
        .all(|needed| text.contains(needed))
    });
    session.send("\x1b");
    session.wait_for("the help closed", |s| {
        !s.contents().contains("keys (Esc closes)")
    });
    session.send("q");
    assert_eq!(session.exit_within(QUIT_DEADLINE), Some(0));
}

/// An image file is a scene of its own: the image as texture and bump on the stage, reloaded
/// when it is saved again.
#[test]
fn an_image_is_shown_and_follows_its_file() {
    let dir = tempfile::tempdir().unwrap();
    let photo = dir.path().join("photo.png");
    let shipped = concat!(env!("CARGO_MANIFEST_DIR"), "/textures/brick.png");
    std::fs::copy(shipped, &photo).unwrap();
    let mut session = Session::bumpwork(
        &["view", "photo.png"],
        Some(dir.path()),
        (160, 30),
        "photo.png",
    );
    assert!(
        session.status_line().contains("photo.png ×30"),
        "{}",
        session.status_line()
    );
    let gravel = concat!(env!("CARGO_MANIFEST_DIR"), "/textures/gravel.png");
    std::fs::copy(gravel, &photo).unwrap();
    session.wait_for("the reload", status_contains("reloaded"));
    std::fs::write(&photo, b"not a png").unwrap();
    session.wait_for("the error", status_contains("not a valid PNG"));
    session.send("q");
    assert_eq!(session.exit_within(QUIT_DEADLINE), Some(0));
}

/// `view --bump NAME --texture NAME` shows them on the scene.
#[test]
fn the_workbench_takes_a_bump_and_a_texture_by_name() {
    let args = [
        "view",
        "plane-dimples",
        "--bump",
        "stucco",
        "--texture",
        "chelsea",
    ];
    let mut session = Session::bumpwork(&args, None, (200, 30), "plane-dimples");
    session.wait_for("the choice", |s| {
        status_contains("stucco ×1.00")(s) && status_contains("tex chelsea")(s)
    });
    session.send("q");
    assert_eq!(session.exit_within(QUIT_DEADLINE), Some(0));
}
