//! Shutdown signals are recorded for the event loop to poll. One signal per process: a second of the
//! same kind is the "exit now" path and would end the test binary.

use bumpwork::term::{ShutdownSignal, ShutdownSignals, is_ctrl_c};
use crossterm::event::{KeyCode, KeyEvent, KeyModifiers};

#[test]
fn a_hang_up_is_recorded_not_fatal() {
    let signals = ShutdownSignals::register().unwrap();
    assert_eq!(signals.received(), None);
    signal_hook::low_level::raise(signal_hook::consts::SIGHUP).unwrap();
    assert_eq!(signals.received(), Some(ShutdownSignal::HangUp));
    assert_eq!(ShutdownSignal::HangUp.exit_code(), 129);
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
