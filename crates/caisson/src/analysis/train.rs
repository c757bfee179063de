//! One realization of a wave-train test: N_z waves from [`crate::loads::generator`] against the
//! caisson in **one continuous simulation** (the state carries from wave to wave), the sliding of
//! each wave, and the rigid-block reference beside it (seed §6; docs/model.md §6.3).
//!
//! * **Sliding per wave**: the permanent sliding ([`super::run::permanent_sliding_m`]) at the end
//!   of the wave minus that at its start. Every wave shape ends at zero load (τ = T), so the
//!   measure is taken with the caisson unloaded.
//! * **Rigid-block reference** ("Shimosako model"): the rigid-plastic block of Shimosako et al.
//!   (1994) / Shimosako & Takahashi (1999), docs/model.md §6.3, integrated on each wave's own load
//!   history from rest: it starts when P(t) > μ (W' − U(t)) and moves shoreward under
//!   (m_c + M_a) ẍ = P(t) − μ (W' − U(t)) until it stops, M_a = 1.0855 ρ_w h'² l, with one
//!   friction coefficient μ as in Shimosako & Takahashi's design practice (`[waves]
//!   rigid_block_mu`, default the foundation's μ_s = 0.6; §6.3 notes μ = 0.6 is the usual
//!   Japanese design value). Integrated
//!   by the trapezoidal rule in velocity (steps of T/2000, and 1/200 of the impulse through an
//!   impulse, landing on the load's breakpoints); the stop is located by linear interpolation of
//!   the velocity. The per-wave slides are summed (§6.3). A wave whose peak forces cannot reach
//!   the static resistance (max P ≤ μ_s (W' − max U)) is skipped: it cannot slide the block.

use super::rigid::RigidBlock;
use super::run::{permanent_sliding_m, Both, Peaks, Response};
use super::site::WaveSetup;
use super::{Progress, Structure};
use crate::dynamics::{Observer, Simulation, SolveError, SolverStats, StepView};
use crate::loads::generator::realization_waves;
use crate::loads::model::{WaveLoadError, WaveRecord};
use crate::loads::regime::RegimeError;
use crate::loads::LoadHistory;
use rayon::prelude::*;
use thiserror::Error;

/// Why a realization could not be run.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TrainRunError {
    #[error(transparent)]
    Regime(#[from] RegimeError),
    #[error(transparent)]
    Loads(#[from] WaveLoadError),
    #[error("realization {realization}")]
    Solve {
        realization: usize,
        #[source]
        source: SolveError,
    },
}

/// One wave of a realization.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct WaveOutcome {
    pub record: WaveRecord,
    /// Start of the wave in the realization, s.
    pub start_s: f64,
    /// Permanent sliding during this wave (dynamic model), m.
    pub sliding_m: f64,
    /// Rigid-block sliding under this wave's load (docs/model.md §6.3), m.
    pub rigid_block_sliding_m: f64,
    /// Peak effective horizontal reaction during this wave, N.
    pub max_horizontal_reaction_n: f64,
}

/// The results of one realization (SI).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct RealizationResult {
    pub index: usize,
    /// Total permanent sliding over the train, m.
    pub sliding_m: f64,
    /// Sum of the per-wave rigid-block slides, m.
    pub rigid_block_sliding_m: f64,
    pub max_horizontal_reaction_n: f64,
    pub slip_events: u64,
    /// Waves of a forced non-breaking train limited to the breaker height at the wall.
    pub limited_waves: usize,
    pub waves: Vec<WaveOutcome>,
    pub solver: SolverStats,
    /// What the plausibility checks need ([`Response`]).
    pub response: Response,
}

/// Tracks the peak reaction of the current wave beside the run's peaks.
struct WavePeak(f64);

impl Observer for WavePeak {
    #[inline]
    fn observe(&mut self, s: &StepView<'_>) {
        self.0 = self.0.max(s.reaction.horizontal_n.abs());
    }
}

struct Three<'a, O: Observer + ?Sized>(Both<'a, O>, &'a mut WavePeak);

impl<O: Observer + ?Sized> Observer for Three<'_, O> {
    #[inline]
    fn observe(&mut self, s: &StepView<'_>) {
        self.0.observe(s);
        self.1.observe(s);
    }
}

/// A wave-train test: a structure and its waves (realizations are numbered from 0).
#[derive(Debug, Clone, Copy)]
pub struct TrainCase<'a> {
    pub structure: &'a Structure,
    pub waves: &'a WaveSetup,
}

impl TrainCase<'_> {
    /// μ of the rigid-block reference.
    pub fn rigid_block_mu(&self) -> f64 {
        self.waves.rigid_block_mu(&self.structure.foundation)
    }

    /// Run realization `index`; `history` (a [`History`](super::run::History) or
    /// [`Rows`](super::run::Rows)) sees its initial state and every committed step.
    pub fn run(&self, index: usize, history: Option<&mut dyn Observer>) -> Result<RealizationResult, TrainRunError> {
        let w = self.waves;
        let drawn = realization_waves(&w.model, &w.train, w.regime(), index)?;
        let train = w.model.train(&drawn.records)?;
        let block = RigidBlock::new(&self.structure.caisson, w.model.site.rho_w, self.rigid_block_mu());
        let mut sim = Simulation::new(self.structure.model(), self.structure.solver, &train);
        let mut peaks = Peaks::default();
        let mut history = history;
        if let Some(h) = history.as_deref_mut() {
            let view = StepView {
                t_s: 0.0,
                state: sim.state(),
                load: train.at(0.0),
                reaction: sim.reaction(),
                springs: sim.springs(),
                iterations: 0,
            };
            h.observe(&view);
        }
        let mut waves = Vec::with_capacity(train.events().len());
        let mut before = permanent_sliding_m(&sim);
        for (e, record) in train.events().iter().zip(&drawn.records) {
            let mut wave_peak = WavePeak(0.0);
            sim.run_until(e.end_s(), &train, &mut Three(Both(&mut peaks, history.as_deref_mut()), &mut wave_peak))
                .map_err(|source| TrainRunError::Solve { realization: index, source })?;
            let after = permanent_sliding_m(&sim);
            waves.push(WaveOutcome {
                record: *record,
                start_s: e.start_s,
                sliding_m: after - before,
                rigid_block_sliding_m: block.wave_sliding_m(e),
                max_horizontal_reaction_n: wave_peak.0,
            });
            before = after;
        }
        if let Some(h) = history {
            h.finish(&super::run::final_view(&sim, &train));
        }
        Ok(RealizationResult {
            index,
            sliding_m: before,
            rigid_block_sliding_m: waves.iter().map(|w| w.rigid_block_sliding_m).sum(),
            max_horizontal_reaction_n: peaks.max_rx,
            slip_events: peaks.slip_events,
            limited_waves: drawn.limited_waves,
            response: Response {
                sliding_m: before,
                slip_events: peaks.slip_events,
                max_rotation_rad: peaks.max_theta,
                max_dashpot_over_friction: peaks.max_dashpot_over_friction,
                max_dashpot_moment_nm: peaks.max_dashpot_moment_nm,
                max_wave_moment_nm: peaks.max_wave_moment_nm,
            },
            waves,
            solver: sim.stats,
        })
    }

    /// Duration of a realization's train, s (for sizing a history).
    pub fn duration_s(&self) -> f64 {
        self.waves.train.waves as f64 * self.waves.train.period_s
    }
}

/// Run every realization of `case` in parallel (module docs of [`super`]); `progress` is called
/// once per finished realization.
pub fn run_realizations(case: &TrainCase<'_>, progress: Progress<'_>) -> Result<TrainSummary, TrainRunError> {
    let rs: Vec<RealizationResult> = (0..case.waves.train.realizations)
        .into_par_iter()
        // A progress callback that unwinds (a Python call stopped by Ctrl-C) stops the items not yet begun.
        .panic_fuse()
        .map(|r| {
            let out = case.run(r, None);
            progress();
            out
        })
        .collect::<Result<_, _>>()?;
    Ok(TrainSummary::new(rs))
}

/// Mean, minimum and maximum of a sample.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Spread {
    pub mean: f64,
    pub min: f64,
    pub max: f64,
}

impl Spread {
    pub fn of(values: impl IntoIterator<Item = f64>) -> Spread {
        let (mut n, mut sum, mut min, mut max) = (0usize, 0.0, f64::INFINITY, f64::NEG_INFINITY);
        for v in values {
            n += 1;
            sum += v;
            min = min.min(v);
            max = max.max(v);
        }
        if n == 0 {
            return Spread { mean: 0.0, min: 0.0, max: 0.0 };
        }
        Spread { mean: sum / n as f64, min, max }
    }
}

/// A test condition's realizations with their spread.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct TrainSummary {
    pub sliding_m: Spread,
    pub rigid_block_sliding_m: Spread,
    pub max_horizontal_reaction_n: Spread,
    pub slip_events: Spread,
    pub realizations: Vec<RealizationResult>,
}

impl TrainSummary {
    pub fn new(realizations: Vec<RealizationResult>) -> Self {
        TrainSummary {
            sliding_m: Spread::of(realizations.iter().map(|r| r.sliding_m)),
            rigid_block_sliding_m: Spread::of(realizations.iter().map(|r| r.rigid_block_sliding_m)),
            max_horizontal_reaction_n: Spread::of(realizations.iter().map(|r| r.max_horizontal_reaction_n)),
            slip_events: Spread::of(realizations.iter().map(|r| r.slip_events as f64)),
            realizations,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spread_of_a_sample() {
        let s = Spread::of([1.0, 3.0, 2.0]);
        assert_eq!((s.mean, s.min, s.max), (2.0, 1.0, 3.0));
    }
}
