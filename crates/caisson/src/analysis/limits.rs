//! The model's limits: where the caisson is taken to rock, to have failed, or to have moved
//! seaward; one definition of each, used by the drivers (a life's failure, its large-rotation
//! waves) and by the plausibility checks ([`super::checks`]) alike. A model piece: it imports
//! nothing.

/// Rotation beyond which the caisson is rocking, not vibrating, rad: the plausibility warning
/// `rocking`, a large-rotation wave of a life and the default `[design] failure_rotation_rad`.
pub const ROCKING_LIMIT_RAD: f64 = 0.01;

/// The default failure limit as a fraction of the base width B: a caisson that has slid a
/// quarter of its base off its place no longer stands on the levelled bedding the foundation
/// model describes (its heel is over the mound's shoulder or berm). For prototype widths of
/// 12-20 m this is 3-5 m, the order of the sliding graded "failure" in Takahashi's performance
/// matrix (3 m; docs/model.md §6.4 step 8). An engineering choice, not a literature value: give
/// `[design] failure_sliding_m` for the site. Also the plausibility warning `beyond-failure`.
pub const FAILURE_FRACTION_OF_WIDTH: f64 = 0.25;

/// Seaward end positions below this are reported (`seaward-lives`), m.
pub const SEAWARD_REPORT_M: f64 = 0.01;
