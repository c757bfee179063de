//! # caisson
//!
//! Dynamic sliding of caisson breakwaters under breaking and non-breaking waves: the model of
//! Cuomo, Lupoi, Shimosako & Takahashi (the "seed" paper, `../shared/seed/`), with every formula
//! it leaves out taken from `../shared/PHYSICS.md`.
//!
//! A rigid caisson (sliding u_x, heave u_y, rocking θ) rests on a bed of nonlinear interface
//! springs (no tension; elastic-Coulomb friction with static and dynamic coefficients) and is
//! integrated by Newmark + Newton-Raphson under a wave-force time history.
//!
//! Sign conventions (used everywhere): x positive shoreward, y positive upward (uplift positive),
//! moments and θ about the centre of the base, positive clockwise looking alongshore with the sea
//! on the left (the sense in which a shoreward force overturns the caisson). SI units inside.
//!
//! The library never prints and never touches files, except [`scenario`], which reads the
//! scenario file and the force series it names.

pub mod analysis;
pub mod dynamics;
pub mod foundation;
pub mod loads;
pub mod scenario;
pub mod structure;
pub mod waves;

/// Gravitational acceleration used throughout, m/s² (PHYSICS.md §0).
pub const G_M_PER_S2: f64 = 9.81;
