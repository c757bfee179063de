//! The foundation: soil stiffness and damping, hydrodynamic mass, and the interface springs.
//!
//! * [`soil`]: K_x, K_y, C from soil parameters (seed Eqs. 20-23, docs/model.md §8.2).
//! * [`hydro`]: added mass of the water in front of the wall (seed Eqs. 18-19, docs/model.md §8.3).
//! * [`spring`]: the nonlinear interface spring (seed Eqs. 27-28, docs/model.md §10 item 12).
//!
//! Springs are spread evenly across the base width B at the centres of n equal strips,
//! x_i = −B/2 + (i + ½) B/n (x shoreward from the base centre), so that Σ x_i² / n = B²/12 ·
//! (1 − 1/n²) tends to the continuous Winkler value. The vertical displacement of spring i is
//! u_y,i = u_y − θ x_i (θ clockwise positive: a positive θ lifts the seaward toe), and all springs
//! share u_x (docs/model.md §10 items 5, 7, 11).
//!
//! Damping (seed Eqs. 24-25): C on u_x, `vertical_damping_factor`·C (10 C) on u_y and on θ.
//! Where the horizontal dashpot acts is a [`DampingMode`] (docs/model.md §10 item 30); how the
//! vertical and rotational dashpots are formed is a [`VerticalDamping`] (§10 item 10).

pub mod hydro;
pub mod soil;
pub mod spring;

pub use hydro::AddedMass;
pub use soil::{FoundationStiffness, Soil};
pub use spring::{SpringLaw, SpringResponse, SpringState};

use crate::check::{between, between_per, count, rule};
use crate::structure::Caisson;
use crate::{ParamError, Profile};

/// The smallest friction coefficient the model takes (`[foundation] mu_static` and `mu_dynamic`,
/// `[waves] rigid_block_mu`, and a storm's coefficients times its friction error): a caisson on
/// less friction slides without bound (the rigid block's deceleration after a wave, μ W', would be
/// zero), and any wave then moves it beyond the failure limits.
pub const MIN_FRICTION: f64 = 1e-6;

/// The range of a stiffness given directly (`kx_kn_per_m`, `ky_kn_per_m`) per metre of caisson
/// length, N/m per m: a modulus, 1 kPa to 1e9 kPa, the range of E100 (1 kPa, a slurry, to a
/// thousand times steel). The seed's Eqs. 20-21 give K/l = (1 + 4ν²) G and (1 + 5ν²) G, 1 to 1.6
/// times the shear modulus (the PARI mound: 1.4e5 and 1.5e5 kN/m per m). Outside it the static
/// settlement W'/K_y, or the natural period, leaves any range a time step can follow (K_y = 1e-200
/// kN/m settles the caisson by 8e200 m).
pub const STIFFNESS_PER_M: (f64, f64) = (1e3, 1e12);

/// The range of the damping given directly (`damping_kns_per_m`) per metre of caisson length,
/// N·s/m per m: 0 to 1e7 kN·s/m per m. Lysmer's C of the seed's Eq. 22 is, per metre,
/// 3.4/(π (1 − ν)) B ρ_s V_s: 1.1 to 2.1 times the base width times the soil's shear-wave
/// impedance ρ_s V_s (the PARI mound: 598 kN·s/m; the design example about 2.4e4 kN·s/m a metre);
/// 1e7 kN·s/m a metre is a caisson 100 m wide on steel (ρ V_s = 2.5e4 kN·s/m³). Per metre of
/// length, not of base, so that a sizing run, which varies the width, never meets the bound.
pub const DAMPING_PER_M: (f64, f64) = (0.0, 1e10);

/// Where the horizontal foundation dashpot acts (docs/model.md §10 item 30).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum DampingMode {
    /// On the caisson's total horizontal velocity, in parallel with the friction slider (seed
    /// Eq. 15 as written; profile `seed-2011`). While the caisson slides, the base shear is
    /// μN + C v, above the friction force: at prototype scale the dashpot, not friction, limits
    /// sliding (the run warns when it does).
    Total,
    /// In series with the slider: each contact spring's dashpot (C/n) acts beside its elastic
    /// spring, on the rate of its elastic deformation, and friction caps the force of both (a
    /// Kelvin element on the slider, [`spring`]), so that a sliding caisson is resisted by
    /// friction, not by the dashpot. A lifted spring carries no damping. Profile `consistent`
    /// (the default): every independent implementation keeps radiation damping off the slip
    /// (OpenSees `PySimple1`, Proteus `CaissonBody`, the SLAMMER coupled block), and the
    /// rigid-plastic sliding models have no dashpot in the sliding phase.
    Elastic,
}

/// How the vertical and rotational dashpots are formed (docs/model.md §10 item 10).
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

/// The hydrodynamic added mass of the water in front of the wall ([`hydro`]).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum AddedMassSpec {
    /// No added mass.
    Off,
    /// Westergaard's added mass for water `depth_m` deep; `None`: the base depth h'.
    Westergaard { depth_m: Option<f64> },
}

/// The foundation as specified (SI, totals): what [`Foundation`] is derived from for a given
/// caisson. The stiffness and damping come from the soil (seed Eqs. 20-23, which depend on the
/// caisson's weight in water and base) unless given; each given value overrides the soil's.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct FoundationSpec {
    /// Number of interface springs n (2 to 1000).
    pub springs: usize,
    pub mu_static: f64,
    /// `None`: the profile's: μ_s (`consistent`), min(0.4, μ_s) (`seed-2011`).
    pub mu_dynamic: Option<f64>,
    pub soil: Option<Soil>,
    /// K_x, N/m (overrides the soil's).
    pub kx_n_per_m: Option<f64>,
    /// K_y, N/m (overrides the soil's).
    pub ky_n_per_m: Option<f64>,
    /// C, N·s/m (overrides the soil's; 0 allowed).
    pub damping_ns_per_m: Option<f64>,
    /// Factor on C for the vertical and rotational dashpots (seed: 10).
    pub vertical_damping_factor: f64,
    /// `None`: the profile's (`elastic` for `consistent`, `total` for `seed-2011`).
    pub damping_mode: Option<DampingMode>,
    /// `None`: the profile's (`springs` for `consistent`, `seed` for `seed-2011`).
    pub vertical_damping: Option<VerticalDamping>,
    pub added_mass: AddedMassSpec,
}

impl Default for FoundationSpec {
    /// The seed's numbers (10 springs, μ_s = 0.6, 10 C), the profile's choices, no soil and no
    /// stiffness (one of them must be set).
    fn default() -> Self {
        FoundationSpec {
            springs: 10,
            mu_static: 0.6,
            mu_dynamic: None,
            soil: None,
            kx_n_per_m: None,
            ky_n_per_m: None,
            damping_ns_per_m: None,
            vertical_damping_factor: 10.0,
            damping_mode: None,
            vertical_damping: None,
            added_mass: AddedMassSpec::Westergaard { depth_m: None },
        }
    }
}

impl FoundationSpec {
    /// The foundation of `caisson` in water of density `rho_w` (kg/m³), every quantity checked,
    /// with the defaults of `profile`.
    pub fn build(&self, caisson: &Caisson, rho_w: f64, profile: Profile) -> Result<Foundation, ParamError> {
        let springs = count("springs", self.springs, 2, 1000)?;
        let mu_static = between("mu_static", self.mu_static, MIN_FRICTION, 10.0)?;
        let mu_dynamic = match (self.mu_dynamic, profile) {
            (Some(v), _) => between("mu_dynamic", v, MIN_FRICTION, 10.0)?,
            (None, Profile::Consistent) => mu_static,
            (None, Profile::Seed2011) => 0.4f64.min(mu_static),
        };
        if mu_dynamic > mu_static {
            return Err(rule(
                "mu_dynamic",
                mu_dynamic,
                format!("must not exceed mu_static = {mu_static} (dynamic friction is at most static friction)"),
            ));
        }
        let derived = match &self.soil {
            Some(s) => {
                Some(s.checked()?.derive(caisson.weight_in_water_n, caisson.width_m, caisson.length_m).stiffness)
            }
            None => None,
        };
        // A given value within its range per metre of caisson length.
        let pick = |quantity: &'static str, given: Option<f64>, from_soil: Option<f64>, range: (f64, f64)| match (
            given, from_soil,
        ) {
            (Some(v), _) => between_per(quantity, v, range, caisson.length_m, "metre of caisson length"),
            (None, Some(v)) => Ok(v),
            (None, None) => Err(rule(quantity, f64::NAN, "give the soil or the stiffnesses and damping")),
        };
        let stiffness = FoundationStiffness {
            kx_n_per_m: pick("kx_n_per_m", self.kx_n_per_m, derived.map(|d| d.kx_n_per_m), STIFFNESS_PER_M)?,
            ky_n_per_m: pick("ky_n_per_m", self.ky_n_per_m, derived.map(|d| d.ky_n_per_m), STIFFNESS_PER_M)?,
            damping_ns_per_m: pick(
                "damping_ns_per_m",
                self.damping_ns_per_m,
                derived.map(|d| d.damping_ns_per_m),
                DAMPING_PER_M,
            )?,
        };
        let vertical_damping_factor = between("vertical_damping_factor", self.vertical_damping_factor, 0.0, 1e3)?;
        let added_mass = match self.added_mass {
            AddedMassSpec::Off => AddedMass::default(),
            AddedMassSpec::Westergaard { depth_m } => {
                let d = match depth_m {
                    Some(v) => between("added_mass_depth_m", v, 0.0, 1e3)?,
                    None => caisson.base_depth_m,
                };
                AddedMass::new(rho_w, d, caisson.length_m)
            }
        };
        Ok(Foundation {
            springs,
            mu_static,
            mu_dynamic,
            stiffness,
            vertical_damping_factor,
            damping_mode: self.damping_mode.unwrap_or(match profile {
                Profile::Consistent => DampingMode::Elastic,
                Profile::Seed2011 => DampingMode::Total,
            }),
            vertical_damping: self.vertical_damping.unwrap_or(match profile {
                Profile::Consistent => VerticalDamping::Springs,
                Profile::Seed2011 => VerticalDamping::Seed,
            }),
            added_mass,
        })
    }
}

/// Validated foundation parameters (SI, totals).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
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
