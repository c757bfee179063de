//! One life of storms (module docs, "One life", "The stick bound"), its still waves settled at its
//! end, and the lives of a run in parallel.

use super::outcome::StormOutcome;
use super::params::{ErrorDraw, ErrorScope, LifeParams, StormCase, StormInput, STORM_WAVE_WORDS_LOG2};
use super::screen::ScreenModes;
use super::storm::{
    storm_from, toe_depth_m, Settle, StillWave, StormError, StormRng, StormScratch, StormSite, StormStart,
    MAX_STILL_WAVES, ROTATION_RESERVE,
};
use super::wave::{base_heel_pressure_pa, wave_event, WaveKind, WaveRun};
use crate::analysis::stick_bound::{Ask, StickBound};
use crate::loads::generator::realization_rng;
use crate::loads::history::{WaveEvent, WaveTrain};
use crate::loads::model::PeriodLoads;
use crate::loads::risetime::LoadRng;
use crate::waves::dispersion::wavenumber;
use crate::waves::surf_zone::SlopeTerms;
use rand::Rng;
use rayon::prelude::*;
use std::cell::OnceCell;
use std::f64::consts::PI;
use std::ops::ControlFlow;
use std::sync::atomic::{AtomicBool, Ordering};
use thiserror::Error;

/// One life of `p.life_years` storms (module docs), life `index` of the stream `seed`.
pub fn simulate_life(st: &StormCase<'_>, p: &LifeParams, seed: u64, index: usize) -> Result<StormOutcome, StormError> {
    let mut rng = realization_rng(seed, index);
    let c = &st.structure.caisson;
    // The heel pressure at rest at still water (the lowest water of the life: the heaviest
    // caisson in water).
    let rest_pa = base_heel_pressure_pa(c.weight_in_water_n, 0.0, c.width_m, c.length_m);
    let mut life = StormOutcome { max_heel_pressure_kpa: rest_pa / 1e3, ..StormOutcome::default() };
    let mut scratch = StormScratch::default();
    let site = &st.model.site;
    // The surf zone's slope terms: the same for every storm of the life.
    let slope = SlopeTerms::new(site.seabed_slope);
    // Errors per life: drawn once, before the first storm.
    let life_errors = (p.errors.scope == ErrorScope::Life).then(|| p.errors.draw(&mut rng));
    // Storms counted over the life: storm k draws its waves from word (k + 1) · 2^40.
    let mut storm_index: u128 = 0;
    for year in 0..p.life_years {
        let rise_m = p.climate.sea_level.rise_in_year_m(year);
        for _ in 0..p.climate.storms.storms_in_year(&mut rng) {
            let (storm, k_toe) = draw_storm(st, p, &slope, &mut rng, life_errors, rise_m);
            // The storm's waves from their own part of the stream: how many it draws does not move
            // the next storm's numbers (common random numbers across caissons, docs/size.md).
            storm_index += 1;
            let mut positioned = None;
            let word = storm_index << STORM_WAVE_WORDS_LOG2;
            let mut waves_rng = StormRng::Storm { life: &rng, word, rng: &mut positioned };
            let failed = life.failed();
            let settle = Settle::Life { floor_rad: life.max_rotation_rad, storm: scratch.storms.len() };
            scratch.storms.push(storm);
            let from = StormStart {
                start_m: life.sliding_m,
                rigid_m: life.rigid_block_sliding_m,
                heel_floor_kpa: life.max_heel_pressure_kpa,
                failed,
                stopped: life.run_on_stopped != 0,
                settle,
            };
            let o = storm_from(st, &storm, &mut waves_rng, from, Some(k_toe), &mut scratch)?;
            if !failed && o.failed() {
                life.failure_year = year as u64 + 1;
            }
            life.add(&o);
            // The still waves the life's largest rotation so far exceeds cannot be its largest.
            scratch.still.retain(|w| w.rotation_rad * ROTATION_RESERVE > life.max_rotation_rad);
            scratch.heel.retain(|w| w.rotation_rad > 1e3 * life.max_heel_pressure_kpa);
            if scratch.still.len() > MAX_STILL_WAVES || scratch.heel.len() > MAX_STILL_WAVES {
                settle_life(st, &mut scratch, &mut life)?;
            }
        }
    }
    settle_life(st, &mut scratch, &mut life)?;
    life.finite()
}

/// One storm of a life as drawn from the life's stream (module docs, "One life", steps 1-3), before
/// its heights at the structure ([`StormDraw::at_structure`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct StormDraw {
    /// The deep-water H1/3 (with its estimation error), m, and T1/3, s.
    pub(super) h0_m: f64,
    pub(super) period_s: f64,
    duration_s: f64,
    angle_rad: f64,
    /// The water level above still water, m.
    tide_m: f64,
    pub(super) errors: ErrorDraw,
}

impl StormDraw {
    /// The next storm of the life's stream `rng` in year `rise_m`'s sea level. `life_errors`: the
    /// errors drawn once per life, if so.
    fn draw(p: &LifeParams, rng: &mut LoadRng, life_errors: Option<ErrorDraw>, rise_m: f64) -> Self {
        let u: f64 = rng.gen::<f64>().clamp(1e-12, 1.0 - 1e-12);
        let errors = match life_errors {
            Some(e) => e,
            None => p.errors.draw(rng),
        };
        let phi = 2.0 * PI * rng.gen::<f64>();
        let h0_m = (p.storm_height_m(u) * errors.h0).max(1e-3);
        let period_s = p.period_coefficient * h0_m.powf(p.period_exponent);
        let duration_s = p.climate.duration.draw_s(p.storm_duration_s, rng);
        let angle_rad = p.climate.direction.draw_rad(rng);
        let tide_m = 0.5 * p.tidal_range_m * (1.0 + phi.cos()) + rise_m;
        StormDraw { h0_m, period_s, duration_s, angle_rad, tide_m, errors }
    }

    /// The storm at the structure (step 4: Goda's surf-zone heights at the toe, times the
    /// transformation error) and the wavenumber at the toe (the dispersion solve serves the
    /// shoaling and the storm's loads).
    pub(super) fn at_structure(&self, st: &StormCase<'_>, p: &LifeParams, slope: &SlopeTerms) -> (StormInput, f64) {
        let depth_m = toe_depth_m(st, self.tide_m);
        let k_toe = wavenumber(self.period_s, depth_m);
        let z = slope.surf_zone_at_wavenumber(self.h0_m, self.period_s, depth_m, k_toe);
        let e = &self.errors;
        let storm = StormInput {
            h13_m: z.h13_m * e.transformation,
            hmax_m: z.hmax_m * e.transformation,
            period_s: self.period_s,
            periods: p.climate.periods,
            waves: (self.duration_s / self.period_s).round().max(1.0) as usize,
            tide_m: self.tide_m,
            angle_rad: self.angle_rad,
            force_factor: e.force,
            impact_factor: e.impact,
            friction_factor: e.friction,
        };
        (storm, k_toe)
    }
}

/// One storm of a life from the life's stream: [`StormDraw::draw`], then at the structure.
fn draw_storm(
    st: &StormCase<'_>,
    p: &LifeParams,
    slope: &SlopeTerms,
    rng: &mut LoadRng,
    life_errors: Option<ErrorDraw>,
    rise_m: f64,
) -> (StormInput, f64) {
    StormDraw::draw(p, rng, life_errors, rise_m).at_structure(st, p, slope)
}

/// The storms of life `index` of the stream `seed` as [`simulate_life`] draws them, before their
/// heights at the structure and without their waves (each storm's waves come from their own part of
/// the stream, so the storms do not depend on them), in order. What a stratified design run ranks
/// a life by ([`super::sampling`]).
pub(super) fn life_storms(p: &LifeParams, seed: u64, index: usize, storms: &mut Vec<StormDraw>) {
    storms.clear();
    let mut rng = realization_rng(seed, index);
    let life_errors = (p.errors.scope == ErrorScope::Life).then(|| p.errors.draw(&mut rng));
    for year in 0..p.life_years {
        let rise_m = p.climate.sea_level.rise_in_year_m(year);
        for _ in 0..p.climate.storms.storms_in_year(&mut rng) {
            storms.push(StormDraw::draw(p, &mut rng, life_errors, rise_m));
        }
    }
}

/// Run the still waves of the life's storms whose rotation bound may exceed the life's largest
/// rotation, largest bound first, until the bound of the next is below it (module docs, "The
/// stick bound"): the life's largest rotation is then what running every wave gives. The bounds
/// are sharpened lazily ([`Settler::still_waves`]). Each wave run moves from the screened to the
/// simulated count; it neither slides nor lifts (its bound says so), so only the rotation and the
/// counts can move. Then the deferred waves for the heel pressure likewise (module docs, "Heel
/// pressure"). Empties `scratch.still` and `scratch.heel`.
pub(super) fn settle_life(
    st: &StormCase<'_>,
    scratch: &mut StormScratch,
    life: &mut StormOutcome,
) -> Result<(), StormError> {
    let modes = scratch.modes(st);
    let StormScratch { train, still, heel, storms, .. } = scratch;
    still.retain(|w| w.rotation_rad * ROTATION_RESERVE > life.max_rotation_rad);
    heel.retain(|w| w.rotation_rad > 1e3 * life.max_heel_pressure_kpa);
    still.sort_unstable_by(|a, b| b.rotation_rad.total_cmp(&a.rotation_rad));
    heel.sort_unstable_by(|a, b| b.rotation_rad.total_cmp(&a.rotation_rad));
    // The sites of the storms whose waves are sharpened or run, and their loads at T1/3, each
    // built when first needed.
    let sites: Vec<OnceCell<StormSite>> = storms.iter().map(|_| OnceCell::new()).collect();
    let loads: Vec<OnceCell<PeriodLoads<'_>>> = storms.iter().map(|_| OnceCell::new()).collect();
    let mut settler = Settler { st, storms, sites: &sites, loads: &loads, train, modes };
    settler.kept_waves(still, WaveKind::Pulsating, life)?;
    settler.kept_waves(heel, WaveKind::HeelOnly, life)?;
    still.clear();
    heel.clear();
    Ok(())
}

/// Whether a kept wave of `kind` whose bound is `bound` may still raise the life's largest
/// rotation (a still wave: `bound` times [`ROTATION_RESERVE`] above it) or heel pressure (a
/// deferred wave: `bound`, Pa, above it), and must run.
fn needed(kind: WaveKind, bound: f64, life: &StormOutcome) -> bool {
    if kind == WaveKind::HeelOnly {
        bound > 1e3 * life.max_heel_pressure_kpa
    } else {
        bound * ROTATION_RESERVE > life.max_rotation_rad
    }
}

/// The margin on the rise of a deferred wave's heel pressure over the rest under its own load
/// history ([`StickBound::heel_under_history_pa`]) for what the all-sticking response leaves out
/// (the shear's departure R, the engine's steps): the engine's rise was at most 1.0005 times the
/// bound's on 215 waves (`tests/verify_stick_bound.rs`).
pub(super) const HEEL_RESERVE: f64 = 1.01;

/// What runs a life's kept waves at its end ([`settle_life`]): the life's storms, the sites of
/// those whose waves may run and their loads at T1/3.
struct Settler<'s, 'a> {
    st: &'s StormCase<'a>,
    storms: &'s [StormInput],
    sites: &'s [OnceCell<StormSite>],
    loads: &'s [OnceCell<PeriodLoads<'s>>],
    train: &'s mut WaveTrain,
    modes: ScreenModes,
}

impl<'s> Settler<'s, '_> {
    fn site(&self, w: &StillWave) -> &'s StormSite {
        let sites: &'s [OnceCell<StormSite>] = self.sites;
        sites[w.storm].get_or_init(|| StormSite::new(self.st, &self.storms[w.storm], self.modes))
    }

    /// The loads at T1/3 of the storm of the kept wave `w`.
    fn loads_t13(&self, w: &StillWave) -> &'s PeriodLoads<'s> {
        let (loads, site): (&'s [OnceCell<PeriodLoads<'s>>], _) = (self.loads, self.site(w));
        loads[w.storm].get_or_init(|| site.model.at_period(self.storms[w.storm].period_s))
    }

    /// The loads of the kept wave `w`.
    fn event(&self, w: &StillWave) -> WaveEvent {
        let (s, site) = (&self.storms[w.storm], self.site(w));
        wave_event(s, site, self.loads_t13(w), (w.height_m, w.deviate, w.period_s))
    }

    /// The kept waves `kept` of `kind` (sorted by their bounds, largest first: the still waves'
    /// rotations, or the deferred waves' heel pressures), largest bound first until the next is
    /// not [`needed`], each bound sharpened ([`Self::sharper`]) when it is the largest left: a
    /// wave's sharper bound is at most its bound, so the largest sharpened one at or above every
    /// bound not yet sharpened is the largest of all, and the wave to run next, or to stop at.
    fn kept_waves(&mut self, kept: &[StillWave], kind: WaveKind, life: &mut StormOutcome) -> Result<(), StormError> {
        let mut sharpened: Vec<(f64, usize, WaveEvent)> = Vec::new();
        let mut next = 0;
        loop {
            let unsharpened = kept
                .get(next)
                .filter(|w| needed(kind, w.rotation_rad, life))
                .map_or(f64::NEG_INFINITY, |w| w.rotation_rad);
            let best = (0..sharpened.len()).max_by(|&a, &b| sharpened[a].0.total_cmp(&sharpened[b].0));
            match best {
                Some(b) if sharpened[b].0 >= unsharpened => {
                    let (bound, i, event) = sharpened.swap_remove(b);
                    if !needed(kind, bound, life) {
                        break;
                    }
                    self.run(&kept[i], event, kind, life)?;
                }
                _ if unsharpened > f64::NEG_INFINITY => {
                    let w = &kept[next];
                    let event = self.event(w);
                    let bound = self.sharper(w, &event, kind, life).map_or(w.rotation_rad, |b| b.min(w.rotation_rad));
                    if needed(kind, bound, life) {
                        sharpened.push((bound, next, event));
                    }
                    next += 1;
                }
                _ => break,
            }
        }
        Ok(())
    }

    /// A sharper bound of the kept wave `w` of loads `event`: a still wave's rotation under its
    /// own load history ([`StickBound::rotation_under_history_rad`]); a deferred one's heel
    /// pressure likewise ([`StickBound::heel_under_history_pa`], its rise over the rest times
    /// [`HEEL_RESERVE`]) if the stick bound shows the wave neither slips nor lifts a spring
    /// (the all-sticking response is then the engine's). Each is asked only to show it is not
    /// [`needed`] where it can ([`Ask::AtMost`]: it gives up as soon as it sees the response above
    /// what would show it, and the heel pressure's bound is asked before the stick bound's test,
    /// which it then spares: on the design example 2 070 heel-pressure bounds a 200 lives, most
    /// of them given up).
    fn sharper(&self, w: &StillWave, event: &WaveEvent, kind: WaveKind, life: &StormOutcome) -> Option<f64> {
        let site = self.site(w);
        let bound = site.stick.get_or_init(|| StickBound::new(site.dyn_model())).as_ref()?;
        if kind != WaveKind::HeelOnly {
            return bound.rotation_under_history_rad(event, Ask::AtMost(life.max_rotation_rad / ROTATION_RESERVE));
        }
        // The heel pressure's bound first: where a value above the floor is seen it stops at once
        // (nothing to show), the stick bound's test is not needed.
        let rest_pa = bound.heel_at_rest_pa(site.width_m, site.length_m);
        let floor_pa = rest_pa + (1e3 * life.max_heel_pressure_kpa - rest_pa) / HEEL_RESERVE;
        let heel_pa = bound.heel_under_history_pa(event, site.width_m, site.length_m, Ask::AtMost(floor_pa))?;
        if heel_pa == f64::INFINITY {
            return None;
        }
        let still = if event.impulse.is_some() {
            bound.impulse_margins(event).still()
        } else {
            let at = bound.at_period(w.period_s)?;
            bound.margins(&at, event.quasi.total(), event.trough.total()).still()
        };
        still.then(|| rest_pa + HEEL_RESERVE * (heel_pa - rest_pa).max(0.0))
    }

    /// Run the kept wave `w` of loads `event` as `kind` (a still wave as pulsating: it is not
    /// counted as impulsive again; a deferred one for its heel pressure), and move it from the
    /// screened to the simulated count.
    fn run(
        &mut self,
        w: &StillWave,
        event: WaveEvent,
        kind: WaveKind,
        life: &mut StormOutcome,
    ) -> Result<(), StormError> {
        let (st, s, site, loads_t13) = (self.st, &self.storms[w.storm], self.site(w), self.loads_t13(w));
        let (mut none, mut no_heel) = (Vec::new(), Vec::new());
        let mut run = WaveRun {
            st,
            s,
            site,
            loads_t13,
            bound_t13: site.bound(s.period_s),
            start_m: 0.0,
            // A still wave can fail no life (module docs, "The stick bound"), nor can a deferred
            // one (its bound is below the failure heel pressure): nothing is recorded; a failed
            // life's wave that does not converge stays screened.
            failed: life.failed(),
            stopped: false,
            rigid_start_m: 0.0,
            rigid_failed: true,
            heel_floor_kpa: 0.0,
            sim: None,
            train: self.train,
            stick_t13: OnceCell::new(),
            still: &mut none,
            heel: &mut no_heel,
            settle: Settle::Storm,
        };
        let mut o = StormOutcome::default();
        run.simulate(event, w.height_m, w.period_s, kind, &mut o)?;
        if o.simulated_waves == 0 {
            // It did not converge, in a failed life: it stays screened.
            return Ok(());
        }
        life.simulated_waves += 1;
        life.screened_waves -= 1;
        if kind == WaveKind::HeelOnly {
            life.max_heel_pressure_kpa = life.max_heel_pressure_kpa.max(o.max_heel_pressure_kpa);
            return Ok(());
        }
        life.rocking_waves += o.rocking_waves;
        life.large_rotation_waves += o.large_rotation_waves;
        life.max_rotation_rad = life.max_rotation_rad.max(o.max_rotation_rad);
        #[cfg(test)]
        super::tests::SETTLED.with(|n| n.set(n.get() + 1));
        Ok(())
    }
}

/// A life that could not be simulated.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("life {life} failed")]
pub struct LifeFailed {
    pub life: usize,
    #[source]
    pub source: StormError,
}

/// Simulate the lives `indices` (any subset, in any order) in parallel on rayon's current pool.
/// Each finished life is passed to `on_life` (from the thread that ran it: the place to record
/// it in a checkpoint and to move a progress bar); when `on_life` returns
/// [`ControlFlow::Break`], no further life starts (the lives under way finish and are
/// returned). The finished lives come back sorted by index. Each life depends only on the seed
/// and its index, so the result does not depend on the thread count, the order or a split of the
/// indices over several runs.
pub fn run_lives(
    st: &StormCase<'_>,
    life: &LifeParams,
    seed: u64,
    indices: &[usize],
    on_life: &(dyn Fn(usize, &StormOutcome) -> ControlFlow<()> + Sync),
) -> Result<Vec<(usize, StormOutcome)>, LifeFailed> {
    let stop = AtomicBool::new(false);
    let finished: Vec<Option<(usize, StormOutcome)>> = indices
        .par_iter()
        .map(|&i| {
            if stop.load(Ordering::SeqCst) {
                return Ok(None);
            }
            let o = simulate_life(st, life, seed, i).map_err(|source| LifeFailed { life: i, source })?;
            if on_life(i, &o).is_break() {
                stop.store(true, Ordering::SeqCst);
            }
            Ok(Some((i, o)))
        })
        .collect::<Result<_, _>>()?;
    let mut finished: Vec<(usize, StormOutcome)> = finished.into_iter().flatten().collect();
    finished.sort_by_key(|(i, _)| *i);
    Ok(finished)
}
