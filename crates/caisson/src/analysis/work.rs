//! Work estimates: what a driver will do, known before it starts, so that a caller can refuse a
//! run beyond a budget (the CLI does, docs/cli.md "Limits") or say how long it will be.
//!
//! A [`WorkEstimate`] counts three things:
//!
//! * **time steps** of the dynamic model, all simulations together: the simulated time of
//!   loading × steps per second. With fixed steps that is 1/`dt_s` (exact, but for halvings).
//!   With adaptive steps it is measured by a **pilot**: the first wave (of realization 0, or a
//!   representative wave of a storm) run with the scenario's solver, at most
//!   [`PILOT_MAX_STEPS`] steps (far fewer than the run); if the pilot fails, 1/`dt_s` (the first
//!   step) is used.
//!   A step's cost grows with the number of springs n (their assembly): it counts
//!   [`step_cost`] = (n + 10)/20 steps of the seed's 10 springs (measured: 0.64 at n = 2, 5.9 at
//!   100, 14.8 at 300; the budget is in steps of 10 springs).
//! * **waves** drawn: every wave of every train, storm and life. A design or fragility run draws
//!   each wave's height and screens it even when it does not simulate it (about 0.1 µs each).
//! * **memory** held until the end of the run, bytes: the results kept for the outputs (every
//!   wave of a train in the JSON summary, a life, a storm) and time histories returned whole
//!   ([`Histories::Held`]: Python's `run`), from the sizes measured on the examples (below); the
//!   solver's own state is small and fixed.
//! * **disk** written while the run goes, bytes: time histories streamed to files row by row
//!   ([`Histories::Streamed`]: `caisson run --out`), which cost no memory (the CLI keeps a bounded
//!   envelope of them for its plots, about 10 MB) but fill a disk: a history is refused before it
//!   starts, not after hours when the disk is full.
//!
//! Which waves of a design or fragility run reach the dynamic model depends on the screen
//! ([`super::lifetime`]); the share is estimated by a **screen pilot**: the first 16 lives (or the
//! storms of up to 16 heights) with few waves per storm, through the real screen, with a coarse
//! adaptive solver (the screen does not depend on the solver, and the coarse one keeps the pilot
//! short); a design pilot does not run the stick bound's still waves again for the largest
//! rotation ([`super::lifetime::StormCase::settle_rotation`]), which a life does once for all its
//! storms (on the design example 617 of 95 614 waves run) and a short pilot life far more often,
//! nor the waves that only its heel pressure needs (a fifth of the design example's, which the
//! estimate leaves out); a fragility pilot's storms draw their load-model errors. The simulated time is that share of the waves' time (a storm of N waves of period T
//! lasts N T); with wave-by-wave periods (`[design] wave_periods`, [`crate::waves::periods`]) the
//! simulated waves are the high ones, whose periods lie close to the mean period τ̄ = 0.89 T1/3
//! (within a few per cent: E[τ/τ̄] = 1 + s² + … with s ≈ 0.14 at H = 1.4 H1/3), so it is that
//! share of N τ̄ ([`simulated_period_ratio`]). The screen pilot runs the waves' own periods.
//!
//! Every estimate is deterministic (the pilots use the run's first random streams), so a run is
//! refused or accepted the same way every time. It is an estimate, not a bound (tests/verify_work_estimates.rs):
//! the steps of the wave-train and campaign examples within 15 % (measured 1-2 %), the waves of
//! the design example within 3 % and its screened share within a factor of 3 (measured 1.15: the
//! rare large storms that pass most waves may or may not be among the pilot's 128), the
//! fragility example's share within 10 % (measured 5.3 %). A pilot takes about 15 ms; a design
//! pilot's cost is mostly its simulated waves (the screened ones are not even drawn,
//! [`super::lifetime`]), up to about 0.3 s for a caisson a third of whose waves pass the screen.
//!
//! Memory per item (measured with `/usr/bin/time -f %M` on the examples scaled up, rounded up):
//! a history row of n springs held whole, 8 (12 + 3n) + 4 bytes of samples plus 75 n bytes for
//! their copies (1.1 kB at n = 10; Python's `run`, the Rust history and its DataFrame and
//! Dataset, measured 0.71 kB a row at its peak on a 2·10⁵-row history); a wave of a train about 2 kB (its result and its entry of the JSON summary); a
//! campaign wave 200 B (2 kB in `campaign.json`); a life or a storm 256 B. Disk per history row
//! streamed: [`CSV_BYTES_PER_NUMBER`] bytes for each number of `history.csv` (time and 12
//! columns) and `springs.csv` (time and 3 n columns): 25 (14 + 3n), 1.1 kB at n = 10 (measured
//! 0.90 kB on `table5_triangle.toml`, 0.84 kB on `fifteen_waves.toml`).

use super::campaign::ConditionSetup;
use super::climate::{StormModel, WavePeriods};
use super::fragility::FragilityParams;
use super::lifetime::{simulate_life, simulate_storm, DesignParams, LifeParams, StormCase};
use super::site::WaveSetup;
use super::train::TrainCase;
use super::Structure;
use crate::dynamics::{AdaptiveParams, Simulation, SolverParams, Stepping};
use crate::loads::generator::{realization_rng, realization_waves, TrainKind, TrainSpec};
use crate::loads::history::WaveTrain;
use crate::loads::regime::RegimeChoice;
use crate::loads::LoadHistory;
use crate::waves::periods::MEAN_PERIOD_RATIO;
use rayon::prelude::*;

/// Most steps of a pilot run (about 0.1 s).
pub const PILOT_MAX_STEPS: u64 = 200_000;
/// Bytes of a wave of a train held until the end (its result and JSON entry).
pub const BYTES_PER_TRAIN_WAVE: f64 = 2048.0;
/// Bytes of a wave of a campaign held until the end (its result); with every wave in the JSON,
/// [`BYTES_PER_TRAIN_WAVE`] more.
pub const BYTES_PER_CAMPAIGN_WAVE: f64 = 200.0;
/// Bytes of a life (design) or a storm (fragility) held until the end.
pub const BYTES_PER_LIFE: f64 = 256.0;
/// Bytes of a design life held until the end: its outcome ([`BYTES_PER_LIFE`]) and its
/// checkpoint line as written, kept for the ordered rewrite at the end (about 390 B on the
/// design example, in a string of up to twice that).
pub const BYTES_PER_DESIGN_LIFE: f64 = BYTES_PER_LIFE + 768.0;

/// Bytes written for each number of a streamed history row, its separator included (the
/// shortest text that reads back to the same float: measured 19-21 on the examples).
pub const CSV_BYTES_PER_NUMBER: f64 = 25.0;

/// Bytes held in memory for one row of time histories kept whole, on `springs` springs (module
/// docs).
pub fn bytes_per_history_row(springs: usize) -> f64 {
    let n = springs as f64;
    8.0 * (12.0 + 3.0 * n) + 4.0 + 25.0 * 3.0 * n
}

/// Bytes written to `history.csv` and `springs.csv` for one row streamed on `springs` springs:
/// [`CSV_BYTES_PER_NUMBER`] × (14 + 3n) (module docs).
pub fn csv_bytes_per_history_row(springs: usize) -> f64 {
    CSV_BYTES_PER_NUMBER * (14.0 + 3.0 * springs as f64)
}

/// What becomes of the time histories of a run (a `[load]` run, or realization 0 of wave
/// trains).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Histories {
    /// None are kept (only the summary).
    None,
    /// Returned whole at the end, held in memory (Python's `run`).
    Held,
    /// Written to files row by row as the run goes (`caisson run --out`): disk, not memory.
    Streamed,
}

impl Histories {
    /// (memory, disk) bytes of `rows` rows on `springs` springs.
    fn cost(self, rows: f64, springs: usize) -> (f64, f64) {
        match self {
            Histories::None => (0.0, 0.0),
            Histories::Held => (rows * bytes_per_history_row(springs), 0.0),
            Histories::Streamed => (0.0, rows * csv_bytes_per_history_row(springs)),
        }
    }

    /// Rows of a history of `duration_s` sampled every `interval_s` in about `steps` steps (0
    /// without histories): a row is the first step at or after each interval, so adaptive steps
    /// longer than the interval give one row a step.
    fn rows(self, duration_s: f64, interval_s: f64, steps: f64) -> f64 {
        if self == Histories::None {
            0.0
        } else {
            (duration_s / interval_s).ceil().min(steps.ceil()) + 1.0
        }
    }

    /// The rows in words for an estimate's basis.
    fn describe(self, rows: f64) -> String {
        match self {
            Histories::None => String::new(),
            Histories::Held => format!(", {rows} history rows held"),
            Histories::Streamed => format!(", {rows} history rows written"),
        }
    }
}

/// The cost of a time step on `springs` springs in steps on the seed's 10: (n + 10)/20 (module
/// docs).
pub fn step_cost(springs: usize) -> f64 {
    (springs as f64 + 10.0) / 20.0
}

/// How the steps of an estimate were counted.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum StepsFrom {
    /// Fixed steps: the simulated time over `dt_s`.
    FixedSteps { dt_s: f64 },
    /// Adaptive steps, measured by a pilot run: steps per second of loading.
    Pilot { steps_per_s: f64 },
    /// Adaptive steps whose pilot failed (or none was possible): the simulated time over the
    /// first step `dt_s`.
    FirstStep { dt_s: f64 },
}

impl StepsFrom {
    /// Steps per second of loading.
    pub fn steps_per_s(&self) -> f64 {
        match *self {
            StepsFrom::FixedSteps { dt_s } | StepsFrom::FirstStep { dt_s } => 1.0 / dt_s,
            StepsFrom::Pilot { steps_per_s } => steps_per_s,
        }
    }

    /// In words.
    pub fn describe(&self) -> String {
        match *self {
            StepsFrom::FixedSteps { dt_s } => format!("fixed steps of {dt_s} s"),
            StepsFrom::Pilot { steps_per_s } => {
                format!("about {steps_per_s:.0} adaptive steps per second of loading (from a pilot run)")
            }
            StepsFrom::FirstStep { dt_s } => format!("adaptive steps counted as steps of the first step {dt_s} s"),
        }
    }
}

/// What a driver will do (module docs).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct WorkEstimate {
    /// Time steps of the dynamic model, all simulations together.
    pub steps: f64,
    /// The cost of one of them in steps on 10 springs ([`step_cost`]).
    pub step_cost: f64,
    /// Waves drawn (trains: waves run; design and fragility: every wave, screened or not).
    pub waves: f64,
    /// Bytes held in memory until the end of the run.
    pub memory_bytes: f64,
    /// Bytes written to files while the run goes (streamed time histories).
    pub disk_bytes: f64,
    /// Seconds of loading run through the dynamic model.
    pub simulated_s: f64,
    pub steps_from: StepsFrom,
    /// Share of the waves that reach the dynamic model (1 without a screen).
    pub simulated_share: f64,
    /// The count in words (e.g. "15 conditions × 10 realizations × 15 waves").
    pub basis: String,
}

/// Limits of a run's work.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Budget {
    pub steps: f64,
    pub waves: f64,
    pub memory_bytes: f64,
    pub disk_bytes: f64,
}

const GIB: f64 = 1024.0 * 1024.0 * 1024.0;

impl Budget {
    /// The budget of the CLI and of Python (docs/cli.md "Limits"): 2·10¹⁰ time steps (about two
    /// hours of one core at 0.3-0.4 µs a step), 2·10¹⁰ waves drawn (about an hour), 4 GiB held,
    /// 10 GiB of time histories written (about 10⁷ rows on 10 springs, 2.7 hours of loading at
    /// the default interval of 1 ms: more than a spreadsheet or a plotting tool reads whole, and
    /// a disk that fills mid-run fails the run after its hours of computing). The bundled
    /// examples stay 90 times or more below each (the design example, the largest, at 1.9·10⁸
    /// steps and 1.9·10⁸ waves; `fifteen_waves.toml --out` writes 38 MB).
    pub const DEFAULT: Budget = Budget { steps: 2e10, waves: 2e10, memory_bytes: 4.0 * GIB, disk_bytes: 10.0 * GIB };
}

/// What an estimate exceeds first.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Resource {
    Steps,
    Waves,
    Memory,
    Disk,
}

/// What to change to lower each kind of work, in the words of the caller's keys and options
/// (the CLI's and Python's differ).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Advice {
    pub steps: &'static str,
    pub waves: &'static str,
    pub memory: &'static str,
    pub disk: &'static str,
}

/// `b` bytes in words (MiB, GiB, TiB: powers of 1024).
pub fn describe_bytes(b: f64) -> String {
    const MIB: f64 = 1024.0 * 1024.0;
    if b >= 1024.0 * GIB {
        format!("{:.1} TiB", b / (1024.0 * GIB))
    } else if b >= GIB {
        format!("{:.1} GiB", b / GIB)
    } else {
        format!("{:.1} MiB", b / MIB)
    }
}

/// Estimates at this many steps or waves or more are long (about half a minute): a caller says
/// them as the run starts ([`WorkEstimate::note`]).
pub const LONG: f64 = 1e8;

impl WorkEstimate {
    /// The steps in steps on 10 springs, [`Self::steps`] × [`Self::step_cost`]: what the budget
    /// counts.
    pub fn weighted_steps(&self) -> f64 {
        self.steps * self.step_cost
    }

    /// The first of waves, weighted steps, memory and disk over `budget`: (which, estimate,
    /// limit).
    pub fn excess(&self, budget: &Budget) -> Option<(Resource, f64, f64)> {
        [
            (Resource::Waves, self.waves, budget.waves),
            (Resource::Steps, self.weighted_steps(), budget.steps),
            (Resource::Memory, self.memory_bytes, budget.memory_bytes),
            (Resource::Disk, self.disk_bytes, budget.disk_bytes),
        ]
        .into_iter()
        .find(|&(_, est, limit)| est.is_nan() || est > limit)
    }

    /// The refusal of a run over `budget`, `None` within it: "`{command}` would take {the
    /// estimate and how it was made}; the budget is {the limit} (docs/cli.md, Limits): {what to
    /// change, from `advice`}".
    pub fn refusal(&self, budget: &Budget, command: &str, advice: &Advice) -> Option<String> {
        let (resource, estimate, _) = self.excess(budget)?;
        let (what, limit, change) = match resource {
            Resource::Steps => (
                format!(
                    "about {estimate:.2e} time steps of the dynamic model ({}; {:.3e} s of loading at {}{})",
                    self.basis,
                    self.simulated_s,
                    self.steps_from.describe(),
                    if self.step_cost == 1.0 {
                        String::new()
                    } else {
                        format!(
                            "; {:.2e} steps, each of {:.3} steps on 10 springs, the budget's unit",
                            self.steps, self.step_cost
                        )
                    }
                ),
                format!("{:.0e} time steps", budget.steps),
                advice.steps,
            ),
            Resource::Waves => (
                format!("about {estimate:.2e} waves ({})", self.basis),
                format!("{:.0e} waves", budget.waves),
                advice.waves,
            ),
            Resource::Memory => (
                format!("about {} of results held in memory ({})", describe_bytes(estimate), self.basis),
                describe_bytes(budget.memory_bytes),
                advice.memory,
            ),
            Resource::Disk => (
                format!("about {} of time histories written to disk ({})", describe_bytes(estimate), self.basis),
                format!("{} written", describe_bytes(budget.disk_bytes)),
                advice.disk,
            ),
        };
        Some(format!("`{command}` would take {what}; the budget is {limit} (docs/cli.md, Limits): {change}"))
    }

    /// The estimate in words, to say as a long run starts ([`LONG`] steps or waves or more);
    /// `None` for a shorter run.
    pub fn note(&self, budget: &Budget) -> Option<String> {
        (self.weighted_steps() >= LONG || self.waves >= LONG).then(|| {
            format!(
                "Estimated work: about {:.1e} time steps and {:.1e} waves, {} held, {} written ({}); the budget is {:.0e} steps, {:.0e} waves, {} held, {} written",
                self.weighted_steps(),
                self.waves,
                describe_bytes(self.memory_bytes),
                describe_bytes(self.disk_bytes),
                self.basis,
                budget.steps,
                budget.waves,
                describe_bytes(budget.memory_bytes),
                describe_bytes(budget.disk_bytes)
            )
        })
    }
}

/// Steps per second of loading of `structure`'s solver on `load` from rest, run until `end_s`
/// or [`PILOT_MAX_STEPS`] steps on 10 springs ([`step_cost`]), checked after each sixteenth of
/// the way; `None` if it fails.
fn pilot_rate(structure: &Structure, load: &dyn LoadHistory, end_s: f64) -> Option<f64> {
    let mut sim = Simulation::new(structure.model(), structure.solver, load);
    let cap = (PILOT_MAX_STEPS as f64 / step_cost(structure.foundation.springs)) as u64;
    let slice = end_s / 16.0;
    let mut t = 0.0;
    while t < end_s && sim.stats.steps < cap {
        t = (t + slice).min(end_s);
        sim.run_until(t, load, &mut ()).ok()?;
    }
    let rate = sim.stats.steps as f64 / sim.state().t_s;
    rate.is_finite().then_some(rate)
}

/// How the steps of `structure` are counted; `pilot` runs the pilot (adaptive steps only).
fn steps_from(structure: &Structure, pilot: impl FnOnce() -> Option<f64>) -> StepsFrom {
    let dt_s = structure.solver.dt_s;
    match structure.solver.stepping {
        Stepping::Fixed => StepsFrom::FixedSteps { dt_s },
        Stepping::Adaptive(_) => match pilot() {
            Some(steps_per_s) => StepsFrom::Pilot { steps_per_s },
            None => StepsFrom::FirstStep { dt_s },
        },
    }
}

/// A `[load]` run of `duration_s` (`analysis::run::run`) with its time `histories`.
/// Adaptive steps are counted as steps of the first step `dt_s` (the run's own limit,
/// [`SolverParams::check_run`]).
pub fn run(structure: &Structure, duration_s: f64, histories: Histories) -> WorkEstimate {
    let s = &structure.solver;
    let steps_from = match s.stepping {
        Stepping::Fixed => StepsFrom::FixedSteps { dt_s: s.dt_s },
        Stepping::Adaptive(_) => StepsFrom::FirstStep { dt_s: s.dt_s },
    };
    let rows = histories.rows(duration_s, s.output_interval_s, duration_s * steps_from.steps_per_s());
    let (memory_bytes, disk_bytes) = histories.cost(rows, structure.foundation.springs);
    WorkEstimate {
        steps: duration_s * steps_from.steps_per_s(),
        step_cost: step_cost(structure.foundation.springs),
        waves: 0.0,
        memory_bytes,
        disk_bytes,
        simulated_s: duration_s,
        steps_from,
        simulated_share: 1.0,
        basis: format!("{duration_s} s of loading{}", histories.describe(rows)),
    }
}

/// The first wave of realization 0 of `waves` on `structure`: the pilot of a train.
fn train_pilot(structure: &Structure, waves: &WaveSetup) -> Option<f64> {
    let spec = TrainSpec { waves: PILOT_TRAIN_WAVES.min(waves.train.waves), realizations: 1, ..waves.train };
    let drawn = realization_waves(&waves.model, &spec, waves.regime(), 0).ok()?;
    let train = waves.model.train(&drawn.records).ok()?;
    pilot_rate(structure, &train, train.duration_s())
}

/// The waves of a train's pilot: the first wave starts from rest and its sticking phase is held
/// to the adaptive tolerance per unit step (`dynamics::adaptive`), so it takes more steps a second
/// than the waves after it; three waves weigh it down (the pilot of `pari_breaking_loads.toml`:
/// 20 % above the run's rate with one wave).
const PILOT_TRAIN_WAVES: usize = 3;

/// Wave-train realizations (`train::run_realizations`) with the time `histories` of
/// realization 0 (`caisson run --out` streams them).
pub fn train(case: &TrainCase<'_>, histories: Histories) -> WorkEstimate {
    let t = &case.waves.train;
    let (n, r) = (t.waves as f64, t.realizations as f64);
    let duration_s = n * t.period_s;
    let steps_from = steps_from(case.structure, || train_pilot(case.structure, case.waves));
    let rows =
        histories.rows(duration_s, case.structure.solver.output_interval_s, duration_s * steps_from.steps_per_s());
    let (history_memory, disk_bytes) = histories.cost(rows, case.structure.foundation.springs);
    WorkEstimate {
        steps: r * duration_s * steps_from.steps_per_s(),
        step_cost: step_cost(case.structure.foundation.springs),
        waves: r * n,
        memory_bytes: r * n * BYTES_PER_TRAIN_WAVE + history_memory,
        disk_bytes,
        simulated_s: r * duration_s,
        steps_from,
        simulated_share: 1.0,
        basis: format!(
            "{} realizations × {} waves of {} s{}",
            t.realizations,
            t.waves,
            t.period_s,
            histories.describe(rows)
        ),
    }
}

/// A campaign (`campaign::run_campaign`); `every_wave`: `campaign.json` with every wave. The
/// pilots run on up to 8 conditions spread over the list; their mean rate is used.
pub fn campaign(setups: &[ConditionSetup], every_wave: bool) -> WorkEstimate {
    let (mut waves, mut simulated_s) = (0.0, 0.0);
    for s in setups {
        let t = &s.waves.train;
        waves += (t.waves * t.realizations) as f64;
        simulated_s += (t.waves * t.realizations) as f64 * t.period_s;
    }
    let picked: Vec<&ConditionSetup> = match setups.len() {
        0 => Vec::new(),
        n => (0..n.min(8)).map(|k| &setups[k * n / n.min(8)]).collect(),
    };
    let first = picked.first().map(|s| &s.structure);
    let steps_from = match first {
        None => StepsFrom::FixedSteps { dt_s: SolverParams::default().dt_s },
        Some(structure) => steps_from(structure, || {
            let rates: Vec<f64> = picked.iter().filter_map(|s| train_pilot(&s.structure, &s.waves)).collect();
            (rates.len() == picked.len()).then(|| rates.iter().sum::<f64>() / rates.len() as f64)
        }),
    };
    let per_wave = BYTES_PER_CAMPAIGN_WAVE + if every_wave { BYTES_PER_TRAIN_WAVE } else { 0.0 };
    WorkEstimate {
        steps: simulated_s * steps_from.steps_per_s(),
        step_cost: first.map_or(1.0, |s| step_cost(s.foundation.springs)),
        waves,
        memory_bytes: waves * per_wave,
        disk_bytes: 0.0,
        simulated_s,
        steps_from,
        simulated_share: 1.0,
        basis: format!("{} conditions, {waves} waves in all", setups.len()),
    }
}

/// The structure of a screen pilot: the scenario's, with a coarse adaptive solver (module docs).
fn coarse(structure: &Structure) -> Structure {
    let dt = structure.solver.dt_s.min(1e-3);
    let solver = SolverParams::fixed(dt)
        .and_then(|s| s.with_adaptive(AdaptiveParams { dt_min_s: dt.min(1e-6), dt_max_s: 1.0, tolerance_m: 1e-3 }))
        .and_then(|s| s.with_iterations(50, 20))
        .unwrap_or(structure.solver);
    Structure { solver, ..structure.clone() }
}

/// Steps per second of loading of the real solver on one wave of height `h_m` and period
/// `period_s` at the site of `case` (the pilot of a storm's simulated waves).
fn storm_pilot(case: &StormCase<'_>, h_m: f64, period_s: f64) -> Option<f64> {
    let m = case.model;
    let loads = m
        .evaluate_with(h_m, period_s, m.options.regime)
        .or_else(|_| m.evaluate_with(h_m, period_s, RegimeChoice::Auto))
        .ok()?;
    let train = WaveTrain::new(vec![m.event(&loads, None, 0.0)]).ok()?;
    pilot_rate(case.structure, &train, period_s)
}

/// The largest wave of the scenario's `[waves]` (H, or H_max = 1.8 H1/3) and its period: the
/// representative wave of a design run's storms.
fn design_wave(waves: &WaveSetup) -> (f64, f64) {
    let h = match waves.train.kind {
        TrainKind::Regular { .. } => waves.height_m(),
        TrainKind::Irregular { .. } => super::conventional::HMAX_OVER_H13 * waves.height_m(),
    };
    (h, waves.period_s())
}

/// Lives of the screen pilot of a design run, and storms per pilot life, and waves per storm
/// (128: with 16, the 2048 waves of the design example's pilot held about 3 simulated ones).
const PILOT_LIVES: usize = 16;
const PILOT_STORMS: usize = 8;
const PILOT_WAVES_PER_STORM: f64 = 128.0;

/// A design run (`lifetime::run_lives`) of `p.lives` lives (for a shard, its own count: the
/// lives of a shard cost as much as any others); `waves` is the scenario's `[waves]` (the
/// representative wave of the step pilot: [`design_wave`]). The screen pilot runs lives 0 to 15
/// whatever the count, so that every shard of a run is estimated at the same work per life.
pub fn design(case: &StormCase<'_>, p: &DesignParams, waves: &WaveSetup) -> WorkEstimate {
    let life = &p.life;
    // Mean waves per storm over the storm distribution (its 64 quantiles), T = a H0^b.
    let period = |q: f64| life.period_coefficient * life.storm_height_m(q).max(1e-3).powf(life.period_exponent);
    let per_storm: f64 =
        (0..64).map(|k| (life.storm_duration_s / period((k as f64 + 0.5) / 64.0)).round().max(1.0)).sum::<f64>() / 64.0;
    let storms = p.lives as f64 * life.life_years as f64 * life.climate.storms.mean_storms_per_year();
    let waves_drawn = storms * per_storm;
    let (h, t) = design_wave(waves);
    // The two pilots at once (on the caller's rayon threads): each is deterministic.
    let (share, steps_from) = rayon::join(
        || if case.screen { design_screen_share(case, p) } else { 1.0 },
        || steps_from(case.structure, || storm_pilot(case, h, t)),
    );
    let simulated_s = storms * life.storm_duration_s * share * simulated_period_ratio(&life.climate.periods);
    WorkEstimate {
        steps: simulated_s * steps_from.steps_per_s(),
        step_cost: step_cost(case.structure.foundation.springs),
        waves: waves_drawn,
        memory_bytes: p.lives as f64 * BYTES_PER_DESIGN_LIFE,
        disk_bytes: 0.0,
        simulated_s,
        steps_from,
        simulated_share: share,
        basis: format!(
            "{} lives × {} years{} × about {per_storm:.0} waves per storm, {:.3} % of them simulated (screen pilot){}",
            p.lives,
            life.life_years,
            match life.climate.storms {
                StormModel::AnnualMaxima => String::new(),
                StormModel::PeaksOverThreshold { rate_per_year, .. } => format!(" × {rate_per_year} storms a year"),
            },
            100.0 * share,
            periods_basis(&life.climate.periods)
        ),
    }
}

/// The simulated waves' mean period over T1/3 (module docs): 1, or τ̄/T1/3 with wave-by-wave
/// periods.
pub fn simulated_period_ratio(periods: &WavePeriods) -> f64 {
    match periods {
        WavePeriods::Significant => 1.0,
        WavePeriods::LonguetHiggins { .. } => MEAN_PERIOD_RATIO,
    }
}

/// The estimate's basis on the waves' periods: nothing, or that they are drawn wave by wave.
fn periods_basis(periods: &WavePeriods) -> &'static str {
    match periods {
        WavePeriods::Significant => "",
        WavePeriods::LonguetHiggins { .. } => ", wave-by-wave periods of mean 0.89 T1/3",
    }
}

/// The share of a design run's waves that reach the dynamic model, from its first lives with
/// short storms (module docs); a pilot life that fails counts as all simulated.
fn design_screen_share(case: &StormCase<'_>, p: &DesignParams) -> f64 {
    let coarse = coarse(case.structure);
    // Only the counts are read: the still waves are not run again for the largest rotation, and
    // no wave for its heel pressure alone (a pilot life of 8 short storms would run them as often
    // as a life of 50 full ones; on the design example they are a fifth of the waves run).
    let pilot_case = StormCase { structure: &coarse, settle_rotation: false, heel_screen_pa: f64::INFINITY, ..*case };
    let life = &p.life;
    let t_median = life.period_coefficient * life.storm_height_m(0.5).max(1e-3).powf(life.period_exponent);
    let storms = life.life_years.min(PILOT_STORMS);
    let pilot = LifeParams {
        life_years: storms,
        storm_duration_s: (PILOT_WAVES_PER_STORM * t_median).min(life.storm_duration_s),
        ..life.clone()
    };
    // The lives in parallel (on the caller's rayon threads); whole counts, so their sums do not
    // depend on the order.
    let (waves, simulated) = (0..PILOT_LIVES)
        .into_par_iter()
        .map(|i| match simulate_life(&pilot_case, &pilot, p.seed, i) {
            Ok(o) => (o.waves, o.simulated_waves),
            Err(_) => {
                let n = (storms as f64 * PILOT_WAVES_PER_STORM) as u64;
                (n, n)
            }
        })
        .reduce(|| (0, 0), |a, b| (a.0 + b.0, a.1 + b.1));
    if waves == 0 {
        1.0
    } else {
        simulated as f64 / waves as f64
    }
}

/// Heights, storms per height and waves per storm of the screen pilot of a fragility run.
const PILOT_LEVELS: usize = 16;
const PILOT_LEVEL_STORMS: usize = 4;
const PILOT_LEVEL_WAVES: usize = 32;

/// A fragility run (`fragility::run_fragility`).
pub fn fragility(case: &StormCase<'_>, p: &FragilityParams) -> WorkEstimate {
    let levels = p.heights_m.len();
    let n = p.waves_per_storm();
    let waves_drawn = (levels * p.storms * n) as f64;
    let share = if case.screen { fragility_screen_share(case, p) } else { 1.0 };
    let middle = p.heights_m.get(levels / 2).copied().unwrap_or(1.0);
    let steps_from =
        steps_from(case.structure, || storm_pilot(case, p.storm_input(case.model, middle).hmax_m, p.period_s));
    let simulated_s = waves_drawn * p.period_s * share * simulated_period_ratio(&p.periods);
    WorkEstimate {
        steps: simulated_s * steps_from.steps_per_s(),
        step_cost: step_cost(case.structure.foundation.springs),
        waves: waves_drawn,
        memory_bytes: (levels * p.storms) as f64 * BYTES_PER_LIFE,
        disk_bytes: 0.0,
        simulated_s,
        steps_from,
        simulated_share: share,
        basis: format!(
            "{levels} heights × {} storms × {n} waves, {:.3} % of them simulated (screen pilot){}",
            p.storms,
            100.0 * share,
            periods_basis(&p.periods)
        ),
    }
}

/// The share of a fragility run's waves that reach the dynamic model: the mean over up to 16
/// heights spread over the grid of their first storms, shortened (module docs).
fn fragility_screen_share(case: &StormCase<'_>, p: &FragilityParams) -> f64 {
    let coarse = coarse(case.structure);
    let pilot_case = StormCase { structure: &coarse, ..super::fragility::storm_case(case, p) };
    let levels = p.heights_m.len();
    let picked = levels.min(PILOT_LEVELS);
    let mut shares = Vec::with_capacity(picked);
    for k in 0..picked {
        let level = k * levels / picked;
        let (mut waves, mut simulated) = (0u64, 0u64);
        for j in 0..p.storms.min(PILOT_LEVEL_STORMS) {
            // Storm j's own errors (and climate), on fewer waves.
            let input = p.storm_input_of(case.model, p.heights_m[level], j);
            let input = super::lifetime::StormInput { waves: input.waves.min(PILOT_LEVEL_WAVES), ..input };
            let mut rng = realization_rng(p.seed, level * p.storms + j);
            match simulate_storm(&pilot_case, &input, &mut rng) {
                Ok(o) => {
                    waves += o.waves;
                    simulated += o.simulated_waves;
                }
                Err(_) => {
                    waves += input.waves as u64;
                    simulated += input.waves as u64;
                }
            }
        }
        shares.push(if waves == 0 { 1.0 } else { simulated as f64 / waves as f64 });
    }
    if shares.is_empty() {
        1.0
    } else {
        shares.iter().sum::<f64>() / shares.len() as f64
    }
}

/// A sizing run (`caisson size`, `sizing::size`): `candidates` widths (the grid and the
/// bisections: at most `curve_points + 2 · bisection_steps`), each one a design run of
/// `[size] lives` lives. `grid` are the design estimates ([`design`]) at the widths of the grid;
/// a bisection width lies between two of them, so each candidate counts as their mean. The
/// lives of one width are held at a time.
pub fn size(grid: &[WorkEstimate], candidates: usize) -> WorkEstimate {
    let n = grid.len().max(1) as f64;
    let k = candidates as f64 / n;
    let sum = |f: fn(&WorkEstimate) -> f64| grid.iter().map(f).sum::<f64>() * k;
    let first = grid.first();
    WorkEstimate {
        steps: sum(|e| e.steps),
        step_cost: first.map_or(1.0, |e| e.step_cost),
        waves: sum(|e| e.waves),
        memory_bytes: grid.iter().map(|e| e.memory_bytes).fold(0.0, f64::max),
        disk_bytes: 0.0,
        simulated_s: sum(|e| e.simulated_s),
        steps_from: first.map_or(StepsFrom::Pilot { steps_per_s: 0.0 }, |e| e.steps_from),
        simulated_share: grid.iter().map(|e| e.simulated_share).sum::<f64>() / n,
        basis: format!("{candidates} candidate widths × ({})", first.map_or_else(String::new, |e| e.basis.clone())),
    }
}

/// A table of wave loads (the Python `loads.evaluate`): `rows` waves of `bytes_per_row` each
/// (its columns), held until the call returns; no time step.
pub fn loads_table(rows: usize, bytes_per_row: f64) -> WorkEstimate {
    WorkEstimate {
        steps: 0.0,
        step_cost: 1.0,
        waves: rows as f64,
        memory_bytes: rows as f64 * bytes_per_row,
        disk_bytes: 0.0,
        simulated_s: 0.0,
        steps_from: StepsFrom::Pilot { steps_per_s: 0.0 },
        simulated_share: 0.0,
        basis: format!("{rows} waves × {bytes_per_row:.0} bytes of columns"),
    }
}
