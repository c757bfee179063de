//! Monte Carlo estimates with their precision: a mean with its standard error and 95 % interval,
//! a proportion with its Wilson interval, a percentile with its order-statistic interval — the
//! estimators for the intervals of the lifetime and sizing statistics (the reports give standard
//! errors of E|S| and of the heel exceedance today; fragility's θ and β carry profile-likelihood
//! intervals, [`super::fragility`]).
//!
//! * **Mean** of n values x_i: x̄, the standard error s/√n with s the sample standard deviation
//!   (n − 1 in the denominator), and the normal interval x̄ ± z s/√n, z = Φ⁻¹(0.975) = 1.959964
//!   (the central limit theorem; the lives of a design run are independent and identically
//!   distributed).
//! * **Proportion** k/n: the standard error √(p̂(1 − p̂)/n) and the Wilson (1927) score interval
//!
//!   ```text
//!   (p̂ + z²/2n ± z √(p̂(1 − p̂)/n + z²/4n²)) / (1 + z²/n),
//!   ```
//!
//!   which stays inside [0, 1] and is not empty at k = 0 or k = n (Brown, Cai & DasGupta 2001
//!   recommend it over the normal interval for the small probabilities of failure).
//! * **Percentile** ξ_q of n values: the order statistics x_(l) ≤ ξ_q ≤ x_(u) (1-based ranks), l
//!   the largest rank with F(l − 1) ≤ 0.025 and u the smallest with F(u − 1) ≥ 0.975, F the
//!   binomial distribution function of n trials at q: the interval holds ξ_q with probability
//!   F(u − 1) − F(l − 1) ≥ 0.95 whatever the distribution of the values (David & Nagaraja 2003,
//!   §7.1). Where no rank has F(l − 1) ≤ 0.025 (too few values for the tail) the end is open
//!   (`None`).

/// z = Φ⁻¹(0.975), the half-width of a 95 % normal interval in standard errors.
pub const Z95: f64 = 1.959_963_984_540_054;

/// An estimate, its standard error and its 95 % interval (module docs).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Estimate {
    pub value: f64,
    pub standard_error: f64,
    /// [low, high].
    pub ci95: [f64; 2],
}

impl Estimate {
    /// The mean of `values` with its standard error and normal 95 % interval; the standard error
    /// of fewer than two values is 0 (nothing to estimate it from) and of no value NaN.
    pub fn mean(values: impl IntoIterator<Item = f64>) -> Estimate {
        // Welford's running mean and sum of squares (no cancellation on values far from 0).
        let (mut n, mut mean, mut m2) = (0_u64, 0.0_f64, 0.0_f64);
        for x in values {
            n += 1;
            let d = x - mean;
            mean += d / n as f64;
            m2 += d * (x - mean);
        }
        if n == 0 {
            return Estimate { value: f64::NAN, standard_error: f64::NAN, ci95: [f64::NAN; 2] };
        }
        let se = if n > 1 { (m2 / (n - 1) as f64 / n as f64).sqrt() } else { 0.0 };
        Estimate { value: mean, standard_error: se, ci95: [mean - Z95 * se, mean + Z95 * se] }
    }

    /// The proportion `k` of `n` with its binomial standard error and Wilson interval; of no
    /// trial (n = 0), 0 within [0, 1] (nothing is known).
    pub fn proportion(k: u64, n: u64) -> Estimate {
        if n == 0 {
            return Estimate { value: 0.0, standard_error: 0.0, ci95: [0.0, 1.0] };
        }
        let p = k as f64 / n as f64;
        Estimate { value: p, standard_error: (p * (1.0 - p) / n as f64).sqrt(), ci95: wilson_ci95(k, n) }
    }
}

/// The normal 95 % interval mean ± z·se of a mean with standard error `se` (module docs).
pub fn normal_ci95(mean: f64, se: f64) -> [f64; 2] {
    [mean - Z95 * se, mean + Z95 * se]
}

/// The Wilson score 95 % interval of `k` successes in `n` > 0 trials (module docs).
pub fn wilson_ci95(k: u64, n: u64) -> [f64; 2] {
    let (p, n) = (k as f64 / n as f64, n as f64);
    let z2 = Z95 * Z95;
    let d = 1.0 + z2 / n;
    let centre = (p + z2 / (2.0 * n)) / d;
    let half = Z95 * (p * (1.0 - p) / n + z2 / (4.0 * n * n)).sqrt() / d;
    [(centre - half).max(0.0), (centre + half).min(1.0)]
}

/// The 1-based ranks (l, u) of the order-statistic 95 % interval of the q-quantile of `n` values
/// (module docs); `None` for an end the values cannot give.
pub fn percentile_ranks(n: usize, q: f64) -> (Option<usize>, Option<usize>) {
    if !(q > 0.0 && q < 1.0) || n == 0 {
        return (None, None);
    }
    // F(r) of Bin(n, q) for r = 0, 1, …, from the pmf by its ratio, in logarithms at the start.
    let (nf, lq, lp) = (n as f64, (1.0 - q).ln(), q.ln());
    let mut ln_pmf = nf * lq; // P(B = 0)
    let mut cdf = 0.0;
    let (mut lower, mut upper) = (None, None);
    for r in 0..=n {
        if r > 0 {
            ln_pmf += ((nf - r as f64 + 1.0) / r as f64).ln() + lp - lq;
        }
        cdf += ln_pmf.exp();
        // F(r) is F(l − 1) for l = r + 1.
        if cdf <= 0.025 {
            lower = Some(r + 1);
        }
        if cdf >= 0.975 {
            upper = Some(r + 1);
            break;
        }
    }
    (lower.filter(|&l| l <= n), upper.filter(|&u| u <= n))
}

/// The order-statistic 95 % interval of the q-quantile of the ascending `sorted` values.
pub fn percentile_ci95(sorted: &[f64], q: f64) -> [Option<f64>; 2] {
    let (l, u) = percentile_ranks(sorted.len(), q);
    [l.map(|r| sorted[r - 1]), u.map(|r| sorted[r - 1])]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Four values 1, 2, 3, 4 by hand: mean 2.5, s = √(5/3) = 1.290994, SE = s/2 = 0.645497,
    /// interval 2.5 ± 1.959964 × 0.645497 = [1.234849, 3.765151].
    #[test]
    fn the_mean_of_four_values_by_hand() {
        let e = Estimate::mean([1.0, 2.0, 3.0, 4.0]);
        assert_eq!(e.value, 2.5);
        assert!((e.standard_error - 0.645_497_224).abs() < 1e-9, "{e:?}");
        assert!((e.ci95[0] - 1.234_849).abs() < 1e-6 && (e.ci95[1] - 3.765_151).abs() < 1e-6, "{e:?}");
        // Values far from zero: no cancellation (the same spread around 1e9).
        let far = Estimate::mean([1e9 + 1.0, 1e9 + 2.0, 1e9 + 3.0, 1e9 + 4.0]);
        assert!((far.standard_error - 0.645_497_224).abs() < 1e-6, "{far:?}");
        assert_eq!(Estimate::mean([7.0]).standard_error, 0.0);
        // The normal interval by hand: 2.5 ± 1.959964 × 0.5 = [1.520018, 3.479982].
        let ci = normal_ci95(2.5, 0.5);
        assert!((ci[0] - 1.520_018).abs() < 1e-6 && (ci[1] - 3.479_982).abs() < 1e-6, "{ci:?}");
        // A share of no lives knows nothing: 0 within [0, 1].
        assert_eq!(Estimate::proportion(0, 0), Estimate { value: 0.0, standard_error: 0.0, ci95: [0.0, 1.0] });
    }

    /// Wilson intervals by hand (module docs' formula evaluated separately): 7 of 50 → [0.069508,
    /// 0.261862]; 0 of 50 → [0, z²/(n + z²) = 0.071348]; 342 of 5000 (the design example's
    /// failures) → [0.061729, 0.075733]; and symmetric: 50 − k of 50 mirrors k of 50.
    #[test]
    fn wilson_intervals_by_hand() {
        let cases = [
            ((7, 50), [0.069_508_334, 0.261_861_937]),
            ((0, 50), [0.0, 0.071_347_599]),
            ((342, 5000), [0.061_729_279, 0.075_733_401]),
        ];
        for ((k, n), want) in cases {
            let got = wilson_ci95(k, n);
            assert!((got[0] - want[0]).abs() < 1e-8 && (got[1] - want[1]).abs() < 1e-8, "{k}/{n}: {got:?}");
            let mirror = wilson_ci95(n - k, n);
            assert!((mirror[0] - (1.0 - got[1])).abs() < 1e-12 && (mirror[1] - (1.0 - got[0])).abs() < 1e-12);
        }
        let e = Estimate::proportion(7, 50);
        assert!((e.standard_error - (0.14_f64 * 0.86 / 50.0).sqrt()).abs() < 1e-15);
    }

    /// Order-statistic ranks against the textbook's (and an exact binomial sum by hand in
    /// Python): the median of 100 values lies between x_(40) and x_(61) (coverage 0.9648), of 20
    /// between x_(6) and x_(15); the 95 % point of 1000 between x_(936) and x_(964); the 99 %
    /// point of 50 values has no upper rank (F(49) < 0.975) and a lower one.
    #[test]
    fn percentile_ranks_by_hand() {
        assert_eq!(percentile_ranks(100, 0.5), (Some(40), Some(61)));
        assert_eq!(percentile_ranks(20, 0.5), (Some(6), Some(15)));
        assert_eq!(percentile_ranks(1000, 0.95), (Some(936), Some(964)));
        let (l, u) = percentile_ranks(50, 0.99);
        assert!(l.is_some() && u.is_none(), "{l:?} {u:?}");
        let sorted: Vec<f64> = (1..=100).map(f64::from).collect();
        assert_eq!(percentile_ci95(&sorted, 0.5), [Some(40.0), Some(61.0)]);
    }
}
