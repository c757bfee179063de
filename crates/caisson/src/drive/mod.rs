//! Drivers over a whole scenario: the ones that vary it (sizing rebuilds it at each width) and so
//! sit above `scenario` and `report`. Each takes a validated [`crate::scenario::Scenario`], runs
//! the `analysis` drivers and returns its report; the CLI and the Python bindings call the same
//! function and add only their files, progress and stopping.

pub mod checkpoint_file;
pub mod design;
pub mod size;
