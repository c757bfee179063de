//! Estimates from a two-phase stratified sample (double sampling for stratification: Neyman 1938;
//! Cochran 1977, *Sampling Techniques*, §12.2; Särndal, Swensson & Wretman 1992, §9.4): the
//! estimators of a stratified design run ([`super::lifetime::sampling`], docs/design.md
//! "Stratified sampling").
//!
//! **The design.** A first-phase sample of N units (the pool: every life of the run, each ranked by
//! a cheap severity) falls into strata h with N_h units; of stratum h each unit is kept with
//! probability f_h (a Bernoulli second phase), and only the kept units are measured (simulated).
//! Strata that kept fewer than two units are joined to a neighbour ([`TwoPhase::new`]): the groups
//! g of the estimator, each with N_g pool units and n_g kept ones, W_g = N_g/N.
//!
//! **Mean.** Within group g a unit i kept with probability f_i weighs d_i = 1/f_i (all equal unless
//! strata were joined), ȳ_g = Σ d_i y_i / Σ d_i, and
//!
//! ```text
//! ȳ = Σ_g W_g ȳ_g,     V(ȳ) = (1/N) [ Σ_g W_g s_g² / f_g  +  Σ_g W_g (ȳ_g − ȳ)² ]
//! ```
//!
//! with s_g² the (weighted) sample variance of group g (n_g − 1 in the denominator) and f_g =
//! n_g/N_g (Cochran 1977, Eq. 12.24 for an infinite population: the first term is the pool's
//! within-stratum variance inflated by the subsampling, the second the variance of the pool's
//! stratum shares). With one group and f = 1 it is the plain s²/N. The estimate is unbiased given
//! every group keeps a unit (Cochran §12.2); the interval is the normal one, ȳ ± z √V.
//!
//! **Proportion** (P(failure), P(|S| > s)): the mean of an indicator, its interval Wilson's score
//! interval at the effective sample size n_eff = p̂(1 − p̂)/V (Korn & Graubard 1998), or, at p̂ = 0
//! or 1 (V = 0), at Kish's n_eff = 1/Σ w_i² of the units' weights w_i = W_g d_i/Σ_{j∈g} d_j.
//!
//! **Domain mean** (E|S| of the surviving lives): the ratio R = Σ w_i 1_D y_i / Σ w_i 1_D, its
//! variance that of the mean of the linearised z_i = 1_D (y_i − R)/P̂(D) (Särndal et al. §5.6).
//!
//! **Percentile** ξ_q: the smallest value whose weighted distribution function F̂ reaches q; its
//! interval Woodruff's (1952): F̂⁻¹(q ∓ z σ_q), σ_q the standard error of the proportion of values
//! at or below ξ_q (an end `None` where q ∓ z σ_q leaves (0, 1)).

use super::estimate::{Estimate, Z95};

/// One group of the estimator: pool units, kept units, their design weights' sum.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Group {
    pool: usize,
    kept: usize,
    design_sum: f64,
}

/// A two-phase stratified sample (module docs): the groups and each kept unit's group and weight.
#[derive(Debug, Clone, PartialEq)]
pub struct TwoPhase {
    pool: usize,
    groups: Vec<Group>,
    /// Per kept unit (in the order given to [`Self::new`]): its group, its design weight d_i and
    /// its weight w_i (Σ w_i = 1).
    group_of: Vec<usize>,
    design: Vec<f64>,
    weight: Vec<f64>,
}

impl TwoPhase {
    /// From the pool's counts N_h by stratum and, per kept unit, its stratum and the probability
    /// f_h it was kept with. Strata are joined, from the lowest up, until each group keeps at least
    /// two units (a last group with fewer joins the one below; a pool with fewer than two kept units
    /// is one group).
    pub fn new(pool_counts: &[usize], kept: &[(usize, f64)]) -> Self {
        let strata = pool_counts.len();
        let mut kept_in = vec![0_usize; strata];
        for &(h, _) in kept {
            kept_in[h] += 1;
        }
        // The group of each stratum.
        let mut group_of_stratum = vec![0_usize; strata];
        let mut groups: Vec<Group> = Vec::new();
        let mut open = Group { pool: 0, kept: 0, design_sum: 0.0 };
        let mut members: Vec<usize> = Vec::new();
        for h in 0..strata {
            open.pool += pool_counts[h];
            open.kept += kept_in[h];
            members.push(h);
            if open.kept >= 2 {
                for &m in &members {
                    group_of_stratum[m] = groups.len();
                }
                groups.push(open);
                open = Group { pool: 0, kept: 0, design_sum: 0.0 };
                members.clear();
            }
        }
        if !members.is_empty() {
            if let Some(last) = groups.last_mut() {
                last.pool += open.pool;
                last.kept += open.kept;
                for &m in &members {
                    group_of_stratum[m] = groups.len() - 1;
                }
            } else {
                groups.push(open);
            }
        }
        let group_of: Vec<usize> = kept.iter().map(|&(h, _)| group_of_stratum[h]).collect();
        let design: Vec<f64> = kept.iter().map(|&(_, f)| 1.0 / f).collect();
        for (g, d) in group_of.iter().zip(&design) {
            groups[*g].design_sum += d;
        }
        let pool: usize = pool_counts.iter().sum();
        let weight = group_of
            .iter()
            .zip(&design)
            .map(|(&g, &d)| groups[g].pool as f64 / pool.max(1) as f64 * d / groups[g].design_sum)
            .collect();
        TwoPhase { pool, groups, group_of, design, weight }
    }

    /// N, the pool.
    pub fn pool(&self) -> usize {
        self.pool
    }

    /// The kept units.
    pub fn kept(&self) -> usize {
        self.weight.len()
    }

    /// The weight w_i of each kept unit (Σ w_i = 1 over a non-empty sample).
    pub fn weights(&self) -> &[f64] {
        &self.weight
    }

    /// Each group's weighted mean ȳ_g and sample variance s_g² of `y` (one value per kept unit).
    fn group_moments(&self, y: &[f64]) -> Vec<(f64, f64)> {
        let mut sum = vec![0.0; self.groups.len()];
        for ((&g, &d), &v) in self.group_of.iter().zip(&self.design).zip(y) {
            sum[g] += d * v;
        }
        let mean: Vec<f64> = sum.iter().zip(&self.groups).map(|(s, g)| s / g.design_sum).collect();
        let mut ss = vec![0.0; self.groups.len()];
        for ((&g, &d), &v) in self.group_of.iter().zip(&self.design).zip(y) {
            ss[g] += d * (v - mean[g]).powi(2);
        }
        self.groups
            .iter()
            .zip(mean.iter().zip(&ss))
            .map(|(g, (&m, &s))| {
                let n = g.kept as f64;
                let var = if g.kept > 1 { s / g.design_sum * n / (n - 1.0) } else { 0.0 };
                (m, var)
            })
            .collect()
    }

    /// ȳ and V(ȳ) of `y` (module docs, "Mean").
    fn mean_and_variance(&self, y: &[f64]) -> (f64, f64) {
        assert_eq!(y.len(), self.kept(), "one value per kept unit");
        if self.kept() == 0 {
            return (f64::NAN, f64::NAN);
        }
        let moments = self.group_moments(y);
        let n = self.pool as f64;
        let mean: f64 = self.groups.iter().zip(&moments).map(|(g, (m, _))| g.pool as f64 / n * m).sum();
        let within: f64 = self
            .groups
            .iter()
            .zip(&moments)
            .filter(|(g, _)| g.kept > 0)
            .map(|(g, (_, s2))| g.pool as f64 / n * s2 * g.pool as f64 / g.kept as f64)
            .sum();
        let between: f64 =
            self.groups.iter().zip(&moments).map(|(g, (m, _))| g.pool as f64 / n * (m - mean).powi(2)).sum();
        (mean, (within + between) / n)
    }

    /// The mean of `y` (one value per kept unit) with its standard error and normal interval.
    pub fn mean(&self, y: &[f64]) -> Estimate {
        let (m, v) = self.mean_and_variance(y);
        let se = v.sqrt();
        Estimate { value: m, standard_error: se, ci95: [m - Z95 * se, m + Z95 * se] }
    }

    /// The proportion of `flags` (one per kept unit) with its standard error and Wilson interval
    /// at the effective sample size (module docs, "Proportion"); of no kept unit 0 within [0, 1].
    pub fn proportion(&self, flags: &[bool]) -> Estimate {
        if self.kept() == 0 {
            return Estimate { value: 0.0, standard_error: 0.0, ci95: [0.0, 1.0] };
        }
        let y: Vec<f64> = flags.iter().map(|&f| f64::from(u8::from(f))).collect();
        let (p, v) = self.mean_and_variance(&y);
        let p = p.clamp(0.0, 1.0);
        Estimate {
            value: p,
            standard_error: v.sqrt(),
            ci95: wilson_ci95_at(p, effective_size(p, v, || kish(&self.weight))),
        }
    }

    /// The proportion of `flags` among the kept units in the domain `inside` (a [`Self::domain_mean`]
    /// of an indicator) with Wilson's interval at its effective size (module docs, "Proportion",
    /// Kish's over the domain's weights); of an empty domain 0 within [0, 1].
    pub fn domain_proportion(&self, flags: &[bool], inside: &[bool]) -> Estimate {
        let y: Vec<f64> = flags.iter().map(|&f| f64::from(u8::from(f))).collect();
        let e = self.domain_mean(&y, inside);
        let weights: Vec<f64> = self.weight.iter().zip(inside).filter(|(_, &d)| d).map(|(&w, _)| w).collect();
        let share: f64 = weights.iter().sum();
        if weights.is_empty() {
            return Estimate { value: 0.0, standard_error: 0.0, ci95: [0.0, 1.0] };
        }
        let p = e.value.clamp(0.0, 1.0);
        // Kish's size of the domain's weights, rescaled to sum to 1.
        let n_eff = effective_size(p, e.standard_error.powi(2), || share * share * kish(&weights));
        Estimate { value: p, standard_error: e.standard_error, ci95: wilson_ci95_at(p, n_eff) }
    }

    /// The mean of `y` over the kept units in the domain `inside` (module docs, "Domain mean"); 0
    /// with no error when the domain holds no kept unit.
    pub fn domain_mean(&self, y: &[f64], inside: &[bool]) -> Estimate {
        let share: f64 = self.weight.iter().zip(inside).filter(|(_, &d)| d).map(|(w, _)| w).sum();
        if share <= 0.0 {
            return Estimate { value: 0.0, standard_error: 0.0, ci95: [0.0, 0.0] };
        }
        let r = self.weight.iter().zip(y).zip(inside).filter(|(_, &d)| d).map(|((w, v), _)| w * v).sum::<f64>() / share;
        let z: Vec<f64> = y.iter().zip(inside).map(|(&v, &d)| if d { (v - r) / share } else { 0.0 }).collect();
        let (_, var) = self.mean_and_variance(&z);
        let se = var.sqrt();
        Estimate { value: r, standard_error: se, ci95: [r - Z95 * se, r + Z95 * se] }
    }

    /// The q-quantile of `y` over the kept units in the domain `inside` (every unit: `None`) and
    /// its Woodruff interval (module docs, "Percentile"); `None` when the domain is empty.
    pub fn quantile(&self, y: &[f64], inside: Option<&[bool]>, q: f64) -> Option<(f64, [Option<f64>; 2])> {
        let member = |i: usize| inside.is_none_or(|d| d[i]);
        let mut order: Vec<usize> = (0..y.len()).filter(|&i| member(i)).collect();
        if order.is_empty() {
            return None;
        }
        order.sort_by(|&a, &b| y[a].total_cmp(&y[b]));
        let share: f64 = order.iter().map(|&i| self.weight[i]).sum();
        // F̂⁻¹(p): the smallest value whose cumulative weight share reaches p.
        let inverse = |p: f64| {
            let mut cum = 0.0;
            for &i in &order {
                cum += self.weight[i] / share;
                if cum >= p * (1.0 - 1e-12) {
                    return y[i];
                }
            }
            y[*order.last().expect("not empty")]
        };
        let xi = inverse(q);
        // σ_q: the standard error of the domain proportion at or below ξ_q, linearised.
        let z: Vec<f64> =
            (0..y.len()).map(|i| if member(i) { (f64::from(u8::from(y[i] <= xi)) - q) / share } else { 0.0 }).collect();
        let (_, var) = self.mean_and_variance(&z);
        let s = Z95 * var.sqrt();
        let low = (q - s > 0.0).then(|| inverse(q - s));
        let high = (q + s < 1.0).then(|| inverse(q + s));
        Some((xi, [low, high]))
    }
}

/// The effective sample size of a proportion `p` estimated with variance `v` (module docs,
/// "Proportion"): p(1 − p)/V, or at p = 0 or 1 (V = 0) Kish's, `kish()`.
fn effective_size(p: f64, v: f64, kish: impl FnOnce() -> f64) -> f64 {
    if v > 0.0 && p > 0.0 && p < 1.0 {
        p * (1.0 - p) / v
    } else {
        kish()
    }
}

/// Kish's effective size 1/Σ w² of units whose weights sum to 1.
fn kish(weights: &[f64]) -> f64 {
    1.0 / weights.iter().map(|w| w * w).sum::<f64>()
}

/// Wilson's score 95 % interval of a proportion `p` at a (real) sample size `n` > 0
/// ([`super::estimate::wilson_ci95`] with k = p n).
pub fn wilson_ci95_at(p: f64, n: f64) -> [f64; 2] {
    let z2 = Z95 * Z95;
    let d = 1.0 + z2 / n;
    let centre = (p + z2 / (2.0 * n)) / d;
    let half = Z95 * (p * (1.0 - p) / n + z2 / (4.0 * n * n)).sqrt() / d;
    [(centre - half).max(0.0), (centre + half).min(1.0)]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::estimate::wilson_ci95;

    /// One stratum kept whole is simple random sampling: the mean, s/√n and Wilson's interval of
    /// the plain estimators.
    #[test]
    fn one_stratum_kept_whole_is_the_plain_estimate() {
        let y = [1.0, 2.0, 3.0, 4.0];
        let s = TwoPhase::new(&[4], &[(0, 1.0); 4]);
        let e = s.mean(&y);
        // By hand: mean 2.5, s = √(5/3), SE = s/2 = 0.645497.
        assert!((e.value - 2.5).abs() < 1e-15 && (e.standard_error - 0.645_497_224).abs() < 1e-9, "{e:?}");
        let flags = [true, false, false, false];
        let p = s.proportion(&flags);
        assert!((p.value - 0.25).abs() < 1e-15);
        // The sample variance of the indicator (n − 1): 0.25 · 0.75 · 4/3 = 0.25, V = 0.25/4.
        assert!((p.standard_error - 0.25).abs() < 1e-12, "{p:?}");
        // n_eff = p(1 − p)/V = 0.1875/0.0625 = 3.
        let want = wilson_ci95_at(0.25, 3.0);
        assert_eq!(p.ci95, want);
        // Wilson at a whole n is the integer formula: 1 of 4 at n = 4.
        assert_eq!(wilson_ci95_at(0.25, 4.0), wilson_ci95(1, 4));
    }

    /// Two strata by hand: pool 80 + 20; kept 4 of the first (f = 0.05) with values 0, 0, 0, 1,
    /// 5 of the second (f = 0.25) with values 1, 1, 1, 1, 0.
    /// ȳ_1 = 0.25, s_1² = 0.25, ȳ_2 = 0.8, s_2² = 0.2; ȳ = 0.8 · 0.25 + 0.2 · 0.8 = 0.36;
    /// V = (1/100) [0.8 · 0.25/(4/80) + 0.2 · 0.2/(5/20) + 0.8 · 0.11² + 0.2 · 0.44²]
    ///   = (1/100) [4 + 0.16 + 0.00968 + 0.03872] = 0.0420840.
    #[test]
    fn two_strata_by_hand() {
        let kept: Vec<(usize, f64)> = [(0, 0.05); 4].into_iter().chain([(1, 0.25); 5]).collect();
        let y = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 1.0, 0.0];
        let s = TwoPhase::new(&[80, 20], &kept);
        let e = s.mean(&y);
        assert!((e.value - 0.36).abs() < 1e-12, "{e:?}");
        assert!((e.standard_error - 0.042_084_f64.sqrt()).abs() < 1e-9, "{e:?}");
        // The weights: 0.8/4 and 0.2/5.
        assert!((s.weights()[0] - 0.2).abs() < 1e-15 && (s.weights()[8] - 0.04).abs() < 1e-15);
        assert!((s.weights().iter().sum::<f64>() - 1.0).abs() < 1e-12);
        let flags: Vec<bool> = y.iter().map(|&v| v > 0.5).collect();
        assert!((s.proportion(&flags).value - 0.36).abs() < 1e-12);
    }

    /// A stratum that kept one unit joins the next one up: pool 50/30/20, kept 3/1/2 — the middle
    /// stratum (one kept) joins the top one; the group's mean weighs its units by 1/f.
    #[test]
    fn a_stratum_with_one_kept_unit_joins_its_neighbour() {
        let kept = [(0, 0.1), (0, 0.1), (0, 0.1), (1, 0.5), (2, 1.0), (2, 1.0)];
        let s = TwoPhase::new(&[50, 30, 20], &kept);
        assert_eq!(s.groups.len(), 2);
        assert_eq!((s.groups[0].pool, s.groups[0].kept), (50, 3));
        assert_eq!((s.groups[1].pool, s.groups[1].kept), (50, 3));
        // Group 0: values 1, 1, 1: 1; group 1: d = 2, 1, 1 on values 0, 2, 4: (0 + 2 + 4)/4 = 1.5;
        // ȳ = 0.5 · 1 + 0.5 · 1.5 = 1.25.
        let y = [1.0, 1.0, 1.0, 0.0, 2.0, 4.0];
        let e = s.mean(&y);
        assert!((e.value - 1.25).abs() < 1e-12, "{e:?}");
        // A top stratum with one kept unit joins the group below.
        let top = TwoPhase::new(&[50, 30, 20], &[(0, 0.1), (0, 0.1), (1, 0.5), (1, 0.5), (2, 1.0)]);
        assert_eq!(top.groups.len(), 2);
        assert_eq!((top.groups[1].pool, top.groups[1].kept), (50, 3));
    }

    /// The domain mean and the percentile of one stratum kept whole: the survivors' plain mean,
    /// and the nearest-rank percentile.
    #[test]
    fn domain_mean_and_percentile_of_one_stratum() {
        let y: Vec<f64> = (1..=100).map(f64::from).collect();
        let s = TwoPhase::new(&[100], &[(0, 1.0); 100]);
        let inside: Vec<bool> = y.iter().map(|&v| v <= 50.0).collect();
        let d = s.domain_mean(&y, &inside);
        assert!((d.value - 25.5).abs() < 1e-12, "{d:?}");
        let (xi, ci) = s.quantile(&y, None, 0.5).expect("values");
        assert_eq!(xi, 50.0);
        // Woodruff: σ = √(0.25 · 100/99 / 100) = 0.050252, q ± 1.96 σ = 0.40151, 0.59849: the
        // 41st and 60th values.
        assert_eq!(ci, [Some(41.0), Some(60.0)]);
        let (xi_in, _) = s.quantile(&y, Some(&inside), 0.5).expect("values");
        assert_eq!(xi_in, 25.0);
    }
}
