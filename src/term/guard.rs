//! Entering and leaving the workbench's terminal state (raw mode, alternate screen, hidden cursor,
//! optional mouse capture), restored on drop, on panic and on the shutdown signals.
//!
//! What is currently changed is kept in one process-wide set of flags: the panic hook and the signal
//! path have no guard to ask, and taking the flags atomically is what makes restoring twice harmless.

use std::io::{self, Write};
use std::sync::Once;
use std::sync::atomic::{AtomicU8, Ordering};

use crossterm::cursor::{Hide, Show};
use crossterm::event::{DisableMouseCapture, EnableMouseCapture};
use crossterm::style::ResetColor;
use crossterm::terminal::{
    EnterAlternateScreen, LeaveAlternateScreen, disable_raw_mode, enable_raw_mode,
};
use crossterm::{Command, queue};

use super::ansi_writer::SYNC_END;

/// Terminal state changes, as bits.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TerminalModes(u8);

impl TerminalModes {
    pub const RAW: TerminalModes = TerminalModes(1);
    pub const ALTERNATE_SCREEN: TerminalModes = TerminalModes(2);
    pub const HIDDEN_CURSOR: TerminalModes = TerminalModes(4);
    pub const MOUSE_CAPTURE: TerminalModes = TerminalModes(8);
    pub const NONE: TerminalModes = TerminalModes(0);
    pub const ALL: TerminalModes = TerminalModes(15);

    pub fn contains(self, other: TerminalModes) -> bool {
        self.0 & other.0 == other.0
    }

    pub fn is_empty(self) -> bool {
        self.0 == 0
    }
}

impl std::ops::BitOr for TerminalModes {
    type Output = TerminalModes;
    fn bitor(self, other: TerminalModes) -> TerminalModes {
        TerminalModes(self.0 | other.0)
    }
}

/// The modes set and not yet restored.
static ACTIVE: AtomicU8 = AtomicU8::new(0);

fn mark_active(modes: TerminalModes) {
    ACTIVE.fetch_or(modes.0, Ordering::SeqCst);
}

/// Takes the active modes, leaving none: whoever takes them restores them, so nobody restores twice.
fn take_active() -> TerminalModes {
    TerminalModes(ACTIVE.swap(0, Ordering::SeqCst))
}

/// Writes the sequences that set the screen `modes` (all but raw mode, which is not a sequence).
pub fn write_enter_sequence(out: &mut impl Write, modes: TerminalModes) -> io::Result<()> {
    queue_if(
        out,
        modes.contains(TerminalModes::ALTERNATE_SCREEN),
        EnterAlternateScreen,
    )?;
    queue_if(out, modes.contains(TerminalModes::HIDDEN_CURSOR), Hide)?;
    queue_if(
        out,
        modes.contains(TerminalModes::MOUSE_CAPTURE),
        EnableMouseCapture,
    )?;
    out.flush()
}

/// Writes the sequences that undo `modes`, first ending any synchronized update and colour a frame
/// interrupted by a panic may have left open.
pub fn write_restore_sequence(out: &mut impl Write, modes: TerminalModes) -> io::Result<()> {
    out.write_all(SYNC_END)?;
    super::graphics::kitty::delete_if_shown(out)?;
    queue!(out, ResetColor)?;
    queue_if(
        out,
        modes.contains(TerminalModes::MOUSE_CAPTURE),
        DisableMouseCapture,
    )?;
    queue_if(out, modes.contains(TerminalModes::HIDDEN_CURSOR), Show)?;
    queue_if(
        out,
        modes.contains(TerminalModes::ALTERNATE_SCREEN),
        LeaveAlternateScreen,
    )?;
    out.flush()
}

fn queue_if(out: &mut impl Write, condition: bool, command: impl Command) -> io::Result<()> {
    if condition {
        queue!(out, command)?;
    }
    Ok(())
}

/// Restores whatever [`TerminalGuard::enter`] changed and is still changed, writing to `out`. Safe to
/// call any number of times, from a panic hook or after the terminal has gone: errors are ignored, since
/// there is nobody left to tell (a write to a hung-up tty fails with EIO).
pub fn restore_terminal_to(out: &mut impl Write) {
    let modes = take_active();
    if modes.is_empty() {
        return;
    }
    // Raw mode first: it is an ioctl, not a write, so it works even if the writes below block or fail.
    if modes.contains(TerminalModes::RAW) {
        let _ = disable_raw_mode();
    }
    let _ = write_restore_sequence(out, modes);
}

/// [`restore_terminal_to`] standard output.
pub fn restore_terminal() {
    restore_terminal_to(&mut io::stdout());
}

/// The workbench's hold on the terminal; dropping it restores the terminal.
#[derive(Debug)]
pub struct TerminalGuard {
    _private: (),
}

impl TerminalGuard {
    /// Enters raw mode and the alternate screen, hides the cursor and, if asked, captures the mouse; also
    /// installs the restoring panic hook (once per process). On an error, whatever was set is undone.
    pub fn enter(mouse_capture: bool) -> io::Result<TerminalGuard> {
        install_panic_hook();
        let guard = TerminalGuard { _private: () };
        take_terminal(mouse_capture)?;
        Ok(guard)
    }

    /// Restores the terminal now (dropping the guard later does nothing more).
    pub fn restore(&mut self) {
        restore_terminal();
    }
}

impl Drop for TerminalGuard {
    fn drop(&mut self) {
        restore_terminal();
    }
}

/// Ctrl-Z: gives the terminal back as on quitting, stops the process (SIGSTOP, as the shell's job
/// control expects), and when continued (`fg`) takes the terminal again with the same modes. The
/// caller draws everything again: the shell has drawn over the screen meanwhile.
pub fn suspend_and_resume(mouse_capture: bool) -> io::Result<()> {
    restore_terminal();
    // SAFETY: raising a signal at our own process; SIGSTOP cannot be caught, so this returns
    // only once the process is continued.
    unsafe {
        libc::raise(libc::SIGSTOP);
    }
    take_terminal(mouse_capture)
}

/// Sets the workbench's modes, each marked active before it is set: a half-written enter
/// sequence is still worth undoing.
fn take_terminal(mouse_capture: bool) -> io::Result<()> {
    enable_raw_mode()?;
    mark_active(TerminalModes::RAW);
    let mut screen = TerminalModes::ALTERNATE_SCREEN | TerminalModes::HIDDEN_CURSOR;
    if mouse_capture {
        screen = screen | TerminalModes::MOUSE_CAPTURE;
    }
    mark_active(screen);
    write_enter_sequence(&mut io::stdout(), screen)
}

/// Chains a hook that restores the terminal before the previous hook prints the panic, so the message
/// lands on the normal screen with a visible cursor instead of vanishing with the alternate screen.
pub fn install_panic_hook() {
    static INSTALL: Once = Once::new();
    INSTALL.call_once(|| {
        let previous = std::panic::take_hook();
        std::panic::set_hook(Box::new(move |info| {
            restore_terminal();
            previous(info);
        }));
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    // One test: the active modes are process-wide, and parallel tests would take each other's.
    #[test]
    fn restoring_twice_writes_once_and_a_dead_terminal_does_not_panic() {
        mark_active(TerminalModes::ALTERNATE_SCREEN | TerminalModes::HIDDEN_CURSOR);
        let mut first = Vec::new();
        restore_terminal_to(&mut first);
        let first = String::from_utf8(first).unwrap();
        assert!(first.contains("\x1b[?1049l"), "{first:?}");
        assert!(first.contains("\x1b[?25h"), "{first:?}");
        let mut second = Vec::new();
        restore_terminal_to(&mut second);
        assert!(second.is_empty());

        struct DeadTerminal;
        impl Write for DeadTerminal {
            fn write(&mut self, _: &[u8]) -> io::Result<usize> {
                Err(io::Error::from_raw_os_error(5)) // EIO, as after SIGHUP
            }
            fn flush(&mut self) -> io::Result<()> {
                Err(io::Error::from_raw_os_error(5))
            }
        }
        mark_active(TerminalModes::ALTERNATE_SCREEN);
        restore_terminal_to(&mut DeadTerminal);
        assert!(take_active().is_empty());
    }
}
