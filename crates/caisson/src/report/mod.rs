//! The JSON contracts: one typed, serializable report per command, the single definition of the
//! keys documented in `docs/cli.md`, `docs/waves.md`, `docs/campaign.md`, `docs/design.md` and
//! `docs/fragility.md`. The CLI serializes them; the bindings build the same structs. Units are in
//! the key names (forces in kN, pressures in kPa; the analyses themselves work in SI).
//!
//! Every report computes its own warnings in its constructor, and [`encode::to_json`] is the one
//! way to JSON (refusing a non-finite number, naming its path): the CLI and the bindings only
//! print what it returns.
//!
//! Every report carries its [`Provenance`]: the version of the tool that made it and the version
//! of the results ([`crate::RESULTS_VERSION`]).

pub mod campaign;
pub mod checkpoint;
pub mod design;
pub mod encode;
pub mod fragility;
pub mod loads;
pub mod run;
pub mod size;
pub mod spectrum;
pub mod train;

use crate::analysis::run::FoundationSummary;
use crate::analysis::site::WaveSetup;
use crate::analysis::train::Spread;
use crate::analysis::Structure;
use crate::foundation::{DampingMode, VerticalDamping};
use crate::loads::breaking_load::BreakingLoad;
use crate::structure::MassMatrix;
use crate::Profile;
pub use encode::{to_json, to_json_pretty, to_json_text, NotFinite};
use serde::Serialize;

/// The tool and results versions of an output.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct Provenance {
    /// The version of `caisson` that computed the results.
    pub caisson_version: &'static str,
    /// [`crate::RESULTS_VERSION`] of that version.
    pub results_version: u32,
}

impl Provenance {
    /// This build's versions.
    pub const CURRENT: Provenance =
        Provenance { caisson_version: crate::VERSION, results_version: crate::RESULTS_VERSION };
}

impl Default for Provenance {
    fn default() -> Self {
        Provenance::CURRENT
    }
}

/// The model a report's numbers were computed with (the `model` object of every report): the
/// profile (`[model] profile`) and the choices it made or the scenario's keys overrode. Two
/// reports with the same `model` and results version came from the same equations.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ModelReport {
    pub profile: Profile,
    /// Where the horizontal foundation dashpot acts (`[foundation] damping_mode`).
    pub damping_mode: DampingMode,
    /// How the vertical and rotational dashpots are formed (`[foundation] vertical_damping`).
    pub vertical_damping: VerticalDamping,
    /// The rigid-body mass matrix (`[caisson] mass_matrix`).
    pub mass_matrix: MassMatrix,
    /// Static and dynamic friction coefficients of the base.
    pub mu_static: f64,
    pub mu_dynamic: f64,
    /// The impulsive peak of a breaking wave (`[waves] breaking_load`); absent from the report of
    /// a run without waves.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub breaking_load: Option<BreakingLoad>,
}

impl ModelReport {
    /// The model of a run on `s` under the wave loads of `waves`, if any.
    pub fn new(s: &Structure, waves: Option<&WaveSetup>) -> Self {
        ModelReport {
            profile: s.profile,
            damping_mode: s.foundation.damping_mode,
            vertical_damping: s.foundation.vertical_damping,
            mass_matrix: s.caisson.mass_matrix,
            mu_static: s.foundation.mu_static,
            mu_dynamic: s.foundation.mu_dynamic,
            breaking_load: waves.map(|w| w.model.options.breaking_load),
        }
    }
}

/// kN from N.
pub(crate) fn kn(n: f64) -> f64 {
    n / 1e3
}

/// Mean, minimum and maximum of a sample, scaled to the unit of the key that holds them.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SpreadReport {
    pub mean: f64,
    pub min: f64,
    pub max: f64,
}

impl SpreadReport {
    /// `s` times `scale` (e.g. 1e-3 for N → kN).
    pub fn scaled(s: &Spread, scale: f64) -> Self {
        SpreadReport { mean: s.mean * scale, min: s.min * scale, max: s.max * scale }
    }

    /// A spread of forces in N reported in kN by [`kn`], as each realization's value is: the
    /// largest realization's value and the spread's `max` are the same number.
    pub fn in_kn(s: &Spread) -> Self {
        SpreadReport { mean: kn(s.mean), min: kn(s.min), max: kn(s.max) }
    }
}

/// The `foundation` object of the run summaries.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FoundationReport {
    pub kx_kn_per_m: f64,
    pub ky_kn_per_m: f64,
    pub damping_kns_per_m: f64,
    pub mass_kg: f64,
    pub added_mass_kg: f64,
    pub natural_period_s: f64,
    pub static_settlement_m: f64,
    pub static_sliding_resistance_kn: f64,
}

impl From<&FoundationSummary> for FoundationReport {
    fn from(f: &FoundationSummary) -> Self {
        FoundationReport {
            kx_kn_per_m: kn(f.kx_n_per_m),
            ky_kn_per_m: kn(f.ky_n_per_m),
            damping_kns_per_m: kn(f.damping_ns_per_m),
            mass_kg: f.mass_kg,
            added_mass_kg: f.added_mass_kg,
            natural_period_s: f.natural_period_s,
            static_settlement_m: f.static_settlement_m,
            static_sliding_resistance_kn: kn(f.static_sliding_resistance_n),
        }
    }
}

/// FNV-1a (64 bit) of `bytes`: a stable fingerprint (the same on every platform and build).
pub fn fnv1a_64(bytes: &[u8]) -> u64 {
    bytes.iter().fold(0xcbf2_9ce4_8422_2325_u64, |h, &b| (h ^ b as u64).wrapping_mul(0x0000_0100_0000_01b3))
}

/// The fingerprint of typed parameters: FNV-1a of their JSON serialization, 16 hex digits. Two
/// runs with the same fingerprint (and results version) compute the same numbers.
pub fn fingerprint<T: Serialize + ?Sized>(value: &T) -> String {
    let json = serde_json::to_vec(value).expect("parameters serialize");
    format!("{:016x}", fnv1a_64(&json))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// FNV-1a test vectors (Fowler, Noll & Vo; the offset basis and "a").
    #[test]
    fn fnv1a_reference_values() {
        assert_eq!(fnv1a_64(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a_64(b"a"), 0xaf63_dc4c_8601_ec8c);
        assert_eq!(fnv1a_64(b"foobar"), 0x8594_4171_f739_67e8);
    }
}
