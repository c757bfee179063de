//! Goda's conventional design of an upright section (Goda 2000, ch. 4; Takahashi 2002, §4;
//! docs/model.md §1.3 and §1.6): the design wave, the static checks under it, and the
//! conventional width that meets them. Per metre of breakwater.
//!
//! **Design wave** H_D ([`DesignWave`]):
//!
//! ```text
//! regular waves     H_D = H,  h_b = h + 5 H tan θ                     (the seed's PARI tests)
//! irregular waves   H_D = H_max = min{ 1.8 H1/3,  H_max,Goda(H0', h_b) },  h_b = h + 5 H1/3 tan θ
//! ```
//!
//! H1/3 is the scenario's significant height at the toe (depth h). 1.8 H1/3 is Goda's design
//! H_max outside the surf zone (Goda 2000, §4.2.1, about H1/250). Inside the surf zone the waves
//! break before they reach it: Goda's breaking-limited H_max (§3.3 of docs/model.md,
//! [`crate::waves::surf_zone`]) evaluated at h_b, from the equivalent deep-water height H0'
//! whose Goda H1/3 at the toe is the given H1/3 ([`equivalent_deep_water_height_m`]). The
//! smaller of the two is used; the report says which ([`DesignWaveRule`]). Goda's formula then
//! takes H_D with h_b for α2 and the wavelength L at the toe for T1/3 (docs/model.md §1.3).
//! Size example (h 20 m, tan θ 0.01, T1/3 12.8 s, H1/3 7.5 m): 1.8 H1/3 = 13.5 m, the
//! breaking-limited H_max 12.38 m: it governs.
//!
//! **Static checks** ([`crate::loads::safety`]): sliding SF_s = μ (W' − U)/P, overturning
//! SF_o = (W' t − M_U)/M_P, heel pressure p_e, all under the design wave's Goda loads.
//!
//! **Conventional width** ([`conventional_width`]): the smallest B with SF_s ≥ 1.2 **and**
//! SF_o ≥ 1.2 under H_D (Goda 2000: both ≥ 1.2), found by bisection on each factor (each grows
//! with B: W' and its lever grow with B, P and M_P do not depend on it, U grows as B and M_U as
//! B²/3, slower than W' B/2 for any caisson that does not float). The heel pressure at that width
//! is reported beside an allowable value: Japanese practice limits p_e to about 400-600 kPa
//! (Goda 2000: 400-500 kPa; Takahashi 2002: 500-600 kPa); 500 kPa is the default. Above it a
//! bearing-capacity check of the mound is needed, not simply a wider caisson: so the heel pressure
//! is a criterion of the width only if asked ([`ConventionalCriteria::heel_pressure_governs`]).

use super::site::WaveSetup;
use super::Structure;
use crate::loads::generator::TrainKind;
use crate::loads::model::{WaveLoadModel, WaveLoads};
use crate::loads::regime::{RegimeChoice, RegimeError};
use crate::loads::safety::SafetyFactors;
use crate::waves::surf_zone::{equivalent_deep_water_height_m, goda_surf_zone};
use serde::Serialize;

/// H_max / H1/3 of Goda's design wave outside the surf zone (Goda 2000, §4.2.1).
pub const HMAX_OVER_H13: f64 = 1.8;
/// Goda's (2000) required sliding safety factor.
pub const DEFAULT_SLIDING_SAFETY_FACTOR: f64 = 1.2;
/// Goda's (2000) required overturning safety factor.
pub const DEFAULT_OVERTURNING_SAFETY_FACTOR: f64 = 1.2;
/// The allowable heel pressure on a rubble mound, Pa (Goda 2000: 400-500 kPa; Takahashi 2002:
/// 500-600 kPa; module docs).
pub const DEFAULT_ALLOWABLE_HEEL_PRESSURE_PA: f64 = 500e3;

/// How the design wave height was found (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum DesignWaveRule {
    /// Regular waves: the wave height itself.
    #[serde(rename = "regular-height")]
    RegularHeight,
    /// Irregular waves outside the surf zone: H_max = 1.8 H1/3.
    #[serde(rename = "1.8-significant-height")]
    OutsideSurfZone,
    /// Irregular waves inside the surf zone: Goda's breaking-limited H_max at h_b.
    #[serde(rename = "goda-breaking-limited")]
    BreakingLimited,
}

impl DesignWaveRule {
    /// The rule in words, for text output.
    pub fn describe(self) -> &'static str {
        match self {
            DesignWaveRule::RegularHeight => "the regular wave height",
            DesignWaveRule::OutsideSurfZone => "H_max = 1.8 H1/3 (Goda 2000, outside the surf zone)",
            DesignWaveRule::BreakingLimited => {
                "H_max = Goda's (2000) breaking-limited H_max at h_b (inside the surf zone: below 1.8 H1/3)"
            }
        }
    }
}

/// The wave of Goda's static checks (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DesignWave {
    /// `"regular"` or `"irregular"`: the scenario's waves.
    pub kind: &'static str,
    pub rule: DesignWaveRule,
    /// H_D, the height in Goda's pressure formula, m.
    pub design_height_m: f64,
    pub period_s: f64,
    /// H1/3 at the toe (irregular waves), m.
    pub significant_height_m: Option<f64>,
    /// 1.8 H1/3 (irregular waves), m.
    pub hmax_from_significant_m: Option<f64>,
    /// H0' whose Goda H1/3 at the toe is H1/3 (irregular waves; `None` if it cannot be found), m.
    pub equivalent_deep_water_height_m: Option<f64>,
    /// Goda's breaking-limited H_max at h_b from H0' (irregular waves), m.
    pub breaking_limited_hmax_m: Option<f64>,
    /// h_b, the depth 5 H1/3 (regular: 5 H) seaward of the wall where α2 is evaluated, m.
    pub depth_5h_seaward_m: f64,
}

impl DesignWave {
    /// A regular wave of height `height_m`: H_D = H.
    pub fn regular(model: &WaveLoadModel, height_m: f64, period_s: f64) -> Self {
        let s = &model.site;
        DesignWave {
            kind: "regular",
            rule: DesignWaveRule::RegularHeight,
            design_height_m: height_m,
            period_s,
            significant_height_m: None,
            hmax_from_significant_m: None,
            equivalent_deep_water_height_m: None,
            breaking_limited_hmax_m: None,
            depth_5h_seaward_m: s.depth_at_toe_m + 5.0 * height_m * s.seabed_slope,
        }
    }

    /// An irregular sea of significant height `h13_m` at the toe (module docs).
    pub fn irregular(model: &WaveLoadModel, h13_m: f64, period_s: f64) -> Self {
        let s = &model.site;
        let slope = s.seabed_slope;
        let hb = s.depth_at_toe_m + 5.0 * h13_m * slope.max(0.0);
        let from_h13 = HMAX_OVER_H13 * h13_m;
        let h0 = equivalent_deep_water_height_m(h13_m, period_s, s.depth_at_toe_m, slope);
        let limited = h0.map(|h0| goda_surf_zone(h0, period_s, hb, slope).hmax_m).filter(|h| h.is_finite());
        let (rule, design) = match limited {
            Some(h) if h < from_h13 => (DesignWaveRule::BreakingLimited, h),
            _ => (DesignWaveRule::OutsideSurfZone, from_h13),
        };
        DesignWave {
            kind: "irregular",
            rule,
            design_height_m: design,
            period_s,
            significant_height_m: Some(h13_m),
            hmax_from_significant_m: Some(from_h13),
            equivalent_deep_water_height_m: h0,
            breaking_limited_hmax_m: limited,
            depth_5h_seaward_m: hb,
        }
    }

    /// The design wave of the scenario's `[waves]`: its height H (regular) or H1/3 (irregular)
    /// and period.
    pub fn of(waves: &WaveSetup) -> Self {
        Self::with_height(waves, waves.height_m(), waves.period_s())
    }

    /// As [`Self::of`] for another height of the scenario's kind: H (regular) or H1/3
    /// (irregular), m, and period, s.
    pub fn with_height(waves: &WaveSetup, height_m: f64, period_s: f64) -> Self {
        match waves.train.kind {
            TrainKind::Regular { .. } => Self::regular(&waves.model, height_m, period_s),
            TrainKind::Irregular { .. } => Self::irregular(&waves.model, height_m, period_s),
        }
    }

    /// The loads of the design wave on `model`'s site, with the regime `choice` (one the wave
    /// contradicts, a non-breaking H_max above the breaking limit, falls back to the criterion's).
    pub fn loads(&self, model: &WaveLoadModel, choice: RegimeChoice) -> Result<WaveLoads, RegimeError> {
        let at = model.at_period(self.period_s);
        let hb = Some(self.depth_5h_seaward_m);
        match self.rule {
            DesignWaveRule::RegularHeight => at.evaluate_with(self.design_height_m, choice),
            _ => at
                .evaluate_at(self.design_height_m, hb, choice)
                .or_else(|_| at.evaluate_at(self.design_height_m, hb, RegimeChoice::Auto)),
        }
    }
}

/// Goda's static checks under the design wave.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StaticCheck {
    pub design_wave: DesignWave,
    pub loads: WaveLoads,
    pub safety: SafetyFactors,
}

impl StaticCheck {
    /// The static checks under `design_wave` on the site of `waves` with the regime `choice`, for
    /// a caisson of total weight in water `weight_in_water_n` (N) and friction `mu`.
    pub fn new(
        waves: &WaveSetup,
        design_wave: DesignWave,
        weight_in_water_n: f64,
        mu: f64,
        choice: RegimeChoice,
    ) -> Result<Self, RegimeError> {
        let loads = design_wave.loads(&waves.model, choice)?;
        let safety = waves.model.safety(&loads, weight_in_water_n, mu);
        Ok(StaticCheck { design_wave, loads, safety })
    }
}

/// The static checks of `structure` under the design wave of `waves` (its regime option).
pub fn static_check(structure: &Structure, waves: &WaveSetup) -> Result<StaticCheck, RegimeError> {
    let (w, mu) = (structure.caisson.weight_in_water_n, structure.foundation.mu_static);
    StaticCheck::new(waves, DesignWave::of(waves), w, mu, waves.regime())
}

/// Where a deterministic criterion is first reached in a range of widths.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "status", rename_all = "snake_case")]
pub enum Reached {
    /// At this width (to the tolerance; the upper end of the final bracket).
    Found { width_m: f64 },
    /// Already at the smallest width of the range.
    AtLowerBound { width_m: f64 },
    /// Not within the range.
    NotInRange { largest_m: f64 },
}

impl Reached {
    pub fn width_m(&self) -> Option<f64> {
        match self {
            Reached::Found { width_m } | Reached::AtLowerBound { width_m } => Some(*width_m),
            Reached::NotInRange { .. } => None,
        }
    }
}

/// The smallest width of `range_m` at which an increasing `f(width)` (e.g. Goda's sliding safety
/// factor, `None` where undefined: taken as below) reaches `target`, by bisection to `tolerance_m`.
pub fn smallest_width_reaching(
    range_m: (f64, f64),
    target: f64,
    tolerance_m: f64,
    f: &mut dyn FnMut(f64) -> Option<f64>,
) -> Reached {
    let reaches = |w: f64, f: &mut dyn FnMut(f64) -> Option<f64>| f(w).is_some_and(|v| v >= target);
    let (mut a, mut b) = range_m;
    if !reaches(b, f) {
        return Reached::NotInRange { largest_m: b };
    }
    if reaches(a, f) {
        return Reached::AtLowerBound { width_m: a };
    }
    while b - a > tolerance_m {
        let mid = 0.5 * (a + b);
        if reaches(mid, f) {
            b = mid;
        } else {
            a = mid;
        }
    }
    Reached::Found { width_m: b }
}

/// What Goda's conventional design requires of a width (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ConventionalCriteria {
    /// Required sliding safety factor (default 1.2).
    pub sliding_safety_factor: f64,
    /// Required overturning safety factor (default 1.2).
    pub overturning_safety_factor: f64,
    /// The allowable heel pressure, Pa (default 500 kPa).
    pub allowable_heel_pressure_pa: f64,
    /// Whether the heel pressure is a criterion of the width (default false: reported and warned).
    pub heel_pressure_governs: bool,
}

impl ConventionalCriteria {
    /// The criteria if in range: each safety factor from 1 to 10, the allowable heel pressure
    /// above 10 kPa and at most 10 MPa.
    pub fn checked(self) -> Result<Self, crate::ParamError> {
        use crate::check::interval;
        interval("sliding_safety_factor", self.sliding_safety_factor, 1.0, 10.0, false)?;
        interval("overturning_safety_factor", self.overturning_safety_factor, 1.0, 10.0, false)?;
        interval("allowable_heel_pressure_pa", self.allowable_heel_pressure_pa, 1e4, 1e7, true)?;
        Ok(self)
    }
}

impl Default for ConventionalCriteria {
    fn default() -> Self {
        ConventionalCriteria {
            sliding_safety_factor: DEFAULT_SLIDING_SAFETY_FACTOR,
            overturning_safety_factor: DEFAULT_OVERTURNING_SAFETY_FACTOR,
            allowable_heel_pressure_pa: DEFAULT_ALLOWABLE_HEEL_PRESSURE_PA,
            heel_pressure_governs: false,
        }
    }
}

/// Which requirement sets the conventional width.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Governs {
    Sliding,
    Overturning,
    HeelPressure,
}

/// The static checks at one width.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ChecksAtWidth {
    pub width_m: f64,
    pub sliding_safety_factor: Option<f64>,
    pub overturning_safety_factor: Option<f64>,
    /// p_e, kPa (`None`: the resultant leaves the base).
    pub heel_pressure_kpa: Option<f64>,
}

impl ChecksAtWidth {
    pub fn new(width_m: f64, sf: &SafetyFactors) -> Self {
        ChecksAtWidth {
            width_m,
            sliding_safety_factor: sf.sliding,
            overturning_safety_factor: sf.overturning,
            heel_pressure_kpa: sf.heel_pressure_pa.map(|p| p / 1e3),
        }
    }
}

/// Goda's conventional width (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ConventionalWidth {
    /// The smallest width meeting every requirement.
    #[serde(flatten)]
    pub reached: Reached,
    /// The requirement that sets it (the last one met as the width grows); `None` outside the range.
    pub governs: Option<Governs>,
    /// The width each requirement alone gives.
    pub sliding_only: Reached,
    pub overturning_only: Reached,
    /// `None` unless the heel pressure is a criterion.
    pub heel_pressure_only: Option<Reached>,
    /// The checks at the conventional width (if reached).
    pub at_width: Option<ChecksAtWidth>,
    /// p_e at the conventional width above the allowable value.
    pub heel_pressure_above_allowable: bool,
}

/// The conventional width over `range_m` to `tolerance_m` (module docs); `check(width)` gives
/// Goda's static checks under the design wave of the caisson at that width (`None` where it
/// cannot be built: taken as not met).
pub fn conventional_width(
    range_m: (f64, f64),
    tolerance_m: f64,
    c: &ConventionalCriteria,
    check: &mut dyn FnMut(f64) -> Option<SafetyFactors>,
) -> ConventionalWidth {
    let sliding_only = smallest_width_reaching(range_m, c.sliding_safety_factor, tolerance_m, &mut |w| {
        check(w).and_then(|s| s.sliding)
    });
    let overturning_only = smallest_width_reaching(range_m, c.overturning_safety_factor, tolerance_m, &mut |w| {
        check(w).and_then(|s| s.overturning)
    });
    // The heel pressure falls as the caisson widens (its weight and lever grow): its criterion is
    // allowable / p_e ≥ 1, undefined (not met) where the resultant leaves the base.
    let allowable = c.allowable_heel_pressure_pa;
    let heel_pressure_only = c.heel_pressure_governs.then(|| {
        smallest_width_reaching(range_m, 1.0, tolerance_m, &mut |w| {
            check(w).and_then(|s| s.heel_pressure_pa).map(|p| allowable / p)
        })
    });
    let mut parts = vec![(Governs::Sliding, sliding_only), (Governs::Overturning, overturning_only)];
    parts.extend(heel_pressure_only.map(|r| (Governs::HeelPressure, r)));
    // Each requirement holds from its own width on: all hold from the largest of them.
    let (reached, governs) = if let Some(&(_, r)) = parts.iter().find(|(_, r)| r.width_m().is_none()) {
        (r, None)
    } else {
        let (g, r) = parts
            .iter()
            .copied()
            .max_by(|a, b| a.1.width_m().unwrap_or(0.0).total_cmp(&b.1.width_m().unwrap_or(0.0)))
            .expect("two requirements at least");
        (r, Some(g))
    };
    let at_width = reached.width_m().and_then(|w| check(w).map(|s| ChecksAtWidth::new(w, &s)));
    let heel_pressure_above_allowable =
        at_width.is_some_and(|a| a.heel_pressure_kpa.is_none_or(|p| p * 1e3 > allowable));
    ConventionalWidth {
        reached,
        governs,
        sliding_only,
        overturning_only,
        heel_pressure_only,
        at_width,
        heel_pressure_above_allowable,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// f(B) = B/10 reaches 1.2 at B = 12 m.
    #[test]
    fn the_smallest_width_reaching_a_safety_factor() {
        let mut f = |b: f64| Some(b / 10.0);
        let Reached::Found { width_m: w } = smallest_width_reaching((5.0, 30.0), 1.2, 1e-3, &mut f) else { panic!() };
        assert!((12.0..=12.001).contains(&w), "{w}");
        assert_eq!(smallest_width_reaching((5.0, 11.0), 1.2, 1e-3, &mut f), Reached::NotInRange { largest_m: 11.0 });
        assert_eq!(smallest_width_reaching((13.0, 20.0), 1.2, 1e-3, &mut f), Reached::AtLowerBound { width_m: 13.0 });
    }
}
