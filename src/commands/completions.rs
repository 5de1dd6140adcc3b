//! `bumpwork completions SHELL`: the shell's completion script for every command and option,
//! printed for the user to install (`bumpwork completions bash > ~/.local/share/bash-completion/completions/bumpwork`).

use bumpwork::Error;

#[derive(clap::Args)]
pub struct CompletionsArgs {
    /// The shell to complete in.
    #[arg(value_enum)]
    shell: clap_complete::Shell,
}

pub fn run(args: CompletionsArgs, command: &mut clap::Command) -> Result<(), Error> {
    let mut script = Vec::new();
    clap_complete::generate(args.shell, command, "bumpwork", &mut script);
    super::write_bytes(&script)
}
