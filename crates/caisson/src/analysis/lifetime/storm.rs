//! One storm (module docs, steps 3-6, "Drawing", "Random numbers"): its site at the storm's water
//! level, its random stream, how it draws its waves and what the storms of a life reuse.

use super::outcome::StormOutcome;
use super::params::{StormCase, StormInput, WaveDraws};
use super::screen::{ScreenBound, ScreenModes, StormScreen};
use super::wave::{base_heel_pressure_pa, WaveRun};
use crate::analysis::rigid::RigidBlock;
use crate::analysis::stick_bound::StickBound;
use crate::dynamics::{Model, SolveError};
use crate::foundation::{Foundation, MIN_FRICTION};
use crate::loads::history::{TrainError, WaveTrain};
use crate::loads::model::{PeakComponents, WaveLoadModel};
use crate::loads::risetime::LoadRng;
use crate::structure::Caisson;
use crate::waves::dispersion::wavenumber;
use crate::waves::periods::WavePeriods;
use crate::waves::statistics::{rayleigh_exceedance, rayleigh_quantile_m, sample_rayleigh_m, DescendingRayleigh};
use crate::G_M_PER_S2;
use rand::Rng;
use rand_distr::StandardNormal;
use std::cell::OnceCell;
use std::f64::consts::PI;
use thiserror::Error;

/// What the storms of one life reuse: the one-wave train of the simulated waves, the waves
/// drawn above the screen's threshold, and the waves the linear bound answered whose rotation
/// may still be the largest (of the storm, or of the life with the life's storms they belong to:
/// module docs, "The screen").
#[derive(Debug, Default)]
pub(super) struct StormScratch {
    pub(super) train: WaveTrain,
    pub(super) waves: Vec<DrawnWave>,
    pub(super) still: Vec<StillWave>,
    /// The waves run for their heel pressure alone when the life's (or storm's) end shows they
    /// may still raise it ([`StillWave::rotation_rad`] their heel-pressure bound, Pa; module docs,
    /// "Heel pressure").
    pub(super) heel: Vec<StillWave>,
    pub(super) storms: Vec<StormInput>,
    /// [`ScreenModes::still_water`], taken at the life's first storm.
    pub(super) modes: Option<ScreenModes>,
}

impl StormScratch {
    /// [`ScreenModes::still_water`] of `st`, once.
    pub(super) fn modes(&mut self, st: &StormCase<'_>) -> ScreenModes {
        *self.modes.get_or_insert_with(|| ScreenModes::still_water(st))
    }
}

/// A wave the linear bound answered ([`crate::analysis::stick_bound`]): the bound on its rotation,
/// rad, and what runs it again (its storm's index among the life's storms, its height, rise-time
/// deviate and period), should the storm's or the life's largest rotation need it (module docs,
/// "The screen").
#[derive(Debug, Clone, Copy)]
pub(super) struct StillWave {
    pub(super) rotation_rad: f64,
    pub(super) storm: usize,
    pub(super) height_m: f64,
    pub(super) deviate: f64,
    pub(super) period_s: f64,
}

/// Whose largest rotation the still waves settle (module docs, "The screen"): a storm's, at its end
/// ([`simulate_storm`]: fragility reads every storm's), or only the life's
/// ([`simulate_life`](super::life::simulate_life)), the life's largest rotation before the storm
/// and the storm's index.
#[derive(Debug, Clone, Copy)]
pub(super) enum Settle {
    Storm,
    Life { floor_rad: f64, storm: usize },
}

/// Most still waves a life keeps unsettled (module docs, "The screen"): beyond, they are settled
/// at the end of the storm (which empties the list). Each is 40 bytes.
pub(super) const MAX_STILL_WAVES: usize = 4096;

/// A still wave whose rotation bound times this factor exceeds the storm's largest rotation so
/// far is run after all (module docs, "The screen"): a margin for a bound below the rotation the
/// engine reports, which has not been seen (docs/history.md, "The stick bound").
pub(super) const ROTATION_RESERVE: f64 = 1.01;

/// A wave drawn above the screen's threshold: its place in the storm (a uniform on [0, 1): the
/// drawn waves run in this order), its height (clamped), its rise-time deviate and its period.
#[derive(Debug, Clone, Copy)]
pub(super) struct DrawnWave {
    pub(super) place: f64,
    pub(super) height_m: f64,
    pub(super) deviate: f64,
    pub(super) period_s: f64,
}

/// Run one storm (module docs). `rng` supplies the per-wave draws.
pub fn simulate_storm(st: &StormCase<'_>, s: &StormInput, rng: &mut LoadRng) -> Result<StormOutcome, StormError> {
    storm_from(st, s, &mut StormRng::Given(rng), StormStart::ALONE, None, &mut StormScratch::default())
}

/// Where a storm starts in its life: the caisson's distance from its place and the rigid
/// block's sliding so far, m, whether the life has failed already (its failing wave is recorded
/// once), and whose largest rotation the storm's still waves settle.
#[derive(Debug, Clone, Copy)]
pub(super) struct StormStart {
    pub(super) start_m: f64,
    pub(super) rigid_m: f64,
    /// The largest heel pressure of the life so far, kPa.
    pub(super) heel_floor_kpa: f64,
    pub(super) failed: bool,
    /// The dynamic model's run-on has stopped ([`StormOutcome::run_on_stopped`]).
    pub(super) stopped: bool,
    pub(super) settle: Settle,
}

impl StormStart {
    /// A storm alone (fragility), from the caisson's place.
    pub(super) const ALONE: StormStart = StormStart {
        start_m: 0.0,
        rigid_m: 0.0,
        heel_floor_kpa: 0.0,
        failed: false,
        stopped: false,
        settle: Settle::Storm,
    };
}

/// The random stream a storm draws its waves from (module docs, "Random numbers").
pub(super) enum StormRng<'r> {
    /// The caller's, drawn from where it stands.
    Given(&'r mut LoadRng),
    /// The life's stream `life` at word `word` (the storm's own part), positioned into `rng`
    /// when the storm first draws: most storms of a life draw no wave (none can pass their
    /// screen), and positioning costs a ChaCha block. The same numbers as positioning it at once:
    /// the words of a stream depend on its key, stream number and position only, not on where
    /// `life` is.
    Storm { life: &'r LoadRng, word: u128, rng: &'r mut Option<LoadRng> },
}

impl StormRng<'_> {
    pub(super) fn get(&mut self) -> &mut LoadRng {
        match self {
            StormRng::Given(rng) => rng,
            StormRng::Storm { life, word, rng } => rng.get_or_insert_with(|| {
                let mut r = (*life).clone();
                r.set_word_pos(*word);
                r
            }),
        }
    }
}

/// A storm that cannot be simulated.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum StormError {
    #[error(transparent)]
    Solve(#[from] SolveError),
    /// A wave whose loads are not a valid train (non-finite forces: an input far outside the
    /// model's range that validation did not catch).
    #[error("a wave of height {height_m} m and period {period_s} s has no valid load history: {source}")]
    Wave { height_m: f64, period_s: f64, source: TrainError },
    /// An outcome that is not a finite number: no valid scenario gives one (the inputs and each
    /// storm's draws are bounded where they enter), and no file is written with it.
    #[error("its {column} is {value}, which no valid scenario gives: please report it with the scenario")]
    NonFinite { column: &'static str, value: f64 },
}
/// The site and the caisson at a storm's water level (module docs, step 3), with its friction
/// error: both models and what the screen's bound needs of them.
pub(super) struct StormSite {
    pub(super) model: WaveLoadModel,
    pub(super) block: RigidBlock,
    /// The caisson and its foundation at the storm's water level and friction, and the dynamic
    /// model of them, built when a wave first needs it (most storms run no wave through it).
    pub(super) caisson: Caisson,
    pub(super) foundation: Foundation,
    pub(super) dyn_model: OnceCell<Model>,
    pub(super) modes: ScreenModes,
    pub(super) weight_n: f64,
    pub(super) mu: f64,
    pub(super) width_m: f64,
    /// l, m, and [`StormCase::heel_screen_pa`].
    pub(super) length_m: f64,
    pub(super) heel_screen_pa: f64,
    /// The bound of the all-sticking response, built when a wave first needs it.
    pub(super) stick: OnceCell<Option<StickBound>>,
}

impl StormSite {
    /// The site of storm `s`; `modes`: [`ScreenModes::still_water`] of `st`.
    pub(super) fn new(st: &StormCase<'_>, s: &StormInput, modes: ScreenModes) -> Self {
        let mut model = *st.model;
        model.site.depth_at_toe_m = toe_depth_m(st, s.tide_m);
        model.site.depth_at_wall_m += s.tide_m;
        model.site.base_depth_m += s.tide_m;
        model.site.crest_freeboard_m = (model.site.crest_freeboard_m - s.tide_m).max(0.0);
        model.options.angle_rad = s.angle_rad;
        let mut caisson = st.structure.caisson;
        caisson.base_depth_m += s.tide_m;
        caisson.weight_in_water_n -= model.site.rho_w * G_M_PER_S2 * caisson.width_m * caisson.length_m * s.tide_m;
        // The friction error can draw a multiplier of 0 (untruncated errors): each coefficient is
        // at least the least the model takes, and the caisson then slides beyond the failure limit.
        let friction = |mu: f64| (mu * s.friction_factor).max(MIN_FRICTION);
        let mut foundation = st.structure.foundation.clone();
        foundation.mu_static = friction(foundation.mu_static);
        foundation.mu_dynamic = friction(foundation.mu_dynamic);
        let block = RigidBlock::new(&caisson, model.site.rho_w, friction(st.rigid_block_mu));
        StormSite {
            weight_n: caisson.weight_in_water_n,
            mu: foundation.mu_static.min(block.mu_static),
            width_m: caisson.width_m,
            length_m: caisson.length_m,
            heel_screen_pa: st.heel_screen_pa,
            stick: OnceCell::new(),
            model,
            block,
            caisson,
            foundation,
            dyn_model: OnceCell::new(),
            modes,
        }
    }

    /// The heel pressure of the caisson at rest at the storm's water level, Pa: W'/(B l), uniform
    /// (the weight acts at the base centre).
    fn rest_heel_pressure_pa(&self) -> f64 {
        base_heel_pressure_pa(self.weight_n, 0.0, self.width_m, self.length_m)
    }

    /// The dynamic model at the storm's water level and friction.
    pub(super) fn dyn_model(&self) -> &Model {
        self.dyn_model.get_or_init(|| Model::new(&self.caisson, &self.foundation))
    }

    /// The screen's bound for a wave of period `period_s`: Ψ = 1 + T/(π t_q), t_q = T_w/4.
    pub(super) fn bound(&self, period_s: f64) -> ScreenBound {
        let ramp = |t0: f64| 1.0 + t0 / (PI * 0.25 * period_s);
        ScreenBound {
            psi_q: ramp(self.modes.t0_s),
            psi_m: ramp(self.modes.t_moment_s),
            weight_n: self.weight_n,
            mu: self.mu,
            width_m: self.width_m,
            lift_factor: self.modes.lift_factor,
            length_m: self.length_m,
            heel_screen_pa: self.heel_screen_pa,
        }
    }
}

impl StormInput {
    /// Peak components times the storm's force errors.
    pub(super) fn scaled(&self, p: &PeakComponents) -> PeakComponents {
        PeakComponents { quasi: p.quasi.scaled(self.force_factor), impact: p.impact.scaled(self.impact_factor) }
    }

    /// The period of a wave of height `height_m` (module docs, "Wave periods"): T1/3 (nothing
    /// drawn), or from one uniform of `rng`.
    fn wave_period_s(&self, height_m: f64, rng: &mut LoadRng) -> f64 {
        match self.periods {
            WavePeriods::Significant => self.period_s,
            p => p.period_s(height_m, self.h13_m, self.period_s, rng.gen()),
        }
    }
}
/// The depth at the toe at the water level `tide_m`, m.
pub(super) fn toe_depth_m(st: &StormCase<'_>, tide_m: f64) -> f64 {
    st.model.site.depth_at_toe_m + tide_m
}

/// [`simulate_storm`] for a caisson that starts the storm where `from` says (for the life's largest
/// excursion and its failure), its still waves settled as `from.settle` says (with [`Settle::Life`]
/// they are left in `scratch.still` for [`settle_life`](super::life::settle_life)). `toe_k`: the
/// wave number of T1/3 at [`toe_depth_m`], if the caller has solved for it (the life, for the
/// storm's shoaling).
pub(super) fn storm_from(
    st: &StormCase<'_>,
    s: &StormInput,
    rng: &mut StormRng<'_>,
    from: StormStart,
    toe_k: Option<f64>,
    scratch: &mut StormScratch,
) -> Result<StormOutcome, StormError> {
    let StormStart { start_m, rigid_m, heel_floor_kpa, failed, stopped, settle } = from;
    let site = StormSite::new(st, s, scratch.modes(st));
    // The loads at this storm's T1/3: the dispersion solves and breaker heights once.
    let k_toe = toe_k.unwrap_or_else(|| wavenumber(s.period_s, site.model.site.depth_at_toe_m));
    let loads_t13 = site.model.at_period_with_toe_wavenumber(s.period_s, k_toe);
    let bound_t13 = site.bound(s.period_s);
    let screen = StormScreen::new(st, s, &site, (&loads_t13, bound_t13));
    let mut out = StormOutcome {
        waves: s.waves as u64,
        max_excursion_m: start_m.abs(),
        max_heel_pressure_kpa: site.rest_heel_pressure_pa() / 1e3,
        ..StormOutcome::default()
    };
    let StormScratch { train, waves, still, heel, .. } = scratch;
    if matches!(settle, Settle::Storm) {
        still.clear();
        heel.clear();
    }
    let mut run = WaveRun {
        st,
        s,
        site: &site,
        loads_t13: &loads_t13,
        bound_t13,
        start_m,
        failed,
        stopped,
        rigid_start_m: rigid_m,
        rigid_failed: st.failure.is_some_and(|f| rigid_m.abs() > f.sliding_m),
        heel_floor_kpa,
        sim: None,
        train,
        stick_t13: OnceCell::new(),
        still,
        heel,
        settle,
    };
    if st.screen && st.draws == WaveDraws::AboveThreshold {
        draw_above_threshold(s, &screen, rng, waves, &mut run, &mut out)?;
    } else {
        // Every wave (the screen tested wave by wave, or off).
        let (low_m, hmax) = height_limits(s);
        let rng = rng.get();
        for _ in 0..s.waves {
            let h = sample_rayleigh_m(s.h13_m, rng).clamp(low_m, hmax);
            let z: f64 = rng.sample(StandardNormal);
            let period_s = s.wave_period_s(h, rng);
            if st.screen && !screen.may_slide_at(h, period_s) {
                out.screened_waves += 1;
                continue;
            }
            run.run(h, z, period_s, &mut out)?;
        }
    }
    run.settle(false, &mut out)?;
    run.settle(true, &mut out)?;
    out.max_storm_sliding_m = out.sliding_m;
    out.finite()
}

/// The smallest and largest height of a storm's waves, m: a thousandth of H1/3, and H_max.
fn height_limits(s: &StormInput) -> (f64, f64) {
    (1e-3 * s.h13_m.max(1e-6), s.hmax_m.max(1e-6))
}

/// The waves at or above the lowest cell that may slide, largest first (module docs,
/// "Drawing"), each run in the order of its place in the storm if its cell may slide.
pub(super) fn draw_above_threshold(
    s: &StormInput,
    screen: &StormScreen,
    rng: &mut StormRng<'_>,
    waves: &mut Vec<DrawnWave>,
    run: &mut WaveRun<'_>,
    out: &mut StormOutcome,
) -> Result<(), StormError> {
    let Some(lowest) = screen.lowest_cell() else {
        out.screened_waves = out.waves;
        return Ok(());
    };
    let (low_m, hmax) = height_limits(s);
    // A shade below the cell's lower edge, so that rounding in the cell of a height cannot put a
    // wave below the threshold into the cell; with the clamp at low_m above it, every wave.
    let threshold_m = lowest as f64 * screen.dh * (1.0 - 1e-9);
    let all = threshold_m <= low_m;
    let q = rayleigh_exceedance(threshold_m, s.h13_m);
    let rng = rng.get();
    let mut sample = DescendingRayleigh::new(out.waves);
    waves.clear();
    while let Some(e) = sample.next_exceedance(rng) {
        if !all && e >= q {
            break;
        }
        // E = 0 (a uniform of exactly 0): an unbounded height, limited to H_max.
        let h = if e > 0.0 { rayleigh_quantile_m(e, s.h13_m) } else { hmax };
        let z: f64 = rng.sample(StandardNormal);
        let place: f64 = rng.gen();
        let height_m = h.clamp(low_m, hmax);
        let period_s = s.wave_period_s(height_m, rng);
        waves.push(DrawnWave { place, height_m, deviate: z, period_s });
    }
    // The drawn waves in the order they arrive in the storm.
    waves.sort_unstable_by(|a, b| a.place.total_cmp(&b.place));
    out.screened_waves = out.waves - waves.len() as u64;
    for w in waves.iter() {
        if screen.may_slide_at(w.height_m, w.period_s) {
            run.run(w.height_m, w.deviate, w.period_s, out)?;
        } else {
            out.screened_waves += 1;
        }
    }
    Ok(())
}
