//! A single run: build the model from a scenario, integrate, and collect the results the user
//! asks for (peaks always; the time histories on request: kept whole ([`History`]) or handed
//! row by row to the caller as the run proceeds ([`Rows`])).
//!
//! Definitions of the reported quantities:
//!
//! * **Permanent sliding**: at the end of the run, the mean slip position of the springs,
//!   (1/n) Σ s_i, a lifted spring counting at u_x (its slip position follows the base while it is
//!   off, and it re-contacts there). At rest under zero load every spring carries N̄ = W'/n (no
//!   moment, so no rotation), so unless a spring slips while the caisson settles this is exactly
//!   where it comes to rest (the stuck springs' forces κ N̄ (u_x − s_i) cancel), free of any
//!   residual vibration or rocking. Weighting s_i by the instantaneous normal forces instead
//!   would move with the rocking whenever the s_i differ (after lifted springs re-contact at a
//!   displaced u_x): up to 0.4 mm per wave on the design example.
//! * **Effective horizontal reaction**: the horizontal force the foundation carries (springs +
//!   horizontal dashpot); its peak is the "effective design load" of the seed.
//! * **Static sliding resistance** (seed Eq. 9): μ_s (W' − F_y(t)).
//! * **Slip event**: a step at which the caisson goes from no spring slipping to at least one.
//!
//! ```
//! // The seed's Table 5 caisson under a triangular push of 2.4 × its sliding resistance, 0.2 m
//! // above the base: it slides about 7 mm, and friction caps the base shear at μ W'.
//! use caisson::analysis::run::run;
//! use caisson::scenario::Scenario;
//! use std::path::Path;
//! let text = r#"
//! [caisson]
//! width_m = 0.78
//! height_m = 1.12
//! base_depth_m = 0.8
//! weight_in_water_kn = 8.24
//! [foundation]
//! e100_kpa = 3.5e5
//! [load]
//! kind = "triangle"
//! peak_horizontal_kn = 11.9
//! rise_time_s = 0.05
//! horizontal_lever_m = 0.2
//! "#;
//! let sc = Scenario::from_toml(text, Path::new("doc.toml"), Path::new(".")).unwrap();
//! let r = run(sc.structure(), sc.load.as_ref().unwrap(), sc.duration_s, false).unwrap();
//! assert!(r.summary.slip_events > 0 && r.summary.permanent_sliding_m > 5e-3);
//! assert!((r.summary.max_horizontal_reaction_n / (0.6 * 8240.0) - 1.0).abs() < 0.01);
//! ```

use super::Structure;
use crate::dynamics::{Model, Observer, Simulation, SolveError, SolverStats, StepView};
use crate::foundation::{Foundation, SpringResponse};
use crate::loads::LoadHistory;
use crate::structure::Caisson;

/// At most this many slip-event times are kept (all are counted).
pub const MAX_SLIP_TIMES: usize = 10_000;

/// Foundation quantities reported with every run.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct FoundationSummary {
    pub kx_n_per_m: f64,
    pub ky_n_per_m: f64,
    pub damping_ns_per_m: f64,
    /// Caisson mass in air, kg.
    pub mass_kg: f64,
    /// Hydrodynamic added mass on u_x, kg.
    pub added_mass_kg: f64,
    /// T0 = 2π sqrt((m + m_hyd)/K_x), s.
    pub natural_period_s: f64,
    /// W'/K_y, m.
    pub static_settlement_m: f64,
    /// μ_s W', N.
    pub static_sliding_resistance_n: f64,
}

impl FoundationSummary {
    pub fn new(c: &Caisson, f: &Foundation, m: &Model) -> Self {
        FoundationSummary {
            kx_n_per_m: f.stiffness.kx_n_per_m,
            ky_n_per_m: f.stiffness.ky_n_per_m,
            damping_ns_per_m: f.stiffness.damping_ns_per_m,
            mass_kg: c.mass_kg,
            added_mass_kg: f.added_mass.translation_kg,
            natural_period_s: m.natural_period_s(),
            static_settlement_m: m.static_settlement_m(),
            static_sliding_resistance_n: f.mu_static * c.weight_in_water_n,
        }
    }
}

/// Peaks and counts of one run (SI).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct RunSummary {
    pub permanent_sliding_m: f64,
    pub max_horizontal_displacement_m: f64,
    pub max_rotation_rad: f64,
    pub max_horizontal_reaction_n: f64,
    pub time_of_max_horizontal_reaction_s: f64,
    pub slip_events: u64,
    pub slip_event_times_s: Vec<f64>,
    /// Largest spring normal force over the run, N.
    pub max_spring_normal_n: f64,
    /// Smallest spring normal force over the run, N (0 = a spring lifted off).
    pub min_spring_normal_n: f64,
    /// Largest spring shear force magnitude, N.
    pub max_spring_shear_n: f64,
    /// Final state.
    pub final_displacement_m: f64,
    pub final_settlement_m: f64,
    pub final_rotation_rad: f64,
    pub duration_s: f64,
    pub foundation: FoundationSummary,
    pub solver: SolverStats,
    /// Largest ratio of the total-velocity dashpot force to the friction force while sliding.
    pub max_dashpot_over_friction: f64,
    /// Largest |moment| of the vertical and rotational dashpots, N·m.
    pub max_dashpot_moment_nm: f64,
    /// Largest |wave moment| about the base centre, N·m.
    pub max_wave_moment_nm: f64,
}

/// What a run (or the worst of several) found, for the plausibility checks
/// ([`super::checks::response_warnings`]).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct Response {
    /// Permanent sliding (or the largest in magnitude), m.
    pub sliding_m: f64,
    pub slip_events: u64,
    pub max_rotation_rad: f64,
    pub max_dashpot_over_friction: f64,
    pub max_dashpot_moment_nm: f64,
    pub max_wave_moment_nm: f64,
}

impl From<&RunSummary> for Response {
    fn from(r: &RunSummary) -> Self {
        Response {
            sliding_m: r.permanent_sliding_m,
            slip_events: r.slip_events,
            max_rotation_rad: r.max_rotation_rad,
            max_dashpot_over_friction: r.max_dashpot_over_friction,
            max_dashpot_moment_nm: r.max_dashpot_moment_nm,
            max_wave_moment_nm: r.max_wave_moment_nm,
        }
    }
}

/// Peak tracker (observer). Allocation-free per step once `slip_times` has its capacity.
#[derive(Debug, Clone)]
pub struct Peaks {
    pub max_ux: f64,
    pub max_theta: f64,
    pub max_rx: f64,
    pub t_max_rx: f64,
    pub slip_events: u64,
    pub slip_times: Vec<f64>,
    pub max_n: f64,
    pub min_n: f64,
    pub max_shear: f64,
    /// Largest ratio of the total-velocity dashpot force to the friction force while the caisson
    /// slides (every spring in contact slipping).
    pub max_dashpot_over_friction: f64,
    /// Largest |moment| of the vertical and rotational dashpots, N·m.
    pub max_dashpot_moment_nm: f64,
    /// Largest |wave moment| about the base centre, N·m.
    pub max_wave_moment_nm: f64,
    was_sliding: bool,
    /// The last observed step's end: time, displacements and velocities (the start of the next
    /// step's interpolant).
    last: Option<(f64, [f64; 3], [f64; 3])>,
}

/// The largest |p(t)| over a step of length `h` from p0 (rate v0) to p1 (rate v1) on the cubic
/// Hermite interpolant through the ends' values and rates (the peak between two step ends, which
/// the ends alone miss: docs/model.md §9.1): p(σ) = a σ³ + b σ² + c σ + p0 for σ = (t − t0)/h,
/// c = h v0, b = 3 (p1 − p0) − h (2 v0 + v1), a = 2 (p0 − p1) + h (v0 + v1); its extremes are at
/// the ends and at the roots of p'(σ) = 3 a σ² + 2 b σ + c within (0, 1).
#[inline]
fn hermite_peak(p0: f64, v0: f64, p1: f64, v1: f64, h: f64) -> f64 {
    let c = h * v0;
    let b = 3.0 * (p1 - p0) - h * (2.0 * v0 + v1);
    let a = 2.0 * (p0 - p1) + h * (v0 + v1);
    let at = |x: f64| ((a * x + b) * x + c) * x + p0;
    let mut peak = p0.abs().max(p1.abs());
    let mut consider = |x: f64| {
        if x > 0.0 && x < 1.0 {
            peak = peak.max(at(x).abs());
        }
    };
    let disc = b * b - 3.0 * a * c;
    if a.abs() <= 1e-12 * (b.abs() + c.abs()) {
        if b != 0.0 {
            consider(-c / (2.0 * b));
        }
    } else if disc >= 0.0 {
        // The roots without cancellation: q = −(b + sign(b) √disc), σ = q/(3a) and c/q.
        let q = -(b + disc.sqrt().copysign(b));
        consider(q / (3.0 * a));
        if q != 0.0 {
            consider(c / q);
        }
    }
    peak
}

impl Default for Peaks {
    fn default() -> Self {
        Peaks {
            max_ux: 0.0,
            max_theta: 0.0,
            max_rx: 0.0,
            t_max_rx: 0.0,
            slip_events: 0,
            slip_times: Vec::with_capacity(256),
            max_n: 0.0,
            min_n: f64::INFINITY,
            max_shear: 0.0,
            max_dashpot_over_friction: 0.0,
            max_dashpot_moment_nm: 0.0,
            max_wave_moment_nm: 0.0,
            was_sliding: false,
            last: None,
        }
    }
}

impl Observer for Peaks {
    #[inline]
    fn observe(&mut self, s: &StepView<'_>) {
        let (u, v) = (&s.state.u, &s.state.v);
        let (mut ux, mut theta) = (u[0].abs(), u[2].abs());
        // Between the last step's end and this one: the step's cubic Hermite interpolant.
        if let Some((t0, u0, v0)) = self.last.filter(|&(t0, _, _)| s.t_s > t0) {
            let h = s.t_s - t0;
            ux = hermite_peak(u0[0], v0[0], u[0], v[0], h);
            theta = hermite_peak(u0[2], v0[2], u[2], v[2], h);
        }
        self.last = Some((s.t_s, *u, *v));
        self.max_ux = self.max_ux.max(ux);
        self.max_theta = self.max_theta.max(theta);
        let rx = s.reaction.horizontal_n.abs();
        if rx > self.max_rx {
            self.max_rx = rx;
            self.t_max_rx = s.t_s;
        }
        let sliding = s.reaction.sliding_springs > 0;
        if sliding && !self.was_sliding {
            self.slip_events += 1;
            if self.slip_times.len() < MAX_SLIP_TIMES {
                self.slip_times.push(s.t_s);
            }
        }
        self.was_sliding = sliding;
        // Comparisons rather than f64::max/min (which also handle NaN, and cost several times
        // more): a committed step has finite spring forces (a non-finite residual is a failed
        // iteration), so both give the same peaks.
        let (mut max_n, mut min_n, mut max_shear) = (self.max_n, self.min_n, self.max_shear);
        let mut friction = 0.0;
        for r in s.springs {
            let shear = r.shear_n.abs();
            if r.normal_n > max_n {
                max_n = r.normal_n;
            }
            if r.normal_n < min_n {
                min_n = r.normal_n;
            }
            if shear > max_shear {
                max_shear = shear;
            }
            friction += shear;
        }
        (self.max_n, self.min_n, self.max_shear) = (max_n, min_n, max_shear);
        if sliding && s.reaction.sliding_springs == s.reaction.contact_springs && friction > 0.0 {
            self.max_dashpot_over_friction =
                self.max_dashpot_over_friction.max(s.reaction.dashpot_horizontal_n.abs() / friction);
        }
        self.max_dashpot_moment_nm = self.max_dashpot_moment_nm.max(s.reaction.dashpot_moment_nm.abs());
        self.max_wave_moment_nm = self.max_wave_moment_nm.max(s.load.m_nm.abs());
    }
}

/// One row of the time histories (SI): the state, loads and reactions of the committed step that
/// [`Sampler`] picks for an output interval. The columns of `history.csv` and `springs.csv`.
#[derive(Debug, Clone, Copy)]
pub struct HistoryRow<'a> {
    pub t_s: f64,
    pub ux_m: f64,
    pub uy_m: f64,
    pub theta_rad: f64,
    pub vx_m_per_s: f64,
    pub fx_n: f64,
    pub fy_n: f64,
    pub m_nm: f64,
    pub reaction_x_n: f64,
    pub reaction_y_n: f64,
    pub reaction_m_nm: f64,
    /// μ_s (W' − F_y(t)), N.
    pub sliding_resistance_n: f64,
    pub sliding_springs: u32,
    /// The springs' responses (normal and shear forces), seaward first.
    pub springs: &'a [SpringResponse],
    /// Spring positions, m.
    pub spring_x_m: &'a [f64],
}

impl HistoryRow<'_> {
    /// Vertical displacement of spring `i`, u_y − θ x_i, m.
    pub fn spring_uy_m(&self, i: usize) -> f64 {
        self.uy_m - self.theta_rad * self.spring_x_m[i]
    }
}

/// Picks the rows of the time histories: the first committed step at or after each
/// `output_interval_s`, from t = 0, and the last step of the run ([`Observer::finish`]) when the
/// run does not end on a row.
#[derive(Debug, Clone)]
pub struct Sampler {
    interval_s: f64,
    next_s: f64,
    /// The time of the last row, s (−∞ before the first).
    last_row_s: f64,
    weight_n: f64,
    mu_static: f64,
    spring_x_m: Vec<f64>,
}

impl Sampler {
    pub fn new(interval_s: f64, spring_x_m: Vec<f64>, weight_n: f64, mu_static: f64) -> Self {
        Sampler { interval_s, next_s: 0.0, last_row_s: f64::NEG_INFINITY, weight_n, mu_static, spring_x_m }
    }

    /// The rows of a run of `structure` (its solver's output interval).
    pub fn of(structure: &Structure) -> Self {
        let (c, f) = (&structure.caisson, &structure.foundation);
        Sampler::new(
            structure.solver.output_interval_s,
            f.spring_positions(c.width_m),
            c.weight_in_water_n,
            f.mu_static,
        )
    }

    /// Spring positions, m.
    pub fn spring_x_m(&self) -> &[f64] {
        &self.spring_x_m
    }

    /// Whether the step at `t_s` is the next row (if so, the next row is due an interval later).
    fn due(&mut self, t_s: f64) -> bool {
        if t_s + 1e-12 < self.next_s {
            return false;
        }
        while self.next_s <= t_s + 1e-12 {
            self.next_s += self.interval_s;
        }
        self.last_row_s = t_s;
        true
    }

    /// Whether the run's last step, at `t_s`, is not a row yet (then it is one).
    fn due_at_end(&mut self, t_s: f64) -> bool {
        let due = t_s > self.last_row_s;
        if due {
            self.last_row_s = t_s;
        }
        due
    }

    /// The row of step `s`.
    fn row<'a>(&'a self, s: &'a StepView<'_>) -> HistoryRow<'a> {
        let u = &s.state.u;
        HistoryRow {
            t_s: s.t_s,
            ux_m: u[0],
            uy_m: u[1],
            theta_rad: u[2],
            vx_m_per_s: s.state.v[0],
            fx_n: s.load.fx_n,
            fy_n: s.load.fy_n,
            m_nm: s.load.m_nm,
            reaction_x_n: s.reaction.horizontal_n,
            reaction_y_n: s.reaction.normal_n,
            reaction_m_nm: s.reaction.moment_nm,
            sliding_resistance_n: self.mu_static * (self.weight_n - s.load.fy_n),
            sliding_springs: s.reaction.sliding_springs as u32,
            springs: s.springs,
            spring_x_m: &self.spring_x_m,
        }
    }
}

/// An observer that hands every row of the time histories to `sink` as the run proceeds and
/// keeps none: the caller writes them out (or keeps a bounded picture of them,
/// [`super::envelope::HistoryEnvelope`]), so a run of any length holds no history in memory.
pub struct Rows<F> {
    sampler: Sampler,
    sink: F,
}

impl<F: FnMut(&HistoryRow<'_>)> Rows<F> {
    pub fn new(sampler: Sampler, sink: F) -> Self {
        Rows { sampler, sink }
    }
    /// The sink back.
    pub fn into_sink(self) -> F {
        self.sink
    }
}

impl<F: FnMut(&HistoryRow<'_>)> Observer for Rows<F> {
    fn observe(&mut self, s: &StepView<'_>) {
        if self.sampler.due(s.t_s) {
            let row = self.sampler.row(s);
            (self.sink)(&row);
        }
    }
    fn finish(&mut self, s: &StepView<'_>) {
        if self.sampler.due_at_end(s.t_s) {
            let row = self.sampler.row(s);
            (self.sink)(&row);
        }
    }
}

/// Time histories (SI) kept whole in memory, one row per output interval. Column-per-quantity
/// vectors of equal length. A long run is better streamed with [`Rows`].
#[derive(Debug, Clone)]
pub struct History {
    pub t_s: Vec<f64>,
    pub ux_m: Vec<f64>,
    pub uy_m: Vec<f64>,
    pub theta_rad: Vec<f64>,
    pub vx_m_per_s: Vec<f64>,
    pub fx_n: Vec<f64>,
    pub fy_n: Vec<f64>,
    pub m_nm: Vec<f64>,
    pub reaction_x_n: Vec<f64>,
    pub reaction_y_n: Vec<f64>,
    pub reaction_m_nm: Vec<f64>,
    /// μ_s (W' − F_y(t)), N.
    pub sliding_resistance_n: Vec<f64>,
    pub sliding_springs: Vec<u32>,
    /// Spring positions, m.
    pub spring_x_m: Vec<f64>,
    /// Per sample, n normal forces then n shear forces (row-major: sample × 2n).
    pub spring_forces_n: Vec<f64>,
    /// Per sample, n vertical spring displacements (u_y − θ x_i), m.
    pub spring_uy_m: Vec<f64>,
    sampler: Sampler,
}

impl History {
    pub fn new(interval_s: f64, expected_samples: usize, spring_x_m: Vec<f64>, weight_n: f64, mu_static: f64) -> Self {
        let n = spring_x_m.len();
        let cap = expected_samples + 2;
        let v = || Vec::with_capacity(cap);
        History {
            t_s: v(),
            ux_m: v(),
            uy_m: v(),
            theta_rad: v(),
            vx_m_per_s: v(),
            fx_n: v(),
            fy_n: v(),
            m_nm: v(),
            reaction_x_n: v(),
            reaction_y_n: v(),
            reaction_m_nm: v(),
            sliding_resistance_n: v(),
            sliding_springs: Vec::with_capacity(cap),
            spring_forces_n: Vec::with_capacity(cap * 2 * n),
            spring_uy_m: Vec::with_capacity(cap * n),
            sampler: Sampler::new(interval_s, spring_x_m.clone(), weight_n, mu_static),
            spring_x_m,
        }
    }

    pub fn len(&self) -> usize {
        self.t_s.len()
    }
    pub fn is_empty(&self) -> bool {
        self.t_s.is_empty()
    }
    pub fn springs(&self) -> usize {
        self.spring_x_m.len()
    }
}

impl Observer for History {
    fn observe(&mut self, s: &StepView<'_>) {
        if self.sampler.due(s.t_s) {
            self.push(s);
        }
    }
    fn finish(&mut self, s: &StepView<'_>) {
        if self.sampler.due_at_end(s.t_s) {
            self.push(s);
        }
    }
}

impl History {
    /// Step `s` as a row.
    fn push(&mut self, s: &StepView<'_>) {
        let r = self.sampler.row(s);
        self.t_s.push(r.t_s);
        self.ux_m.push(r.ux_m);
        self.uy_m.push(r.uy_m);
        self.theta_rad.push(r.theta_rad);
        self.vx_m_per_s.push(r.vx_m_per_s);
        self.fx_n.push(r.fx_n);
        self.fy_n.push(r.fy_n);
        self.m_nm.push(r.m_nm);
        self.reaction_x_n.push(r.reaction_x_n);
        self.reaction_y_n.push(r.reaction_y_n);
        self.reaction_m_nm.push(r.reaction_m_nm);
        self.sliding_resistance_n.push(r.sliding_resistance_n);
        self.sliding_springs.push(r.sliding_springs);
        self.spring_forces_n.extend(r.springs.iter().map(|x| x.normal_n));
        self.spring_forces_n.extend(r.springs.iter().map(|x| x.shear_n));
        self.spring_uy_m.extend((0..r.spring_x_m.len()).map(|i| r.spring_uy_m(i)));
    }
}

/// Both observers at once (the run and the wave-train drivers): the peaks and, if any, the
/// histories' observer.
pub(crate) struct Both<'a, O: Observer + ?Sized>(pub(crate) &'a mut Peaks, pub(crate) Option<&'a mut O>);

impl<O: Observer + ?Sized> Observer for Both<'_, O> {
    #[inline]
    fn observe(&mut self, s: &StepView<'_>) {
        self.0.observe(s);
        if let Some(h) = self.1.as_deref_mut() {
            h.observe(s);
        }
    }
}

/// The results of [`run`].
#[derive(Debug, Clone)]
pub struct RunResult {
    pub summary: RunSummary,
    pub history: Option<History>,
}

/// Permanent sliding from the committed state (see the module docs).
pub fn permanent_sliding_m(sim: &Simulation) -> f64 {
    let springs = &sim.state().springs;
    if springs.is_empty() {
        return sim.state().u[0];
    }
    springs.iter().map(|c| c.slip_m).sum::<f64>() / springs.len() as f64
}

/// The committed state of `sim` as a step for [`Observer::finish`].
pub(crate) fn final_view<'a, L: LoadHistory + ?Sized>(sim: &'a Simulation, load: &L) -> StepView<'a> {
    let t_s = sim.state().t_s;
    StepView {
        t_s,
        state: sim.state(),
        load: load.at(t_s),
        reaction: sim.reaction(),
        springs: sim.springs(),
        iterations: 0,
    }
}

/// Integrate `load` on `structure` for `duration_s` (from static equilibrium); with
/// `record_history`, keep the time histories whole in memory ([`History`]; a long run is better
/// streamed with [`run_observed`] and [`Rows`]).
pub fn run<L: LoadHistory + ?Sized>(
    structure: &Structure,
    load: &L,
    duration_s: f64,
    record_history: bool,
) -> Result<RunResult, SolveError> {
    let solver = structure.solver;
    let mut history = record_history.then(|| {
        let samples = (duration_s / solver.output_interval_s).ceil() as usize + 1;
        let (c, f) = (&structure.caisson, &structure.foundation);
        History::new(solver.output_interval_s, samples, f.spring_positions(c.width_m), c.weight_in_water_n, f.mu_static)
    });
    let summary = run_observed(structure, load, duration_s, history.as_mut())?;
    Ok(RunResult { summary, history })
}

/// [`run`] with an observer of its own (`rows`, e.g. [`Rows`] or a [`History`]) that sees the
/// initial static equilibrium at t = 0 and then every committed step.
pub fn run_observed<L: LoadHistory + ?Sized, O: Observer + ?Sized>(
    structure: &Structure,
    load: &L,
    duration_s: f64,
    mut rows: Option<&mut O>,
) -> Result<RunSummary, SolveError> {
    let (caisson, foundation, solver) = (&structure.caisson, &structure.foundation, structure.solver);
    let model = Model::new(caisson, foundation);
    let fsum = FoundationSummary::new(caisson, foundation, &model);
    let mut sim = Simulation::new(model, solver, load);
    let mut peaks = Peaks::default();
    if let Some(h) = rows.as_deref_mut() {
        // The initial (static equilibrium) state.
        let view = StepView {
            t_s: 0.0,
            state: sim.state(),
            load: load.at(0.0),
            reaction: sim.reaction(),
            springs: sim.springs(),
            iterations: 0,
        };
        h.observe(&view);
    }
    sim.run_until(duration_s, load, &mut Both(&mut peaks, rows.as_deref_mut()))?;
    if let Some(h) = rows {
        h.finish(&final_view(&sim, load));
    }
    let st = sim.state();
    Ok(RunSummary {
        permanent_sliding_m: permanent_sliding_m(&sim),
        max_horizontal_displacement_m: peaks.max_ux,
        max_rotation_rad: peaks.max_theta,
        max_horizontal_reaction_n: peaks.max_rx,
        time_of_max_horizontal_reaction_s: peaks.t_max_rx,
        slip_events: peaks.slip_events,
        slip_event_times_s: peaks.slip_times,
        max_spring_normal_n: peaks.max_n,
        min_spring_normal_n: if peaks.min_n.is_finite() { peaks.min_n } else { 0.0 },
        max_spring_shear_n: peaks.max_shear,
        final_displacement_m: st.u[0],
        final_settlement_m: -st.u[1],
        final_rotation_rad: st.u[2],
        duration_s,
        foundation: fsum,
        solver: sim.stats,
        max_dashpot_over_friction: peaks.max_dashpot_over_friction,
        max_dashpot_moment_nm: peaks.max_dashpot_moment_nm,
        max_wave_moment_nm: peaks.max_wave_moment_nm,
    })
}

#[cfg(test)]
mod tests {
    use super::hermite_peak;

    /// The Hermite interpolant reproduces a cubic: the peak of p(t) = 2 − (t − 0.3)² + 0.5 (t − 0.3)³
    /// over [0, 1] (at t = 0.3, p = 2, within rounding), and of its negative, read from the ends'
    /// values and rates alone; ends that are the extremes (a monotonic cubic) give the larger end;
    /// a sine of period 1 over a step of a tenth of it straddling its crest is read within 5e-4
    /// of 1 (measured 4.0e-4; the ends 0.951; the interpolant's error bound h⁴ max|p⁗|/384 is
    /// 4.1e-4). 4 cases.
    #[test]
    fn the_peak_of_the_interpolant_is_found_between_the_ends() {
        let p = |t: f64| 2.0 - (t - 0.3).powi(2) + 0.5 * (t - 0.3).powi(3);
        let dp = |t: f64| -2.0 * (t - 0.3) + 1.5 * (t - 0.3).powi(2);
        let mut checked = 0;
        for sign in [1.0, -1.0] {
            let peak = hermite_peak(sign * p(0.0), sign * dp(0.0), sign * p(1.0), sign * dp(1.0), 1.0);
            assert!((peak - 2.0).abs() <= 1e-14, "{peak}");
            checked += 1;
        }
        // Monotonic: p = t³ + t over [0, 2] (h = 2): the ends.
        assert_eq!(hermite_peak(0.0, 1.0, 10.0, 13.0, 2.0), 10.0);
        checked += 1;
        let w = 2.0 * std::f64::consts::PI;
        let (t0, h) = (0.2, 0.1);
        let peak = hermite_peak((w * t0).sin(), w * (w * t0).cos(), (w * (t0 + h)).sin(), w * (w * (t0 + h)).cos(), h);
        assert!((peak - 1.0).abs() <= 5e-4 && (w * t0).sin() < 0.96, "{peak}");
        checked += 1;
        assert_eq!(checked, 4);
    }
}
