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

use crate::analysis::lifetime::sampling::{Pool, Strata};
use crate::analysis::lifetime::{
    run_lives, DesignParams, FailureLimits, LifeFailed, Sampling, StormCase, StormOutcome,
};
use crate::analysis::site::WaveSetup;
use crate::analysis::work::{self, WorkEstimate};
use crate::dynamics::Stepping;
use crate::report::design::{design_fingerprint, DesignReport};
use crate::scenario::{Scenario, ScenarioError};
use std::ops::{ControlFlow, Range};

/// How a design run departs from the scenario's `[design]`.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct DesignOptions {
    /// The number of lives (the CLI's `--lives`, a merge's lives); `None`: `[design] lives`.
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

    /// The work of `lives` lives of this run (a shard's, or the run's own count).
    pub fn estimate(&self, lives: usize) -> WorkEstimate {
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

    /// The report of `lives` (lives 0..N in index order): statistics, the model and the warnings.
    pub fn report(&self, lives: &[StormOutcome]) -> DesignReport {
        DesignReport::new(&self.design, &self.case, Some(self.waves), lives)
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
            Some(s) => DesignReport::stratified(&self.design, &self.case, Some(self.waves), lives, &s.strata, &s.pool),
            None => self.report(lives),
        }
    }

    /// The statistics of `lives` alone ([`DesignReport::statistics`]: no model, no warnings).
    pub fn statistics(&self, lives: &[StormOutcome]) -> DesignReport {
        let failure_m = self.failure_limits().sliding_m;
        DesignReport::statistics(&self.design, self.case.rigid_block_mu, failure_m, lives)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
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
