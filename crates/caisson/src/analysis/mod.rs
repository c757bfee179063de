//! Drivers: a single run, the shock spectrum, wave-train realizations and campaigns. (Lifetime
//! Monte Carlo and fragility come with their issue.)

pub mod campaign;
pub mod closed_form;
pub mod fragility;
pub mod lifetime;
pub mod run;
pub mod spectrum;
pub mod train;
