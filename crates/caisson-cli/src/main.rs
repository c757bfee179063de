//! The `caisson` command-line tool: clap definitions → validated options → library → exporters.
//!
//! Exit codes: 0 success, 2 bad input (scenario, file, option), 1 a run that failed
//! (non-convergence) or an I/O error while writing results.

mod cli;
mod cmd_campaign;
mod cmd_design;
mod cmd_fragility;
mod cmd_loads;
mod cmd_run;
mod cmd_spectrum;
mod cmd_validation;
mod output;
mod plot;
mod train_out;

use clap::Parser;
use std::process::ExitCode;

/// An error that is the user's input: printed as `Error: ...`, exit code 2.
#[derive(Debug)]
pub struct InputError(pub String);

impl std::fmt::Display for InputError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}
impl std::error::Error for InputError {}

/// Wrap a library scenario error as an input error.
pub fn input_err(e: impl std::fmt::Display) -> anyhow::Error {
    anyhow::Error::new(InputError(e.to_string()))
}

fn main() -> ExitCode {
    let args = match cli::Cli::try_parse() {
        Ok(a) => a,
        Err(e) => {
            let code = if e.use_stderr() { 2 } else { 0 };
            let _ = e.print();
            return ExitCode::from(code);
        }
    };
    let result = match args.command {
        cli::Command::Run(a) => cmd_run::run(a),
        cli::Command::Spectrum(a) => cmd_spectrum::run(a),
        cli::Command::Loads(a) => cmd_loads::run(a),
        cli::Command::Campaign(a) => cmd_campaign::run(a),
        cli::Command::Validation(a) => cmd_validation::run(a),
        cli::Command::Design(a) => cmd_design::run(a),
        cli::Command::Fragility(a) => cmd_fragility::run(a),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            if e.downcast_ref::<InputError>().is_some() {
                eprintln!("Error: {e}");
                ExitCode::from(2)
            } else {
                eprintln!("Error: {e:#}");
                ExitCode::from(1)
            }
        }
    }
}
