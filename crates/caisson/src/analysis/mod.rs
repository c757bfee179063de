//! Drivers: a single run and the shock spectrum. (Wave campaigns, lifetime Monte Carlo and
//! fragility come with their issues.)

pub mod closed_form;
pub mod run;
pub mod spectrum;
