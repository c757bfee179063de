//! Performance-based design: the sliding of a caisson over its service life by Monte Carlo, with
//! the dynamic model for every wave that can slide it (Shimosako & Takahashi 1999; Goda & Takagi
//! 2000; docs/model.md §6.4), and the storms of a fragility analysis (docs/model.md §7).
//!
//! **One life** (`life_years` years of storms, one per year by default, docs/model.md §6.4 steps
//! 1-7; the other climates of [`super::climate`] change the steps as its docs say):
//!
//! 1. annual maximum deep-water significant height H0 from an extreme-value distribution,
//!    by inversion of a uniform U: Weibull F(H) = 1 − exp[−((H − B)/A)^k] (H ≥ B), or Gumbel
//!    F(H) = exp[−exp(−(H − B)/A)]; times the deep-water estimation error (peaks over threshold:
//!    a Poisson number of storms a year, each H0 an exceedance of the threshold);
//! 2. period T1/3 = a H0^b (Goda & Takagi: a = 3.3, b = 0.63) and N = duration / T1/3 waves;
//! 3. tide at the peak ζ = (R/2)(1 + cos φ), φ uniform: every depth (toe, wall, base) grows by ζ,
//!    the crest freeboard shrinks by ζ, and the weight in water falls by ρ_w g B l ζ (the caisson
//!    is more submerged); the foundation stiffness and the dynamic model's added mass stay at
//!    their still-water values (a simplification), while the rigid block's added mass, 1.0855
//!    ρ_w h'² l ([`super::rigid`]), is that of the storm's base depth h' + ζ;
//! 4. H1/3 and H_max at the structure by Goda's surf-zone formulas at the toe depth
//!    ([`crate::waves::surf_zone`]), times the transformation error;
//! 5. N Rayleigh heights of that H1/3, each limited to H_max (Goda's random-wave breaking), each
//!    with a rise time from the seed's log-normal model, each at T1/3 or at a period of its own
//!    given its height ("Wave periods" below);
//! 6. per wave: the loads of [`crate::loads::model::WaveLoadModel`] (regime by the breaking
//!    criterion; the impulsive peak of a breaking wave by `[waves] breaking_load`) times the
//!    wave-force error; friction coefficients times the friction error;
//!    the wave is run through the dynamic model from rest (static equilibrium) and its permanent
//!    sliding added; the rigid block (Shimosako model, [`super::rigid::RigidBlock`]) beside it.
//!
//! Estimation errors are multipliers 1 + bias + COV·z, z standard normal truncated at ±k
//! (Kim & Takayama 2003, doubly truncated; docs/model.md §6.4 step 4), drawn once per storm
//! ([`Errors`]: or once per life, untruncated as in Shimosako & Takahashi 1999, and the impulsive
//! component with coefficients of its own).
//!
//! **The screen** skips waves that provably cannot slide the caisson. A wave can slide it only if
//! its effective load exceeds the friction resistance, P_eff > μ_s (W' − U_eff), with P_eff =
//! max(Ψ_i F_x,max, Ψ_q α_qs F_qs+) and U_eff likewise, Ψ the dynamic amplification: Ψ_i = 2 on
//! impulsive components (the largest amplification of a single rising-and-falling pulse on a linear
//! oscillator from rest, reached by a step; Chopra §4.7-4.11) and Ψ_q = 1 + T0/(π t_q) on the
//! pulsating component, the bound of a load that rises over t_q = T/4 (Chopra §4.8, ramp load) —
//! **or** if the seaward spring can lift off, (6 M_eff/B) f ≥ W' − U_eff: a rocking caisson
//! ratchets shoreward by millimetres as its lifted springs re-contact, well below the sliding
//! resistance (without this condition a full run differed from the screened one by 1 %,
//! `tests/equiv_lifetime.rs`). M_eff is the moment about the base centre amplified like the forces, its
//! pulsating part with the longer of T0 and the rocking period T_θ = 2π (m_θ/K_θ)^½ (K_θ = Σ k_y
//! x_i²) in Ψ. f is the lift-off factor of the springs ([`Model::lift_off_factor`]): n equal
//! springs at x_i carry N_i = V/n + M x_i/Σx_j² statically, so the outermost one lifts at (6 M/B) ·
//! n/(n + 1) = V (f = 10/11 for the 10 springs of the seed; f = 1 is the continuous linear base
//! pressure, 6 M/B = V, which simulated 22 % more waves of the design example, none of which lifted
//! or slid). The test is made per storm on a grid of 64 heights from 0 to H_max plus the breaker
//! height at the wall; a wave whose grid cell or a neighbouring cell can slide has its own loads
//! computed, and is simulated if they pass the test (a fifth of the waves near the threshold do
//! not: they are screened too). The grid is skipped (every node false) in a storm where upper
//! bounds of the loads over all heights up to H_max pass neither test
//! ([`crate::loads::model::PeriodLoads::peak_bound`]: Goda's loads grow with the height, the
//! impulsive peak of each breaking-wave load is bounded too, Eq. 30's impact by its value at the
//! reduction 1, Goda's force with Takahashi's α* term by term, and there is none below the breaker
//! height at the wall); in the other storms the nodes up to the highest node height where those bounds up to it
//! pass neither test (found by bisection) are false without their loads, the same grid for a
//! seventh of the loads (design example). The friction used is the smaller of μ_s and the rigid block's μ, so a screened wave
//! slides neither model. The share of waves screened is reported; `screen = false`
//! runs every wave (on the same waves, [`WaveDraws::EveryWave`], the screened run gives the same
//! totals to 1 µm per life, `tests/equiv_lifetime.rs`).
//!
//! **The stick bound** (issue 19). The static test lets through many waves that
//! then neither slide nor lift (its amplifications are bounds for any load shape; on the design
//! example 156 010 of its 217 856 simulated waves moved no spring). A pulsating wave that passes
//! it is then tested on the all-sticking response itself ([`super::stick_bound`]: the exact
//! steady state of its crest and trough plus the modes' envelopes of the free vibration, at every
//! instant of the wave): if that leaves the outer springs 5 % of their normal force at rest and
//! the friction demand within 95 % of μ_s, no spring slips or lifts, the wave's sliding is
//! exactly 0 and it is not run ([`StormCase::stick_bound`]). Impulsive waves are left to the
//! engine.
//!
//! Only such a still wave's rotation θ_w is not known; its bound b_w is 0.2-4.2 % over the
//! engine's rotation on the design example, and `ROTATION_RESERVE` r = 1.01 is a margin for a
//! bound below it (θ_w ≤ r b_w); a wave is answered only if r b_w is below the rotation limit.
//! The largest rotation may be a still wave's, so the waves whose r b_w exceeds the largest
//! rotation known are kept on a list and **settled**: run after all, largest bound first, until
//! the next one's r b_w is at most the largest rotation so far. When depends on who reads it:
//! - a storm alone ([`simulate_storm`]: fragility reads every storm's largest rotation) settles at
//!   the storm's end;
//! - a life ([`simulate_life`]: the design and sizing runs and the climates read only the life's
//!   largest rotation: `lives.csv`, the JSON reports, the plots) settles once, at the life's end,
//!   the still waves of all its storms (each kept with its storm's index; the storm's site is
//!   rebuilt to run it). After each storm the list keeps only the waves whose r b_w exceeds the
//!   life's largest rotation so far; should it hold more than `MAX_STILL_WAVES` (4096), it is
//!   settled then (which empties it). The design example's lives run 617 still waves again
//!   (17 233 when each storm settled).
//!
//! Why the settled largest rotation M is what running every wave gives, M*, to the bit: M is the
//! largest rotation of the waves run, so M ≤ M*. A still wave not run was dropped or left when r
//! b_w was at most the largest rotation known then, which is at most M (it only grows): θ_w ≤ r b_w
//! ≤ M. So no wave's rotation exceeds M, M = M*, and a maximum of the same numbers does not depend
//! on their order. **Failure** (below) is not moved either: a still wave's θ_w ≤ r b_w is below the
//! rotation limit (and [`ROCKING_LIMIT_RAD`]), and it neither slides nor lifts, so it cannot fail a
//! life, count as rocking or large-rotation, or move the sliding and the excursions; whether and at
//! which wave a life fails is decided by the waves run, as when every wave runs, and settling at the
//! life's end moves only `max_rotation_rad` (to M*) and the counts (a wave run moves from the
//! screened to the simulated count). Every output is then the same to the last bit as without the
//! bound but the counts of simulated and screened waves (`tests/equiv_lifetime.rs`).
//!
//! **Wave periods** ([`StormInput::periods`], [`crate::waves::periods`]). By default every wave
//! has the storm's T1/3. With Longuet-Higgins' periods each wave's period τ is drawn given its
//! height (in 0.5-2.5 τ̄, τ̄ = 0.89 T1/3), and its loads, rise time, screen bound (Ψ at τ) and
//! run (for τ) are those of τ. The loads are not monotone in the period, so the screen's grid is
//! then over heights and periods: the 65 height nodes (and the breaker height) at each of 9
//! period nodes uniform in u = 1 − τ̄/τ, each period node with its own Ψ and its own load-bound
//! test of the row; a cell may slide if a node within one cell of it, in height or in period,
//! may. The drawing's threshold is the lowest height that may slide at any period; each drawn
//! wave draws its period, then is tested against its cell and on its own loads at its period
//! (`tests/verify_climate.rs` holds the screened and unscreened lives within 1 µm per life).
//!
//! **Drawing** ([`WaveDraws`]). A screened wave contributes nothing, so a storm draws only the
//! waves that can pass the screen ([`WaveDraws::AboveThreshold`], the default). With h_t the
//! lower edge of the lowest grid cell that may slide and q = P(H > h_t) = exp[−2 (h_t/H1/3)²]
//! (the Rayleigh exceedance of [`crate::waves::statistics`]), the number of the storm's N waves
//! above h_t is K ~ Binomial(N, q), and those K heights are independent Rayleigh heights truncated
//! below at h_t, H = √(h_t² − ½ H1/3² ln U) by the inverse CDF. They are drawn as the descending
//! order statistics of the N heights ([`DescendingRayleigh`]): the largest first, each from one
//! uniform, until the first one below h_t — which gives K and the truncated heights together, and
//! the same k-th largest wave whatever h_t is. Each drawn wave takes a rise-time deviate and a
//! uniform place in the storm; the waves run in the order of their places (the order of an
//! i.i.d. sequence), each limited to H_max and tested as before, against its cell (the flags
//! need not be monotone in the height) and then by its own loads. The screened count stays
//! N − simulated. Every per-life output has the distribution it had when all N waves were drawn
//! and tested ([`WaveDraws::EveryWave`]); the numbers differ within sampling noise (`tests/equiv_lifetime.rs`
//! holds the design example's statistics of both drawings within a few standard errors).
//!
//! **Failure** ([`FailureLimits`], docs/design.md "Failure"). A life fails when the caisson's
//! distance from its place exceeds the sliding limit (`[design] failure_sliding_m`, default B/4),
//! a wave rotates it beyond the rotation limit (`[design] failure_rotation_rad`, default 0.01 rad,
//! beyond which the model's small-rotation kinematics and its foundation under the heel do not
//! hold) or, if given, presses its heel beyond `[design] failure_heel_pressure_kpa`. Every life
//! runs to its end: with [`StormCase::failure`] given (a design run) the life records the wave that
//! failed it, once — its year ([`StormOutcome::failure_year`]), its modes (a wave may fail a life
//! by several) and whether it was impulsive — and the dynamic model keeps integrating, as the
//! rigid block does (its failing wave, beyond the sliding limit, recorded likewise). The capped
//! statistics ([`capped_statistics`]) read only whether a life failed and a surviving life's |S|,
//! so they are those of lives that end at failure; the means of the lives as simulated
//! (`expected_sliding_uncapped_m`) are those of whole lives, the expected sliding distance of
//! Shimosako & Takahashi (1999) and Goda & Takagi (2000). What the model computes after a failure
//! is outside its validity: only that statistic reads it. Should a wave after the failure not
//! converge (bounded sub-stepping, then the solver's error), the dynamic model runs no further
//! wave of that life ([`StormOutcome::run_on_stopped`]; the rigid block runs on). The engine does
//! not follow a caisson that overturns or slides away: the wave that fails a life, if its run does
//! not converge once it has rotated the caisson beyond [`ROCKING_LIMIT_RAD`] or moved it beyond the
//! sliding limit, ends at its last converged step, with the slip and the largest rotation the
//! engine had reached (a slender caisson rocking over, a storm far beyond the site's climate); the
//! life then fails by the usual tests, and the wave counts (and is warned about) as a large
//! rotation. Any other failure to converge before the failure is an error of the run.
//!
//! **Impulsive waves** ([`StormOutcome::impulsive_waves`]). The waves whose load event has an
//! impulse ([`WaveEvent::impulse`]: under the scenario's breaking-wave load, a breaking wave with
//! an impact) and that may slide the caisson or lift its base: they pass the screen's friction or
//! lift-off test (the screened ones slide neither model, so the count is the same with the screen
//! off, where the test is made all the same). Each runs through both models; their sliding
//! ([`StormOutcome::impulsive_sliding_m`], the rigid block's beside it) gives the share of E|S| as
//! simulated they make, Σ sign(S) S_imp / Σ |S| ([`ImpulsiveShare`]), and their failing waves the
//! share of the failures.
//!
//! **Heel pressure** ([`StormOutcome::max_heel_pressure_kpa`], [`base_heel_pressure_pa`]). At every
//! step of a wave run through the dynamic model, the heel (shoreward edge) value of the linear
//! base pressure without tension that carries the springs' normal forces: with V = Σ N_i (per
//! metre, / l) and the resultant t_e = B/2 − Σ x_i N_i / Σ N_i from the heel, Goda's (2000) p_e =
//! 2V/(3 t_e) for t_e ≤ B/3 (part of the base unloaded) and (2V/B)(2 − 3 t_e/B) above
//! ([`crate::loads::safety::heel_pressure_pa`]): under a static load it is Goda's heel pressure of
//! the static check (`tests/verify_heel_pressure.rs`). The spring dashpots are left out (the
//! soil's elastic reaction). A life's value is the largest over its waves run and the caisson at
//! rest at still water (W'/(B l)). The rigid block has no foundation pressure: it has none.
//!
//! The screen would miss a wave that cannot slide or lift the caisson yet presses its heel: its
//! bound of the heel pressure is p_e with the screen's amplified moment M_eff and the springs'
//! normal force at either end of W' − U_eff to W' + (Ψ − 1) U (for a fixed moment p_e is largest at
//! an end of an interval of normal forces), the amplifications' argument being the screen's. The
//! screen lets through every wave whose bound reaches [`StormCase::heel_screen_pa`] (the allowable
//! heel pressure, or the failure heel pressure if lower). A wave let through for that alone runs
//! for its heel pressure only (its sliding, rotation and lift are not read: every other output is
//! that of the screen without it, `tests/equiv_lifetime.rs`), and only if its bound exceeds the
//! largest heel pressure known: at the life's end (with the still waves, [`settle_life`]; a storm
//! alone at its end), largest bound first, until the next bound is at most the life's largest,
//! unless it may fail the life by heel pressure (then in its place). The same holds for a still
//! wave whose bound reaches it. So a life's largest heel pressure is exact wherever it is at or
//! above the screen's heel pressure, and P(q_heel > q_a) with it; below, it is the largest of the
//! waves run (a lower bound). On the design example the heel pressure costs 16 % more
//! instructions (the lives run to their end another 25 %).
//!
//! **Random numbers**: one ChaCha8 stream per life (seed, stream = life index); per storm in
//! order: U for H0, four truncated normals for the errors, U for the tide phase (and, only for
//! the climates that need them, the draws [`super::climate`] lists). The waves of
//! storm y (counting from 0 over the life) come from the same stream at word (y + 1) · 2^40
//! ([`STORM_WAVE_WORDS_LOG2`]; about 6 words per wave, 8 with periods of their own, so a storm of
//! up to 10¹¹ waves stays in its part): per drawn wave, U for its exceedance probability, one
//! standard normal for the rise time, U for its place ([`WaveDraws::EveryWave`] and the screen
//! off: per wave, U for the height and one standard normal for the rise time); then, with periods
//! of their own, U for its period. So how many waves a storm draws (which
//! depends on the caisson) never moves the numbers of the next storm: a life sees the same
//! storms and the same largest waves on every caisson (common random numbers of `caisson size`,
//! docs/size.md), and the same storms with either drawing.
//! Lives are independent, so results do not depend on the thread count, and a life can be
//! recomputed alone (checkpoint/resume).

use super::climate::{Climate, StormModel, MAX_STORM_DURATION_S, MAX_STORM_RATE_PER_YEAR};
use super::limits::{FAILURE_FRACTION_OF_WIDTH, ROCKING_LIMIT_RAD, SEAWARD_REPORT_M};
use super::rigid::RigidBlock;
use super::run::permanent_sliding_m;
use super::stick_bound::{AtPeriod, StickBound};
use super::Structure;
use crate::check::{self, count, interval};
use crate::dynamics::{Model, Observer, Simulation, SolveError, StepView};
use crate::foundation::{Foundation, MIN_FRICTION};
use crate::loads::generator::realization_rng;
use crate::loads::history::{TrainError, WaveEvent, WaveTrain};
use crate::loads::model::{PeakComponents, PeriodLoads, WaveLoadModel};
use crate::loads::regime::RegimeChoice;
use crate::loads::risetime::LoadRng;
use crate::loads::safety::heel_pressure_pa;
use crate::structure::Caisson;
use crate::waves::dispersion::wavenumber;
use crate::waves::periods::{self, WavePeriods};
use crate::waves::statistics::{rayleigh_exceedance, rayleigh_quantile_m, sample_rayleigh_m, DescendingRayleigh};
use crate::waves::surf_zone::SlopeTerms;
use crate::{ParamError, G_M_PER_S2};
use rand::Rng;
use rand_distr::StandardNormal;
use rayon::prelude::*;
use std::cell::OnceCell;
use std::f64::consts::PI;
use std::ops::ControlFlow;
use std::sync::atomic::{AtomicBool, Ordering};
use thiserror::Error;

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

    fn draw(&self, rng: &mut LoadRng) -> f64 {
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
struct ErrorDraw {
    h0: f64,
    transformation: f64,
    force: f64,
    friction: f64,
    impact: f64,
}

impl Errors {
    /// The multipliers, in the stream's order: H0, transformation, force, friction, then the
    /// impulsive component's if it has its own coefficients.
    fn draw(&self, rng: &mut LoadRng) -> ErrorDraw {
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
    /// threshold; [`super::climate`]).
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
/// reference and whether to screen.
#[derive(Debug, Clone, Copy)]
pub struct StormCase<'a> {
    pub structure: &'a Structure,
    /// The wave-load model at still water (its regime choice is used per wave).
    pub model: &'a WaveLoadModel,
    pub rigid_block_mu: f64,
    /// Skip the waves that cannot slide the caisson (module docs).
    pub screen: bool,
    /// With the screen, answer the pulsating waves that the bound of the all-sticking response
    /// shows can neither slide nor lift the caisson without running them (module docs, "The
    /// screen"; [`super::stick_bound`]): `false` runs them as up to results version 20 (the
    /// tests' reference).
    pub stick_bound: bool,
    /// With the stick bound, run the answered waves whose rotation bound may exceed the largest
    /// rotation (module docs, "The stick bound"), so that `max_rotation_rad` is every wave's:
    /// `false` leaves it the largest of the waves run, for what reads only the counts (the work
    /// estimate's screen pilot, whose short lives would run them far more often than a life).
    pub settle_rotation: bool,
    /// How a screened storm draws its waves (module docs, "Drawing"); without the screen every
    /// wave is drawn and simulated.
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
    /// Every wave drawn and tested against the screen (as up to results version 8): the tests'
    /// reference. It draws the same waves as a run with the screen off, so the two compare wave
    /// for wave; the default must agree with it in distribution.
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

/// The outcome of one storm (or, summed, of one life). Sign convention: sliding is positive
/// shoreward (the direction of the wave's push), negative seaward. The field names are the
/// columns of `lives.csv` and of the checkpoint lines ([`LIFE_COLUMNS`]).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StormOutcome {
    /// Net sliding of the dynamic model: the sum of every wave's permanent sliding, signed, m.
    pub sliding_m: f64,
    /// The sum of the shoreward wave slides (≥ 0), m.
    pub shoreward_sliding_m: f64,
    /// The sum of the seaward wave slides, as a magnitude (≥ 0), m:
    /// `sliding_m = shoreward_sliding_m − seaward_sliding_m`.
    pub seaward_sliding_m: f64,
    /// The largest distance of the caisson from its place at the start (of the life, for a life)
    /// after any wave (≥ |sliding_m|), m. A life fails when it exceeds the failure limit.
    pub max_excursion_m: f64,
    /// Rigid block (Shimosako model; it slides shoreward only), m.
    pub rigid_block_sliding_m: f64,
    /// The storm's net sliding of the largest magnitude, with its sign (for a life), m.
    pub max_storm_sliding_m: f64,
    pub waves: u64,
    /// Waves run through the dynamic model.
    pub simulated_waves: u64,
    /// Waves skipped by the screen (and those after the wave that failed a life, which are not
    /// run either).
    pub screened_waves: u64,
    /// Simulated waves during which part of the base lifted off (a spring out of contact).
    pub rocking_waves: u64,
    /// Simulated waves that rotated the caisson beyond [`ROCKING_LIMIT_RAD`]: the model does
    /// not follow overturning itself (large rotations, the mound's bearing capacity under the
    /// heel), so a life with such a wave is outside its validity (docs/design.md).
    pub large_rotation_waves: u64,
    /// The largest rotation |θ| of the caisson during any simulated wave, rad. A life fails when
    /// it exceeds the rotation limit ([`FailureLimits`]).
    pub max_rotation_rad: f64,
    /// The waves with an impulsive load (their load event has an impulse: a breaking wave with
    /// an impact under the load model) that may slide the caisson or lift its base (they pass the
    /// screen's friction or lift-off test: the others slide neither model, module docs
    /// "Impulsive waves"); each runs through both models.
    pub impulsive_waves: u64,
    /// The dynamic model's net sliding under those waves, signed (shoreward +), m.
    pub impulsive_sliding_m: f64,
    /// The rigid block's sliding under those waves, m.
    pub rigid_block_impulsive_sliding_m: f64,
    /// The largest heel pressure of the dynamic model, kPa (module docs, "Heel pressure"): of the
    /// caisson at rest at still water and of every wave run; exact at and above the screen's heel
    /// pressure ([`StormCase::heel_screen_pa`]), every wave that may reach it being run.
    pub max_heel_pressure_kpa: f64,
    /// The year (from 1) of the storm in which the life failed; 0 if it did not (a storm alone:
    /// 0; its failure is the flags below).
    pub failure_year: u64,
    /// 1 if the wave that failed the life (or storm) took the caisson beyond the sliding limit,
    /// else 0 (module docs, "Failure"; a failing wave may count in several modes).
    pub failed_by_sliding: u64,
    /// 1 if the failing wave rotated the caisson beyond the rotation limit.
    pub failed_by_rotation: u64,
    /// 1 if the failing wave pressed the heel beyond the failure heel pressure.
    pub failed_by_heel_pressure: u64,
    /// 1 if the failing wave had an impulsive load.
    pub failing_wave_impulsive: u64,
    /// 1 if the wave that took the rigid block beyond the sliding limit had an impulsive load.
    pub rigid_block_failing_wave_impulsive: u64,
    /// 1 if, after the failure, a wave did not converge in the dynamic model (far outside its
    /// validity) and the dynamic model ran no further wave of the life: its columns stop there
    /// (module docs, "Failure").
    pub run_on_stopped: u64,
}

/// One column of a life's outcome: its value as metres or as a count.
#[derive(Debug, Clone, Copy)]
pub enum LifeColumn {
    Metres(fn(&StormOutcome) -> f64),
    Count(fn(&StormOutcome) -> u64),
    Radians(fn(&StormOutcome) -> f64),
    Kilopascals(fn(&StormOutcome) -> f64),
}

/// The columns of a life's outcome (after `life`) in `lives.csv` and the Python `DataFrame`,
/// named as the [`StormOutcome`] fields.
pub const LIFE_COLUMNS: [(&str, LifeColumn); 23] = [
    ("sliding_m", LifeColumn::Metres(|o| o.sliding_m)),
    ("shoreward_sliding_m", LifeColumn::Metres(|o| o.shoreward_sliding_m)),
    ("seaward_sliding_m", LifeColumn::Metres(|o| o.seaward_sliding_m)),
    ("max_excursion_m", LifeColumn::Metres(|o| o.max_excursion_m)),
    ("rigid_block_sliding_m", LifeColumn::Metres(|o| o.rigid_block_sliding_m)),
    ("max_storm_sliding_m", LifeColumn::Metres(|o| o.max_storm_sliding_m)),
    ("waves", LifeColumn::Count(|o| o.waves)),
    ("simulated_waves", LifeColumn::Count(|o| o.simulated_waves)),
    ("screened_waves", LifeColumn::Count(|o| o.screened_waves)),
    ("rocking_waves", LifeColumn::Count(|o| o.rocking_waves)),
    ("large_rotation_waves", LifeColumn::Count(|o| o.large_rotation_waves)),
    ("max_rotation_rad", LifeColumn::Radians(|o| o.max_rotation_rad)),
    ("impulsive_waves", LifeColumn::Count(|o| o.impulsive_waves)),
    ("impulsive_sliding_m", LifeColumn::Metres(|o| o.impulsive_sliding_m)),
    ("rigid_block_impulsive_sliding_m", LifeColumn::Metres(|o| o.rigid_block_impulsive_sliding_m)),
    ("max_heel_pressure_kpa", LifeColumn::Kilopascals(|o| o.max_heel_pressure_kpa)),
    ("failure_year", LifeColumn::Count(|o| o.failure_year)),
    ("failed_by_sliding", LifeColumn::Count(|o| o.failed_by_sliding)),
    ("failed_by_rotation", LifeColumn::Count(|o| o.failed_by_rotation)),
    ("failed_by_heel_pressure", LifeColumn::Count(|o| o.failed_by_heel_pressure)),
    ("failing_wave_impulsive", LifeColumn::Count(|o| o.failing_wave_impulsive)),
    ("rigid_block_failing_wave_impulsive", LifeColumn::Count(|o| o.rigid_block_failing_wave_impulsive)),
    ("run_on_stopped", LifeColumn::Count(|o| o.run_on_stopped)),
];

impl StormOutcome {
    /// Append storm `o`, which started where this life's caisson now stands.
    fn add(&mut self, o: &StormOutcome) {
        self.sliding_m += o.sliding_m;
        self.shoreward_sliding_m += o.shoreward_sliding_m;
        self.seaward_sliding_m += o.seaward_sliding_m;
        self.max_excursion_m = self.max_excursion_m.max(o.max_excursion_m);
        self.rigid_block_sliding_m += o.rigid_block_sliding_m;
        if o.sliding_m.abs() > self.max_storm_sliding_m.abs() {
            self.max_storm_sliding_m = o.sliding_m;
        }
        self.waves += o.waves;
        self.simulated_waves += o.simulated_waves;
        self.screened_waves += o.screened_waves;
        self.rocking_waves += o.rocking_waves;
        self.large_rotation_waves += o.large_rotation_waves;
        self.max_rotation_rad = self.max_rotation_rad.max(o.max_rotation_rad);
        self.impulsive_waves += o.impulsive_waves;
        self.impulsive_sliding_m += o.impulsive_sliding_m;
        self.rigid_block_impulsive_sliding_m += o.rigid_block_impulsive_sliding_m;
        self.max_heel_pressure_kpa = self.max_heel_pressure_kpa.max(o.max_heel_pressure_kpa);
        // A storm records a failure only in a life that had not failed (and the rigid block's
        // failing wave only once).
        self.failed_by_sliding |= o.failed_by_sliding;
        self.failed_by_rotation |= o.failed_by_rotation;
        self.failed_by_heel_pressure |= o.failed_by_heel_pressure;
        self.failing_wave_impulsive |= o.failing_wave_impulsive;
        self.rigid_block_failing_wave_impulsive |= o.rigid_block_failing_wave_impulsive;
        self.run_on_stopped |= o.run_on_stopped;
    }

    /// Whether the life (or storm) failed: a wave took it beyond a failure limit (module docs,
    /// "Failure"); the modes are those of that wave.
    pub fn failed(&self) -> bool {
        (self.failed_by_sliding | self.failed_by_rotation | self.failed_by_heel_pressure) != 0
    }

    /// The failure modes that the caisson's state now reaches: beyond the sliding limit from its
    /// place, rotated beyond the rotation limit, the heel pressed beyond the failure pressure.
    fn beyond(&self, f: &FailureLimits) -> [bool; 3] {
        [
            self.max_excursion_m > f.sliding_m,
            self.max_rotation_rad > f.rotation_rad,
            f.heel_pressure_pa.is_some_and(|q| self.max_heel_pressure_kpa * 1e3 > q),
        ]
    }

    /// Whether the rigid block's sliding exceeds the sliding limit (it fails by sliding only).
    pub fn rigid_block_failed(&self, f: &FailureLimits) -> bool {
        self.rigid_block_sliding_m.abs() > f.sliding_m
    }
}

/// What a wave did besides sliding: the largest rotation, whether part of the base lifted and
/// the largest heel pressure.
#[derive(Debug, Clone, Copy, Default)]
struct WaveWatch {
    max_rotation_rad: f64,
    lifted: bool,
    /// Pa ([`base_heel_pressure_pa`] of the springs' resultant).
    max_heel_pressure_pa: f64,
    /// B and the caisson's length l, m.
    width_m: f64,
    length_m: f64,
}

impl WaveWatch {
    fn new(width_m: f64, length_m: f64) -> Self {
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

/// Dynamic amplification bound on impulsive components (module docs).
pub const PSI_IMPULSE: f64 = 2.0;
/// Cells of the per-storm screen grid over the heights.
const SCREEN_CELLS: usize = 64;
/// Cells of the per-storm screen grid over the periods, when the waves have periods of their own
/// (module docs, "Wave periods"): uniform in u = 1 − τ̄/τ over the periods drawn.
const PERIOD_CELLS: usize = 8;

/// The screen's amplifications and resistance at one wave period (module docs).
#[derive(Debug, Clone, Copy)]
struct ScreenBound {
    /// Ψ_q on the pulsating horizontal and vertical components.
    psi_q: f64,
    /// Ψ_m on the pulsating moment (the longer of the horizontal and rocking periods).
    psi_m: f64,
    /// W', N.
    weight_n: f64,
    /// The smaller friction coefficient of the two models.
    mu: f64,
    /// B, m.
    width_m: f64,
    /// f of [`Model::lift_off_factor`].
    lift_factor: f64,
    /// The caisson's length l, m, and the heel pressure the screen lets through, Pa
    /// ([`StormCase::heel_screen_pa`]).
    length_m: f64,
    heel_screen_pa: f64,
}

/// The effective peak loads of one wave's event for the screen (module docs): the horizontal
/// force P_eff, the uplift U_eff, the moment M_eff, and the uplift's overshoot above the weight
/// when it falls off, (Ψ − 1) U, N and N·m.
fn effective(e: &PeakComponents, b: &ScreenBound) -> [f64; 4] {
    let p = (PSI_IMPULSE * e.impact.x.fx_n).max(b.psi_q * e.quasi.x.fx_n);
    let u = (PSI_IMPULSE * e.impact.y.fy_n).max(b.psi_q * e.quasi.y.fy_n).max(0.0);
    let m = (PSI_IMPULSE * e.impact.total().m_nm).max(b.psi_m * e.quasi.total().m_nm).max(0.0);
    let overshoot = ((PSI_IMPULSE - 1.0) * e.impact.y.fy_n).max((b.psi_q - 1.0) * e.quasi.y.fy_n).max(0.0);
    [p, u, m, overshoot]
}

/// The screen's friction and lift-off tests of one wave's event: whether it may slide the
/// caisson (either model) or lift its seaward spring.
fn may_slide(e: &PeakComponents, b: &ScreenBound) -> bool {
    let [p, u, m, _] = effective(e, b);
    // Sliding, or the seaward spring lifting off ((6 M/B) f ≥ W' − U): a rocking caisson
    // ratchets shoreward a little as its springs re-contact.
    p > b.mu * (b.weight_n - u) || 6.0 * m / b.width_m * b.lift_factor >= b.weight_n - u
}

/// The screen's bound on the heel pressure of one wave's event, Pa (module docs, "Heel
/// pressure"): the largest of [`heel_pressure_pa`] with M_eff and the springs' normal force at
/// either end of its range, W' − U_eff to W' + (Ψ − 1) U (for a fixed moment it is largest at an
/// end of a range of normal forces); infinite where W' − U_eff ≤ 0.
fn heel_bound_pa(e: &PeakComponents, b: &ScreenBound) -> f64 {
    let [_, u, m, overshoot] = effective(e, b);
    let at = |v: f64| {
        if v <= 0.0 {
            f64::INFINITY
        } else {
            heel_pressure_pa(v / b.length_m, 0.5 * b.width_m - m / v, b.width_m)
        }
    };
    at(b.weight_n - u).max(at(b.weight_n + overshoot))
}

/// Whether the screen lets a wave through: it may slide or lift the caisson ([`may_slide`]), or
/// press its heel to the screen's heel pressure ([`heel_bound_pa`]).
fn may_pass(e: &PeakComponents, b: &ScreenBound) -> bool {
    may_slide(e, b) || heel_bound_pa(e, b) >= b.heel_screen_pa
}

/// What the storms of one life reuse: the one-wave train of the simulated waves, the waves
/// drawn above the screen's threshold, and the waves the linear bound answered whose rotation
/// may still be the largest (of the storm, or of the life with the life's storms they belong to:
/// module docs, "The screen").
#[derive(Debug, Default)]
struct StormScratch {
    train: WaveTrain,
    waves: Vec<DrawnWave>,
    still: Vec<StillWave>,
    /// The waves run for their heel pressure alone when the life's (or storm's) end shows they
    /// may still raise it ([`StillWave::rotation_rad`] their heel-pressure bound, Pa; module docs,
    /// "Heel pressure").
    heel: Vec<StillWave>,
    storms: Vec<StormInput>,
    /// [`ScreenModes::still_water`], taken at the life's first storm.
    modes: Option<ScreenModes>,
}

impl StormScratch {
    /// [`ScreenModes::still_water`] of `st`, once.
    fn modes(&mut self, st: &StormCase<'_>) -> ScreenModes {
        *self.modes.get_or_insert_with(|| ScreenModes::still_water(st))
    }
}

/// A wave the linear bound answered ([`super::stick_bound`]): the bound on its rotation, rad,
/// and what runs it again (its storm's index among the life's storms, its height, rise-time
/// deviate and period), should the storm's or the life's largest rotation need it (module docs,
/// "The screen").
#[derive(Debug, Clone, Copy)]
struct StillWave {
    rotation_rad: f64,
    storm: usize,
    height_m: f64,
    deviate: f64,
    period_s: f64,
}

/// Whose largest rotation the still waves settle (module docs, "The screen"): a storm's, at its
/// end ([`simulate_storm`]: fragility reads every storm's), or only the life's
/// ([`simulate_life`]), the life's largest rotation before the storm and the storm's index.
#[derive(Debug, Clone, Copy)]
enum Settle {
    Storm,
    Life { floor_rad: f64, storm: usize },
}

/// Most still waves a life keeps unsettled (module docs, "The screen"): beyond, they are settled
/// at the end of the storm (which empties the list). Each is 40 bytes; the design example's lives
/// keep a few.
const MAX_STILL_WAVES: usize = 4096;

/// A still wave whose rotation bound times this factor exceeds the storm's largest rotation so
/// far is run after all (module docs, "The screen"): a margin for a bound below the rotation the
/// engine reports, which has not been seen (the bound was 0.2-4.2 % above it on every answered
/// wave of the design and sizing examples, 98 142 and 832 538 waves, results version 21).
const ROTATION_RESERVE: f64 = 1.01;

/// A wave drawn above the screen's threshold: its place in the storm (a uniform on [0, 1): the
/// drawn waves run in this order), its height (clamped), its rise-time deviate and its period.
#[derive(Debug, Clone, Copy)]
struct DrawnWave {
    place: f64,
    height_m: f64,
    deviate: f64,
    period_s: f64,
}

/// Run one storm (module docs). `rng` supplies the per-wave draws.
pub fn simulate_storm(st: &StormCase<'_>, s: &StormInput, rng: &mut LoadRng) -> Result<StormOutcome, StormError> {
    storm_from(st, s, &mut StormRng::Given(rng), StormStart::ALONE, None, &mut StormScratch::default())
}

/// Where a storm starts in its life: the caisson's distance from its place and the rigid
/// block's sliding so far, m, whether the life has failed already (its failing wave is recorded
/// once), and whose largest rotation the storm's still waves settle.
#[derive(Debug, Clone, Copy)]
struct StormStart {
    start_m: f64,
    rigid_m: f64,
    /// The largest heel pressure of the life so far, kPa.
    heel_floor_kpa: f64,
    failed: bool,
    /// The dynamic model's run-on has stopped ([`StormOutcome::run_on_stopped`]).
    stopped: bool,
    settle: Settle,
}

impl StormStart {
    /// A storm alone (fragility), from the caisson's place.
    const ALONE: StormStart = StormStart {
        start_m: 0.0,
        rigid_m: 0.0,
        heel_floor_kpa: 0.0,
        failed: false,
        stopped: false,
        settle: Settle::Storm,
    };
}

/// The random stream a storm draws its waves from (module docs, "Random numbers").
enum StormRng<'r> {
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
    fn get(&mut self) -> &mut LoadRng {
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

impl StormOutcome {
    /// `Ok` if every column is a finite number, else the first that is not
    /// ([`StormError::NonFinite`]).
    fn finite(self) -> Result<Self, StormError> {
        for (column, c) in LIFE_COLUMNS {
            let value = match c {
                LifeColumn::Metres(f) | LifeColumn::Radians(f) | LifeColumn::Kilopascals(f) => f(&self),
                LifeColumn::Count(_) => continue,
            };
            if !value.is_finite() {
                return Err(StormError::NonFinite { column, value });
            }
        }
        Ok(self)
    }
}

/// What the screen's bound reads of the dynamic model ([`StormSite::bound`]): the same at every
/// storm of a caisson, whose tide and friction error change the caisson's weight in water, its
/// base depth and its friction, not its mass, added mass, stiffness or springs' places (the
/// still-water model's numbers to the bit, `tests::the_screen_reads_the_still_water_modes`), so
/// taken once per life from the still-water model.
#[derive(Debug, Clone, Copy, PartialEq)]
struct ScreenModes {
    /// T0 of the horizontal mode, and the longer of T0 and the rocking period, s.
    t0_s: f64,
    t_moment_s: f64,
    /// f of [`Model::lift_off_factor`].
    lift_factor: f64,
}

impl ScreenModes {
    fn of(m: &Model) -> Self {
        let t0_s = m.natural_period_s();
        ScreenModes { t0_s, t_moment_s: t0_s.max(m.rocking_period_s()), lift_factor: m.lift_off_factor() }
    }

    /// Those of the still-water model of `st`'s caisson.
    fn still_water(st: &StormCase<'_>) -> Self {
        Self::of(&Model::new(&st.structure.caisson, &st.structure.foundation))
    }
}

/// The site and the caisson at a storm's water level (module docs, step 3), with its friction
/// error: both models and what the screen's bound needs of them.
struct StormSite {
    model: WaveLoadModel,
    block: RigidBlock,
    /// The caisson and its foundation at the storm's water level and friction, and the dynamic
    /// model of them, built when a wave first needs it (most storms run no wave through it).
    caisson: Caisson,
    foundation: Foundation,
    dyn_model: OnceCell<Model>,
    modes: ScreenModes,
    weight_n: f64,
    mu: f64,
    width_m: f64,
    /// l, m, and [`StormCase::heel_screen_pa`].
    length_m: f64,
    heel_screen_pa: f64,
    /// The bound of the all-sticking response, built when a wave first needs it.
    stick: OnceCell<Option<StickBound>>,
}

impl StormSite {
    /// The site of storm `s`; `modes`: [`ScreenModes::still_water`] of `st`.
    fn new(st: &StormCase<'_>, s: &StormInput, modes: ScreenModes) -> Self {
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
    fn dyn_model(&self) -> &Model {
        self.dyn_model.get_or_init(|| Model::new(&self.caisson, &self.foundation))
    }

    /// The screen's bound for a wave of period `period_s`: Ψ = 1 + T/(π t_q), t_q = T_w/4.
    fn bound(&self, period_s: f64) -> ScreenBound {
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
    fn scaled(&self, p: &PeakComponents) -> PeakComponents {
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

/// The screen's grid of one storm (module docs, "The screen"): whether a wave may slide or lift
/// the caisson, at the nodes of a grid over the heights [0, H_max] (plus the breaker height at the
/// wall) and, for waves with periods of their own, over the storm's periods.
struct StormScreen {
    /// Bit i of `node[j]`: at period node j, height i · dh (`SCREEN_CELLS` + 1 bits a row).
    node: [u128; PERIOD_CELLS + 1],
    /// Period nodes: 1 (every wave at T1/3) or `PERIOD_CELLS + 1`.
    periods: usize,
    /// The lowest height node that may slide at any period node (`None`: no node may, in a calm
    /// storm or without the screen).
    first_node: Option<usize>,
    dh: f64,
    /// τ̄, and u = 1 − τ̄/τ at the first period node and its step.
    mean_period_s: f64,
    u0: f64,
    du: f64,
    /// Nodes of the rows run that the bound left false without their loads (what the tests see
    /// of the bisection).
    #[cfg_attr(not(test), allow(dead_code))]
    bound_nodes: usize,
}

impl StormScreen {
    /// The grid of storm `s` on `site` (every node false without the screen); `t13` are the
    /// loads and the bound at the storm's T1/3 (the one period node of waves at T1/3).
    fn new(st: &StormCase<'_>, s: &StormInput, site: &StormSite, t13: (&PeriodLoads<'_>, ScreenBound)) -> Self {
        Self::grid(st, s, site, t13, true)
    }

    /// [`Self::new`]; `bisect`: leave the nodes the bound of the loads up to their height holds
    /// without their loads (`false`: every node's loads, the tests' reference).
    fn grid(
        st: &StormCase<'_>,
        s: &StormInput,
        site: &StormSite,
        t13: (&PeriodLoads<'_>, ScreenBound),
        bisect: bool,
    ) -> Self {
        let hmax = s.hmax_m.max(1e-6);
        let dh = hmax / SCREEN_CELLS as f64;
        let (periods, [u0, u1]) = match s.periods {
            WavePeriods::Significant => (1, [0.0, 0.0]),
            WavePeriods::LonguetHiggins { .. } => (PERIOD_CELLS + 1, periods::u_range()),
        };
        let mean_period_s = periods::MEAN_PERIOD_RATIO * s.period_s;
        let du = (u1 - u0) / PERIOD_CELLS as f64;
        let mut node = [0_u128; PERIOD_CELLS + 1];
        let mut bound_nodes = 0;
        for (j, row) in node.iter_mut().enumerate().take(if st.screen { periods } else { 0 }) {
            let own;
            let (loads_at, bound) = if periods == 1 {
                t13
            } else {
                let period_s = mean_period_s / (1.0 - (u0 + j as f64 * du));
                own = site.model.at_period(period_s);
                (&own, site.bound(period_s))
            };
            // Where even the bounds of the loads over all heights up to h cannot slide or lift the
            // caisson, every node up to h is false: at a period where that holds for H_max the
            // row is not needed, else the nodes up to the highest node height where it holds (by
            // bisection; the bound covers every lower node whatever the others give) are false
            // without their loads.
            let still_up_to = |h: f64| loads_at.peak_bound(h).is_some_and(|b| !may_pass(&s.scaled(&b), &bound));
            if still_up_to(hmax) {
                continue;
            }
            let node_h = |i: usize| (i as f64 * dh).max(1e-3 * hmax);
            // Nodes below `first` are false; the bound does not hold the caisson at node `last`.
            let (mut first, mut last) = (0, SCREEN_CELLS + 1);
            while bisect && last - first > 1 {
                let mid = (first + last) / 2;
                if still_up_to(node_h(mid - 1)) {
                    first = mid;
                } else {
                    last = mid;
                }
            }
            let node_may_slide =
                |h: f64| loads_at.peaks(h, RegimeChoice::Auto).map_or(true, |p| may_pass(&s.scaled(&p), &bound));
            bound_nodes += first;
            for i in first..=SCREEN_CELLS {
                *row |= u128::from(node_may_slide(node_h(i))) << i;
            }
            let hbr = loads_at.breaker_height_at_wall_m();
            if hbr < hmax {
                let i = (hbr / dh) as usize;
                let flag = node_may_slide(hbr);
                *row |= (u128::from(flag) << i) | (u128::from(flag) << (i + 1).min(SCREEN_CELLS));
            }
        }
        // Only the rows of the period nodes can hold a flag (the others stay false).
        let first_node = node[..periods].iter().map(|row| row.trailing_zeros() as usize).min().filter(|&i| i < 128);
        StormScreen { node, periods, first_node, dh, mean_period_s, u0, du, bound_nodes }
    }

    /// The period cells of the grid.
    #[cfg(test)]
    fn period_cells(&self) -> usize {
        (self.periods - 1).max(1)
    }

    /// Cell (c, j) = [c dh, (c + 1) dh] × [period node j, j + 1] may slide if a node within one
    /// cell of it may, in both directions.
    fn cell_may_slide(&self, c: usize, j: usize) -> bool {
        // Nodes c − 1 to c + 2 (within the grid): the bits below c + 3 less those below c − 1.
        let below = |i: usize| (1_u128 << i) - 1;
        let window = below((c + 3).min(SCREEN_CELLS + 1)) & !below(c.saturating_sub(1));
        self.node[j.saturating_sub(1)..=(j + 2).min(self.periods - 1)].iter().any(|row| row & window != 0)
    }

    /// Whether the cell of a wave of height `h` and period `period_s` may slide.
    fn may_slide_at(&self, h: f64, period_s: f64) -> bool {
        let c = ((h / self.dh) as usize).min(SCREEN_CELLS - 1);
        let j = if self.periods == 1 {
            0
        } else {
            (((1.0 - self.mean_period_s / period_s - self.u0) / self.du).max(0.0) as usize).min(PERIOD_CELLS - 1)
        };
        self.cell_may_slide(c, j)
    }

    /// The lowest height cell that may slide at some period: two cells below the lowest node that
    /// may. Cell c reads the nodes c − 1 to c + 2 ([`Self::cell_may_slide`]), and the period cells
    /// together read every period node, so c may slide if and only if a node from c − 1 to c + 2
    /// may at some period: the lowest is max(0, i − 2) for the lowest such node i (at most
    /// `SCREEN_CELLS` − 2, a cell of the grid).
    fn lowest_cell(&self) -> Option<usize> {
        self.first_node.map(|i| i.saturating_sub(2))
    }

    /// [`Self::lowest_cell`] cell by cell (the tests' reference).
    #[cfg(test)]
    fn lowest_cell_by_cells(&self) -> Option<usize> {
        (0..SCREEN_CELLS).find(|&c| (0..self.period_cells()).any(|j| self.cell_may_slide(c, j)))
    }
}

/// One wave through both models (module docs, step 6): its loads at its own period tested against
/// the screen's bound at that period, then the rigid block, then the dynamic model (unless the
/// stick bound answers it).
struct WaveRun<'a> {
    st: &'a StormCase<'a>,
    s: &'a StormInput,
    site: &'a StormSite,
    /// The loads and the screen's bound at the storm's T1/3 (every wave's period by default).
    loads_t13: &'a PeriodLoads<'a>,
    bound_t13: ScreenBound,
    start_m: f64,
    /// Whether the life (or storm) has failed already (module docs, "Failure"): its failing wave
    /// is recorded once.
    failed: bool,
    /// Whether the dynamic model has stopped running on after the failure (a wave that did not
    /// converge, [`StormOutcome::run_on_stopped`]): only the rigid block runs.
    stopped: bool,
    /// The rigid block's sliding before the storm, m, and whether it has passed the sliding
    /// limit already (its failing wave is recorded once).
    rigid_start_m: f64,
    rigid_failed: bool,
    /// The largest heel pressure of the life before the storm, kPa.
    heel_floor_kpa: f64,
    sim: Option<Simulation>,
    train: &'a mut WaveTrain,
    /// The linear bound at T1/3, built when a wave first needs it.
    stick_t13: OnceCell<Option<AtPeriod>>,
    /// The waves the linear bound answered whose rotation may be the storm's (or the life's)
    /// largest.
    still: &'a mut Vec<StillWave>,
    /// The waves that may press the heel beyond the screen's pressure and the largest known, run
    /// for it at the storm's (or life's) end if it may still be the largest.
    heel: &'a mut Vec<StillWave>,
    /// Whose largest rotation they settle.
    settle: Settle,
}

impl WaveRun<'_> {
    /// The loads of the wave of height `h` (clamped), rise-time deviate `z` and period
    /// `period_s`, times the storm's errors, and the screen's bound at its period.
    fn event(&self, h: f64, z: f64, period_s: f64) -> (WaveEvent, ScreenBound) {
        let (s, site) = (self.s, self.site);
        let own;
        let (loads_at, bound) = if s.periods.is_significant() {
            (self.loads_t13, self.bound_t13)
        } else {
            own = site.model.at_period(period_s);
            (&own, site.bound(period_s))
        };
        // A forced regime the wave contradicts (non-breaking above the limit): the criterion decides.
        let e = match loads_at.event(h, site.model.options.regime, z) {
            Ok(e) => e,
            Err(_) => loads_at.event(h, RegimeChoice::Auto, z).expect("the automatic regime always applies"),
        };
        let event = WaveEvent {
            quasi: e.quasi.scaled(s.force_factor),
            trough: e.trough.scaled(s.force_factor),
            impact: e.impact.scaled(s.impact_factor),
            ..e
        };
        (event, bound)
    }

    /// Wave of height `h` (clamped), rise-time deviate `z` and period `period_s`.
    fn run(&mut self, h: f64, z: f64, period_s: f64, out: &mut StormOutcome) -> Result<(), StormError> {
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
                // [`settle_life`]) decides, unless a larger one is known already.
                out.screened_waves += 1;
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

    /// The bound on the rotation of a pulsating wave that the linear bound shows can neither
    /// slide nor lift the caisson, nor rotate it near the rocking or failure limits
    /// ([`super::stick_bound`]); `None` for any other wave.
    fn still_rotation_rad(&self, event: &WaveEvent, period_s: f64) -> Option<f64> {
        if event.impulse.is_some() {
            return None;
        }
        let site = self.site;
        let bound = site.stick.get_or_init(|| StickBound::new(site.dyn_model())).as_ref()?;
        let own;
        let at = if self.s.periods.is_significant() {
            self.stick_t13.get_or_init(|| bound.at_period(self.s.period_s)).as_ref()?
        } else {
            own = bound.at_period(period_s)?;
            &own
        };
        let m = bound.margins(at, event.quasi.total(), event.trough.total());
        let limit_rad = self.st.failure.map_or(ROCKING_LIMIT_RAD, |f| f.rotation_rad.min(ROCKING_LIMIT_RAD));
        (m.still() && m.rotation_rad * ROTATION_RESERVE < limit_rad).then_some(m.rotation_rad)
    }

    /// Run the kept waves of a storm alone whose bound may exceed the storm's largest, largest
    /// bound first, until the bound of the next is at most it (module docs, "The stick bound" and
    /// "Heel pressure"; a life's are run by [`settle_life`]): the still waves for the rotation
    /// (`heel` false), or the deferred waves for the heel pressure. The storm's largest is then
    /// what running every such wave gives. Each wave run moves from the screened to the simulated
    /// count.
    fn settle(&mut self, heel: bool, out: &mut StormOutcome) -> Result<(), StormError> {
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
    fn simulate(
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
enum WaveKind {
    Impulsive,
    Pulsating,
    HeelOnly,
}

/// The depth at the toe at the water level `tide_m`, m.
fn toe_depth_m(st: &StormCase<'_>, tide_m: f64) -> f64 {
    st.model.site.depth_at_toe_m + tide_m
}

/// [`simulate_storm`] for a caisson that starts the storm where `from` says (for the life's
/// largest excursion and its failure), its still waves settled as `from.settle` says (with
/// [`Settle::Life`] they are left in `scratch.still` for [`settle_life`]). `toe_k`: the wave
/// number of T1/3 at [`toe_depth_m`], if the caller has solved for it (the life, for the storm's
/// shoaling).
fn storm_from(
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
fn draw_above_threshold(
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
            let u: f64 = rng.gen::<f64>().clamp(1e-12, 1.0 - 1e-12);
            let e = match life_errors {
                Some(e) => e,
                None => p.errors.draw(&mut rng),
            };
            let phi = 2.0 * PI * rng.gen::<f64>();
            let h0 = (p.storm_height_m(u) * e.h0).max(1e-3);
            let period_s = p.period_coefficient * h0.powf(p.period_exponent);
            let duration_s = p.climate.duration.draw_s(p.storm_duration_s, &mut rng);
            let angle_rad = p.climate.direction.draw_rad(&mut rng);
            let tide_m = 0.5 * p.tidal_range_m * (1.0 + phi.cos()) + rise_m;
            // The dispersion solve at the toe serves the shoaling and the storm's loads.
            let depth_m = toe_depth_m(st, tide_m);
            let k_toe = wavenumber(period_s, depth_m);
            let z = slope.surf_zone_at_wavenumber(h0, period_s, depth_m, k_toe);
            let storm = StormInput {
                h13_m: z.h13_m * e.transformation,
                hmax_m: z.hmax_m * e.transformation,
                period_s,
                periods: p.climate.periods,
                waves: (duration_s / period_s).round().max(1.0) as usize,
                tide_m,
                angle_rad,
                force_factor: e.force,
                impact_factor: e.impact,
                friction_factor: e.friction,
            };
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

/// Run the still waves of the life's storms whose rotation bound may exceed the life's largest
/// rotation, largest bound first, until the bound of the next is below it (module docs, "The
/// screen"): the life's largest rotation is then what running every wave gives. Each wave run
/// moves from the screened to the simulated count; it neither slides nor lifts (its bound says
/// so), so only the rotation and the counts can move. Empties `scratch.still`.
fn settle_life(st: &StormCase<'_>, scratch: &mut StormScratch, life: &mut StormOutcome) -> Result<(), StormError> {
    let modes = scratch.modes(st);
    let StormScratch { train, still, heel, storms, .. } = scratch;
    still.sort_unstable_by(|a, b| b.rotation_rad.total_cmp(&a.rotation_rad));
    heel.sort_unstable_by(|a, b| b.rotation_rad.total_cmp(&a.rotation_rad));
    // The site of the storm whose waves run (the waves of a storm are mostly together).
    let mut site: Option<(usize, StormSite)> = None;
    let (mut none, mut no_heel) = (Vec::new(), Vec::new());
    // The still waves for the rotation, then the deferred waves for the heel pressure (module
    // docs, "Heel pressure"): each list while its next bound may exceed the life's largest.
    let pending = still.iter().map(|w| (w, WaveKind::Pulsating)).chain(heel.iter().map(|w| (w, WaveKind::HeelOnly)));
    for (w, kind) in pending {
        let needed = match kind {
            WaveKind::HeelOnly => w.rotation_rad > 1e3 * life.max_heel_pressure_kpa,
            _ => w.rotation_rad * ROTATION_RESERVE > life.max_rotation_rad,
        };
        if !needed {
            if kind == WaveKind::HeelOnly {
                break;
            }
            continue;
        }
        let s = &storms[w.storm];
        if site.as_ref().is_none_or(|(i, _)| *i != w.storm) {
            site = Some((w.storm, StormSite::new(st, s, modes)));
        }
        let site = &site.as_ref().expect("the wave's storm's site").1;
        let mut run = WaveRun {
            st,
            s,
            site,
            loads_t13: &site.model.at_period(s.period_s),
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
            train,
            stick_t13: OnceCell::new(),
            still: &mut none,
            heel: &mut no_heel,
            settle: Settle::Storm,
        };
        let (event, _) = run.event(w.height_m, w.deviate, w.period_s);
        let mut o = StormOutcome::default();
        run.simulate(event, w.height_m, w.period_s, kind, &mut o)?;
        if o.simulated_waves == 0 {
            // It did not converge, in a failed life: it stays screened.
            continue;
        }
        life.simulated_waves += 1;
        life.screened_waves -= 1;
        if kind == WaveKind::HeelOnly {
            life.max_heel_pressure_kpa = life.max_heel_pressure_kpa.max(o.max_heel_pressure_kpa);
            continue;
        }
        life.rocking_waves += o.rocking_waves;
        life.large_rotation_waves += o.large_rotation_waves;
        life.max_rotation_rad = life.max_rotation_rad.max(o.max_rotation_rad);
        #[cfg(test)]
        tests::SETTLED.with(|n| n.set(n.get() + 1));
    }
    still.clear();
    heel.clear();
    Ok(())
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
    /// The allowable heel pressure q_a, Pa (default [`DEFAULT_ALLOWABLE_HEEL_PRESSURE_PA`]): the
    /// exceedance P(q_heel > q_a) is reported, and the screen runs every wave that may reach it
    /// (module docs, "Heel pressure").
    pub allowable_heel_pressure_pa: f64,
    /// The heel pressure beyond which a life fails, Pa; `None` (the default): no failure by
    /// heel pressure.
    pub failure_heel_pressure_pa: Option<f64>,
}

/// The allowable heel pressure on a rubble mound of a design (`[design]
/// allowable_heel_pressure_kpa`), as Goda's check has it ([`DEFAULT_ALLOWABLE_HEEL_PRESSURE_PA`]
/// of [`super::conventional`]).
pub use super::conventional::DEFAULT_ALLOWABLE_HEEL_PRESSURE_PA;

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
        Ok(DesignParams { life, ..self })
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

/// Statistics of the life totals.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct LifeStatistics {
    pub lives: usize,
    pub mean_m: f64,
    /// (percent, value m) for 5, 50, 95, 99 %.
    pub percentiles_m: Vec<(f64, f64)>,
    /// (threshold m, probability of exceeding it).
    pub exceedance: Vec<(f64, f64)>,
}

/// The headline statistics of a model's lives (module docs, "Failure"): mean, percentiles and
/// exceedances of the magnitudes |S| with each failed life at the sliding limit `limit_m` (a
/// surviving life's |S| never exceeds it, so the mean is bounded by it), and a failed life
/// counted as exceeding every threshold (at and beyond the limit too: P(|S| > s) ≥ P(failure)).
pub fn capped_statistics(magnitudes: &[f64], failed: &[bool], limit_m: f64, thresholds_m: &[f64]) -> LifeStatistics {
    let capped: Vec<f64> = magnitudes.iter().zip(failed).map(|(&m, &f)| if f { limit_m } else { m }).collect();
    let mut s = life_statistics(&capped, &[]);
    let n = magnitudes.len().max(1) as f64;
    s.exceedance = thresholds_m
        .iter()
        .map(|&t| (t, magnitudes.iter().zip(failed).filter(|(&m, &f)| f || m > t).count() as f64 / n))
        .collect();
    s
}

/// Mean, percentiles (nearest-rank) and exceedance probabilities of `values`.
pub fn life_statistics(values: &[f64], thresholds_m: &[f64]) -> LifeStatistics {
    let n = values.len();
    let mut sorted = values.to_vec();
    sorted.sort_by(f64::total_cmp);
    let pct = |p: f64| if n == 0 { 0.0 } else { sorted[((p / 100.0 * n as f64).ceil() as usize).clamp(1, n) - 1] };
    LifeStatistics {
        lives: n,
        mean_m: if n == 0 { 0.0 } else { values.iter().sum::<f64>() / n as f64 },
        percentiles_m: [5.0, 50.0, 95.0, 99.0].iter().map(|&p| (p, pct(p))).collect(),
        exceedance: thresholds_m
            .iter()
            .map(|&t| (t, values.iter().filter(|&&v| v > t).count() as f64 / n.max(1) as f64))
            .collect(),
    }
}

/// What the life warnings need of a model's lives: a design run's lives reduce to it, and a
/// sizing candidate keeps it ([`super::sizing::Candidate::life_counts`]).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct LifeCounts {
    pub lives: usize,
    /// Lives that failed (any mode), and by each mode of their failing wave (a life may count
    /// in several).
    pub failed_lives: usize,
    pub failed_by_sliding_lives: usize,
    pub failed_by_rotation_lives: usize,
    pub failed_by_heel_pressure_lives: usize,
    /// Lives with a wave that rotated the caisson beyond [`ROCKING_LIMIT_RAD`].
    pub large_rotation_lives: usize,
    /// Lives that ended more than [`SEAWARD_REPORT_M`] seaward of their place.
    pub seaward_lives: usize,
    /// The largest of those seaward distances, m (0 without such lives).
    pub largest_seaward_sliding_m: f64,
    /// E|S| of the lives as simulated (every life to its end, not capped at the failure
    /// limit), m.
    pub expected_sliding_uncapped_m: f64,
    /// E|S| of the rigid block (over the whole lives), m.
    pub rigid_block_expected_sliding_m: f64,
    /// The largest net sliding of a single storm, m.
    pub max_storm_sliding_m: f64,
    /// Failed lives whose dynamic model stopped running on at a wave that did not converge.
    pub run_on_stopped_lives: usize,
    /// What the impulsive waves make of each model's lives.
    pub impulsive: ImpulsiveShare,
    pub rigid_block_impulsive: ImpulsiveShare,
}

impl LifeCounts {
    /// The counts of `lives` with the failure limits `failure` (the rigid block's failure: its
    /// sliding beyond the sliding limit).
    pub fn of(lives: &[StormOutcome], failure: &FailureLimits) -> Self {
        let count = |f: &dyn Fn(&StormOutcome) -> bool| lives.iter().filter(|l| f(l)).count();
        let seaward = |l: &StormOutcome| l.sliding_m < -SEAWARD_REPORT_M;
        LifeCounts {
            lives: lives.len(),
            failed_lives: count(&|l| l.failed()),
            failed_by_sliding_lives: count(&|l| l.failed_by_sliding != 0),
            failed_by_rotation_lives: count(&|l| l.failed_by_rotation != 0),
            failed_by_heel_pressure_lives: count(&|l| l.failed_by_heel_pressure != 0),
            large_rotation_lives: count(&|l| l.large_rotation_waves > 0),
            seaward_lives: count(&seaward),
            largest_seaward_sliding_m: lives.iter().filter(|l| seaward(l)).map(|l| -l.sliding_m).fold(0.0, f64::max),
            expected_sliding_uncapped_m: lives.iter().map(|l| l.sliding_m.abs()).sum::<f64>()
                / lives.len().max(1) as f64,
            rigid_block_expected_sliding_m: lives.iter().map(|l| l.rigid_block_sliding_m.abs()).sum::<f64>()
                / lives.len().max(1) as f64,
            max_storm_sliding_m: lives.iter().map(|l| l.max_storm_sliding_m).fold(0.0, f64::max),
            run_on_stopped_lives: count(&|l| l.run_on_stopped != 0),
            impulsive: ImpulsiveShare::dynamic(lives),
            rigid_block_impulsive: ImpulsiveShare::rigid_block(lives, failure),
        }
    }
}

/// What the impulsive waves make of one model's lives (or storms; module docs, "Impulsive
/// waves"): the `impulsive` group of `design.json`, `size.json` and `fragility.json`.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct ImpulsiveShare {
    /// The impulsive waves of all lives ([`StormOutcome::impulsive_waves`]).
    pub waves: u64,
    /// The mean over the lives of the sliding those waves caused, m (signed for the dynamic
    /// model, shoreward +).
    pub sliding_m: f64,
    /// Their share of E|S| as simulated: Σ sign(S) S_imp / Σ |S| over the lives, S a life's
    /// sliding and S_imp its impulsive waves' (the part of |S| they made; above 1 where other
    /// waves slid the caisson back); 0 when E|S| = 0.
    pub share_of_expected_sliding: f64,
    /// The failed lives whose failing wave was impulsive, over the failed lives (0 when none
    /// failed).
    pub share_of_failures: f64,
    /// The failed lives.
    pub failures: usize,
}

impl ImpulsiveShare {
    /// From each life's (S, S_imp, failed, failing wave impulsive).
    fn of(waves: u64, lives: impl Iterator<Item = (f64, f64, bool, bool)>) -> Self {
        let (mut n, mut imp, mut part, mut total, mut failures, mut impulsive_failures) = (0usize, 0.0, 0.0, 0.0, 0, 0);
        for (s, s_imp, failed, impulsive) in lives {
            n += 1;
            imp += s_imp;
            part += if s < 0.0 { -s_imp } else { s_imp };
            total += s.abs();
            failures += usize::from(failed);
            impulsive_failures += usize::from(failed && impulsive);
        }
        ImpulsiveShare {
            waves,
            sliding_m: imp / n.max(1) as f64,
            share_of_expected_sliding: if total > 0.0 { part / total } else { 0.0 },
            share_of_failures: if failures > 0 { impulsive_failures as f64 / failures as f64 } else { 0.0 },
            failures,
        }
    }

    /// The dynamic model's.
    pub fn dynamic(lives: &[StormOutcome]) -> Self {
        let waves = lives.iter().map(|l| l.impulsive_waves).sum();
        Self::of(
            waves,
            lives.iter().map(|l| (l.sliding_m, l.impulsive_sliding_m, l.failed(), l.failing_wave_impulsive != 0)),
        )
    }

    /// The rigid block's (it fails by sliding beyond `failure.sliding_m`).
    pub fn rigid_block(lives: &[StormOutcome], failure: &FailureLimits) -> Self {
        let waves = lives.iter().map(|l| l.impulsive_waves).sum();
        Self::of(
            waves,
            lives.iter().map(|l| {
                (
                    l.rigid_block_sliding_m,
                    l.rigid_block_impulsive_sliding_m,
                    l.rigid_block_failed(failure),
                    l.rigid_block_failing_wave_impulsive != 0,
                )
            }),
        )
    }

    /// Whether impulsive waves make more than half of E|S| or of the failures.
    pub fn dominates(&self) -> bool {
        self.share_of_expected_sliding > 0.5 || self.share_of_failures > 0.5
    }
}

/// The exceedance of the allowable heel pressure by the lives' largest heel pressure
/// ([`StormOutcome::max_heel_pressure_kpa`]; module docs, "Heel pressure"): the dynamic model's
/// (the rigid block has no foundation pressure).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
pub struct HeelPressureExceedance {
    /// q_a, kPa.
    pub allowable_kpa: f64,
    /// P(q_heel > q_a): the share of lives whose largest heel pressure exceeds q_a (exact: the
    /// screen runs every wave that may reach q_a).
    pub probability: f64,
    /// Its standard error √(p(1 − p)/n).
    pub standard_error: f64,
    /// The lives beyond q_a.
    pub lives: usize,
    /// The heel pressure at and above which each life's value is exact, kPa (the screen's: q_a,
    /// or the failure heel pressure if lower); below it a life's value is the largest of the
    /// waves run.
    pub exact_from_kpa: f64,
    /// The largest heel pressure of any life, kPa.
    pub largest_kpa: f64,
}

impl HeelPressureExceedance {
    /// Of `lives` against q_a = `allowable_pa`, exact from `exact_from_pa`.
    pub fn of(lives: &[StormOutcome], allowable_pa: f64, exact_from_pa: f64) -> Self {
        let allowable_kpa = allowable_pa / 1e3;
        let beyond = lives.iter().filter(|l| l.max_heel_pressure_kpa > allowable_kpa).count();
        let n = lives.len().max(1) as f64;
        let p = beyond as f64 / n;
        HeelPressureExceedance {
            allowable_kpa,
            probability: p,
            standard_error: (p * (1.0 - p) / n).sqrt(),
            lives: beyond,
            exact_from_kpa: exact_from_pa / 1e3,
            largest_kpa: lives.iter().map(|l| l.max_heel_pressure_kpa).fold(0.0, f64::max),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::cell::Cell;

    thread_local! {
        /// The still waves [`settle_life`] ran on this thread.
        pub(super) static SETTLED: Cell<usize> = const { Cell::new(0) };
    }

    /// A life's largest rotation, settled once at its end, is that of running every wave the
    /// screen lets through (the bound off): on 16 lives of 8 years of the small design's site
    /// under small storms (H0's location 4 m), where a life's few simulated waves may all be
    /// still and its largest rotation a still wave's, every output of every life is the same but
    /// the counts, which move together, and [`settle_life`] runs waves.
    #[test]
    fn a_lifes_largest_rotation_settled_at_its_end_is_every_waves() {
        let text = include_str!("../../tests/data/small_design.toml")
            .replace("life_years = 5", "life_years = 8")
            .replace("lives = 12", "lives = 16")
            .replace("seed = 3", "seed = 9")
            .replace("storm_location_m = 7.5", "storm_location_m = 4.0");
        let sc =
            crate::scenario::Scenario::from_toml(&text, std::path::Path::new("small.toml"), std::path::Path::new("."))
                .unwrap();
        let d = sc.design.clone().unwrap();
        let st = sc.storm_case(true).unwrap();
        let run = |stick_bound: bool| {
            let st = StormCase { stick_bound, ..st };
            (0..d.lives).map(|i| simulate_life(&st, &d.life, d.seed, i).unwrap()).collect::<Vec<_>>()
        };
        SETTLED.with(|n| n.set(0));
        let with = run(true);
        let settled = SETTLED.with(Cell::get);
        let without = run(false);
        let (mut lives, mut answered) = (0, 0);
        for (a, b) in with.iter().zip(&without) {
            let moved = b.simulated_waves - a.simulated_waves;
            assert_eq!(a.screened_waves, b.screened_waves + moved, "the counts move together");
            // The largest heel pressure too where it reaches the screen's 500 kPa; below, the
            // still waves are not run for it (module docs, "Heel pressure").
            let heel = if b.max_heel_pressure_kpa >= 500.0 { b.max_heel_pressure_kpa } else { a.max_heel_pressure_kpa };
            assert!(a.max_heel_pressure_kpa <= b.max_heel_pressure_kpa);
            let same = StormOutcome { simulated_waves: b.simulated_waves, screened_waves: b.screened_waves, ..*a };
            assert_eq!(
                StormOutcome { max_heel_pressure_kpa: heel, ..same },
                StormOutcome { max_heel_pressure_kpa: heel, ..*b }
            );
            lives += 1;
            answered += moved;
        }
        eprintln!("{lives} lives compared, {answered} waves answered by the bound, {settled} run at the lives' ends");
        assert_eq!(lives, 16);
        assert!(answered > 0 && settled > 0, "{answered} answered, {settled} settled");
    }

    /// The design example's scenario.
    fn design_example() -> crate::scenario::Scenario {
        design_example_with(|t| t.to_string())
    }

    /// The design example's scenario with its text changed by `change`.
    fn design_example_with(change: impl Fn(&str) -> String) -> crate::scenario::Scenario {
        let text = change(include_str!("../../../../examples/design_breakwater.toml"));
        crate::scenario::Scenario::from_toml(&text, std::path::Path::new("design.toml"), std::path::Path::new("."))
            .expect("the design example")
    }

    /// What the screen reads of the dynamic model (T0, the rocking period, the lift-off factor)
    /// is the still-water model's to the bit at every water level and friction error, though the
    /// storm's model weighs less: 5 tides by 3 friction factors on the design example.
    #[test]
    fn the_screen_reads_the_still_water_modes() {
        let sc = design_example();
        let st = sc.storm_case(true).expect("a design");
        let still = ScreenModes::still_water(&st);
        let mut checked = 0;
        for tide_m in [-1.0, 0.0, 0.7, 1.5, 3.0] {
            for friction_factor in [0.7, 1.0, 1.3] {
                let s = StormInput {
                    h13_m: 5.0,
                    hmax_m: 9.0,
                    period_s: 11.0,
                    periods: WavePeriods::Significant,
                    waves: 1000,
                    tide_m,
                    angle_rad: 0.0,
                    force_factor: 1.0,
                    impact_factor: 1.0,
                    friction_factor,
                };
                let site = StormSite::new(&st, &s, still);
                let own = ScreenModes::of(site.dyn_model());
                let bits = |m: ScreenModes| [m.t0_s, m.t_moment_s, m.lift_factor].map(f64::to_bits);
                assert_eq!(bits(own), bits(still), "tide {tide_m} m, friction x {friction_factor}");
                let weighs_less = site.dyn_model().weight_n < st.structure.caisson.weight_in_water_n;
                assert_eq!(weighs_less, tide_m > 0.0, "tide {tide_m} m");
                checked += 1;
            }
        }
        assert_eq!(checked, 15);
    }

    /// The screen's grid leaves out the nodes the bound of the loads up to their height holds:
    /// the same grid as every node's loads, on the design example's site at 720 storms (heights
    /// from calm to past breaking at the wall, three periods, tides, angles and force errors),
    /// in most of which the bound leaves nodes out; under the seed's impact (`cuomo-2010`) and
    /// under `goda-takahashi` on a high mound with a berm (d = 11 m, B_M = 18 m: impulsive
    /// breaking waves).
    #[test]
    fn the_bisected_screen_grid_is_every_nodes_grid() {
        let cuomo = design_example_with(|t| t.replace("[waves]\n", "[waves]\nbreaking_load = \"cuomo-2010\"\n"));
        let high_mound = design_example_with(|t| {
            t.replace("[waves]\n", "[waves]\nbreaking_load = \"goda-takahashi\"\n")
                .replace("depth_at_wall_m = 16.5", "depth_at_wall_m = 11.0\nberm_width_m = 18.0")
        });
        let counts = |sc: &crate::scenario::Scenario| grid_counts(&sc.storm_case(true).expect("a design"));
        // Under cuomo-2010, 466 storms may slide, lift or press the heel to 500 kPa somewhere on
        // their grid; the bound leaves nodes out in 481. The lowest cell that may is the one
        // found cell by cell (above the first in each of the 466, on both grids).
        assert_eq!(counts(&cuomo), (720, 466, 481, 2 * 466));
        // On the high mound, 441 and 470.
        assert_eq!(counts(&high_mound), (720, 441, 470, 2 * 441));
    }

    /// The storms of the grid test on `st`, checked: (storms, storms that may slide somewhere,
    /// storms whose bound leaves nodes out, grids whose lowest sliding cell is above the first).
    fn grid_counts(st: &StormCase<'_>) -> (usize, usize, usize, usize) {
        let (mut storms, mut cut, mut sliding, mut lowest) = (0, 0, 0, 0);
        for h13 in [0.5, 1.5, 2.5, 3.5, 4.5, 5.5, 6.5, 8.0, 10.0, 12.0] {
            for period_s in [7.0, 10.0, 14.0] {
                for tide_m in [0.0, 1.5, 3.0] {
                    for (angle_rad, force_factor) in [(0.0, 1.0), (0.4, 0.8), (0.0, 1.3), (0.2, 1.0)] {
                        for periods in [WavePeriods::Significant, WavePeriods::LonguetHiggins { spectral_width: 0.4 }] {
                            let s = StormInput {
                                h13_m: h13,
                                hmax_m: 1.8 * h13,
                                period_s,
                                periods,
                                waves: 1000,
                                tide_m,
                                angle_rad,
                                force_factor,
                                impact_factor: force_factor,
                                friction_factor: 1.0,
                            };
                            let site = StormSite::new(st, &s, ScreenModes::still_water(st));
                            let t13 = (&site.model.at_period(period_s), site.bound(period_s));
                            let (a, b) = (
                                StormScreen::grid(st, &s, &site, t13, true),
                                StormScreen::grid(st, &s, &site, t13, false),
                            );
                            assert_eq!(a.node, b.node, "H1/3 {h13} m, T {period_s} s, tide {tide_m} m");
                            storms += 1;
                            sliding += usize::from(b.first_node.is_some());
                            for g in [&a, &b] {
                                assert_eq!(g.lowest_cell(), g.lowest_cell_by_cells());
                                lowest += usize::from(g.lowest_cell().is_some_and(|c| c > 0));
                            }
                            assert_eq!(b.bound_nodes, 0);
                            cut += usize::from(a.bound_nodes > 0);
                        }
                    }
                }
            }
        }
        (storms, sliding, cut, lowest)
    }

    /// A storm given the life's toe wave number (solved once for the shoaling and the loads)
    /// is the storm that solves for it itself, to the bit: 12 storms of the design example's site
    /// (three heights and periods, two tides, two force errors), 7 of them simulating waves.
    #[test]
    fn a_storm_given_the_toe_wave_number_is_the_storm_that_solves_for_it() {
        let sc = design_example();
        let st = sc.storm_case(true).expect("a design");
        let (mut storms, mut simulating) = (0, 0);
        for (h13, period_s) in [(3.0, 8.0), (6.0, 11.0), (9.0, 14.0)] {
            for tide_m in [0.0, 2.0] {
                for force_factor in [1.0, 1.3] {
                    let s = StormInput {
                        h13_m: h13,
                        hmax_m: 1.8 * h13,
                        period_s,
                        periods: WavePeriods::Significant,
                        waves: 300,
                        tide_m,
                        angle_rad: 0.0,
                        force_factor,
                        impact_factor: force_factor,
                        friction_factor: 1.0,
                    };
                    let k = wavenumber(period_s, toe_depth_m(&st, tide_m));
                    let run = |toe_k| {
                        let mut rng = realization_rng(7, storms);
                        let rng = &mut StormRng::Given(&mut rng);
                        storm_from(&st, &s, rng, StormStart::ALONE, toe_k, &mut StormScratch::default()).unwrap()
                    };
                    let (given, solved) = (run(Some(k)), run(None));
                    assert_eq!(format!("{given:?}"), format!("{solved:?}"), "H1/3 {h13} m, tide {tide_m} m");
                    storms += 1;
                    simulating += usize::from(solved.simulated_waves > 0);
                }
            }
        }
        assert_eq!(storms, 12);
        assert!(simulating >= 4, "{simulating} storms simulate waves");
    }

    #[test]
    fn extreme_value_quantiles_invert_their_distributions() {
        let w = StormDistribution::Weibull { scale_m: 1.5, shape: 1.4, location_m: 2.0 };
        let g = StormDistribution::Gumbel { location_m: 4.0, scale_m: 0.8 };
        for p in [0.01, 0.3, 0.5, 0.9, 0.99] {
            let h = w.quantile_m(p);
            assert!((1.0 - (-((h - 2.0) / 1.5f64).powf(1.4)).exp() - p).abs() < 1e-12);
            let h = g.quantile_m(p);
            assert!(((-(-(h - 4.0) / 0.8f64).exp()).exp() - p).abs() < 1e-12);
        }
    }

    /// 200 000 errors of COV 0.1: truncated at ±2σ the variance of z is
    /// 1 − 2k φ(k)/(2Φ(k) − 1) = 1 − 4 · 0.053991/0.954500 = 0.773741 (the doubly truncated
    /// normal), untruncated 1; the sample variance of (m − 1 − bias)/cov within 2 % of each (its
    /// standard error is about 0.3 %); truncated, none beyond 1 + bias ± 2 cov.
    #[test]
    fn error_variance_truncated_and_not() {
        let n = 200_000;
        let mut checked = 0;
        for (k, var_z) in [(Some(2.0), 0.773741), (None, 1.0)] {
            let m = ErrorModel { bias: -0.09, cov: 0.1, truncation_sigmas: k };
            let mut rng = crate::loads::generator::realization_rng(9, 2);
            let z: Vec<f64> = (0..n).map(|_| (m.draw(&mut rng) - 0.91) / 0.1).collect();
            let mean = z.iter().sum::<f64>() / n as f64;
            let var = z.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1) as f64;
            assert!((var / var_z - 1.0).abs() < 0.02, "k = {k:?}: variance {var}");
            assert!(mean.abs() < 5.0 / (n as f64).sqrt());
            assert_eq!(k.is_some(), z.iter().all(|v| v.abs() <= 2.0 + 1e-9));
            checked += 1;
        }
        assert_eq!(checked, 2);
    }

    /// The constructors' rules by hand: a truncated error of bias −0.09 reaches 1 − 0.09 − 2 · 0.455
    /// = 0 at COV 0.455 (refused, naming the COV), untruncated it is allowed; a Weibull of B = 7.5 m,
    /// A = 1.5 m, k = 1.4 is exceeded at 10 m (1 − F = exp(−(2.5/1.5)^1.4) = 0.106) but not at 90 m.
    #[test]
    fn constructors_refuse_what_cannot_be_drawn() {
        let e = ErrorModel::new(-0.09, 0.455, Some(2.0)).unwrap_err();
        assert_eq!((e.quantity, e.value), ("cov", 0.455));
        assert!(ErrorModel::new(-0.09, 0.45, Some(2.0)).is_ok() && ErrorModel::new(-0.09, 0.9, None).is_ok());
        let w = StormDistribution::Weibull { scale_m: 1.5, shape: 1.4, location_m: 7.5 };
        assert_eq!(
            w.peaks_over_threshold(3.0, 10.0),
            Ok(StormModel::PeaksOverThreshold { rate_per_year: 3.0, threshold_m: 10.0 })
        );
        assert!((1.0 - w.cdf(10.0) - (-(2.5f64 / 1.5).powf(1.4)).exp()).abs() < 1e-15);
        assert_eq!(w.peaks_over_threshold(3.0, 90.0).unwrap_err().quantity, "threshold_m");
    }

    /// Each constructor refuses a value outside its range by itself, naming the quantity: the
    /// ranges' ends are allowed (B = 0 m and k = 0.1 for a Weibull whose 10 000-year storm stays
    /// within [`MAX_STORM_HEIGHT_M`], 1000 years, 72 h, 20 m of tide), the values just beyond them
    /// are not.
    #[test]
    fn life_constructors_name_what_they_refuse() {
        let q = |r: Result<StormDistribution, ParamError>| r.unwrap_err().quantity;
        assert!(StormDistribution::weibull(1e-10, 0.1, 0.0).is_ok() && StormDistribution::gumbel(90.0, 1.0).is_ok());
        assert!(StormDistribution::weibull(80.0, 20.0, 0.0).is_ok());
        assert_eq!(q(StormDistribution::weibull(0.0, 1.4, 0.0)), "scale_m");
        assert_eq!(q(StormDistribution::weibull(1.5, 0.09, 0.0)), "shape");
        assert_eq!(q(StormDistribution::weibull(1.5, 1.4, -0.1)), "location_m");
        assert_eq!(q(StormDistribution::gumbel(0.0, 1.0)), "location_m");
        assert_eq!(q(StormDistribution::gumbel(4.0, f64::NAN)), "scale_m");
        let w = StormDistribution::weibull(1.5, 1.4, 2.0).unwrap();
        assert_eq!(w.peaks_over_threshold(0.0, 3.0).unwrap_err().quantity, "rate_per_year");
        assert_eq!(w.peaks_over_threshold(MAX_STORM_RATE_PER_YEAR * 1.01, 3.0).unwrap_err().quantity, "rate_per_year");
        assert_eq!(w.peaks_over_threshold(3.0, -0.1).unwrap_err().quantity, "threshold_m");
        for (bias, cov, k, quantity) in
            [(-0.91, 0.1, Some(2.0), "bias"), (0.0, 1.01, None, "cov"), (0.0, 0.1, Some(0.4), "truncation_sigmas")]
        {
            assert_eq!(ErrorModel::new(bias, cov, k).unwrap_err().quantity, quantity);
        }
        let life = LifeParams {
            life_years: 1000,
            storms: w,
            period_coefficient: 3.3,
            period_exponent: 0.63,
            storm_duration_s: 72.0 * 3600.0,
            tidal_range_m: 20.0,
            errors: Errors::default(),
            climate: Climate::default(),
        };
        assert_eq!(life.clone().checked(), Ok(life.clone()));
        let refused = |l: LifeParams| l.checked().unwrap_err().quantity;
        assert_eq!(refused(LifeParams { life_years: 1001, ..life.clone() }), "life_years");
        assert_eq!(refused(LifeParams { period_coefficient: 0.0, ..life.clone() }), "period_coefficient");
        assert_eq!(refused(LifeParams { period_exponent: 2.1, ..life.clone() }), "period_exponent");
        assert_eq!(refused(LifeParams { storm_duration_s: 72.0 * 3600.0 + 1.0, ..life.clone() }), "storm_duration_s");
        assert_eq!(refused(LifeParams { tidal_range_m: 20.5, ..life.clone() }), "tidal_range_m");
        let friction = ErrorModel { bias: 0.0, cov: 0.6, truncation_sigmas: Some(2.0) };
        assert_eq!(refused(LifeParams { errors: Errors { friction, ..Errors::default() }, ..life.clone() }), "cov");
        let storms = StormModel::PeaksOverThreshold { rate_per_year: 3.0, threshold_m: 90.0 };
        assert_eq!(
            refused(LifeParams { climate: Climate { storms, ..Climate::default() }, ..life.clone() }),
            "threshold_m"
        );
        let design = DesignParams {
            life,
            lives: 10,
            seed: 1,
            thresholds_m: DesignParams::thresholds_m(&[0.3, 0.05]).unwrap(),
            screen: true,
            failure_sliding_m: Some(1000.0),
            failure_rotation_rad: MAX_FAILURE_ROTATION_RAD,
            allowable_heel_pressure_pa: 500e3,
            failure_heel_pressure_pa: Some(1e7),
        };
        assert_eq!(design.thresholds_m, [0.03, 0.05, 0.1, 0.3, 1.0, 3.0]);
        assert_eq!(DesignParams::thresholds_m(&[0.2, -0.1]).unwrap_err().0, 1);
        assert_eq!(design.clone().checked(), Ok(design.clone()));
        let refused = |d: DesignParams| d.checked().unwrap_err().quantity;
        assert_eq!(refused(DesignParams { lives: 0, ..design.clone() }), "lives");
        assert_eq!(refused(DesignParams { thresholds_m: vec![0.3, 0.1], ..design.clone() }), "thresholds_m");
        assert_eq!(refused(DesignParams { failure_sliding_m: Some(0.0), ..design.clone() }), "failure_sliding_m");
        assert_eq!(refused(DesignParams { failure_rotation_rad: 0.11, ..design.clone() }), "failure_rotation_rad");
        assert_eq!(
            refused(DesignParams { allowable_heel_pressure_pa: 1e4, ..design.clone() }),
            "allowable_heel_pressure_pa"
        );
        assert_eq!(
            refused(DesignParams { failure_heel_pressure_pa: Some(1.1e7), ..design.clone() }),
            "failure_heel_pressure_pa"
        );
        assert_eq!(
            refused(DesignParams { life: LifeParams { life_years: 0, ..design.life.clone() }, ..design }),
            "life_years"
        );
    }

    /// Limit 1 m; lives |S| 0.1, 0.5 (failed by rotation), 3 (failed by sliding), 0.2: the
    /// capped values 0.1, 1, 1, 0.2 (mean 0.575); above 2 m only the failed lives exceed.
    #[test]
    fn capped_statistics_of_a_sample_by_hand() {
        let s = capped_statistics(&[0.1, 0.5, 3.0, 0.2], &[false, true, true, false], 1.0, &[0.15, 0.5, 2.0]);
        assert!((s.mean_m - 0.575).abs() < 1e-15);
        assert_eq!(s.percentiles_m[1], (50.0, 0.2));
        assert_eq!(s.percentiles_m[3], (99.0, 1.0));
        assert_eq!(s.exceedance, vec![(0.15, 0.75), (0.5, 0.5), (2.0, 0.5)]);
    }

    #[test]
    fn statistics_of_a_sample() {
        let s = life_statistics(&[0.0, 0.1, 0.2, 0.5, 2.0], &[0.1, 1.0]);
        assert!((s.mean_m - 0.56).abs() < 1e-12);
        assert_eq!(s.percentiles_m[1], (50.0, 0.2));
        assert_eq!(s.exceedance, vec![(0.1, 0.6), (1.0, 0.2)]);
    }
}
