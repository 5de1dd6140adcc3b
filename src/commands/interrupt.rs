//! Ctrl-C, SIGTERM, SIGHUP and every other signal whose default is to end the process, during a
//! long render: noted, so the render stops between groups of passes and removes its temporary
//! file instead of dying with a partial one. (SIGKILL cannot be caught; SIGPIPE keeps its
//! default, which `main` restores: a closed pipe is never written to through a temporary file.)

use signal_hook::consts::{
    SIGALRM, SIGHUP, SIGINT, SIGPROF, SIGQUIT, SIGTERM, SIGUSR1, SIGUSR2, SIGVTALRM, SIGXCPU,
    SIGXFSZ,
};
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};

pub struct Interrupt {
    signal: Arc<AtomicUsize>,
}

impl Interrupt {
    /// Starts noting the signals (until the process ends).
    pub fn watch() -> Interrupt {
        let signal = Arc::new(AtomicUsize::new(0));
        let terminating = [
            SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM, SIGPROF,
            SIGXCPU, SIGXFSZ,
        ];
        for s in terminating {
            // If a handler cannot be installed the default action stays: the process dies and
            // the temporary file is left (never the destination).
            let _ = signal_hook::flag::register_usize(s, Arc::clone(&signal), s as usize);
        }
        Interrupt { signal }
    }

    /// The signal received, if any.
    pub fn received(&self) -> Option<i32> {
        match self.signal.load(Ordering::Relaxed) {
            0 => None,
            s => Some(s as i32),
        }
    }
}
