//! Linear wave theory, breaking criteria and wave-height statistics (docs/model.md §3, §4.2).
//!
//! * [`dispersion`]: the linear dispersion relation ω² = g k tanh(k h) at any depth, solved to
//!   machine precision.
//! * [`breaking`]: breaker heights and breaking depths (Miche 1944, Goda 1970/2000 breaker index,
//!   McCowan), each with its closed-form inversion for the breaking depth and a generic bisection.
//! * [`surf_zone`]: Goda's (2000) surf-zone H1/3 and H_max with Kweon & Goda (1996) nonlinear
//!   shoaling.
//! * [`statistics`]: Rayleigh wave heights (exceedance, quantiles, seeded sampling), the normal
//!   distribution's Φ, φ and Φ⁻¹.
//! * [`periods`]: wave-by-wave periods given the heights (Longuet-Higgins 1983).
//!
//! All functions take SI inputs (m, s) and return SI outputs. They are pure: no allocation, no
//! I/O. Inputs outside the stated domain give `NaN` or `None`, never a panic; the scenario
//! validation (`scenario::waves`) rejects such inputs before they get here.

pub mod breaking;
pub mod dispersion;
pub mod periods;
pub mod statistics;
pub mod surf_zone;
