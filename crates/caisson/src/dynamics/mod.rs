//! Time integration: Newmark-β with Newton-Raphson and a consistent tangent (seed §3.1;
//! docs/model.md §9.1, after Chopra 2001 §5.7 and Ch. 15).
//!
//! Equation of motion for q = (u_x, u_y, θ) of the base centre (see [`crate::structure`]):
//!
//! ```text
//! M q̈ + C q̇ + f_S(q, q̇) = p(t) + (0, −W', 0)
//! ```
//!
//! M is the caisson mass matrix plus the added mass of the water, C the linear dashpots
//! ([`crate::foundation`]), f_S the interface springs (and, in the `elastic` damping mode, their
//! dashpots), p the wave forces and W' the weight in water (docs/model.md §10 item 6).
//!
//! Each step t → t + h is explicit in its phases: **load** p(t + h) → **predictor** (by default
//! the last step's acceleration carried over, q̈_{n+1} = q̈_n, i.e. δ = h q̇_n + h²/2 q̈_n:
//! [`Predictor`]) → **Newton corrector** on the displacement increment δ = q_{n+1} − q_n, with
//!
//! ```text
//! q̈_{n+1} = δ/(β h²) − q̇_n/(β h) − (1/(2β) − 1) q̈_n
//! q̇_{n+1} = q̇_n + h [(1 − γ) q̈_n + γ q̈_{n+1}]
//! r = p − M q̈ − C q̇ − f_S,     K̂ = M/(β h²) + γ C/(β h) + ∂f_S/∂q,   K̂ Δδ = r
//! ```
//!
//! until max(|r_x|, |r_y|, |r_θ|/B) ≤ tol · W' → **commit** (copy the trial spring states). After
//! a step that left every spring in contact and sticking, the next one is first solved directly
//! as all-sticking (a quadratic in δ_x, `sticking`), and iterated only if a spring slips or lifts
//! there. A step
//! that does not converge in `max_iterations` is reverted (nothing was committed) and split in two
//! halves, recursively, at most `max_substep_levels` times; then the run fails with
//! [`SolveError::NonConvergence`] carrying the time and the residual. A non-finite residual
//! counts as non-convergence. No step is ever accepted unconverged.
//!
//! **Adaptive stepping** ([`Stepping::Adaptive`]): the local displacement error of a Newmark step
//! is estimated after Zienkiewicz & Xie (1991), e_{n+1} = (β − 1/6) h² (q̈_{n+1} − q̈_n)
//! (rotation counted as θ·B/2), and with it the error of the springs' slip positions
//! (`Simulation::slip_error_m`, docs/model.md §9.1): of a spring slipping at the step's end, u_x's
//! plus the trapezoidal rule's in its elastic displacement, h² κ N_i |ė_{n+1} − ė_n| / (12 c_d)
//! (with the dashpot beside the springs, the `elastic` mode); of a spring that touches down within
//! the step, λ (1 − λ) |h u̇_x,n − Δu_x|, the straight line's departure from the step's quadratic
//! where it touches (without [`SolverParams::locate_contact`], the `seed-2011` profile, where
//! such a spring takes u_x,n as its slip position, λ |Δu_x|). The largest is e. **In a sticking
//! phase** (a step that ends with every spring in contact and sticking; without
//! [`SolverParams::locate_contact`], the `seed-2011` profile, also one that ends with every
//! spring in contact sticking, some lifted; with it, such a step that neither lands on an event
//! nor changes the contact set, where the horizontal vibration outlives T_x/2: `adaptive`,
//! `coherent_partial_s`) Newmark's error is held per unit step: the
//! Zienkiewicz-Xie estimate times T_x/(2h) if h < T_x/2, T_x the horizontal mode's natural period
//! ([`Model::natural_period_s`]), so that the error summed over each half period is within the
//! tolerance (docs/model.md §9.1, "Sticking phases per unit step"); a touch-down's error (the
//! only slip position's error such a step can have) is once per event, held per step, e the
//! larger of the two (scaled too, that one, ∝ h, did not shrink with the step: grazing springs
//! of the 15-wave test drove the steps to dt_min, 16 of them accepted over the tolerance). That
//! error, about u̇_x times the time from the step's start to the touch, is the same for every
//! step that holds the touch: a step rejected for it is retaken to end just short of the first
//! touch over the tolerance (`before_touch_down`), not shortened by the estimate's ratio. There
//! the response is the quasi-static path plus a vibration on the springs, and Newmark's error is a
//! lag of that vibration's phase that every step adds with the same sign: held per step, the
//! sum over a phase of hundreds of steps reached 100 tolerances (5e-7 m against a vibration of
//! 6e-7 m) and moved the slip onset, which falls on a crest of the vibration, by 6 ms (+11 % of
//! the sliding on a `seed-2011` case of `tests/verify_adaptive_accuracy.rs`' random family).
//! The step ratio of such an estimate (∝ h²) is 0.9 (tol/‖e‖)^{1/2}, for accepted and rejected
//! steps alike. After an accepted step the next is
//! h·min(2, 0.9 (tol/‖e‖)^{1/3}) (at least 0.2 h; the cube root by `fast_cbrt`), within
//! [dt_min, dt_max]; after a step shortened to a breakpoint, or landed on an event (below), it may
//! grow past 2 h up to the step planned before it, or the step in which the event was found, so
//! that the fragment to an event (on the design example down to 6e-4 s of a planned 0.03 s) does
//! not restart the growth from itself. A converged step with ‖e‖∞ > tol is rejected
//! and retried with h·0.9 (tol/‖e‖)^{2/5} (within [0.1 h, 0.9 h]): nearly every rejection falls
//! on the first step after an event (305 of 314 on 67 lifting waves of the design example), where
//! a slip onset or a lift-off starts a transient of a few hundredths of a second and the estimate
//! grows with the step as h^2.4 to h^2.7, not h³; with the cube root 130 of the 314 were
//! rejected again (docs/model.md §9.1, "The step after an event"). No
//! step straddles a breakpoint of the load ([`LoadHistory::next_breakpoint_s`]: the start, peak
//! and end of an impulse), so a short impact cannot be stepped over. Small steps then fall where
//! the acceleration changes (impacts, slip onsets), large ones through the slowly varying
//! pulsating load. A step that fails to converge is halved as in the fixed mode (at most
//! `max_substep_levels` times in a row).
//!
//! **Sticking phases** ([`Accel::exact_sticking`], adaptive stepping): from a committed
//! state where every spring in contact sticks (all of them in contact, or with
//! [`SolverParams::locate_contact`] some lifted), a step of dt_max/2^k (k = 0 … 3: `exact`'s
//! ladder, one per contact set) with no load
//! breakpoint inside it is solved exactly (`exact`: the linear part by its matrix exponential,
//! the shear's bilinear remainder and the load interpolated quadratically), and kept if every
//! spring in contact sticks at its end and in its middle (and, springs lifted, at its quarter
//! points, with the contact set unchanged) and its error estimate is within the tolerance (else
//! the next shorter rung); otherwise the Newmark step is taken from the same state.
//!
//! **Events**: a converged step in which a spring that was in contact and sticking starts to
//! slip is not committed if the onset falls inside it: the friction margin of that spring held
//! sticking, g = κ N_i e_lim − |κ N_i e_i + c_d ė_i|, interpolated linearly between the step's
//! start (g_0 > 0) and end (g_1 < 0), puts the onset at θ = g_0/(g_0 − g_1) of the step; the
//! step is retaken to θ (1 + 1e-6) h, just past the earliest onset, then the rest of the
//! fixed step. The adaptive stepper instead lands on the event (`adaptive::Landing`): it retakes the step
//! until it ends past the event within its last hundredth, each length the root of the event's
//! margin g(s) at the ends of the steps tried (inverse quadratic interpolation through the last
//! three, else the Illinois rule) aimed 0.25 % of the step past it, at most 6 retakes. An onset
//! within 1 % of either end of the step (or within 1e-2 dt_s) is left where it falls; at most 16
//! onsets are located in a step. Without it, the force's kink (or with μ_d < μ_s its jump) at
//! the onset is smeared over the step and the sliding converges at first order. Located or not,
//! the jump at an onset inside a Newmark step is weighed by h/2 in its trapezoidal velocity
//! whatever the part of the step after it, (1 − θ) h: a first-order error of (θ − 1/2) h ΔF/m in
//! the velocity, largest on the step landed on the onset (θ ≈ 1), that later flights and
//! landings of a rocking caisson grow (1 % of u̇_x at the onset of all ten springs of
//! `tests/data/accuracy/pari_ten_springs.toml`, and the run 1.3 % off). The adaptive stepper
//! corrects each accepted step for it (`Simulation::correct_onset_jumps`: the dropped force,
//! weighed by 2θ_i − 1 for each spring's onset, taken out of the step by one Newton correction,
//! the acceleration restarted under the slipping force at its end); fixed steps do not (their
//! onsets land within 1e-6 of the step, an error of h/2 ΔF/m, first order in dt_s). With [`SolverParams::locate_contact`]
//! (adaptive stepping, the consistent profile) lift-off and re-contact are located the same way:
//! a spring's unclamped normal force N_i = −k_y u_y,i, linear in the step, changes sign at
//! θ = N_0/(N_0 − N_1); and the adaptive stepper anticipates them: before a step it extrapolates
//! each spring's u_y,i from the committed u_y,i, u̇_y,i, ü_y,i, and if it crosses 0 within the
//! step, plans the step to end 0.25 % past the crossing (kept if it ends short, landed on as
//! above if it passes the event by more than the step's last hundredth:
//! [`Simulation::contact_ahead`]). That makes the time of a lift exact, not whether a spring that
//! comes within rounding of N_i = 0 lifts: a lift resets its shear, so such runs still part by that
//! shear under rounding (docs/model.md §9.1). With `locate_contact` (both steppings) the end of a
//! slip is located too: a spring slipping at the step's start in the direction σ of its force,
//! with the slip rate ṡ = u̇_x − ė, σ ṡ_0 > 0, and at the end the rate of the slip it would have
//! gone on with, ṡ_1 = 2 (s_slip − s_n)/h − ṡ_0, σ ṡ_1 < 0: θ = ṡ_0/(ṡ_0 − ṡ_1); and a spring
//! lifted at the step's start and in contact at its end touches down within the step, at
//! λ = u_y,i,n/(u_y,i,n − u_y,i), with its slip position the caisson's u_x there
//! ([`crate::foundation::SpringLaw::trial_recontact`]), not u_x,n. Lift-off and re-contact are
//! located in fixed steps too; the step cut at one is solved with the vertical dashpots of the
//! springs in contact at its start, and the acceleration restarts across their jump at its end
//! ([`Simulation::restart_at_event`]; a change in a step's first hundredth restarts it at the
//! step's start, [`Simulation::restart_at_start`]), so that the jump is not weighted by h/2 in
//! Newmark's velocity (a first-order error).
//!
//! The time loop allocates nothing: all per-spring buffers live in [`Simulation`] and are sized
//! when it is built.
//!
//! **Cost of an iteration**: the resisting force is summed at every iterate (a pass over the
//! springs that stores their trial responses, then one that sums them: fewer values live in each,
//! the first compiled apart for steps that end at a located event), the tangent only when a
//! correction follows (another pass over the stored responses), and the base reaction only for
//! an observer that looks at the step ([`Observer::observes`]). Of the all-sticking closed form
//! (`sticking`) and the pass over the springs, the iterate tries first the one its predecessor
//! took (the first iterate of a step: the closed form unless the direct all-sticking step has just
//! failed); after the pass, the closed form is taken if it found every spring in contact and
//! sticking, so either order gives the same force, and the closed form's test, which fails on
//! nearly every iterate after one that took the pass, is mostly spared. The 3×3 solve is nalgebra's LU
//! with partial pivoting unrolled (`solve3`, identical to the last bit). Splitting the passes
//! changed no result: every sum has its terms in the same order as before. Whether a spring
//! changes contact over a converged step (its events, the dashpots' jump) is read from the runs of
//! springs in and out of contact at its two ends (u_y,i, rounded, is monotonic in x_i: each run
//! is told by its end springs and its length), and whether one may change within the step ahead
//! ([`Simulation::contact_ahead`]) from the ends of those runs with a margin above the rounding;
//! the springs are tested one by one only where these say one may: the same answers, so the same
//! numbers to the last bit.

mod adaptive;
mod exact;
mod params;
mod solve3;
mod sticking;

pub use params::{Accel, AdaptiveParams, Predictor, SolverParams, Stepping, MAX_FIXED_STEPS};

use crate::foundation::{DampingMode, Foundation, SpringLaw, SpringResponse, SpringState, VerticalDamping};
use crate::loads::{LoadHistory, WaveForce};
use crate::structure::Caisson;
use nalgebra::{Matrix3, Vector3};
use thiserror::Error;

/// Events located within one step of the fixed stepping (or in a row by the adaptive stepping):
/// a bound on the work of a step where many springs lift or slip one after the other.
const MAX_EVENTS_PER_STEP: usize = 16;

/// A step shortened to an event ends this fraction beyond it.
const EVENT_OVERSHOOT: f64 = 1e-6;
/// An event is located only if it splits the step into parts of at least this fraction of it.
const EVENT_MIN_FRACTION: f64 = 0.01;
/// Steps retaken to land on one event by the adaptive stepping (module docs, "Events").
const MAX_LOCATE_TRIES: usize = 6;
/// The adaptive stepping aims a step retaken to an event this fraction of it past the event's
/// estimate, a quarter of the window in which it is left (`EVENT_MIN_FRACTION`): a step that
/// ends short of the event is retaken again, one past it within the window is kept.
const EVENT_LEAD: f64 = 0.25 * EVENT_MIN_FRACTION;

/// What changes at an event (module docs, "Events").
#[derive(Debug, Clone, Copy, PartialEq)]
enum EventKind {
    /// A spring lifts off or touches down.
    Contact,
    /// A slipping spring stops slipping.
    SlipEnd,
    /// A sticking spring starts to slip.
    Onset,
}

/// The first event of a converged step ([`Simulation::event_fraction`]).
#[derive(Debug, Clone, Copy)]
struct Event {
    /// Where it falls, as a fraction of the step (found: just past it, `EVENT_OVERSHOOT`;
    /// anticipated: at it).
    theta: f64,
    spring: usize,
    kind: EventKind,
    /// Its margin at the step's start and end ([`Simulation::event_margins`]), signed so that
    /// g0 > 0 > g1.
    g0: f64,
    g1: f64,
}

/// Why a run stopped.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum SolveError {
    #[error("Newton-Raphson did not converge at t = {t_s:.6} s after {iterations} iterations and {levels} step halvings (residual {residual:.3e} N); try a smaller [solver] dt_s or a larger [solver] max_substep_levels")]
    NonConvergence { t_s: f64, iterations: usize, levels: usize, residual: f64 },
}

/// The assembled, immutable model: matrices, spring positions and law.
#[derive(Debug, Clone)]
pub struct Model {
    /// Total mass matrix (caisson + added mass), about the base centre.
    pub mass: Matrix3<f64>,
    /// Linear dashpots (diagonal).
    pub damping: Matrix3<f64>,
    /// Spring positions x_i, m (shoreward from the base centre).
    pub x_m: Vec<f64>,
    pub law: SpringLaw,
    /// Per-spring horizontal dashpot in the `elastic` mode, N·s/m (0 in the `total` mode).
    pub spring_dashpot_ns_per_m: f64,
    /// Per-spring vertical dashpot in the `springs` vertical-damping form, N·s/m (0 otherwise).
    pub spring_vertical_dashpot_ns_per_m: f64,
    /// W', N.
    pub weight_n: f64,
    pub mu_static: f64,
    pub mu_dynamic: f64,
    /// B, m (scales the moment residual).
    pub width_m: f64,
    /// Total stiffnesses K_x, K_y, N/m.
    pub kx_n_per_m: f64,
    pub ky_n_per_m: f64,
}

impl Model {
    pub fn new(c: &Caisson, f: &Foundation) -> Self {
        let mut m = Matrix3::from(c.mass_matrix()).transpose();
        let a = f.added_mass;
        m[(0, 0)] += a.translation_kg;
        m[(2, 2)] += a.rotation_kg_m2;
        if c.mass_matrix == crate::structure::MassMatrix::Coupled {
            m[(0, 2)] += a.coupling_kg_m;
            m[(2, 0)] += a.coupling_kg_m;
        }
        let x_m = f.spring_positions(c.width_m);
        let cc = f.stiffness.damping_ns_per_m;
        let cv = f.vertical_damping_factor * cc;
        let (c_y, c_theta, c_spring_y) = match f.vertical_damping {
            VerticalDamping::Seed => (cv, cv, 0.0),
            VerticalDamping::Springs => (0.0, 0.0, cv / f.springs as f64),
        };
        let (c_x, c_spring) = match f.damping_mode {
            DampingMode::Total => (cc, 0.0),
            DampingMode::Elastic => (0.0, cc / f.springs as f64),
        };
        Model {
            mass: m,
            damping: Matrix3::from_diagonal(&Vector3::new(c_x, c_y, c_theta)),
            law: SpringLaw::new(
                f.stiffness.kx_n_per_m,
                f.stiffness.ky_n_per_m,
                c.weight_in_water_n,
                f.springs,
                f.mu_static,
                f.mu_dynamic,
            ),
            x_m,
            spring_dashpot_ns_per_m: c_spring,
            spring_vertical_dashpot_ns_per_m: c_spring_y,
            weight_n: c.weight_in_water_n,
            mu_static: f.mu_static,
            mu_dynamic: f.mu_dynamic,
            width_m: c.width_m,
            kx_n_per_m: f.stiffness.kx_n_per_m,
            ky_n_per_m: f.stiffness.ky_n_per_m,
        }
    }

    /// Horizontal mass m_x (caisson + added), kg.
    pub fn horizontal_mass_kg(&self) -> f64 {
        self.mass[(0, 0)]
    }

    /// Undamped natural period of the horizontal mode alone, T0 = 2π sqrt(m_x / K_x), s.
    pub fn natural_period_s(&self) -> f64 {
        2.0 * std::f64::consts::PI * (self.horizontal_mass_kg() / self.kx_n_per_m).sqrt()
    }

    /// Undamped natural period of the rocking mode alone, T_θ = 2π sqrt(m_θ / K_θ) with m_θ the
    /// rotational inertia about the base centre (added inertia included) and K_θ = Σ k_y,i x_i²
    /// the springs' rocking stiffness, s (infinite for a single central spring).
    pub fn rocking_period_s(&self) -> f64 {
        let k_theta: f64 = self.x_m.iter().map(|x| self.law.ky_n_per_m * x * x).sum();
        2.0 * std::f64::consts::PI * (self.mass[(2, 2)] / k_theta).sqrt()
    }

    /// The factor f of the springs' lift-off test: under a static vertical load V (compression
    /// +) and moment M about the base centre the first spring lifts when (6 M / B) f ≥ V. Equal
    /// springs k at x_i (Σ x_i = 0) carry N_i = V/n + M x_i / Σ x_j², so the outermost one
    /// (x_max) lifts when M x_max n / Σ x_j² ≥ V: f = B n x_max / (6 Σ x_j²), which for n springs
    /// at the centres of n equal cells is n/(n + 1) (1 for a continuous linear base pressure);
    /// 1 when the springs have no lever arm.
    pub fn lift_off_factor(&self) -> f64 {
        let n = self.x_m.len() as f64;
        let sum_x2: f64 = self.x_m.iter().map(|x| x * x).sum();
        let x_max = self.x_m.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
        if sum_x2 > 0.0 && x_max > 0.0 {
            self.width_m * n * x_max / (6.0 * sum_x2)
        } else {
            1.0
        }
    }

    /// Static settlement under self-weight, W'/K_y, m (downward positive).
    pub fn static_settlement_m(&self) -> f64 {
        self.weight_n / self.ky_n_per_m
    }
}

/// The committed elastic rate ė_n of a spring beside its dashpot: its own while it slips, the
/// caisson's horizontal velocity `vx_n` while it sticks or is lifted (`foundation::spring`).
#[inline(always)]
fn elastic_rate(c: &SpringState, vx_n: f64) -> f64 {
    if c.sliding {
        c.rate_m_per_s
    } else {
        vx_n
    }
}

/// Whether the vertical dashpot beside a spring acts in a step: while the spring is in contact
/// at the trial (normal force `normal_n` > 0), or, in a step that ends at a located event
/// (`event_step`), while it was in contact at the step's start (its vertical displacement
/// `uy_start_m` < 0), so that the force is smooth over the step and jumps at its end
/// ([`Simulation::restart_at_event`]).
#[inline(always)]
fn dashpot_acts(event_step: bool, uy_start_m: f64, normal_n: f64) -> bool {
    if event_step {
        uy_start_m < 0.0
    } else {
        normal_n > 0.0
    }
}

/// x^(1/3) for x > 0, to about 1e-5 relative, without libm's `cbrt` (the step-size rule of the
/// adaptive stepper needs a few digits, and `cbrt` cost 10 % of the design run's instructions):
/// an estimate from the exponent bits (the bit pattern divided by 3, within 4 %), then two
/// Newton steps y ← y − (y³ − x)/(3 y²), each about squaring the relative error.
#[inline]
fn fast_cbrt(x: f64) -> f64 {
    let mut y = f64::from_bits(x.to_bits() / 3 + 0x2A9F_7893_782D_A1CE);
    for _ in 0..2 {
        y -= (y * y * y - x) / (3.0 * y * y);
    }
    y
}

/// Committed state: a plain snapshot (no scratch).
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct State {
    pub t_s: f64,
    /// q = (u_x m, u_y m, θ rad) of the base centre.
    pub u: [f64; 3],
    pub v: [f64; 3],
    pub a: [f64; 3],
    pub springs: Vec<SpringState>,
}

/// Base reactions of the foundation on the caisson at one instant.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Reaction {
    /// Horizontal reaction (springs + horizontal dashpot), N, positive when it resists a
    /// shoreward push (i.e. the force the caisson exerts on the foundation, shoreward +).
    pub horizontal_n: f64,
    /// Sum of the spring normal forces, N (compression +).
    pub normal_n: f64,
    /// Moment of the normal forces about the base centre, N·m, clockwise +.
    pub moment_nm: f64,
    /// Springs slipping.
    pub sliding_springs: usize,
    /// Springs in contact.
    pub contact_springs: usize,
    /// The horizontal dashpot on the total velocity (`damping_mode = "total"`), C u̇_x, N (0 in
    /// the `elastic` mode, whose dashpots are inside the springs' capped shear).
    pub dashpot_horizontal_n: f64,
    /// The moment of the vertical and rotational dashpots about the base centre, N·m, clockwise +
    /// (both `vertical_damping` forms).
    pub dashpot_moment_nm: f64,
}

/// What an observer sees after each committed (sub)step.
pub struct StepView<'a> {
    pub t_s: f64,
    pub state: &'a State,
    pub load: WaveForce,
    /// All zeros for an observer that does not read it ([`Observer::reads_reaction`]).
    pub reaction: Reaction,
    /// The springs' responses; empty on an all-sticking step for an observer that does not read
    /// them ([`Observer::reads_springs`]).
    pub springs: &'a [SpringResponse],
    pub iterations: usize,
}

/// Receives every committed step (peaks, decimated histories). Must not allocate per call in
/// production observers.
pub trait Observer {
    fn observe(&mut self, view: &StepView<'_>);
    /// Whether [`Self::observe`] looks at the steps at all; `false` spares the engine building
    /// the [`StepView`] (the base reaction) of every step.
    #[inline]
    fn observes(&self) -> bool {
        true
    }
    /// The run's last committed step again, after the run (the drivers call it): an observer
    /// that samples the steps (the time histories) keeps it if it did not already, so that its
    /// rows run to the end. Nothing by default.
    #[inline]
    fn finish(&mut self, _view: &StepView<'_>) {}
    /// Whether [`Self::observe`] reads [`StepView::springs`]; `false` spares the engine building
    /// the springs' responses of an all-sticking step (the slice is then empty).
    #[inline]
    fn reads_springs(&self) -> bool {
        true
    }
    /// Whether [`Self::observe`] reads [`StepView::reaction`]; `false` spares the engine summing
    /// the base reaction of every step (the view's is then [`Reaction::default`], all zeros).
    #[inline]
    fn reads_reaction(&self) -> bool {
        true
    }
}

/// No observer: a run that needs only its final state (the waves of a design run).
impl Observer for () {
    fn observe(&mut self, _: &StepView<'_>) {}
    #[inline]
    fn observes(&self) -> bool {
        false
    }
}

/// Solver statistics.
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct SolverStats {
    /// Committed steps (sub-steps included).
    pub steps: u64,
    pub newton_iterations: u64,
    /// Times a step was halved.
    pub substeps: u64,
    /// Largest converged residual, N.
    pub max_residual: f64,
    /// Deepest halving level used.
    pub max_substep_level: usize,
    /// Adaptive stepping: steps rejected by the error estimate.
    pub rejected_steps: u64,
    /// Adaptive stepping: steps accepted at dt_min with an error estimate above the tolerance.
    pub forced_min_steps: u64,
    /// Shortest and longest accepted steps, s.
    pub min_step_s: f64,
    pub max_step_s: f64,
    /// Onsets of slip located within a step (the step retaken to end at the onset: module
    /// docs); not reported (a measure of the engine's work).
    #[serde(skip)]
    pub located_events: u64,
    /// Newton iterates whose resisting force took the all-sticking fast path (`sticking`); not
    /// reported (a measure of the engine's work, not a result).
    #[serde(skip)]
    pub sticking_iterates: u64,
    /// All-sticking steps solved exactly (`exact`); not reported.
    #[serde(skip)]
    pub exact_steps: u64,
    /// Those of them with springs lifted (`exact`, "Partial contact"); not reported.
    #[serde(skip)]
    pub exact_partial_steps: u64,
}

/// A running simulation: model, solver controls, committed state and scratch.
pub struct Simulation {
    pub model: Model,
    pub solver: SolverParams,
    state: State,
    /// The springs' trial responses at the last iterate.
    trial: Vec<SpringResponse>,
    /// A spring slips in `trial` (the general path's last iterate): without one,
    /// [`Self::event_fraction`] has no slip onset to look for.
    trial_slips: bool,
    pub stats: SolverStats,
    gravity: Vector3<f64>,
    /// The all-sticking fast path's sums and scratch (`sticking`).
    fast: sticking::FastPath,
    /// Adaptive stepping with [`Accel::exact_sticking`]: the propagators of all-sticking
    /// steps of dt_max/2^k (`exact`).
    exact: Option<exact::Ladder>,
    /// What a run carries from one step to the next beside the state ([`Self::reset`] starts it
    /// afresh).
    run: RunMemory,
}

/// What a run carries from one step to the next beside its [`State`].
struct RunMemory {
    /// Adaptive stepping: the next step to try, s.
    h_next: f64,
    /// The last committed step, if it was exact (its end and R at its start: `exact`).
    exact_prev: Option<exact::Previous>,
    /// The load (gravity included) of the last step committed by the adaptive stepping, and its
    /// time.
    last_load: Option<(f64, Vector3<f64>)>,
    /// The step being tried ends at a located event: the springs' vertical dashpots act as at
    /// the step's start, and the acceleration restarts at its end ([`Simulation::restart_at_event`]).
    event_step: bool,
    /// The time of the last restart at a step's start ([`Simulation::restart_at_start`]).
    restarted_at_s: f64,
}

impl RunMemory {
    /// A run's start: the first step `dt_s`, nothing remembered.
    fn new(dt_s: f64) -> Self {
        RunMemory {
            h_next: dt_s,
            exact_prev: None,
            last_load: None,
            event_step: false,
            restarted_at_s: f64::NEG_INFINITY,
        }
    }
}

struct Converged {
    u: [f64; 3],
    v: [f64; 3],
    a: [f64; 3],
    iterations: usize,
    residual: f64,
}

impl Simulation {
    /// Start from static equilibrium under self-weight: u = (0, −W'/K_y, 0), every spring at rest
    /// with N̄ = W'/n, and q̈(0) from the equation of motion with the load at t = 0.
    pub fn new<L: LoadHistory + ?Sized>(model: Model, solver: SolverParams, load: &L) -> Self {
        let n = model.x_m.len();
        let state = State {
            t_s: 0.0,
            u: [0.0, -model.static_settlement_m(), 0.0],
            v: [0.0; 3],
            a: [0.0; 3],
            springs: vec![SpringState::default(); n],
        };
        let gravity = Vector3::new(0.0, -model.weight_n, 0.0);
        let fast = sticking::FastPath::new(&model.x_m);
        let mut sim = Simulation {
            model,
            solver,
            state,
            trial: vec![SpringResponse::default(); n],
            trial_slips: false,
            stats: SolverStats { min_step_s: f64::INFINITY, ..SolverStats::default() },
            gravity,
            fast,
            exact: None,
            run: RunMemory::new(solver.dt_s),
        };
        if let (Stepping::Adaptive(p), true) =
            (solver.stepping, solver.accel.exact_sticking && solver.accel.sticking_fast_path)
        {
            sim.exact = exact::Ladder::cached(&sim.model, p.dt_max_s, solver.accel.cached_propagators);
        }
        sim.reset(load);
        sim
    }

    /// Back to static equilibrium at t = 0 under `load` (as [`Self::new`]), keeping the model, the
    /// buffers and the accumulated statistics. Allocates nothing: for runs of many independent
    /// waves on one caisson.
    pub fn reset<L: LoadHistory + ?Sized>(&mut self, load: &L) {
        self.state.t_s = 0.0;
        self.state.u = [0.0, -self.model.static_settlement_m(), 0.0];
        self.state.v = [0.0; 3];
        self.state.a = [0.0; 3];
        self.state.springs.iter_mut().for_each(|s| *s = SpringState::default());
        self.run = RunMemory::new(self.solver.dt_s);
        self.fast.invalidate();
        if let Some(l) = self.exact.as_mut() {
            l.restart();
        }
        let p0 = self.load_vector(load.at(0.0));
        // The general path: it leaves the springs' responses of the static equilibrium.
        let f = self.general_force(self.state.u, [0.0; 3], self.solver.dt_s);
        let rhs = p0 - f;
        let a0 = self.model.mass.lu().solve(&rhs).unwrap_or_else(Vector3::zeros);
        self.state.a = [a0[0], a0[1], a0[2]];
        for (c, r) in self.state.springs.iter_mut().zip(&self.trial) {
            *c = r.state;
        }
        self.fast.direct = true;
    }

    pub fn state(&self) -> &State {
        &self.state
    }
    /// The base reaction of the committed step (of the static equilibrium after [`Self::new`]
    /// and [`Self::reset`]), from the springs' responses and the committed velocity.
    pub fn reaction(&self) -> Reaction {
        if let Some(r) = self.sticking_reaction() {
            return r;
        }
        let v = self.state.v;
        let cdy = self.model.spring_vertical_dashpot_ns_per_m;
        let mut reaction = Reaction::default();
        for (&x, r) in self.model.x_m.iter().zip(&self.trial) {
            if cdy > 0.0 && r.normal_n > 0.0 {
                let fd = cdy * (v[1] - v[2] * x);
                reaction.dashpot_moment_nm -= x * fd;
            }
            reaction.horizontal_n += r.shear_n;
            reaction.normal_n += r.normal_n;
            reaction.moment_nm += x * r.normal_n;
            reaction.contact_springs += (r.normal_n > 0.0) as usize;
            reaction.sliding_springs += (r.state.sliding && r.normal_n > 0.0) as usize;
        }
        reaction.dashpot_horizontal_n = self.model.damping[(0, 0)] * v[0];
        reaction.horizontal_n += reaction.dashpot_horizontal_n;
        reaction.dashpot_moment_nm += self.model.damping[(2, 2)] * v[2];
        reaction
    }
    /// [`Self::reaction`] for the observer `obs`'s view of the committed step: zeros if it does
    /// not read it ([`Observer::reads_reaction`]).
    #[inline]
    fn observed_reaction<O: Observer + ?Sized>(&self, obs: &O) -> Reaction {
        if obs.reads_reaction() {
            self.reaction()
        } else {
            Reaction::default()
        }
    }
    /// The springs' responses at the committed step (the static equilibrium after [`Self::new`]
    /// and [`Self::reset`]).
    pub fn springs(&self) -> &[SpringResponse] {
        &self.trial
    }

    #[inline]
    fn load_vector(&self, w: WaveForce) -> Vector3<f64> {
        Vector3::new(w.fx_n, w.fy_n, w.m_nm) + self.gravity
    }

    /// Resisting force f_S (springs, and their dashpots) at trial displacement `u` and velocity
    /// `v`, from the committed spring states: in closed form while every spring is in contact
    /// and sticks (`sticking`, when [`Accel::sticking_fast_path`]), else spring by spring.
    ///
    /// `stick_first`: the fast path's test is tried before the general path (the iterate is
    /// likely all-sticking); otherwise the general path goes first, and the fast path is taken
    /// after it only if it found every spring in contact and sticking, where the fast path's test
    /// (the spring law's own, `sticking`) says the same. Either order gives the same force to the
    /// last bit; the guess only spares the test that would fail (module docs, "Cost of an
    /// iteration").
    #[inline]
    fn resisting_force(&mut self, u: [f64; 3], v: [f64; 3], h: f64, stick_first: bool) -> Vector3<f64> {
        if !self.solver.accel.sticking_fast_path {
            return self.general_force(u, v, h);
        }
        if stick_first {
            if let Some(f) = self.sticking_force(u, v, h) {
                return f;
            }
            return self.general_force(u, v, h);
        }
        let f = self.general_force(u, v, h);
        if !self.trial_slips && self.trial.iter().all(|r| r.normal_n > 0.0) {
            if let Some(f) = self.sticking_force(u, v, h) {
                return f;
            }
        }
        f
    }

    /// [`Self::resisting_force`] spring by spring. Fills `self.trial` (what [`Self::tangent`]
    /// and [`Self::reaction`] are summed from).
    #[inline]
    fn general_force(&mut self, u: [f64; 3], v: [f64; 3], h: f64) -> Vector3<f64> {
        match (self.solver.locate_contact && self.committed_lifted(), self.run.event_step) {
            (true, false) => self.springs_force::<true, false, true>(u, v, h),
            (false, false) => self.springs_force::<false, false, true>(u, v, h),
            (true, true) => self.springs_force::<true, true, true>(u, v, h),
            (false, true) => self.springs_force::<false, true, true>(u, v, h),
        }
    }

    /// The springs' trial responses at the displacement `u` of a step of length `h`, as
    /// [`Self::general_force`] leaves them in `self.trial` (and `self.trial_slips`), without
    /// summing the force: for a step whose force is known otherwise, committed spring by spring
    /// (an exact step with springs lifted, `exact`; an all-sticking step from a state with
    /// slipping springs, [`Self::commit`]).
    #[inline]
    pub(super) fn general_trial(&mut self, u: [f64; 3], h: f64) {
        if self.solver.locate_contact && self.committed_lifted() {
            self.springs_force::<true, false, false>(u, [0.0; 3], h);
        } else {
            self.springs_force::<false, false, false>(u, [0.0; 3], h);
        }
    }

    /// Whether a spring is lifted (u_y,i ≥ 0) at the committed state: u_y,i is linear in x_i,
    /// so the outermost springs tell (the positions ascend: `Foundation::spring_positions`).
    #[inline]
    fn committed_lifted(&self) -> bool {
        let (uy, th) = (self.state.u[1], self.state.u[2]);
        match (self.model.x_m.first(), self.model.x_m.last()) {
            (Some(&lo), Some(&hi)) => uy - th * lo >= 0.0 || uy - th * hi >= 0.0,
            _ => false,
        }
    }

    /// [`Self::general_force`]; with `RECONTACT` a spring lifted at the step's start and in
    /// contact at the trial touches within the step (module docs, "Events"); `EVENT` is
    /// `self.run.event_step` ([`dashpot_acts`]); without `SUMS` only the trial responses (and
    /// `trial_slips`), the force returned 0 ([`Self::general_trial`]).
    #[inline]
    fn springs_force<const RECONTACT: bool, const EVENT: bool, const SUMS: bool>(
        &mut self,
        u: [f64; 3],
        v: [f64; 3],
        h: f64,
    ) -> Vector3<f64> {
        self.fast.iterate = None;
        let cd = self.model.spring_dashpot_ns_per_m;
        let c_prime = 2.0 * cd / h;
        let cdy = self.model.spring_vertical_dashpot_ns_per_m;
        let law = self.model.law;
        let (ux_n, vx_n) = (self.state.u[0], self.state.v[0]);
        let (uy_n, th_n) = (self.state.u[1], self.state.u[2]);
        let mut slips = false;
        for ((&x, c), out) in self.model.x_m.iter().zip(&self.state.springs).zip(self.trial.iter_mut()) {
            let uy = u[1] - u[2] * x;
            let uy_start = uy_n - th_n * x;
            // Elastic mode: the dashpot sits beside the spring, on its elastic displacement, with
            // the trapezoidal rate from ē_n = e_n + (h/2) ė_n (`foundation::spring`).
            let (mut r, e_bar, rho) = if RECONTACT && uy_start >= 0.0 && uy < 0.0 {
                // Lifted at the start, in contact at the trial: it touches within the step,
                // with its slip position where it touches.
                law.trial_recontact(ux_n, uy_start, u[0], uy, 0.5 * h * vx_n, c_prime)
            } else {
                let e_bar = ux_n - c.slip_m + 0.5 * h * elastic_rate(c, vx_n);
                (law.trial_with_dashpot(*c, u[0], uy, e_bar, c_prime), e_bar, 1.0)
            };
            if cd > 0.0 && r.state.sliding {
                r.state.rate_m_per_s = 2.0 * (u[0] - r.state.slip_m - e_bar) / (rho * h);
            }
            if !SUMS {
                slips |= r.state.sliding;
            }
            *out = r;
        }
        if !SUMS {
            self.trial_slips = slips;
            return Vector3::zeros();
        }
        // The sums, spring by spring in a second pass (fewer values live in the first).
        let (mut f0, mut f1, mut f2) = (0.0, 0.0, 0.0);
        for (&x, r) in self.model.x_m.iter().zip(&self.trial) {
            slips |= r.state.sliding;
            if cdy > 0.0 && dashpot_acts(EVENT, uy_n - th_n * x, r.normal_n) {
                // Vertical dashpot beside the spring: resisting force c (v_y − θ̇ x) on the
                // local vertical coordinate u_y − θ x.
                let fd = cdy * (v[1] - v[2] * x);
                f1 += fd;
                f2 -= x * fd;
            }
            f0 += r.shear_n;
            f1 -= r.normal_n;
            f2 += x * r.normal_n;
        }
        self.trial_slips = slips;
        Vector3::new(f0, f1, f2)
    }

    /// The tangent ∂f_S/∂q at the last iterate of [`Self::resisting_force`] for a step of length
    /// `h`: the springs' terms and, through v = q̇_n + γ/(β h) δ + ..., their vertical dashpots;
    /// summed from the trial responses in `self.trial`, or in closed form after an all-sticking
    /// iterate.
    #[inline]
    fn tangent(&self, h: f64) -> Matrix3<f64> {
        if let Some(it) = self.fast.iterate {
            return self.sticking_tangent(it, h);
        }
        let cdy = self.model.spring_vertical_dashpot_ns_per_m;
        let kd = cdy * (self.solver.gamma / (self.solver.beta * h));
        let (mut k00, mut k01, mut k02) = (0.0, 0.0, 0.0);
        let (mut k11, mut k12, mut k21, mut k22) = (0.0, 0.0, 0.0, 0.0);
        let (uy_n, th_n) = (self.state.u[1], self.state.u[2]);
        for (&x, r) in self.model.x_m.iter().zip(&self.trial) {
            if cdy > 0.0 && dashpot_acts(self.run.event_step, uy_n - th_n * x, r.normal_n) {
                k11 += kd;
                k12 -= x * kd;
                k21 -= x * kd;
                k22 += x * x * kd;
            }
            let (kxy, dn) = (r.dshear_duy, r.dnormal_duy);
            k00 += r.dshear_dux;
            k01 += kxy;
            k02 -= x * kxy;
            k11 -= dn;
            k12 += x * dn;
            k21 += x * dn;
            k22 -= x * x * dn;
        }
        Matrix3::new(k00, k01, k02, 0.0, k11, k12, 0.0, k21, k22)
    }

    /// Resisting force and tangent together (the finite-difference test of the tangent).
    #[cfg(test)]
    fn assemble(&mut self, u: [f64; 3], v: [f64; 3], h: f64) -> (Vector3<f64>, Matrix3<f64>) {
        let f = self.resisting_force(u, v, h, true);
        (f, self.tangent(h))
    }

    /// The first event of a converged step of length `h` (to `c`) (module docs, "Events"): the
    /// onset of a slip (a spring in contact and sticking at the step's start that slips at its
    /// end: the friction margin κ N_i e_lim − |F_i| of the spring held sticking, interpolated
    /// linearly over the step), with `contact` a lift-off or re-contact, and with
    /// [`SolverParams::locate_contact`] the end of a slip (the slip rate's sign change). `None`
    /// if there is none, or if it falls close to either end of the step.
    fn event_fraction(&self, h: f64, c: &Converged, contact: bool) -> Option<Event> {
        let mut first = Event { theta: 1.0, spring: 0, kind: EventKind::Contact, g0: 1.0, g1: -1.0 };
        let mut keep = |kind: EventKind, spring: usize, (g0, g1): (f64, f64)| {
            let theta = g0 / (g0 - g1);
            if theta < first.theta {
                first = Event { theta, spring, kind, g0, g1 };
            }
        };
        // Lift-off and re-contact: N_i = −k_y u_y,i (unclamped) is linear in the step's
        // displacements, so its root is where the straight line between the ends crosses 0. The
        // outermost springs tell whether any spring's contact changes (none: no spring to test).
        if contact && self.contact_may_change(self.state.u, c.u) {
            for i in 0..self.model.x_m.len() {
                let (g0, g1) = self.event_margins(EventKind::Contact, i, h, c);
                if (g0 > 0.0) != (g1 > 0.0) {
                    keep(EventKind::Contact, i, (g0, g1));
                }
            }
        }
        let all_stick = self.fast.iterate.is_some();
        if self.solver.locate_contact && self.committed_sliding() {
            // The end of a slip: a spring slipping at the step's start and in contact at its end.
            for (i, (&x, s)) in self.model.x_m.iter().zip(&self.state.springs).enumerate() {
                if !(s.sliding && c.u[1] - c.u[2] * x < 0.0) {
                    continue;
                }
                let (g0, g1) = self.event_margins(EventKind::SlipEnd, i, h, c);
                if g0 > 0.0 && g1 < 0.0 {
                    keep(EventKind::SlipEnd, i, (g0, g1));
                }
            }
        }
        if !all_stick && self.trial_slips {
            // The springs' responses at the converged iterate (the general path's) say which
            // ones slip at the step's end; only those that stuck at its start are measured (when
            // every spring sticks at the step's end, none; `trial_slips`, summed with them, says
            // whether one slips without walking them).
            let (un, law) = (self.state.u, self.model.law);
            let starts = self.model.x_m.iter().zip(&self.state.springs).zip(&self.trial).enumerate();
            for (i, _) in starts.filter(|(_, ((_, s), r))| r.state.sliding && !s.sliding && r.normal_n > 0.0) {
                let x = self.model.x_m[i];
                // The spring law's own tests: in contact while N > 0, sticking while the margin
                // ≥ 0 (a contact event in the step is located above).
                let n0 = -law.ky_n_per_m * (un[1] - un[2] * x);
                let n1 = -law.ky_n_per_m * (c.u[1] - c.u[2] * x);
                let (g0, g1) = self.event_margins(EventKind::Onset, i, h, c);
                if n0 > 0.0 && n1 > 0.0 && g0 > 0.0 && g1 < 0.0 {
                    keep(EventKind::Onset, i, (g0, g1));
                }
            }
        }
        let theta = self.event_within(first.theta, h)?;
        // Signed so that the margin is positive before the event (a re-contact's N_i < 0).
        let sign = first.g0.signum();
        Some(Event { theta, g0: sign * first.g0, g1: sign * first.g1, ..first })
    }

    /// The margin g of spring `i` for an event of `kind` at the start and the end of a converged
    /// step of length `h` (to `c`), whose sign change is the event (module docs, "Events"):
    ///
    /// * `Contact`: the unclamped normal force over the normal stiffness, −u_y,i;
    /// * `SlipEnd`: σ ṡ, the slip rate ṡ = u̇_x − ė in the direction σ of the force of a spring
    ///   slipping at the start, ṡ_0 there and at the end the rate of the slip it would have gone
    ///   on with, ṡ_1 = 2 (s_slip − s_n)/h − ṡ_0 (the trapezoidal rule, as the step's u_x): it
    ///   changes sign where the slip stops, whether the spring sticks at the end or, having
    ///   slipped more forward than back over the step, still slips there;
    /// * `Onset`: the friction margin κ N_i e_lim − |F_i| of the spring held sticking, at the
    ///   start with F = κ N e_n + c_d u̇_x,n (ē = e_n − (h/2) u̇_x,n), at the end from the step's
    ///   sticking trial.
    fn event_margins(&self, kind: EventKind, i: usize, h: f64, c: &Converged) -> (f64, f64) {
        let (un, vn) = (self.state.u, self.state.v);
        let (x, s, law) = (self.model.x_m[i], self.state.springs[i], self.model.law);
        let (uy0, uy1) = (un[1] - un[2] * x, c.u[1] - c.u[2] * x);
        let c_prime = 2.0 * self.model.spring_dashpot_ns_per_m / h;
        match kind {
            EventKind::Contact => (-uy0, -uy1),
            EventKind::SlipEnd => {
                let cd = self.model.spring_dashpot_ns_per_m;
                let kn0 = law.kappa_per_m * (-law.ky_n_per_m * uy0);
                let sign = (kn0 * (un[0] - s.slip_m) + cd * s.rate_m_per_s).signum();
                let rate0 = vn[0] - s.rate_m_per_s;
                let e_bar = un[0] - s.slip_m + 0.5 * h * s.rate_m_per_s;
                let slip1 = law.slipping_position(sign, c.u[0], uy1, e_bar, c_prime);
                let rate1 = 2.0 * (slip1 - s.slip_m) / h - rate0;
                (sign * rate0, sign * rate1)
            }
            EventKind::Onset => {
                let limit = law.limit_m(s);
                let e_n = un[0] - s.slip_m;
                let (_, g0) = law.stick_margin(s.slip_m, limit, un[0], uy0, e_n - 0.5 * h * vn[0], c_prime);
                let e_bar = e_n + 0.5 * h * elastic_rate(&s, vn[0]);
                let (_, g1) = law.stick_margin(s.slip_m, limit, c.u[0], uy1, e_bar, c_prime);
                (g0, g1)
            }
        }
    }

    /// The first lift-off or touch-down ahead of the committed state within a step of length `h`,
    /// predicted from the committed u_y,i, u̇_y,i and ü_y,i of each spring: the first root in
    /// (0, h) of the margin g(t) = −(u_y,i + u̇_y,i t + ü_y,i t²/2) (module docs, "Events"), with
    /// g0 and g(h) signed as [`Self::event_fraction`]'s.
    /// The ends of the runs of springs in and out of contact answer first
    /// ([`Self::contact_kept_ahead`]); the springs are tested one by one only if they do not.
    fn contact_ahead(&self, h: f64) -> Option<Event> {
        if self.solver.accel.contact_runs && self.contact_kept_ahead(h) {
            None
        } else {
            self.contact_ahead_each(h)
        }
    }

    /// [`Self::contact_ahead`] spring by spring.
    fn contact_ahead_each(&self, h: f64) -> Option<Event> {
        let (u, v, a) = (self.state.u, self.state.v, self.state.a);
        let mut first: Option<Event> = None;
        for (i, &x) in self.model.x_m.iter().enumerate() {
            let g0 = -(u[1] - u[2] * x);
            let sign = g0.signum();
            // g(t)·sign = g0 + d t + q t², g0 > 0.
            let (g0, d, q) = (sign * g0, -sign * (v[1] - v[2] * x), -0.5 * sign * (a[1] - a[2] * x));
            let gh = g0 + d * h + q * h * h;
            if gh.is_nan() || gh >= 0.0 {
                continue;
            }
            // One root in (0, h) (g0 > 0 > g(h)), by the cancellation-free forms of the formula.
            let disc = (d * d - 4.0 * q * g0).max(0.0).sqrt();
            let t = [2.0 * g0 / (-d + disc), 2.0 * g0 / (-d - disc)]
                .into_iter()
                .filter(|t| *t > 0.0 && *t < h)
                .fold(f64::INFINITY, f64::min);
            if t.is_finite() && first.is_none_or(|e| t < e.theta * h) {
                first = Some(Event { theta: t / h, spring: i, kind: EventKind::Contact, g0, g1: gh });
            }
        }
        first
    }

    /// Whether no spring can change contact ahead within a step of length `h` in
    /// [`Self::contact_ahead`]'s extrapolation: the test of the ends of the runs of springs in and
    /// out of contact, and the same answer as every spring's. The committed u_y,i = u_y − θ x_i,
    /// rounded, is monotonic in x_i (as in [`Self::contact_may_change`]), so the springs in contact
    /// form one run and those out of it another (the positions ascend); the extrapolated
    /// u_y,i(h) = u_y,i + u̇_y,i h + ü_y,i h²/2 is linear in x_i, so within a run it lies between
    /// its values at the run's ends. `true` when at both ends of both runs it stays on its side
    /// by more than 1e-12 of M = |u_y| + |θ| x̂ + h (|u̇_y| + |θ̇| x̂) + h²/2 (|ü_y| + |θ̈| x̂) (x̂ the
    /// largest |x_i|), far more than the rounding of any spring's margin (a few units in the last
    /// place of M): then no spring's margin at h, as [`Self::contact_ahead`] rounds it, changes
    /// sign. Else `false` (the springs are tested one by one).
    #[inline]
    fn contact_kept_ahead(&self, h: f64) -> bool {
        let (u, v, a) = (self.state.u, self.state.v, self.state.a);
        let xs = &self.model.x_m[..];
        let (Some(&lo), Some(&hi)) = (xs.first(), xs.last()) else {
            return true;
        };
        let x_hat = lo.abs().max(hi.abs());
        let m = (u[1].abs() + u[2].abs() * x_hat)
            + h * (v[1].abs() + v[2].abs() * x_hat)
            + 0.5 * h * h * (a[1].abs() + a[2].abs() * x_hat);
        let margin = 1e-12 * m;
        // The margin at h of the spring at x, signed positive on its side at the start
        // (as `contact_ahead`'s g(h)), and whether it starts off the threshold.
        let kept = |x: f64| {
            let g0 = -(u[1] - u[2] * x);
            let sign = g0.signum();
            let (g0, d, q) = (sign * g0, -sign * (v[1] - v[2] * x), -0.5 * sign * (a[1] - a[2] * x));
            g0 != 0.0 && g0 + d * h + q * h * h > margin
        };
        // The first spring whose contact differs from the first one's (monotonic: a partition).
        let first_in = u[1] - u[2] * lo < 0.0;
        let k = xs.partition_point(|&x| (u[1] - u[2] * x < 0.0) == first_in);
        kept(lo) && kept(hi) && (k == xs.len() || (kept(xs[k - 1]) && kept(xs[k])))
    }

    /// The event at the fraction `theta` of a step of length `h`, if it is one to locate (module
    /// docs, "Events").
    fn event_within(&self, theta: f64, h: f64) -> Option<f64> {
        // Just past the event, so that the step's end is not within rounding of the spring
        // law's threshold (which side it fell on would then be decided by rounding).
        let theta = theta * (1.0 + EVENT_OVERSHOOT);
        // Neither part of the step shorter than a hundredth of it, nor than a hundredth of dt_s
        // (shorter steps add work and rounding, and gain little accuracy).
        let floor = EVENT_MIN_FRACTION.max(1e-2 * self.solver.dt_s / h);
        (theta >= floor && theta <= 1.0 - floor).then_some(theta)
    }

    /// The local error of the springs' slip positions over a converged step of length `h` to
    /// `c` (module docs, adaptive stepping), m, given `ux_error_m`, the Zienkiewicz-Xie estimate
    /// of u_x's:
    ///
    /// * a spring slipping at the step's end has s_i = u_x − e_i, so its error is u_x's plus
    ///   that of the trapezoidal rule for its elastic displacement: on a slip c_d ė = F − κ N e
    ///   relaxes e with the time constant τ = c_d/(κ N), so d³e/dt³ = −ë/τ and the rule's error
    ///   h³ |d³e/dt³|/12 is h² |ė_{n+1} − ė_n| / (12 τ) (0 without a dashpot beside the
    ///   springs). The committed rate ė_{n+1} is e's over τ: held with e;
    /// * a spring re-contacting within the step takes the straight line's u_x where it touches,
    ///   at the fraction λ of the step (`foundation::spring`, "Re-contact"); the step's own
    ///   u_x is the quadratic u_x,n + λ h u̇_x,n + λ² (Δu_x − h u̇_x,n), λ (1 − λ) |h u̇_x,n − Δu_x|
    ///   from the line; without [`SolverParams::locate_contact`] (the `seed-2011` profile) it
    ///   takes u_x,n, λ |Δu_x| from where it touches (issue 34: unseen, a caisson rocking on its
    ///   springs slid back by where the steps fell, up to 7.5 % on
    ///   `tests/data/accuracy/pari_ten_springs.toml`).
    ///
    /// 0 when every spring sticks at the step's end (no slip position moved).
    fn slip_error_m(&self, h: f64, c: &Converged, ux_error_m: f64) -> f64 {
        if self.fast.iterate.is_some() {
            // Every spring in contact and sticking at the step's end: none slipped; without
            // located contact a spring lifted at its start touched down (the closed form gives it
            // u_x,n as its slip position, as spring by spring).
            if self.solver.locate_contact || !self.committed_lifted() {
                return 0.0;
            }
            let (un, mut touch) = (self.state.u, 0.0f64);
            for &x in &self.model.x_m {
                let uy_start = un[1] - un[2] * x;
                if uy_start >= 0.0 {
                    touch = touch.max(uy_start / (uy_start - (c.u[1] - c.u[2] * x)));
                }
            }
            return touch * (c.u[0] - un[0]).abs();
        }
        let recontact = self.committed_lifted();
        if !recontact && !self.trial_slips {
            // No spring slips at the step's end (`trial_slips` is false only then) and none
            // touches down within it: the sums below would be 0.
            return 0.0;
        }
        let locate = self.solver.locate_contact;
        let cd = self.model.spring_dashpot_ns_per_m;
        let (un, vx_n) = (self.state.u, self.state.v[0]);
        let chord = (h * vx_n - (c.u[0] - un[0])).abs();
        let (mut rate, mut touch) = (0.0f64, 0.0f64);
        let mut slipping = false;
        for ((&x, s), r) in self.model.x_m.iter().zip(&self.state.springs).zip(&self.trial) {
            if r.normal_n <= 0.0 {
                continue;
            }
            if r.state.sliding {
                slipping = true;
                if cd > 0.0 {
                    let kn = self.model.law.kappa_per_m * r.normal_n;
                    rate = rate.max(kn * (r.state.rate_m_per_s - elastic_rate(s, vx_n)).abs());
                }
            }
            let uy_start = un[1] - un[2] * x;
            if recontact && uy_start >= 0.0 {
                let lambda = uy_start / (uy_start - (c.u[1] - c.u[2] * x));
                touch = touch.max(if locate { lambda * (1.0 - lambda) } else { lambda });
            }
        }
        let slip = if slipping { ux_error_m + h * h * rate / (12.0 * cd.max(f64::MIN_POSITIVE)) } else { 0.0 };
        // Located, the touch-down's error is the line's departure from the step's quadratic;
        // not located (`seed-2011`), the spring takes u_x,n, λ Δu_x from where it touches.
        slip.max(touch * if locate { chord } else { (c.u[0] - un[0]).abs() })
    }

    /// Newton-Raphson for one step of length `h` to load `p`. Commits nothing.
    fn try_step(&mut self, h: f64, p: Vector3<f64>) -> Result<Converged, (usize, f64)> {
        let (beta, gamma) = (self.solver.beta, self.solver.gamma);
        let c1 = 1.0 / (beta * h * h);
        let c2 = 1.0 / (beta * h);
        let c3 = 0.5 / beta - 1.0;
        let un = Vector3::from(self.state.u);
        let vn = Vector3::from(self.state.v);
        let an = Vector3::from(self.state.a);
        let tol = self.solver.tolerance * self.model.weight_n;
        let inv_b = 1.0 / self.model.width_m;
        if self.solver.accel.sticking_fast_path && self.fast.direct {
            if let Some(c) = self.direct_sticking_step(h, p, tol) {
                return Ok(c);
            }
        }
        // M and C read in place (not copied per step), K_dyn only for a step that iterates.
        let k_dyn = self.model.mass * c1 + self.model.damping * (gamma * c2);
        let mut delta = match self.solver.accel.predictor {
            Predictor::LastDisplacement => Vector3::zeros(),
            Predictor::ConstantAcceleration => vn * h + an * (0.5 * h * h),
        };
        let mut norm = f64::INFINITY;
        for it in 0..=self.solver.max_iterations {
            let a = delta * c1 - vn * c2 - an * c3;
            let v = vn + (an * (1.0 - gamma) + a * gamma) * h;
            let u = un + delta;
            // The fast path's test first where it mostly holds (on the design example, 99 % of
            // the iterates after an all-sticking one; 21 % of the first iterates of a step from a
            // state with slipping springs; none after the direct step failed, or after an iterate
            // with a spring slipping or lifted).
            let stick_first = if it == 0 { !self.fast.direct } else { self.fast.iterate.is_some() };
            let fs = self.resisting_force([u[0], u[1], u[2]], [v[0], v[1], v[2]], h, stick_first);
            let r = p - self.model.mass * a - self.model.damping * v - fs;
            norm = r[0].abs().max(r[1].abs()).max(r[2].abs() * inv_b);
            if !norm.is_finite() {
                return Err((it, norm));
            }
            if norm <= tol {
                return Ok(Converged { u: u.into(), v: v.into(), a: a.into(), iterations: it, residual: norm });
            }
            if it == self.solver.max_iterations {
                break;
            }
            match solve3::lu_solve(&(k_dyn + self.tangent(h)), &r) {
                Some(d) => delta += d,
                None => return Err((it, norm)),
            }
        }
        Err((self.solver.max_iterations, norm))
    }

    fn commit(&mut self, h: f64, mut c: Converged) {
        if self.run.event_step {
            c.a = self.restart_at_event(&c);
        }
        if self.fast.iterate.is_some() && !self.sticking_commit_possible() {
            // All-sticking from a state with slipping springs: their responses need their own
            // committed rates, so the step is committed spring by spring (`sticking`).
            self.general_trial(c.u, h);
        }
        if self.fast.iterate.is_some() {
            self.commit_sticking(h, self.state.u[0], self.state.v[0]);
            self.fast.direct = true;
        } else {
            for (s, r) in self.state.springs.iter_mut().zip(&self.trial) {
                *s = r.state;
            }
            self.fast.invalidate();
            self.fast.direct = self.trial.iter().all(|r| !r.state.sliding && r.normal_n > 0.0);
        }
        self.state.t_s += h;
        self.state.u = c.u;
        self.state.v = c.v;
        self.state.a = c.a;
        self.stats.steps += 1;
        self.stats.min_step_s = self.stats.min_step_s.min(h);
        self.stats.max_step_s = self.stats.max_step_s.max(h);
        self.stats.newton_iterations += c.iterations as u64;
        self.stats.max_residual = self.stats.max_residual.max(c.residual);
    }

    /// The acceleration after a step to a located event (converged to `c`), where a spring
    /// touched down or lifted: the step was solved with the vertical dashpots of the springs in
    /// contact at its start ([`dashpot_acts`]), so `c.a` is the acceleration on the event's near
    /// side; the displacements and velocities are continuous across it and the force jumps by
    /// the dashpot of each spring that changed, ΔF = ± c_y (v_y − θ̇ x_i) (0, 1, −x_i) (+ for a
    /// touch-down), so the next step starts from q̈⁺ = q̈⁻ − M⁻¹ ΔF. Otherwise Newmark's
    /// trapezoidal velocity would weight the jump by h/2 in the step to the event whatever its
    /// length, a first-order error (docs/model.md §9.1, "Events").
    fn restart_at_event(&self, c: &Converged) -> [f64; 3] {
        let da = self.dashpot_jump(self.state.u, c.u, c.v, f64::INFINITY);
        [c.a[0] - da[0], c.a[1] - da[1], c.a[2] - da[2]]
    }

    /// The converged Newmark step `c` of length `h` corrected for the friction's jump at the
    /// slip onsets within it (module docs, "Events"; docs/model.md §9.1): with μ_d < μ_s the
    /// force of a spring that starts to slip drops at the onset, by ΔF_i = ±κ N_i (e_s − e_d),
    /// and the step's trapezoidal velocity weighs the end's acceleration (after the drop) by
    /// h/2 whatever the part of the step after it, (1 − θ_i) h for an onset at the fraction θ_i:
    /// an error of (θ_i − 1/2) h ΔF_i/m in the velocity, of first order in the step (on
    /// `tests/data/accuracy/pari_ten_springs.toml` the 31 µs step landed on the onset of all ten
    /// springs at 0.0111 s left u̇_x 102 µm/s off, 1 % of it, and the run 1.3 % off: module docs
    /// of the test). The dropped force D = Σ_i w_i (F_i⁺ − F_i⁻) e_x, F_i⁺ the spring's slipping
    /// force at the step's end and F_i⁻ = ±κ N_i e_s the sticking force at its limit, weighed by
    /// w_i = 2θ_i − 1 (θ_i where its friction margin, linear over the step, crosses 0:
    /// `event_margins`; 1 for an onset landed on at the step's end, −1 at its start), is what
    /// the trapezoid counted for the wrong part of the step: one Newton correction of the step,
    /// K̂ δ = D (K̂ the step's Newmark matrix and the springs' tangent, κ N_i + c' of the springs
    /// held sticking), gives u = u⁺ + δ, u̇ = u̇⁺ + γ/(β h) δ, ü = ü⁺ + δ/(β h²); the springs are
    /// committed as the step found them (slipping, their slip positions moved with u_x by δ_x),
    /// and the next step starts from ü − M⁻¹ D, the acceleration under the slipping force. δ is
    /// of order D β h²/m (7e-10 m on that onset), the velocity's correction D γ h/m. Nothing
    /// changes without an onset in the step or with μ_d = μ_s (D = 0). Held by
    /// `pari_ten_springs_meets_converged_fixed_steps` (within 1 % on six first steps: 1.34 %
    /// without) and `random_family_meets_converged_fixed_steps` (`verify_adaptive_accuracy.rs`).
    /// What remains at that onset is its time: the adaptive run finds it 5 µs before fixed steps
    /// of 1.5625e-6 s, its u_x 1e-8 m (two tolerances) ahead while u̇_x is 2.7 mm/s, and u̇_x is
    /// 34 µm/s off after it (130 µm/s without the correction).
    #[inline(always)]
    fn correct_onset_jumps(&mut self, h: f64, c: &mut Converged) {
        // A spring slips at the step's end (`trial_slips`), by the general path, and μ_d ≠ μ_s.
        if self.trial_slips && self.fast.iterate.is_none() && self.model.mu_dynamic != self.model.mu_static {
            self.correct_onset_jumps_at(h, c);
        }
    }

    /// [`Self::correct_onset_jumps`] past its first tests.
    fn correct_onset_jumps_at(&mut self, h: f64, c: &mut Converged) {
        // The springs that stuck at the step's start and slip at its end, in contact.
        let starts = |(s, r): (&SpringState, &SpringResponse)| !s.sliding && r.state.sliding && r.normal_n > 0.0;
        let Some(first) = self.state.springs.iter().zip(&self.trial).position(starts) else {
            return;
        };
        let law = self.model.law;
        let c_prime = 2.0 * self.model.spring_dashpot_ns_per_m / h;
        let (mut d_x, mut k_x) = (0.0, 0.0);
        for i in first..self.model.x_m.len() {
            let (s, r) = (&self.state.springs[i], &self.trial[i]);
            if !starts((s, r)) {
                continue;
            }
            let (g0, g1) = self.event_margins(EventKind::Onset, i, h, c);
            if !(g0 > 0.0 && g1 <= 0.0) {
                continue;
            }
            let w = 2.0 * g0 / (g0 - g1) - 1.0;
            let kn = law.kappa_per_m * r.normal_n;
            d_x += w * (r.shear_n - (kn * law.limit_m(*s)).copysign(r.shear_n));
            k_x += w.max(0.0) * (kn + c_prime);
        }
        if d_x == 0.0 {
            return;
        }
        let (beta, gamma) = (self.solver.beta, self.solver.gamma);
        let (c1, c2) = (1.0 / (beta * h * h), 1.0 / (beta * h));
        let mut k = self.model.mass * c1 + self.model.damping * (gamma * c2) + self.tangent(h);
        k[(0, 0)] += k_x;
        let d = Vector3::new(d_x, 0.0, 0.0);
        let (Some(delta), Some(m_inv_d)) = (solve3::lu_solve(&k, &d), solve3::lu_solve(&self.model.mass, &d)) else {
            return;
        };
        for j in 0..3 {
            c.u[j] += delta[j];
            c.v[j] += gamma * c2 * delta[j];
            c.a[j] += c1 * delta[j] - m_inv_d[j];
        }
        // Slipping and lifted springs' slip positions follow u_x.
        for r in self.trial.iter_mut().filter(|r| r.state.sliding || r.normal_n <= 0.0) {
            r.state.slip_m += delta[0];
        }
    }

    /// M⁻¹ ΔF, ΔF the jump of the vertical dashpots (`springs` form) of the springs whose
    /// contact changes between the displacements `u0` and `u1` at a fraction below
    /// `max_fraction` of the way (their u_y,i linear between them), at the velocity `v`:
    /// ± c_y (v_y − θ̇ x_i) (0, 1, −x_i), + for a touch-down. Zero without such dashpots.
    fn dashpot_jump(&self, u0: [f64; 3], u1: [f64; 3], v: [f64; 3], max_fraction: f64) -> Vector3<f64> {
        let cdy = self.model.spring_vertical_dashpot_ns_per_m;
        let mut df = Vector3::zeros();
        if cdy <= 0.0 || !self.contact_may_change(u0, u1) {
            return df;
        }
        for &x in &self.model.x_m {
            let (y0, y1) = (u0[1] - u0[2] * x, u1[1] - u1[2] * x);
            if (y0 < 0.0) != (y1 < 0.0) && y0 / (y0 - y1) < max_fraction {
                let fd = cdy * (v[1] - v[2] * x);
                let sign = if y1 < 0.0 { 1.0 } else { -1.0 };
                df[1] += sign * fd;
                df[2] -= sign * x * fd;
            }
        }
        if df == Vector3::zeros() {
            return df;
        }
        self.model.mass.lu().solve(&df).unwrap_or_else(Vector3::zeros)
    }

    /// Whether a spring is in contact (u_y,i < 0) at one of the displacements `u0`, `u1` and not
    /// at the other. u_y,i = u_y − θ x_i, rounded, is monotonic in x_i (each rounded operation
    /// is), so at each displacement the springs in the first one's contact state form a run from
    /// the first (the positions ascend: `Foundation::spring_positions`), the others the rest: the
    /// same set at both when the first and the last spring's states and the run's length agree
    /// (`false`, the springs' own tests would find no change).
    #[inline]
    fn contact_may_change(&self, u0: [f64; 3], u1: [f64; 3]) -> bool {
        let xs = &self.model.x_m[..];
        let touch = |u: [f64; 3], x: f64| u[1] - u[2] * x < 0.0;
        if !self.solver.accel.contact_runs {
            return xs.iter().any(|&x| touch(u0, x) != touch(u1, x));
        }
        let Some(&lo) = xs.first() else {
            return false;
        };
        let hi = xs[xs.len() - 1];
        let (first, last) = (touch(u0, lo), touch(u0, hi));
        if touch(u1, lo) != first || touch(u1, hi) != last {
            return true;
        }
        // Both ends as at `u0`: every spring as well if they agree, else the runs' lengths tell.
        first != last
            && xs.partition_point(|&x| touch(u0, x) == first) != xs.partition_point(|&x| touch(u1, x) == first)
    }

    /// A spring that touched down or lifted in the first hundredth of a converged step (to `c`),
    /// too close to its start to be located (typically just after a step cut at the event's
    /// estimate ended a little short of it): the step counted its vertical dashpot as at its end
    /// over the whole step, so the committed acceleration restarts as across the event at the
    /// step's start, q̈_n ← q̈_n − M⁻¹ ΔF (ΔF as in [`Self::restart_at_event`], at the start's
    /// velocity), and the step is to be retaken. Once per start time; `true` if it restarted.
    fn restart_at_start(&mut self, c: &Converged) -> bool {
        if self.run.event_step || self.run.restarted_at_s == self.state.t_s {
            return false;
        }
        let da = self.dashpot_jump(self.state.u, c.u, self.state.v, EVENT_MIN_FRACTION);
        if da == Vector3::zeros() {
            return false;
        }
        for (a, d) in self.state.a.iter_mut().zip(da.iter()) {
            *a -= d;
        }
        self.run.restarted_at_s = self.state.t_s;
        true
    }

    /// Advance by `h` seconds, halving on failure (recursively, up to the allowed levels), and
    /// shortening a step to end at its first event (`events` more at most: module docs).
    /// `event`: the step ends at a located event ([`Self::restart_at_event`]).
    fn advance<L: LoadHistory + ?Sized, O: Observer + ?Sized>(
        &mut self,
        h: f64,
        level: usize,
        events: usize,
        event: bool,
        load: &L,
        obs: &mut O,
    ) -> Result<(), SolveError> {
        let t0 = self.state.t_s;
        let t1 = t0 + h;
        let w = load.at(t1);
        self.run.event_step = event;
        let tried = self.try_step(h, self.load_vector(w));
        match tried {
            Ok(c) => {
                if self.restart_at_start(&c) {
                    return self.advance(h, level, events, event, load, obs);
                }
                if events > 0 {
                    if let Some(Event { theta, .. }) = self.event_fraction(h, &c, self.solver.locate_contact) {
                        // To the event without locating again, then the rest of the step.
                        self.stats.located_events += 1;
                        self.advance(theta * h, level, 0, true, load, obs)?;
                        return self.advance(t1 - self.state.t_s, level, events - 1, false, load, obs);
                    }
                }
                let it = c.iterations;
                self.commit(h, c);
                self.run.event_step = false;
                if obs.observes() {
                    if obs.reads_springs() {
                        self.fill_sticking_responses();
                    }
                    obs.observe(&StepView {
                        t_s: self.state.t_s,
                        state: &self.state,
                        load: w,
                        reaction: self.observed_reaction(obs),
                        springs: self.step_springs(),
                        iterations: it,
                    });
                }
                Ok(())
            }
            Err((iterations, residual)) => {
                if level >= self.solver.max_substep_levels {
                    return Err(SolveError::NonConvergence { t_s: t1, iterations, levels: level, residual });
                }
                self.stats.substeps += 1;
                self.stats.max_substep_level = self.stats.max_substep_level.max(level + 1);
                self.run.event_step = false;
                self.advance(0.5 * h, level + 1, events, event, load, obs)?;
                self.advance(t1 - self.state.t_s, level + 1, events, event, load, obs)
            }
        }
    }

    /// Advance one time step of `solver.dt_s`.
    #[inline]
    pub fn step<L: LoadHistory + ?Sized, O: Observer + ?Sized>(
        &mut self,
        load: &L,
        obs: &mut O,
    ) -> Result<(), SolveError> {
        let r = self.advance(self.solver.dt_s, 0, MAX_EVENTS_PER_STEP, false, load, obs);
        self.fill_sticking_responses();
        r
    }

    /// Run until `t_end_s` (the last step is shortened to land on it), with the stepping of
    /// `solver.stepping`.
    pub fn run_until<L: LoadHistory + ?Sized, O: Observer + ?Sized>(
        &mut self,
        t_end_s: f64,
        load: &L,
        obs: &mut O,
    ) -> Result<(), SolveError> {
        let r = match self.solver.stepping {
            Stepping::Fixed => self.run_fixed(t_end_s, load, obs),
            Stepping::Adaptive(p) => self.run_adaptive(t_end_s, p, load, obs),
        };
        self.run.event_step = false;
        // What `reaction` and `springs` read after the run.
        self.fill_sticking_responses();
        r
    }

    /// Commit the converged step `c` of length `h` ending at `t1` under the load `w`, and show it
    /// to the observer.
    fn commit_observed<O: Observer + ?Sized>(&mut self, h: f64, c: Converged, t1: f64, w: WaveForce, obs: &mut O) {
        let it = c.iterations;
        self.commit(h, c);
        self.state.t_s = t1;
        self.run.last_load = Some((t1, self.load_vector(w)));
        if obs.observes() {
            if obs.reads_springs() {
                self.fill_sticking_responses();
            }
            obs.observe(&StepView {
                t_s: t1,
                state: &self.state,
                load: w,
                reaction: self.observed_reaction(obs),
                springs: self.step_springs(),
                iterations: it,
            });
        }
    }

    /// Fixed steps of `solver.dt_s` to `t_end_s`.
    fn run_fixed<L: LoadHistory + ?Sized, O: Observer + ?Sized>(
        &mut self,
        t_end_s: f64,
        load: &L,
        obs: &mut O,
    ) -> Result<(), SolveError> {
        let dt = self.solver.dt_s;
        let n = ((t_end_s - self.state.t_s) / dt - 1e-9).ceil().max(0.0) as u64;
        let t0 = self.state.t_s;
        for i in 0..n {
            // Step to an absolute grid time to avoid drift from repeated additions.
            let target = (t0 + (i + 1) as f64 * dt).min(t_end_s);
            let h = target - self.state.t_s;
            if h <= 0.0 {
                continue;
            }
            self.advance(h, 0, MAX_EVENTS_PER_STEP, false, load, obs)?;
            self.state.t_s = target;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::foundation::{AddedMassSpec, FoundationSpec};
    use crate::loads::WaveForce;
    use crate::structure::{CaissonSpec, MassMatrix, MassSpec};

    /// The seed's Table 5 caisson on its Table 6 foundation with the given dashpot placements.
    pub(super) fn simulation(mode: DampingMode, vertical: VerticalDamping) -> Simulation {
        simulation_with(mode, vertical, MassMatrix::Coupled, SolverParams::default())
    }

    /// [`simulation`] with the given mass matrix and solver controls.
    pub(super) fn simulation_with(
        mode: DampingMode,
        vertical: VerticalDamping,
        mass_matrix: MassMatrix,
        solver: SolverParams,
    ) -> Simulation {
        let caisson = CaissonSpec {
            width_m: 0.78,
            length_m: 1.0,
            height_m: 1.12,
            base_depth_m: 0.8,
            mass: MassSpec::WeightInWater { weight_in_water_n: 8240.0 },
            cog_height_m: None,
            inertia_cog_kg_m2: None,
            mass_matrix: Some(mass_matrix),
        }
        .build(1000.0, crate::Profile::Consistent)
        .unwrap();
        let foundation = FoundationSpec {
            kx_n_per_m: Some(1.511e8),
            ky_n_per_m: Some(1.404e8),
            damping_ns_per_m: Some(5.98e5),
            damping_mode: Some(mode),
            vertical_damping: Some(vertical),
            added_mass: AddedMassSpec::Off,
            ..FoundationSpec::default()
        }
        .build(&caisson, 1000.0, crate::Profile::Consistent)
        .unwrap();
        Simulation::new(Model::new(&caisson, &foundation), solver, &WaveForceAt(WaveForce::ZERO))
    }

    struct WaveForceAt(WaveForce);
    impl LoadHistory for WaveForceAt {
        fn at(&self, _: f64) -> WaveForce {
            self.0
        }
    }

    /// A random displacement of the seed's caisson (10 springs at |x_i| ≤ 0.351 m) on the scale
    /// `s_m` whose springs change contact (u_y,i = 0) at a random x within 0.6 m of the centre,
    /// or with θ = 0, or exactly at a spring.
    fn displacement_at(rng: &mut impl rand::Rng, s_m: f64, xs: &[f64]) -> [f64; 3] {
        let uy = s_m * rng.gen_range(-2.0..2.0);
        let x_m = rng.gen_range(-0.6..0.6);
        match rng.gen_range(0..8) {
            0 => [0.0, uy, 0.0],
            1 => [0.0, uy, uy / xs[rng.gen_range(0..xs.len())]],
            _ => [0.0, uy, uy / x_m],
        }
    }

    /// `contact_may_change`, which compares the runs of springs in and out of contact by their
    /// ends and lengths, against every spring's own contact test, at 200 000 random pairs of
    /// displacements (both with the springs' change of contact anywhere across the base and
    /// beyond, one tenth of them the same displacement, others with θ = 0 or a spring exactly
    /// at the threshold): the same answer at every pair, and each answer at more than 30 000 pairs.
    #[test]
    fn contact_runs_answer_as_every_spring() {
        use rand::{Rng, SeedableRng};
        let sim = simulation(DampingMode::Elastic, VerticalDamping::Springs);
        let xs = sim.model.x_m.clone();
        assert_eq!(xs.len(), 10);
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(19);
        let (mut changed, mut kept) = (0, 0);
        for _ in 0..200_000 {
            let s_m = 10f64.powi(rng.gen_range(-7..=-3));
            let u0 = displacement_at(&mut rng, s_m, &xs);
            let u1 = if rng.gen_range(0..10) == 0 { u0 } else { displacement_at(&mut rng, s_m, &xs) };
            let each = xs.iter().any(|x| (u0[1] - u0[2] * x < 0.0) != (u1[1] - u1[2] * x < 0.0));
            assert_eq!(sim.contact_may_change(u0, u1), each, "{u0:?} -> {u1:?}");
            if each {
                changed += 1;
            } else {
                kept += 1;
            }
        }
        assert!(changed > 30_000 && kept > 30_000, "{changed} changed, {kept} kept");
    }

    /// `contact_ahead` (the ends of the runs of springs in and out of contact first, then the
    /// springs one by one) against `contact_ahead_each` (always one by one) at 200 000 random
    /// committed states and step lengths (1e-4 to 1e-2 s, the velocities and accelerations
    /// such that springs change contact within the step about as often as not): the same event
    /// (the same spring, the same θ to the bit) or none at every state, the runs' ends alone
    /// answering (no event) at many, and events found at many.
    #[test]
    fn contact_ahead_by_run_ends_as_by_every_spring() {
        use rand::{Rng, SeedableRng};
        let mut sim = simulation(DampingMode::Elastic, VerticalDamping::Springs);
        let xs = sim.model.x_m.clone();
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(23);
        let (mut by_ends, mut events) = (0, 0);
        for _ in 0..200_000 {
            let s_m = 10f64.powi(rng.gen_range(-7..=-3));
            let h = 10f64.powf(rng.gen_range(-4.0..-2.0));
            sim.state.u = displacement_at(&mut rng, s_m, &xs);
            let dv = displacement_at(&mut rng, s_m, &xs);
            let da = displacement_at(&mut rng, s_m, &xs);
            let (fv, fa) = (rng.gen_range(0.0..2.0) / h, rng.gen_range(0.0..4.0) / (h * h));
            sim.state.v = [0.0, fv * dv[1], fv * dv[2]];
            sim.state.a = [0.0, fa * da[1], fa * da[2]];
            let key = |e: Option<Event>| e.map(|e| (e.spring, e.theta.to_bits(), e.g0.to_bits(), e.g1.to_bits()));
            let each = key(sim.contact_ahead_each(h));
            assert_eq!(key(sim.contact_ahead(h)), each, "{:?} h = {h}", sim.state);
            by_ends += usize::from(sim.contact_kept_ahead(h));
            events += usize::from(each.is_some());
        }
        assert!(by_ends > 30_000 && events > 30_000, "{by_ends} by the runs' ends, {events} events");
    }

    /// `resisting_force` with the fast path's test first and with the pass over the springs
    /// first: the same force and tangent to the last bit, and the same path taken, for both
    /// horizontal and both vertical dashpot placements at 20 000 random committed states (slip
    /// positions within ±1.2 e_s of u_x or, half of them, ±0.6 e_s; a third of the springs
    /// slipping; some lifted) and trials (sticking, slipping, lifting), each path taken in more
    /// than 4 000 of them.
    #[test]
    fn resisting_force_is_the_same_in_either_order() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(9);
        let (mut fast, mut general) = (0, 0);
        for (mode, vertical) in [
            (DampingMode::Total, VerticalDamping::Seed),
            (DampingMode::Total, VerticalDamping::Springs),
            (DampingMode::Elastic, VerticalDamping::Seed),
            (DampingMode::Elastic, VerticalDamping::Springs),
        ] {
            let mut sims = [simulation(mode, vertical), simulation(mode, vertical)];
            let (law, settle, half_b) =
                (sims[0].model.law, sims[0].model.static_settlement_m(), 0.5 * sims[0].model.width_m);
            for _ in 0..5_000 {
                // Half of the states near the friction limits and lift-off, half within them.
                let spread = if rng.gen_bool(0.5) { 1.2 } else { 0.6 };
                let ux_n = rng.gen_range(-1e-3..1e-3);
                let u_n = [ux_n, -settle, settle / half_b * rng.gen_range(-spread..spread)];
                let springs: Vec<SpringState> = (0..10)
                    .map(|_| SpringState {
                        slip_m: ux_n - law.stick_limit_m * rng.gen_range(-spread..spread),
                        sliding: rng.gen_range(0..3) == 0,
                        rate_m_per_s: rng.gen_range(-1e-3..1e-3),
                    })
                    .collect();
                let v_n = [rng.gen_range(-0.01..0.01), rng.gen_range(-0.01..0.01), rng.gen_range(-0.01..0.01)];
                let scale = 10f64.powi(rng.gen_range(-3..=0));
                let u = [
                    ux_n + scale * law.stick_limit_m * rng.gen_range(-1.0..1.0),
                    u_n[1] + scale * settle * rng.gen_range(-0.5..0.5),
                    u_n[2] + scale * settle / half_b * rng.gen_range(-0.5..0.5),
                ];
                let v = [rng.gen_range(-0.01..0.01), rng.gen_range(-0.01..0.01), rng.gen_range(-0.01..0.01)];
                let h = 10f64.powf(rng.gen_range(-4.0..-2.0));
                let mut out = Vec::new();
                for (sim, stick_first) in sims.iter_mut().zip([true, false]) {
                    sim.state.u = u_n;
                    sim.state.v = v_n;
                    sim.state.springs.copy_from_slice(&springs);
                    sim.fast.invalidate();
                    let f = sim.resisting_force(u, v, h, stick_first);
                    let k = sim.tangent(h);
                    let bits: Vec<u64> = f.iter().chain(k.iter()).map(|x| x.to_bits()).collect();
                    out.push((bits, sim.fast.iterate.is_some()));
                }
                assert_eq!(out[0], out[1], "{mode:?}/{vertical:?} from {u_n:?} {springs:?} to {u:?}");
                if out[0].1 {
                    fast += 1;
                } else {
                    general += 1;
                }
            }
        }
        assert!(fast > 4_000 && general > 4_000, "{fast} by the closed form, {general} spring by spring");
    }

    /// `fast_cbrt` against `cbrt` from 1e-30 to 1e30: within 1e-4 relative (two Newton steps
    /// from an estimate within 4 % leave about 1e-5; a step-size rule needs a few digits).
    #[test]
    fn fast_cbrt_is_cbrt() {
        let mut checked = 0;
        for k in -3000..=3000 {
            let x = 10f64.powf(k as f64 * 0.01 + 0.003);
            let (a, b) = (fast_cbrt(x), x.cbrt());
            assert!((a / b - 1.0).abs() <= 1e-4, "{x}: {a} against {b}");
            checked += 1;
        }
        assert_eq!(checked, 6001);
    }

    /// The assembled tangent at the trial (`u0`, `v0`) of a step of length `h` against central
    /// differences of the resisting force (displacement steps of `eps`, m, the rotation's
    /// `eps`/B; the velocity following as in a Newmark step, v = v0 + γ/(β h) (u − u0)), each
    /// entry within 1e-6 of the tangent's largest; returns the entries checked (9).
    fn tangent_against_differences(
        sim: &mut Simulation,
        u0: [f64; 3],
        v0: [f64; 3],
        h: f64,
        eps: f64,
        what: &str,
    ) -> usize {
        let dv_du = sim.solver.gamma / (sim.solver.beta * h);
        let (_, k) = sim.assemble(u0, v0, h);
        let scale = k.abs().max();
        let mut checked = 0;
        for j in 0..3 {
            let eps = if j == 2 { eps / 0.78 } else { eps };
            let mut f_at = |sign: f64| {
                let mut u = u0;
                u[j] += sign * eps;
                let mut v = v0;
                v[j] += sign * eps * dv_du;
                sim.assemble(u, v, h).0
            };
            let fd = (f_at(1.0) - f_at(-1.0)) / (2.0 * eps);
            for r in 0..3 {
                assert!(
                    (fd[r] - k[(r, j)]).abs() <= 1e-6 * scale,
                    "{what}: ∂f_{r}/∂q_{j} = {} by differences, {} assembled",
                    fd[r],
                    k[(r, j)]
                );
                checked += 1;
            }
        }
        checked
    }

    /// The tangent of the assembled resisting force (springs with their shear, normal and
    /// rotation coupling, and the per-spring dashpots of the `elastic` and `springs` placements)
    /// against central finite differences, for both horizontal and both vertical dashpot
    /// placements, at a state where the caisson is rotated so that the two seaward springs are
    /// lifted, some springs stick and some slip (every spring well away from a kink: the
    /// response is linear or bilinear there, so the differences are exact to rounding). The
    /// velocity follows the displacement as in a Newmark step, v = v0 + γ/(β h) (u − u0).
    #[test]
    fn assembled_tangent_matches_finite_differences() {
        let h = 1e-4;
        let mut checked = 0;
        for mode in [DampingMode::Total, DampingMode::Elastic] {
            for vertical in [VerticalDamping::Seed, VerticalDamping::Springs] {
                let mut sim = simulation(mode, vertical);
                let law = sim.model.law;
                let settle = sim.model.static_settlement_m();
                // Committed state: shifted shoreward, springs at assorted slip positions.
                sim.state.u = [2e-4, -settle, 0.0];
                for (i, s) in sim.state.springs.iter_mut().enumerate() {
                    let e = law.stick_limit_m * [0.3, -0.4, 2.5, -3.0, 0.1, 1.8, -0.2, 4.0, -2.2, 0.5][i];
                    *s = SpringState { slip_m: sim.state.u[0] - e, sliding: i % 3 == 0, rate_m_per_s: 0.0 };
                }
                let x = sim.model.x_m.clone();
                // Trial: a small further shoreward push (the elastic-mode dashpot c/(n h) turns
                // large pushes into slip), settlement, and a rotation lifting the two
                // seaward springs (u_y,i = u_y − θ x_i > 0 for x_i < −0.25 B).
                let theta = settle / (0.3 * 0.78);
                let u0 = [2.0e-4 + 1e-3 * law.stick_limit_m, -settle - 1e-7, theta];
                assert!(x.iter().filter(|&&xi| u0[1] - u0[2] * xi > 0.0).count() == 2, "two springs lifted");
                let v0 = [0.01, -0.002, 0.03];
                sim.assemble(u0, v0, h);
                let contact = sim.trial.iter().filter(|r| r.normal_n > 0.0);
                let sliding = contact.clone().filter(|r| r.state.sliding).count();
                let sticking = contact.filter(|r| !r.state.sliding).count();
                assert!(
                    sliding >= 2 && sticking >= 2 && sliding + sticking == 8,
                    "{sliding} sliding, {sticking} sticking"
                );
                checked += tangent_against_differences(&mut sim, u0, v0, h, 1e-9, &format!("{mode:?}/{vertical:?}"));
            }
        }
        assert_eq!(checked, 4 * 9);
    }

    /// The assembled tangent against central finite differences where two seaward springs
    /// lifted at the committed state touch again at the trial (`SpringLaw::trial_recontact`:
    /// their slip positions depend on the trial's u_x and u_y), for both horizontal and both
    /// vertical dashpot placements; the re-contacting springs' slip positions lie between u_x,n
    /// and u_x (they touch within the step).
    #[test]
    fn assembled_tangent_matches_finite_differences_at_recontact() {
        let h = 1e-4;
        let mut checked = 0;
        for mode in [DampingMode::Total, DampingMode::Elastic] {
            for vertical in [VerticalDamping::Seed, VerticalDamping::Springs] {
                let mut sim = simulation(mode, vertical);
                let settle = sim.model.static_settlement_m();
                let x = sim.model.x_m.clone();
                // Committed: rotated so that the two seaward springs are lifted (s_i = u_x,n).
                let theta_n = settle / (0.3 * 0.78);
                sim.state.u = [2e-4, -settle, theta_n];
                for (s, &xi) in sim.state.springs.iter_mut().zip(&x) {
                    let lifted = -settle - theta_n * xi >= 0.0;
                    let e = if lifted { 0.0 } else { 0.2 * sim.model.law.stick_limit_m };
                    *s = SpringState { slip_m: 2e-4 - e, sliding: false, rate_m_per_s: 0.0 };
                }
                assert_eq!(x.iter().filter(|&&xi| -settle - theta_n * xi >= 0.0).count(), 2);
                sim.fast.invalidate();
                // Trial: every spring in contact.
                let u0 = [2e-4 + 1e-7, -settle - 1e-7, 0.2 * theta_n];
                let v0 = [0.01, -0.002, 0.03];
                sim.assemble(u0, v0, h);
                let touching: Vec<f64> = sim.trial[..2].iter().map(|r| r.state.slip_m).collect();
                assert!(sim.trial.iter().all(|r| r.normal_n > 0.0 && !r.state.sliding));
                assert!(touching.iter().all(|&s| s > 2e-4 && s < u0[0]), "slip positions {touching:?}");
                checked += tangent_against_differences(&mut sim, u0, v0, h, 1e-10, &format!("{mode:?}/{vertical:?}"));
            }
        }
        assert_eq!(checked, 4 * 9);
    }

    /// Whether a spring is out of contact at each step, as an observer that reads neither the
    /// springs' responses of an all-sticking step nor the reaction (the lifetime's) sees it.
    struct Lift<const REACTION: bool>(Vec<bool>, usize);
    impl<const REACTION: bool> Observer for Lift<REACTION> {
        fn observe(&mut self, s: &StepView<'_>) {
            let lifted = if REACTION {
                s.reaction.contact_springs < s.state.springs.len()
            } else {
                assert_eq!(s.reaction, Reaction::default(), "not summed");
                !s.springs.iter().all(|r| r.normal_n > 0.0)
            };
            self.0.push(lifted);
            self.1 += s.springs.is_empty() as usize;
        }
        fn reads_springs(&self) -> bool {
            false
        }
        fn reads_reaction(&self) -> bool {
            REACTION
        }
    }

    /// An observer that does not read the reaction is shown zeros, and a spring out of contact
    /// in the springs' responses (none when they are not built, on an all-sticking step) at
    /// exactly the steps where the reaction counts fewer springs in contact than there are:
    /// through a pulse that rocks the caisson (its seaward springs lift) with fixed and adaptive
    /// steps and both vertical dashpot placements; steps lifted, sticking (springs not built)
    /// and neither in each run.
    #[test]
    fn lift_seen_without_the_reaction() {
        use crate::loads::pulse::TrianglePulse;
        let load =
            TrianglePulse { peak: WaveForce::from_levers(15e3, 0.8, 3e3, 0.52, 0.78), rise_s: 0.2, start_s: 0.0 };
        let mut runs = 0;
        for stepping in [Stepping::Fixed, Stepping::Adaptive(AdaptiveParams::default())] {
            for vertical in [VerticalDamping::Seed, VerticalDamping::Springs] {
                let solver = SolverParams { stepping, ..SolverParams::default() };
                let run = |obs: &mut dyn Observer| {
                    let mut sim = simulation_with(DampingMode::Elastic, vertical, MassMatrix::Coupled, solver);
                    sim.run_until(0.2, &load, obs).unwrap();
                };
                let (mut by_reaction, mut by_springs) = (Lift::<true>(Vec::new(), 0), Lift::<false>(Vec::new(), 0));
                run(&mut by_reaction);
                run(&mut by_springs);
                assert_eq!(by_reaction.0, by_springs.0, "{stepping:?}/{vertical:?}");
                let lifted = by_springs.0.iter().filter(|&&l| l).count();
                let (steps, sticking) = (by_springs.0.len(), by_springs.1);
                assert!(lifted > 0 && sticking > 0 && lifted + sticking < steps, "{lifted} {sticking} {steps}");
                runs += 1;
            }
        }
        assert_eq!(runs, 4);
    }
}
