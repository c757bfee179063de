//! Static stability checks of an upright section under the Goda loads (Goda 2000 conventions;
//! docs/model.md §1.5, seed Eqs. 9-11). Per metre of breakwater.
//!
//! ```text
//! sliding       SF_s = μ (W' − U) / P                          (Goda: ≥ 1.2)
//! overturning   SF_o = (W' t − M_U) / M_P                      (Goda: ≥ 1.2)
//! heel bearing  M_e = W' t − M_U − M_P,  V_e = W' − U,  t_e = M_e / V_e
//!               p_e = 2 V_e / (3 t_e)                 if t_e ≤ B/3
//!               p_e = (2 V_e / B)(2 − 3 t_e / B)      if t_e > B/3
//! ```
//!
//! W' is the weight in water, t the horizontal distance from the heel to the centre of gravity
//! (B/2 for a symmetric caisson, seed Eq. 11), M_P the moment of P about the base and M_U the
//! moment of U about the heel. A factor is `None` when its denominator is zero (no load); the heel
//! pressure is `None` when V_e ≤ 0 or t_e ≤ 0 (the caisson lifts off or overturns). A factor is
//! also `None` when its resistance is not positive (U ≥ W', or a restoring moment ≤ 0): there is
//! then no resistance to compare (never a negative factor).

/// Inputs (SI, per metre).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SafetyInput {
    /// W', weight in water, N/m.
    pub weight_in_water_n_per_m: f64,
    /// t, distance from the heel to the centre of gravity, m.
    pub cog_from_heel_m: f64,
    /// B, base width, m.
    pub width_m: f64,
    /// μ, friction coefficient.
    pub mu: f64,
    /// P, N/m.
    pub horizontal_force_n_per_m: f64,
    /// M_P about the base, N·m/m.
    pub horizontal_moment_base_nm_per_m: f64,
    /// U, N/m.
    pub uplift_force_n_per_m: f64,
    /// M_U about the heel, N·m/m.
    pub uplift_moment_heel_nm_per_m: f64,
}

/// Safety factors and heel pressure.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SafetyFactors {
    pub sliding: Option<f64>,
    pub overturning: Option<f64>,
    /// p_e, bearing pressure at the heel, Pa.
    pub heel_pressure_pa: Option<f64>,
    /// t_e = M_e / V_e, distance of the resultant from the heel, m.
    pub resultant_from_heel_m: Option<f64>,
}

/// Goda's stability checks (module docs).
pub fn safety_factors(i: &SafetyInput) -> SafetyFactors {
    let w = i.weight_in_water_n_per_m;
    // A factor exists where the load and the resistance are both positive: with no resistance
    // left (uplift above the weight, a restoring moment ≤ 0) there is nothing to compare.
    let ratio = |num: f64, den: f64| (den > 0.0 && num > 0.0).then(|| num / den);
    let sliding = ratio(i.mu * (w - i.uplift_force_n_per_m), i.horizontal_force_n_per_m);
    let restoring = w * i.cog_from_heel_m - i.uplift_moment_heel_nm_per_m;
    let overturning = ratio(restoring, i.horizontal_moment_base_nm_per_m);
    let me = restoring - i.horizontal_moment_base_nm_per_m;
    let ve = w - i.uplift_force_n_per_m;
    let (te, pe) = if ve > 0.0 && me > 0.0 {
        let te = me / ve;
        (Some(te), Some(heel_pressure_pa(ve, te, i.width_m)))
    } else {
        (None, None)
    };
    SafetyFactors { sliding, overturning, heel_pressure_pa: pe, resultant_from_heel_m: te }
}

/// The heel (shoreward edge) value of the linear base pressure without tension that carries the
/// normal force `v_n_per_m` (> 0) with its resultant `te_m` from the heel on a base `width_m` wide,
/// Pa (module docs): 2V/(3 t_e) where part of the base is unloaded (t_e ≤ B/3), (2V/B)(2 − 3 t_e/B)
/// where the whole base is pressed, 0 where the resultant lies two thirds of the base or more
/// from the heel (the heel unloaded), and infinite where t_e ≤ 0 (no base carries it).
pub fn heel_pressure_pa(v_n_per_m: f64, te_m: f64, width_m: f64) -> f64 {
    let b = width_m;
    if te_m <= 0.0 {
        f64::INFINITY
    } else if te_m <= b / 3.0 {
        2.0 * v_n_per_m / (3.0 * te_m)
    } else {
        (2.0 * v_n_per_m / b * (2.0 - 3.0 * te_m / b)).max(0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn no_wave_load_gives_uniform_bearing_and_no_factors() {
        // P = U = 0: t_e = B/2 > B/3 → p_e = (2W/B)(2 − 3/2) = W/B, the uniform pressure.
        let r = safety_factors(&SafetyInput {
            weight_in_water_n_per_m: 8240.0,
            cog_from_heel_m: 0.39,
            width_m: 0.78,
            mu: 0.6,
            horizontal_force_n_per_m: 0.0,
            horizontal_moment_base_nm_per_m: 0.0,
            uplift_force_n_per_m: 0.0,
            uplift_moment_heel_nm_per_m: 0.0,
        });
        assert!(r.sliding.is_none() && r.overturning.is_none());
        assert!((r.heel_pressure_pa.unwrap() - 8240.0 / 0.78).abs() < 1e-9);
    }

    /// An uplift above the weight leaves no resistance: no factor, not a negative one.
    #[test]
    fn no_resistance_gives_no_factor() {
        let r = safety_factors(&SafetyInput {
            weight_in_water_n_per_m: 1000.0,
            cog_from_heel_m: 0.39,
            width_m: 0.78,
            mu: 0.6,
            horizontal_force_n_per_m: 500.0,
            horizontal_moment_base_nm_per_m: 200.0,
            uplift_force_n_per_m: 1500.0,
            uplift_moment_heel_nm_per_m: 800.0,
        });
        assert_eq!((r.sliding, r.overturning, r.heel_pressure_pa), (None, None, None));
    }

    #[test]
    fn overturned_caisson_has_no_heel_pressure() {
        let r = safety_factors(&SafetyInput {
            weight_in_water_n_per_m: 1000.0,
            cog_from_heel_m: 0.39,
            width_m: 0.78,
            mu: 0.6,
            horizontal_force_n_per_m: 5000.0,
            horizontal_moment_base_nm_per_m: 3000.0,
            uplift_force_n_per_m: 100.0,
            uplift_moment_heel_nm_per_m: 52.0,
        });
        assert!(r.heel_pressure_pa.is_none() && r.overturning.unwrap() < 1.0);
    }
}
