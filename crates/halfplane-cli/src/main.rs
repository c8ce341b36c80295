//! The `halfplane` command: parses the arguments, runs the command and maps the outcome to the
//! exit code. Everything else is in the `halfplane_cli` library (`commands::*`).

use clap::Parser;
use halfplane_cli::args::Cli;
use halfplane_cli::commands;
use halfplane_cli::output::{note, StdoutError};
use std::io;
use std::process::ExitCode;

/// Exit 0 on success, 2 on any error. A closed stdout pipe is a success, quietly: the reader
/// stopped on purpose (`| head`), as it would for `cat`; a shell would otherwise report 141
/// (SIGPIPE), which Rust programs do not receive (the runtime ignores the signal).
fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        // Usage errors go to stderr (exit 2); --help and --version go to stdout (exit 0), where
        // a full disk is an error like any other output (clap's own exit would ignore it).
        Err(e) => {
            let printed = e.print();
            let args: Vec<String> = std::env::args().collect();
            if let Some(valid) = halfplane_cli::args::valid_subcommands(&e, &args) {
                note(&valid);
            }
            return match printed {
                _ if e.use_stderr() => ExitCode::from(2),
                Err(io) if io.kind() != io::ErrorKind::BrokenPipe => {
                    note(&format!("error: {}", StdoutError(io)));
                    ExitCode::from(2)
                }
                _ => ExitCode::SUCCESS,
            };
        }
    };
    match commands::run(&cli.command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => match e.downcast_ref::<StdoutError>() {
            Some(StdoutError(io)) if io.kind() == io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
            _ => {
                note(&format!("error: {e:#}"));
                if let Some(h) = commands::hint(&e, &cli.command) {
                    note(&format!("hint: {h}"));
                }
                ExitCode::from(2)
            }
        },
    }
}
