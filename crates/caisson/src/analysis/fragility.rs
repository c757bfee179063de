//! Fragility curves for sliding (docs/model.md §7; the generic method of Lupoi et al. 2007 and
//! similar): for a grid of significant heights at the structure, many storms each; the
//! probability that a storm's sliding exceeds each limit; a lognormal curve fitted to the counts.
//!
//! **Storms.** The intensity measure IM is H1/3 at the structure (the toe of the mound). At
//! height level i (H_i) storm j is one [`simulate_storm`] with
//!
//! * H1/3 = H_i, the Rayleigh heights of the storm limited to Goda's design-wave H_max of H_i
//!   ([`super::conventional::DesignWave::irregular`], docs/model.md §1.3): 1.8 H_i ([`HMAX_RATIO`],
//!   Goda's design ratio for the largest of about 250-1000 waves), or Goda's (2000)
//!   breaking-limited H_max at the toe where that is lower (inside the surf zone), as the design
//!   life limits its waves; waves above the breaker height at the wall break on it and load it by
//!   the impact model of the scenario;
//! * T1/3 = `period_s` for every wave, N = round(duration / T1/3) waves (at least 1);
//! * no tide; the load-model errors of a design life drawn per storm ([`FragilityParams::errors`],
//!   on by default): the multipliers of the wave force, of the friction and of the impulsive
//!   component, 1 + bias + COV z with z truncated as `[design]` draws them
//!   ([`super::lifetime::Errors::draw_load_errors`]; Takayama & Ikeda 1992 via Shimosako &
//!   Takahashi 1999; Kim & Takayama 2003). The errors of the deep-water height and of the wave
//!   transformation are not drawn: the IM is H1/3 at the structure itself. Without the errors the
//!   spread comes from the wave sequence and the rise times only, and the curves are steep
//!   (docs/fragility.md gives β with and without them);
//! * the conservative screen of [`simulate_storm`] (waves that provably cannot slide either
//!   model are skipped; the share is reported).
//!
//! **Streams.** Storm j at height H draws from its own generator, keyed by the height and the
//! storm index, never by their position in the grid ([`storm_rng`]): the ChaCha8 generator of
//! the seed, on the stream numbered by the bits of H1/3 (`f64::to_bits`), from word position
//! j · 2^[`STORM_WORDS_LOG2`]. So adding heights, running heights apart or adding storms leaves
//! every existing storm as it was. Distinct heights are distinct streams (`to_bits` is one to
//! one); within a stream storm j owns the 2^40 32-bit words from j · 2^40, and a storm draws
//! at most about 6 words per wave (only the waves above the screen's threshold, each a uniform
//! for its height, a standard-normal rise-time deviate and a uniform place, 2 words each; module
//! docs of [`super::lifetime`], "Drawing"): storms could share numbers only beyond 1.8e11 waves
//! per storm (`[fragility] storms`
//! ≤ 10^6 < 2^20 keeps j · 2^40 inside ChaCha's 2^68 words). The (level, storm) pairs run with
//! rayon and are collected in order, so the results do not depend on the number of threads. The
//! library does not print: `progress` is called once per storm.
//!
//! **Climate** (`[fragility] storm_duration_model`, `wave_direction`: the keys of `[design]`,
//! [`super::climate`]). By default every storm lasts `storm_duration_h` and meets the breakwater
//! head-on. With lognormal durations or a distribution of directions, storm j draws its duration
//! and then its angle from the last 64 words of its part of the stream (from (j + 1) · 2^40 − 64),
//! so its waves are drawn as before; N = round(D / T1/3). Its errors come from the 64 words
//! before those (from (j + 1) · 2^40 − 128), so they move neither its waves nor its climate.
//!
//! **Counts.** k_i(s) = #{storms at H_i with |S| > s} (strictly greater), S the storm's net
//! sliding (shoreward +; a rocking caisson can end a storm seaward, docs/design.md), for the
//! dynamic model and for the rigid block (Shimosako model; S ≥ 0) separately; P̂_i = k_i / n_i.
//! The mean and largest storm sliding of a level are of |S| too. A storm in which a wave rotated
//! the caisson beyond `[fragility] failure_rotation_rad` (default 0.01 rad, as `[design]
//! failure_rotation_rad`: beyond it the model's kinematics and foundation do not hold,
//! docs/design.md) counts as exceeding every limit of the dynamic model, whatever its sliding;
//! their number is reported per height (`rotation_failures`). Storms run whole (a design life
//! ends at failure; a fragility storm is counted, and the rigid block keeps its full storm).
//!
//! **Lognormal fit** (docs/model.md §7 step 4): P(S > s | IM) = Φ((ln IM − ln θ)/β), θ the median
//! capacity (m of H1/3) and β the log-standard deviation, by maximum likelihood on the binomial
//! counts,
//!
//! ```text
//! ln L(ln θ, β) = Σ_i k_i ln p_i + (n_i − k_i) ln(1 − p_i),   p_i = Φ((ln IM_i − ln θ)/β),
//! ```
//!
//! p_i and 1 − p_i = Φ(−z_i) computed separately and clamped to [1e-12, 1 − 1e-12]. The maximum
//! is found by Nelder & Mead (1965) on (ln θ, ln β) (so β > 0), restarted from its own result
//! until it stops moving, from ln θ at the middle of the heights where the counts are mixed and
//! β half their spread. Standard errors come from the expected (Fisher) information at the
//! maximum: I = Σ_i n_i φ(z_i)² / (p_i (1 − p_i)) ∇z_i ∇z_iᵀ with ∂z/∂ln θ = −1/β,
//! ∂z/∂β = −z/β.
//!
//! **Intervals.** θ and β each carry a 95 % profile-likelihood interval (Venzon & Moolgavkar 1988;
//! Pawitan 2001, §2.6): the values of the parameter at which the log-likelihood, maximised over
//! the other one, lies χ²₁(0.95)/2 = 1.9207 below its maximum. Unlike θ̂ · exp(±1.96 SE) it
//! follows the likelihood's asymmetry, which is large for the few storms of a fragility run. The
//! log-likelihood is concave in (−ln θ/β, 1/β) (probit regression), so each profile is found by a
//! golden-section search on the other parameter, and each end by bisection after stepping out
//! from the maximum by doubling multiples of the standard error; an end that lies beyond the
//! search bounds (the likelihood never drops by 1.92 there) is open (`None`).
//!
//! **When the counts do not determine both parameters** the fit is refused with a reason
//! ([`FitFailure`]):
//!
//! * no storm exceeds the limit at any height, or every storm exceeds it at every height;
//! * the counts are *separated*: no level with an exceedance lies below a level with a
//!   non-exceedance (the counts go from none to all between two neighbouring heights, with at
//!   most one mixed level between them; this includes a single level). The likelihood then
//!   grows without bound as β → 0 (a step at an undetermined height);
//! * the maximum lies at the search bounds (β > [`BETA_MAX`] or θ more than e^5 ≈ 150 times
//!   beyond the grid): the probabilities do not rise across the grid, or rise so little that the
//!   median is far outside it.
//!
//! **Φ** is computed from erfc by the Chebyshev fit of Numerical Recipes (Press et al. 1992,
//! §6.2, `erfcc`): fractional error below 1.2e-7 everywhere, so Φ(z) and its tail Φ(−z) have the
//! same relative accuracy.

use super::climate::{StormDuration, WaveDirection, WavePeriods, MAX_STORM_DURATION_S};
use super::conventional::DesignWave;
#[cfg(test)]
use super::lifetime::ErrorModel;
use super::lifetime::{
    failure_rotation_rad, simulate_storm, Errors, FailureLimits, StormCase, StormError, StormInput, StormOutcome,
};
use super::Progress;
use crate::check::{self, count, interval};
use crate::loads::model::{WaveLoadModel, MIN_LENGTH_M, MIN_PERIOD_S};
use crate::loads::risetime::LoadRng;
use crate::waves::breaking::MICHE_STEEPNESS;
use crate::waves::dispersion::deep_water_wavelength_m;
/// Φ, φ and erfc live with the other distributions of the waves; named here as before.
pub use crate::waves::statistics::{erfc, normal_cdf, normal_pdf};
use crate::ParamError;
use rand::SeedableRng;
use rayon::prelude::*;
use thiserror::Error;

/// H_max / H1/3 of a storm (Goda's design ratio).
pub const HMAX_RATIO: f64 = super::conventional::HMAX_OVER_H13;
/// log2 of the 32-bit words of its stream each storm owns (module docs, "Streams").
pub const STORM_WORDS_LOG2: u32 = 40;

/// The generator of storm `storm` at H1/3 = `h13_m` (module docs, "Streams"): ChaCha8 seeded
/// with `seed`, stream `h13_m.to_bits()`, word position `storm · 2^STORM_WORDS_LOG2`.
pub fn storm_rng(seed: u64, h13_m: f64, storm: usize) -> LoadRng {
    let mut rng = LoadRng::seed_from_u64(seed);
    rng.set_stream(h13_m.to_bits());
    rng.set_word_pos((storm as u128) << STORM_WORDS_LOG2);
    rng
}
/// The largest β the fit accepts (in units of ln IM).
pub const BETA_MAX: f64 = 20.0;
/// The smallest β the search considers.
const BETA_MIN: f64 = 1e-4;
/// How far beyond the grid (in ln IM) the median may lie.
const LN_MEDIAN_MARGIN: f64 = 5.0;
/// Clamp of p and 1 − p in the likelihood.
const P_CLAMP: f64 = 1e-12;

/// A fitted lognormal fragility curve P(IM) = Φ((ln IM − ln θ)/β).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct LognormalFit {
    /// θ, the median (the IM at which P = 1/2), in the unit of the IM.
    pub median: f64,
    /// β, the log-standard deviation.
    pub beta: f64,
    /// Standard error of ln θ (expected information).
    pub ln_median_se: f64,
    /// Standard error of β.
    pub beta_se: f64,
    /// The maximised log-likelihood (binomial coefficients left out).
    pub log_likelihood: f64,
    /// 95 % profile-likelihood interval of θ (module docs, "Intervals"); an end beyond the search
    /// bounds is `None`.
    pub median_ci95: [Option<f64>; 2],
    /// 95 % profile-likelihood interval of β.
    pub beta_ci95: [Option<f64>; 2],
}

impl LognormalFit {
    /// P(exceedance) at intensity `im` > 0.
    pub fn probability(&self, im: f64) -> f64 {
        normal_cdf((im.ln() - self.median.ln()) / self.beta)
    }
}

/// Why counts cannot be fitted (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Error, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum FitFailure {
    #[error("no storm exceeded the limit at any height")]
    NoExceedance,
    #[error("every storm exceeded the limit at every height")]
    AllExceed,
    #[error("the counts do not overlap (no height with an exceedance lies below a height with a storm under the limit), so β is not determined; add heights (or storms) where the probability is between 0 and 1")]
    Separated,
    #[error("the likelihood has its maximum at the search bounds (β > 20 or a median far outside the heights): the probabilities do not rise across the grid")]
    AtBounds,
}

/// Negative binomial log-likelihood (module docs) at (ln θ, β).
fn neg_log_likelihood(x: &[f64], k: &[u64], n: &[u64], ln_median: f64, beta: f64) -> f64 {
    let mut s = 0.0;
    for i in 0..x.len() {
        let z = (x[i] - ln_median) / beta;
        let p = normal_cdf(z).clamp(P_CLAMP, 1.0 - P_CLAMP);
        let q = normal_cdf(-z).clamp(P_CLAMP, 1.0 - P_CLAMP);
        s -= k[i] as f64 * p.ln() + (n[i] - k[i]) as f64 * q.ln();
    }
    s
}

/// Nelder & Mead (1965) simplex minimisation in two dimensions (reflection 1, expansion 2,
/// contraction 1/2, shrink 1/2), from `start` with initial steps `step`, until every vertex is
/// within `xtol` of the best (in each coordinate) or `max_evals` evaluations.
fn nelder_mead(
    f: &dyn Fn([f64; 2]) -> f64,
    start: [f64; 2],
    step: [f64; 2],
    xtol: f64,
    max_evals: usize,
) -> ([f64; 2], f64) {
    let mut v = [start, [start[0] + step[0], start[1]], [start[0], start[1] + step[1]]];
    let mut fv = [f(v[0]), f(v[1]), f(v[2])];
    let mut evals = 3;
    let lerp = |a: [f64; 2], b: [f64; 2], t: f64| [a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])];
    while evals < max_evals {
        // Order: best, middle, worst.
        let mut idx = [0, 1, 2];
        idx.sort_by(|&a, &b| fv[a].total_cmp(&fv[b]));
        v = [v[idx[0]], v[idx[1]], v[idx[2]]];
        fv = [fv[idx[0]], fv[idx[1]], fv[idx[2]]];
        let size = (1..3).map(|i| (v[i][0] - v[0][0]).abs().max((v[i][1] - v[0][1]).abs())).fold(0.0, f64::max);
        if size <= xtol {
            break;
        }
        let centroid = lerp(v[0], v[1], 0.5);
        let reflected = lerp(centroid, v[2], -1.0);
        let fr = f(reflected);
        evals += 1;
        if fr < fv[0] {
            let expanded = lerp(centroid, v[2], -2.0);
            let fe = f(expanded);
            evals += 1;
            (v[2], fv[2]) = if fe < fr { (expanded, fe) } else { (reflected, fr) };
        } else if fr < fv[1] {
            (v[2], fv[2]) = (reflected, fr);
        } else {
            // Contract towards the better of the worst and its reflection.
            let (toward, f_toward) = if fr < fv[2] { (reflected, fr) } else { (v[2], fv[2]) };
            let contracted = lerp(centroid, toward, 0.5);
            let fc = f(contracted);
            evals += 1;
            if fc < f_toward {
                (v[2], fv[2]) = (contracted, fc);
            } else {
                for i in 1..3 {
                    v[i] = lerp(v[0], v[i], 0.5);
                    fv[i] = f(v[i]);
                }
                evals += 2;
            }
        }
    }
    let best = (0..3).min_by(|&a, &b| fv[a].total_cmp(&fv[b])).expect("three vertices");
    (v[best], fv[best])
}

/// Fit P(IM) = Φ((ln IM − ln θ)/β) to `k[i]` exceedances of `n[i]` trials at `im[i]` > 0 by
/// maximum likelihood (module docs). Levels with n = 0 are ignored.
pub fn fit_lognormal(im: &[f64], k: &[u64], n: &[u64]) -> Result<LognormalFit, FitFailure> {
    assert!(im.len() == k.len() && k.len() == n.len(), "one count per level");
    let levels: Vec<usize> = (0..im.len()).filter(|&i| n[i] > 0).collect();
    let x: Vec<f64> = levels.iter().map(|&i| im[i].ln()).collect();
    let k: Vec<u64> = levels.iter().map(|&i| k[i].min(n[i])).collect();
    let n: Vec<u64> = levels.iter().map(|&i| n[i]).collect();
    if k.iter().all(|&k| k == 0) {
        return Err(FitFailure::NoExceedance);
    }
    if k.iter().zip(&n).all(|(k, n)| k == n) {
        return Err(FitFailure::AllExceed);
    }
    // Overlap: the lowest level with an exceedance lies below the highest with a non-exceedance.
    let lo = (0..x.len()).filter(|&i| k[i] > 0).map(|i| x[i]).fold(f64::INFINITY, f64::min);
    let hi = (0..x.len()).filter(|&i| k[i] < n[i]).map(|i| x[i]).fold(f64::NEG_INFINITY, f64::max);
    if lo >= hi {
        return Err(FitFailure::Separated);
    }
    let (x_min, x_max) = x.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| (a.min(v), b.max(v)));
    let (a_lo, a_hi) = (x_min - LN_MEDIAN_MARGIN, x_max + LN_MEDIAN_MARGIN);
    let (c_lo, c_hi) = (BETA_MIN.ln(), (2.0 * BETA_MAX).ln());
    // The search stays inside the bounds: outside them the objective is that of the nearest
    // bound plus a growing penalty.
    let objective = |p: [f64; 2]| {
        let a = p[0].clamp(a_lo, a_hi);
        let c = p[1].clamp(c_lo, c_hi);
        neg_log_likelihood(&x, &k, &n, a, c.exp()) * (1.0 + (p[0] - a).abs() + (p[1] - c).abs())
            + (p[0] - a).abs()
            + (p[1] - c).abs()
    };
    let mut best = [0.5 * (lo + hi), (0.5 * (hi - lo)).ln()];
    let mut f_best = objective(best);
    for _ in 0..20 {
        let (p, fp) = nelder_mead(&objective, best, [0.2, 0.3], 1e-10, 20_000);
        let moved = (p[0] - best[0]).abs().max((p[1] - best[1]).abs());
        if fp <= f_best {
            best = p;
            f_best = fp;
        }
        if moved <= 1e-9 {
            break;
        }
    }
    let (ln_median, beta) = (best[0], best[1].exp());
    if !(ln_median > a_lo + 1e-6 && ln_median < a_hi - 1e-6 && beta <= BETA_MAX && beta > 2.0 * BETA_MIN) {
        return Err(FitFailure::AtBounds);
    }
    // Expected information on (ln θ, β).
    let mut info = [[0.0; 2]; 2];
    for i in 0..x.len() {
        let z = (x[i] - ln_median) / beta;
        let p = normal_cdf(z).clamp(P_CLAMP, 1.0 - P_CLAMP);
        let q = normal_cdf(-z).clamp(P_CLAMP, 1.0 - P_CLAMP);
        let w = n[i] as f64 * normal_pdf(z).powi(2) / (p * q);
        let g = [-1.0 / beta, -z / beta];
        for r in 0..2 {
            for c in 0..2 {
                info[r][c] += w * g[r] * g[c];
            }
        }
    }
    let det = info[0][0] * info[1][1] - info[0][1] * info[1][0];
    let (ln_median_se, beta_se) = if det > 0.0 && det.is_finite() {
        ((info[1][1] / det).sqrt(), (info[0][0] / det).sqrt())
    } else {
        (f64::INFINITY, f64::INFINITY)
    };
    if !(ln_median_se.is_finite() && beta_se.is_finite()) {
        return Err(FitFailure::AtBounds);
    }
    let profile = Profile { x: &x, k: &k, n: &n, ln_median: (a_lo, a_hi), ln_beta: (c_lo, c_hi) };
    let nll_max = -neg_log_likelihood(&x, &k, &n, ln_median, beta) - PROFILE_DROP;
    let median_ci95 = Profile::ends(ln_median, ln_median_se, (a_lo, a_hi), nll_max, |a| profile.over_beta(a))
        .map(|e| e.map(f64::exp));
    let beta_ci95 =
        Profile::ends(beta.ln(), beta_se / beta, (c_lo, BETA_MAX.ln()), nll_max, |c| profile.over_median(c.exp()))
            .map(|e| e.map(f64::exp));
    Ok(LognormalFit {
        median: ln_median.exp(),
        beta,
        ln_median_se,
        beta_se,
        log_likelihood: -f_best,
        median_ci95,
        beta_ci95,
    })
}

/// The drop of the log-likelihood from its maximum at the ends of a 95 % profile-likelihood
/// interval: χ²₁(0.95)/2.
pub const PROFILE_DROP: f64 = 3.841_458_820_694_124 / 2.0;

/// The counts of a fit and its search bounds, for the profile likelihood (module docs,
/// "Intervals").
struct Profile<'a> {
    x: &'a [f64],
    k: &'a [u64],
    n: &'a [u64],
    /// Bounds of ln θ and of ln β.
    ln_median: (f64, f64),
    ln_beta: (f64, f64),
}

impl Profile<'_> {
    /// The log-likelihood at ln θ = `a`, maximised over β.
    fn over_beta(&self, a: f64) -> f64 {
        -golden_min(|c| neg_log_likelihood(self.x, self.k, self.n, a, c.exp()), self.ln_beta)
    }

    /// The log-likelihood at β = `beta`, maximised over ln θ.
    fn over_median(&self, beta: f64) -> f64 {
        -golden_min(|a| neg_log_likelihood(self.x, self.k, self.n, a, beta), self.ln_median)
    }

    /// The two ends (in the variable `v` of `profile`, maximum at `v_hat` with standard error
    /// `se`, searched within `(lo, hi)`) where `profile` falls to `level`: stepping out by 1, 2,
    /// 4, … standard errors, then bisection; `None` where it does not fall that far within the
    /// bounds.
    fn ends(v_hat: f64, se: f64, (lo, hi): (f64, f64), level: f64, profile: impl Fn(f64) -> f64) -> [Option<f64>; 2] {
        [-1.0, 1.0].map(|dir| {
            let mut inside = v_hat;
            let mut step = se.max(1e-6);
            loop {
                let v = (v_hat + dir * step).clamp(lo, hi);
                if profile(v) < level {
                    let (mut a, mut b) = (inside, v);
                    while (b - a).abs() > 1e-10 * (1.0 + a.abs()) {
                        let mid = 0.5 * (a + b);
                        if profile(mid) < level {
                            b = mid;
                        } else {
                            a = mid;
                        }
                    }
                    return Some(0.5 * (a + b));
                }
                if v == lo || v == hi {
                    return None;
                }
                inside = v;
                step *= 2.0;
            }
        })
    }
}

/// The minimum of `f` on `[lo, hi]` (unimodal there) by golden-section search to a bracket of
/// 1e-10 (1 + |x|).
fn golden_min(f: impl Fn(f64) -> f64, (lo, hi): (f64, f64)) -> f64 {
    let r = 0.5 * (5f64.sqrt() - 1.0);
    let (mut a, mut b) = (lo, hi);
    let (mut c, mut d) = (b - r * (b - a), a + r * (b - a));
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..200 {
        if (b - a).abs() <= 1e-10 * (1.0 + a.abs().max(b.abs())) {
            break;
        }
        if fc < fd {
            (b, d, fd) = (d, c, fc);
            c = b - r * (b - a);
            fc = f(c);
        } else {
            (a, c, fc) = (c, d, fd);
            d = a + r * (b - a);
            fd = f(d);
        }
    }
    fc.min(fd)
}

/// A non-empty, strictly increasing list of at most [`MAX_LEVELS`] finite numbers in (0, `hi`)
/// (`unit`: the words after the bound).
/// A list of 1 to [`MAX_LEVELS`] increasing values, each from `lo` (above it with `lo_open`, else
/// at least it) to below `hi` (shown as `hi_shown`); `unit`: the unit and what the upper bound is.
fn increasing(
    quantity: &'static str,
    v: &[f64],
    (lo, lo_open): (f64, bool),
    (hi, hi_shown): (f64, &str),
    unit: &str,
) -> Result<(), FragilityParamError> {
    if v.is_empty() {
        return Err(FragilityParamError::Empty { quantity });
    }
    if v.len() > MAX_LEVELS {
        return Err(FragilityParamError::TooMany { quantity, count: v.len() });
    }
    let low = if lo_open { ">" } else { "≥" };
    for (index, &x) in v.iter().enumerate() {
        let at = |words: String| FragilityParamError::Element { index, error: check::rule(quantity, x, words) };
        if !(x.is_finite() && (if lo_open { x > lo } else { x >= lo }) && x < hi) {
            let lo = crate::fmt_number(lo);
            return Err(at(format!("must be a finite number {low} {lo} and < {hi_shown} ({unit})")));
        }
        if index > 0 && x <= v[index - 1] {
            return Err(at(format!(
                "must be larger than the value before it ({}): the list must increase",
                crate::fmt_value(v[index - 1])
            )));
        }
    }
    Ok(())
}

/// The storms of a fragility analysis (module docs).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct FragilityParams {
    /// The IM grid: H1/3 at the structure, m, increasing.
    pub heights_m: Vec<f64>,
    /// Storms per height.
    pub storms: usize,
    /// Sliding limits s_lim, m, increasing.
    pub limits_m: Vec<f64>,
    /// Duration of a storm, s.
    pub storm_duration_s: f64,
    /// T1/3 of every wave, s.
    pub period_s: f64,
    pub seed: u64,
    /// A storm that rotates the caisson beyond this counts as exceeding every limit (module
    /// docs, "Counts"), rad.
    pub failure_rotation_rad: f64,
    /// The storms' durations (fixed: `storm_duration_s`; or a distribution of that mean) and
    /// wave directions (module docs, "Climate").
    pub duration: StormDuration,
    pub direction: WaveDirection,
    /// The waves' periods (module docs, "Climate"): every wave at `period_s` (T1/3), or each
    /// its own given its height.
    #[serde(skip_serializing_if = "WavePeriods::is_significant")]
    pub periods: WavePeriods,
    /// The load-model errors drawn per storm (module docs, "Storms": the wave force's, the
    /// friction's and the impulsive component's of these; the deep-water and transformation
    /// errors are not used); `None`: none (`[fragility] errors = false`).
    pub errors: Option<Errors>,
}

/// At most this many heights and limits.
pub const MAX_LEVELS: usize = 1000;
/// At most this many storms per height.
pub const MAX_STORMS_PER_HEIGHT: usize = 1_000_000;
/// At most this many storms in all (heights × storms).
pub const MAX_STORMS: usize = 10_000_000;

/// Why [`FragilityParams`] are refused: a quantity, or a list's length or element.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FragilityParamError {
    #[error(transparent)]
    Param(#[from] ParamError),
    #[error("{quantity} is empty: it must list at least one value")]
    Empty { quantity: &'static str },
    #[error("{quantity} has {count} values: at most {MAX_LEVELS}")]
    TooMany { quantity: &'static str, count: usize },
    /// The element `index` of the list `error.quantity`.
    #[error("{}[{index}] = {}: {}", error.quantity, crate::fmt_value(error.value), error.allowed.describe(1.0, ""))]
    Element { index: usize, error: ParamError },
}

impl FragilityParams {
    /// The storms if in range: a period from [`MIN_PERIOD_S`] to 1000 s; 1 to [`MAX_LEVELS`]
    /// heights, increasing, each from [`MIN_LENGTH_M`] to below Miche's deep-water limit 0.142 L0
    /// at that period (as `[waves] period_s` and `significant_height_m`); 1 to [`MAX_LEVELS`] limits, increasing, above 0 and below 1 km; 1
    /// to [`MAX_STORMS_PER_HEIGHT`] storms a height and at most [`MAX_STORMS`] in all; a duration
    /// in (0, [`MAX_STORM_DURATION_S`]]; the failure rotation
    /// ([`super::lifetime::failure_rotation_rad`]) and the climate's choices (their `checked`).
    pub fn checked(self) -> Result<Self, FragilityParamError> {
        interval("period_s", self.period_s, MIN_PERIOD_S, 1e3, false)?;
        let limit = MICHE_STEEPNESS * deep_water_wavelength_m(self.period_s);
        let words = format!("m; 0.142 L0 for T = {} s", crate::fmt_value(self.period_s));
        increasing("heights_m", &self.heights_m, (MIN_LENGTH_M, false), (limit, &format!("{limit:.3}")), &words)?;
        increasing("limits_m", &self.limits_m, (0.0, true), (1e3, "1000"), "m")?;
        count("storms", self.storms, 1, MAX_STORMS_PER_HEIGHT as u64)?;
        let all = self.storms.saturating_mul(self.heights_m.len());
        if all > MAX_STORMS {
            let n = self.heights_m.len();
            let words = format!("times {n} heights is {all} storms; at most {MAX_STORMS} in all");
            return Err(check::rule("storms", self.storms as f64, words).into());
        }
        interval("storm_duration_s", self.storm_duration_s, 0.0, MAX_STORM_DURATION_S, true)?;
        failure_rotation_rad(self.failure_rotation_rad)?;
        self.duration.checked()?;
        self.direction.checked()?;
        if let WavePeriods::LonguetHiggins { spectral_width } = self.periods {
            WavePeriods::longuet_higgins(spectral_width)?;
        }
        if let Some(e) = &self.errors {
            for m in [e.wave_force, e.friction].iter().chain(&e.impact_force) {
                m.checked()?;
            }
        }
        Ok(self)
    }

    /// Waves per storm, round(duration / T1/3), at least 1.
    pub fn waves_per_storm(&self) -> usize {
        (self.storm_duration_s / self.period_s).round().max(1.0) as usize
    }

    /// The storm at height `h13_m` on the site of `model` (module docs): its waves limited to
    /// the design wave's H_max.
    pub fn storm_input(&self, model: &WaveLoadModel, h13_m: f64) -> StormInput {
        StormInput {
            h13_m,
            hmax_m: DesignWave::irregular(model, h13_m, self.period_s).design_height_m,
            period_s: self.period_s,
            periods: self.periods,
            waves: self.waves_per_storm(),
            tide_m: 0.0,
            angle_rad: 0.0,
            force_factor: 1.0,
            impact_factor: 1.0,
            friction_factor: 1.0,
        }
    }

    /// Storm `storm` at height `h13_m`: [`Self::storm_input`] with its own errors, duration and
    /// angle when they are drawn (module docs, "Storms" and "Climate").
    pub fn storm_input_of(&self, model: &WaveLoadModel, h13_m: f64, storm: usize) -> StormInput {
        let mut s = self.storm_input(model, h13_m);
        if let Some(e) = &self.errors {
            let mut rng = storm_rng(self.seed, h13_m, storm);
            rng.set_word_pos((((storm as u128) + 1) << STORM_WORDS_LOG2) - 2 * STORM_CLIMATE_WORDS);
            [s.force_factor, s.friction_factor, s.impact_factor] = e.draw_load_errors(&mut rng);
        }
        if self.duration != StormDuration::Fixed || self.direction != WaveDirection::HeadOn {
            let mut rng = storm_rng(self.seed, h13_m, storm);
            rng.set_word_pos((((storm as u128) + 1) << STORM_WORDS_LOG2) - STORM_CLIMATE_WORDS);
            let duration_s = self.duration.draw_s(self.storm_duration_s, &mut rng);
            s.waves = (duration_s / self.period_s).round().max(1.0) as usize;
            s.angle_rad = self.direction.draw_rad(&mut rng);
        }
        s
    }
}

/// The words at the end of each storm's part of its stream that its duration and angle are
/// drawn from (module docs, "Climate").
const STORM_CLIMATE_WORDS: u128 = 64;

/// The storms of one height.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct LevelResult {
    /// H1/3 at the structure, m.
    pub h13_m: f64,
    /// H_max of its storms (the design wave's: 1.8 H1/3 or the breaking limit), m.
    pub hmax_m: f64,
    /// One outcome per storm, in storm order.
    pub storms: Vec<StormOutcome>,
    /// Storms with a dynamic sliding magnitude |S| > each limit.
    pub dynamic_exceedances: Vec<u64>,
    /// Storms with rigid-block sliding > each limit.
    pub rigid_block_exceedances: Vec<u64>,
    /// Storms that rotated the caisson beyond the rotation limit (counted in every
    /// `dynamic_exceedances`).
    pub rotation_failures: u64,
}

impl LevelResult {
    fn new(input: &StormInput, storms: Vec<StormOutcome>, limits_m: &[f64], rotation_rad: f64) -> Self {
        let rotated = |o: &StormOutcome| o.max_rotation_rad > rotation_rad;
        let count = |exceeds: &dyn Fn(&StormOutcome, f64) -> bool| {
            limits_m.iter().map(|&s| storms.iter().filter(|o| exceeds(o, s)).count() as u64).collect()
        };
        LevelResult {
            h13_m: input.h13_m,
            hmax_m: input.hmax_m,
            dynamic_exceedances: count(&|o, s| rotated(o) || o.sliding_m.abs() > s),
            rigid_block_exceedances: count(&|o, s| o.rigid_block_sliding_m > s),
            rotation_failures: storms.iter().filter(|o| rotated(o)).count() as u64,
            storms,
        }
    }

    fn mean(&self, f: fn(&StormOutcome) -> f64) -> f64 {
        self.storms.iter().map(f).sum::<f64>() / self.storms.len().max(1) as f64
    }

    /// Mean magnitude |S| of the storm sliding, dynamic model, m.
    pub fn mean_sliding_m(&self) -> f64 {
        self.mean(|o| o.sliding_m.abs())
    }

    /// Mean storm sliding, rigid block, m.
    pub fn mean_rigid_block_sliding_m(&self) -> f64 {
        self.mean(|o| o.rigid_block_sliding_m)
    }

    /// Share of the waves skipped by the screen.
    pub fn screened_share(&self) -> f64 {
        let waves: u64 = self.storms.iter().map(|o| o.waves).sum();
        self.storms.iter().map(|o| o.screened_waves).sum::<u64>() as f64 / waves.max(1) as f64
    }
}

/// The fitted curves of one limit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LimitFit {
    pub limit_m: f64,
    /// IM = H1/3 in m: the median is in m.
    pub dynamic: Result<LognormalFit, FitFailure>,
    pub rigid_block: Result<LognormalFit, FitFailure>,
}

/// Everything a fragility analysis found.
#[derive(Debug, Clone, PartialEq)]
pub struct FragilityResult {
    pub levels: Vec<LevelResult>,
    /// One per limit, in the order of the limits.
    pub fits: Vec<LimitFit>,
}

/// A storm that could not be run.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("storm {storm} at H1/3 = {h13_m} m")]
pub struct StormFailed {
    pub h13_m: f64,
    pub storm: usize,
    #[source]
    pub source: StormError,
}

/// The storms' case of fragility `p` on `st`: storms run whole, each recording its failing wave
/// (module docs, "Counts"): the wave that takes the caisson beyond the largest limit from its
/// place or rotates it beyond the rotation limit (the rigid block: beyond the largest limit); the
/// screen looks at sliding and lift-off only (no heel pressure is reported).
pub fn storm_case<'a>(st: &StormCase<'a>, p: &FragilityParams) -> StormCase<'a> {
    let failure = FailureLimits {
        sliding_m: p.limits_m.last().copied().unwrap_or(f64::INFINITY),
        rotation_rad: p.failure_rotation_rad,
        heel_pressure_pa: None,
    };
    StormCase { failure: Some(failure), heel_screen_pa: f64::INFINITY, ..*st }
}

/// Run every storm of every height in parallel and fit the curves (module docs).
pub fn run_fragility(
    st: &StormCase<'_>,
    p: &FragilityParams,
    progress: Progress<'_>,
) -> Result<FragilityResult, StormFailed> {
    let storms = p.storms;
    let st = &storm_case(st, p);
    let outcomes: Vec<StormOutcome> = (0..p.heights_m.len() * storms)
        .into_par_iter()
        // A progress callback that unwinds (a Python call stopped by Ctrl-C) stops the items not yet begun.
        .panic_fuse()
        .map(|job| {
            let (level, storm) = (job / storms, job % storms);
            let h = p.heights_m[level];
            let mut rng = storm_rng(p.seed, h, storm);
            let out = simulate_storm(st, &p.storm_input_of(st.model, h, storm), &mut rng)
                .map_err(|source| StormFailed { h13_m: h, storm, source });
            progress();
            out
        })
        .collect::<Result<_, _>>()?;
    let levels: Vec<LevelResult> = p
        .heights_m
        .iter()
        .zip(outcomes.chunks(storms.max(1)))
        .map(|(&h, o)| LevelResult::new(&p.storm_input(st.model, h), o.to_vec(), &p.limits_m, p.failure_rotation_rad))
        .collect();
    Ok(FragilityResult { fits: fit_levels(&levels, &p.limits_m), levels })
}

/// The lognormal fits of every limit, dynamic and rigid block.
pub fn fit_levels(levels: &[LevelResult], limits_m: &[f64]) -> Vec<LimitFit> {
    let im: Vec<f64> = levels.iter().map(|l| l.h13_m).collect();
    let n: Vec<u64> = levels.iter().map(|l| l.storms.len() as u64).collect();
    limits_m
        .iter()
        .enumerate()
        .map(|(j, &limit_m)| {
            let counts = |f: fn(&LevelResult) -> &Vec<u64>| levels.iter().map(|l| f(l)[j]).collect::<Vec<u64>>();
            LimitFit {
                limit_m,
                dynamic: fit_lognormal(&im, &counts(|l| &l.dynamic_exceedances), &n),
                rigid_block: fit_lognormal(&im, &counts(|l| &l.rigid_block_exceedances), &n),
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::loads::risetime::load_rng;
    use rand::Rng;

    /// The constructor refuses each bad value by itself, naming the quantity (a list's element
    /// by its index): at T1/3 = 12 s Miche's limit is 0.142 · 224.8 m = 31.9 m.
    #[test]
    fn fragility_params_name_what_they_refuse() {
        let p = FragilityParams {
            heights_m: vec![4.0, 31.0],
            storms: 10,
            limits_m: vec![0.1, 999.0],
            storm_duration_s: MAX_STORM_DURATION_S,
            period_s: 12.0,
            seed: 1,
            failure_rotation_rad: 0.01,
            duration: StormDuration::Fixed,
            direction: WaveDirection::HeadOn,
            periods: WavePeriods::Significant,
            errors: None,
        };
        assert_eq!(p.clone().checked(), Ok(p.clone()));
        let refused = |q: FragilityParams| q.checked().unwrap_err();
        let element = |q: FragilityParams| match q.checked() {
            Err(FragilityParamError::Element { index, error }) => (index, error.quantity),
            other => panic!("{other:?}"),
        };
        assert_eq!(element(FragilityParams { heights_m: vec![4.0, 32.0], ..p.clone() }), (1, "heights_m"));
        assert_eq!(element(FragilityParams { heights_m: vec![4.0, 4.0], ..p.clone() }), (1, "heights_m"));
        assert_eq!(element(FragilityParams { limits_m: vec![f64::NAN], ..p.clone() }), (0, "limits_m"));
        assert_eq!(element(FragilityParams { limits_m: vec![0.3, 1000.0], ..p.clone() }), (1, "limits_m"));
        assert_eq!(
            refused(FragilityParams { heights_m: vec![], ..p.clone() }),
            FragilityParamError::Empty { quantity: "heights_m" }
        );
        assert_eq!(
            refused(FragilityParams { limits_m: vec![1.0; 1001], ..p.clone() }),
            FragilityParamError::TooMany { quantity: "limits_m", count: 1001 }
        );
        let quantity = |q: FragilityParams| match q.checked() {
            Err(FragilityParamError::Param(e)) => e.quantity,
            other => panic!("{other:?}"),
        };
        assert_eq!(quantity(FragilityParams { period_s: 0.0, ..p.clone() }), "period_s");
        assert_eq!(quantity(FragilityParams { storms: 0, ..p.clone() }), "storms");
        // 10 heights × 10⁶ storms: 10⁷ storms are allowed, 10⁷ + 10⁶ are not.
        let heights_m: Vec<f64> = (1..=11).map(f64::from).collect();
        assert!(FragilityParams { heights_m: heights_m[..10].to_vec(), storms: 1_000_000, ..p.clone() }
            .checked()
            .is_ok());
        assert_eq!(quantity(FragilityParams { heights_m, storms: 1_000_000, ..p.clone() }), "storms");
        assert_eq!(quantity(FragilityParams { storm_duration_s: 0.0, ..p.clone() }), "storm_duration_s");
        assert_eq!(quantity(FragilityParams { failure_rotation_rad: 0.2, ..p.clone() }), "failure_rotation_rad");
        let duration = StormDuration::Lognormal { cov: 3.0 };
        assert_eq!(quantity(FragilityParams { duration, ..p }), "duration_cov");
    }

    fn exact_counts(im: &[f64], median: f64, beta: f64, n: u64) -> Vec<u64> {
        im.iter().map(|&x| (n as f64 * normal_cdf((x / median).ln() / beta)).round() as u64).collect()
    }

    #[test]
    fn recovers_the_curve_from_large_exact_counts() {
        let im: Vec<f64> = (0..10).map(|i| 1.0 + 0.5 * i as f64).collect();
        for (median, beta) in [(3.0, 0.3), (2.2, 0.15), (4.5, 0.5)] {
            let n = vec![100_000; im.len()];
            let k = exact_counts(&im, median, beta, 100_000);
            let f = fit_lognormal(&im, &k, &n).unwrap();
            // 1 % asked; the rounding of the counts to whole storms costs about 1e-5.
            assert!((f.median / median - 1.0).abs() < 1e-3, "θ = {} for {median}", f.median);
            assert!((f.beta / beta - 1.0).abs() < 1e-3, "β = {} for {beta}", f.beta);
            assert!((f.probability(median) - 0.5).abs() < 0.01);
        }
    }

    #[test]
    fn recovers_the_curve_from_sampled_counts_within_its_standard_errors() {
        let im: Vec<f64> = (0..8).map(|i| 2.0 + 0.5 * i as f64).collect();
        let (median, beta) = (3.5_f64, 0.25);
        for seed in 0..20 {
            let mut rng = load_rng(seed);
            let n = vec![200_u64; im.len()];
            let k: Vec<u64> = im
                .iter()
                .map(|&x| {
                    let p = normal_cdf((x / median).ln() / beta);
                    (0..200).filter(|_| rng.gen::<f64>() < p).count() as u64
                })
                .collect();
            let f = fit_lognormal(&im, &k, &n).unwrap();
            assert!(
                (f.median.ln() - median.ln()).abs() < 4.0 * f.ln_median_se,
                "seed {seed}: θ = {} ± {}",
                f.median,
                f.ln_median_se
            );
            assert!((f.beta - beta).abs() < 4.0 * f.beta_se, "seed {seed}: β = {} ± {}", f.beta, f.beta_se);
            assert!(f.ln_median_se < 0.05 && f.beta_se < 0.1, "standard errors {} {}", f.ln_median_se, f.beta_se);
        }
    }

    /// The profile-likelihood intervals against a brute-force profile: the log-likelihood on a
    /// 1201 × 1201 grid of (ln θ, ln β) around the maximum; the interval of ln θ is the range of
    /// grid ln θ whose best grid β comes within 1.9207 of the maximum (likewise for β). Counts of
    /// few storms (10 a height: a skewed likelihood, where θ̂ · exp(±1.96 SE) is not the
    /// interval). The ends agree within two grid spacings (the grid's resolution), and the
    /// interval of ln θ is not symmetric about ln θ̂ by more than the grid's resolution shows.
    #[test]
    fn the_profile_intervals_are_those_of_a_brute_force_profile() {
        let im = [1.0, 2.0, 3.0, 4.0, 5.0];
        let (k, n) = ([0, 2, 5, 9, 10], [10, 10, 10, 10, 10]);
        let f = fit_lognormal(&im, &k, &n).unwrap();
        let x: Vec<f64> = im.iter().map(|v: &f64| v.ln()).collect();
        let (a0, c0) = (f.median.ln(), f.beta.ln());
        let (half_a, half_c) = (1.5, 2.0);
        let m = 1201;
        let (da, dc) = (2.0 * half_a / (m - 1) as f64, 2.0 * half_c / (m - 1) as f64);
        let grid: Vec<Vec<f64>> = (0..m)
            .map(|i| {
                let a = a0 - half_a + i as f64 * da;
                (0..m).map(|j| -neg_log_likelihood(&x, &k, &n, a, (c0 - half_c + j as f64 * dc).exp())).collect()
            })
            .collect();
        let max = grid.iter().flatten().copied().fold(f64::NEG_INFINITY, f64::max);
        assert!((max - f.log_likelihood).abs() < 1e-3, "the grid holds the maximum: {max} vs {}", f.log_likelihood);
        let level = max - 3.841_458_820_694_124 / 2.0;
        let inside_a: Vec<usize> = (0..m).filter(|&i| grid[i].iter().any(|&l| l >= level)).collect();
        let inside_c: Vec<usize> = (0..m).filter(|&j| grid.iter().any(|row| row[j] >= level)).collect();
        let ends = |v: &[usize], lo: f64, d: f64| [lo + v[0] as f64 * d, lo + v[v.len() - 1] as f64 * d];
        let (ga, gc) = (ends(&inside_a, a0 - half_a, da), ends(&inside_c, c0 - half_c, dc));
        assert!(inside_a.len() > 10 && inside_a[0] > 0 && inside_a[inside_a.len() - 1] < m - 1, "bounded in the grid");
        assert!(inside_c.len() > 10 && inside_c[0] > 0 && inside_c[inside_c.len() - 1] < m - 1, "bounded in the grid");
        let [ma, mb] = f.median_ci95.map(|e| e.expect("closed").ln());
        let [ba, bb] = f.beta_ci95.map(|e| e.expect("closed").ln());
        for (got, want, d, what) in
            [(ma, ga[0], da, "θ low"), (mb, ga[1], da, "θ high"), (ba, gc[0], dc, "β low"), (bb, gc[1], dc, "β high")]
        {
            assert!((got - want).abs() <= 2.0 * d, "{what}: ln {got} against the grid's {want} (spacing {d})");
        }
        // The likelihood of 10 storms a height is skewed: the upper end of β lies further from β̂
        // than the lower one (by far more than the grid's spacing).
        assert!((bb - c0) - (c0 - ba) > 10.0 * dc, "β: {ba} {c0} {bb}");
    }

    /// Coverage: 400 sets of counts drawn from a known curve (θ = 3.5 m, β = 0.25, 6 heights of
    /// 20 storms; fixed seeds, so the test is deterministic): the 95 % profile intervals hold θ
    /// and β in 93-97 % of the fitted sets each (the binomial standard deviation of 400 trials at
    /// 95 % is 1.1 %: the band is ±2 of it, and a profile interval of such counts covers close to
    /// its nominal level; Pawitan 2001, §2.6).
    #[test]
    fn the_profile_intervals_cover_the_true_curve_at_their_level() {
        let im: Vec<f64> = (0..6).map(|i| 2.5 + 0.4 * i as f64).collect();
        let (median, beta) = (3.5_f64, 0.25);
        let (mut fitted, mut theta_in, mut beta_in) = (0, 0, 0);
        for seed in 0..400 {
            let mut rng = load_rng(1000 + seed);
            let n = vec![20_u64; im.len()];
            let k: Vec<u64> = im
                .iter()
                .map(|&x| {
                    let p = normal_cdf((x / median).ln() / beta);
                    (0..20).filter(|_| rng.gen::<f64>() < p).count() as u64
                })
                .collect();
            let Ok(f) = fit_lognormal(&im, &k, &n) else { continue };
            fitted += 1;
            let holds = |c: [Option<f64>; 2], v: f64| c[0].is_none_or(|lo| lo <= v) && c[1].is_none_or(|hi| v <= hi);
            theta_in += usize::from(holds(f.median_ci95, median));
            beta_in += usize::from(holds(f.beta_ci95, beta));
        }
        assert!(fitted >= 380, "{fitted} of 400 sets fitted");
        let (pt, pb) = (theta_in as f64 / fitted as f64, beta_in as f64 / fitted as f64);
        eprintln!("coverage of {fitted} fits: θ {pt:.3}, β {pb:.3}");
        assert!((0.93..=0.97).contains(&pt) && (0.93..=0.97).contains(&pb), "coverage θ {pt}, β {pb}");
    }

    #[test]
    fn the_maximum_is_a_maximum() {
        let im = [1.0, 2.0, 3.0, 4.0];
        let (k, n) = ([0, 3, 9, 10], [10, 10, 10, 10]);
        let f = fit_lognormal(&im, &k, &n).unwrap();
        let x: Vec<f64> = im.iter().map(|v: &f64| v.ln()).collect();
        let l0 = -neg_log_likelihood(&x, &k, &n, f.median.ln(), f.beta);
        assert!((l0 - f.log_likelihood).abs() < 1e-9);
        for (da, db) in [(1e-3, 0.0), (-1e-3, 0.0), (0.0, 1e-3), (0.0, -1e-3)] {
            assert!(-neg_log_likelihood(&x, &k, &n, f.median.ln() + da, f.beta + db) < l0);
        }
    }

    #[test]
    fn undetermined_counts_are_refused_with_a_reason() {
        let im = [1.0, 2.0, 3.0, 4.0];
        let n = [10, 10, 10, 10];
        assert_eq!(fit_lognormal(&im, &[0, 0, 0, 0], &n), Err(FitFailure::NoExceedance));
        assert_eq!(fit_lognormal(&im, &[10, 10, 10, 10], &n), Err(FitFailure::AllExceed));
        assert_eq!(fit_lognormal(&im, &[0, 0, 10, 10], &n), Err(FitFailure::Separated));
        assert_eq!(fit_lognormal(&im, &[0, 4, 10, 10], &n), Err(FitFailure::Separated));
        assert_eq!(fit_lognormal(&[2.0], &[4], &[10]), Err(FitFailure::Separated));
        // Decreasing probabilities: the constrained maximum is a flat curve, β at the bound.
        assert_eq!(fit_lognormal(&im, &[10, 10, 0, 0], &n), Err(FitFailure::AtBounds));
        assert_eq!(fit_lognormal(&im, &[9, 6, 3, 1], &n), Err(FitFailure::AtBounds));
        // Two mixed neighbours are enough.
        assert!(fit_lognormal(&im, &[0, 4, 7, 10], &n).is_ok());
        // Levels without trials are ignored.
        assert_eq!(fit_lognormal(&[1.0, 2.0], &[0, 0], &[0, 0]), Err(FitFailure::NoExceedance));
    }

    /// The storms of examples/fragility.toml, shortened to 30 min (141 waves).
    fn example() -> crate::scenario::Scenario {
        crate::scenario::load(&std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples/fragility.toml"))
            .unwrap()
    }

    #[test]
    fn storms_are_keyed_by_height_and_index_not_by_their_place_in_the_grid() {
        let sc = example();
        let case = sc.storm_case(true).unwrap();
        let base = FragilityParams {
            heights_m: vec![8.5, 10.5],
            storms: 3,
            storm_duration_s: 1800.0,
            ..sc.fragility_for("test").unwrap().clone()
        };
        // Heights added below, between and above, more storms; and one height run alone.
        let grown = FragilityParams { heights_m: vec![7.0, 8.5, 9.0, 10.5, 11.0], storms: 5, ..base.clone() };
        let alone = FragilityParams { heights_m: vec![10.5], storms: 2, ..base.clone() };
        let run = |p: &FragilityParams| run_fragility(&case, p, &|| {}).unwrap();
        let (a, g, one) = (run(&base), run(&grown), run(&alone));
        let mut compared = 0;
        for level in &a.levels {
            let other = g.levels.iter().find(|l| l.h13_m == level.h13_m).unwrap();
            assert_eq!(other.storms[..3], level.storms[..], "H1/3 = {} m", level.h13_m);
            compared += 3;
        }
        assert_eq!(one.levels[0].storms[..], a.levels[1].storms[..2]);
        compared += 2;
        assert_eq!(compared, 8);
        // The comparison is not of empty storms: the storms at 10.5 m slide, and differ.
        let top = &a.levels[1].storms;
        assert!(top.iter().all(|o| o.sliding_m.abs() > 1e-4), "{top:?}");
        assert!(top[0] != top[1] && top[1] != top[2]);
    }

    #[test]
    fn storm_streams_are_distinct_and_a_storm_stays_inside_its_words() {
        // Neighbouring heights (one ulp apart) and neighbouring storms draw different numbers.
        let h = 8.5_f64;
        let next = f64::from_bits(h.to_bits() + 1);
        let first = |h: f64, j: usize| storm_rng(1, h, j).gen::<u64>();
        let draws = [first(h, 0), first(next, 0), first(h, 1), first(h, 2), first(next, 1)];
        for i in 0..draws.len() {
            for k in i + 1..draws.len() {
                assert_ne!(draws[i], draws[k], "draws {i} and {k}");
            }
        }
        assert_ne!(first(h, 0), storm_rng(2, h, 0).gen::<u64>(), "the seed matters");
        // A storm of the example draws at most about 6 words per wave (only the waves above the
        // screen's threshold, and one more), far from the 2^40 it owns.
        let sc = example();
        let case = sc.storm_case(true).unwrap();
        let p = sc.fragility_for("test").unwrap();
        let input = p.storm_input(case.model, 11.0);
        let mut rng = storm_rng(p.seed, 11.0, 7);
        let start = rng.get_word_pos();
        let o = simulate_storm(&case, &input, &mut rng).unwrap();
        let words = rng.get_word_pos() - start;
        let waves = input.waves as u128;
        assert!(
            o.simulated_waves > 0 && words >= 6 * o.simulated_waves as u128 && words <= 7 * waves,
            "{words} words for {waves} waves, {} simulated",
            o.simulated_waves
        );
    }

    /// The load-model errors of a storm (docs/fragility.md): drawn per storm (the same storm the
    /// same, 200 storms not all alike, each within its truncation 1 + bias ± 2 COV) without
    /// moving its waves or climate: errors of zero bias and COV (multipliers 1) give every storm
    /// of two heights of the example the outcome of no errors, to the bit (12 storms, angles
    /// drawn too), and without errors every factor is 1.
    #[test]
    fn storms_draw_their_load_errors_apart_from_their_waves() {
        let sc = example();
        let case = sc.storm_case(true).unwrap();
        let mut p = sc.fragility_for("test").unwrap().clone();
        p.direction = WaveDirection::Uniform { mean_rad: 0.2, half_width_rad: 0.1 };
        let none = Errors { wave_force: ErrorModel::NONE, friction: ErrorModel::NONE, ..Errors::default() };
        let mut compared = 0;
        for h in [8.5, 10.0] {
            for j in 0..6 {
                let run = |errors: Option<Errors>| {
                    let p = FragilityParams { errors, ..p.clone() };
                    let s = p.storm_input_of(case.model, h, j);
                    (s, simulate_storm(&case, &s, &mut storm_rng(p.seed, h, j)).unwrap())
                };
                let ((a, oa), (b, ob)) = (run(None), run(Some(none)));
                assert_eq!((a.force_factor, a.friction_factor, a.impact_factor), (1.0, 1.0, 1.0));
                assert_eq!((a, oa), (b, ob), "H1/3 {h} m, storm {j}");
                compared += 1;
            }
        }
        assert_eq!(compared, 12);
        let p = FragilityParams { errors: Some(Errors::default()), ..p };
        let f: Vec<[f64; 3]> = (0..200)
            .map(|j| {
                let s = p.storm_input_of(case.model, 9.0, j);
                [s.force_factor, s.friction_factor, s.impact_factor]
            })
            .collect();
        assert!(f.iter().all(|x| (0.71..=1.11).contains(&x[0]) && (0.8..=1.2).contains(&x[1]) && x[2] == x[0]));
        assert!(f.windows(2).any(|w| w[0] != w[1]), "the storms draw their own errors");
        let again = p.storm_input_of(case.model, 9.0, 17);
        assert_eq!([again.force_factor, again.friction_factor, again.impact_factor], f[17]);
    }

    /// Lognormal durations (mean 2 h, COV 0.5) and uniform angles (20° ± 10°) over 4000 storms
    /// of one height: the waves per storm have the mean 7200 s / 11 s = 654.5 (within 5 standard
    /// errors, 327/√4000 = 5.2) and the angles the mean 20° (5 standard errors of 5.77°/√4000);
    /// each storm's own angle and duration, and the same storm the same.
    #[test]
    fn storms_draw_their_duration_and_angle() {
        let p = FragilityParams {
            heights_m: vec![4.0],
            storms: 4000,
            limits_m: vec![0.1],
            storm_duration_s: 7200.0,
            period_s: 11.0,
            periods: WavePeriods::Significant,
            errors: None,
            seed: 1,
            failure_rotation_rad: 0.01,
            duration: StormDuration::Lognormal { cov: 0.5 },
            direction: WaveDirection::Uniform { mean_rad: 20f64.to_radians(), half_width_rad: 10f64.to_radians() },
        };
        let sc = example();
        let model = sc.storm_case(true).unwrap().model;
        let s: Vec<StormInput> = (0..p.storms).map(|j| p.storm_input_of(model, 4.0, j)).collect();
        let n = s.len() as f64;
        let waves = s.iter().map(|x| x.waves as f64).sum::<f64>() / n;
        let angle = s.iter().map(|x| x.angle_rad.to_degrees()).sum::<f64>() / n;
        assert!((waves - 654.5).abs() < 5.0 * 327.0 / n.sqrt(), "{waves}");
        assert!((angle - 20.0).abs() < 5.0 * 5.77 / n.sqrt(), "{angle}");
        assert!(s.iter().all(|x| (10.0 - 1e-9..=30.0 + 1e-9).contains(&x.angle_rad.to_degrees())));
        assert_ne!(s[0].waves, s[1].waves);
        assert_eq!(p.storm_input_of(model, 4.0, 1), s[1]);
    }

    #[test]
    fn storms_follow_the_grid() {
        let p = FragilityParams {
            heights_m: vec![2.0, 4.0],
            storms: 3,
            limits_m: vec![0.1],
            storm_duration_s: 7200.0,
            period_s: 11.0,
            periods: WavePeriods::Significant,
            errors: None,
            seed: 1,
            failure_rotation_rad: 0.01,
            duration: StormDuration::Fixed,
            direction: WaveDirection::HeadOn,
        };
        let sc = example();
        let model = sc.storm_case(true).unwrap().model;
        assert_eq!(p.storm_input_of(model, 4.0, 2), p.storm_input(model, 4.0));
        let s = p.storm_input(model, 4.0);
        assert_eq!((s.h13_m, s.waves, s.tide_m, s.force_factor, s.friction_factor), (4.0, 655, 0.0, 1.0, 1.0));
        // H_max is at most 1.8 H1/3 = 7.2 m; at h = 20 m and T = 11 s Goda's breaking-limited
        // H_max of the H0' whose H1/3 is 4 m is a little lower (7.05 m, 1.76 H1/3).
        assert!(s.hmax_m <= 7.2 && s.hmax_m > 7.0, "H_max at H1/3 = 4 m: {}", s.hmax_m);
        // Inside the surf zone the storm's waves stop at Goda's breaking-limited H_max: at
        // H1/3 = 7.5 m, T = 12.8 s on the example's site (h = 20 m, tan θ = 1/100) it is the
        // 13.451 m of the hand calculation in tests/verify_goda_design.rs, not 1.8 × 7.5 = 13.5 m; at
        // 11 m it stays below the 20 m depth (1.8 × 11 = 19.8 m).
        let p128 = FragilityParams { period_s: 12.8, ..p.clone() };
        assert!((p128.storm_input(model, 7.5).hmax_m - 13.451).abs() < 1e-3, "{:?}", p128.storm_input(model, 7.5));
        let h11 = p128.storm_input(model, 11.0).hmax_m;
        assert!(h11 > 13.451 && h11 < 16.0, "H_max at H1/3 = 11 m: {h11} m");
        // The third storm ends seaward: it counts by its magnitude (signed, it would exceed no
        // limit above 0.05 m and the mean would be −0.05/3 m).
        let storms = [0.05, 0.1, -0.2].map(|v: f64| StormOutcome {
            sliding_m: v,
            rigid_block_sliding_m: 2.0 * v.abs(),
            waves: 10,
            screened_waves: 4,
            ..StormOutcome::default()
        });
        let level = StormInput { h13_m: 2.0, hmax_m: 3.6, ..s };
        let l = LevelResult::new(&level, storms.to_vec(), &[0.05, 0.1, 0.3], 0.01);
        assert_eq!((l.h13_m, l.hmax_m), (2.0, 3.6));
        assert_eq!(l.dynamic_exceedances, vec![2, 1, 0]);
        assert_eq!(l.rigid_block_exceedances, vec![3, 2, 1]);
        assert_eq!(l.rotation_failures, 0);
        assert!((l.mean_sliding_m() - 0.35 / 3.0).abs() < 1e-15);
        assert!((l.screened_share() - 0.4).abs() < 1e-15);
        // The first storm rotated 0.02 rad: it exceeds every limit of the dynamic model (not the
        // rigid block's); at the limit itself it does not count.
        let mut rotated = storms;
        rotated[0].max_rotation_rad = 0.02;
        rotated[1].max_rotation_rad = 0.01;
        let l = LevelResult::new(&level, rotated.to_vec(), &[0.05, 0.1, 0.3], 0.01);
        assert_eq!(l.dynamic_exceedances, vec![3, 2, 1]);
        assert_eq!(l.rigid_block_exceedances, vec![3, 2, 1]);
        assert_eq!(l.rotation_failures, 1);
    }
}
