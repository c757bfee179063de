//! Drivers over a whole scenario, above `scenario` and `report`: each takes a validated
//! [`crate::scenario::Scenario`], runs the `analysis` drivers and returns its report; the CLI and
//! the Python bindings call the same function and add only their files, progress and stopping.
//!
//! - [`design`]: a design run ([`design::Designer`]: the lives, their fingerprint, work estimate
//!   and report) of `caisson design`, `caisson merge`, the validation report and Python's `Design`;
//! - [`size`]: the sizing search ([`size::Sizer`], which rebuilds the scenario at each width);
//! - [`checkpoint_file`]: the design checkpoint as a file (read, append, flush), the one module of
//!   the library that writes files.

pub mod checkpoint_file;
pub mod design;
pub mod size;
