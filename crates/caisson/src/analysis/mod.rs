//! Drivers: a single run, the shock spectrum, wave-train realizations and campaigns, the lifetime
//! Monte Carlo of performance-based design and fragility curves.

pub mod campaign;
pub mod closed_form;
pub mod fragility;
pub mod lifetime;
pub mod run;
pub mod spectrum;
pub mod train;
