//! Rayleigh distribution of individual wave heights (docs/model.md §6.4 item 5).
//!
//! ```text
//! P(H > x) = exp[−2 (x / H1/3)²]          quantile:  x(p) = H1/3 √(−ln p / 2)
//! ```
//!
//! (Equivalently H_rms = H1/3/√2 and P(H > x) = exp[−(x/H_rms)²].) Samples come from a caller's
//! generator, so that a named seeded generator (`rand_chacha`) gives reproducible sequences.

use rand::Rng;

/// Exceedance probability P(H > x) for significant height `h13_m`.
#[inline]
pub fn rayleigh_exceedance(x_m: f64, h13_m: f64) -> f64 {
    if x_m <= 0.0 {
        return 1.0;
    }
    let r = x_m / h13_m;
    (-2.0 * r * r).exp()
}

/// Height exceeded with probability `p` (0 < p ≤ 1). `NaN` outside that range.
#[inline]
pub fn rayleigh_quantile_m(p: f64, h13_m: f64) -> f64 {
    if !(p > 0.0 && p <= 1.0) {
        return f64::NAN;
    }
    h13_m * (-0.5 * p.ln()).sqrt()
}

/// One Rayleigh wave height (inverse transform of a uniform draw in (0, 1]).
#[inline]
pub fn sample_rayleigh_m<R: Rng + ?Sized>(h13_m: f64, rng: &mut R) -> f64 {
    let u: f64 = rng.gen();
    rayleigh_quantile_m(1.0 - u, h13_m)
}

/// The waves of a sample of `n` independent Rayleigh heights one by one from the **largest**
/// down, by their exceedance probabilities (descending order statistics; Devroye 1986,
/// *Non-Uniform Random Variate Generation*, §V.3): the exceedance probabilities E = P(H > h_i)
/// of the sample are n independent uniforms on (0, 1); their smallest, and given the k-th
/// smallest E_(k) the smallest of the n − k others, are
///
/// ```text
/// 1 − E_(1) = V_1^(1/n),   1 − E_(k+1) = (1 − E_(k)) · V_(k+1)^(1/(n − k)),   V_k uniform on (0, 1],
/// ```
///
/// accumulated as ln(1 − E_(k)) = Σ ln V_j / (n − j + 1), E_(k) = −expm1 of it (precise for the
/// tiny E of the largest waves). The heights are H_(k) = [`rayleigh_quantile_m`]`(E_(k))`. A caller
/// that needs only the waves above a height h_t stops at the first E_(k) ≥ P(H > h_t): it has
/// drawn K ~ Binomial(n, P(H > h_t)) waves, distributed as n Rayleigh heights truncated below at h_t,
/// with one uniform each (and one more for the first wave below h_t). One uniform per call.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DescendingRayleigh {
    /// Waves not yet drawn.
    left: u64,
    /// ln(1 − E) of the last wave drawn (0 before the first).
    log_survival: f64,
}

impl DescendingRayleigh {
    /// A sample of `n` waves, none drawn yet.
    pub fn new(n: u64) -> Self {
        DescendingRayleigh { left: n, log_survival: 0.0 }
    }

    /// Waves not yet drawn.
    pub fn left(&self) -> u64 {
        self.left
    }

    /// The exceedance probability E of the next largest wave (E in [0, 1], non-decreasing from
    /// call to call; 0 only when the uniform is 1), or `None` once all n were drawn.
    #[inline]
    pub fn next_exceedance<R: Rng + ?Sized>(&mut self, rng: &mut R) -> Option<f64> {
        if self.left == 0 {
            return None;
        }
        let v = 1.0 - rng.gen::<f64>();
        self.log_survival += v.ln() / self.left as f64;
        self.left -= 1;
        Some(-self.log_survival.exp_m1())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::SeedableRng;
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn quantile_inverts_exceedance() {
        for &p in &[1e-6, 0.01, 0.135, 0.5, 0.99, 1.0] {
            let x = rayleigh_quantile_m(p, 2.0);
            assert!((rayleigh_exceedance(x, 2.0) - p).abs() <= 1e-12 * p, "p = {p}");
        }
        assert!(rayleigh_quantile_m(0.0, 1.0).is_nan());
    }

    #[test]
    fn samples_have_significant_height_h13() {
        // The mean of the highest third of these heights is H_rms [√ln3 + 3 (√π/2) erfc(√ln3)]
        // = 1.416 H_rms = 1.0013 H1/3 (the 0.13 % is the usual rounding of 1.416 to √2).
        // 3e5 draws: standard error of the top-third mean ≈ 0.3 H/√1e5 ≈ 1e-3 H → tolerance 0.5 %.
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        let mut h: Vec<f64> = (0..300_000).map(|_| sample_rayleigh_m(1.5, &mut rng)).collect();
        h.sort_by(|a, b| b.total_cmp(a));
        let top = &h[..h.len() / 3];
        let h13 = top.iter().sum::<f64>() / top.len() as f64;
        assert!((h13 - 1.5).abs() / 1.5 < 0.005, "H1/3 from samples = {h13}");
        // Same seed → same sequence.
        let mut a = ChaCha8Rng::seed_from_u64(3);
        let mut b = ChaCha8Rng::seed_from_u64(3);
        for _ in 0..100 {
            assert_eq!(sample_rayleigh_m(1.0, &mut a), sample_rayleigh_m(1.0, &mut b));
        }
    }

    /// The heights a [`DescendingRayleigh`] gives above a threshold h_t, against closed forms,
    /// M = 20 000 samples each of n = 200 waves of H1/3 = 1 m above h_t = 1.2 m (q = e^−2.88 =
    /// 0.0561) and of n = 4 waves above h_t = 0.589 m (q = 0.5): K ~ Binomial(n, q), mean n q
    /// (standard error of the sample mean √(n q (1 − q)/M): 0.023 and 0.007) and variance
    /// n q (1 − q) (standard error ≈ var·√(2/M)); above h_t, H² − h_t² is exponential with mean
    /// H1/3²/2 = 0.5 m² (standard error 0.5/√ΣK); the largest exceeds x with probability
    /// 1 − (1 − e^(−2x²))^n (x = 2 and 1 m: 0.0648 and 0.4409). Each within four standard errors
    /// (a fixed seed: the test cannot be flaky). The small sample catches an exponent off by one
    /// (1/(n − k + 1): the order statistics of n + 1 waves, E K 60 standard errors off), the large
    /// one a missing truncation. The heights come largest first.
    #[test]
    fn descending_heights_above_a_threshold_are_the_truncated_rayleigh() {
        let (h13, samples) = (1.0, 20_000usize);
        let m = samples as f64;
        let mut rng = ChaCha8Rng::seed_from_u64(11);
        for (n, ht, x) in [(200u64, 1.2, 2.0), (4, (0.5f64.ln() / -2.0).sqrt(), 1.0)] {
            let q = rayleigh_exceedance(ht, h13);
            let (mut sum_k, mut sum_k2, mut sum_excess, mut above_x) = (0.0, 0.0, 0.0, 0usize);
            for _ in 0..samples {
                let mut sample = DescendingRayleigh::new(n);
                let mut k = 0u64;
                let mut previous = 0.0;
                while let Some(e) = sample.next_exceedance(&mut rng) {
                    assert!(e >= previous, "exceedance probabilities ascend: {e} after {previous}");
                    previous = e;
                    if e >= q {
                        break;
                    }
                    let h = rayleigh_quantile_m(e, h13);
                    if k == 0 && h > x {
                        above_x += 1;
                    }
                    sum_excess += h * h - ht * ht;
                    k += 1;
                }
                assert_eq!(sample.left(), n - k - u64::from(k < n), "one wave drawn beyond the K above h_t");
                sum_k += k as f64;
                sum_k2 += (k * k) as f64;
            }
            let (mean, var) = (sum_k / m, sum_k2 / m - (sum_k / m).powi(2));
            let (mean_exact, var_exact) = (n as f64 * q, n as f64 * q * (1.0 - q));
            assert!((mean - mean_exact).abs() < 4.0 * (var_exact / m).sqrt(), "n = {n}: E K = {mean} vs {mean_exact}");
            assert!(
                (var - var_exact).abs() < 4.0 * var_exact * (2.0 / m).sqrt(),
                "n = {n}: Var K = {var} vs {var_exact}"
            );
            let excess = sum_excess / sum_k;
            assert!((excess - 0.5).abs() < 4.0 * 0.5 / sum_k.sqrt(), "n = {n}: E[H² − h_t²] = {excess} vs 0.5");
            let p_max = 1.0 - (1.0 - (-2.0 * x * x).exp()).powi(n as i32);
            let got = above_x as f64 / m;
            assert!(
                (got - p_max).abs() < 4.0 * (p_max * (1.0 - p_max) / m).sqrt(),
                "n = {n}: P(max > {x}) = {got} vs {p_max}"
            );
        }
    }

    /// Without a threshold a [`DescendingRayleigh`] gives all n waves, and they are the sample
    /// of n Rayleigh heights: the mean of H² is H1/3²/2 (H² exponential; 200 waves × 2000 samples,
    /// standard error 0.5/√4e5 = 8e-4 m²), and then it stops.
    #[test]
    fn descending_heights_without_a_threshold_are_the_whole_sample() {
        let mut rng = ChaCha8Rng::seed_from_u64(5);
        let (n, samples) = (200u64, 2000);
        let mut sum_h2 = 0.0;
        for _ in 0..samples {
            let mut sample = DescendingRayleigh::new(n);
            let mut count = 0;
            while let Some(e) = sample.next_exceedance(&mut rng) {
                let h = rayleigh_quantile_m(e, 1.0);
                assert!(h.is_finite(), "E = {e}");
                sum_h2 += h * h;
                count += 1;
            }
            assert_eq!(count, n);
            assert_eq!(sample.next_exceedance(&mut rng), None);
        }
        let mean = sum_h2 / (n as f64 * samples as f64);
        assert!((mean - 0.5).abs() < 4.0 * 0.5 / ((n * samples) as f64).sqrt(), "E H² = {mean} vs 0.5");
    }
}
