//! The foundation: soil stiffness and damping, hydrodynamic mass, and the interface springs.
//!
//! * [`soil`]: K_x, K_y, C from soil parameters (seed Eqs. 20-23, PHYSICS.md §8.2).
//! * [`hydro`]: added mass of the water in front of the wall (seed Eqs. 18-19, PHYSICS.md §8.3).
//! * [`spring`]: the nonlinear interface spring (seed Eqs. 27-28, PHYSICS.md §10 item 12).
//!
//! Springs are spread evenly across the base width B at the centres of n equal strips,
//! x_i = −B/2 + (i + ½) B/n (x shoreward from the base centre), so that Σ x_i² / n = B²/12 ·
//! (1 − 1/n²) tends to the continuous Winkler value. The vertical displacement of spring i is
//! u_y,i = u_y − θ x_i (θ clockwise positive: a positive θ lifts the seaward toe), and all springs
//! share u_x (PHYSICS.md §10 items 5, 7, 11).
//!
//! Damping (seed Eqs. 24-25): C on u_x, `vertical_damping_factor`·C (10 C) on u_y and on θ.
//! Where the horizontal dashpot acts is a [`DampingMode`] (PHYSICS.md §10 item 30); how the
//! vertical and rotational dashpots are formed is a [`VerticalDamping`] (§10 item 10).

pub mod hydro;
pub mod soil;
pub mod spring;

pub use hydro::AddedMass;
pub use soil::{FoundationStiffness, Soil};
pub use spring::{SpringLaw, SpringResponse, SpringState};

/// Where the horizontal foundation dashpot acts (PHYSICS.md §10 item 30).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum DampingMode {
    /// On the caisson's total horizontal velocity, in parallel with the friction slider (seed
    /// Eq. 15 as written).
    Total,
    /// In series with the slider: each contact spring's dashpot (C/n) acts beside its elastic
    /// spring, on the rate of its elastic deformation, and friction caps the force of both (a
    /// Kelvin element on the slider, [`spring`]), so that a sliding caisson is resisted by
    /// friction, not by the dashpot. A lifted spring carries no damping. The validation report
    /// (`docs/validation.md`) compares both placements; `Total` stays the default.
    Elastic,
}

/// How the vertical and rotational dashpots are formed (PHYSICS.md §10 item 10).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum VerticalDamping {
    /// The seed's Eq. 24-25: global dashpots factor·C on u_y and factor·C on θ, the latter's
    /// number used as N·m·s/rad (option A, reproduction). They act on the base centre and keep
    /// acting when springs lift off.
    Seed,
    /// A dashpot factor·C/n beside each vertical spring, on its vertical velocity u̇_y − θ̇ x_i,
    /// active only while the spring is in contact (option B, consistent): with all springs in
    /// contact, c_y = factor·C and c_θ = (factor·C/n) Σ x_i².
    Springs,
}

/// Validated foundation parameters (SI, totals).
#[derive(Debug, Clone, PartialEq)]
pub struct Foundation {
    /// Number of interface springs n ≥ 2.
    pub springs: usize,
    pub mu_static: f64,
    pub mu_dynamic: f64,
    pub stiffness: FoundationStiffness,
    /// Factor on C for the vertical and rotational dashpots (seed: 10).
    pub vertical_damping_factor: f64,
    pub damping_mode: DampingMode,
    pub vertical_damping: VerticalDamping,
    /// Added mass of the water in front of the wall (zero when switched off).
    pub added_mass: AddedMass,
}

impl Foundation {
    /// Spring positions x_i across a base of width `b_m` (m, shoreward from the base centre).
    pub fn spring_positions(&self, b_m: f64) -> Vec<f64> {
        let n = self.springs;
        (0..n).map(|i| -0.5 * b_m + (i as f64 + 0.5) * b_m / n as f64).collect()
    }
}
