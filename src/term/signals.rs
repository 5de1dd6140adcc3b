//! The signals that end the workbench: SIGINT, SIGTERM and SIGHUP (the SSH link dropped, the terminal
//! window closed). Handlers only record the signal; the event loop polls [`ShutdownSignals::received`]
//! (say after each `crossterm::event::poll` with a timeout of 100 ms or less), drops its terminal guard
//! and exits with [`ShutdownSignal::exit_code`].
//!
//! In raw mode the terminal does not turn Ctrl-C into SIGINT: it arrives as a key event, which the event
//! loop must treat as quit itself ([`is_ctrl_c`]). SIGINT still comes from `kill -INT`.
//!
//! A second signal of the same kind, while the first is still unhandled, exits at once with 128 + signal
//! and without restoring: the way out of an event loop that has stopped polling.

use std::io;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

use crossterm::event::{KeyCode, KeyEvent, KeyEventKind, KeyModifiers};
use signal_hook::SigId;
use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
use signal_hook::flag;

/// A signal asking the workbench to end.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ShutdownSignal {
    Interrupt,
    Terminate,
    HangUp,
}

impl ShutdownSignal {
    pub const ALL: [ShutdownSignal; 3] = [
        ShutdownSignal::Interrupt,
        ShutdownSignal::Terminate,
        ShutdownSignal::HangUp,
    ];

    pub fn number(self) -> i32 {
        match self {
            ShutdownSignal::Interrupt => SIGINT,
            ShutdownSignal::Terminate => SIGTERM,
            ShutdownSignal::HangUp => SIGHUP,
        }
    }

    /// The shell's convention for a process ended by this signal.
    pub fn exit_code(self) -> i32 {
        128 + self.number()
    }

    fn from_number(number: usize) -> Option<ShutdownSignal> {
        Self::ALL
            .into_iter()
            .find(|s| s.number() as usize == number)
    }
}

/// The installed handlers; dropping this removes them (the default actions apply again).
#[derive(Debug)]
pub struct ShutdownSignals {
    received: Arc<AtomicUsize>,
    ids: Vec<SigId>,
}

impl ShutdownSignals {
    /// Installs the handlers for SIGINT, SIGTERM and SIGHUP.
    pub fn register() -> io::Result<ShutdownSignals> {
        let received = Arc::new(AtomicUsize::new(0));
        let mut signals = ShutdownSignals {
            received: Arc::clone(&received),
            ids: Vec::new(),
        };
        for signal in ShutdownSignal::ALL {
            let number = signal.number();
            let pending = Arc::new(AtomicBool::new(false));
            // Registered before the flag setter, so it sees the flag as the earlier signal left it.
            signals.ids.push(flag::register_conditional_shutdown(
                number,
                signal.exit_code(),
                Arc::clone(&pending),
            )?);
            signals.ids.push(flag::register(number, pending)?);
            signals.ids.push(flag::register_usize(
                number,
                Arc::clone(&received),
                number as usize,
            )?);
        }
        Ok(signals)
    }

    /// The last shutdown signal received, if any.
    pub fn received(&self) -> Option<ShutdownSignal> {
        ShutdownSignal::from_number(self.received.load(Ordering::SeqCst))
    }
}

impl Drop for ShutdownSignals {
    fn drop(&mut self) {
        for id in self.ids.drain(..) {
            signal_hook::low_level::unregister(id);
        }
    }
}

/// Whether `key` is Ctrl-C, the interrupt key that raw mode delivers as a key instead of SIGINT.
pub fn is_ctrl_c(key: &KeyEvent) -> bool {
    key.kind != KeyEventKind::Release
        && key.modifiers.contains(KeyModifiers::CONTROL)
        && matches!(key.code, KeyCode::Char('c') | KeyCode::Char('C'))
}
