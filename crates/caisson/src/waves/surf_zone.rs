//! Goda's (2000) surf-zone wave heights for random waves, with Kweon & Goda (1996) nonlinear
//! shoaling (docs/model.md §3.3; verified against the `breakwater` package, BW).
//!
//! ```text
//! H1/3  = min{ β0 H0' + β1 h,   β_max H0',   K_s H0' }          (h/L0 < 0.2; else K_s H0')
//! H_max = min{ β0* H0' + β1* h, β_max* H0',  1.8 K_s H0' }     (h/L0 < 0.2; else 1.8 K_s H0')
//! β0  = 0.028 (H0'/L0)^−0.38 exp(20 tan^1.5 θ)     β0*  = 0.052 (H0'/L0)^−0.38 exp(20 tan^1.5 θ)
//! β1  = 0.52 exp(4.2 tan θ)                         β1*  = 0.63 exp(3.8 tan θ)
//! β_max = max{0.92, 0.32 (H0'/L0)^−0.29 exp(2.4 tan θ)}
//! β_max*= max{1.65, 0.53 (H0'/L0)^−0.29 exp(2.4 tan θ)}
//! K_s ≈ K_si + 0.0015 (h/L0)^−2.87 (H0'/L0)^1.27              (Kweon & Goda 1996)
//! ```
//!
//! H0' is the equivalent deep-water significant height, L0 = g T1/3²/(2π), θ the seabed slope.
//! The design H_max for Goda's pressure formula is evaluated at h_b = h + 5 H1/3 tan θ
//! ([`design_heights`]).

use super::dispersion::{deep_water_wavelength_m, linear_shoaling_coefficient, shoaling_coefficient_from_wavenumber};

/// Surf-zone heights at one depth.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SurfZoneHeights {
    /// Significant height H1/3, m.
    pub h13_m: f64,
    /// Maximum height H_max, m.
    pub hmax_m: f64,
    /// Nonlinear shoaling coefficient K_s used, -.
    pub shoaling: f64,
}

/// Kweon & Goda (1996) nonlinear shoaling coefficient K_s (docs/model.md §3.3).
#[inline]
pub fn kweon_goda_shoaling(depth_m: f64, period_s: f64, h0_prime_m: f64) -> f64 {
    let l0 = deep_water_wavelength_m(period_s);
    linear_shoaling_coefficient(period_s, depth_m) + 0.0015 * (depth_m / l0).powf(-2.87) * (h0_prime_m / l0).powf(1.27)
}

/// Goda's H1/3 and H_max at depth `depth_m` for deep-water H0' `h0_prime_m`, period T1/3
/// `period_s` and seabed slope tan θ `slope` (≥ 0).
pub fn goda_surf_zone(h0_prime_m: f64, period_s: f64, depth_m: f64, slope: f64) -> SurfZoneHeights {
    SlopeTerms::new(slope).surf_zone(h0_prime_m, period_s, depth_m)
}

/// The factors of Goda's β coefficients that depend on the seabed slope alone (module docs):
/// exp(20 tan^1.5 θ), β1, exp(2.4 tan θ) and β1*, for many storms on one slope.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlopeTerms {
    e20: f64,
    beta1: f64,
    e24: f64,
    beta1s: f64,
}

impl SlopeTerms {
    /// The terms of the slope tan θ `slope` (negative taken as 0).
    pub fn new(slope: f64) -> Self {
        let s = slope.max(0.0);
        SlopeTerms {
            e20: (20.0 * s.powf(1.5)).exp(),
            beta1: 0.52 * (4.2 * s).exp(),
            e24: (2.4 * s).exp(),
            beta1s: 0.63 * (3.8 * s).exp(),
        }
    }

    /// [`goda_surf_zone`] on this slope: the same numbers, the slope's terms computed once.
    pub fn surf_zone(&self, h0_prime_m: f64, period_s: f64, depth_m: f64) -> SurfZoneHeights {
        self.surf_zone_with(h0_prime_m, period_s, depth_m, linear_shoaling_coefficient(period_s, depth_m))
    }

    /// [`Self::surf_zone`] with the wave number at `depth_m` given (rad/m; the same numbers when it
    /// is [`crate::waves::dispersion::wavenumber`]`(period_s, depth_m)`: a caller that needs it too
    /// solves the dispersion relation once).
    pub fn surf_zone_at_wavenumber(&self, h0_prime_m: f64, period_s: f64, depth_m: f64, k: f64) -> SurfZoneHeights {
        self.surf_zone_with(h0_prime_m, period_s, depth_m, shoaling_coefficient_from_wavenumber(k, depth_m))
    }

    /// [`Self::surf_zone`] with the linear shoaling coefficient K_si at `depth_m` given (it does
    /// not depend on H0': a search over H0' solves the dispersion relation once).
    fn surf_zone_with(&self, h0_prime_m: f64, period_s: f64, depth_m: f64, ksi: f64) -> SurfZoneHeights {
        let l0 = deep_water_wavelength_m(period_s);
        let ks = ksi + 0.0015 * (depth_m / l0).powf(-2.87) * (h0_prime_m / l0).powf(1.27);
        let shoaled = ks * h0_prime_m;
        if depth_m / l0 >= 0.2 {
            return SurfZoneHeights { h13_m: shoaled, hmax_m: 1.8 * shoaled, shoaling: ks };
        }
        let steep = h0_prime_m / l0;
        // (H0'/L0)^−0.38 and ^−0.29, each in two coefficients.
        let (s38, s29) = (steep.powf(-0.38), steep.powf(-0.29));
        let beta0 = 0.028 * s38 * self.e20;
        let beta_max = (0.32 * s29 * self.e24).max(0.92);
        let beta0s = 0.052 * s38 * self.e20;
        let beta_maxs = (0.53 * s29 * self.e24).max(1.65);
        let h13_m = (beta0 * h0_prime_m + self.beta1 * depth_m).min(beta_max * h0_prime_m).min(shoaled);
        let hmax_m = (beta0s * h0_prime_m + self.beta1s * depth_m).min(beta_maxs * h0_prime_m).min(1.8 * shoaled);
        SurfZoneHeights { h13_m, hmax_m, shoaling: ks }
    }
}

/// Design heights for Goda's pressure formula (docs/model.md §1.3, §3.3): H1/3 at the site depth
/// `depth_m`, and H_max at h_b = h + 5 H1/3 tan θ. Returns (H1/3 at h, H_max at h_b, h_b), m.
pub fn design_heights(h0_prime_m: f64, period_s: f64, depth_m: f64, slope: f64) -> (f64, f64, f64) {
    let at_site = goda_surf_zone(h0_prime_m, period_s, depth_m, slope);
    let hb = depth_m + 5.0 * at_site.h13_m * slope.max(0.0);
    let at_hb = goda_surf_zone(h0_prime_m, period_s, hb, slope);
    (at_site.h13_m, at_hb.hmax_m, hb)
}

/// The equivalent deep-water height H0' whose Goda H1/3 at `depth_m` is `h13_m` (Goda's H1/3 grows
/// with H0': each term of its minimum does), by regula falsi (Illinois) to a relative 1e-12; `None` if `h13_m`
/// or the site is not a positive finite number. What a design from H1/3 at the toe needs to
/// find Goda's breaking-limited H_max there ([`crate::analysis::conventional`]).
pub fn equivalent_deep_water_height_m(h13_m: f64, period_s: f64, depth_m: f64, slope: f64) -> Option<f64> {
    let positive = |x: f64| x.is_finite() && x > 0.0;
    if !(positive(h13_m) && positive(period_s) && positive(depth_m) && slope.is_finite()) {
        return None;
    }
    let ksi = linear_shoaling_coefficient(period_s, depth_m);
    let terms = SlopeTerms::new(slope);
    let h13 = |h0: f64| terms.surf_zone_with(h0, period_s, depth_m, ksi).h13_m;
    // A bracket [lo, hi] with H1/3(lo) < h13_m ≤ H1/3(hi), from H0' = H1/3 by halving or doubling
    // (K_s ≥ 0.9 and β_max ≥ 0.92: H1/3 is of the order of H0').
    let f = |h0: f64| h13(h0) - h13_m;
    let reaches = |h0: f64| f(h0) >= 0.0; // false for a NaN
    let (mut lo, mut hi) = (h13_m, h13_m);
    let mut tries = 0;
    while !reaches(hi) && tries < 200 {
        (lo, hi) = (hi, 2.0 * hi);
        tries += 1;
    }
    while reaches(lo) && tries < 400 {
        (hi, lo) = (lo, 0.5 * lo);
        tries += 1;
    }
    let (mut f_lo, mut f_hi) = (f(lo), f(hi));
    let bracketed = f_lo < 0.0 && f_hi >= 0.0; // false for a NaN too
    if !bracketed {
        return None;
    }
    // The Illinois variant of regula falsi (Dowell & Jarratt 1971): the secant of the bracket,
    // halving the value kept at an end that stays twice in a row, so both ends converge
    // (superlinearly; about 8 evaluations where bisection takes 40). A secant point outside the
    // bracket (rounding) falls back to bisection.
    let mut kept = 0i8;
    for _ in 0..200 {
        if hi - lo <= 1e-12 * hi {
            break;
        }
        let mut c = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
        if !(c > lo && c < hi) {
            c = 0.5 * (lo + hi);
        }
        let fc = f(c);
        if fc >= 0.0 {
            (hi, f_hi) = (c, fc);
            if kept == 1 {
                f_lo *= 0.5;
            }
            kept = 1;
            if fc == 0.0 {
                break;
            }
        } else {
            (lo, f_lo) = (c, fc);
            if kept == -1 {
                f_hi *= 0.5;
            }
            kept = -1;
        }
    }
    Some(hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The inverse of Goda's H1/3: H0' → H1/3 → H0' returns the H0' to 1e-10 (relative; the search
    /// stops at 1e-12 of the bracket, and H1/3 grows about as fast as H0'), over depths from the
    /// surf zone to outside it (h/L0 from 0.02 to 0.3), slopes, periods and steepnesses: 48 cases.
    #[test]
    fn the_equivalent_deep_water_height_inverts_godas_h13() {
        let mut n = 0;
        for period in [8.0, 12.8, 16.0] {
            for depth in [5.0, 12.0, 20.0, 60.0] {
                for slope in [0.0, 0.02] {
                    for h0 in [1.5, 6.0] {
                        let h13 = goda_surf_zone(h0, period, depth, slope).h13_m;
                        let back = equivalent_deep_water_height_m(h13, period, depth, slope).unwrap();
                        assert!(
                            (back - h0).abs() < 1e-10 * h0,
                            "T {period}, h {depth}, θ {slope}: {h0} → {h13} → {back}"
                        );
                        n += 1;
                    }
                }
            }
        }
        assert_eq!(n, 48);
        assert_eq!(equivalent_deep_water_height_m(f64::NAN, 12.8, 20.0, 0.01), None);
        assert_eq!(equivalent_deep_water_height_m(7.5, 12.8, -1.0, 0.01), None);
    }

    #[test]
    fn outside_surf_zone_is_shoaling_only() {
        // h/L0 ≥ 0.2: H1/3 = K_s H0', H_max = 1.8 K_s H0' exactly, with K_s = K_si + the
        // Kweon-Goda term 0.0015 (h/L0)^-2.87 (H0'/L0)^1.27.
        let (t, h0) = (8.0, 2.0);
        let l0 = deep_water_wavelength_m(t);
        let h = 0.3 * l0;
        let r = goda_surf_zone(h0, t, h, 0.01);
        assert_eq!(r.h13_m, r.shoaling * h0);
        assert_eq!(r.hmax_m, 1.8 * r.shoaling * h0);
        let expected = linear_shoaling_coefficient(t, h) + 0.0015 * 0.3f64.powf(-2.87) * (h0 / l0).powf(1.27);
        assert!((r.shoaling - expected).abs() < 1e-14, "K_s = {}", r.shoaling);
    }

    #[test]
    fn surf_zone_heights_are_the_smallest_of_goda_s_three_terms() {
        // docs/model.md §3.3 example by hand: H0' = 3 m, T = 10 s, tan θ = 0.02, h = 5 m.
        let (t, h0, s, h) = (10.0f64, 3.0f64, 0.02f64, 5.0f64);
        let l0 = deep_water_wavelength_m(t);
        let st = h0 / l0;
        let ks = kweon_goda_shoaling(h, t, h0);
        let e20 = (20.0 * s.powf(1.5)).exp();
        let h13 = (0.028 * st.powf(-0.38) * e20 * h0 + 0.52 * (4.2 * s).exp() * h)
            .min((0.32 * st.powf(-0.29) * (2.4 * s).exp()).max(0.92) * h0)
            .min(ks * h0);
        let r = goda_surf_zone(h0, t, h, s);
        assert!((r.h13_m - h13).abs() < 1e-12, "{} vs {h13}", r.h13_m);
        // At 5 m depth the 3 m wave is depth-limited: H1/3 below the shoaled height, H_max ≥ H1/3.
        assert!(r.h13_m < ks * h0 && r.hmax_m > r.h13_m, "{r:?}");
        // In very shallow water the linear term governs and H1/3 → β0 H0' + β1 h grows with h.
        let a = goda_surf_zone(h0, t, 1.0, s).h13_m;
        let b = goda_surf_zone(h0, t, 1.5, s).h13_m;
        assert!(b > a && a < 1.0, "{a} {b}");
    }

    #[test]
    fn design_depth_is_five_heights_seaward() {
        let (h13, hmax, hb) = design_heights(3.0, 10.0, 8.0, 0.02);
        assert!((hb - (8.0 + 5.0 * h13 * 0.02)).abs() < 1e-12);
        assert!(hmax > h13);
    }
}
