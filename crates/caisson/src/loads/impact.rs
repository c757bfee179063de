//! Breaking-wave impact: Cuomo et al. (2010) horizontal impact force (seed Eq. 30), the impact
//! uplift of Oumeraci et al. (2001) as simplified by the seed (Eq. 32), and the lever arms of the
//! PROVERBS simplified impact distribution (docs/model.md §4.2, §4.3, §5.1, §10 item 19).
//!
//! ```text
//! F_x,max = a_imp · α_max · ρ_w g · H · L(d_s) · max{0, 1 − |d_b − d| / d}          (seed Eq. 30)
//! p1      = F_x,max / (0.4 H_br + 0.7 d*),   d* = h' = d + e
//! F_y,max = 0.45 p1 · B/2                                                            (seed Eq. 32)
//! M_h     = p1 [ 0.4 H_br (d* + 0.8 H_br/3) + d*² (0.45/2 + 0.55/3) ]   (about the base) (§4.3)
//! ```
//!
//! * H is the wave height at the toe (Miche-limited at d_s by the caller), L(d_s) the wavelength
//!   at the toe depth for T (regular waves: T = T_m).
//! * d_b is the breaking depth of H and H_br = H_b(d) the breaker height at the wall, both from
//!   the chosen breaking criterion (default Miche: docs/model.md §4.2 recommendation; the seed's
//!   PROVERBS recipe was not recovered). If the criterion gives no breaking depth, the reduction
//!   factor is 0.
//! * α_max = 1/1.8 for regular waves (seed), 1 with H = H_s for random waves; `a_imp` = 1 as in
//!   the seed (docs/model.md §5.1, §12: the coefficient of Cuomo et al. (2010) is unconfirmed).
//! * The distribution behind M_h: zero at 0.8 H_br above still water, p1 at still water,
//!   0.45 p1 at the base; above still water it is cut at the crest h_c if 0.8 H_br > h_c. The lever
//!   y_L = M_h / F_x,max (the 0.7 in p1 approximates 0.725, as in the seed). The uplift is a
//!   triangle, 0.45 p1 at the seaward toe and zero at the heel (seed: zero rear pressure): it acts
//!   2B/3 from the heel.

use super::profile::Profile;
use crate::waves::breaking::{BreakerCriterion, BreakingAtPeriod};
use crate::G_M_PER_S2;

/// Inputs (SI, per metre).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactInput {
    /// H, wave height at the toe, m.
    pub height_m: f64,
    /// T, period (T_m), s.
    pub period_s: f64,
    /// L(d_s), wavelength at the toe depth, m.
    pub toe_wavelength_m: f64,
    /// d, depth in front of the wall, m.
    pub wall_depth_m: f64,
    /// h' = d + e, depth of the caisson base, m.
    pub base_depth_m: f64,
    /// h_c, crest freeboard, m.
    pub crest_freeboard_m: f64,
    /// B, base width, m.
    pub width_m: f64,
    pub criterion: BreakerCriterion,
    /// α_max (1/1.8 for regular waves).
    pub alpha_max: f64,
    /// a_imp, extra coefficient (1 in the seed).
    pub a_imp: f64,
    pub rho_w: f64,
}

/// Impact quantities (per metre).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct ImpactResult {
    /// d_b, breaking depth of H, m (`None` if the criterion gives none).
    pub breaking_depth_m: Option<f64>,
    /// H_br = H_b(d), breaker height at the wall, m.
    pub breaker_height_m: f64,
    /// max{0, 1 − |d_b − d|/d}.
    pub reduction: f64,
    /// F_x,max, N/m.
    pub horizontal_force_n_per_m: f64,
    /// p1 of the impact distribution, Pa.
    pub p1_pa: f64,
    /// M_h about the base, N·m/m.
    pub horizontal_moment_base_nm_per_m: f64,
    /// y_L, height of the horizontal resultant above the base, m.
    pub horizontal_lever_m: f64,
    /// F_y,max, N/m.
    pub uplift_force_n_per_m: f64,
    /// Distance of the uplift resultant from the heel (2B/3), m.
    pub uplift_from_heel_m: f64,
    /// F_y,max · 2B/3 about the heel, N·m/m.
    pub uplift_moment_heel_nm_per_m: f64,
}

/// Seed Eq. 30 reduction factor max{0, 1 − |d_b − d|/d} (docs/model.md §10 item 19: clamped at 0).
#[inline]
pub fn eq30_reduction(breaking_depth_m: Option<f64>, wall_depth_m: f64) -> f64 {
    breaking_depth_m.map_or(0.0, |db| (1.0 - (db - wall_depth_m).abs() / wall_depth_m).max(0.0))
}

/// Impact force, uplift and lever arms (module docs).
pub fn impact(i: &ImpactInput) -> ImpactResult {
    impact_with_breaking(i, i.criterion.breaker_height_m(i.wall_depth_m, i.period_s))
}

/// As [`impact`] with the breaker height at the wall H_br (m) already computed.
pub fn impact_with_breaking(i: &ImpactInput, hbr: f64) -> ImpactResult {
    ImpactPeriod::new(i, hbr).at(i.height_m)
}

/// The part of the impact that does not depend on the height: the breaker height at the wall,
/// the lever of the unit distribution and the breaking criterion at the period.
/// [`ImpactPeriod::at`] finishes it for one height with the same floating-point operations as
/// [`impact_with_breaking`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ImpactPeriod {
    input: ImpactInput,
    hbr: f64,
    breaking: BreakingAtPeriod,
    /// a_imp α_max ρ_w g.
    force_coefficient: f64,
    denom: f64,
    lever: f64,
}

impl ImpactPeriod {
    /// Everything of `i` but its height (`height_m` is ignored), with H_br = `hbr`.
    pub fn new(i: &ImpactInput, hbr: f64) -> Self {
        let ds = i.base_depth_m;
        let denom = 0.4 * hbr + 0.7 * ds;
        // Unit distribution (p1 = 1): its moment about the base, cut at the crest.
        let unit = impact_profile(1.0, hbr, ds, i.crest_freeboard_m);
        ImpactPeriod {
            input: *i,
            hbr,
            breaking: i.criterion.at_period(i.period_s),
            force_coefficient: i.a_imp * i.alpha_max * i.rho_w * G_M_PER_S2,
            denom,
            lever: unit.moment_about(ds) / denom,
        }
    }

    /// Upper bounds [F_x,max, its moment about the base, F_y,max] (per metre, each ≥ 0) over
    /// every height up to `max_height_m` at the toe: the reduction of Eq. 30 is at most 1, F_y,max
    /// and the moment follow F_x,max with their height-free factors. `None` unless a_imp α_max ≥ 0,
    /// B > 0 and the distribution's denominator 0.4 H_br + 0.7 h' > 0 (what the bounds assume).
    pub fn upper_bounds(&self, max_height_m: f64) -> Option<[f64; 3]> {
        let i = &self.input;
        if !(self.force_coefficient >= 0.0 && i.toe_wavelength_m > 0.0 && self.denom > 0.0 && i.width_m > 0.0) {
            return None;
        }
        let fx = self.force_coefficient * max_height_m.max(0.0) * i.toe_wavelength_m;
        let fy = 0.45 * (fx / self.denom) * i.width_m / 2.0;
        Some([fx, fx * self.lever.max(0.0), fy])
    }

    /// The impact of a wave of height `height_m` at the toe.
    #[inline(always)]
    pub fn at(&self, height_m: f64) -> ImpactResult {
        let i = &self.input;
        let db = self.breaking.breaking_depth_m(height_m);
        let reduction = eq30_reduction(db, i.wall_depth_m);
        let fx = self.force_coefficient * height_m * i.toe_wavelength_m * reduction;
        let p1 = fx / self.denom;
        let fy = 0.45 * p1 * i.width_m / 2.0;
        let xu = 2.0 * i.width_m / 3.0;
        ImpactResult {
            breaking_depth_m: db,
            breaker_height_m: self.hbr,
            reduction,
            horizontal_force_n_per_m: fx,
            p1_pa: p1,
            horizontal_moment_base_nm_per_m: fx * self.lever,
            horizontal_lever_m: self.lever,
            uplift_force_n_per_m: fy,
            uplift_from_heel_m: xu,
            uplift_moment_heel_nm_per_m: fy * xu,
        }
    }
}

/// The PROVERBS simplified impact distribution (docs/model.md §4.3) for a given p1: zero at
/// 0.8 H_br above still water (cut at the crest h_c), p1 at still water, 0.45 p1 at the base h'.
pub fn impact_profile(p1_pa: f64, breaker_height_m: f64, base_depth_m: f64, crest_freeboard_m: f64) -> Profile {
    let top = 0.8 * breaker_height_m;
    let cut = top.min(crest_freeboard_m);
    let p_top = if top > 0.0 { p1_pa * (1.0 - cut / top) } else { p1_pa };
    Profile::new(&[(-cut, p_top), (0.0, p1_pa), (base_depth_m, 0.45 * p1_pa)])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lever_matches_physics_md_closed_form_when_not_overtopped() {
        // §4.3: M_h = p1 [0.4 H_b (d* + 0.8 H_b/3) + d*² (0.45/2 + 0.55/3)], 0.8 H_b ≤ h_c.
        let (p1, hb, ds) = (1000.0, 0.336, 0.8);
        let closed = p1 * (0.4 * hb * (ds + 0.8 * hb / 3.0) + ds * ds * (0.45 / 2.0 + 0.55 / 3.0));
        let m = impact_profile(p1, hb, ds, 0.32).moment_about(ds);
        assert!((m - closed).abs() < 1e-12 * closed, "{m} vs {closed}");
        // Cut at a low crest: smaller moment than the uncut distribution.
        assert!(impact_profile(p1, hb, ds, 0.1).moment_about(ds) < closed);
    }

    #[test]
    fn reduction_is_clamped_at_zero() {
        assert_eq!(eq30_reduction(Some(0.9), 0.4), 0.0);
        assert_eq!(eq30_reduction(None, 0.4), 0.0);
        assert_eq!(eq30_reduction(Some(0.4), 0.4), 1.0);
    }
}
