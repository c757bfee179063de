//! Breaking or non-breaking: which load model applies to a wave (seed §4.1-4.2; docs/model.md §4.2).
//!
//! The seed classifies its tests by set-up (d = 0.4 m with the extra berm: breaking; d = 0.8 m:
//! non-breaking). Here the regime is decided by the breaking criterion at the wall, or forced:
//!
//! * `Auto`: **breaking** if H ≥ H_br = H_b(d) (equivalently d_b ≥ d: the wave reaches its limit at
//!   or before the wall), else **non-breaking**. With Miche and the PARI geometry this reproduces
//!   the seed's split: H_br(0.4 m) = 0.336 m < every test H; H_b(0.8 m) ≈ 0.63 m > every test H.
//! * `Forced(Breaking)`: always allowed (seed Eq. 30 then gives a reduced impact, possibly zero).
//! * `Forced(NonBreaking)` for H ≥ H_br is rejected ([`RegimeError`]): such a wave cannot reach the
//!   wall as a standing wave, and the Goda/Sainflou pulsating loads alone would misrepresent it.

use crate::waves::breaking::BreakerCriterion;
use thiserror::Error;

/// The load regime of one wave.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Regime {
    /// Seed Eq. 31 (or a Table 2 shape): impact plus pulsating loads.
    Breaking,
    /// Seed Eq. 29: pulsating (Goda) and standing-wave trough (Sainflou) loads.
    NonBreaking,
}

impl Regime {
    pub fn name(self) -> &'static str {
        match self {
            Regime::Breaking => "breaking",
            Regime::NonBreaking => "non-breaking",
        }
    }
}

/// How the regime is chosen.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum RegimeChoice {
    Auto,
    Forced(Regime),
}

impl RegimeChoice {
    /// The scenario name: `"auto"`, `"breaking"` or `"non-breaking"`.
    pub fn name(self) -> &'static str {
        match self {
            RegimeChoice::Auto => "auto",
            RegimeChoice::Forced(r) => r.name(),
        }
    }

    /// The choice of a scenario name (see [`Self::name`]).
    pub fn from_name(name: &str) -> Option<Self> {
        match name {
            "auto" => Some(RegimeChoice::Auto),
            "breaking" => Some(RegimeChoice::Forced(Regime::Breaking)),
            "non-breaking" => Some(RegimeChoice::Forced(Regime::NonBreaking)),
            _ => None,
        }
    }
}

impl serde::Serialize for RegimeChoice {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

/// The decision for one wave, with the numbers behind it.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct RegimeDecision {
    pub regime: Regime,
    /// True if the user forced it.
    pub forced: bool,
    /// H_br = H_b(d), the breaker height at the wall, m.
    pub breaker_height_at_wall_m: f64,
}

/// A forced regime that contradicts the breaking criterion.
#[derive(Debug, Clone, Copy, PartialEq, Error)]
#[error("a wave of height {height_m:.4} m breaks at or before the wall (breaker height {breaker_height_m:.4} m at the wall depth {wall_depth_m} m by the {criterion} criterion), so it cannot be treated as non-breaking")]
pub struct RegimeError {
    pub height_m: f64,
    pub breaker_height_m: f64,
    pub wall_depth_m: f64,
    pub criterion: &'static str,
}

/// Decide the regime of a wave of height `height_m` (at the toe) and period `period_s` in front
/// of a wall in depth `wall_depth_m` (module docs).
pub fn decide(
    choice: RegimeChoice,
    height_m: f64,
    period_s: f64,
    wall_depth_m: f64,
    criterion: BreakerCriterion,
) -> Result<RegimeDecision, RegimeError> {
    decide_with_limit(choice, height_m, criterion.breaker_height_m(wall_depth_m, period_s), wall_depth_m, criterion)
}

/// As [`decide`] with the breaker height at the wall H_br (m) already computed.
pub fn decide_with_limit(
    choice: RegimeChoice,
    height_m: f64,
    hbr: f64,
    wall_depth_m: f64,
    criterion: BreakerCriterion,
) -> Result<RegimeDecision, RegimeError> {
    let breaks = height_m >= hbr;
    match choice {
        RegimeChoice::Auto => Ok(RegimeDecision {
            regime: if breaks { Regime::Breaking } else { Regime::NonBreaking },
            forced: false,
            breaker_height_at_wall_m: hbr,
        }),
        RegimeChoice::Forced(Regime::NonBreaking) if breaks => {
            Err(RegimeError { height_m, breaker_height_m: hbr, wall_depth_m, criterion: criterion.name() })
        }
        RegimeChoice::Forced(r) => Ok(RegimeDecision { regime: r, forced: true, breaker_height_at_wall_m: hbr }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pari_tests_split_as_in_the_seed() {
        for h in [0.428, 0.524, 0.569, 0.619] {
            let b = decide(RegimeChoice::Auto, h, 3.04, 0.4, BreakerCriterion::Miche).unwrap();
            assert_eq!(b.regime, Regime::Breaking, "H = {h}, d = 0.4");
            let n = decide(RegimeChoice::Auto, h, 3.04, 0.8, BreakerCriterion::Miche).unwrap();
            assert_eq!(n.regime, Regime::NonBreaking, "H = {h}, d = 0.8");
        }
    }

    #[test]
    fn forcing_non_breaking_above_the_limit_is_an_error() {
        let e =
            decide(RegimeChoice::Forced(Regime::NonBreaking), 0.428, 3.04, 0.4, BreakerCriterion::Miche).unwrap_err();
        assert!((e.breaker_height_m - 0.336).abs() < 0.002);
        let ok = decide(RegimeChoice::Forced(Regime::Breaking), 0.428, 3.04, 0.8, BreakerCriterion::Miche).unwrap();
        assert!(ok.forced && ok.regime == Regime::Breaking);
    }
}
