//! `caisson loads`: wave loads for the scenario's waves (owned by the wave-loads work).

use crate::cli::LoadsArgs;
use anyhow::Result;

pub fn run(_args: LoadsArgs) -> Result<()> {
    anyhow::bail!(crate::InputError("`caisson loads` is not implemented yet".into()))
}
