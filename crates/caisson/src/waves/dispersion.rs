//! Linear (Airy) dispersion relation at any depth.
//!
//! ```text
//!     ω² = g k tanh(k h),      ω = 2π/T,   L = 2π/k,   L0 = g T²/(2π)      (docs/model.md §0)
//! ```
//!
//! With x = k0 h = ω² h/g and y = k h the relation reads y tanh y = x. It is solved by Halley's
//! method on f(y) = y tanh y − x (f' = tanh y + y sech² y, f'' = 2 sech² y (1 − y tanh y)),
//! started from Hunt's (1979) Padé approximation y² = x² + x/(1 + Σ_{n=1..6} d_n xⁿ) (exact in
//! both the deep-water limit y → x and the shallow-water limit y → √x). Halley converges
//! cubically: after a step smaller than 1e-7 y the remaining error is below an ulp, and the
//! iteration stops (usually after two steps). For x ≥ 20, tanh y = 1 to machine precision and
//! y = x. The unit tests check the residual of y tanh y = x to a few ulp for x from 1e-8 to 1e6.
//!
//! Also: the linear shoaling coefficient K_si = [tanh(kh) · 2n]^{−1/2},
//! n = ½ (1 + 2kh / sinh 2kh) (docs/model.md §3.3).

use crate::G_M_PER_S2;
use std::f64::consts::PI;

/// Angular frequency ω = 2π/T, rad/s.
#[inline]
pub fn angular_frequency(period_s: f64) -> f64 {
    2.0 * PI / period_s
}

/// Deep-water wavelength L0 = g T²/(2π), m.
#[inline]
pub fn deep_water_wavelength_m(period_s: f64) -> f64 {
    G_M_PER_S2 * period_s * period_s / (2.0 * PI)
}

/// Deep-water wave number k0 = ω²/g, rad/m.
#[inline]
pub fn deep_water_wavenumber(period_s: f64) -> f64 {
    let w = angular_frequency(period_s);
    w * w / G_M_PER_S2
}

/// Solve y tanh y = x for y > 0 (x = k0 h > 0). Returns `NaN` for x ≤ 0 or non-finite x.
#[inline]
pub fn solve_kh(x: f64) -> f64 {
    if !(x > 0.0 && x.is_finite()) {
        return f64::NAN;
    }
    // Deep water: 1 − tanh(20) = 8.5e-18 is below half an ulp of 1, so y = x exactly.
    if x >= 20.0 {
        return x;
    }
    // Hunt (1979) Padé start: y² = x² + x / (1 + Σ d_n xⁿ), relative error ~1e-4 or better.
    const D: [f64; 6] = [0.6666666667, 0.3555555556, 0.1608465608, 0.0632098765, 0.0217540484, 0.0065407983];
    let poly = 1.0 + x * (D[0] + x * (D[1] + x * (D[2] + x * (D[3] + x * (D[4] + x * D[5])))));
    let mut y = (x * x + x / poly).sqrt();
    // Halley iterations (cubic convergence): once a step is below 1e-7 y the remaining error is
    // ~(1e-7)³ y, far below an ulp, so the iteration stops after that step.
    for _ in 0..40 {
        let t = y.tanh();
        let s2 = 1.0 - t * t;
        let f = y * t - x;
        let df = t + y * s2;
        let ddf = 2.0 * s2 * (1.0 - y * t);
        let dy = 2.0 * f * df / (2.0 * df * df - f * ddf);
        let y_new = if y - dy > 0.0 { y - dy } else { 0.5 * y };
        let done = (y_new - y).abs() <= 1e-7 * y_new;
        y = y_new;
        if done {
            break;
        }
    }
    y
}

/// Wave number k (rad/m) for period `period_s` at depth `depth_m`. `NaN` if either is ≤ 0.
#[inline]
pub fn wavenumber(period_s: f64, depth_m: f64) -> f64 {
    if !(period_s > 0.0 && depth_m > 0.0) {
        return f64::NAN;
    }
    solve_kh(deep_water_wavenumber(period_s) * depth_m) / depth_m
}

/// Wavelength L = 2π/k (m) for period `period_s` at depth `depth_m`.
#[inline]
pub fn wavelength_m(period_s: f64, depth_m: f64) -> f64 {
    2.0 * PI / wavenumber(period_s, depth_m)
}

/// Ratio of group to phase velocity n = ½ (1 + 2kh / sinh 2kh).
#[inline]
pub fn group_velocity_ratio(kh: f64) -> f64 {
    if kh > 350.0 {
        return 0.5;
    }
    0.5 * (1.0 + 2.0 * kh / (2.0 * kh).sinh())
}

/// Linear shoaling coefficient K_si = [tanh(kh) · 2n]^{−1/2} (docs/model.md §3.3).
#[inline]
pub fn linear_shoaling_coefficient(period_s: f64, depth_m: f64) -> f64 {
    shoaling_coefficient_from_wavenumber(wavenumber(period_s, depth_m), depth_m)
}

/// [`linear_shoaling_coefficient`] from the wave number k at the depth (rad/m; saves a
/// dispersion solve when k is known).
#[inline]
pub fn shoaling_coefficient_from_wavenumber(k: f64, depth_m: f64) -> f64 {
    let kh = k * depth_m;
    1.0 / (kh.tanh() * 2.0 * group_velocity_ratio(kh)).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn residual_is_machine_precision_over_all_depths() {
        // Relative residual of y tanh y = x. Tolerance 8 ulp: the residual of an exact root,
        // evaluated in floating point, is itself a few ulp.
        let mut x = 1e-8;
        while x < 1e6 {
            let y = solve_kh(x);
            let r = (y * y.tanh() - x).abs() / x;
            assert!(r <= 8.0 * f64::EPSILON, "x = {x}: y = {y}, residual {r:e}");
            x *= 1.37;
        }
    }

    #[test]
    fn pari_wavelength_matches_physics_md() {
        // docs/model.md §11: T = 3.04 s, h = 1.14 m → L = 9.3214 m (given to 5 digits → 1e-5 relative).
        let l = wavelength_m(3.04, 1.14);
        assert!((l - 9.3214).abs() / 9.3214 < 1e-5, "L = {l}");
    }

    #[test]
    fn limits_deep_and_shallow() {
        // Deep water (h/L0 = 10): L = L0 to 1e-12 (tanh(2π·10) = 1 − 1e-54).
        let l0 = deep_water_wavelength_m(5.0);
        assert!((wavelength_m(5.0, 10.0 * l0) - l0).abs() / l0 < 1e-12);
        // Shallow water (h/L0 = 1e-6): L = T √(g h) to 1e-5 (first correction is (kh)²/6 ≈ 7e-6).
        let h = 1e-6 * l0;
        let ls = 5.0 * (G_M_PER_S2 * h).sqrt();
        assert!((wavelength_m(5.0, h) - ls).abs() / ls < 1e-5);
    }

    #[test]
    fn bad_input_gives_nan_not_panic() {
        assert!(wavenumber(0.0, 1.0).is_nan());
        assert!(wavenumber(1.0, -1.0).is_nan());
        assert!(wavenumber(f64::NAN, 1.0).is_nan());
        assert!(solve_kh(f64::INFINITY).is_nan());
    }

    #[test]
    fn shoaling_coefficient_deep_water_is_one() {
        // Deep water: tanh = 1, n = ½ → K_si = 1 (to 1e-12).
        assert!((linear_shoaling_coefficient(5.0, 1000.0) - 1.0).abs() < 1e-12);
        // Minimum of K_si is about 0.913 near h/L0 ≈ 0.15 (textbook value).
        let l0 = deep_water_wavelength_m(5.0);
        let k = linear_shoaling_coefficient(5.0, 0.15 * l0);
        assert!((k - 0.913).abs() < 0.002, "K_si = {k}");
    }
}
