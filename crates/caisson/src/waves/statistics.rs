//! Rayleigh distribution of individual wave heights (docs/model.md §6.4 item 5).
//!
//! ```text
//! P(H > x) = exp[−2 (x / H1/3)²]          quantile:  x(p) = H1/3 √(−ln p / 2)
//! ```
//!
//! (Equivalently H_rms = H1/3/√2 and P(H > x) = exp[−(x/H_rms)²].) Samples come from a caller's
//! generator, so that a named seeded generator (`rand_chacha`) gives reproducible sequences.

use rand::Rng;
use std::f64::consts::{FRAC_1_SQRT_2, PI};

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

/// Coefficients of the Chebyshev fit of `erfcc` (Numerical Recipes, §6.2), lowest order first.
const ERFCC: [f64; 10] = [
    -1.265_512_23,
    1.000_023_68,
    0.374_091_96,
    0.096_784_18,
    -0.186_288_06,
    0.278_868_07,
    -1.135_203_98,
    1.488_515_87,
    -0.822_152_23,
    0.170_872_77,
];

/// erfc(x), Numerical Recipes `erfcc`: erfc(|x|) = t exp(−x² + Σ c_k t^k), t = 1/(1 + |x|/2)
/// (fractional error < 1.2e-7 for all x), and erfc(−x) = 2 − erfc(x).
pub fn erfc(x: f64) -> f64 {
    let z = x.abs();
    let t = 1.0 / (1.0 + 0.5 * z);
    let poly = ERFCC.iter().rev().fold(0.0, |acc, &c| acc * t + c);
    let r = t * (-z * z + poly).exp();
    if x >= 0.0 {
        r
    } else {
        2.0 - r
    }
}

/// The standard normal CDF Φ(z) = erfc(−z/√2)/2 (relative error < 1.2e-7, tails included).
pub fn normal_cdf(z: f64) -> f64 {
    0.5 * erfc(-z * FRAC_1_SQRT_2)
}

/// The standard normal density φ(z).
pub fn normal_pdf(z: f64) -> f64 {
    (-0.5 * z * z).exp() / (2.0 * PI).sqrt()
}

/// Coefficients of Acklam's rational approximation of Φ⁻¹ (central region, then tails).
const ACKLAM_A: [f64; 6] = [
    -3.969_683_028_665_376e1,
    2.209_460_984_245_205e2,
    -2.759_285_104_469_687e2,
    1.383_577_518_672_69e2,
    -3.066_479_806_614_716e1,
    2.506_628_277_459_239,
];
const ACKLAM_B: [f64; 5] = [
    -5.447_609_879_822_406e1,
    1.615_858_368_580_409e2,
    -1.556_989_798_598_866e2,
    6.680_131_188_771_972e1,
    -1.328_068_155_288_572e1,
];
const ACKLAM_C: [f64; 6] = [
    -7.784_894_002_430_293e-3,
    -3.223_964_580_411_365e-1,
    -2.400_758_277_161_838,
    -2.549_732_539_343_734,
    4.374_664_141_464_968,
    2.938_163_982_698_783,
];
const ACKLAM_D: [f64; 4] =
    [7.784_695_709_041_462e-3, 3.224_671_290_700_398e-1, 2.445_134_137_142_996, 3.754_408_661_907_416];

/// Φ⁻¹(p), the standard normal quantile, for p in (0, 1) (−∞ at 0, +∞ at 1, NaN outside):
/// P. J. Acklam's rational approximation (relative error below 1.15e-9; central region
/// |p − ½| ≤ ½ − 0.02425, tails in q = √(−2 ln p)).
pub fn normal_quantile(p: f64) -> f64 {
    const P_LOW: f64 = 0.02425;
    let poly = |c: &[f64], x: f64| c.iter().fold(0.0, |acc, &k| acc * x + k);
    let tail = |p: f64| {
        let q = (-2.0 * p.ln()).sqrt();
        poly(&ACKLAM_C, q) / (poly(&ACKLAM_D, q) * q + 1.0)
    };
    if !(0.0..=1.0).contains(&p) {
        f64::NAN
    } else if p == 0.0 {
        f64::NEG_INFINITY
    } else if p == 1.0 {
        f64::INFINITY
    } else if p < P_LOW {
        tail(p)
    } else if p <= 1.0 - P_LOW {
        let q = p - 0.5;
        let r = q * q;
        poly(&ACKLAM_A, r) * q / (poly(&ACKLAM_B, r) * r + 1.0)
    } else {
        -tail(1.0 - p)
    }
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
    fn normal_cdf_matches_tables() {
        // Abramowitz & Stegun Table 26.1 / standard values.
        let cases = [
            (0.0, 0.5),
            (1.0, 0.841_344_746),
            (-1.0, 0.158_655_254),
            (-2.0, 0.022_750_132),
            (1.96, 0.975_002_105),
            (3.0, 0.998_650_102),
            (-3.0, 0.001_349_898),
            (-5.0, 2.866_515_72e-7),
            (-8.0, 6.220_960_57e-16),
        ];
        for (z, want) in cases {
            let got = normal_cdf(z);
            assert!(((got - want) / want).abs() < 2e-7, "Φ({z}) = {got}, want {want}");
        }
        for z in [-6.0, -2.5, -0.3, 0.7, 4.0] {
            assert!((normal_cdf(z) + normal_cdf(-z) - 1.0).abs() < 1e-15);
        }
        assert!((erfc(0.0) - 1.0).abs() < 2e-7);
        assert!((erfc(0.5) - 0.479_500_122).abs() < 1e-7);
    }

    /// Φ⁻¹ against tabulated quantiles (Abramowitz & Stegun Table 26.5: 1.959964 at 0.975,
    /// 3.090232 at 0.999, 6.361341 at 1 − 1e-10) to 1e-8, symmetric, and Φ(Φ⁻¹(p)) = p within
    /// 3e-7 over 999 points of (0, 1) (the 1.2e-7 of Φ and the 1.15e-9 of Φ⁻¹ times |z| φ/Φ),
    /// 4e-7 in the far tails down to 1e-300 (measured 1.3e-7).
    #[test]
    fn normal_quantile_inverts_the_cdf() {
        for (p, z) in [(0.975, 1.959_963_985), (0.999, 3.090_232_306), (1e-10, -6.361_340_902), (0.5, 0.0)] {
            assert!((normal_quantile(p) - z).abs() < 1e-8, "Φ⁻¹({p}) = {}", normal_quantile(p));
        }
        let mut checked = 0;
        for i in 1..1000 {
            let p = i as f64 / 1000.0;
            assert!((normal_quantile(p) + normal_quantile(1.0 - p)).abs() < 1e-12);
            assert!((normal_cdf(normal_quantile(p)) / p - 1.0).abs() < 3e-7, "p = {p}");
            checked += 1;
        }
        for p in [1e-300, 1e-50, 1e-12] {
            assert!((normal_cdf(normal_quantile(p)) / p - 1.0).abs() < 4e-7, "p = {p}");
        }
        assert_eq!(checked, 999);
        assert_eq!((normal_quantile(0.0), normal_quantile(1.0)), (f64::NEG_INFINITY, f64::INFINITY));
        assert!(normal_quantile(1.5).is_nan());
    }

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
