//! End to end: the real binary in a pseudo-terminal, read back through a terminal emulator
//! (vt100). Start, wait for the first frame, orbit, change scene and view mode, export, quit, and
//! check the terminal was given back (main screen, cursor shown, line discipline cooked again).
//!
//! Every wait polls the emulated screen until a condition holds, with a generous deadline, so a
//! loaded machine makes the test slower, not flaky.

#![cfg(unix)]

use crate::cli_support::wait_until;
use crate::pty_support::{QUIT_DEADLINE, Session, status_contains};
use portable_pty::CommandBuilder;
use std::time::Duration;

const COLS: u16 = 100;
const ROWS: u16 = 30;

/// The picture's colours, to see that it changed.
fn picture(screen: &vt100::Screen) -> Vec<(vt100::Color, vt100::Color)> {
    (0..ROWS - 1)
        .flat_map(|row| (0..COLS).map(move |col| (row, col)))
        .filter_map(|(row, col)| screen.cell(row, col))
        .map(|cell| (cell.fgcolor(), cell.bgcolor()))
        .collect()
}

#[test]
fn the_workbench_runs_in_a_real_terminal_and_gives_it_back() {
    let dir = tempfile::tempdir().expect("a temporary directory");
    let dir = dir.path();
    // The shell reports the exit status and the line discipline after the workbench ends.
    let mut command = CommandBuilder::new("sh");
    command.args([
        "-c",
        "\"$0\" view plane-dimples sphere-on-plane-dimples; echo \"exit=$?\"; stty -a; echo DONE",
        env!("CARGO_BIN_EXE_bumpwork"),
    ]);
    command.cwd(dir);
    command.env("TERM", "xterm-256color");
    command.env("COLORTERM", "truecolor");
    command.env_remove("NO_COLOR");
    let mut session = Session::spawn(command, COLS, ROWS);

    session.wait_for("the first frame", status_contains("1/2 plane-dimples"));
    session.wait_for("the alternate screen, cursor hidden", |s| {
        s.alternate_screen() && s.hide_cursor()
    });
    let before = picture(session.screen.lock().unwrap().screen());

    session.send("lll");
    session.wait_for("the orbit to change the picture", |s| picture(s) != before);

    session.send("\t");
    session.wait_for(
        "the next scene",
        status_contains("2/2 sphere-on-plane-dimples"),
    );

    session.send("v");
    session.wait_for("the height view", status_contains("│ height │"));

    session.send("p");
    session.wait_for(
        "the next bump pattern",
        status_contains(" dimples ×1.00 period="),
    );

    session.send("e");
    session.wait_for("the export to finish", status_contains("exported"));
    let exported: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.path().extension().is_some_and(|x| x == "png"))
        .collect();
    assert_eq!(exported.len(), 1, "status: {}", session.status_line());
    let png = std::fs::read(exported[0].path()).unwrap();
    assert_eq!(&png[1..4], b"PNG");

    session.send("q");
    session.wait_for("the shell after the workbench", |s| {
        s.contents().contains("DONE")
    });
    let status = session.child.wait().unwrap();
    assert!(status.success());
    let parser = session.screen.lock().unwrap();
    let screen = parser.screen();
    let text = screen.contents();
    assert!(text.contains("exit=0"), "{text}");
    assert!(!screen.alternate_screen(), "still on the alternate screen");
    assert!(!screen.hide_cursor(), "cursor still hidden");
    // Raw mode off: canonical input and echo are back.
    assert!(text.contains(" icanon") && text.contains(" echo"), "{text}");
    assert!(!text.contains("-icanon"), "{text}");
    drop(parser);
}

/// `--export-dir` sends the export key's stills there, not to the current directory.
#[test]
fn the_export_key_writes_into_the_export_dir() {
    let cwd = tempfile::tempdir().unwrap();
    let stills = cwd.path().join("stills");
    std::fs::create_dir(&stills).unwrap();
    let args = [
        "view",
        "plane-dimples",
        "--export-size",
        "64x36",
        "--export-dir",
        "stills",
    ];
    let mut session = Session::bumpwork(&args, Some(cwd.path()), (COLS, ROWS), "plane-dimples");
    session.send("e");
    session.wait_for("the export to finish", status_contains("exported"));
    let pngs = |dir: &std::path::Path| {
        std::fs::read_dir(dir)
            .unwrap()
            .filter_map(|e| e.ok())
            .filter(|e| e.path().extension().is_some_and(|x| x == "png"))
            .count()
    };
    assert_eq!(pngs(&stills), 1, "status: {}", session.status_line());
    assert_eq!(pngs(cwd.path()), 0);
    session.send("q");
    assert_eq!(
        session.exit_within(std::time::Duration::from_secs(30)),
        Some(0)
    );
}

/// The workbench in `dir`, exporting a still large and supersampled enough to be still running
/// when the test acts.
fn exporting_in(dir: &std::path::Path) -> Session {
    let args = [
        "view",
        "plane-dimples",
        "--export-size",
        "8000x8000",
        "--export-samples",
        "64",
    ];
    let mut session = Session::bumpwork(&args, Some(dir), (COLS, ROWS), "plane-dimples");
    session.send("e");
    session.wait_for("the export to start", status_contains("exporting"));
    session
}

/// Every catchable signal that ends the workbench during an export leaves neither the still nor
/// its temporary file, and ends it within the 0.5 s grace.
#[test]
fn a_signal_during_an_export_leaves_no_file() {
    for (name, signal) in [("SIGQUIT", libc::SIGQUIT), ("SIGUSR1", libc::SIGUSR1)] {
        let dir = tempfile::tempdir().unwrap();
        let mut session = exporting_in(dir.path());
        let pid = session.child.process_id().unwrap() as i32;
        // SAFETY: kill only sends a signal to the process we started.
        assert_eq!(unsafe { libc::kill(pid, signal) }, 0);
        let start = std::time::Instant::now();
        let status = session.exit_within(std::time::Duration::from_secs(3));
        eprintln!("{name}: ended in {:?}", start.elapsed());
        assert_eq!(status, Some(128 + signal as u32), "{name}");
        let left: Vec<_> = std::fs::read_dir(dir.path())
            .unwrap()
            .map(|entry| entry.unwrap().file_name())
            .collect();
        assert!(left.is_empty(), "{name} left {left:?}");
    }
}

/// The process state letter Linux reports (`T` when stopped).
fn process_state(pid: u32) -> char {
    let stat = std::fs::read_to_string(format!("/proc/{pid}/stat")).unwrap_or_default();
    // The state follows the command name, which is in parentheses.
    stat.rsplit_once(") ")
        .and_then(|(_, rest)| rest.chars().next())
        .unwrap_or('?')
}

/// Ctrl-Z and SIGTSTP give the terminal back and stop the workbench; continued, it takes the
/// terminal again and draws everything.
#[test]
fn ctrl_z_suspends_with_the_terminal_restored_and_continuing_redraws() {
    for suspend in ["Ctrl-Z", "SIGTSTP"] {
        let view = ["view", "plane-dimples"];
        let mut session = Session::bumpwork(&view, None, (COLS, ROWS), "plane-dimples");
        let pid = session.child.process_id().unwrap();
        match suspend {
            "Ctrl-Z" => session.send("\x1a"),
            // SAFETY: kill only sends a signal to the process we started.
            _ => assert_eq!(unsafe { libc::kill(pid as i32, libc::SIGTSTP) }, 0),
        }
        wait_until("the process to stop", Duration::from_secs(10), || {
            process_state(pid) == 'T'
        });
        session.wait_for("the main screen with a cursor", |screen| {
            !screen.alternate_screen() && !screen.hide_cursor()
        });
        // SAFETY: as above.
        assert_eq!(unsafe { libc::kill(pid as i32, libc::SIGCONT) }, 0);
        session.wait_for("the picture again", |screen| {
            screen.alternate_screen() && status_contains("plane-dimples")(screen)
        });
        session.send("q");
        assert_eq!(
            session.exit_within(std::time::Duration::from_secs(5)),
            Some(0),
            "{suspend}"
        );
    }
}

/// A save that does not load shows its whole diagnostic over the picture (the source line and
/// the caret, not only the status line's first line); Esc hides it, and a good save removes it.
#[test]
fn a_failed_reload_shows_the_whole_diagnostic_until_dismissed_or_fixed() {
    let dir = tempfile::tempdir().unwrap();
    let pattern = dir.path().join("live.pat");
    std::fs::write(&pattern, "height = 0.1 * sin(20 * u)\n").unwrap();
    let mut session = Session::bumpwork(
        &["view", "live.pat"],
        Some(dir.path()),
        (COLS, ROWS),
        "live.pat",
    );
    let overlay = |screen: &vt100::Screen| {
        let text = screen.contents();
        text.contains("does not load") && text.contains("1 | height = 0.1 * * u")
    };
    let broken = "height = 0.1 * * u\n";
    std::fs::write(&pattern, broken).unwrap();
    session.wait_for("the diagnostic overlay", overlay);
    session.send("\x1b");
    session.wait_for("the overlay dismissed", |screen| !overlay(screen));
    assert!(
        session.status_line().contains("expected"),
        "the status line keeps the error"
    );
    std::fs::write(&pattern, "height = 0.2 * sin(20 * u)\n").unwrap();
    session.wait_for("the good save", status_contains("reloaded"));
    std::fs::write(&pattern, broken).unwrap();
    session.wait_for("the overlay again", overlay);
    std::fs::write(&pattern, "height = 0.3 * sin(20 * u)\n").unwrap();
    session.wait_for("the overlay gone with the fix", |screen| {
        !overlay(screen) && status_contains("reloaded")(screen)
    });
    session.send("q");
    assert_eq!(session.exit_within(QUIT_DEADLINE), Some(0));
}

/// While an export runs the status line shows its progress; `q` first says what quitting would
/// cancel, and a second `q` cancels it, leaves no file, and says so on the normal screen.
#[test]
fn quitting_during_an_export_says_it_was_cancelled() {
    let dir = tempfile::tempdir().unwrap();
    let mut session = exporting_in(dir.path());
    session.wait_for("the export's progress", |screen| {
        let status = screen.contents();
        status
            .lines()
            .last()
            .is_some_and(|l| l.contains("exporting") && l.contains('%'))
    });
    session.send("q");
    session.wait_for(
        "the warning",
        status_contains("quitting cancels the export"),
    );
    assert!(
        session.child.try_wait().unwrap().is_none(),
        "one q quit during the export"
    );
    session.send("q");
    assert_eq!(session.exit_within(QUIT_DEADLINE), Some(0));
    session.wait_for("the note on the normal screen", |screen| {
        !screen.alternate_screen() && screen.contents().contains("was cancelled on quitting")
    });
    assert_eq!(std::fs::read_dir(dir.path()).unwrap().count(), 0);
}

/// The parameter panel lists the pattern's parameters with range and default; a click selects
/// a row and the wheel over it changes the value, as the status line then shows.
#[test]
fn the_parameter_panel_is_edited_with_keys_and_the_mouse() {
    let dir = tempfile::tempdir().unwrap();
    let pattern = dir.path().join("two.pat");
    std::fs::write(
        &pattern,
        "param period = 20 in 2..100\nparam depth = 0.5 in 0..1\n\
         height = depth * sin(u / period)\n",
    )
    .unwrap();
    let mut session = Session::bumpwork(
        &["view", "two.pat"],
        Some(dir.path()),
        (COLS, ROWS),
        "two.pat",
    );
    session.send("m");
    session.wait_for("the panel", |screen| {
        let text = screen.contents();
        text.contains("parameters (m closes)")
            && text.contains("▸ period")
            && text.contains("2..100 (20)")
            && text.contains("0..1 (0.5)")
    });
    let text = session.contents();
    let depth_row = text
        .lines()
        .position(|l| l.contains("  depth "))
        .expect("a depth row") as u16;
    let column = COLS - 10;
    // SGR mouse: a left press on the depth row, then two wheel-downs over it.
    session.send(&format!("\x1b[<0;{};{}M", column + 1, depth_row + 1));
    session.wait_for("depth selected", |screen| {
        screen.contents().contains("▸ depth")
    });
    session.send(&format!("\x1b[<65;{};{}M", column + 1, depth_row + 1));
    session.send(&format!("\x1b[<65;{};{}M", column + 1, depth_row + 1));
    session.wait_for(
        "depth lowered by two steps",
        status_contains("depth=[0.460]"),
    );
    session.send(".");
    session.wait_for("depth raised by a key", status_contains("depth=[0.480]"));
    session.send("\x1b");
    session.wait_for("the panel closed by Esc", |screen| {
        !screen.contents().contains("parameters (m closes)")
    });
    session.send("q");
    assert_eq!(session.exit_within(QUIT_DEADLINE), Some(0));
}
