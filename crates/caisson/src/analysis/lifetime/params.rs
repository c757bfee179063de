//! The inputs of a life and of a design run: the storm climate, the estimation errors, what the
//! storms act on, the failure limits.

use crate::analysis::climate::{Climate, StormModel, MAX_STORM_DURATION_S, MAX_STORM_RATE_PER_YEAR};
use crate::analysis::limits::FAILURE_FRACTION_OF_WIDTH;
use crate::analysis::Structure;
use crate::check::{self, count, interval};
use crate::loads::model::WaveLoadModel;
use crate::loads::risetime::LoadRng;
use crate::waves::periods::WavePeriods;
use crate::ParamError;
use rand::Rng;
use rand_distr::StandardNormal;

/// Annual maxima of the deep-water significant height.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum StormDistribution {
    /// F(H) = 1 − exp[−((H − location)/scale)^shape], H ≥ location.
    Weibull { scale_m: f64, shape: f64, location_m: f64 },
    /// F(H) = exp[−exp(−(H − location)/scale)].
    Gumbel { location_m: f64, scale_m: f64 },
}

/// The largest 10 000-year deep-water H1/3 a storm distribution may give, m: five times the
/// largest significant wave height measured at sea (about 19 m, North Atlantic, 2013). A fit
/// whose tail passes it (a Weibull shape of 0.12 puts the 50-year storm near 10⁵ m, with periods
/// of a quarter of an hour and heights at the wall of a kilometre) is a slip, not a climate.
pub const MAX_STORM_HEIGHT_M: f64 = 100.0;

impl StormDistribution {
    /// A Weibull distribution of annual maxima: scale A in (0, 100] m, shape k from 0.1 to 20,
    /// location B from 0 to 100 m; refused naming the quantity.
    pub fn weibull(scale_m: f64, shape: f64, location_m: f64) -> Result<Self, ParamError> {
        StormDistribution::Weibull { scale_m, shape, location_m }.checked()
    }

    /// A Gumbel distribution of annual maxima: location B and scale A in (0, 100] m; refused
    /// naming the quantity.
    pub fn gumbel(location_m: f64, scale_m: f64) -> Result<Self, ParamError> {
        StormDistribution::Gumbel { location_m, scale_m }.checked()
    }

    /// The distribution if its parameters are in range ([`Self::weibull`], [`Self::gumbel`]) and
    /// its 10 000-year height F⁻¹(1 − 10⁻⁴) is at most [`MAX_STORM_HEIGHT_M`] (refused naming
    /// the shape of a Weibull distribution, the scale of a Gumbel one).
    pub fn checked(self) -> Result<Self, ParamError> {
        let tail = match self {
            StormDistribution::Weibull { scale_m, shape, location_m } => {
                interval("scale_m", scale_m, 0.0, 100.0, true)?;
                interval("shape", shape, 0.1, 20.0, false)?;
                interval("location_m", location_m, 0.0, 100.0, false)?;
                ("shape", shape)
            }
            StormDistribution::Gumbel { location_m, scale_m } => {
                interval("location_m", location_m, 0.0, 100.0, true)?;
                interval("scale_m", scale_m, 0.0, 100.0, true)?;
                ("scale_m", scale_m)
            }
        };
        let h = self.quantile_m(1.0 - 1e-4);
        if h.is_nan() || h > MAX_STORM_HEIGHT_M {
            return Err(check::rule(
                tail.0,
                tail.1,
                format!(
                    "gives a 10 000-year storm (F⁻¹(1 − 10⁻⁴)) of {} m, where at most {MAX_STORM_HEIGHT_M} m is allowed (the largest significant wave height measured at sea is about 19 m): check the distribution's parameters",
                    if h < 1e6 { format!("{h:.1}") } else { format!("{h:.2e}") }
                ),
            ));
        }
        Ok(self)
    }

    /// The height of non-exceedance probability `p` in (0, 1).
    pub fn quantile_m(&self, p: f64) -> f64 {
        match *self {
            StormDistribution::Weibull { scale_m, shape, location_m } => {
                location_m + scale_m * (-(1.0 - p).ln()).powf(1.0 / shape)
            }
            StormDistribution::Gumbel { location_m, scale_m } => location_m - scale_m * (-p.ln()).ln(),
        }
    }

    /// Peaks over threshold of this fitted distribution ([`StormModel::PeaksOverThreshold`]):
    /// a rate in (0, [`MAX_STORM_RATE_PER_YEAR`]] storms a year and a threshold from 0 to 100 m,
    /// refused naming `threshold_m` where the distribution leaves no room above the threshold
    /// (1 − F(threshold) < 10⁻⁹: its exceedances could not be drawn).
    pub fn peaks_over_threshold(&self, rate_per_year: f64, threshold_m: f64) -> Result<StormModel, ParamError> {
        interval("rate_per_year", rate_per_year, 0.0, MAX_STORM_RATE_PER_YEAR, true)?;
        interval("threshold_m", threshold_m, 0.0, 100.0, false)?;
        if 1.0 - self.cdf(threshold_m) < 1e-9 {
            return Err(check::rule(
                "threshold_m",
                threshold_m,
                "must be a height the storm distribution exceeds (1 − F(threshold) ≥ 1e-9): lower it, or check the distribution's parameters",
            ));
        }
        Ok(StormModel::PeaksOverThreshold { rate_per_year, threshold_m })
    }

    /// F(h), the probability of a height at most `h_m`.
    pub fn cdf(&self, h_m: f64) -> f64 {
        match *self {
            StormDistribution::Weibull { scale_m, shape, location_m } => {
                if h_m <= location_m {
                    0.0
                } else {
                    1.0 - (-((h_m - location_m) / scale_m).powf(shape)).exp()
                }
            }
            StormDistribution::Gumbel { location_m, scale_m } => (-(-(h_m - location_m) / scale_m).exp()).exp(),
        }
    }
}

/// An estimation error: the multiplier 1 + bias + cov·z, z ~ N(0,1) truncated at ±k (Kim &
/// Takayama 2003), or not truncated (`truncation_sigmas: None`, as in Shimosako & Takahashi 1999);
/// a multiplier below zero is taken as zero.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct ErrorModel {
    pub bias: f64,
    pub cov: f64,
    pub truncation_sigmas: Option<f64>,
}

impl ErrorModel {
    pub const NONE: ErrorModel = ErrorModel { bias: 0.0, cov: 0.0, truncation_sigmas: Some(2.0) };

    /// An error model of bias from −0.9 to 1 and COV from 0 to 1, truncated at ±k with k from
    /// 0.5 to 10 (or not truncated), whose multiplier stays positive: truncated, the lowest
    /// multiplier it can draw, 1 + bias − k·cov, is above 0; refused naming `bias`, `cov` or
    /// `truncation_sigmas`.
    pub fn new(bias: f64, cov: f64, truncation_sigmas: Option<f64>) -> Result<Self, ParamError> {
        ErrorModel { bias, cov, truncation_sigmas }.checked()
    }

    /// The model if its coefficients are in range ([`Self::new`]).
    pub fn checked(self) -> Result<Self, ParamError> {
        let ErrorModel { bias, cov, truncation_sigmas } = self;
        if let Some(k) = truncation_sigmas {
            interval("truncation_sigmas", k, 0.5, 10.0, false)?;
        }
        interval("bias", bias, -0.9, 1.0, false)?;
        interval("cov", cov, 0.0, 1.0, false)?;
        if let Some(k) = truncation_sigmas {
            if 1.0 + bias - k * cov <= 0.0 {
                return Err(check::rule(
                    "cov",
                    cov,
                    format!("with bias {bias} and truncation ±{k}σ the multiplier 1 + bias − k·cov must stay positive"),
                ));
            }
        }
        Ok(self)
    }

    pub(super) fn draw(&self, rng: &mut LoadRng) -> f64 {
        let z = loop {
            let z: f64 = rng.sample(StandardNormal);
            if self.truncation_sigmas.is_none_or(|k| z.abs() <= k) {
                break z;
            }
        };
        (1.0 + self.bias + self.cov * z).max(0.0)
    }
}

/// The estimation errors of docs/model.md §6.4 step 4, and when they are drawn.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Errors {
    pub deep_water_height: ErrorModel,
    pub transformation: ErrorModel,
    /// The error of every wave force component (and of the impulsive one, unless
    /// `impact_force` is given).
    pub wave_force: ErrorModel,
    pub friction: ErrorModel,
    /// The error of the impulsive component (impact force and impulsive uplift) when it has
    /// coefficients of its own (Kim & Takayama 2003: larger COVs for impulsive loads); `None`: the
    /// wave-force error (one draw for all components).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub impact_force: Option<ErrorModel>,
    /// Drawn once per storm (the default) or once per life.
    #[serde(skip_serializing_if = "ErrorScope::is_per_storm")]
    pub scope: ErrorScope,
}

/// When the estimation errors are drawn (docs/design.md, "Climate").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum ErrorScope {
    /// Afresh for every storm (Shimosako & Takahashi 1999; the default).
    #[default]
    Storm,
    /// Once for the life, shared by its storms: a site's estimate is wrong the same way in every
    /// storm (the errors of the site's wave statistics and of the design formulas, not storm to
    /// storm scatter).
    Life,
}

impl ErrorScope {
    fn is_per_storm(&self) -> bool {
        *self == ErrorScope::Storm
    }
}

/// One draw of the errors: the multipliers of H0, of the transformation, of the wave force, of
/// the friction and of the impulsive component.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct ErrorDraw {
    pub(super) h0: f64,
    pub(super) transformation: f64,
    pub(super) force: f64,
    pub(super) friction: f64,
    pub(super) impact: f64,
}

impl Errors {
    /// The multipliers, in the stream's order: H0, transformation, force, friction, then the
    /// impulsive component's if it has its own coefficients.
    pub(super) fn draw(&self, rng: &mut LoadRng) -> ErrorDraw {
        let (h0, transformation, force, friction) = (
            self.deep_water_height.draw(rng),
            self.transformation.draw(rng),
            self.wave_force.draw(rng),
            self.friction.draw(rng),
        );
        let impact = self.impact_force.map_or(force, |m| m.draw(rng));
        ErrorDraw { h0, transformation, force, friction, impact }
    }
}

impl Errors {
    /// The load-model errors of a storm of given H1/3 (a fragility's, docs/fragility.md): the
    /// multipliers of the wave force, the friction and the impulsive component, drawn in that
    /// order (the impulsive one only if it has coefficients of its own; else the force's).
    pub fn draw_load_errors(&self, rng: &mut LoadRng) -> [f64; 3] {
        let (force, friction) = (self.wave_force.draw(rng), self.friction.draw(rng));
        [force, friction, self.impact_force.map_or(force, |m| m.draw(rng))]
    }
}

impl Default for Errors {
    /// Takayama & Ikeda (1992) via Shimosako & Takahashi (1999), truncated at ±2σ, per storm.
    fn default() -> Self {
        Errors {
            deep_water_height: ErrorModel { bias: 0.0, cov: 0.10, truncation_sigmas: Some(2.0) },
            transformation: ErrorModel { bias: -0.13, cov: 0.09, truncation_sigmas: Some(2.0) },
            wave_force: ErrorModel { bias: -0.09, cov: 0.10, truncation_sigmas: Some(2.0) },
            friction: ErrorModel { bias: 0.0, cov: 0.10, truncation_sigmas: Some(2.0) },
            impact_force: None,
            scope: ErrorScope::Storm,
        }
    }
}

/// The life model (docs/model.md §6.4), every coefficient a parameter.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct LifeParams {
    pub life_years: usize,
    pub storms: StormDistribution,
    /// T1/3 = a H0^b: a (s·m^−b) and b.
    pub period_coefficient: f64,
    pub period_exponent: f64,
    /// Duration of the storm peak, s (N = duration / T1/3 waves); the mean of a distribution of
    /// durations ([`Climate::duration`]).
    pub storm_duration_s: f64,
    /// Tidal range R, m.
    pub tidal_range_m: f64,
    pub errors: Errors,
    /// The climate's choices beyond today's model ([`Climate`]); not in the fingerprint when they
    /// are the defaults, so checkpoints of earlier runs stay valid.
    #[serde(skip_serializing_if = "Climate::is_default")]
    pub climate: Climate,
}

/// The longest life, years (`[design] life_years`).
pub const MAX_LIFE_YEARS: usize = 1000;

impl LifeParams {
    /// The life model if every coefficient is in range: 1 to [`MAX_LIFE_YEARS`] years, the storm
    /// distribution ([`StormDistribution::checked`]), a period coefficient a in (0, 100] s·m^−b
    /// and exponent b from 0 to 2, a storm duration in (0, [`MAX_STORM_DURATION_S`]], a tidal range
    /// from 0 to 20 m, the errors ([`ErrorModel::checked`]) and the climate
    /// ([`StormDistribution::peaks_over_threshold`], [`Climate::checked`]); refused naming the
    /// quantity.
    pub fn checked(self) -> Result<Self, ParamError> {
        count("life_years", self.life_years, 1, MAX_LIFE_YEARS as u64)?;
        self.storms.checked()?;
        if let StormModel::PeaksOverThreshold { rate_per_year, threshold_m } = self.climate.storms {
            self.storms.peaks_over_threshold(rate_per_year, threshold_m)?;
        }
        let climate = self.climate.checked()?;
        interval("period_coefficient", self.period_coefficient, 0.0, 100.0, true)?;
        interval("period_exponent", self.period_exponent, 0.0, 2.0, false)?;
        interval("storm_duration_s", self.storm_duration_s, 0.0, MAX_STORM_DURATION_S, true)?;
        interval("tidal_range_m", self.tidal_range_m, 0.0, 20.0, false)?;
        let e = &self.errors;
        for m in [e.deep_water_height, e.transformation, e.wave_force, e.friction].iter().chain(&e.impact_force) {
            m.checked()?;
        }
        Ok(LifeParams { climate, ..self })
    }

    /// The highest water level above still water of the life's storms: the tidal range and the
    /// largest sea-level rise, m.
    pub fn highest_water_m(&self) -> f64 {
        self.tidal_range_m + self.climate.sea_level.max_rise_m(self.life_years)
    }

    /// The deep-water H0 of a storm from the uniform `u` (before its error): the annual maximum
    /// F⁻¹(u), or an exceedance of the threshold t, F⁻¹(F(t) + u (1 − F(t))) (peaks over
    /// threshold; [`crate::analysis::climate`]).
    pub fn storm_height_m(&self, u: f64) -> f64 {
        match self.climate.storms {
            StormModel::AnnualMaxima => self.storms.quantile_m(u),
            StormModel::PeaksOverThreshold { threshold_m, .. } => {
                let f = self.storms.cdf(threshold_m);
                self.storms.quantile_m((f + u * (1.0 - f)).min(1.0 - 1e-12)).max(threshold_m)
            }
        }
    }
}

/// What the storms act on: the structure at still water, the site's wave loads, the rigid-block
/// reference and the lifetime's fast paths. Those are the lifetime fields of the policy
/// [`crate::dynamics::Accel`] (`screen`, `screen_load_bound`, `draw_above_threshold`,
/// `stick_bound`, as [`crate::scenario::Scenario::storm_case`] resolves them: the screen where
/// both `[design] screen` and the policy have it, the others as the policy has them, acting only
/// with the screen), kept here
/// resolved so that a run with another solver (the work estimate's coarse pilot) screens the same.
#[derive(Debug, Clone, Copy)]
pub struct StormCase<'a> {
    pub structure: &'a Structure,
    /// The wave-load model at still water (its regime choice is used per wave).
    pub model: &'a WaveLoadModel,
    pub rigid_block_mu: f64,
    /// Skip the waves that cannot slide the caisson (module docs; `Accel::screen`).
    pub screen: bool,
    /// With the screen, leave the grid's rows and nodes that the bound of the loads over all
    /// heights up to theirs holds false without their loads (module docs, "The screen";
    /// `Accel::screen_load_bound`): `false` computes every node's loads (the same grid).
    pub screen_load_bound: bool,
    /// With the screen, answer the pulsating waves that the bound of the all-sticking response
    /// shows can neither slide nor lift the caisson without running them (module docs, "The
    /// screen"; [`crate::analysis::stick_bound`]; `Accel::stick_bound`): `false` runs them all
    /// (the tests' reference).
    pub stick_bound: bool,
    /// With the stick bound, run the answered waves whose rotation bound may exceed the largest
    /// rotation (module docs, "The stick bound"), so that `max_rotation_rad` is every wave's:
    /// `false` leaves it the largest of the waves run, for what reads only the counts (the work
    /// estimate's screen pilot, whose short lives would run them far more often than a life).
    pub settle_rotation: bool,
    /// How a screened storm draws its waves (module docs, "Drawing"; `Accel::draw_above_threshold`);
    /// without the screen every wave is drawn and simulated.
    pub draws: WaveDraws,
    /// The failure limits whose failing wave a life (or storm) records (module docs, "Failure");
    /// `None`: no failure is recorded. Every life runs to its end either way.
    pub failure: Option<FailureLimits>,
    /// The heel pressure that the screen lets every wave through that may reach it (module docs,
    /// "Heel pressure"), Pa: the allowable heel pressure of a design, or the failure heel pressure
    /// if lower; infinite: the screen looks at sliding and lift-off only (fragility).
    pub heel_screen_pa: f64,
}

/// When a life (or a storm) has failed: its distance from its place exceeded `sliding_m` or a
/// wave rotated the caisson beyond `rotation_rad` (docs/design.md, "Failure").
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct FailureLimits {
    /// `[design] failure_sliding_m` (default [`FAILURE_FRACTION_OF_WIDTH`] of the base width), m.
    pub sliding_m: f64,
    /// `[design] failure_rotation_rad` (default [`ROCKING_LIMIT_RAD`]), rad.
    pub rotation_rad: f64,
    /// `[design] failure_heel_pressure_kpa` (absent by default: no failure by heel pressure), Pa.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub heel_pressure_pa: Option<f64>,
}

/// How a screened storm draws its waves (module docs, "Drawing").
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum WaveDraws {
    /// Only the waves that can pass the screen: the largest first, down to the lowest height the
    /// screen lets through (the default).
    #[default]
    AboveThreshold,
    /// Every wave drawn and tested against the screen (the drawing before the one above the
    /// threshold): the tests' reference. It draws the same waves as a run with the screen off, so
    /// the two compare wave for wave; the default must agree with it in distribution.
    EveryWave,
}

/// log2 of the 32-bit words of the life's stream each storm's waves own (module docs, "Random
/// numbers"): storm y of a life draws its waves from word (y + 1) · 2^40.
pub const STORM_WAVE_WORDS_LOG2: u32 = 40;

/// One storm at the structure.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct StormInput {
    /// H1/3 at the structure, m.
    pub h13_m: f64,
    /// Largest individual height (breaking limit), m.
    pub hmax_m: f64,
    /// T1/3, s: every wave's period, or the scale of their distribution (`periods`).
    pub period_s: f64,
    /// How the waves' periods are drawn (module docs, "Wave periods").
    pub periods: WavePeriods,
    pub waves: usize,
    /// Water level above still water (the tide and the sea-level rise), m.
    pub tide_m: f64,
    /// The waves' angle to the breakwater's normal, rad (Goda's β before the 15° rule).
    pub angle_rad: f64,
    /// Multiplier on every wave force (but the impulsive component's).
    pub force_factor: f64,
    /// Multiplier on the impulsive component (impact force and uplift), = `force_factor` unless
    /// the impact has error coefficients of its own ([`Errors::impact_force`]).
    pub impact_factor: f64,
    /// Multiplier on the friction coefficients.
    pub friction_factor: f64,
}

/// A design run: the life model, how many lives, their seed, the reported thresholds and the
/// screen.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct DesignParams {
    pub life: LifeParams,
    pub lives: usize,
    pub seed: u64,
    /// Sorted sliding thresholds of the exceedance probabilities, m.
    pub thresholds_m: Vec<f64>,
    pub screen: bool,
    /// The failure limit on the caisson's distance from its place, m; `None`:
    /// [`FAILURE_FRACTION_OF_WIDTH`] of the base width ([`Self::failure_limit_m`]).
    pub failure_sliding_m: Option<f64>,
    /// The failure limit on the caisson's rotation, rad (default [`ROCKING_LIMIT_RAD`]).
    pub failure_rotation_rad: f64,
    /// The allowable heel pressure q_a, Pa (default
    /// [`DEFAULT_ALLOWABLE_HEEL_PRESSURE_PA`](super::DEFAULT_ALLOWABLE_HEEL_PRESSURE_PA)): the
    /// exceedance P(q_heel > q_a) is reported, and the screen runs every wave that may reach it
    /// (module docs, "Heel pressure").
    pub allowable_heel_pressure_pa: f64,
    /// The heel pressure beyond which a life fails, Pa; `None` (the default): no failure by
    /// heel pressure.
    pub failure_heel_pressure_pa: Option<f64>,
    /// Which lives are simulated ([`Sampling`]).
    pub sampling: Sampling,
    /// `lives = "auto"`: run lives in batches until the target precision is met, `lives` being
    /// then the most lives the run may take ([`AutoLives`]); `None`: exactly `lives` lives.
    pub auto: Option<AutoLives>,
}

/// Which of a design run's lives are simulated (`[design] sampling`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Sampling {
    /// Every life (plain Monte Carlo; the default).
    #[default]
    Plain,
    /// A share of each stratum of the lives' storm severity, the estimates weighted
    /// ([`super::sampling`]).
    Stratified,
}

/// Lives to a target precision (`[design] lives = "auto"`, and `[size]`'s per candidate;
/// docs/design.md, "Lives to a target precision").
///
/// The lives run in batches of [`AUTO_BATCH_LIVES`] in index order, and after each batch the
/// rule ([`AutoLives::judge`]) is applied to the statistics of lives 0..k (k the batch's end):
/// the run stops at the first k where it is met, or at the budget (the run's `lives`, `[design]
/// max_lives`) if it is never met. The rule reads only lives 0..k, each of which depends only on
/// the seed and its index, so the stopping point — and so every statistic — is the same on any
/// thread count, shard split or resume.
///
/// The rule, with t the target relative error:
///
/// - **E|S|** (the dynamic model's, each failed life at the sliding limit): its standard error
///   over its mean, SE/E|S| ≤ t; with every life at 0 (E|S| = 0 and SE = 0) the relative error is
///   0 (no life slid: nothing varies);
/// - **P(failure)** (k failed lives of n): the binomial standard error √(p(1 − p)/n) over p =
///   k/n, √((1 − p)/(k)) ≤ t — which needs about (1 − p)/t² failures, 400 at t = 0.05 — **or**
///   P(failure) shown negligible: the Wilson 95 % upper bound below
///   [`FAILURE_PROBABILITY_FLOOR`]. At k = 0 the relative error is undefined and only the bound
///   can meet the target (about 3.84/n < 10⁻³, 3 840 lives without a failure).
///
/// Both must be met.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct AutoLives {
    /// t, the target relative standard error of E|S| and of P(failure) (default
    /// [`DEFAULT_TARGET_RELATIVE_ERROR`]).
    pub target_relative_error: f64,
}

/// The default target relative error of `lives = "auto"`: 5 %, a 95 % interval of about ±10 %
/// of the value — the second significant digit of E|S| and of P(failure) known to about one unit,
/// what the design example's 5000 lives give today (E|S| 0.355 ± 0.018 m, P(failure) 0.068 with a
/// relative error of 5.2 %). Halving it costs four times the lives.
pub const DEFAULT_TARGET_RELATIVE_ERROR: f64 = 0.05;

/// The lives of a batch of `lives = "auto"`: the rule is applied every 500 lives. Small enough
/// that a run stops within 10 % of the lives it needs once past 5000, large enough that both
/// threads stay busy (a batch's end leaves a core idle for at most one life) and that the
/// statistics recomputed at each boundary (O(n log n)) stay a small part of the run.
pub const AUTO_BATCH_LIVES: usize = 500;

/// The default budget of `lives = "auto"` (`max_lives`): 100 000 lives, what a relative error of
/// 5 % on a lifetime P(failure) of 1 % needs ((1 − p)/(p t²) = 39 600 lives) with room to spare;
/// 160 s of CPU at the design example's 1.6 ms a life. A smaller P(failure) is met by the floor.
pub const DEFAULT_AUTO_MAX_LIVES: usize = 100_000;

/// The floor of P(failure) in the rule of `lives = "auto"` ([`AutoLives`]): a P(failure) whose
/// Wilson 95 % upper bound is below 10⁻³ is taken as negligible: a tenth of the smallest lifetime
/// probability of failure a design would read to one significant digit from the default budget
/// (1 %, above). Without a failure it takes 3 840 lives to show.
pub const FAILURE_PROBABILITY_FLOOR: f64 = 1e-3;

/// The largest target relative error: beyond 0.5 not even the first digit is known.
pub const MAX_TARGET_RELATIVE_ERROR: f64 = 0.5;

/// What the rule of [`AutoLives`] found of lives 0..n: the `precision` object of design.json and
/// of each candidate of size.json.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct AutoPrecision {
    /// The target t.
    pub target_relative_error: f64,
    /// The lives it took (the statistics' lives), and the most the run could take.
    pub lives: usize,
    pub max_lives: usize,
    /// The batch of the rule, lives ([`AUTO_BATCH_LIVES`]).
    pub batch_lives: usize,
    /// SE/E|S| of the dynamic model's capped E|S| (0 when no life slid).
    pub expected_sliding_relative_error: f64,
    /// SE/P of the dynamic model's P(failure); `None` (null) without a failed life.
    pub failure_relative_error: Option<f64>,
    /// The Wilson 95 % upper bound of P(failure), and the floor below which it meets the target.
    pub failure_probability_upper: f64,
    pub failure_probability_floor: f64,
    pub expected_sliding_met: bool,
    pub failure_met: bool,
    /// Both met: the run stopped at the target; `false`: the budget ran out first.
    pub met: bool,
}

impl AutoLives {
    /// The target if in range: t in (0, [`MAX_TARGET_RELATIVE_ERROR`]], refused naming
    /// `target_relative_error`.
    pub fn checked(self) -> Result<Self, ParamError> {
        interval("target_relative_error", self.target_relative_error, 0.0, MAX_TARGET_RELATIVE_ERROR, true)?;
        Ok(self)
    }

    /// The rule (type docs) on E|S| = `mean` with standard error `se`, and `failures` failed
    /// lives of `lives`; `max_lives` is reported beside.
    pub fn judge(&self, es: (f64, f64), failures: usize, lives: usize, max_lives: usize) -> AutoPrecision {
        let failure = crate::analysis::estimate::Estimate::proportion(failures as u64, lives as u64);
        self.judge_estimates(es, &failure, lives, max_lives)
    }

    /// The rule on estimates: E|S| = `mean` with standard error `se`, and P(failure) `failure`
    /// (its value, standard error and 95 % interval, whose upper end is held to the floor) of
    /// `lives` lives — the binomial proportion of a plain run ([`Self::judge`]), or a stratified
    /// run's weighted proportion with its two-phase standard error and its Wilson interval at
    /// the effective size ([`crate::analysis::stratified::TwoPhase::proportion`]).
    pub fn judge_estimates(
        &self,
        (mean, se): (f64, f64),
        failure: &crate::analysis::estimate::Estimate,
        lives: usize,
        max_lives: usize,
    ) -> AutoPrecision {
        let t = self.target_relative_error;
        let es = if se == 0.0 { 0.0 } else { se / mean };
        let p = failure.value;
        let failure_relative_error = (p > 0.0).then(|| failure.standard_error / p);
        let upper = if lives == 0 { 1.0 } else { failure.ci95[1] };
        let expected_sliding_met = lives > 0 && es <= t;
        let failure_met =
            lives > 0 && (failure_relative_error.is_some_and(|r| r <= t) || upper < FAILURE_PROBABILITY_FLOOR);
        AutoPrecision {
            target_relative_error: t,
            lives,
            max_lives,
            batch_lives: AUTO_BATCH_LIVES,
            expected_sliding_relative_error: es,
            failure_relative_error,
            failure_probability_upper: upper,
            failure_probability_floor: FAILURE_PROBABILITY_FLOOR,
            expected_sliding_met,
            failure_met,
            met: expected_sliding_met && failure_met,
        }
    }
}

/// The batch boundaries of `lives = "auto"` up to the budget `max_lives`: 500, 1000, …, and
/// `max_lives` itself if it is not a multiple of [`AUTO_BATCH_LIVES`].
pub fn auto_boundaries(max_lives: usize) -> impl Iterator<Item = usize> {
    (1..=max_lives.div_ceil(AUTO_BATCH_LIVES)).map(move |b| (b * AUTO_BATCH_LIVES).min(max_lives))
}

/// Most lives of a design run (`[design] lives`, the CLI's `--lives`, Python's `Design(lives=)`).
pub const MAX_LIVES: usize = 10_000_000;

/// Takahashi's performance grades (docs/model.md §6.4 step 8), m: always among the reported
/// thresholds.
pub const STANDARD_THRESHOLDS_M: [f64; 5] = [0.03, 0.1, 0.3, 1.0, 3.0];

/// The largest failure rotation limit (`[design]` and `[fragility] failure_rotation_rad`), rad:
/// 0.1 rad (5.7°) lifts the heel of a 20 m wide caisson by 2 m, far beyond the small rotations the
/// model describes.
pub const MAX_FAILURE_ROTATION_RAD: f64 = 0.1;

/// A failure rotation limit in (0, [`MAX_FAILURE_ROTATION_RAD`]] rad, refused naming
/// `failure_rotation_rad` (the design's and the fragility's).
pub fn failure_rotation_rad(v: f64) -> Result<f64, ParamError> {
    interval("failure_rotation_rad", v, 0.0, MAX_FAILURE_ROTATION_RAD, true)
}

impl DesignParams {
    /// The run if in range: the life model ([`LifeParams::checked`]), 1 to [`MAX_LIVES`] lives,
    /// thresholds above 0 and increasing, a failure sliding limit in (0, 1000] m and a failure
    /// rotation limit ([`failure_rotation_rad`]); refused naming the quantity.
    pub fn checked(self) -> Result<Self, ParamError> {
        let life = self.life.checked()?;
        count("lives", self.lives, 1, MAX_LIVES as u64)?;
        for (i, &t) in self.thresholds_m.iter().enumerate() {
            check::positive("thresholds_m", t)?;
            if i > 0 && t <= self.thresholds_m[i - 1] {
                return Err(check::rule("thresholds_m", t, "must be larger than the threshold before it"));
            }
        }
        if let Some(s) = self.failure_sliding_m {
            interval("failure_sliding_m", s, 0.0, 1000.0, true)?;
        }
        failure_rotation_rad(self.failure_rotation_rad)?;
        heel_pressure_limit("allowable_heel_pressure_pa", self.allowable_heel_pressure_pa)?;
        if let Some(q) = self.failure_heel_pressure_pa {
            heel_pressure_limit("failure_heel_pressure_pa", q)?;
        }
        let auto = self.auto.map(AutoLives::checked).transpose()?;
        Ok(DesignParams { life, auto, ..self })
    }

    /// The reported thresholds: [`STANDARD_THRESHOLDS_M`] and `extra_m`, sorted, each once;
    /// refused at the first of `extra_m` that is not above 0 (its index and the rule).
    pub fn thresholds_m(extra_m: &[f64]) -> Result<Vec<f64>, (usize, ParamError)> {
        let mut thresholds_m = STANDARD_THRESHOLDS_M.to_vec();
        for (i, &v) in extra_m.iter().enumerate() {
            thresholds_m.push(check::positive("thresholds_m", v).map_err(|e| (i, e))?);
        }
        thresholds_m.sort_by(f64::total_cmp);
        thresholds_m.dedup();
        Ok(thresholds_m)
    }

    /// The failure limit for a caisson of base width `width_m`, m.
    pub fn failure_limit_m(&self, width_m: f64) -> f64 {
        self.failure_sliding_m.unwrap_or(FAILURE_FRACTION_OF_WIDTH * width_m)
    }

    /// The failure limits for a caisson of base width `width_m`.
    pub fn failure_limits(&self, width_m: f64) -> FailureLimits {
        FailureLimits {
            sliding_m: self.failure_limit_m(width_m),
            rotation_rad: self.failure_rotation_rad,
            heel_pressure_pa: self.failure_heel_pressure_pa,
        }
    }

    /// The heel pressure the screen lets every wave through that may reach it
    /// ([`StormCase::heel_screen_pa`]): the allowable heel pressure, or the failure heel pressure
    /// if lower, Pa.
    pub fn heel_screen_pa(&self) -> f64 {
        self.failure_heel_pressure_pa
            .map_or(self.allowable_heel_pressure_pa, |q| q.min(self.allowable_heel_pressure_pa))
    }
}

/// A heel pressure of a design in [10 kPa, 10 MPa] (the range of `[size]
/// allowable_heel_pressure_kpa`), refused naming `quantity`.
fn heel_pressure_limit(quantity: &'static str, v: f64) -> Result<f64, ParamError> {
    interval(quantity, v, 1e4, 1e7, true)
}
