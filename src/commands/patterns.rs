//! `bumpwork patterns [NAME]`: the shipped patterns, each with its kind and the first sentence its
//! file says of itself, then its parameters with default and range; or one pattern's file.

use bumpwork::Error;
use bumpwork::pattern::{BUILTINS, OutputKind, Pattern};

#[derive(clap::Args)]
pub struct PatternsArgs {
    /// Print this shipped pattern's file instead of the list.
    name: Option<String>,
}

pub fn run(args: PatternsArgs) -> Result<(), Error> {
    match args.name {
        Some(name) => print_file(&name),
        None => {
            for (name, source) in BUILTINS {
                say!("{}", describe(name, source)?);
            }
            Ok(())
        }
    }
}

fn print_file(name: &str) -> Result<(), Error> {
    let source = bumpwork::pattern::builtin(name).ok_or_else(|| {
        let names: Vec<&str> = BUILTINS.iter().map(|(n, _)| *n).collect();
        Error::InvalidArgument(format!(
            "no shipped pattern is called '{}'; they are {}",
            bumpwork::diagnostic::shown_input(name),
            names.join(", ")
        ))
    })?;
    super::write_bytes(source.as_bytes())
}

/// `name (kind): the file's first sentence`, then `    param=default (min..max)…` below it.
fn describe(name: &str, source: &str) -> Result<String, Error> {
    let pattern = Pattern::compile(source, &format!("{name}.pat"))
        .map_err(|e| Error::Diagnostic(e.to_string()))?;
    let kind = match pattern.output() {
        OutputKind::Height => "height",
        OutputKind::Slope => "slope",
        OutputKind::Color => "colour",
    };
    let params: Vec<String> = pattern
        .params()
        .iter()
        .map(|p| format!("{}={} ({}..{})", p.name, p.default, p.min, p.max))
        .collect();
    let params = match params.is_empty() {
        true => "no parameters".to_string(),
        false => params.join("  "),
    };
    let about = wrapped(&format!("{name} ({kind}): {}", summary(source)));
    Ok(format!("{about}\n    {params}"))
}

/// Lines of the list are at most this wide; continuation lines are indented by four.
const WIDTH: usize = 96;

/// The first sentence of the comment a pattern file opens with, however many lines it spans.
/// The comment ends at a line that is not a comment or is indented (quoted code).
fn summary(source: &str) -> String {
    let mut words: Vec<&str> = Vec::new();
    for line in source.lines() {
        let Some(text) = line.strip_prefix('#') else {
            break;
        };
        if text.starts_with("  ") {
            break;
        }
        for word in text.split_whitespace() {
            words.push(word);
            if word.ends_with('.') {
                return words.join(" ");
            }
        }
    }
    words.join(" ")
}

/// `text` broken at spaces into lines of at most `WIDTH` (a longer word stands alone).
fn wrapped(text: &str) -> String {
    let mut out = String::new();
    let mut line_len = 0;
    for word in text.split(' ') {
        if line_len > 0 && line_len + 1 + word.chars().count() > WIDTH {
            out.push_str("\n    ");
            line_len = 4;
        } else if line_len > 0 {
            out.push(' ');
            line_len += 1;
        }
        out.push_str(word);
        line_len += word.chars().count();
    }
    out
}
