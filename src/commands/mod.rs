//! One file per subcommand; `main.rs` only parses and dispatches.

/// Prints a line to standard output, as `println!` does, but a failed write (a full disk) is
/// the command's error instead of a panic. A closed pipe ends the process by SIGPIPE, quietly,
/// as coreutils do (`main` restores its default action).
macro_rules! say {
    ($($arg:tt)*) => {
        $crate::commands::write_line(format_args!($($arg)*))?
    };
}

pub mod argument_error;
pub mod bake;
mod bake_recipe;
pub mod bench;
pub mod check;
pub mod completions;
pub mod gallery;
mod interrupt;
pub mod man_page;
pub mod patterns;
mod progress;
pub mod render;
mod shard;
pub mod sheet;
pub mod sweep;
pub mod view;

/// Largest output side accepted (stills are rendered in bands, so memory does not grow with it).
pub use bumpwork::still::MAX_SIDE;

pub fn write_line(line: std::fmt::Arguments) -> Result<(), bumpwork::Error> {
    write_bytes(format!("{line}\n").as_bytes())
}

/// Writes `bytes` to standard output; a failed write is the command's error, as in `say!`.
pub fn write_bytes(bytes: &[u8]) -> Result<(), bumpwork::Error> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    out.write_all(bytes)
        .and_then(|()| out.flush())
        .map_err(|e| {
            bumpwork::Error::write(
                std::path::Path::new("standard output"),
                bumpwork::bounded_read::io_words(&e),
            )
        })
}

/// Text from a file or the command line, safe to show in a terminal.
pub fn sanitized(text: &str) -> String {
    bumpwork::diagnostic::sanitize(text).into_owned()
}

pub fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let expected = || {
        format!(
            "expected WIDTHxHEIGHT with each side 1..={MAX_SIDE}, like 1920x1080; got '{}'",
            bumpwork::diagnostic::shown_input(text)
        )
    };
    let (w, h) = text.split_once(['x', 'X']).ok_or_else(expected)?;
    let side = |s: &str| {
        s.trim()
            .parse::<u32>()
            .ok()
            .filter(|n| (1..=MAX_SIDE).contains(n))
    };
    match (side(w), side(h)) {
        (Some(w), Some(h)) => Ok((w, h)),
        _ => Err(expected()),
    }
}
