//! Drivers: a single run, the shock spectrum, wave-train realizations and campaigns, the lifetime
//! Monte Carlo of performance-based design and fragility curves.
//!
//! In three floors; a module names only modules of its floor or below, without a circle
//! (ARCHITECTURE.md; tests/contract_floors.rs):
//! 0. the model pieces: [`Structure`] (here), [`site`], [`rigid`], [`limits`], [`closed_form`],
//!    [`climate`], [`stick_bound`], [`estimate`] (Monte Carlo estimates with their precision) and
//!    [`stratified`] (those of a two-phase stratified sample);
//! 1. the drivers: [`run`], [`envelope`], [`spectrum`], [`train`], [`campaign`], [`lifetime`],
//!    [`fragility`], [`conventional`], [`sizing`];
//! 2. the judgement: [`checks`] (plausibility warnings of inputs and results), [`findings`] (the
//!    seed's findings as criteria) and [`work`] (work estimates).
//!
//! Every driver takes typed parameters (a [`Structure`], loads, waves) and a progress callback
//! called once per finished item (realization, point, life, storm); none prints or writes files.
//! Parallel drivers use rayon's current thread pool (the caller chooses it with
//! `ThreadPool::install`) and gather their results by index, so they do not depend on the number
//! of threads.

pub mod campaign;
pub mod checks;
pub mod climate;
pub mod closed_form;
pub mod conventional;
pub mod envelope;
pub mod estimate;
pub mod findings;
pub mod fragility;
pub mod lifetime;
pub mod limits;
pub mod rigid;
pub mod run;
pub mod site;
pub mod sizing;
pub mod spectrum;
pub mod stick_bound;
pub mod stratified;
pub mod train;
pub mod work;

use crate::dynamics::{Model, SolverParams};
use crate::foundation::Foundation;
use crate::structure::Caisson;

/// What every analysis runs on: the caisson, its foundation and how the equations of motion are
/// integrated.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Structure {
    pub caisson: Caisson,
    pub foundation: Foundation,
    pub solver: SolverParams,
    /// The profile whose defaults built the caisson and the foundation (`[model] profile`),
    /// recorded in the reports. Not serialized: the choices it made are in the caisson and the
    /// foundation, so the fingerprint of what a run depends on stays that of the choices.
    #[serde(skip)]
    pub profile: crate::Profile,
}

impl Structure {
    /// The assembled dynamic model.
    pub fn model(&self) -> Model {
        Model::new(&self.caisson, &self.foundation)
    }
}

/// A progress callback: called once for every finished item of a driver (from any thread).
pub type Progress<'a> = &'a (dyn Fn() + Sync);
