//! `postc completions SHELL` and `postc man DIR`: the shell completions
//! (clap_complete) and the man pages (clap_mangen) of the command line,
//! made from the same definitions the parser reads, so they say what the
//! binary accepts.

use std::path::PathBuf;

use clap::CommandFactory;

use super::{Cli, Failed, fail};

#[derive(clap::Args, Debug)]
pub struct CompletionsArgs {
    /// The shell: bash, zsh, fish, elvish or powershell.
    ///
    /// bash: `postc completions bash > ~/.local/share/bash-completion/completions/postc`;
    /// zsh: into a folder of `$fpath` as `_postc`; fish: `~/.config/fish/completions/postc.fish`.
    #[arg(value_enum)]
    shell: ShellArg,
}

/// The shells `completions` writes for.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum ShellArg {
    /// GNU bash (bash-completion).
    Bash,
    /// zsh (a `_postc` file on `$fpath`).
    Zsh,
    /// fish.
    Fish,
    /// elvish.
    Elvish,
    /// PowerShell (`Register-ArgumentCompleter`).
    Powershell,
}

impl From<ShellArg> for clap_complete::Shell {
    fn from(shell: ShellArg) -> clap_complete::Shell {
        match shell {
            ShellArg::Bash => clap_complete::Shell::Bash,
            ShellArg::Zsh => clap_complete::Shell::Zsh,
            ShellArg::Fish => clap_complete::Shell::Fish,
            ShellArg::Elvish => clap_complete::Shell::Elvish,
            ShellArg::Powershell => clap_complete::Shell::PowerShell,
        }
    }
}

#[derive(clap::Args, Debug)]
pub struct ManArgs {
    /// The folder the pages are written to (made if missing): `postc.1`, and
    /// `postc-SUBCOMMAND.1` for each subcommand (`postc-toolpath-gen.1`).
    ///
    /// Read one with `man -l DIR/postc-post.1`, or put DIR under a `man1`
    /// folder of `$MANPATH`.
    dir: PathBuf,
}

/// Prints the completion script of `shell` on standard output.
pub fn completions(args: CompletionsArgs) -> Result<(), Failed> {
    let mut command = Cli::command();
    clap_complete::generate(clap_complete::Shell::from(args.shell), &mut command, "postc", &mut std::io::stdout());
    Ok(())
}

/// Writes one man page per command and subcommand into `dir`.
pub fn man(args: ManArgs) -> Result<(), Failed> {
    let mut sources = postc_report::source_map();
    std::fs::create_dir_all(&args.dir).map_err(|e| fail(&mut sources, super::outputs::cannot_write(&args.dir, &e)))?;
    let mut command = Cli::command();
    command.build();
    let mut pages = Vec::new();
    pages_of(&command, "postc", &mut pages);
    let batch = super::outputs::Batch::default();
    for (name, page) in &pages {
        batch.stage_bytes(&args.dir.join(format!("{name}.1")), page).map_err(|d| fail(&mut sources, d))?;
    }
    batch.commit(&[], None).map_err(|d| fail(&mut sources, d))?;
    super::report::wrote(format_args!("{} man pages to {}", pages.len(), args.dir.display()));
    Ok(())
}

/// The page of `command` (named `name`) and of each of its subcommands.
fn pages_of(command: &clap::Command, name: &str, out: &mut Vec<(String, Vec<u8>)>) {
    let mut page = Vec::new();
    let titled = command.clone().name(name.to_string());
    // Rendering into memory cannot fail: a `Vec` takes every write.
    let _ = clap_mangen::Man::new(titled).render(&mut page);
    out.push((name.to_string(), page));
    for sub in command.get_subcommands().filter(|s| s.get_name() != "help") {
        pages_of(sub, &format!("{name}-{}", sub.get_name()), out);
    }
}
