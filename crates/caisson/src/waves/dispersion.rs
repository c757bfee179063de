//! Linear (Airy) dispersion relation at any depth.
//!
//! ```text
//!     ω² = g k tanh(k h),      ω = 2π/T,   L = 2π/k,   L0 = g T²/(2π)      (PHYSICS.md §0)
//! ```
//!
//! With x = k0 h = ω² h/g and y = k h the relation reads y tanh y = x. It is solved by Newton's
//! method on f(y) = y tanh y − x, f'(y) = tanh y + y (1 − tanh² y), started from Guo's (2002)
//! explicit approximation y0 = x (1 − exp(−x^{5/4}))^{−2/5} (relative error below 1 %, exact in
//! both the deep-water limit y → x and the shallow-water limit y → √x). Newton then converges
//! quadratically; iteration stops when the update is below 2 ulp of y, which is machine precision
//! (the unit tests check the residual of ω² = g k tanh(kh) to a few ulp for kh from 1e-4 to 1e3).
//!
//! Also: the linear shoaling coefficient K_si = [tanh(kh) · 2n]^{−1/2},
//! n = ½ (1 + 2kh / sinh 2kh) (PHYSICS.md §3.3).

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
    // Guo (2002) start: exact in both limits (y → x deep, y → √x shallow).
    let mut y = x / (1.0 - (-x.powf(1.25)).exp()).powf(0.4);
    if !(y.is_finite() && y > 0.0) {
        y = if x < 1.0 { x.sqrt() } else { x };
    }
    for _ in 0..60 {
        let t = y.tanh();
        let f = y * t - x;
        let df = t + y * (1.0 - t * t);
        let dy = f / df;
        let mut y_new = y - dy;
        if y_new <= 0.0 {
            y_new = 0.5 * y;
        }
        let done = (y_new - y).abs() <= 2.0 * f64::EPSILON * y_new;
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

/// Linear shoaling coefficient K_si = [tanh(kh) · 2n]^{−1/2} (PHYSICS.md §3.3).
#[inline]
pub fn linear_shoaling_coefficient(period_s: f64, depth_m: f64) -> f64 {
    let kh = wavenumber(period_s, depth_m) * depth_m;
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
        // PHYSICS.md §11: T = 3.04 s, h = 1.14 m → L = 9.3214 m (given to 5 digits → 1e-5 relative).
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
