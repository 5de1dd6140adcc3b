//! The command line: parses arguments and calls the library. Exit status 0 on success, 1 on any
//! user error with one message on stderr.

#[macro_use]
mod commands;

use bumpwork::Error;
use bumpwork::diagnostic::sanitize_lines;
use clap::{CommandFactory, Parser, Subcommand};
use std::process::ExitCode;

#[derive(Parser)]
#[command(
    name = "bumpwork",
    version,
    about = "Bump maps and texture maps, rasterized on the CPU"
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand)]
enum Command {
    /// Render a built-in scene or a scene file to a PNG still.
    Render(Box<commands::render::RenderArgs>),
    /// Bake a pattern or a scene object's bump and colour into PNG texture maps (height, normal,
    /// colour) for other programs.
    Bake(commands::bake::BakeArgs),
    /// Render every built-in scene to a still and a contact sheet of them all.
    Gallery(commands::gallery::GalleryArgs),
    /// Render a scene at every combination of values of its settings, with a labelled contact
    /// sheet and an index.
    Sweep(commands::sweep::SweepArgs),
    /// Make a contact sheet of the stills in a directory (after shards), naming missing frames.
    Sheet(commands::sheet::SheetArgs),
    /// Check pattern files, scene files and images without rendering.
    Check(commands::check::CheckArgs),
    /// List the shipped patterns (kind, parameters, what each is), or print one's file.
    Patterns(commands::patterns::PatternsArgs),
    /// Time every quality preset and knob on standard scenes and measure their error against
    /// the exact reference.
    Bench(commands::bench::BenchArgs),
    /// Open the terminal workbench on scenes (default: every built-in scene).
    View(commands::view::ViewArgs),
    /// Print the completion script for a shell (bash, zsh, fish, elvish, powershell).
    Completions(commands::completions::CompletionsArgs),
    /// Print the manual page (roff): `bumpwork man > bumpwork.1`.
    Man,
}

fn main() -> ExitCode {
    restore_default_sigpipe();
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if !e.use_stderr() => {
            let _ = e.print();
            return ExitCode::SUCCESS;
        }
        Err(mut e) => {
            shorten_quoted_arguments(&mut e);
            // Plain text (no styling), escaped: an argument may hold terminal controls.
            let rendered = sanitize_lines(&e.render().to_string());
            let (line, hints) = commands::argument_error::one_line(&rendered);
            eprintln!("bumpwork: error: {line}");
            if !hints.is_empty() {
                eprintln!("{hints}");
            }
            return ExitCode::FAILURE;
        }
    };
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(Error::Reported) => ExitCode::FAILURE,
        Err(Error::Interrupted(signal)) => {
            eprintln!("bumpwork: {}", Error::Interrupted(signal));
            ExitCode::from(128 + signal as u8)
        }
        Err(e) => {
            // Messages escape what they quote; this is the backstop for any that does not.
            eprintln!("bumpwork: error: {}", sanitize_lines(&e.to_string()));
            ExitCode::FAILURE
        }
    }
}

/// Cuts the arguments clap's message quotes (a value it refused, an unknown argument) to the
/// length file diagnostics quote, so a 100 000-character argument is not echoed whole.
fn shorten_quoted_arguments(e: &mut clap::Error) {
    use clap::error::{ContextKind, ContextValue};
    for kind in [
        ContextKind::InvalidValue,
        ContextKind::InvalidArg,
        ContextKind::InvalidSubcommand,
    ] {
        if let Some(ContextValue::String(text)) = e.get(kind) {
            let short = bumpwork::diagnostic::shown_input(text);
            e.insert(kind, ContextValue::String(short));
        }
    }
}

/// Rust ignores SIGPIPE, so a closed pipe would be an error on every later write; with the
/// default action `bumpwork check … | head -1` ends quietly, as coreutils do.
fn restore_default_sigpipe() {
    #[cfg(unix)]
    // SAFETY: setting a signal's disposition to the default before any thread starts.
    unsafe {
        libc::signal(libc::SIGPIPE, libc::SIG_DFL);
    }
}

fn run(cli: Cli) -> Result<(), Error> {
    bumpwork::memory_budget::check_budget_var().map_err(Error::InvalidArgument)?;
    match cli.command {
        Some(Command::Render(args)) => commands::render::run(*args),
        Some(Command::Bake(args)) => commands::bake::run(args),
        Some(Command::Check(args)) => commands::check::run(args),
        Some(Command::Patterns(args)) => commands::patterns::run(args),
        Some(Command::Gallery(args)) => commands::gallery::run(args),
        Some(Command::Sweep(args)) => commands::sweep::run(args),
        Some(Command::Sheet(args)) => commands::sheet::run(args),
        Some(Command::View(args)) => commands::view::run(args),
        Some(Command::Completions(args)) => commands::completions::run(args, &mut Cli::command()),
        Some(Command::Man) => commands::man_page::run(Cli::command()),
        Some(Command::Bench(args)) => commands::bench::run(args),
        None => commands::view::run(Default::default()),
    }
}
