//! Nothing a watched file turns into can stop the workbench from quitting: a pattern file
//! replaced by a FIFO (which would block a reader's `open`) or by a symbolic link to `/dev/zero`
//! (which never ends) is reported, and q, Ctrl-C, SIGTERM and SIGHUP still end the workbench at
//! once.

#![cfg(unix)]

use crate::cli_support::make_fifo;
use crate::pty_support::{Session, status_contains};
use std::path::Path;
use std::time::{Duration, Instant};

/// Far past the 0.5 s the workbench is allowed, so a loaded machine does not fail the test, yet
/// far below "stuck".
const QUIT_LIMIT: Duration = Duration::from_secs(10);

enum Quit {
    Key(&'static str),
    Signal(i32),
}

const QUITS: [(&str, Quit); 4] = [
    ("q", Quit::Key("q")),
    ("Ctrl-C", Quit::Key("\x03")),
    ("SIGTERM", Quit::Signal(libc::SIGTERM)),
    ("SIGHUP", Quit::Signal(libc::SIGHUP)),
];

/// Starts `view live.pat`, turns the file into what `replace` makes, waits for the failed reload
/// to be reported, then quits each way in turn (a fresh workbench for each).
fn quits_after(replace: impl Fn(&Path), reported: &'static str) {
    for (name, quit) in QUITS {
        let dir = tempfile::tempdir().unwrap();
        let pattern = dir.path().join("live.pat");
        std::fs::write(&pattern, "height = 0.1 * sin(20 * u)\n").unwrap();
        let view = ["view", "live.pat"];
        let mut session = Session::bumpwork(&view, Some(dir.path()), (120, 30), "live.pat");

        let replacement = dir.path().join("replacement");
        replace(&replacement);
        std::fs::rename(&replacement, &pattern).unwrap();
        session.wait_for("the failed reload", status_contains(reported));

        let start = Instant::now();
        match quit {
            Quit::Key(keys) => session.send(keys),
            Quit::Signal(signal) => {
                let pid = session.child.process_id().unwrap() as i32;
                // SAFETY: kill only sends a signal to the process we started.
                assert_eq!(unsafe { libc::kill(pid, signal) }, 0);
            }
        }
        let status = session.exit_within(QUIT_LIMIT);
        let took = start.elapsed();
        assert!(
            status.is_some(),
            "{name}: still running after {took:?}; status line: {}",
            session.status_line()
        );
        eprintln!("{name}: ended in {took:?} with status {status:?}");
    }
}

#[test]
fn a_pattern_file_turned_into_a_fifo_does_not_stop_quitting() {
    quits_after(make_fifo, "named pipe");
}

#[test]
fn a_pattern_file_turned_into_an_endless_device_does_not_stop_quitting() {
    quits_after(
        |path| std::os::unix::fs::symlink("/dev/zero", path).unwrap(),
        "a device",
    );
}
