//! The `caisson` binary: [`caisson_cli::main_entry`] (the command-line tool's crate root is
//! `lib.rs`).

fn main() -> std::process::ExitCode {
    caisson_cli::main_entry()
}
