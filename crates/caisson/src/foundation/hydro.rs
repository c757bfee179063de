//! Hydrodynamic (added) mass of the water in front of the wall (seed Eqs. 18-19; docs/model.md §8.3).
//!
//! Westergaard's problem solved exactly by the cosine series (rigid wall, water depth d on one
//! side, free surface φ = 0): per metre of wall,
//!
//! ```text
//! m_hyd,x  = 0.54275 ρ_w d²     translation (seed Eq. 18, Pedersen 1997: 0.543)
//! s_hyd    = 0.21787 ρ_w d³     static moment about the base (the seed's Eq. 19 "0.218",
//!                               read as a coupling, docs/model.md §10 item 8)
//! I_hyd    = 0.1031  ρ_w d⁴     rotational inertia about the base (docs/model.md §10 item 9)
//! ```
//!
//! multiplied by the alongshore length. One face only, as in the seed. d defaults to the base
//! depth h' (the wetted height of the seaward face).

/// Added-mass matrix terms (totals).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct AddedMass {
    /// kg, on u_x.
    pub translation_kg: f64,
    /// kg·m, u_x-θ coupling about the base.
    pub coupling_kg_m: f64,
    /// kg·m², on θ about the base.
    pub rotation_kg_m2: f64,
}

/// Exact series coefficients (translation, coupling, rotation) for d = 1, ρ = 1, l = 1.
/// Translation is 14ζ(3)/π³. The series (`series`) summed once and kept as constants, to the
/// bit as summed here (x86-64, glibc's sin and cos; `coefficients_are_the_series_summed`): its
/// 20 000 terms' sines and cosines cost 3.4 M instructions (callgrind), a quarter of loading the
/// 15-wave test's scenario, for every foundation built.
pub fn coefficients() -> (f64, f64, f64) {
    (0.5427545143602056, 0.21787492335089592, 0.10307829110287506)
}

/// The series of [`coefficients`], summed.
#[cfg(test)]
fn series() -> (f64, f64, f64) {
    // φ(x, ζ) = Σ A_n cos(λ_n ζ) e^(−λ_n x), ζ the height above the base (seabed side ∂φ/∂ζ = 0,
    // free surface φ = 0 at ζ = d), λ_n = (2n−1)π/(2d). For wall velocity profiles a(ζ), b(ζ)
    // the added-mass coefficient is Σ_n (2/(d λ_n)) A_n B_n, A_n = ∫₀ᵈ a cos(λ_n ζ) dζ.
    // With d = 1: translation a = 1; rotation about the base a = ζ.
    let (mut t, mut c, mut r) = (0.0, 0.0, 0.0);
    for n in 1..=20000 {
        let lam = (2 * n - 1) as f64 * std::f64::consts::FRAC_PI_2;
        let s = lam.sin();
        let a_trans = s / lam; // ∫₀¹ cos(λζ) dζ
        let a_rot = s / lam - (1.0 - lam.cos()) / (lam * lam); // ∫₀¹ ζ cos(λζ) dζ
        let w = 2.0 / lam;
        t += w * a_trans * a_trans;
        c += w * a_trans * a_rot;
        r += w * a_rot * a_rot;
    }
    (t, c, r)
}

impl AddedMass {
    /// Added mass for water of density `rho_w` and depth `d_m` in front of a wall of length `l_m`.
    pub fn new(rho_w: f64, d_m: f64, l_m: f64) -> Self {
        let (t, c, r) = coefficients();
        AddedMass {
            translation_kg: t * rho_w * d_m.powi(2) * l_m,
            coupling_kg_m: c * rho_w * d_m.powi(3) * l_m,
            rotation_kg_m2: r * rho_w * d_m.powi(4) * l_m,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// docs/model.md §8.3: 0.54275, 0.21787, 0.1031 (to the digits printed there; the series is
    /// summed to 20000 terms, truncation < 1e-9).
    /// The kept coefficients are the series summed, to the bit here (x86-64, glibc), within
    /// 1e-14 of each wherever another libm rounds a sine or a cosine otherwise (20 000 terms, each
    /// rounded to 1e-16 relative: far below the series' truncation, < 1e-9).
    #[test]
    fn coefficients_are_the_series_summed() {
        let (kept, summed) = (coefficients(), series());
        for (k, s) in [(kept.0, summed.0), (kept.1, summed.1), (kept.2, summed.2)] {
            assert!((k - s).abs() <= 1e-14 * s.abs(), "kept {k}, summed {s}");
            if cfg!(all(target_arch = "x86_64", target_os = "linux", target_env = "gnu")) {
                assert_eq!(k.to_bits(), s.to_bits(), "kept {k}, summed {s}");
            }
        }
    }

    #[test]
    fn series_coefficients_match_physics_md() {
        let (t, c, r) = coefficients();
        assert!((t - 0.54275).abs() < 1e-5, "{t}");
        assert!((c - 0.21787).abs() < 1e-5, "{c}");
        assert!((r - 0.1031).abs() < 1e-4, "{r}");
    }
}
