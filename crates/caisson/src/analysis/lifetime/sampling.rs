//! Stratified sampling of the lives of a design run (`[design] sampling = "stratified"`;
//! docs/design.md, "Stratified sampling"): two-phase sampling for stratification (Neyman 1938;
//! Cochran 1977, §12.2), whose estimators are [`crate::analysis::stratified`].
//!
//! A life's answer (failed or not, |S|) is decided mostly by its worst storm, and a storm's
//! severity is known before a single wave is run: its storms come first in the life's stream and
//! do not depend on its waves ([`life_storms`]). So:
//!
//! 1. **Severity** of life i (the pool: every life of the run): s_i = max over its storms of
//!    H_max² F, H_max the largest wave height at the structure (with the transformation error) and
//!    F the wave-force error factor — the scale of the overturning moment of Goda's pressures
//!    (pressure ∝ H, lever ∝ H), over the [`RANKED_STORMS`] storms of the largest deep-water
//!    height (times the transformation error). It costs the storms' draws and three surf-zone
//!    solves: about 2 % of a life of the design example.
//! 2. **Strata** by severity: [`STRATA`] strata bounded by the [`STRATUM_QUANTILES`] of the
//!    severities of the first [`PILOT_LIVES`] lives of the stream (the same bounds for every run of
//!    the seed, whatever its count, shard or resume).
//! 3. **Second phase**: life i of stratum h is simulated if a uniform of its own
//!    ([`SELECTION_WORD`] of its stream: no other draw of the life moves) is below
//!    [`STRATUM_FRACTIONS`]\[h\]. A simulated life is the very life of a plain run of the same
//!    index, and which lives are simulated depends only on the seed and the index: any thread
//!    count, shard split or resume gives the same lives.
//!
//! Any severity gives unbiased estimates; a good one gives small ones' errors. The fractions keep
//! few of the lives that neither fail nor slide much (1 % of the lowest 60 %) and more of the
//! worse (40 % of the top 1 %; set on the design example, where simulating more of the top
//! strata costs more than it gains: their lives are the longest to run): on the design example the standard error of E|S| and of P(failure)
//! per CPU-second is 3-5 times smaller than by plain Monte Carlo (BENCHMARKS.md), on the sizing
//! example's required width 10 times. Statistics of the mild lives (the heel pressure's exceedance,
//! often reached by most lives) get wider intervals than by plain sampling of as many lives.

use super::life::{life_storms, StormDraw};
use super::params::{LifeParams, StormCase};
use crate::analysis::stratified::TwoPhase;
use crate::loads::generator::realization_rng;
use crate::waves::surf_zone::SlopeTerms;
use rand::Rng;
use rayon::prelude::*;
use std::cell::RefCell;
use std::ops::Range;

/// Strata of the severity.
pub const STRATA: usize = 6;
/// The upper bounds of the strata but the last, as quantiles of the pilot's severities.
pub const STRATUM_QUANTILES: [f64; STRATA - 1] = [0.6, 0.8, 0.9, 0.96, 0.99];
/// The share of each stratum's lives simulated, lowest first.
pub const STRATUM_FRACTIONS: [f64; STRATA] = [0.01, 0.03, 0.1, 0.2, 0.3, 0.4];
/// The share of a pool the sample simulates on average: Σ_h (q_h − q_{h−1}) f_h over the strata's
/// quantile bounds, 4.7 %.
pub fn expected_share() -> f64 {
    let mut lower = 0.0;
    let mut share = 0.0;
    for (h, f) in STRATUM_FRACTIONS.iter().enumerate() {
        let upper = STRATUM_QUANTILES.get(h).copied().unwrap_or(1.0);
        share += (upper - lower) * f;
        lower = upper;
    }
    share
}

/// The lives of a pool of `lives` the work estimate counts: the expected sample, times 2.5 — the
/// top strata's lives are the costliest (on the design example 1.4 ms a life against 0.55 ms on
/// average, BENCHMARKS.md), and the pilot that estimates the cost of a life runs plain lives.
pub fn work_lives(lives: usize) -> usize {
    ((lives as f64 * expected_share() * 2.5).ceil() as usize).clamp(1, lives.max(1))
}

/// The storms of a life whose heights at the structure rank it ([`severity`]).
pub const RANKED_STORMS: usize = 3;
/// Lives 0..PILOT_LIVES of the stream set the strata's bounds.
pub const PILOT_LIVES: usize = 2000;
/// The word of a life's stream its selection uniform comes from: 2^66, beyond every storm's waves
/// (storm k's start at word k · 2^40: a life would need 2^26 storms to reach it).
pub const SELECTION_WORD: u128 = 1 << 66;

/// The severity s_i of life `index` (module docs): max over its storms of H_max² F, m², of its
/// [`RANKED_STORMS`] storms of the largest deep-water height times the transformation error (the
/// others' surf-zone heights are not computed: the ranking is any function of the life's draws).
pub fn severity(st: &StormCase<'_>, p: &LifeParams, seed: u64, index: usize) -> f64 {
    thread_local! {
        static STORMS: RefCell<Vec<StormDraw>> = const { RefCell::new(Vec::new()) };
    }
    STORMS.with_borrow_mut(|storms| {
        life_storms(p, seed, index, storms);
        let key = |d: &StormDraw| d.h0_m * d.errors.transformation;
        let ranked = RANKED_STORMS.min(storms.len());
        if ranked > 0 && ranked < storms.len() {
            storms.select_nth_unstable_by(ranked - 1, |a, b| key(b).total_cmp(&key(a)));
        }
        let slope = SlopeTerms::new(st.model.site.seabed_slope);
        storms[..ranked]
            .iter()
            .map(|d| {
                let s = d.at_structure(st, p, &slope).0;
                s.hmax_m * s.hmax_m * s.force_factor
            })
            .fold(0.0, f64::max)
    })
}

/// The strata of a seed's lives: their severity bounds and the shares simulated.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Strata {
    /// The upper severity bound of each stratum but the last, m².
    pub upper_m2: [f64; STRATA - 1],
    pub fractions: [f64; STRATA],
}

impl Strata {
    /// The strata of the lives of `seed` (module docs, 2): the pilot's severities on rayon's
    /// current pool.
    pub fn pilot(st: &StormCase<'_>, p: &LifeParams, seed: u64) -> Self {
        let mut s: Vec<f64> = (0..PILOT_LIVES).into_par_iter().map(|i| severity(st, p, seed, i)).collect();
        s.sort_by(f64::total_cmp);
        // Nearest-rank quantiles.
        let at = |q: f64| s[((q * PILOT_LIVES as f64).ceil() as usize).clamp(1, PILOT_LIVES) - 1];
        Strata { upper_m2: STRATUM_QUANTILES.map(at), fractions: STRATUM_FRACTIONS }
    }

    /// The stratum of a severity.
    pub fn stratum(&self, severity: f64) -> usize {
        self.upper_m2.iter().take_while(|&&u| severity > u).count()
    }

    /// Whether life `index` of `seed`, of stratum `h`, is simulated (module docs, 3).
    pub fn selected(&self, seed: u64, index: usize, h: usize) -> bool {
        let mut rng = realization_rng(seed, index);
        rng.set_word_pos(SELECTION_WORD);
        rng.gen::<f64>() < self.fractions[h]
    }
}

/// The lives of a range of the pool: how many of each stratum, and those simulated with their
/// stratum, in index order.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Pool {
    pub counts: [usize; STRATA],
    pub selected: Vec<(usize, usize)>,
}

impl Pool {
    /// The lives `range` of `seed` under `strata`, on rayon's current pool.
    pub fn of(st: &StormCase<'_>, p: &LifeParams, seed: u64, strata: &Strata, range: Range<usize>) -> Self {
        let each: Vec<(usize, bool)> = range
            .clone()
            .into_par_iter()
            .map(|i| {
                let h = strata.stratum(severity(st, p, seed, i));
                (h, strata.selected(seed, i, h))
            })
            .collect();
        let mut pool = Pool::default();
        for (i, (h, kept)) in range.zip(each) {
            pool.counts[h] += 1;
            if kept {
                pool.selected.push((i, h));
            }
        }
        pool
    }

    /// The pool of this range followed by `next`'s (the range just after it): the pool of the
    /// two ranges, as [`Self::of`] gives it of their union (each life's stratum and selection
    /// are its own).
    pub fn append(&mut self, next: Pool) {
        for (c, n) in self.counts.iter_mut().zip(next.counts) {
            *c += n;
        }
        self.selected.extend(next.selected);
    }

    /// The simulated lives' indices.
    pub fn indices(&self) -> Vec<usize> {
        self.selected.iter().map(|&(i, _)| i).collect()
    }

    /// The estimator of the pool's simulated lives ([`TwoPhase`]), `strata`'s fractions.
    pub fn estimator(&self, strata: &Strata) -> TwoPhase {
        let kept: Vec<(usize, f64)> = self.selected.iter().map(|&(_, h)| (h, strata.fractions[h])).collect();
        TwoPhase::new(&self.counts, &kept)
    }
}
