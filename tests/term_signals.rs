//! Shutdown signals are recorded for the event loop to poll, and a watchdog ends a process whose loop
//! does not. One signal per process: a second of the same kind is the "exit now" path.

use std::process::Command;
use std::time::{Duration, Instant};

use bumpwork::term::{ShutdownSignal, ShutdownSignals, is_ctrl_c};
use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

#[test]
fn a_hang_up_is_recorded_for_the_event_loop() {
    let signals = ShutdownSignals::register().unwrap();
    assert_eq!(signals.received(), None);
    signal_hook::low_level::raise(signal_hook::consts::SIGHUP).unwrap();
    assert_eq!(signals.received(), Some(ShutdownSignal::HangUp));
    assert_eq!(ShutdownSignal::HangUp.exit_code(), 129);
    // Dropped well within the grace period: the watchdog stands down and this test process lives on.
}

const STUCK_CHILD: &str = "BUMPWORK_TERM_STUCK_CHILD";
const STUCK_TEST: &str = "a_stuck_event_loop_is_ended_by_the_watchdog";

#[test]
fn a_stuck_event_loop_is_ended_by_the_watchdog() {
    if std::env::var_os(STUCK_CHILD).is_some() {
        stuck_child();
    }
    let status = Command::new(std::env::current_exe().unwrap())
        .args(["--exact", STUCK_TEST, "--test-threads=1", "--quiet"])
        .env(STUCK_CHILD, "1")
        .status()
        .unwrap();
    assert_eq!(status.code(), Some(ShutdownSignal::Terminate.exit_code()));
}

/// Gets SIGTERM and never polls, like an event loop spinning on a dead tty; gives up after 5 s.
fn stuck_child() -> ! {
    let _signals = ShutdownSignals::register_with_grace(Duration::from_millis(100)).unwrap();
    signal_hook::low_level::raise(signal_hook::consts::SIGTERM).unwrap();
    let start = Instant::now();
    while start.elapsed() < Duration::from_secs(5) {
        std::thread::sleep(Duration::from_millis(10));
    }
    std::process::exit(0)
}

#[test]
fn ctrl_c_is_a_key_in_raw_mode() {
    assert!(is_ctrl_c(&KeyEvent::new(
        KeyCode::Char('c'),
        KeyModifiers::CONTROL
    )));
    assert!(!is_ctrl_c(&KeyEvent::new(
        KeyCode::Char('c'),
        KeyModifiers::NONE
    )));
}
