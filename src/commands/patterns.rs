//! `bumpwork patterns [NAME]`: the shipped patterns, each with its kind and what its file says of
//! itself, then its parameters with default and range; or one pattern's file.

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
            super::sanitized(name),
            names.join(", ")
        ))
    })?;
    super::write_bytes(source.as_bytes())
}

/// `name (kind): first comment line`, then `    param=default (min..max)…` below it.
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
    let about = source
        .lines()
        .find_map(|line| line.strip_prefix('#'))
        .map_or("", str::trim);
    let params = match params.is_empty() {
        true => "no parameters".to_string(),
        false => params.join("  "),
    };
    Ok(format!("{name} ({kind}): {about}\n    {params}"))
}
