//! The load of a breaking wave: which rule gives the impulsive peak of a wave that breaks at the
//! wall (`[waves] breaking_load`; docs/model.md §5.5).
//!
//! Every wave carries the pulsating load of the seed: Goda's F_qs+ with α* = α2 (no impulsive
//! coefficient) times α_qs, and Sainflou's trough F_qs−. A wave that breaks at the wall (the
//! regime of [`super::regime`]: H at the toe ≥ H_br, or forced) also gets an impulsive peak F_peak
//! (horizontal force with its lever, uplift with its lever) by the rule:
//!
//! | rule | F_peak (horizontal; uplift) | source |
//! |---|---|---|
//! | `cuomo-2010` | F_x,max = a_imp α_max ρ_w g H L(h_s) max{0, 1 − \|d_b − d\|/d} (seed Eq. 30) at the PROVERBS lever; F_y,max (Eq. 32) at 2B/3 from the heel | Cuomo et al. (2010) as the seed uses it ([`super::impact`]) |
//! | `goda-takahashi` | Goda's P and M_P for the wave's height with α* = max(α2, α_I) in p1; Goda's U (α_I does not enter pu) at 2B/3 from the heel | Takahashi, Tanimoto & Shimosako (1994): the loads of the expected sliding distance method (Shimosako & Takahashi 1999; Goda & Takagi 2000) |
//! | `none` | none: the pulsating load only | |
//!
//! The wave is **impulsive** when F* = F_x,peak / P(α2) > 1 (and finite): under `goda-takahashi`
//! exactly when α_I > α2 (p1 grows with α*, and with it P). An impulsive wave's rise time follows
//! the seed's log-normal model at that F* (Eqs. 34-36, [`super::risetime`]) and its time shape is
//! `[waves] load_shape`; any other wave, breaking or not, is the pulsating sine of Eq. 29 (with
//! `alpha_qs_breaking` if it breaks). α_I takes the berm width B_M of `[water] berm_width_m`, or
//! B_M = 0 where the rule is the profile's default and no berm is given (a valid input of
//! Takahashi's formula: no berm in front of the wall; docs/model.md §5.5).

use super::goda::GodaResult;
use super::impact::ImpactResult;
use crate::Profile;

/// The rule that gives a breaking wave's impulsive peak (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum BreakingLoad {
    /// Cuomo et al. (2010), seed Eq. 30 and 32.
    #[serde(rename = "cuomo-2010")]
    Cuomo2010,
    /// Goda's force with Takahashi's α* = max(α2, α_I).
    #[serde(rename = "goda-takahashi")]
    GodaTakahashi,
    /// No impulsive peak: the pulsating load only.
    #[serde(rename = "none")]
    None,
}

impl BreakingLoad {
    /// Every rule with its scenario name.
    pub const ALL: [(&'static str, BreakingLoad); 3] = [
        ("cuomo-2010", BreakingLoad::Cuomo2010),
        ("goda-takahashi", BreakingLoad::GodaTakahashi),
        ("none", BreakingLoad::None),
    ];

    /// The scenario name (`[waves] breaking_load`).
    pub fn name(self) -> &'static str {
        match self {
            BreakingLoad::Cuomo2010 => "cuomo-2010",
            BreakingLoad::GodaTakahashi => "goda-takahashi",
            BreakingLoad::None => "none",
        }
    }

    /// The rule a profile takes where the scenario gives none: the seed's own under `seed-2011`;
    /// the load of the published expected-sliding method under `consistent` (docs/model.md §5.5).
    pub fn for_profile(profile: Profile) -> BreakingLoad {
        match profile {
            Profile::Consistent => BreakingLoad::GodaTakahashi,
            Profile::Seed2011 => BreakingLoad::Cuomo2010,
        }
    }
}

/// The impulsive peak of a breaking wave under a rule (per metre): its horizontal force with the
/// height of its resultant above the base, and its uplift with the distance of its resultant from
/// the heel. All zero under `none`.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct ImpulsivePeak {
    /// F_x,peak, N/m (shoreward).
    pub horizontal_force_n_per_m: f64,
    /// Height of the horizontal resultant above the base, m.
    pub horizontal_lever_m: f64,
    /// F_y,peak, N/m (upward).
    pub uplift_force_n_per_m: f64,
    /// Distance of the uplift resultant from the heel, m.
    pub uplift_from_heel_m: f64,
}

impl ImpulsivePeak {
    /// The peak of `cuomo-2010`: seed Eq. 30 and 32 with their levers.
    pub fn of_impact(i: &ImpactResult) -> Self {
        ImpulsivePeak {
            horizontal_force_n_per_m: i.horizontal_force_n_per_m,
            horizontal_lever_m: i.horizontal_lever_m,
            uplift_force_n_per_m: i.uplift_force_n_per_m,
            uplift_from_heel_m: i.uplift_from_heel_m,
        }
    }

    /// The peak of `goda-takahashi`: Goda's P (with α*), its lever M_P/P, and U at 2B/3.
    pub fn of_goda(g: &GodaResult) -> Self {
        ImpulsivePeak {
            horizontal_force_n_per_m: g.horizontal_force_n_per_m,
            horizontal_lever_m: g.horizontal_lever_m,
            uplift_force_n_per_m: g.uplift_force_n_per_m,
            uplift_from_heel_m: g.uplift_from_heel_m,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip_and_profiles_choose() {
        for (n, r) in BreakingLoad::ALL {
            assert_eq!(r.name(), n);
            assert_eq!(serde_json::to_value(r).unwrap(), serde_json::Value::String(n.into()));
        }
        assert_eq!(BreakingLoad::for_profile(Profile::Seed2011), BreakingLoad::Cuomo2010);
        assert_eq!(BreakingLoad::for_profile(Profile::Consistent), BreakingLoad::GodaTakahashi);
    }
}
