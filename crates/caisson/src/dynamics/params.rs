//! Controls of the time integration (docs/model.md §9.1): the Newmark constants, the Newton-Raphson
//! iteration, sub-stepping and the step length, fixed or adaptive. Each `with_*` setter checks
//! what it sets and names the quantity when it refuses ([`ParamError`]).

use crate::check::{between, count, fail, positive, rule};
use crate::{Allowed, ParamError};

/// How the step length is chosen (see [`crate::dynamics`]).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum Stepping {
    /// Every step is `dt_s` (halved only when Newton-Raphson fails).
    Fixed,
    /// Local error control (Zienkiewicz & Xie 1991), landing on the load's breakpoints.
    Adaptive(AdaptiveParams),
}

/// Controls of the adaptive stepper.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct AdaptiveParams {
    /// Smallest step, s: a step this short is accepted whatever its error estimate.
    pub dt_min_s: f64,
    /// Largest step, s.
    pub dt_max_s: f64,
    /// Allowed local displacement error per step, m (rotation counted as θ·B/2). Default 5e-9 m:
    /// an undamped caisson rocking for hundreds of steps sums their errors of one sign, 1.05 % of
    /// its sliding at 1e-8 m on the worst case of `tests/verify_adaptive_accuracy.rs`, 0.54 % at
    /// 5e-9 m (docs/model.md §9.1).
    pub tolerance_m: f64,
}

impl Default for AdaptiveParams {
    fn default() -> Self {
        AdaptiveParams { dt_min_s: 1e-6, dt_max_s: 5e-3, tolerance_m: 5e-9 }
    }
}

impl AdaptiveParams {
    /// The defaults adjusted to a first step `dt_s`: dt_min ≤ dt_s ≤ dt_max.
    pub fn for_first_step(dt_s: f64) -> Self {
        let d = AdaptiveParams::default();
        AdaptiveParams { dt_min_s: d.dt_min_s.min(dt_s), dt_max_s: d.dt_max_s.max(dt_s), ..d }
    }
}

/// The first Newton iterate of a step (docs/model.md §9.1). Both converge to the same step
/// within the residual tolerance; they differ in how many corrections it takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Predictor {
    /// The displacement of the last step, δ = 0 (Chopra's u^(1) = u_i; the plain path's,
    /// [`Accel::none`]). About two corrections per step on the design example, where the spring
    /// shear κ N e is bilinear in the displacements.
    LastDisplacement,
    /// The acceleration of the last step carried over, q̈_{n+1} = q̈_n: δ = h q̇_n + h²/2 q̈_n.
    /// About one correction per step on the design example (the default).
    ConstantAcceleration,
}

/// The engine's accelerators: the fast paths that stand in for the plain path (Newmark steps,
/// each iterated by Newton from δ = 0 with the springs summed one by one; in a design or
/// fragility run, every wave drawn and run through the dynamic model), one field each, and what
/// each claims against it (ARCHITECTURE.md lists them; `tests/equiv_accel.rs` checks every claim
/// with each accelerator off in turn and all off). [`Accel::auto`] is every one on (the
/// default), [`Accel::none`] the plain path; a scenario picks one by `[solver] accel`. The
/// lifetime switches reach a run through [`crate::scenario::Scenario::storm_case`], which
/// resolves them into the [`crate::analysis::lifetime::StormCase`] (the screen only where
/// `[design] screen` has it too). Not results, so not reported (the screen and the drawing are
/// in a design's fingerprint through the `StormCase`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Accel {
    /// The first Newton iterate ([`Predictor`]): the constant-acceleration predictor, or off
    /// Chopra's δ = 0. Claims: the same step within the Newton tolerance.
    pub predictor: Predictor,
    /// While every spring is in contact and sticks, the resisting force and its tangent in closed
    /// form, and an all-sticking step solved directly (`dynamics::sticking`). Claims: within the
    /// Newton tolerance's reach (1e-6 of a value on the examples).
    pub sticking_fast_path: bool,
    /// Adaptive stepping: all-sticking phases advanced by exact steps (`dynamics::exact`, with
    /// its ladder of step lengths and its partial contact sets). Needs
    /// [`Self::sticking_fast_path`]; off under the `seed-2011` profile. Claims: within the
    /// adaptive tolerance's reach (a different step sequence, the same accuracy:
    /// `tests/verify_adaptive_accuracy.rs`).
    pub exact_sticking: bool,
    /// The exact steps' propagators shared per thread among caissons of the same matrices
    /// (`exact::Ladder::cached`). Claims: the same bits.
    pub cached_propagators: bool,
    /// Whether a spring's contact changes over a step, or may change ahead, read from the ends
    /// of the runs of springs in and out of contact (`Simulation::contact_may_change`,
    /// `Simulation::contact_ahead`). Claims: the same bits.
    pub contact_runs: bool,
    /// The lifetime screen (`analysis::lifetime`, "The screen"): a wave that provably neither
    /// slides nor lifts the caisson (nor presses its heel to the screen's heel pressure) is not
    /// run. Off, every wave is drawn and run (and the three below, which need it, are off).
    /// Claims, on the same waves (every wave drawn): the life's sliding within 1 µm, the rigid
    /// block's to rounding, the largest heel pressure the same where it reaches the screen's heel
    /// pressure; the counts of simulated and screened waves move.
    pub screen: bool,
    /// The screen's bound of the loads over all heights up to one (`PeriodLoads::peak_bound`): a
    /// storm's grid row left false where it holds up to H_max, else its nodes up to where it
    /// holds, by bisection, without their loads (`StormScreen::grid`). Claims: the same grid,
    /// so the same bits.
    pub screen_load_bound: bool,
    /// A screened storm draws only the waves above the lowest height its screen lets through,
    /// largest first (`WaveDraws::AboveThreshold`; off: every wave drawn and tested,
    /// `WaveDraws::EveryWave`). Claims: the same storms and the same distribution of every
    /// per-life output, not the same waves (`tests/equiv_lifetime.rs` holds the statistics
    /// within a few standard errors).
    pub draw_above_threshold: bool,
    /// The bound of the all-sticking response (`analysis::stick_bound`): a pulsating wave it
    /// shows sticking is not run (its rotation settled at the life's end). Claims: the same bits
    /// but the counts of simulated and screened waves (which move together) and the largest heel
    /// pressure below the screen's heel pressure (at most the one without the bound, as the
    /// screen has it).
    pub stick_bound: bool,
}

impl Accel {
    /// Every accelerator on (the default; `exact_sticking` then follows the profile).
    pub fn auto() -> Self {
        Accel {
            predictor: Predictor::ConstantAcceleration,
            sticking_fast_path: true,
            exact_sticking: true,
            cached_propagators: true,
            contact_runs: true,
            screen: true,
            screen_load_bound: true,
            draw_above_threshold: true,
            stick_bound: true,
        }
    }

    /// The plain path: every accelerator off.
    pub fn none() -> Self {
        Accel {
            predictor: Predictor::LastDisplacement,
            sticking_fast_path: false,
            exact_sticking: false,
            cached_propagators: false,
            contact_runs: false,
            screen: false,
            screen_load_bound: false,
            draw_above_threshold: false,
            stick_bound: false,
        }
    }
}

impl Default for Accel {
    fn default() -> Self {
        Accel::auto()
    }
}

/// Newmark and Newton-Raphson controls (docs/model.md §9.1).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SolverParams {
    /// Time step (fixed stepping) or first step (adaptive stepping), s.
    pub dt_s: f64,
    pub stepping: Stepping,
    /// Newmark γ (default ½) and β (default ¼): average acceleration.
    pub gamma: f64,
    pub beta: f64,
    /// The accelerators ([`Accel`]).
    #[serde(skip)]
    pub accel: Accel,
    /// Adaptive stepping: locate lift-off and re-contact within the step as the onsets of slip
    /// are; both steppings: locate the end of a slip, and give a spring that touches down within
    /// a step its slip position where it touches (docs/model.md §9.1, "Events"). Default on; off
    /// under the `seed-2011` profile. Part of the numerics of a results version, not reported.
    #[serde(skip)]
    pub locate_contact: bool,
    /// Newton iterations allowed per (sub)step before the step is sub-stepped.
    pub max_iterations: usize,
    /// Times a failing step may be halved (2^levels sub-steps at most) before the run fails.
    pub max_substep_levels: usize,
    /// Convergence tolerance on the residual, relative to the weight in water W'.
    pub tolerance: f64,
    /// Interval between recorded history samples, s.
    pub output_interval_s: f64,
}

impl Default for SolverParams {
    fn default() -> Self {
        SolverParams {
            dt_s: 1e-4,
            stepping: Stepping::Fixed,
            gamma: 0.5,
            beta: 0.25,
            accel: Accel::auto(),
            locate_contact: true,
            max_iterations: 30,
            max_substep_levels: 8,
            tolerance: 1e-9,
            output_interval_s: 1e-3,
        }
    }
}

/// At most this many steps of `dt_s` in one run: the fixed steps, or with adaptive stepping the
/// simulated time over its first step `dt_s` (docs/scenario.md).
pub const MAX_FIXED_STEPS: f64 = 1e9;

/// The shortest adaptive step `dt_min_s`, s, and so the shortest first step `dt_s` of adaptive
/// stepping.
pub const MIN_ADAPTIVE_DT_S: f64 = 1e-9;

/// The longest time step `dt_s`, s (as `dt_max_s` of adaptive stepping): a longer one cannot
/// follow a caisson's response, and far longer ones (1e156 s) lose the time itself to rounding.
pub const MAX_DT_S: f64 = 1.0;

/// `dt_s` > 0 and at most [`MAX_DT_S`].
fn time_step(dt_s: f64) -> Result<f64, ParamError> {
    let dt_s = positive("dt_s", dt_s)?;
    if dt_s > MAX_DT_S {
        return Err(rule("dt_s", dt_s, format!("must be at most {MAX_DT_S} (s)")));
    }
    Ok(dt_s)
}

impl SolverParams {
    /// The defaults with fixed steps of `dt_s` (> 0, at most 1 s); the output interval is at
    /// least `dt_s`.
    pub fn fixed(dt_s: f64) -> Result<Self, ParamError> {
        let dt_s = time_step(dt_s)?;
        let d = SolverParams::default();
        Ok(SolverParams { dt_s, output_interval_s: d.output_interval_s.max(dt_s), ..d })
    }

    /// Adaptive steps starting with `dt_s`: dt_max from dt_s to 1 s, dt_min from 1e-9 s to dt_s,
    /// the tolerance from 1e-12 to 1e-3 m.
    pub fn with_adaptive(mut self, p: AdaptiveParams) -> Result<Self, ParamError> {
        let dt = self.dt_s;
        // The first step is an adaptive step: at least the shortest one dt_min_s may be.
        if dt < MIN_ADAPTIVE_DT_S {
            return Err(rule(
                "dt_s",
                dt,
                format!("must be at least {} (s) with adaptive stepping: the shortest adaptive step (dt_min_s) is at least that", crate::fmt_value(MIN_ADAPTIVE_DT_S)),
            ));
        }
        let dt_shown = crate::fmt_value(dt);
        if !(p.dt_max_s.is_finite() && p.dt_max_s >= dt && p.dt_max_s <= 1.0) {
            return Err(rule(
                "dt_max_s",
                p.dt_max_s,
                format!("must be between {dt_shown} and 1 (s, from dt_s to 1 s)"),
            ));
        }
        if !(p.dt_min_s.is_finite() && p.dt_min_s >= MIN_ADAPTIVE_DT_S && p.dt_min_s <= dt) {
            return Err(rule(
                "dt_min_s",
                p.dt_min_s,
                format!(
                    "must be between {} and {dt_shown} (s, from {0} s to dt_s)",
                    crate::fmt_value(MIN_ADAPTIVE_DT_S)
                ),
            ));
        }
        between("error_tolerance_m", p.tolerance_m, 1e-12, 1e-3)?;
        self.stepping = Stepping::Adaptive(p);
        Ok(self)
    }

    /// The numerics of `profile`: [`Self::locate_contact`] and [`Accel::exact_sticking`] on under
    /// `consistent`, off under `seed-2011` (whose numbers reproduce the paper); the exact steps
    /// only with [`Accel::sticking_fast_path`], which they need (so [`Accel::none`] stays off).
    pub fn for_profile(mut self, profile: crate::Profile) -> Self {
        self.locate_contact = profile == crate::Profile::Consistent;
        self.accel.exact_sticking = self.locate_contact && self.accel.sticking_fast_path;
        self
    }

    /// The accelerators `accel`, as the profile has them ([`Self::for_profile`]: the exact steps
    /// are on only where it steps them and `accel` has them).
    pub fn with_accel(mut self, accel: Accel) -> Self {
        let exact = self.accel.exact_sticking;
        self.accel = Accel { exact_sticking: accel.exact_sticking && exact, ..accel };
        self
    }

    /// Newmark γ from ½ to 1 and β from γ/2 to ½ (unconditionally stable).
    pub fn with_newmark(mut self, gamma: f64, beta: f64) -> Result<Self, ParamError> {
        self.gamma = between("gamma", gamma, 0.5, 1.0)?;
        if !(beta.is_finite() && beta >= 0.5 * gamma && beta <= 0.5) {
            return Err(rule(
                "beta",
                beta,
                format!("must be between {} and 0.5 (-; unconditional stability needs 2·beta ≥ gamma)", 0.5 * gamma),
            ));
        }
        self.beta = beta;
        Ok(self)
    }

    /// Newton iterations per step (1 to 1000), and halvings of a failing step (0 to 20).
    pub fn with_iterations(mut self, max_iterations: usize, max_substep_levels: usize) -> Result<Self, ParamError> {
        self.max_iterations = count("max_iterations", max_iterations, 1, 1000)?;
        self.max_substep_levels = count("max_substep_levels", max_substep_levels, 0, 20)?;
        Ok(self)
    }

    /// The convergence tolerance relative to W', from 1e-15 to 1e-2.
    pub fn with_tolerance(mut self, tolerance: f64) -> Result<Self, ParamError> {
        self.tolerance = between("tolerance", tolerance, 1e-15, 1e-2)?;
        Ok(self)
    }

    /// The history sampling interval (checked against the run's duration by [`Self::check_run`]).
    pub fn with_output_interval_s(mut self, output_interval_s: f64) -> Self {
        self.output_interval_s = output_interval_s;
        self
    }

    /// The controls if `dt_s` is at most the simulated time `duration_s` (a rule of
    /// [`Self::check_run`], for a caller that checks it first).
    pub fn within(self, duration_s: f64) -> Result<Self, ParamError> {
        if self.dt_s > duration_s {
            let shown = crate::fmt_value(duration_s);
            return Err(rule("dt_s", self.dt_s, format!("must not exceed the simulated time {shown} s")));
        }
        Ok(self)
    }

    /// Check the controls against a run of `duration_s`: dt_s at most the duration, at most 1e9
    /// steps of dt_s (fixed or adaptive stepping: docs/scenario.md), and an output interval from
    /// dt_s to the duration.
    pub fn check_run(&self, duration_s: f64) -> Result<(), ParamError> {
        time_step(self.dt_s)?;
        self.within(duration_s)?;
        if duration_s / self.dt_s > MAX_FIXED_STEPS {
            let adaptive = if self.stepping == Stepping::Fixed { "" } else { " of dt_s (the first adaptive step)" };
            return Err(rule(
                "dt_s",
                self.dt_s,
                format!(
                    "gives {:.2e} steps{adaptive} for {} s; at most 1e9",
                    duration_s / self.dt_s,
                    crate::fmt_value(duration_s)
                ),
            ));
        }
        let hi = duration_s.max(self.dt_s);
        if !(self.output_interval_s.is_finite() && self.output_interval_s >= self.dt_s && self.output_interval_s <= hi)
        {
            return Err(fail(
                "output_interval_s",
                self.output_interval_s,
                Allowed::Rule(format!(
                    "must be between {} and {} (s, from dt_s to the simulated time)",
                    crate::fmt_value(self.dt_s),
                    crate::fmt_value(hi)
                )),
            ));
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One rule for a step longer than the run: [`SolverParams::within`] and
    /// [`SolverParams::check_run`] refuse dt_s = 0.5 s on a 0.4 s run naming `dt_s` with the same
    /// words, and allow it on a run of 0.5 s.
    #[test]
    fn a_step_longer_than_the_run_is_refused_naming_dt() {
        let s = SolverParams::fixed(0.5).unwrap();
        let e = s.within(0.4).unwrap_err();
        assert_eq!((e.quantity, e.value), ("dt_s", 0.5));
        assert_eq!(s.check_run(0.4), Err(e));
        assert!(s.within(0.5).is_ok() && s.check_run(0.5).is_ok());
    }
}
