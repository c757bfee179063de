//! The design driver of `caisson design`, `caisson merge`, the validation report and Python's
//! `Design` (docs/design.md): a scenario with `[design]` and `[waves]` in, the lives and their
//! [`DesignReport`] out.
//!
//! A design run is the scenario's `[design]` ([`DesignParams`]) and the storms' case of its
//! caisson and site ([`crate::scenario::Scenario::storm_case`], with the screen of `[design]`);
//! [`Designer`] assembles them once, so that every front-end runs, fingerprints, estimates and
//! reports the same run: lives by [`run_lives`] (each depends only on the seed and its index, so
//! any subset in any order on any thread count gives the same lives), the fingerprint of what a
//! life depends on ([`design_fingerprint`], the checkpoint's header), the work estimate of
//! [`crate::analysis::work::design`] and the report of [`DesignReport::new`]. The front-ends keep
//! what is theirs: the checkpoint file, the progress, stopping, the outputs.
//!
//! **Lives to a target precision** (`[design] lives = "auto"`, [`AutoLives`]; docs/design.md):
//! [`Designer::run_auto`] runs lives in batches of
//! [`AUTO_BATCH_LIVES`](crate::analysis::lifetime::AUTO_BATCH_LIVES) in index order and stops
//! at the first batch boundary k where the rule, read from the report's statistics of lives 0..k
//! ([`DesignReport::judge`]), is met, or at the budget (`max_lives`, the design's `lives`). A
//! stopping point depends only on lives 0..k, so threads, resumes and shards find the same one;
//! shards run fixed ranges, and [`Designer::stopping_point`] applies the rule over the boundaries
//! of the lives they hold, in order (what `caisson merge` does). The report of lives 0..k carries
//! the rule's verdict ([`DesignReport::precision`]) and, if the budget ran out first, the
//! `precision-not-met` warning. A stratified run (`sampling = "stratified"`) batches its pool: each
//! batch's pool appended ([`Pool::append`]) and its sample simulated, the rule reading the weighted
//! estimates ([`Designer::judge_sampled`]).

use crate::analysis::checks::precision_warning;
use crate::analysis::lifetime::sampling::{Pool, Strata};
use crate::analysis::lifetime::{
    auto_boundaries, run_lives, AutoLives, AutoPrecision, DesignParams, FailureLimits, LifeFailed, Sampling, StormCase,
    StormOutcome,
};
use crate::analysis::site::WaveSetup;
use crate::analysis::work::{self, WorkEstimate};
use crate::dynamics::Stepping;
use crate::report::design::{design_fingerprint, DesignReport};
use crate::scenario::{Scenario, ScenarioError};
use std::collections::BTreeMap;
use std::ops::{ControlFlow, Range};

/// How a design run departs from the scenario's `[design]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct DesignOptions {
    /// The number of lives (the CLI's `--lives`, a merge's lives): exactly these, `lives =
    /// "auto"` turned off; `None`: `[design] lives`.
    pub lives: Option<usize>,
    /// Every wave through the dynamic model (no screen), on a scenario made by [`brute_force`].
    pub brute_force: bool,
}

/// The scenario of a brute-force design run (`--brute-force`): every step at the fixed step dt_s
/// ([`Stepping::Fixed`]); its [`Designer`] takes [`DesignOptions::brute_force`].
pub fn brute_force(sc: Scenario) -> Result<Scenario, ScenarioError> {
    let solver = crate::dynamics::SolverParams { stepping: Stepping::Fixed, ..sc.solver() };
    sc.with_solver(solver)
}

/// The lives a stratified run simulates: its strata and its pool.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    pub strata: Strata,
    pub pool: Pool,
}

/// A design run of a scenario: its `[design]` (with the options applied) and the storms' case.
#[derive(Debug, Clone)]
pub struct Designer<'a> {
    pub design: DesignParams,
    pub case: StormCase<'a>,
    pub waves: &'a WaveSetup,
}

impl<'a> Designer<'a> {
    /// The design run of `sc` (`what` names the front-end in the error of a file without
    /// `[design]`): refused as [`Scenario::design_for`], then [`Scenario::storm_case`] refuse.
    pub fn new(sc: &'a Scenario, what: &str, options: DesignOptions) -> Result<Self, ScenarioError> {
        let mut design = sc.design_for(what)?.clone();
        if let Some(n) = options.lives {
            // 1 to 1e7 (checked by the parser, as `[design] lives`).
            design.lives = n;
            design.auto = None;
        }
        if options.brute_force {
            design.screen = false;
        }
        let case = sc.storm_case(design.screen)?;
        let waves = sc.waves_for(what)?;
        Ok(Designer { design, case, waves })
    }

    /// What every life depends on (a checkpoint's header holds it).
    pub fn fingerprint(&self) -> String {
        design_fingerprint(&self.case, &self.design)
    }

    /// The work of `lives` lives of this run (a shard's, or the run's own count; a stratified
    /// run's of the lives it simulates, [`crate::analysis::lifetime::sampling::work_lives`]).
    pub fn estimate(&self, lives: usize) -> WorkEstimate {
        let lives = match self.design.sampling {
            Sampling::Stratified => crate::analysis::lifetime::sampling::work_lives(lives),
            Sampling::Plain => lives,
        };
        work::design(&self.case, &DesignParams { lives, ..self.design.clone() }, self.waves)
    }

    /// The failure limits of the run's caisson.
    pub fn failure_limits(&self) -> FailureLimits {
        self.design.failure_limits(self.case.structure.caisson.width_m)
    }

    /// Simulate the lives `indices` on rayon's current pool ([`run_lives`]: `on_life` sees each
    /// finished life and may stop the run).
    pub fn run(
        &self,
        indices: &[usize],
        on_life: &(dyn Fn(usize, &StormOutcome) -> ControlFlow<()> + Sync),
    ) -> Result<Vec<(usize, StormOutcome)>, LifeFailed> {
        run_lives(&self.case, &self.design.life, self.design.seed, indices, on_life)
    }

    /// The report of `lives` (lives 0..N in index order): statistics, the model and the warnings;
    /// with `lives = "auto"` the rule's verdict on them and, if not met, its warning.
    pub fn report(&self, lives: &[StormOutcome]) -> DesignReport {
        let mut r = DesignReport::new(&self.design, &self.case, Some(self.waves), lives);
        if let Some(auto) = &self.design.auto {
            let p = r.judge(auto, self.design.lives);
            r.precision = Some(p);
            r.warnings.extend(precision_warning(&p, "the design run"));
        }
        r
    }

    /// A stratified run's strata and its pool of the lives `range` ([`crate::analysis::lifetime::sampling`],
    /// on rayon's current pool); `None` for a plain run (every life simulated).
    pub fn sample(&self, range: Range<usize>) -> Option<Sample> {
        (self.design.sampling == Sampling::Stratified).then(|| self.sample_of(range))
    }

    /// The strata and the pool of `range` whatever `[design] sampling` says (the tests compare a
    /// stratified estimate with a plain one on the same lives).
    pub fn sample_of(&self, range: Range<usize>) -> Sample {
        let strata = Strata::pilot(&self.case, &self.design.life, self.design.seed);
        let pool = Pool::of(&self.case, &self.design.life, self.design.seed, &strata, range);
        Sample { strata, pool }
    }

    /// The lives of `range` to simulate: the sample's, or every one.
    pub fn to_simulate(&self, range: Range<usize>, sample: Option<&Sample>) -> Vec<usize> {
        sample.map_or_else(|| range.collect(), |s| s.pool.indices())
    }

    /// The report of the simulated `lives` (in index order) of a run sampled by `sample`
    /// ([`DesignReport::stratified`]), or of every life ([`Self::report`]).
    pub fn report_sampled(&self, lives: &[StormOutcome], sample: Option<&Sample>) -> DesignReport {
        match sample {
            Some(s) => {
                let mut r =
                    DesignReport::stratified(&self.design, &self.case, Some(self.waves), lives, &s.strata, &s.pool);
                if let Some(p) = self.judge_sampled(lives, s) {
                    r.precision = Some(p);
                    r.warnings.extend(precision_warning(&p, "the design run"));
                }
                r
            }
            None => self.report(lives),
        }
    }

    /// The statistics of `lives` alone ([`DesignReport::statistics`]: no model, no warnings;
    /// with `lives = "auto"` the rule's verdict).
    pub fn statistics(&self, lives: &[StormOutcome]) -> DesignReport {
        let failure_m = self.failure_limits().sliding_m;
        let mut r = DesignReport::statistics(&self.design, self.case.rigid_block_mu, failure_m, lives);
        r.precision = self.design.auto.map(|auto| r.judge(&auto, self.design.lives));
        r
    }

    /// The rule of `lives = "auto"` on lives 0..n (`lives`, in index order): the verdict of the
    /// report's statistics ([`DesignReport::judge`]); `None` with a fixed number of lives.
    pub fn judge(&self, lives: &[StormOutcome]) -> Option<AutoPrecision> {
        let failure_m = self.failure_limits().sliding_m;
        let auto = self.design.auto?;
        let r = DesignReport::statistics(&self.design, self.case.rigid_block_mu, failure_m, lives);
        Some(r.judge(&auto, self.design.lives))
    }

    /// The rule of `lives = "auto"` on the simulated `lives` (in index order) of a stratified run
    /// sampled by `s` (its pool, lives 0..k): the weighted E|S| with its two-phase standard error
    /// and the weighted P(failure) with its standard error and Wilson interval at the effective
    /// size ([`AutoLives::judge_estimates`]); `lives` counts the pool. `None` with a fixed number
    /// of lives.
    pub fn judge_sampled(&self, lives: &[StormOutcome], s: &Sample) -> Option<AutoPrecision> {
        let auto = self.design.auto?;
        let failure_m = self.failure_limits().sliding_m;
        let r = DesignReport::stratified_statistics(
            &self.design,
            self.case.rigid_block_mu,
            failure_m,
            lives,
            &s.strata,
            &s.pool,
        );
        let failed: Vec<bool> = lives.iter().map(StormOutcome::failed).collect();
        let failure = s.pool.estimator(&s.strata).proportion(&failed);
        let es = &r.dynamic.sliding;
        let mean = (es.expected_sliding_m, es.expected_sliding_standard_error_m);
        Some(auto.judge_estimates(mean, &failure, r.lives, self.design.lives))
    }

    /// [`Self::judge`] of a plain run, [`Self::judge_sampled`] of a stratified one.
    fn judge_of(&self, lives: &[StormOutcome], sample: Option<&Sample>) -> Option<AutoPrecision> {
        match sample {
            Some(s) => self.judge_sampled(lives, s),
            None => self.judge(lives),
        }
    }

    /// The strata of a stratified run, its pool empty (lives 0..0); `None` for a plain run.
    fn empty_sample(&self) -> Option<Sample> {
        (self.design.sampling == Sampling::Stratified).then(|| Sample {
            strata: Strata::pilot(&self.case, &self.design.life, self.design.seed),
            pool: Pool::default(),
        })
    }

    /// The lives `start..k` of a batch that the run simulates: every one, or (stratified) the
    /// batch's pool's sample, the pool appended to `sample`'s.
    fn batch(&self, start: usize, k: usize, sample: Option<&mut Sample>) -> Vec<usize> {
        match sample {
            Some(s) => {
                let pool = Pool::of(&self.case, &self.design.life, self.design.seed, &s.strata, start..k);
                let indices = pool.indices();
                s.pool.append(pool);
                indices
            }
            None => (start..k).collect(),
        }
    }

    /// Where `lives = "auto"` stops on the lives `held` (any indices, e.g. the shards' of a
    /// merge): the first batch boundary k, over the boundaries whose lives 0..k that the run
    /// simulates (every one, or a stratified run's sample) are all held, in order, at which the
    /// rule is met, or the budget's end. `None` with a fixed number of lives.
    pub fn stopping_point(&self, held: &BTreeMap<usize, StormOutcome>) -> Option<Stopping> {
        self.design.auto?;
        let mut sample = self.empty_sample();
        let mut lives: Vec<StormOutcome> = Vec::new();
        let mut start = 0;
        for k in auto_boundaries(self.design.lives) {
            for i in self.batch(start, k, sample.as_mut()) {
                match held.get(&i) {
                    Some(o) => lives.push(*o),
                    None => return Some(Stopping::NotReached { missing: i, last_boundary: start }),
                }
            }
            start = k;
            let p = self.judge_of(&lives, sample.as_ref()).expect("auto");
            if p.met || k == self.design.lives {
                return Some(Stopping::At(k, p, sample.map(Box::new)));
            }
        }
        unreachable!("the last boundary is the budget")
    }

    /// `lives = "auto"` (module docs): batch after batch, the lives not in `done` run
    /// ([`Self::run`], `on_life` sees each and may stop the run), until the rule is met on lives
    /// 0..k or the budget is spent. With a fixed number of lives, the batches run to `lives`
    /// without the rule.
    pub fn run_auto(
        &self,
        done: &BTreeMap<usize, StormOutcome>,
        on_life: &(dyn Fn(usize, &StormOutcome) -> ControlFlow<()> + Sync),
    ) -> Result<AutoRun, LifeFailed> {
        let mut sample = self.empty_sample();
        let mut computed: Vec<(usize, StormOutcome)> = Vec::new();
        let mut lives: Vec<StormOutcome> = Vec::new();
        let mut start = 0;
        for k in auto_boundaries(self.design.lives) {
            let batch = self.batch(start, k, sample.as_mut());
            let todo: Vec<usize> = batch.iter().copied().filter(|i| !done.contains_key(i)).collect();
            let ran = self.run(&todo, on_life)?;
            let stopped = ran.len() < todo.len();
            let mut ran = ran.into_iter().peekable();
            for i in batch {
                match done.get(&i) {
                    Some(o) => lives.push(*o),
                    None => {
                        if let Some(&(_, o)) = ran.peek().filter(|(j, _)| *j == i) {
                            lives.push(o);
                            computed.push(ran.next().expect("peeked"));
                        }
                    }
                }
            }
            computed.extend(ran);
            if stopped {
                return Ok(AutoRun::Stopped { computed });
            }
            start = k;
            let precision = self.judge_of(&lives, sample.as_ref());
            if k == self.design.lives || precision.is_some_and(|p| p.met) {
                return Ok(AutoRun::Done { lives, computed, precision, sample: sample.map(Box::new) });
            }
        }
        unreachable!("the last boundary is the budget")
    }
}

/// Where `lives = "auto"` stops on the lives a merge holds ([`Designer::stopping_point`]).
#[derive(Debug, Clone, PartialEq)]
pub enum Stopping {
    /// At lives 0..k, with the rule's verdict there (met, or the budget's end) and, for a
    /// stratified run, its sample of lives 0..k (the lives simulated are its pool's).
    At(usize, AutoPrecision, Option<Box<Sample>>),
    /// Life `missing` (of the lives the run simulates) is not held and the rule is met at no
    /// boundary up to `last_boundary`, where the lives held end: the lives from there are needed.
    NotReached { missing: usize, last_boundary: usize },
}

/// What [`Designer::run_auto`] ran.
#[derive(Debug, Clone, PartialEq)]
pub enum AutoRun {
    /// The lives of 0..k the run simulates (every one, or a stratified run's sample of them;
    /// those of `done` and those run, in index order), the lives this call ran (index, outcome),
    /// the rule's verdict at k and, for a stratified run, its sample of lives 0..k.
    Done {
        lives: Vec<StormOutcome>,
        computed: Vec<(usize, StormOutcome)>,
        precision: Option<AutoPrecision>,
        sample: Option<Box<Sample>>,
    },
    /// `on_life` stopped the run: the lives it ran before it stopped.
    Stopped { computed: Vec<(usize, StormOutcome)> },
}

impl Designer<'_> {
    /// The rule's target, if `lives = "auto"`.
    pub fn auto(&self) -> Option<AutoLives> {
        self.design.auto
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::lifetime::AUTO_BATCH_LIVES;
    use std::path::Path;

    /// The small design of the tests' data.
    fn small_design() -> Scenario {
        let text = include_str!("../../tests/data/small_design.toml");
        Scenario::from_toml(text, Path::new("small.toml"), Path::new(".")).expect("the small design")
    }

    /// The designer assembles what the front-ends assembled by hand (`design_for` + `storm_case`
    /// with the design's screen): the same fingerprint, lives and report; `lives` replaces the
    /// count only, and the brute force turns the screen off (so the fingerprint changes).
    #[test]
    fn the_designer_is_the_run_assembled_by_hand() {
        let sc = small_design();
        let design = sc.design_for("test").unwrap().clone();
        let case = sc.storm_case(design.screen).unwrap();
        let run = Designer::new(&sc, "test", DesignOptions::default()).unwrap();
        assert_eq!(run.design, design);
        assert_eq!(run.fingerprint(), design_fingerprint(&case, &design));
        let indices = [2, 0];
        let by_hand = run_lives(&case, &design.life, design.seed, &indices, &|_, _| ControlFlow::Continue(())).unwrap();
        let lives = run.run(&indices, &|_, _| ControlFlow::Continue(())).unwrap();
        assert_eq!(lives, by_hand);
        assert_eq!(lives.len(), 2, "two lives compared");
        let outcomes: Vec<StormOutcome> = lives.iter().map(|(_, o)| *o).collect();
        let report = |r: DesignReport| serde_json::to_string(&r).unwrap();
        assert_eq!(
            report(run.report(&outcomes)),
            report(DesignReport::new(&design, &case, sc.waves.as_ref(), &outcomes))
        );

        let more = Designer::new(&sc, "test", DesignOptions { lives: Some(7), brute_force: false }).unwrap();
        assert_eq!(more.design, DesignParams { lives: 7, ..design.clone() });
        assert_eq!(more.fingerprint(), run.fingerprint(), "the count is not in the fingerprint");
        let brute = Designer::new(&sc, "test", DesignOptions { lives: None, brute_force: true }).unwrap();
        assert!(!brute.design.screen && !brute.case.screen);
        assert_ne!(brute.fingerprint(), run.fingerprint());
    }

    /// The rule of `lives = "auto"` by hand (t = 0.05, floor 10⁻³), 7 verdicts:
    /// - E|S| 0.4 m, SE 0.02 m: 0.02/0.4 = 0.05 ≤ 0.05, met; SE 0.0201: 0.05025, not;
    /// - 400 failures of 4000 (p = 0.1): √((1 − p)/k) = √(0.9/400) = 0.047434 ≤ 0.05, met; 300 of
    ///   3000: √(0.9/300) = 0.054772, not;
    /// - no failure of 3000: Wilson upper z²/(n + z²) = 3.841459/3003.841459 = 1.27885e-3 ≥ 10⁻³,
    ///   not; of 4000: 3.841459/4003.841459 = 9.59443e-4 < 10⁻³, met (relative error null);
    /// - every life at 0 (E|S| = 0, SE = 0): relative error 0, met.
    #[test]
    fn the_rule_of_auto_lives_by_hand() {
        let auto = AutoLives { target_relative_error: 0.05 };
        let p = auto.judge((0.4, 0.02), 400, 4000, 10_000);
        assert!(p.expected_sliding_met && p.failure_met && p.met, "{p:?}");
        assert!((p.expected_sliding_relative_error - 0.05).abs() < 1e-15);
        assert!((p.failure_relative_error.unwrap() - 0.047_434_164).abs() < 1e-9, "{p:?}");
        assert!(!auto.judge((0.4, 0.0201), 400, 4000, 10_000).expected_sliding_met);
        let p = auto.judge((0.4, 0.02), 300, 3000, 10_000);
        assert!((p.failure_relative_error.unwrap() - 0.054_772_256).abs() < 1e-9 && !p.failure_met && !p.met, "{p:?}");
        let p = auto.judge((0.4, 0.02), 0, 3000, 10_000);
        assert_eq!(p.failure_relative_error, None);
        assert!((p.failure_probability_upper - 1.278_85e-3).abs() < 1e-8 && !p.failure_met, "{p:?}");
        let p = auto.judge((0.4, 0.02), 0, 4000, 10_000);
        assert!((p.failure_probability_upper - 9.594_43e-4).abs() < 1e-9 && p.failure_met && p.met, "{p:?}");
        let p = auto.judge((0.0, 0.0), 0, 4000, 10_000);
        assert_eq!(p.expected_sliding_relative_error, 0.0);
        assert!(p.met, "{p:?}");
        assert_eq!((p.lives, p.max_lives, p.batch_lives), (4000, 10_000, AUTO_BATCH_LIVES));
        assert!(AutoLives { target_relative_error: 0.0 }.checked().is_err());
        assert!(AutoLives { target_relative_error: 0.51 }.checked().is_err());
        assert_eq!(auto_boundaries(1200).collect::<Vec<_>>(), [500, 1000, 1200]);
    }

    /// Where "auto" stops on lives made by hand (t = 0.1; the small design's limit B/4 = 5 m):
    /// the surviving lives |S| alternately 0.5 and 1.5 m, a failed life (by sliding, 6 m) every
    /// 10th life of 0..500 (50) and every 10th plus lives 501, 503, ..., 519 (60) of 500..1000.
    /// At 500: √((1 − 0.1)/50) = 0.1342 > 0.1, not met. At 1000: k = 110, p = 0.11,
    /// √(0.89/110) = 0.08995 ≤ 0.1; E|S| (failed at 5 m) has the relative error 0.03 < 0.1 (the
    /// capped values' SE over their mean, checked below by hand from the values): met, the run
    /// stops at 1000. With life 700 missing the held lives end at 700 and no boundary up to 500
    /// meets it; with a budget of 700 the rule stops at 700 (k = 50 + 20 + 10 = 80, p = 0.1143,
    /// √(0.8857/80) = 0.1052 > 0.1), not met, and the report warns.
    #[test]
    fn auto_stops_at_the_first_boundary_where_the_rule_is_met() {
        let sc = small_design();
        let mut run = Designer::new(&sc, "test", DesignOptions::default()).unwrap();
        run.design.auto = Some(AutoLives { target_relative_error: 0.1 });
        run.design.lives = 2000;
        assert_eq!(run.failure_limits().sliding_m, 5.0);
        let life = |i: usize| {
            let failed = i.is_multiple_of(10) || ((500..520).contains(&i) && !i.is_multiple_of(2));
            let s = if failed {
                6.0
            } else if i.is_multiple_of(2) {
                0.5
            } else {
                1.5
            };
            StormOutcome { sliding_m: s, failed_by_sliding: u64::from(failed), ..StormOutcome::default() }
        };
        let held: BTreeMap<usize, StormOutcome> = (0..1500).map(|i| (i, life(i))).collect();
        let lives: Vec<StormOutcome> = held.values().copied().collect();
        let p500 = run.judge(&lives[..500]).unwrap();
        assert!((p500.failure_relative_error.unwrap() - (0.9f64 / 50.0).sqrt()).abs() < 1e-12 && !p500.met, "{p500:?}");
        let Some(Stopping::At(k, p, None)) = run.stopping_point(&held) else { panic!("a stopping point") };
        assert_eq!(k, 1000);
        assert!((p.failure_relative_error.unwrap() - (0.89f64 / 110.0).sqrt()).abs() < 1e-12 && p.met, "{p:?}");
        // E|S| by hand from the capped values of lives 0..1000.
        let capped: Vec<f64> = lives[..1000].iter().map(|l| if l.failed() { 5.0 } else { l.sliding_m }).collect();
        let mean = capped.iter().sum::<f64>() / 1000.0;
        let var = capped.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / 999.0;
        let rel = (var / 1000.0).sqrt() / mean;
        assert!((p.expected_sliding_relative_error - rel).abs() < 1e-12 && rel < 0.1, "{rel} {p:?}");
        // The report of lives 0..k says the same.
        assert_eq!(run.statistics(&lives[..1000]).precision, Some(p));
        let mut gap = held.clone();
        gap.remove(&700);
        assert_eq!(run.stopping_point(&gap), Some(Stopping::NotReached { missing: 700, last_boundary: 500 }));
        run.design.lives = 700;
        let Some(Stopping::At(k, p, None)) = run.stopping_point(&held) else { panic!("the budget's end") };
        assert_eq!((k, p.met, p.max_lives), (700, false, 700));
        assert!((p.failure_relative_error.unwrap() - ((1.0 - 80.0 / 700.0) / 80.0f64).sqrt()).abs() < 1e-12);
        let r = run.report(&lives[..700]);
        assert!(r.warnings.iter().any(|w| w.code == "precision-not-met"), "{:?}", r.warnings);
        run.design.auto = None;
        assert_eq!(run.stopping_point(&held), None);
    }

    /// A stratified `lives = "auto"` run (t = 0.3, a budget of 3000 lives): batch by batch the
    /// pool of lives 0..k is the pool `Pool::of` gives of 0..k at once, the lives simulated are
    /// its sample's, the run stops at the first boundary where the rule on the weighted
    /// estimates is met (checked at every boundary up to it), and `stopping_point` on the lives
    /// it ran finds the same k, verdict and sample.
    #[test]
    fn stratified_auto_stops_where_the_weighted_estimates_meet_the_target() {
        let sc = small_design();
        let mut run = Designer::new(&sc, "test", DesignOptions::default()).unwrap();
        run.design.sampling = Sampling::Stratified;
        run.design.auto = Some(AutoLives { target_relative_error: 0.3 });
        run.design.lives = 3000;
        let AutoRun::Done { lives, computed, precision: Some(p), sample: Some(sample) } =
            run.run_auto(&BTreeMap::new(), &|_, _| ControlFlow::Continue(())).unwrap()
        else {
            panic!("a stratified run to its stopping point")
        };
        let k: usize = sample.pool.counts.iter().sum();
        assert_eq!(*sample, run.sample_of(0..k));
        assert_eq!(computed.iter().map(|(i, _)| *i).collect::<Vec<_>>(), sample.pool.indices());
        assert_eq!(lives, computed.iter().map(|(_, o)| *o).collect::<Vec<_>>());
        assert!(p.met && p.lives == k && k > AUTO_BATCH_LIVES && k < 3000, "{p:?}");
        let mut checked = 0;
        for b in auto_boundaries(3000).take_while(|&b| b < k) {
            let earlier = run.sample_of(0..b);
            let held: Vec<StormOutcome> =
                earlier.pool.indices().iter().map(|i| lives[sample.pool.indices().binary_search(i).unwrap()]).collect();
            assert!(!run.judge_sampled(&held, &earlier).unwrap().met, "met at {b} already");
            checked += 1;
        }
        assert_eq!(checked, k / AUTO_BATCH_LIVES - 1);
        let held: BTreeMap<usize, StormOutcome> = computed.into_iter().collect();
        assert_eq!(run.stopping_point(&held), Some(Stopping::At(k, p, Some(sample))));
    }

    /// A scenario without `[design]` is refused naming the front-end.
    #[test]
    fn a_scenario_without_a_design_is_refused_naming_who_asked() {
        let text = include_str!("../../tests/data/small_design.toml");
        // The last table (the file says so): cut from its header to the end.
        let start = text.find("\n[design]").expect("a [design] table");
        let sc = Scenario::from_toml(&text[..start], Path::new("s.toml"), Path::new(".")).expect("without [design]");
        let e = Designer::new(&sc, "`caisson design`", DesignOptions::default()).unwrap_err();
        assert!(e.to_string().contains("`caisson design` needs a [design] table"), "{e}");
    }
}
