//! One wave through both models (module docs, step 6): its loads, the screen's and the stick
//! bound's decisions, its run through the dynamic model and what it records.

use super::outcome::StormOutcome;
use super::params::{StormCase, StormInput};
use super::screen::{heel_bound_pa, may_slide, ScreenBound};
use super::storm::{Settle, StillWave, StormError, StormSite, ROTATION_RESERVE};
use crate::analysis::limits::ROCKING_LIMIT_RAD;
use crate::analysis::run::permanent_sliding_m;
use crate::analysis::stick_bound::{AtPeriod, StickBound};
use crate::dynamics::{Observer, Simulation, StepView};
use crate::loads::history::{WaveEvent, WaveTrain};
use crate::loads::model::{PeakComponents, PeriodLoads};
use crate::loads::regime::RegimeChoice;
use crate::loads::safety::heel_pressure_pa;
use std::cell::OnceCell;

/// What a wave did besides sliding: the largest rotation, whether part of the base lifted and
/// the largest heel pressure.
#[derive(Debug, Clone, Copy, Default)]
struct WaveWatch {
    pub(super) max_rotation_rad: f64,
    pub(super) lifted: bool,
    /// Pa ([`base_heel_pressure_pa`] of the springs' resultant).
    max_heel_pressure_pa: f64,
    /// B and the caisson's length l, m.
    pub(super) width_m: f64,
    pub(super) length_m: f64,
}

impl WaveWatch {
    pub(super) fn new(width_m: f64, length_m: f64) -> Self {
        WaveWatch { width_m, length_m, ..WaveWatch::default() }
    }
}

impl Observer for WaveWatch {
    #[inline]
    fn observe(&mut self, s: &StepView<'_>) {
        self.max_rotation_rad = self.max_rotation_rad.max(s.state.u[2].abs());
        // A spring out of contact (N_i ≤ 0, as the reaction counts them), once is enough.
        self.lifted = self.lifted || !s.springs.iter().all(|r| r.normal_n > 0.0);
        let r = &s.reaction;
        let q = base_heel_pressure_pa(r.normal_n, r.moment_nm, self.width_m, self.length_m);
        self.max_heel_pressure_pa = self.max_heel_pressure_pa.max(q);
    }
    /// The springs' responses, not built for an all-sticking step (the slice is then empty:
    /// every spring is in contact).
    #[inline]
    fn reads_springs(&self) -> bool {
        false
    }
    /// The springs' resultant, for the heel pressure.
    #[inline]
    fn reads_reaction(&self) -> bool {
        true
    }
}

/// The heel pressure of the base that carries the springs' normal forces `normal_n` (their sum,
/// N) with the moment `moment_nm` about the base centre (Σ x_i N_i, N·m, x shoreward: module docs,
/// "Heel pressure"), on a caisson `width_m` wide and `length_m` long, Pa: the heel (shoreward
/// edge) value of the linear base pressure without tension that has that resultant, Goda's
/// (2000) heel pressure p_e of [`crate::loads::safety::heel_pressure_pa`] with V = ΣN_i / l and
/// t_e = B/2 − Σ x_i N_i / ΣN_i; 0 with no spring pressed.
pub fn base_heel_pressure_pa(normal_n: f64, moment_nm: f64, width_m: f64, length_m: f64) -> f64 {
    if normal_n <= 0.0 {
        return 0.0;
    }
    heel_pressure_pa(normal_n / length_m, 0.5 * width_m - moment_nm / normal_n, width_m)
}
/// The loads of the wave of height `h` (clamped), rise-time deviate `z` and period `period_s` of
/// storm `s` at `site`, times the storm's errors; `loads_t13`: the loads at the storm's T1/3.
pub(super) fn wave_event(
    s: &StormInput,
    site: &StormSite,
    loads_t13: &PeriodLoads<'_>,
    (h, z, period_s): (f64, f64, f64),
) -> WaveEvent {
    let own;
    let loads_at = if s.periods.is_significant() {
        loads_t13
    } else {
        own = site.model.at_period(period_s);
        &own
    };
    // A forced regime the wave contradicts (non-breaking above the limit): the criterion decides.
    let e = match loads_at.event(h, site.model.options.regime, z) {
        Ok(e) => e,
        Err(_) => loads_at.event(h, RegimeChoice::Auto, z).expect("the automatic regime always applies"),
    };
    WaveEvent {
        quasi: e.quasi.scaled(s.force_factor),
        trough: e.trough.scaled(s.force_factor),
        impact: e.impact.scaled(s.impact_factor),
        ..e
    }
}

/// One wave through both models (module docs, step 6): its loads at its own period tested against
/// the screen's bound at that period, then the rigid block, then the dynamic model (unless the
/// stick bound answers it).
pub(super) struct WaveRun<'a> {
    pub(super) st: &'a StormCase<'a>,
    pub(super) s: &'a StormInput,
    pub(super) site: &'a StormSite,
    /// The loads and the screen's bound at the storm's T1/3 (every wave's period by default).
    pub(super) loads_t13: &'a PeriodLoads<'a>,
    pub(super) bound_t13: ScreenBound,
    pub(super) start_m: f64,
    /// Whether the life (or storm) has failed already (module docs, "Failure"): its failing wave
    /// is recorded once.
    pub(super) failed: bool,
    /// Whether the dynamic model has stopped running on after the failure (a wave that did not
    /// converge, [`StormOutcome::run_on_stopped`]): only the rigid block runs.
    pub(super) stopped: bool,
    /// The rigid block's sliding before the storm, m, and whether it has passed the sliding
    /// limit already (its failing wave is recorded once).
    pub(super) rigid_start_m: f64,
    pub(super) rigid_failed: bool,
    /// The largest heel pressure of the life before the storm, kPa.
    pub(super) heel_floor_kpa: f64,
    pub(super) sim: Option<Simulation>,
    pub(super) train: &'a mut WaveTrain,
    /// The linear bound at T1/3, built when a wave first needs it.
    pub(super) stick_t13: OnceCell<Option<AtPeriod>>,
    /// The waves the linear bound answered whose rotation may be the storm's (or the life's)
    /// largest.
    pub(super) still: &'a mut Vec<StillWave>,
    /// The waves that may press the heel beyond the screen's pressure and the largest known, run
    /// for it at the storm's (or life's) end if it may still be the largest.
    pub(super) heel: &'a mut Vec<StillWave>,
    /// Whose largest rotation they settle.
    pub(super) settle: Settle,
}

impl WaveRun<'_> {
    /// The loads of the wave of height `h` (clamped), rise-time deviate `z` and period
    /// `period_s`, times the storm's errors, and the screen's bound at its period.
    pub(super) fn event(&self, h: f64, z: f64, period_s: f64) -> (WaveEvent, ScreenBound) {
        let (s, site) = (self.s, self.site);
        let bound = if s.periods.is_significant() { self.bound_t13 } else { site.bound(period_s) };
        (wave_event(s, site, self.loads_t13, (h, z, period_s)), bound)
    }

    /// Wave of height `h` (clamped), rise-time deviate `z` and period `period_s`.
    pub(super) fn run(&mut self, h: f64, z: f64, period_s: f64, out: &mut StormOutcome) -> Result<(), StormError> {
        let (st, site) = (self.st, self.site);
        let (event, bound) = self.event(h, z, period_s);
        // The grid's neighbours are a margin for the heights (and periods) between its nodes; the
        // wave's own loads decide.
        let peaks = PeakComponents { quasi: event.quasi, impact: event.impact };
        let slides = may_slide(&peaks, &bound);
        if st.screen && !slides {
            // A wave that can neither slide nor lift the caisson runs for its heel pressure alone,
            // if it may press the heel to the screen's pressure and beyond the largest heel
            // pressure known (module docs, "Heel pressure").
            let heel_pa = heel_bound_pa(&peaks, &bound);
            if heel_pa < site.heel_screen_pa || heel_pa <= self.heel_known_pa(out) {
                out.screened_waves += 1;
                return Ok(());
            }
            if self.stopped || self.defers_heel(heel_pa) {
                out.screened_waves += 1;
                if !self.stopped {
                    self.defer_heel(heel_pa, h, z, period_s);
                }
                return Ok(());
            }
            return self.simulate(event, h, period_s, WaveKind::HeelOnly, out);
        }
        // The impulsive waves counted: those that may slide or lift (module docs, "Impulsive
        // waves"), whether the screen is on or not.
        let impulsive = event.impulse.is_some() && slides;
        let rigid_m = site.block.wave_sliding_m(&event);
        out.rigid_block_sliding_m += rigid_m;
        if impulsive {
            out.rigid_block_impulsive_sliding_m += rigid_m;
        }
        if !self.rigid_failed {
            if let Some(f) = st.failure {
                if (self.rigid_start_m + out.rigid_block_sliding_m).abs() > f.sliding_m {
                    self.rigid_failed = true;
                    out.rigid_block_failing_wave_impulsive = u64::from(event.impulse.is_some());
                }
            }
        }
        if self.stopped {
            out.screened_waves += 1;
            return Ok(());
        }
        // A wave that may press the heel to the screen's heel pressure and beyond the largest
        // known runs, whatever the stick bound says (it bounds no heel pressure).
        let heel_pa = heel_bound_pa(&peaks, &bound);
        let heel_known = heel_pa < site.heel_screen_pa || heel_pa <= self.heel_known_pa(out);
        if st.screen && st.stick_bound && (heel_known || self.defers_heel(heel_pa)) {
            if let Some(rotation_rad) = self.still_rotation_rad(&event, period_s) {
                if !heel_known {
                    self.defer_heel(heel_pa, h, z, period_s);
                }
                // Neither slides nor lifts (module docs, "The screen"): its rotation may still be
                // the storm's (or the life's) largest, which [`Self::settle`] (or
                // [`settle_life`]) decides, unless a larger one is known already. An impulsive
                // one counts as impulsive all the same (its sliding, 0, adds nothing); settled, it
                // runs as a still wave, not counted again.
                out.screened_waves += 1;
                out.impulsive_waves += u64::from(impulsive);
                let (floor_rad, storm) = match self.settle {
                    Settle::Storm => (out.max_rotation_rad, 0),
                    Settle::Life { floor_rad, storm } => (floor_rad.max(out.max_rotation_rad), storm),
                };
                if st.settle_rotation && rotation_rad * ROTATION_RESERVE > floor_rad {
                    self.still.push(StillWave { rotation_rad, storm, height_m: h, deviate: z, period_s });
                }
                return Ok(());
            }
        }
        let kind = if impulsive { WaveKind::Impulsive } else { WaveKind::Pulsating };
        self.simulate(event, h, period_s, kind, out)
    }

    /// The largest heel pressure known in the life (or storm) so far, Pa.
    fn heel_known_pa(&self, out: &StormOutcome) -> f64 {
        1e3 * out.max_heel_pressure_kpa.max(self.heel_floor_kpa)
    }

    /// Whether a wave that neither slides nor lifts the caisson and may press its heel to
    /// `heel_pa` can run at the storm's (or life's) end: unless it may fail the life by heel
    /// pressure (then it runs in its place, so that the failing wave is the first).
    fn defers_heel(&self, heel_pa: f64) -> bool {
        self.st.failure.and_then(|f| f.heel_pressure_pa).is_none_or(|q| heel_pa <= q)
    }

    /// Keep the wave of height `h`, deviate `z` and period `period_s`, whose heel pressure may
    /// reach `heel_pa`, for the storm's (or life's) end.
    fn defer_heel(&mut self, heel_pa: f64, h: f64, z: f64, period_s: f64) {
        let storm = match self.settle {
            Settle::Storm => 0,
            Settle::Life { storm, .. } => storm,
        };
        self.heel.push(StillWave { rotation_rad: heel_pa, storm, height_m: h, deviate: z, period_s });
    }

    /// The bound on the rotation of a wave that the linear bound shows can neither slide nor
    /// lift the caisson, nor rotate it near the rocking or failure limits
    /// ([`crate::analysis::stick_bound`]: a pulsating wave's by [`StickBound::margins`], an
    /// impulsive one's by [`StickBound::impulse_margins`]); `None` for any other wave.
    fn still_rotation_rad(&self, event: &WaveEvent, period_s: f64) -> Option<f64> {
        let site = self.site;
        let bound = site.stick.get_or_init(|| StickBound::new(site.dyn_model())).as_ref()?;
        let m = if event.impulse.is_some() {
            bound.impulse_margins(event)
        } else {
            let own;
            let at = if self.s.periods.is_significant() {
                self.stick_t13.get_or_init(|| bound.at_period(self.s.period_s)).as_ref()?
            } else {
                own = bound.at_period(period_s)?;
                &own
            };
            bound.margins(at, event.quasi.total(), event.trough.total())
        };
        let limit_rad = self.st.failure.map_or(ROCKING_LIMIT_RAD, |f| f.rotation_rad.min(ROCKING_LIMIT_RAD));
        (m.still() && m.rotation_rad * ROTATION_RESERVE < limit_rad).then_some(m.rotation_rad)
    }

    /// Run the kept waves of a storm alone whose bound may exceed the storm's largest, largest
    /// bound first, until the bound of the next is at most it (module docs, "The stick bound" and
    /// "Heel pressure"; a life's are run by [`settle_life`](super::life::settle_life)): the still
    /// waves for the rotation (`heel` false), or the deferred waves for the heel pressure. The
    /// storm's largest is then what running every such wave gives. Each wave run moves from the
    /// screened to the simulated count.
    pub(super) fn settle(&mut self, heel: bool, out: &mut StormOutcome) -> Result<(), StormError> {
        if matches!(self.settle, Settle::Life { .. }) {
            return Ok(());
        }
        let mut kept = std::mem::take(if heel { &mut *self.heel } else { &mut *self.still });
        kept.sort_unstable_by(|a, b| b.rotation_rad.total_cmp(&a.rotation_rad));
        let kind = if heel { WaveKind::HeelOnly } else { WaveKind::Pulsating };
        for w in &kept {
            let needed = if heel {
                w.rotation_rad > 1e3 * out.max_heel_pressure_kpa
            } else {
                w.rotation_rad * ROTATION_RESERVE > out.max_rotation_rad
            };
            if !needed {
                break;
            }
            let (event, _) = self.event(w.height_m, w.deviate, w.period_s);
            out.screened_waves -= 1;
            self.simulate(event, w.height_m, w.period_s, kind, out)?;
        }
        kept.clear();
        *(if heel { &mut *self.heel } else { &mut *self.still }) = kept;
        Ok(())
    }

    /// Run `event` (of height `h` and period `period_s`, of the `kind` the screen found) through
    /// the dynamic model, and record the failure it brings.
    pub(super) fn simulate(
        &mut self,
        event: WaveEvent,
        h: f64,
        period_s: f64,
        kind: WaveKind,
        out: &mut StormOutcome,
    ) -> Result<(), StormError> {
        let (st, site) = (self.st, self.site);
        let train = &mut *self.train;
        train.set_single(event).map_err(|source| StormError::Wave { height_m: h, period_s, source })?;
        let sim = match self.sim.as_mut() {
            Some(x) => {
                x.reset(&*train);
                x
            }
            None => self.sim.insert(Simulation::new(site.dyn_model().clone(), st.structure.solver, &*train)),
        };
        let mut watch = WaveWatch::new(site.width_m, site.length_m);
        match sim.run_until(period_s, &*train, &mut watch) {
            Ok(()) => {}
            // After the failure the model is outside its validity: a wave that does not converge
            // stops the dynamic model's run-on (module docs, "Failure"); before it, an error.
            Err(_) if self.failed => {
                self.stopped = true;
                out.run_on_stopped = 1;
                out.screened_waves += 1;
                return Ok(());
            }
            // The engine does not follow a caisson that overturns or slides away (module docs,
            // "Failure"): the failing wave, if the engine cannot integrate it past the model's
            // limits, ends at its last converged step.
            Err(e) => {
                let beyond_sliding = st
                    .failure
                    .is_some_and(|f| (self.start_m + out.sliding_m + permanent_sliding_m(sim)).abs() > f.sliding_m);
                if !(watch.max_rotation_rad > ROCKING_LIMIT_RAD || beyond_sliding) {
                    return Err(e.into());
                }
            }
        }
        out.simulated_waves += 1;
        out.max_heel_pressure_kpa = out.max_heel_pressure_kpa.max(watch.max_heel_pressure_pa / 1e3);
        if kind == WaveKind::HeelOnly {
            // It can neither slide nor lift the caisson (the screen's bound): only its heel
            // pressure is read, so that every other output is that of the screen without the heel
            // pressure (module docs, "Heel pressure").
            self.record_failure(out, &event);
            return Ok(());
        }
        let slide = permanent_sliding_m(sim);
        out.sliding_m += slide;
        if kind == WaveKind::Impulsive {
            out.impulsive_waves += 1;
            out.impulsive_sliding_m += slide;
        }
        if slide >= 0.0 {
            out.shoreward_sliding_m += slide;
        } else {
            out.seaward_sliding_m -= slide;
        }
        out.max_excursion_m = out.max_excursion_m.max((self.start_m + out.sliding_m).abs());
        out.rocking_waves += u64::from(watch.lifted);
        out.large_rotation_waves += u64::from(watch.max_rotation_rad > ROCKING_LIMIT_RAD);
        out.max_rotation_rad = out.max_rotation_rad.max(watch.max_rotation_rad);
        self.record_failure(out, &event);
        Ok(())
    }

    /// Record the failure the wave `event` just run brings, if the life (or storm) had not
    /// failed: its modes and whether it was impulsive.
    fn record_failure(&mut self, out: &mut StormOutcome, event: &WaveEvent) {
        if !self.failed {
            if let Some(f) = self.st.failure {
                let [sliding, rotation, heel] = out.beyond(&f);
                if sliding || rotation || heel {
                    self.failed = true;
                    out.failed_by_sliding = u64::from(sliding);
                    out.failed_by_rotation = u64::from(rotation);
                    out.failed_by_heel_pressure = u64::from(heel);
                    out.failing_wave_impulsive = u64::from(event.impulse.is_some());
                }
            }
        }
    }
}

/// What the screen found of a wave that runs through the dynamic model: it may slide or lift
/// the caisson, with an impulsive load (counted as impulsive) or not, or it may only press the
/// heel beyond the screen's heel pressure (module docs, "Heel pressure").
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum WaveKind {
    Impulsive,
    Pulsating,
    HeelOnly,
}
