//! The signals that end the workbench: SIGINT, SIGTERM, SIGHUP (the SSH link dropped, the terminal
//! window closed) and every other catchable signal whose default is to end the process (SIGQUIT,
//! SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM, SIGPROF, SIGXCPU, SIGXFSZ), so none of them leaves the
//! terminal raw or an export's temporary file behind. Handlers only record the signal; the event loop polls [`ShutdownSignals::received`]
//! (say after each `crossterm::event::poll` with a timeout of 100 ms or less), drops its terminal guard
//! and exits with [`ShutdownSignal::exit_code`].
//!
//! In raw mode the terminal does not turn Ctrl-C into SIGINT: it arrives as a key event, which the event
//! loop must treat as quit itself ([`is_ctrl_c`]). SIGINT still comes from `kill -INT`.
//!
//! An event loop may never poll again: crossterm 0.29's `event::poll` spins forever, ignoring its
//! timeout, once the tty is gone (crossterm issue #793), which is exactly the SIGHUP case. So a watchdog
//! thread also sees each shutdown signal and, if the process is still alive a grace period later, removes
//! the temporary files still being written (`unfinished_files`), restores the terminal and exits with
//! 128 + signal itself. Shutdown signals therefore always end the process.
//!
//! A second signal of the same kind, while the first is still unhandled, exits at once with 128 + signal
//! and without restoring.

use std::io;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::mpsc::{self, RecvTimeoutError};
use std::thread;
use std::time::Duration;

use crossterm::event::{KeyCode, KeyEvent, KeyEventKind, KeyModifiers};
use signal_hook::SigId;
use signal_hook::consts::{
    SIGALRM, SIGHUP, SIGINT, SIGPROF, SIGQUIT, SIGTERM, SIGUSR1, SIGUSR2, SIGVTALRM, SIGXCPU,
    SIGXFSZ,
};
use signal_hook::flag;
use signal_hook::iterator::Signals;
use signal_hook::iterator::backend::Handle;

use super::guard::restore_terminal;

/// A signal asking the workbench to end.
#[derive(Clone, Copy, Debug, PartialEq, Eq, strum::VariantArray)]
pub enum ShutdownSignal {
    Interrupt,
    Terminate,
    HangUp,
    Quit,
    User1,
    User2,
    Alarm,
    VirtualAlarm,
    Profiling,
    CpuTimeLimit,
    FileSizeLimit,
}

impl ShutdownSignal {
    pub const ALL: &'static [ShutdownSignal] = <ShutdownSignal as strum::VariantArray>::VARIANTS;

    pub fn number(self) -> i32 {
        match self {
            ShutdownSignal::Interrupt => SIGINT,
            ShutdownSignal::Terminate => SIGTERM,
            ShutdownSignal::HangUp => SIGHUP,
            ShutdownSignal::Quit => SIGQUIT,
            ShutdownSignal::User1 => SIGUSR1,
            ShutdownSignal::User2 => SIGUSR2,
            ShutdownSignal::Alarm => SIGALRM,
            ShutdownSignal::VirtualAlarm => SIGVTALRM,
            ShutdownSignal::Profiling => SIGPROF,
            ShutdownSignal::CpuTimeLimit => SIGXCPU,
            ShutdownSignal::FileSizeLimit => SIGXFSZ,
        }
    }

    /// The shell's convention for a process ended by this signal.
    pub fn exit_code(self) -> i32 {
        128 + self.number()
    }

    fn from_number(number: usize) -> Option<ShutdownSignal> {
        Self::ALL
            .iter()
            .copied()
            .find(|s| s.number() as usize == number)
    }
}

/// How long the event loop has to act on a shutdown signal before the watchdog ends the process.
pub const DEFAULT_GRACE: Duration = Duration::from_millis(500);

/// The installed handlers and watchdog; dropping this removes them (the default actions apply again).
#[derive(Debug)]
pub struct ShutdownSignals {
    received: Arc<AtomicUsize>,
    ids: Vec<SigId>,
    watchdog: Handle,
    /// Dropping it tells a watchdog in its grace period to stand down.
    _cancel: mpsc::Sender<()>,
    /// Set on drop: the terminal watcher, if any, stops.
    unwatch: Arc<AtomicBool>,
}

impl ShutdownSignals {
    /// Installs the handlers for every [`ShutdownSignal`], with the [`DEFAULT_GRACE`] watchdog.
    pub fn register() -> io::Result<ShutdownSignals> {
        Self::register_with_grace(DEFAULT_GRACE)
    }

    /// [`ShutdownSignals::register`] with the watchdog waiting `grace` after a signal.
    pub fn register_with_grace(grace: Duration) -> io::Result<ShutdownSignals> {
        let (cancel, cancelled) = mpsc::channel();
        let watchdog = spawn_watchdog(grace, cancelled)?;
        let received = Arc::new(AtomicUsize::new(0));
        let mut signals = ShutdownSignals {
            received: Arc::clone(&received),
            ids: Vec::new(),
            watchdog,
            _cancel: cancel,
            unwatch: Arc::new(AtomicBool::new(false)),
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

    /// Watches stdout, a terminal now, and raises SIGHUP on this process when it stops being one.
    ///
    /// A tty hung up while its hang-up signal went elsewhere (a parent that catches SIGHUP keeps
    /// the session, and the kernel signals only the session leader) leaves reads at end-of-file
    /// forever, and crossterm's reader spins on that without returning (so the event loop cannot
    /// notice). Every ioctl on a hung-up tty fails, so `is_terminal` turns false; the raised
    /// SIGHUP then ends the workbench as a real one would (restored terminal, exit status 129).
    pub fn watch_terminal(&self) -> io::Result<()> {
        use std::io::IsTerminal;
        if !io::stdout().is_terminal() {
            return Ok(());
        }
        let unwatch = Arc::clone(&self.unwatch);
        thread::Builder::new()
            .name("terminal-watch".into())
            .spawn(move || {
                while !unwatch.load(Ordering::SeqCst) {
                    if !io::stdout().is_terminal() {
                        let _ = signal_hook::low_level::raise(SIGHUP);
                        return;
                    }
                    thread::sleep(TERMINAL_WATCH);
                }
            })?;
        Ok(())
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
        self.watchdog.close();
        self.unwatch.store(true, Ordering::SeqCst);
    }
}

/// How often the terminal watcher looks.
const TERMINAL_WATCH: Duration = Duration::from_millis(250);

/// A thread that, on the first shutdown signal, gives the event loop `grace` to exit and then restores
/// the terminal and exits itself; it stands down when `cancelled` disconnects.
fn spawn_watchdog(grace: Duration, cancelled: mpsc::Receiver<()>) -> io::Result<Handle> {
    let numbers = ShutdownSignal::ALL
        .iter()
        .copied()
        .map(ShutdownSignal::number);
    let mut signals = Signals::new(numbers)?;
    let handle = signals.handle();
    thread::Builder::new()
        .name("shutdown-watchdog".into())
        .spawn(move || {
            let Some(number) = signals.forever().next() else {
                return;
            };
            if let Err(RecvTimeoutError::Timeout) = cancelled.recv_timeout(grace) {
                crate::unfinished_files::remove_all();
                restore_terminal();
                std::process::exit(128 + number);
            }
        })?;
    Ok(handle)
}

/// Whether `key` is Ctrl-C, the interrupt key that raw mode delivers as a key instead of SIGINT.
pub fn is_ctrl_c(key: &KeyEvent) -> bool {
    key.kind != KeyEventKind::Release
        && key.modifiers.contains(KeyModifiers::CONTROL)
        && matches!(key.code, KeyCode::Char('c') | KeyCode::Char('C'))
}
