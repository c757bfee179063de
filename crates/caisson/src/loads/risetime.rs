//! Impact rise time: the seed's log-normal model (Eqs. 34-36), read as in docs/model.md §5.3 and
//! §10 item 20.
//!
//! ```text
//! F* = F_x,max / F_qs+,     t* = t_r / T_m
//! μ(F*) = a_μ F*^{b_μ},  σ(F*) = a_σ F*^{b_σ},   a_μ = 0.34, b_μ = −3.42, a_σ = 0.87, b_σ = −0.26
//! ```
//!
//! * [`RiseTimeModel::Median`] (default): μ is the **median of t*** itself,
//!   ln t* ~ N(ln μ, σ²), so t_r = T μ exp(σ Z) with Z ~ N(0, 1). F* = 3.45 gives a median
//!   t_r = 0.015 s at T = 3.04 s; F* = 1 gives 0.34 T.
//! * [`RiseTimeModel::Literal`]: Eq. 34 as printed, ln t* ~ N(μ, σ²); its median exp(μ) is between
//!   1 and 1.4 for every F* ≥ 1 (t_r ≥ T), which docs/model.md §5.3 calls absurd. Kept as an option.
//!
//! Every draw is clamped to t_r ≤ T/4, so that the impact (duration 2 t_r) fits in the first
//! half-period. A wave with F* ≤ 1 is **non-impulsive** ([`RiseTimeParams::distribution`] returns
//! `None`): the history then uses the pulsating sine only.
//!
//! Randomness: draws take the caller's generator. The crate's named generator is
//! [`LoadRng`] = `rand_chacha::ChaCha8Rng`, seeded with [`load_rng`], so that a scenario and a seed
//! always give the same rise times on every platform.

use rand::{Rng, SeedableRng};
use rand_distr::StandardNormal;

/// The named, seeded generator behind every random draw of the load generation.
pub type LoadRng = rand_chacha::ChaCha8Rng;

/// The generator for `seed`.
pub fn load_rng(seed: u64) -> LoadRng {
    LoadRng::seed_from_u64(seed)
}

/// How Eq. 34's μ is read.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum RiseTimeModel {
    /// μ is the median of t* (docs/model.md §5.3 recommendation; default).
    Median,
    /// μ is the mean of ln t* (Eq. 34 as printed).
    Literal,
}

/// Parameters of Eqs. 35-36.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct RiseTimeParams {
    pub model: RiseTimeModel,
    pub a_mu: f64,
    pub b_mu: f64,
    pub a_sigma: f64,
    pub b_sigma: f64,
}

impl Default for RiseTimeParams {
    fn default() -> Self {
        RiseTimeParams { model: RiseTimeModel::Median, a_mu: 0.34, b_mu: -3.42, a_sigma: 0.87, b_sigma: -0.26 }
    }
}

/// The log-normal distribution of t_r for one wave.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct RiseTimeDistribution {
    /// Median of t_r before the clamp, s.
    pub median_s: f64,
    /// σ, standard deviation of ln t_r.
    pub log_std: f64,
    /// Upper clamp T/4, s.
    pub max_s: f64,
}

impl RiseTimeDistribution {
    /// t_r for a standard normal deviate `z`, clamped to T/4.
    #[inline]
    pub fn at_deviate(&self, z: f64) -> f64 {
        (self.median_s * (self.log_std * z).exp()).min(self.max_s)
    }
    /// The median rise time, clamped to T/4.
    #[inline]
    pub fn median_clamped_s(&self) -> f64 {
        self.median_s.min(self.max_s)
    }
    /// One random t_r (one standard normal draw from `rng`), clamped to T/4.
    #[inline]
    pub fn sample<R: Rng + ?Sized>(&self, rng: &mut R) -> f64 {
        let z: f64 = rng.sample(StandardNormal);
        self.at_deviate(z)
    }
}

impl RiseTimeParams {
    /// The distribution of t_r for dimensionless impact force `f_star` and period `period_s`;
    /// `None` for a non-impulsive wave (F* ≤ 1, or F* not finite).
    pub fn distribution(&self, f_star: f64, period_s: f64) -> Option<RiseTimeDistribution> {
        if !(f_star > 1.0 && f_star.is_finite()) {
            return None;
        }
        let mu = self.a_mu * f_star.powf(self.b_mu);
        let sigma = self.a_sigma * f_star.powf(self.b_sigma);
        let median_star = match self.model {
            RiseTimeModel::Median => mu,
            RiseTimeModel::Literal => mu.exp(),
        };
        Some(RiseTimeDistribution { median_s: median_star * period_s, log_std: sigma, max_s: 0.25 * period_s })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn physics_md_5_3_examples() {
        // F* = 3.45 → 0.015 s, F* = 1.66 → 0.18 s at T = 3.04 s (given to 2 digits → 3 %).
        let p = RiseTimeParams::default();
        let a = p.distribution(3.45, 3.04).unwrap().median_s;
        let b = p.distribution(1.66, 3.04).unwrap().median_s;
        assert!((a - 0.015).abs() / 0.015 < 0.03, "{a}");
        assert!((b - 0.18).abs() / 0.18 < 0.03, "{b}");
        assert!(p.distribution(1.0, 3.04).is_none() && p.distribution(0.5, 3.04).is_none());
        // Literal reading: median t* = exp(0.34·F*^−3.42) ≥ 1 → clamped to T/4.
        let lit = RiseTimeParams { model: RiseTimeModel::Literal, ..p }.distribution(1.66, 3.04).unwrap();
        assert!(lit.median_s > 3.04 && lit.median_clamped_s() == 0.76);
    }
}
