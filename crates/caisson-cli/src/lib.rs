//! The `caisson` command-line tool as a library: clap definitions → validated options → library →
//! exporters. The binary (`main.rs`) calls [`main_entry`]; the Python package calls
//! [`cmd_report::run`] for `caisson.report` (the calculation note is the CLI's exporter).
//!
//! Exit codes: 0 success, 2 bad input (scenario, file, option), 1 a run that failed
//! (non-convergence) or an I/O error while writing results, 130 stopped by Ctrl-C. Every error is
//! one message on stderr that begins with `Error:` (the argument parser's included).

mod checkpoint_file;
pub mod cli;
mod cmd_campaign;
mod cmd_design;
mod cmd_fragility;
mod cmd_loads;
mod cmd_merge;
pub mod cmd_report;
mod cmd_run;
mod cmd_size;
mod cmd_spectrum;
mod cmd_validation;
mod csv_rows;
mod history_out;
mod output;
mod plot;
mod report_html;
mod train_out;
mod work;

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

/// A run stopped by Ctrl-C that stopped cleanly: printed as `Error: ...` (what was kept),
/// exit code 130.
#[derive(Debug)]
pub struct Interrupted(pub String);

impl std::fmt::Display for Interrupted {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}
impl std::error::Error for Interrupted {}

/// Ctrl-C (SIGINT). By default the process stops at once: it removes its temporary files (no
/// output file is ever half-written: each is renamed into place whole) and exits with 130. A
/// command that keeps work as it goes (`design` with a checkpoint) asks for a graceful stop with
/// [`interrupt::graceful`]: the first Ctrl-C sets a flag that it polls, a second one stops at once.
pub mod interrupt {
    use std::sync::atomic::{AtomicBool, Ordering};

    static INTERRUPTED: AtomicBool = AtomicBool::new(false);
    static GRACEFUL: AtomicBool = AtomicBool::new(false);

    /// Exit code of a run stopped by Ctrl-C (128 + SIGINT, as the shells report it).
    pub const EXIT_CODE: u8 = 130;

    /// Install the handler (once, at start).
    pub fn install() {
        // If it cannot be installed (no signals here), Ctrl-C keeps its default action.
        let _ = ctrlc::set_handler(|| {
            let again = INTERRUPTED.swap(true, Ordering::SeqCst);
            if GRACEFUL.load(Ordering::SeqCst) && !again {
                eprintln!(
                    "\nInterrupted: finishing the work in progress and keeping it (Ctrl-C again to stop at once)"
                );
                return;
            }
            let kept = if GRACEFUL.load(Ordering::SeqCst) {
                "stopped at once; the checkpoint keeps every finished life (a line cut short is dropped by --resume)"
            } else {
                "nothing was kept; no output file was left half-written"
            };
            eprintln!("\nError: interrupted (Ctrl-C): {kept}");
            crate::output::remove_pending_and_exit(EXIT_CODE as i32)
        });
    }

    /// The command stops by itself on Ctrl-C (it polls [`requested`]).
    pub fn graceful() {
        GRACEFUL.store(true, Ordering::SeqCst);
    }

    /// Whether Ctrl-C was pressed.
    pub fn requested() -> bool {
        INTERRUPTED.load(Ordering::SeqCst)
    }

    /// One item done on `pb`; whether the run goes on (not after Ctrl-C): the per-life hook of
    /// the drivers' runs.
    pub fn tick(pb: &indicatif::ProgressBar) -> std::ops::ControlFlow<()> {
        pb.inc(1);
        if requested() {
            std::ops::ControlFlow::Break(())
        } else {
            std::ops::ControlFlow::Continue(())
        }
    }
}

/// The argument parser's message as every other error: `Error: ...` (clap writes `error: ...`).
fn parser_error(e: &clap::Error) -> String {
    let text = e.render().to_string();
    match text.strip_prefix("error:") {
        Some(rest) => format!("Error:{rest}"),
        None => format!("Error: a command is required\n\n{text}"),
    }
}

/// Wrap a library scenario error as an input error.
pub fn input_err(e: impl std::fmt::Display) -> anyhow::Error {
    anyhow::Error::new(InputError(e.to_string()))
}

/// The `caisson` command: parse the arguments, run the command, the exit code.
pub fn main_entry() -> ExitCode {
    let args = match cli::Cli::try_parse() {
        Ok(a) => a,
        // --help and --version: on stdout, exit 0.
        Err(e) if !e.use_stderr() => {
            let _ = e.print();
            return ExitCode::SUCCESS;
        }
        Err(e) => {
            let text = parser_error(&e);
            eprint!("{text}{}", if text.ends_with('\n') { "" } else { "\n" });
            return ExitCode::from(2);
        }
    };
    interrupt::install();
    let result = match args.command {
        cli::Command::Run(a) => cmd_run::run(a),
        cli::Command::Spectrum(a) => cmd_spectrum::run(a),
        cli::Command::Loads(a) => cmd_loads::run(a),
        cli::Command::Campaign(a) => cmd_campaign::run(a),
        cli::Command::Validation(a) => cmd_validation::run(a),
        cli::Command::Design(a) => cmd_design::run(a),
        cli::Command::Size(a) => cmd_size::run(a),
        cli::Command::Fragility(a) => cmd_fragility::run(a),
        cli::Command::Merge(a) => cmd_merge::run(a),
        cli::Command::Report(a) => cmd_report::run(a),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            if e.downcast_ref::<Interrupted>().is_some() {
                eprintln!("Error: {e}");
                ExitCode::from(interrupt::EXIT_CODE)
            } else if e.downcast_ref::<InputError>().is_some() {
                eprintln!("Error: {e}");
                ExitCode::from(2)
            } else {
                eprintln!("Error: {e:#}");
                ExitCode::from(1)
            }
        }
    }
}
