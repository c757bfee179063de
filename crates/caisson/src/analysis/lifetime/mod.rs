//! Performance-based design: the sliding of a caisson over its service life by Monte Carlo, with
//! the dynamic model for every wave that can slide it (Shimosako & Takahashi 1999; Goda & Takagi
//! 2000; docs/model.md §6.4), and the storms of a fragility analysis (docs/model.md §7).
//!
//! **The files**:
//!
//! - `params.rs`: the inputs, each checked where it is built: [`StormDistribution`],
//!   [`ErrorModel`] and [`Errors`], [`LifeParams`], [`StormCase`] (what the storms act on),
//!   [`FailureLimits`], [`WaveDraws`], [`StormInput`] (one storm at the structure),
//!   [`DesignParams`];
//! - `life.rs`: [`simulate_life`] (steps 1-4 below, storm by storm), `settle_life` (the still and
//!   deferred waves at the life's end), [`run_lives`] (lives in parallel);
//! - `storm.rs`: [`simulate_storm`] and `storm_from`: the storm's site at its water level
//!   (`StormSite`), its random stream (`StormRng`), the drawing of its waves
//!   (`draw_above_threshold`), what a life's storms reuse (`StormScratch`);
//! - `screen.rs`: the screen's effective-load tests (`may_slide`, `heel_bound_pa`,
//!   [`PSI_IMPULSE`]) and its per-storm grid over heights and periods (`StormScreen`);
//! - `wave.rs`: one wave through both models (`WaveRun`): its loads, the screen's and the stick
//!   bound's decisions, its run and what it records ([`base_heel_pressure_pa`]);
//! - `outcome.rs`: [`StormOutcome`], whose fields are the columns of `lives.csv` and of the
//!   checkpoint lines ([`LIFE_COLUMNS`]);
//! - `sampling.rs`: [`sampling`], the stratified sampling of a design run's lives by the
//!   severity of their storms;
//! - `statistics.rs`: [`capped_statistics`], [`LifeCounts`], [`ImpulsiveShare`],
//!   [`HeelPressureExceedance`];
//! - `tests.rs`: the unit tests of the private parts (the equivalences of the fast paths against
//!   the plain path are `tests/equiv_lifetime.rs`).
//!
//! A design run is assembled from a scenario by [`crate::drive::design::Designer`]. What the
//! fast paths below measured on the examples when they were introduced is in docs/history.md.
//!
//! **One life** (`life_years` years of storms, one per year by default, docs/model.md §6.4 steps
//! 1-7; the other climates of [`crate::analysis::climate`] change the steps as its docs say):
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
//!    ρ_w h'² l ([`crate::analysis::rigid`]), is that of the storm's base depth h' + ζ;
//! 4. H1/3 and H_max at the structure by Goda's surf-zone formulas at the toe depth
//!    ([`crate::waves::surf_zone`]), times the transformation error;
//! 5. N Rayleigh heights of that H1/3, each limited to H_max (Goda's random-wave breaking), each
//!    with a rise time from the seed's log-normal model, each at T1/3 or at a period of its own
//!    given its height ("Wave periods" below);
//! 6. per wave: the loads of [`crate::loads::model::WaveLoadModel`] (regime by the breaking
//!    criterion; the impulsive peak of a breaking wave by `[waves] breaking_load`) times the
//!    wave-force error; friction coefficients times the friction error; the wave is run through the
//!    dynamic model from rest (static equilibrium) and its permanent sliding added; the rigid block
//!    (Shimosako model, [`crate::analysis::rigid::RigidBlock`]) beside it.
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
//! resistance (`tests/equiv_lifetime.rs` holds a full run and the screened one together only with
//! this condition). M_eff is the moment about the base centre amplified like the forces, its
//! pulsating part with the longer of T0 and the rocking period T_θ = 2π (m_θ/K_θ)^½ (K_θ = Σ k_y
//! x_i²) in Ψ. f is the lift-off factor of the springs ([`Model::lift_off_factor`]): n equal
//! springs at x_i carry N_i = V/n + M x_i/Σx_j² statically, so the outermost one lifts at (6 M/B) ·
//! n/(n + 1) = V (f = 10/11 for the 10 springs of the seed; f = 1 would be the continuous linear
//! base pressure, 6 M/B = V). The test is made per storm on a grid of 64 heights from 0 to H_max
//! plus the breaker height at the wall; a wave whose grid cell or a neighbouring cell can slide has
//! its own loads computed, and is simulated if they pass the test (else it is screened too). The
//! grid is skipped (every node false) in a storm where upper bounds of the loads over all heights
//! up to H_max pass neither test ([`crate::loads::model::PeriodLoads::peak_bound`]: Goda's loads
//! grow with the height, the impulsive peak of each breaking-wave load is bounded too, Eq. 30's
//! impact by its value at the reduction 1, Goda's force with Takahashi's α* term by term, and there
//! is none below the breaker height at the wall); in the other storms the nodes up to the highest
//! node height where those bounds up to it pass neither test (found by bisection) are false without
//! their loads, the same grid as every node's loads
//! (`tests::the_bisected_screen_grid_is_every_nodes_grid`; off by [`StormCase::screen_load_bound`]). The friction used is the smaller of μ_s
//! and the rigid block's μ, so a screened wave slides neither model. The share of waves screened is
//! reported; `screen = false` (`[design] screen`, or the policy's `Accel::screen` off:
//! [`StormCase::screen`]) runs every wave (on the same waves, [`WaveDraws::EveryWave`], the
//! screened run gives the same totals to 1 µm per life, `tests/equiv_lifetime.rs`).
//!
//! **The stick bound**. The static test lets through many waves that then neither slide nor lift
//! (its amplifications are bounds for any load shape). A wave that passes it is then tested on
//! the all-sticking response itself ([`crate::analysis::stick_bound`]: for a pulsating wave the
//! exact steady state of its crest and trough plus the modes' envelopes of the free vibration, at
//! every instant of the wave; for an impulsive one the system's peak-to-peak gains times the
//! largest magnitude and rate of each load component): if that leaves the outer springs 5 % of
//! their normal force at rest and the friction demand within 95 % of μ_s, no spring slips or
//! lifts, the wave's sliding is exactly 0 and it is not run ([`StormCase::stick_bound`]). An
//! impulsive wave so answered still counts as impulsive ("Impulsive waves" below; its sliding is
//! 0); settled, it runs as a still wave and is not counted again.
//!
//! Only such a still wave's rotation θ_w is not known; its bound b_w is above the engine's rotation
//! on every answered wave measured (docs/history.md), and `ROTATION_RESERVE` r = 1.01 is a margin
//! for a bound below it (θ_w ≤ r b_w); a wave is answered only if r b_w is below the rotation
//! limit. The largest rotation may be a still wave's, so the waves whose r b_w exceeds the largest
//! rotation known are kept on a list and **settled**: run after all, largest bound first, until the
//! next one's r b_w is at most the largest rotation so far. At a life's end each kept wave's bound
//! is first **sharpened**, lazily, when it is the largest left: b_w is replaced by the smaller
//! bound of the all-sticking response under the wave's own load history
//! ([`crate::analysis::stick_bound::StickBound::rotation_under_history_rad`], within 0.5 % of the
//! linear response's largest |θ|, where the impulsive bound is 1.1-1.5 times it), and the wave
//! with the largest sharpened bound, once that is at least every bound not yet sharpened (a
//! sharpened bound is at most its wave's bound), is the next to run or to stop at
//! (`settle_life`'s `Settler::still_waves`). On the 10 m deep study site this runs 3 247 still
//! waves in 1000 lives where the coarse bounds ran about 40 100 (BENCHMARKS.md). When depends on
//! who reads it:
//! - a storm alone ([`simulate_storm`]: fragility reads every storm's largest rotation) settles at
//!   the storm's end;
//! - a life ([`simulate_life`]: the design and sizing runs and the climates read only the life's
//!   largest rotation: `lives.csv`, the JSON reports, the plots) settles once, at the life's end,
//!   the still waves of all its storms (each kept with its storm's index; the storm's site is
//!   rebuilt to run it). After each storm the list keeps only the waves whose r b_w exceeds the
//!   life's largest rotation so far; should it hold more than `MAX_STILL_WAVES` (4096), it is
//!   settled then (which empties it).
//!
//! Why the settled largest rotation M is what running every wave gives, M*, to the bit: M is the
//! largest rotation of the waves run, so M ≤ M*. A still wave not run was dropped or left when r
//! b_w was at most the largest rotation known then, which is at most M (it only grows): θ_w ≤ r b_w
//! ≤ M. So no wave's rotation exceeds M, M = M*, and a maximum of the same numbers does not depend
//! on their order. **Failure** (below) is not moved either: a still wave's θ_w ≤ r b_w is below the
//! rotation limit (and [`ROCKING_LIMIT_RAD`]), and it neither slides nor lifts, so it cannot fail a
//! life, count as rocking or large-rotation, or move the sliding and the excursions; whether and at
//! which wave a life fails is decided by the waves run, as when every wave runs, and settling at
//! the life's end moves only `max_rotation_rad` (to M*) and the counts (a wave run moves from the
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
//! waves that can pass the screen ([`WaveDraws::AboveThreshold`], the default). With h_t the lower
//! edge of the lowest grid cell that may slide and q = P(H > h_t) = exp[−2 (h_t/H1/3)²] (the
//! Rayleigh exceedance of [`crate::waves::statistics`]), the number of the storm's N waves above
//! h_t is K ~ Binomial(N, q), and those K heights are independent Rayleigh heights truncated below
//! at h_t, H = √(h_t² − ½ H1/3² ln U) by the inverse CDF. They are drawn as the descending order
//! statistics of the N heights ([`DescendingRayleigh`]): the largest first, each from one uniform,
//! until the first one below h_t — which gives K and the truncated heights together, and the same
//! k-th largest wave whatever h_t is. Each drawn wave takes a rise-time deviate and a uniform place
//! in the storm; the waves run in the order of their places (the order of an i.i.d. sequence), each
//! limited to H_max and tested as before, against its cell (the flags need not be monotone in the
//! height) and then by its own loads. The screened count stays N − simulated. Every per-life output
//! has the distribution it had when all N waves were drawn and tested ([`WaveDraws::EveryWave`]);
//! the numbers differ within sampling noise (`tests/equiv_lifetime.rs` holds the design example's
//! statistics of both drawings within a few standard errors).
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
//! **Heel pressure** ([`StormOutcome::max_heel_pressure_kpa`],
//! [`base_heel_pressure_pa`]). At every step of a wave run through the
//! dynamic model, the heel (shoreward edge) value of the linear base pressure without tension that
//! carries the springs' normal forces: with V = Σ N_i (per metre, / l) and the resultant t_e = B/2
//! − Σ x_i N_i / Σ N_i from the heel, Goda's (2000) p_e = 2V/(3 t_e) for t_e ≤ B/3 (part of the
//! base unloaded) and (2V/B)(2 − 3 t_e/B) above ([`crate::loads::safety::heel_pressure_pa`]): under
//! a static load it is Goda's heel pressure of the static check (`tests/verify_heel_pressure.rs`).
//! The spring dashpots are left out (the soil's elastic reaction). A life's value is the largest
//! over its waves run and the caisson at rest at still water (W'/(B l)). The rigid block has no
//! foundation pressure: it has none.
//!
//! The screen would miss a wave that cannot slide or lift the caisson yet presses its heel: its
//! bound of the heel pressure is p_e with the screen's amplified moment M_eff and the springs'
//! normal force at either end of W' − U_eff to W' + (Ψ − 1) U (for a fixed moment p_e is largest at
//! an end of an interval of normal forces), the amplifications' argument being the screen's. The
//! screen lets through every wave whose bound reaches [`StormCase::heel_screen_pa`] (the allowable
//! heel pressure, or the failure heel pressure if lower). A wave let through for that alone runs
//! for its heel pressure only (its sliding, rotation and lift are not read: every other output is
//! that of the screen without it, `tests/equiv_lifetime.rs`), and only if its bound exceeds the
//! largest heel pressure known: at the life's end (with the still waves,
//! [`settle_life`](life::settle_life); a storm alone at its end), largest bound first, until the
//! next bound is at most the life's largest, unless it may fail the life by heel pressure (then in
//! its place). At a life's end the bounds are sharpened as the still waves' are, where
//! the stick bound shows the wave neither slips nor lifts a spring: to the all-sticking response's
//! heel pressure under the wave's own load history
//! ([`crate::analysis::stick_bound::StickBound::heel_under_history_pa`]), its rise over the rest
//! times `HEEL_RESERVE` (1.01; the engine's rise measured at most 1.0005 times the bound's). The same holds for a still wave whose bound reaches it. So a life's largest heel
//! pressure is exact wherever it is at or above the screen's heel pressure, and P(q_heel > q_a)
//! with it; below, it is the largest of the waves run (a lower bound).
//!
//! **Random numbers**: one ChaCha8 stream per life (seed, stream = life index); per storm in
//! order: U for H0, four truncated normals for the errors, U for the tide phase (and, only for
//! the climates that need them, the draws [`crate::analysis::climate`] lists). The waves of
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

mod life;
mod outcome;
mod params;
pub mod sampling;
mod screen;
mod statistics;
mod storm;
mod wave;

pub use life::{run_lives, simulate_life, LifeFailed};
pub use outcome::{LifeColumn, StormOutcome, LIFE_COLUMNS};
pub use params::{
    auto_boundaries, failure_rotation_rad, AutoLives, AutoPrecision, DesignParams, ErrorModel, ErrorScope, Errors,
    FailureLimits, LifeParams, Sampling, StormCase, StormDistribution, StormInput, WaveDraws, AUTO_BATCH_LIVES,
    DEFAULT_AUTO_MAX_LIVES, DEFAULT_TARGET_RELATIVE_ERROR, FAILURE_PROBABILITY_FLOOR, MAX_FAILURE_ROTATION_RAD,
    MAX_LIFE_YEARS, MAX_LIVES, MAX_STORM_HEIGHT_M, MAX_TARGET_RELATIVE_ERROR, STANDARD_THRESHOLDS_M,
    STORM_WAVE_WORDS_LOG2,
};
pub use screen::PSI_IMPULSE;
pub use statistics::{
    capped_statistics, life_statistics, HeelPressureExceedance, ImpulsiveShare, LifeCounts, LifeStatistics,
};
pub use storm::{simulate_storm, StormError};
pub use wave::base_heel_pressure_pa;

/// The allowable heel pressure on a rubble mound of a design (`[design]
/// allowable_heel_pressure_kpa`), as Goda's check has it ([`DEFAULT_ALLOWABLE_HEEL_PRESSURE_PA`]
/// of [`crate::analysis::conventional`]).
pub use crate::analysis::conventional::DEFAULT_ALLOWABLE_HEEL_PRESSURE_PA;

#[cfg(test)]
mod tests;
