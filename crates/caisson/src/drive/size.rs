//! The sizing driver of `caisson size` and Python's `caisson.size` (docs/size.md): a scenario with
//! `[size]`, `[design]` and a caisson given by its construction in, a [`SizeReport`] out.
//!
//! For each width the search asks for ([`crate::analysis::sizing::size`]), the scenario is
//! rebuilt at that width ([`Sizer::at_width`]: `Scenario::with_caisson` +
//! `CaissonSpec::with_width_m`, the construction gives the weight, mass, centre of gravity and
//! inertia), lives 0..N of the design's seed run with [`run_lives`] (common random numbers) and
//! reduce to a [`Candidate`]. Goda's conventional width is searched from a quarter of the range's
//! smallest width to twice its largest ([`conventional_width`] on [`static_check`] of the
//! scenario at each width, under the design wave of its `[waves]`). The report computes its own
//! warnings ([`SizeReport::new`]).
//!
//! With `[size] lives = "auto"` ([`crate::analysis::lifetime::AutoLives`]) each candidate runs
//! its lives in batches of [`crate::analysis::lifetime::AUTO_BATCH_LIVES`] and stops at the first
//! boundary where its own statistics meet the target ([`Candidate::judge`]), at most `[size]
//! max_lives`: each width takes the lives it needs (lives 0..k of the seed, common random numbers
//! over the widths' common lives), and the candidate records the verdict (`precision`).
//!
//! A stratified `[design]` ([`crate::analysis::lifetime::sampling`]) simulates the same sample at
//! every width: the strata and each batch's pool are drawn once, when a width first needs them
//! (`Sample`), and every width weighs its lives by the pool of lives 0..k — with "auto" the rule
//! reads the weighted estimates, as `caisson design` does.
//!
//! The front-ends keep what is theirs through [`Hooks`]: the progress, stopping (Ctrl-C), and
//! the checkpoint of the finished candidates (the CLI's file; its codec is
//! [`crate::report::checkpoint`]): candidates read back from it are passed in `done` and reused,
//! never run again.

use crate::analysis::conventional::{conventional_width, static_check, ChecksAtWidth, DesignWave};
use crate::analysis::lifetime::sampling::{work_lives, Pool, Strata};
use crate::analysis::lifetime::{
    auto_boundaries, run_lives, DesignParams, LifeFailed, Sampling, StormCase, StormOutcome,
};
use crate::analysis::sizing::{
    bisection_steps, candidate, candidate_sampled, curve_widths, size, Candidate, SizeParams,
};
use crate::analysis::stratified::TwoPhase;
use crate::analysis::work::{self, WorkEstimate};
use crate::loads::safety::SafetyFactors;
use crate::report::design::design_fingerprint;
use crate::report::size::{GodaWidth, SizeReport};
use crate::scenario::{Scenario, ScenarioError};
use std::ops::ControlFlow;

/// Width tolerance of the deterministic (Goda) width, m.
pub const GODA_TOLERANCE_M: f64 = 1e-3;

/// Why a sizing run stops.
#[derive(Debug, thiserror::Error)]
pub enum SizeError {
    /// The scenario has no `[size]`, `[design]` or `[waves]`, or its storms do not build.
    #[error(transparent)]
    Scenario(#[from] ScenarioError),
    /// The caisson is given by its weight: it cannot follow the width.
    #[error(
        "{0} varies the width, so the caisson's weight must follow it: give `[caisson]` its construction (wall_thickness_m, slab_thickness_m, fill_density_kg_per_m3, ...; docs/scenario.md) instead of `weight_in_water_kn`"
    )]
    NoConstruction(String),
    /// The scenario does not build at a width of the search (its caisson would float, ...).
    #[error("at the width {width_m} m of the search: {source}")]
    AtWidth { width_m: f64, source: ScenarioError },
    /// A life at a width failed to run.
    #[error("the lives at the width {width_m} m: {source}")]
    Run { width_m: f64, source: LifeFailed },
    /// [`Hooks::life`] asked to stop while the lives at `width_m` ran.
    #[error("stopped at the width {width_m} m")]
    Stopped { width_m: f64 },
    /// [`Hooks::candidate`] refused a finished candidate (e.g. its checkpoint line could not be
    /// written): its words.
    #[error("{0}")]
    Candidate(String),
}

/// What a front-end sees of a sizing run.
pub struct Hooks<'h> {
    /// A width's evaluation begins (from the calling thread); `true` if it comes from `done`.
    pub width: &'h mut (dyn FnMut(f64, bool) + Send),
    /// A life finished (from a worker thread); `Break` stops the run ([`SizeError::Stopped`]).
    pub life: &'h (dyn Fn() -> ControlFlow<()> + Sync),
    /// A newly evaluated candidate (not one of `done`); an error stops the run.
    pub candidate: &'h mut (dyn FnMut(&Candidate) -> Result<(), String> + Send),
}

/// A sizing run of a scenario: its `[size]` and `[design]`, checked.
pub struct Sizer<'a> {
    sc: &'a Scenario,
    pub params: SizeParams,
    pub design: DesignParams,
}

impl<'a> Sizer<'a> {
    /// The sizing of `sc` (`what` names the command in the error of a file without `[size]`,
    /// `[design]` or a construction).
    pub fn new(sc: &'a Scenario, what: &str) -> Result<Self, SizeError> {
        let params = *sc.size_for(what)?;
        let design = sc.design_for(what)?.clone();
        if sc.caisson_spec().construction().is_none() {
            return Err(SizeError::NoConstruction(what.to_string()));
        }
        Ok(Sizer { sc, params, design })
    }

    /// The scenario with the caisson `width_m` wide (its construction gives the weight).
    pub fn at_width(&self, width_m: f64) -> Result<Scenario, SizeError> {
        self.sc
            .clone()
            .with_caisson(|c| *c = c.with_width_m(width_m))
            .map_err(|source| SizeError::AtWidth { width_m, source })
    }

    /// How many candidates the search evaluates at most: the grid and two bisections.
    pub fn candidates(&self) -> usize {
        let p = &self.params;
        let grid = curve_widths(p).len();
        grid + 2 * bisection_steps(p, (p.range_m.1 - p.range_m.0) / (grid - 1) as f64)
    }

    /// The lives a candidate simulates at most: `[size] lives` (with "auto" its budget), of a
    /// stratified design their expected sample ([`work_lives`]).
    pub fn simulated_lives(&self) -> usize {
        match self.design.sampling {
            Sampling::Stratified => work_lives(self.params.lives),
            Sampling::Plain => self.params.lives,
        }
    }

    /// The work of the run, estimated on every width of the grid as a design run of one width's
    /// lives (each must build: a width whose caisson floats is an input error).
    pub fn estimate(&self, what: &str) -> Result<WorkEstimate, SizeError> {
        let one_width = DesignParams { lives: self.simulated_lives(), ..self.design.clone() };
        let mut grid = Vec::new();
        for w in curve_widths(&self.params) {
            let sw = self.at_width(w)?;
            let case = sw.storm_case(self.design.screen)?;
            grid.push(work::design(&case, &one_width, sw.waves_for(what)?));
        }
        Ok(work::size(&grid, self.candidates()))
    }

    /// What every candidate depends on: the design's fingerprint and `[size]` (a checkpoint of
    /// the candidates holds it).
    pub fn fingerprint(&self) -> Result<String, SizeError> {
        let case = self.sc.storm_case(self.design.screen)?;
        let lives = design_fingerprint(&case, &self.design);
        Ok(match self.design.sampling {
            // A stratified search's candidates are of its sample: not a plain search's.
            Sampling::Stratified => crate::report::fingerprint(&(lives, &self.params, Sampling::Stratified)),
            Sampling::Plain => crate::report::fingerprint(&(lives, &self.params)),
        })
    }

    /// Run the search (reusing the candidates `done`) and Goda's width: the report. Lives run on
    /// rayon's current pool.
    pub fn run(&self, done: &[Candidate], hooks: Hooks<'_>) -> Result<SizeReport, SizeError> {
        let (p, design) = (&self.params, &self.design);
        let Hooks { width, life, candidate: finished } = hooks;
        // A stratified design samples the same lives at every width (their storms' severity does
        // not depend on the caisson: common random numbers, module docs): the strata, and the
        // pool of each batch of lives with the lives it simulates, are drawn once.
        let boundaries: Vec<usize> = match p.auto {
            Some(_) => auto_boundaries(p.lives).collect(),
            None => vec![p.lives],
        };
        let mut sample = match design.sampling {
            Sampling::Stratified => Some(Sample::new(self.sc.storm_case(design.screen)?, design)),
            Sampling::Plain => None,
        };
        let mut evaluate = |w: f64| -> Result<Candidate, SizeError> {
            if let Some(c) = done.iter().find(|c| c.width_m == w) {
                width(w, true);
                return Ok(c.clone());
            }
            let sw = self.at_width(w)?;
            let case = sw.storm_case(design.screen)?;
            width(w, false);
            let heel_pa = (design.allowable_heel_pressure_pa, design.heel_screen_pa());
            let of = |outcomes: &[StormOutcome], est: Option<&TwoPhase>| {
                let (weight_n, failure) = (sw.caisson().weight_in_water_n, &design.failure_limits(w));
                match est {
                    Some(est) => candidate_sampled(w, weight_n, outcomes, failure, &p.criteria, heel_pa, est),
                    None => candidate(w, weight_n, outcomes, failure, &p.criteria, heel_pa),
                }
            };
            // A fixed number of lives is one batch; "auto" stops at the first boundary where the
            // candidate's statistics meet the target (module docs). A stratified batch runs the
            // lives its pool samples and is weighted by the pool of lives 0..k.
            let mut outcomes: Vec<StormOutcome> = Vec::new();
            let mut c = None;
            for (b, &k) in boundaries.iter().enumerate() {
                let (indices, est): (Vec<usize>, Option<&TwoPhase>) = match &mut sample {
                    Some(s) => {
                        let (indices, est) = s.batch(b, &boundaries);
                        (indices.clone(), Some(est))
                    }
                    None => ((outcomes.len()..k).collect(), None),
                };
                let lives = run_lives(&case, &design.life, design.seed, &indices, &|_, _| life())
                    .map_err(|source| SizeError::Run { width_m: w, source })?;
                if lives.len() < indices.len() {
                    return Err(SizeError::Stopped { width_m: w });
                }
                outcomes.extend(lives.into_iter().map(|(_, o)| o));
                let mut at_k = of(&outcomes, est);
                at_k.precision = p.auto.map(|auto| at_k.judge(&auto, p.lives));
                let met = at_k.precision.is_none_or(|q| q.met);
                c = Some(at_k);
                if met {
                    break;
                }
            }
            let c = c.expect("at least one boundary");
            finished(&c).map_err(SizeError::Candidate)?;
            Ok(c)
        };
        let sizing = size(p, &mut evaluate)?;
        // The deterministic width is cheap: it is searched from a quarter of the range's smallest
        // width to twice its largest, so it shows even where it lies far from the widths the
        // dynamic model needs.
        let goda_checks = |w: f64| -> Option<SafetyFactors> {
            let s = self.at_width(w).ok()?;
            static_check(s.structure(), s.waves.as_ref()?).ok().map(|c| c.safety)
        };
        let goda_range = (p.range_m.0 / 4.0, 2.0 * p.range_m.1);
        let width_found = conventional_width(goda_range, GODA_TOLERANCE_M, &p.conventional, &mut |w| goda_checks(w));
        let waves = self.sc.waves_for("sizing")?;
        let goda = GodaWidth::new(DesignWave::of(waves), &p.conventional, width_found);
        let extra = |c: &Candidate| {
            let checks = goda_checks(c.width_m).map(|sf| ChecksAtWidth::new(c.width_m, &sf));
            (design.failure_limit_m(c.width_m), checks)
        };
        Ok(SizeReport::new(p, design, (self.sc.structure(), self.sc.waves.as_ref()), &sizing, goda, &extra))
    }
}

/// A stratified search's sample: its strata, and batch after batch the pool of the lives
/// 0..k and the lives it simulates, drawn when a width first needs the batch and kept for the
/// other widths (the same lives at every width).
struct Sample<'c> {
    case: StormCase<'c>,
    design: &'c DesignParams,
    strata: Strata,
    pool: Pool,
    /// Per batch drawn: the lives it simulates, and the estimator of the pool up to its end.
    drawn: Vec<(Vec<usize>, TwoPhase)>,
}

impl<'c> Sample<'c> {
    fn new(case: StormCase<'c>, design: &'c DesignParams) -> Self {
        let strata = Strata::pilot(&case, &design.life, design.seed);
        Sample { case, design, strata, pool: Pool::default(), drawn: Vec::new() }
    }

    /// Batch `b` (lives `boundaries[b - 1]..boundaries[b]`, from 0 for the first), the batches
    /// before it drawn first.
    fn batch(&mut self, b: usize, boundaries: &[usize]) -> &(Vec<usize>, TwoPhase) {
        while self.drawn.len() <= b {
            let d = self.drawn.len();
            let start = if d == 0 { 0 } else { boundaries[d - 1] };
            let next = Pool::of(&self.case, &self.design.life, self.design.seed, &self.strata, start..boundaries[d]);
            let indices = next.indices();
            self.pool.append(next);
            self.drawn.push((indices, self.pool.estimator(&self.strata)));
        }
        &self.drawn[b]
    }
}
