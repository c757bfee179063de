//! Wave-by-wave periods: the period of each wave of a storm drawn given its height from the joint
//! distribution of wave heights and periods of Longuet-Higgins (1983) (docs/design.md,
//! "Climate", `[design] wave_periods`).
//!
//! **The joint density** (Longuet-Higgins 1983, "On the joint distribution of wave periods and
//! amplitudes in a random wave field", Proc. R. Soc. Lond. A 389, 241-258):
//!
//! ```text
//! p(R, T) = (2 / (√π ν)) L(ν) (R² / T²) exp{−R² [1 + (1 − 1/T)² / ν²]},   R, T > 0,
//! L(ν) = 2 / [1 + (1 + ν²)^(−½)],   ν² = m0 m2 / m1² − 1,
//! ```
//!
//! with R = a / (2 m0)^½ = H / H_rms the normalised amplitude, T = τ / τ̄ the period normalised by
//! the mean period τ̄ = 2π m0/m1 (T_m01), m_n the moments of the spectrum and ν its spectral
//! width (the same density as WAFO's `lh83pdf`). With u = 1 − 1/T (du = dT/T²) the density in
//! (R, u) is L (2/(√π ν)) R² e^(−R²) exp(−R² u²/ν²): **given the height, u is normal with mean 0
//! and standard deviation s = ν / (√2 R)**, truncated to u < 1 (T > 0). caisson keeps the storm's
//! heights Rayleigh (`super::statistics`; the marginal of this density, L R e^(−R²) [1 +
//! erf(R/ν)], is the Rayleigh 2R e^(−R²) times L(ν) [1 + erf(R/ν)]/2, within 4 % of 1 above
//! R = 1 at ν ≤ 0.4) and draws each wave's period
//! from this conditional, with R = H/H_rms = √2 H/H1/3, so s = ν H1/3 / (2 H): the highest
//! waves have periods close to τ̄, the low ones scatter widely.
//!
//! **Truncated to 0.5 τ̄ ≤ τ ≤ 2.5 τ̄** ([`PERIOD_RANGE`]; u in [−1, 0.6]): the untruncated
//! conditional falls off as T⁻² for long periods, so its mean period is infinite (a known defect
//! of the narrow-band density for the low waves), and a screen over the periods of a storm needs
//! them bounded. For the waves that can slide a caisson the truncation is immaterial: at R = 2
//! (H = 1.4 H1/3) and ν = 0.39, s = 0.14 and the bounds are 4.3 s (long) and 7 s (short) away.
//! One uniform V per wave, by the inverse CDF: u = s Φ⁻¹(Φ(−1/s) + V [Φ(0.6/s) − Φ(−1/s)]).
//!
//! **Scaled to the storm**: τ̄ = T_m01 = 0.89 T1/3 ([`MEAN_PERIOD_RATIO`]). The ratio is that of
//! the JONSWAP spectrum with γ = 3.3: T_m01 = 0.834 T_p from its moments (computed in the tests),
//! and T1/3 = [1 − 0.132 (γ + 0.2)^(−0.559)] T_p = 0.934 T_p (Goda 1988, as given in Goda 2010,
//! *Random Seas and Design of Maritime Structures*, 3rd ed., ch. 2); the Pierson-Moskowitz
//! spectrum (γ = 1) gives 0.88. The default spectral width ν = 0.39 ([`DEFAULT_SPECTRAL_WIDTH`])
//! is the same spectrum's (PM: 0.42); `[design] period_spectral_width` takes 0.05-0.6
//! ([`SPECTRAL_WIDTH_RANGE`]: the density is derived for narrow spectra, ν² ≪ 1; Goda 1978 found
//! it to describe the observed joint distribution of the high waves, with ν fitted to the observed
//! periods, and not that of the low ones).

use super::statistics::{normal_cdf, normal_quantile};

/// How the periods of a storm's waves are drawn (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum WavePeriods {
    /// Every wave at the storm's T1/3 (the default; no number drawn).
    #[default]
    Significant,
    /// Each wave's period from the conditional of Longuet-Higgins (1983) given its height, with
    /// spectral width ν = `spectral_width`.
    LonguetHiggins { spectral_width: f64 },
}

/// τ̄ / T1/3: the mean period T_m01 of a storm as a fraction of its T1/3 (module docs).
pub const MEAN_PERIOD_RATIO: f64 = 0.89;
/// The periods drawn, as multiples of τ̄ (module docs).
pub const PERIOD_RANGE: [f64; 2] = [0.5, 2.5];
/// u = 1 − τ̄/τ at the ends of [`PERIOD_RANGE`].
const U_RANGE: [f64; 2] = [1.0 - 1.0 / PERIOD_RANGE[0], 1.0 - 1.0 / PERIOD_RANGE[1]];
/// The default spectral width ν (JONSWAP, γ = 3.3).
pub const DEFAULT_SPECTRAL_WIDTH: f64 = 0.39;
/// The spectral widths `[design] period_spectral_width` accepts.
pub const SPECTRAL_WIDTH_RANGE: [f64; 2] = [0.05, 0.6];

impl WavePeriods {
    /// Longuet-Higgins' periods of spectral width ν = `spectral_width`, in
    /// [`SPECTRAL_WIDTH_RANGE`] (refused naming `spectral_width` otherwise: the spectral width of
    /// a wind sea, 0.39 for JONSWAP with γ = 3.3; the density is derived for narrow spectra).
    pub fn longuet_higgins(spectral_width: f64) -> Result<Self, crate::ParamError> {
        let [lo, hi] = SPECTRAL_WIDTH_RANGE;
        crate::check::between("spectral_width", spectral_width, lo, hi)?;
        Ok(WavePeriods::LonguetHiggins { spectral_width })
    }

    /// Whether every wave has the storm's T1/3 (the default).
    pub fn is_significant(&self) -> bool {
        *self == WavePeriods::Significant
    }

    /// The smallest and largest period of a wave of a storm of T1/3 `t13_s`, s.
    pub fn range_s(&self, t13_s: f64) -> [f64; 2] {
        match self {
            WavePeriods::Significant => [t13_s, t13_s],
            WavePeriods::LonguetHiggins { .. } => PERIOD_RANGE.map(|t| t * MEAN_PERIOD_RATIO * t13_s),
        }
    }

    /// The period of a wave of height `height_m` in a storm of H1/3 `h13_m` and T1/3 `t13_s`, s,
    /// from the uniform `v` in [0, 1) (module docs); `t13_s` itself (whatever `v`) for
    /// [`WavePeriods::Significant`].
    pub fn period_s(&self, height_m: f64, h13_m: f64, t13_s: f64, v: f64) -> f64 {
        match *self {
            WavePeriods::Significant => t13_s,
            WavePeriods::LonguetHiggins { spectral_width } => {
                MEAN_PERIOD_RATIO * t13_s / (1.0 - conditional_u(spectral_width, height_m / h13_m, v))
            }
        }
    }
}

/// s = ν / (2 x): the standard deviation of u = 1 − τ̄/τ given H = x H1/3 before the truncation
/// (R = √2 x; module docs).
pub fn conditional_sd(spectral_width: f64, x: f64) -> f64 {
    spectral_width / (2.0 * x.max(1e-9))
}

/// The bounds of u = 1 − τ̄/τ of the drawn periods.
pub fn u_range() -> [f64; 2] {
    U_RANGE
}

/// u = 1 − τ̄/τ of a wave of height x H1/3 from the uniform `v` in [0, 1): N(0, s²) truncated to
/// [`u_range`], by the inverse CDF (module docs).
pub fn conditional_u(spectral_width: f64, x: f64, v: f64) -> f64 {
    let s = conditional_sd(spectral_width, x);
    let [lo, hi] = U_RANGE;
    let (a, b) = (normal_cdf(lo / s), normal_cdf(hi / s));
    (s * normal_quantile(a + v * (b - a))).clamp(lo, hi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::waves::statistics::normal_pdf;

    /// The spectral moments m0, m1, m2 of the JONSWAP spectrum of peak enhancement γ, with
    /// ω_p = 1: S(ω) = ω⁻⁵ exp(−1.25 ω⁻⁴) γ^exp(−(ω − 1)²/(2σ²)), σ = 0.07 (ω ≤ 1) or 0.09
    /// (Hasselmann et al. 1973; the scale α g² drops out of the ratios), by the trapezoidal rule
    /// on [0.05, 60] with 600 000 intervals (the tail beyond 60 adds ~1/(2·60²) to m2).
    fn jonswap_moments(gamma: f64) -> [f64; 3] {
        let (a, b, n) = (0.05, 60.0, 600_000);
        let h = (b - a) / n as f64;
        let mut m = [0.0; 3];
        for i in 0..=n {
            let w: f64 = a + i as f64 * h;
            let sigma: f64 = if w <= 1.0 { 0.07 } else { 0.09 };
            let s = w.powi(-5)
                * (-1.25 * w.powi(-4)).exp()
                * gamma.powf((-(w - 1.0).powi(2) / (2.0 * sigma * sigma)).exp());
            let weight = if i == 0 || i == n { 0.5 } else { 1.0 };
            for (k, mk) in m.iter_mut().enumerate() {
                *mk += weight * h * s * w.powi(k as i32);
            }
        }
        m
    }

    /// The constants from the spectra they are quoted for: JONSWAP γ = 3.3 gives ν = 0.389 and
    /// T_m01/T1/3 = (m0/m1 ω_p) / [1 − 0.132 (γ + 0.2)^(−0.559)] = 0.834/0.934 = 0.893; the
    /// Pierson-Moskowitz spectrum (γ = 1) ν = 0.424 and 0.772/0.881 = 0.876. The rounded
    /// constants within 0.005 of the JONSWAP values.
    #[test]
    fn the_constants_are_the_jonswap_spectrum_s() {
        let ratios = |gamma: f64| {
            let [m0, m1, m2] = jonswap_moments(gamma);
            let nu = (m0 * m2 / (m1 * m1) - 1.0).sqrt();
            let t13_over_tp = 1.0 - 0.132 * (gamma + 0.2).powf(-0.559);
            (nu, (m0 / m1) / t13_over_tp)
        };
        let (nu, r) = ratios(3.3);
        assert!((nu - 0.389).abs() < 1e-3 && (r - 0.893).abs() < 1e-3, "JONSWAP: ν {nu}, T_m01/T1/3 {r}");
        assert!((DEFAULT_SPECTRAL_WIDTH - nu).abs() < 5e-3 && (MEAN_PERIOD_RATIO - r).abs() < 5e-3);
        let (nu, r) = ratios(1.0);
        assert!((nu - 0.424).abs() < 1e-3 && (r - 0.876).abs() < 1e-3, "PM: ν {nu}, T_m01/T1/3 {r}");
    }

    /// 200 000 periods given the height, for heights 0.5 H1/3 (s = 0.39 at ν = 0.39: both
    /// bounds bite, at −2.6 s and 1.5 s) and 1.5 H1/3 (s = 0.13): the sample mean and variance of
    /// τ̄/τ = 1 − u against those of the truncated normal, E[u] = s (φ(α) − φ(β))/Z and Var u =
    /// s² [1 + (α φ(α) − β φ(β))/Z − ((φ(α) − φ(β))/Z)²], α = −1/s, β = 0.6/s, Z = Φ(β) −
    /// Φ(α), within 5 standard errors (σ/√n for the mean, σ² √(3/n) for the variance, which
    /// allows an excess kurtosis up to 1: a truncated normal's lies between −1.2 and the half
    /// normal's 0.87); every period in [0.5, 2.5] τ̄.
    #[test]
    fn conditional_periods_have_the_truncated_normal_moments() {
        let n = 200_000;
        let nu = DEFAULT_SPECTRAL_WIDTH;
        let p = WavePeriods::LonguetHiggins { spectral_width: nu };
        let mut rng = crate::loads::generator::realization_rng(5, 3);
        let mut checked = 0;
        for x in [0.5, 1.5] {
            let s = conditional_sd(nu, x);
            let (alpha, beta) = (-1.0 / s, 0.6 / s);
            let z = normal_cdf(beta) - normal_cdf(alpha);
            let d = (normal_pdf(alpha) - normal_pdf(beta)) / z;
            let (mean_u, var_u) =
                (s * d, s * s * (1.0 + (alpha * normal_pdf(alpha) - beta * normal_pdf(beta)) / z - d * d));
            let f: Vec<f64> = (0..n)
                .map(|_| {
                    use rand::Rng;
                    let t = p.period_s(x * 4.0, 4.0, 10.0, rng.gen());
                    assert!((0.5 - 1e-12..=2.5 + 1e-12).contains(&(t / (MEAN_PERIOD_RATIO * 10.0))), "τ = {t} s");
                    MEAN_PERIOD_RATIO * 10.0 / t
                })
                .collect();
            let mean = f.iter().sum::<f64>() / n as f64;
            let var = f.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1) as f64;
            let sd = var_u.sqrt();
            assert!(
                (mean - (1.0 - mean_u)).abs() < 5.0 * sd / (n as f64).sqrt(),
                "x = {x}: mean {mean} vs {}",
                1.0 - mean_u
            );
            assert!((var - var_u).abs() < 5.0 * var_u * (3.0 / n as f64).sqrt(), "x = {x}: var {var} vs {var_u}");
            checked += 1;
        }
        assert_eq!(checked, 2);
    }

    /// The constructor keeps ν within 0.05-0.6 (and refuses NaN), naming it.
    #[test]
    fn the_spectral_width_is_checked() {
        assert_eq!(WavePeriods::longuet_higgins(0.39), Ok(WavePeriods::LonguetHiggins { spectral_width: 0.39 }));
        let mut refused = 0;
        for nu in [0.0, 0.049, 0.61, f64::NAN] {
            assert_eq!(WavePeriods::longuet_higgins(nu).unwrap_err().quantity, "spectral_width");
            refused += 1;
        }
        assert_eq!(refused, 4);
    }

    /// The default draws nothing from `v` and returns T1/3; the range of a storm of T1/3 = 10 s
    /// is 4.45-22.25 s with Longuet-Higgins' periods.
    #[test]
    fn significant_periods_and_the_range() {
        assert_eq!(WavePeriods::Significant.period_s(3.0, 4.0, 10.0, 0.3), 10.0);
        assert_eq!(WavePeriods::Significant.range_s(10.0), [10.0, 10.0]);
        let [lo, hi] = WavePeriods::LonguetHiggins { spectral_width: 0.4 }.range_s(10.0);
        assert!((lo - 4.45).abs() < 1e-12 && (hi - 22.25).abs() < 1e-12);
    }
}
