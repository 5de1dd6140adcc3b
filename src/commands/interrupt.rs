//! Ctrl-C, SIGTERM and SIGHUP during a long render: noted, so the render stops between groups of
//! passes and removes its temporary file instead of dying with a partial one.

use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};

pub struct Interrupt {
    signal: Arc<AtomicUsize>,
}

impl Interrupt {
    /// Starts noting the signals (until the process ends).
    pub fn watch() -> Interrupt {
        let signal = Arc::new(AtomicUsize::new(0));
        for s in [SIGINT, SIGTERM, SIGHUP] {
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
