//! The signature runner: what a bundled example computes, briefly, by the driver its tables call
//! for (a `[load]` run, the first [`GOLDEN_LIVES`] lives of a `[design]`, 2 storms at the lowest and highest
//! heights of a `[fragility]`, realization 0 of `[waves]` trains). tests/regress_golden.rs,
//! tests/equiv_predictor.rs and tests/equiv_sticking_fast_path.rs each read what they compare from it.

use caisson::analysis::fragility::run_fragility;
use caisson::analysis::lifetime::{run_lives, StormOutcome};
use caisson::analysis::run::{run, History, RunResult};
use caisson::analysis::train::RealizationResult;
use caisson::scenario::Scenario;
use std::ops::ControlFlow;

/// What an example computed.
pub enum Signature {
    /// A `[load]` run (its whole history if asked for).
    Load(RunResult),
    /// The first [`GOLDEN_LIVES`] lives of a design.
    Lives(Vec<StormOutcome>),
    /// 2 storms at the lowest and 2 at the highest height of a fragility run.
    Storms(Vec<StormOutcome>),
    /// Realization 0 of the wave trains (and its history if asked for).
    Train(RealizationResult, Option<History>),
}

/// The lives of a design example that its signature runs: the smallest count in which every
/// design example has a life that slides, so that every accelerator of the dynamic model acts on
/// a slip (`breaking_site_15m`'s first is life 13; `size_breakwater`'s life 3; the others' life 0).
/// `tests/regress_golden.rs` asserts that each accelerator is exercised by them.
pub const GOLDEN_LIVES: usize = 14;

/// An empty history of `sc` for a run of `duration_s`.
pub fn history_for(sc: &Scenario, duration_s: f64) -> History {
    let (c, f, s) = (sc.caisson(), sc.foundation(), sc.solver());
    let samples = (duration_s / s.output_interval_s).ceil() as usize + 1;
    History::new(s.output_interval_s, samples, f.spring_positions(c.width_m), c.weight_in_water_n, f.mu_static)
}

/// Run `sc` briefly (module docs), keeping the time history of a run or a train if `history`.
pub fn signature(sc: &Scenario, history: bool) -> Signature {
    if let Some(load) = &sc.load {
        Signature::Load(run(sc.structure(), load, sc.duration_s, history).unwrap())
    } else if let Some(design) = &sc.design {
        let case = sc.storm_case(design.screen).unwrap();
        let indices: Vec<usize> = (0..GOLDEN_LIVES).collect();
        let lives = run_lives(&case, &design.life, design.seed, &indices, &|_, _| ControlFlow::Continue(())).unwrap();
        assert_eq!(lives.len(), GOLDEN_LIVES);
        Signature::Lives(lives.into_iter().map(|(_, o)| o).collect())
    } else if let Some(params) = &sc.fragility {
        let case = sc.storm_case(true).unwrap();
        let mut p = params.clone();
        p.heights_m = vec![params.heights_m[0], *params.heights_m.last().unwrap()];
        p.storms = 2;
        let r = run_fragility(&case, &p, &|| {}).unwrap();
        Signature::Storms(r.levels.iter().flat_map(|l| l.storms.iter().copied()).collect())
    } else {
        let case = sc.train_case().unwrap();
        let mut h = history.then(|| history_for(sc, case.duration_s()));
        let r = case.run(0, h.as_mut().map(|h| h as &mut dyn caisson::dynamics::Observer)).unwrap();
        Signature::Train(r, h)
    }
}

/// The per-wave sliding and peak reaction and the total sliding of a train realization, as
/// tests/equiv_predictor.rs and tests/equiv_sticking_fast_path.rs compare them.
pub fn train_values(out: &mut std::collections::BTreeMap<String, Vec<f64>>, r: &RealizationResult) {
    out.insert("wave_sliding_m".into(), r.waves.iter().map(|w| w.sliding_m).collect());
    out.insert("wave_max_horizontal_reaction_n".into(), r.waves.iter().map(|w| w.max_horizontal_reaction_n).collect());
    out.insert("sliding_m".into(), vec![r.sliding_m]);
}

/// Values of a signature by name, each a series (one value for a single run).
pub type Values = std::collections::BTreeMap<String, Vec<f64>>;

/// What `sc` computes ([`signature`], without histories) as named values: a `[load]` run's
/// summary values, its slip events and steps; a design's lives' sliding, largest storm sliding,
/// largest rotation and simulated waves (`life_*`); a fragility run's storms' sliding and largest
/// rotation (`storm_*`); a train's [`train_values`] and steps. With the solver's statistics where
/// the driver reports them. tests/equiv_accel.rs, tests/equiv_predictor.rs and
/// tests/equiv_sticking_fast_path.rs each compare the values they name ([`pick`]).
pub fn values(sc: &Scenario) -> (Values, Option<caisson::dynamics::SolverStats>) {
    let mut out = Values::new();
    let mut stats = None;
    match signature(sc, false) {
        Signature::Load(r) => {
            let r = r.summary;
            for (key, v) in [
                ("permanent_sliding_m", r.permanent_sliding_m),
                ("max_horizontal_displacement_m", r.max_horizontal_displacement_m),
                ("max_rotation_rad", r.max_rotation_rad),
                ("max_horizontal_reaction_n", r.max_horizontal_reaction_n),
                ("max_spring_normal_n", r.max_spring_normal_n),
                ("min_spring_normal_n", r.min_spring_normal_n),
                ("max_spring_shear_n", r.max_spring_shear_n),
                ("final_displacement_m", r.final_displacement_m),
                ("final_rotation_rad", r.final_rotation_rad),
                ("max_dashpot_moment_nm", r.max_dashpot_moment_nm),
                ("slip_events", r.slip_events as f64),
                ("steps", r.solver.steps as f64),
            ] {
                out.insert(key.into(), vec![v]);
            }
            stats = Some(r.solver);
        }
        Signature::Lives(lives) => {
            out.insert("life_sliding_m".into(), lives.iter().map(|o| o.sliding_m).collect());
            out.insert("life_max_storm_sliding_m".into(), lives.iter().map(|o| o.max_storm_sliding_m).collect());
            out.insert("life_max_rotation_rad".into(), lives.iter().map(|o| o.max_rotation_rad).collect());
            out.insert("life_simulated_waves".into(), lives.iter().map(|o| o.simulated_waves as f64).collect());
        }
        Signature::Storms(storms) => {
            out.insert("storm_sliding_m".into(), storms.iter().map(|o| o.sliding_m).collect());
            out.insert("storm_max_rotation_rad".into(), storms.iter().map(|o| o.max_rotation_rad).collect());
        }
        Signature::Train(r, _) => {
            train_values(&mut out, &r);
            out.insert("steps".into(), vec![r.solver.steps as f64]);
            stats = Some(r.solver);
        }
    }
    (out, stats)
}

/// The values of `all` named in `keys` (a name of another kind of run is not there: skipped).
pub fn pick(mut all: Values, keys: &[&str]) -> Values {
    all.retain(|k, _| keys.contains(&k.as_str()));
    all
}

/// `sc` with its accelerators changed by `f` (set as given: `Scenario::with_solver`).
pub fn with_accel(sc: &Scenario, f: impl FnOnce(caisson::dynamics::Accel) -> caisson::dynamics::Accel) -> Scenario {
    let s = sc.solver();
    sc.clone().with_solver(caisson::dynamics::SolverParams { accel: f(s.accel), ..s }).unwrap()
}
