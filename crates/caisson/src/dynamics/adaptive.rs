//! The adaptive step control (docs/model.md §9.1; the rules in the module docs of
//! [`crate::dynamics`], "Adaptive stepping" and "Events"): a run is a sequence of tries, each of
//! one [`StepKind`], judged by one [`Verdict`]. From a state where every spring in contact sticks
//! the exact step is tried first (`exact`); otherwise a Newmark step is planned ([`Plan`]: the
//! controller's length, cut at the load's next breakpoint and the run's end, or short of a contact
//! event anticipated ahead) and tried; a converged try is then judged: the acceleration restarted
//! at its start and the step retaken, the step retaken shorter to land on an event (found in it,
//! or being landed on), rejected by its error estimate, or accepted. A try that does not converge
//! is halved. [`StepControl`] holds what one try leaves for the next.

use super::{
    fast_cbrt, AdaptiveParams, Converged, Event, EventKind, LoadHistory, Observer, Simulation, SolveError, EVENT_LEAD,
    EVENT_MIN_FRACTION, MAX_EVENTS_PER_STEP, MAX_LOCATE_TRIES,
};

/// An event being landed on by the adaptive stepping: the longest step from the current state
/// known to end before it (`lo`) and the shortest known to end past it (`hi`), each with the
/// event's margin g at its end. The next step length is the root of g(s) by inverse quadratic
/// interpolation through these two and the end the last step replaced (as in Brent's method,
/// Brent 1973 ch. 4) if it falls inside the bracket, else by the Illinois variant of regula
/// falsi (Dowell & Jarratt 1971: the end kept twice in a row has its margin halved).
#[derive(Debug, Clone, Copy)]
struct Landing {
    spring: usize,
    kind: EventKind,
    /// (step length s, margin g(s)).
    lo: (f64, f64),
    hi: (f64, f64),
    /// Which end moved last: `Some(true)` the upper.
    moved_hi: Option<bool>,
    /// Steps retaken so far.
    tries: usize,
    /// Predicted ([`Simulation::contact_ahead`]), not found: a step that ends short of it is kept.
    predicted: bool,
}

impl Landing {
    fn new(e: Event, h: f64) -> Self {
        Landing {
            spring: e.spring,
            kind: e.kind,
            lo: (0.0, e.g0),
            hi: (h, e.g1),
            moved_hi: None,
            tries: 0,
            predicted: false,
        }
    }

    /// The step of length `s` ended with margin `g`; the next step length to try.
    fn narrow(&mut self, s: f64, g: f64) -> f64 {
        let upper = g <= 0.0;
        let old = if upper { self.hi } else { self.lo };
        if upper {
            self.hi = (s, g);
        } else {
            self.lo = (s, g);
        }
        self.tries += 1;
        let ((a, ga), (b, gb)) = (self.lo, self.hi);
        let (c, gc) = old;
        // Inverse quadratic interpolation: s(g) through the three points, at g = 0.
        if ga != gc && gb != gc {
            let q = a * gb * gc / ((ga - gb) * (ga - gc))
                + b * ga * gc / ((gb - ga) * (gb - gc))
                + c * ga * gb / ((gc - ga) * (gc - gb));
            if q > a && q < b {
                self.moved_hi = Some(upper);
                return q * (1.0 + EVENT_LEAD);
            }
        }
        if self.moved_hi == Some(upper) {
            // The same end moved twice: halve the other's margin (Illinois).
            if upper {
                self.lo.1 *= 0.5;
            } else {
                self.hi.1 *= 0.5;
            }
        }
        self.moved_hi = Some(upper);
        let ((a, ga), (b, gb)) = (self.lo, self.hi);
        (a + (b - a) * ga / (ga - gb)) * (1.0 + EVENT_LEAD)
    }
}

/// What a Newmark try is (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum StepKind {
    /// The controller's length, cut at the load's next breakpoint or the run's end.
    Ordinary,
    /// Ended just past a contact event anticipated ahead of the committed state.
    ToAnticipatedEvent,
    /// Retaken to land on an event found in an earlier try from the same state.
    ToEvent,
    /// After a Newton failure: half the failed length.
    Halved,
}

/// The length of the step to try.
#[derive(Debug, Clone, Copy)]
struct Plan {
    kind: StepKind,
    h: f64,
    /// The controller's length before the cuts.
    planned: f64,
    /// Cut at a breakpoint or the run's end: the next step may grow back to `planned`.
    truncated: bool,
}

/// The judgement of a converged Newmark try.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Verdict {
    /// A spring changed contact in the try's first hundredth: the acceleration restarted at the
    /// step's start (`Simulation::restart_at_start`), the step is retaken.
    RestartedAtStart,
    /// Retaken with this length to land on the event being landed on (or another found before it).
    Narrowed(f64),
    /// The try's first event: retaken with this length to land on it.
    EventFound(f64),
    /// The error estimate is over the tolerance: retried with this length.
    Rejected(f64),
    /// Kept; the error estimate's step ratio 0.9 (tol/‖e‖)^{1/3} (^{1/2} for an estimate per
    /// unit step: [`Estimate`]).
    Accepted { ratio: f64 },
}

/// The error estimate of a converged Newmark try, m, and how it grows with the step: as h³ (the
/// local error), or as h² where a step that ends with every spring in contact and sticking is
/// held to the tolerance per `StepControl::coherent_s` of time (its Zienkiewicz-Xie estimate
/// times coherent_s/h: module docs of [`crate::dynamics`], "Adaptive stepping"), unless a
/// touch-down's error, held per step, is the larger.
#[derive(Debug, Clone, Copy)]
struct Estimate {
    err_m: f64,
    per_unit_step: bool,
    /// A sticking step whose estimate is a touch-down's (`seed-2011`), not Newmark's.
    touch_down: bool,
}

impl Estimate {
    /// The step ratio after an accepted step: 0.9 (tol/‖e‖)^{1/3}, or ^{1/2} per unit step.
    #[inline(always)]
    fn ratio(&self, tol_m: f64) -> f64 {
        if self.err_m <= 0.0 {
            f64::INFINITY
        } else if self.per_unit_step {
            0.9 * (tol_m / self.err_m).sqrt()
        } else {
            0.9 * fast_cbrt(tol_m / self.err_m)
        }
    }

    /// The retry's ratio after a rejection: 0.9 (tol/‖e‖)^{2/5} (module docs, "Adaptive
    /// stepping"), or ^{1/2} per unit step.
    #[inline(always)]
    fn shrink(&self, tol_m: f64) -> f64 {
        if self.per_unit_step {
            0.9 * (tol_m / self.err_m).sqrt()
        } else {
            0.9 * (tol_m / self.err_m).powf(0.4)
        }
    }
}

/// What one try of the adaptive stepping leaves for the next.
struct StepControl {
    p: AdaptiveParams,
    /// |β − 1/6|, the Zienkiewicz-Xie constant, and B/2, the rotation's lever in the estimate.
    c_err: f64,
    half_b: f64,
    /// Half the natural period of the horizontal mode, s: a step that ends with every spring in
    /// contact and sticking, if shorter, is held to the tolerance per this much time
    /// ([`Estimate`]; 0 if the period is not finite).
    coherent_s: f64,
    /// The same span for a Newmark step with springs lifted, located contact, and every spring
    /// in contact sticking: `coherent_s` if the horizontal mode's vibration outlives it (its
    /// decay time 2 m_x/c_x, c_x the horizontal dashpots, at least T_x/2: damping ratio at most
    /// 1/π), else 0, held per step (`Simulation::error_estimate_m`).
    coherent_partial_s: f64,
    /// Halvings in a row after Newton failures.
    level: usize,
    /// Events located in a row, and whether the step to try was shortened to end at one.
    events: usize,
    at_event: bool,
    /// The event being landed on, while the steps to it are retaken, and the length of the step
    /// in which it was found (or predicted): the step after the event may be as long.
    landing: Option<Landing>,
    before_event_s: f64,
    /// The load's next breakpoint after the step's start: it stays the next one until the steps
    /// pass it, so it is looked up again only then.
    breakpoint_s: f64,
}

impl Simulation {
    /// Adaptive stepping to `t_end_s` (module docs).
    pub(super) fn run_adaptive<L: LoadHistory + ?Sized, O: Observer + ?Sized>(
        &mut self,
        t_end_s: f64,
        p: AdaptiveParams,
        load: &L,
        obs: &mut O,
    ) -> Result<(), SolveError> {
        let mut ctl = StepControl {
            p,
            c_err: (self.solver.beta - 1.0 / 6.0).abs(),
            half_b: 0.5 * self.model.width_m,
            coherent_s: self.half_period_s(),
            coherent_partial_s: self.coherent_partial_s(),
            level: 0,
            events: 0,
            at_event: false,
            landing: None,
            before_event_s: 0.0,
            breakpoint_s: f64::NEG_INFINITY,
        };
        // Round-off guard: never plan a step shorter than this fraction of dt_min to land on t_end.
        while t_end_s - self.state.t_s > 1e-3 * p.dt_min_s {
            let t = self.state.t_s;
            self.run.event_step = ctl.at_event;
            if t >= ctl.breakpoint_s {
                ctl.breakpoint_s = load.next_breakpoint_s(t);
            }
            // From a state where every spring in contact sticks, an exact step if one fits before
            // the breakpoint (`exact`); where a spring would slip, lift or touch down, the
            // Newmark step instead.
            if ctl.level == 0
                && !ctl.at_event
                && self.exact_advance(ctl.breakpoint_s, t_end_s, p.tolerance_m, load, obs)
            {
                continue;
            }
            let plan = self.plan_step(&mut ctl, t, t_end_s);
            let t1 = t + plan.h;
            let w = load.at(t1);
            match self.try_step(plan.h, self.load_vector(w)) {
                Ok(c) => match self.judge(&mut ctl, &plan, &c) {
                    Verdict::RestartedAtStart => {}
                    Verdict::Narrowed(s) | Verdict::EventFound(s) | Verdict::Rejected(s) => self.run.h_next = s,
                    Verdict::Accepted { ratio } => {
                        let mut c = c;
                        self.correct_onset_jumps(plan.h, &mut c);
                        self.commit_observed(plan.h, c, t1, w, obs);
                        self.run.h_next = ctl.accepted(&plan, ratio);
                    }
                },
                Err((iterations, residual)) => {
                    if ctl.level >= self.solver.max_substep_levels {
                        let levels = ctl.level;
                        return Err(SolveError::NonConvergence { t_s: t1, iterations, levels, residual });
                    }
                    ctl.level += 1;
                    ctl.landing = None;
                    self.stats.substeps += 1;
                    self.stats.max_substep_level = self.stats.max_substep_level.max(ctl.level);
                    self.run.h_next = (0.5 * plan.h).max(p.dt_min_s * 0.5f64.powi(ctl.level as i32));
                }
            }
        }
        Ok(())
    }

    /// The Newmark step to try from time `t`: the controller's length within [dt_min, dt_max]
    /// (after a Newton failure it may go below dt_min), cut at the load's next breakpoint and so
    /// as to leave no sliver shorter than dt_min before `t_end_s`; ended just past a lift-off or
    /// touch-down anticipated within it.
    #[inline(always)]
    fn plan_step(&mut self, ctl: &mut StepControl, t: f64, t_end_s: f64) -> Plan {
        let p = ctl.p;
        let planned =
            if ctl.level > 0 { self.run.h_next.min(p.dt_max_s) } else { self.run.h_next.clamp(p.dt_min_s, p.dt_max_s) };
        let mut h = planned.min(t_end_s - t);
        let bp = ctl.breakpoint_s;
        if bp - t > p.dt_min_s && bp < t + h {
            h = bp - t;
        }
        // Do not leave a sliver shorter than dt_min before t_end.
        if t_end_s - (t + h) < p.dt_min_s {
            h = t_end_s - t;
        }
        let truncated = h < planned;
        let kind = match (ctl.level > 0, ctl.landing.is_some()) {
            (true, _) => StepKind::Halved,
            (false, true) => StepKind::ToEvent,
            (false, false) => StepKind::Ordinary,
        };
        let mut plan = Plan { kind, h, planned, truncated };
        // A lift-off or touch-down ahead within the step: the step ends just past it.
        if kind == StepKind::Ordinary && !ctl.at_event && ctl.events < MAX_EVENTS_PER_STEP && self.solver.locate_contact
        {
            if let Some(e) = self.contact_ahead(h) {
                let to_event = e.theta * h * (1.0 + EVENT_LEAD);
                if to_event < h * (1.0 - EVENT_MIN_FRACTION) && to_event >= p.dt_min_s {
                    self.stats.located_events += 1;
                    ctl.landing = Some(Landing { predicted: true, ..Landing::new(e, h) });
                    ctl.before_event_s = h;
                    ctl.at_event = true;
                    self.run.event_step = true;
                    plan = Plan { kind: StepKind::ToAnticipatedEvent, h: to_event, ..plan };
                }
            }
        }
        plan
    }

    /// The verdict on the converged try `c` of `plan` (module docs, "Events" and "Adaptive
    /// stepping"), with the controller's bookkeeping of events.
    #[inline(always)]
    fn judge(&mut self, ctl: &mut StepControl, plan: &Plan, c: &Converged) -> Verdict {
        let (p, h) = (ctl.p, plan.h);
        if self.restart_at_start(c) {
            return Verdict::RestartedAtStart;
        }
        let contact = self.solver.locate_contact;
        debug_assert_eq!(ctl.landing.is_some(), matches!(plan.kind, StepKind::ToEvent | StepKind::ToAnticipatedEvent));
        if let Some(l) = ctl.landing.as_mut() {
            // A step retaken to end at an event: narrowed until it ends just past it (the event
            // in its last hundredth), or just short of it.
            let next = match self.event_fraction(h, c, contact) {
                Some(e) if (e.spring, e.kind) == (l.spring, l.kind) => Some(l.narrow(h, e.g1)),
                Some(e) => {
                    // Another event before it: land on that one instead.
                    *l = Landing { tries: l.tries + 1, ..Landing::new(e, h) };
                    Some(e.theta * h * (1.0 + EVENT_LEAD))
                }
                None => {
                    let (g0, g1) = self.event_margins(l.kind, l.spring, h, c);
                    let g = g1 * g0.signum();
                    // Short of it by more than a hundredth of the step.
                    if g > 0.0 && !l.predicted {
                        Some(l.narrow(h, g)).filter(|s| s - h > EVENT_MIN_FRACTION * h)
                    } else {
                        None
                    }
                }
            };
            if let Some(s) = next.filter(|&s| l.tries <= MAX_LOCATE_TRIES && s >= p.dt_min_s) {
                return Verdict::Narrowed(s);
            }
        }
        if ctl.landing.is_none() && !ctl.at_event && ctl.events < MAX_EVENTS_PER_STEP && h > p.dt_min_s {
            // The step's first event: the step is retaken to land on it.
            if let Some(e) = self.event_fraction(h, c, contact).filter(|e| e.theta * h >= p.dt_min_s) {
                self.stats.located_events += 1;
                ctl.events += 1;
                ctl.at_event = true;
                ctl.landing = Some(Landing::new(e, h));
                ctl.before_event_s = h;
                ctl.level = 0;
                return Verdict::EventFound(e.theta * h * (1.0 + EVENT_LEAD));
            }
        }
        let est = self.error_estimate_m(ctl, h, c);
        let err = est.err_m;
        let ratio = est.ratio(p.tolerance_m);
        if err > p.tolerance_m && h > p.dt_min_s {
            // Retried shorter by the estimate as h^(5/2) (module docs, "Adaptive stepping": the
            // step after an event, where nearly every rejection falls), or as h² per unit step.
            self.stats.rejected_steps += 1;
            let shrink = est.shrink(p.tolerance_m);
            ctl.landing = None;
            let mut next = (h * shrink.clamp(0.1, 0.9)).max(p.dt_min_s);
            if est.touch_down {
                if let Some(s) = self.before_touch_down(h, c, p.tolerance_m).filter(|&s| s >= p.dt_min_s) {
                    next = s;
                }
            }
            return Verdict::Rejected(next);
        }
        if err > p.tolerance_m {
            self.stats.forced_min_steps += 1;
        }
        Verdict::Accepted { ratio }
    }

    /// After a sticking try `c` of length `h` rejected for a touch-down's error (`seed-2011`: a
    /// spring that touches down at the fraction λ_i takes u_x,n as its slip position, an error
    /// λ_i |Δu_x| ≈ u̇_x τ_i, τ_i from the step's start to the touch, the same for any step that
    /// holds the touch): the step that ends just short of the first touch whose error is over the
    /// tolerance `tol_m` (θ (1 − EVENT_LEAD) h), so that the next step starts at it; `None` if
    /// none is (the estimate was another spring's).
    fn before_touch_down(&self, h: f64, c: &Converged, tol_m: f64) -> Option<f64> {
        let (un, du) = (self.state.u, (c.u[0] - self.state.u[0]).abs());
        let mut first = f64::INFINITY;
        for &x in &self.model.x_m {
            let (uy_start, uy_end) = (un[1] - un[2] * x, c.u[1] - c.u[2] * x);
            if uy_start >= 0.0 && uy_end < 0.0 {
                let lambda = uy_start / (uy_start - uy_end);
                if lambda * du > tol_m {
                    first = first.min(lambda);
                }
            }
        }
        first.is_finite().then_some(first * h * (1.0 - EVENT_LEAD))
    }

    /// [`StepControl::coherent_s`]: T_x/2, 0 if the period is not finite.
    fn half_period_s(&self) -> f64 {
        Some(0.5 * self.model.natural_period_s()).filter(|t| t.is_finite()).unwrap_or(0.0)
    }

    /// [`StepControl::coherent_partial_s`]: T_x/2 if 2 m_x/c_x ≥ T_x/2 (c_x the linear
    /// horizontal dashpot and those beside the springs), else 0.
    fn coherent_partial_s(&self) -> f64 {
        let half_period_s = self.half_period_s();
        let c_x = self.model.damping[(0, 0)] + self.model.x_m.len() as f64 * self.model.spring_dashpot_ns_per_m;
        if 2.0 * self.model.horizontal_mass_kg() >= half_period_s * c_x {
            half_period_s
        } else {
            0.0
        }
    }

    /// The error estimate of the converged try `c` of length `h`: the local error, m, the
    /// Zienkiewicz-Xie estimate of each row (θ as θ B/2) and the springs' slip positions'
    /// (`slip_error_m`); where every spring is in contact and sticks at the step's end and the
    /// step is shorter than `coherent_s`, the Zienkiewicz-Xie estimate times coherent_s/h, the
    /// error per unit step, or, if larger, `slip_error_m`'s (there a touch-down's), per step
    /// ([`Estimate`]).
    #[inline(always)]
    fn error_estimate_m(&self, ctl: &StepControl, h: f64, c: &Converged) -> Estimate {
        let an = self.state.a;
        let da = [(c.a[0] - an[0]).abs(), (c.a[1] - an[1]).abs(), (c.a[2] - an[2]).abs() * ctl.half_b];
        let ux_err = ctl.c_err * h * h * da[0];
        let newmark_m = ctl.c_err * h * h * da[0].max(da[1]).max(da[2]);
        let slip_m = self.slip_error_m(h, c, ux_err);
        // A sticking phase, whose Newmark error is the phase lag of its vibration: every spring
        // in contact and sticking at the step's end (the all-sticking iterate, or the general
        // one with none slipping and none lifted), or, without located contact (`seed-2011`),
        // every spring in contact sticking (some lifted). With located contact the phases with
        // springs lifted are stepped exactly (`exact`, "Partial contact"), and a Newmark step
        // among them is one the exact path declined. The same rule with the accelerators off.
        let sticking = self.fast.iterate.is_some()
            || (!self.trial_slips && (!self.solver.locate_contact || self.trial.iter().all(|r| r.normal_n > 0.0)));
        // With located contact, springs lifted and every spring in contact sticking, a step that
        // neither lands on an event nor changes the contact set (one of those the exact path
        // declined while it brackets an event) is held per unit step too where the vibration
        // outlives the span (`StepControl::coherent_partial_s`): held per step, on an undamped
        // caisson rocking on part of its base (family case 22 of
        // `tests/verify_adaptive_accuracy.rs`) the 437 Newmark steps with springs lifted before
        // 0.228 s (these and those landed on events) each within the tolerance, their
        // displacement errors summed to 4.8e-7 m and the run took the other
        // branch of a toe's slip (+1.99 µm, 5 %; held per unit step, +0.04 µm). Where the
        // horizontal dashpots damp the vibration within the span (the design example: decay time
        // 0.11 s, T_x/2 0.20 s) nothing changes: holding them there costs 3 % to 5 % more
        // instructions.
        let partial = !sticking
            && !self.trial_slips
            && !ctl.at_event
            && h < ctl.coherent_partial_s
            && !self.contact_may_change(self.state.u, c.u);
        let span_s = if partial { ctl.coherent_partial_s } else { ctl.coherent_s };
        if partial || (sticking && h < ctl.coherent_s) {
            // Only Newmark's error is a lag that every step adds: in a sticking phase no spring
            // slips, and what `slip_error_m` sees is a touch-down's (`seed-2011`), once per
            // event, held per step. Scaled by span/h, that one (∝ h) did not shrink with the
            // step: grazing springs drove the steps to dt_min, accepted over the tolerance.
            let per_unit_m = newmark_m * (span_s / h);
            if per_unit_m >= slip_m {
                Estimate { err_m: per_unit_m, per_unit_step: true, touch_down: false }
            } else {
                Estimate { err_m: slip_m, per_unit_step: false, touch_down: !self.solver.locate_contact }
            }
        } else {
            Estimate { err_m: newmark_m.max(slip_m), per_unit_step: false, touch_down: false }
        }
    }
}

impl StepControl {
    /// After the try of `plan` was accepted with the estimate's step ratio `ratio`: the next
    /// step's length. A step shortened to a breakpoint or landed on an event: the next one may
    /// be as long as the step planned before (the fragment does not restart the growth).
    #[inline(always)]
    fn accepted(&mut self, plan: &Plan, ratio: f64) -> f64 {
        let (p, h) = (self.p, plan.h);
        self.landing = None;
        let cap = if plan.truncated { plan.planned.max(2.0 * h) } else { 2.0 * h };
        let cap = if self.at_event { cap.max(self.before_event_s) } else { cap };
        let next = (h * ratio).min(cap).max(0.2 * h).clamp(p.dt_min_s, p.dt_max_s);
        self.level = 0;
        if !self.at_event {
            self.events = 0;
        }
        self.at_event = false;
        next
    }
}
