//! The wave-load model of one site: every pressure model evaluated for a wave, and the wave
//! trains built from per-wave records (seed §4; docs/model.md §1-§6.1).
//!
//! For a wave of incident height H and period T at a site (toe depth h_s, wall depth d, base depth
//! h', crest freeboard h_c, base width B, seabed slope, berm width):
//!
//! 1. H is limited at the toe by Miche, H_toe = min(H, H_b,Miche(h_s)) (seed §4.2.1).
//! 2. Regime: breaking criterion at the wall, or forced ([`super::regime`]).
//! 3. Goda ([`super::goda`]) with H_D = H_toe, L at h_s, h_b = h_s + 5 H_toe tan θ: the
//!    pulsating load F_qs+ with α* = α2, and Goda's static check, with Takahashi's
//!    α* = max(α2, α_I) if a berm width is given.
//! 4. Sainflou (F_qs−, [`super::sainflou`]) at h = h_s (default) or h = d.
//! 5. Impact (F_x,max, F_y,max, [`super::impact`]) with d_b and H_br from the breaking criterion.
//! 6. The impulsive peak of a breaking wave by the rule of `breaking_load`
//!    ([`super::breaking_load`]: the impact of step 5, Goda's force with Takahashi's α*, or none),
//!    F* = F_x,peak / P(α2) and the rise-time distribution ([`super::risetime`]).
//!
//! [`WaveLoadModel::evaluate`] returns all of it per metre ([`WaveLoads`]). The histories take
//! per-wave [`WaveRecord`]s (H, T, regime, t_r): [`WaveLoadModel::train`] turns a list of records
//! into a [`WaveTrain`] (totals: per-metre values × the alongshore length), one wave after the
//! other. [`WaveLoadModel::regular_records`] makes the records of N regular waves with rise times
//! drawn from the seeded generator, one standard-normal draw per wave (so wave j always uses the
//! j-th draw whatever the regime of the others).
//!
//! The waves of one period share its work ([`WaveLoadModel::at_period`]); a storm's wave takes
//! its event from [`PeriodLoads::event`], which computes only what the event holds (Sainflou's
//! trough, not its crest; the impact and the rise time of a breaking wave only), the same numbers
//! as [`WaveLoadModel::event`] of the wave's full loads.

use super::breaking_load::{BreakingLoad, ImpulsivePeak};
use super::goda::{GodaInput, GodaPeriod, GodaResult};
use super::history::{LoadComponent, TrainError, WaveEvent, WaveTrain};
use super::impact::{ImpactInput, ImpactPeriod, ImpactResult};
use super::regime::{decide_with_limit, Regime, RegimeChoice, RegimeDecision, RegimeError};
use super::risetime::{LoadRng, RiseTimeDistribution, RiseTimeParams};
use super::safety::{safety_factors, SafetyFactors, SafetyInput};
use super::sainflou::{SainflouInput, SainflouPeriod, SainflouResult, SainflouTrough};
use super::shapes::{Impulse, LoadShape};
use super::WaveForce;
use crate::check::{interval, rule};
use crate::waves::breaking::{miche_breaker_height_from_wavenumber_m, miche_breaker_height_m, BreakerCriterion};
use crate::waves::dispersion::{deep_water_wavelength_m, wavelength_m, wavenumber};
use crate::ParamError;
use rand::Rng;
use rand_distr::StandardNormal;
use std::cell::OnceCell;
use std::f64::consts::PI;
use thiserror::Error;

/// Which depth the Sainflou standing wave forms in (docs/model.md §10 item 21).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum SainflouDepth {
    /// h = h_s, the toe depth (default; the depth Goda uses).
    Toe,
    /// h = d, the depth in front of the wall.
    Wall,
}

/// The site and the caisson as the wave loads see them (SI).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct WaveSite {
    /// ρ_w, kg/m³.
    pub rho_w: f64,
    /// h_s, depth at the toe of the mound, m.
    pub depth_at_toe_m: f64,
    /// d, depth in front of the wall (above the berm), m.
    pub depth_at_wall_m: f64,
    /// h', depth of the caisson base, m.
    pub base_depth_m: f64,
    /// h_c, crest freeboard (caisson height − base depth), m.
    pub crest_freeboard_m: f64,
    /// B, base width, m.
    pub width_m: f64,
    /// Alongshore length, m (per-metre loads × this = totals).
    pub length_m: f64,
    /// tan θ of the seabed seaward of the structure.
    pub seabed_slope: f64,
    /// B_M, berm width, m: Takahashi's α_I in Goda's static check, and in the breaking-wave peak
    /// of `goda-takahashi` (B_M = 0 there without it).
    pub berm_width_m: Option<f64>,
}

/// The smallest water depth and wave height accepted, m: a millimetre, below any laboratory
/// flume's waves; smaller values (5e-324 m) only drive the formulas to NaN or give safety
/// factors of 1e100.
pub const MIN_LENGTH_M: f64 = 1e-3;
/// The shortest wave period accepted, s (capillary ripples are shorter; no wave that loads a
/// caisson is).
pub const MIN_PERIOD_S: f64 = 0.01;

/// Why a wave site, its load options or its trains were refused: one quantity out of its range
/// ([`ParamError`], named as in its type), or a rule between quantities, with their values (SI).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum WaveParamError {
    #[error(transparent)]
    Param(#[from] ParamError),
    /// d outside [[`MIN_LENGTH_M`], h_s]: the berm cannot be below the seabed.
    #[error(
        "depth_at_wall_m = {depth_at_wall_m}: must be from {MIN_LENGTH_M} m to depth_at_toe_m = {depth_at_toe_m} m"
    )]
    WallDepth { depth_at_wall_m: f64, depth_at_toe_m: f64 },
    /// h' < d: the caisson base above the water depth in front of the wall.
    #[error("base_depth_m = {base_depth_m}: must be at least depth_at_wall_m = {depth_at_wall_m} m")]
    BaseAboveWall { base_depth_m: f64, depth_at_wall_m: f64 },
    /// h' > h_s: the caisson base below the seabed at the toe.
    #[error("base_depth_m = {base_depth_m}: must be at most depth_at_toe_m = {depth_at_toe_m} m")]
    BaseBelowToe { base_depth_m: f64, depth_at_toe_m: f64 },
    /// More than [`super::generator::MAX_TRAIN_WAVES`] waves in all the realizations together.
    #[error("{waves} waves × {realizations} realizations: at most {} waves in all", super::generator::MAX_TRAIN_WAVES)]
    TooManyWaves { waves: usize, realizations: usize },
    /// A forced regime that contradicts the breaking criterion for the train's height.
    #[error(transparent)]
    Regime(#[from] RegimeError),
}

impl WaveSite {
    /// The site if every quantity is in range (SI): ρ_w from 500 to 2000 kg/m³; h_s from
    /// [`MIN_LENGTH_M`] to 10 km; d from [`MIN_LENGTH_M`] to h_s; the base depth h' from d to
    /// h_s (the base sits on or in the mound, not below the seabed); tan θ from 0 to 0.5; a berm
    /// width from 0 to 10 km. The caisson's own dimensions are its type's ([`crate::structure`]).
    pub fn checked(self) -> Result<Self, WaveParamError> {
        interval("rho_w", self.rho_w, 500.0, 2000.0, false)?;
        let hs = interval("depth_at_toe_m", self.depth_at_toe_m, MIN_LENGTH_M, 1e4, false)?;
        let d = self.depth_at_wall_m;
        if !(d.is_finite() && d >= MIN_LENGTH_M && d <= hs) {
            return Err(WaveParamError::WallDepth { depth_at_wall_m: d, depth_at_toe_m: hs });
        }
        let hp = self.base_depth_m;
        if hp < d {
            return Err(WaveParamError::BaseAboveWall { base_depth_m: hp, depth_at_wall_m: d });
        }
        if hp > hs {
            return Err(WaveParamError::BaseBelowToe { base_depth_m: hp, depth_at_toe_m: hs });
        }
        interval("seabed_slope", self.seabed_slope, 0.0, 0.5, false)?;
        if let Some(b) = self.berm_width_m {
            interval("berm_width_m", b, 0.0, 1e4, false)?;
        }
        Ok(self)
    }
}

/// Model options (defaults as in the seed / docs/model.md).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct WaveLoadOptions {
    pub regime: RegimeChoice,
    /// The rule of a breaking wave's impulsive peak ([`super::breaking_load`]; default the
    /// seed's, `cuomo-2010`: a scenario takes its profile's).
    pub breaking_load: BreakingLoad,
    /// Breaking criterion for d_b, H_br and the regime (default Miche).
    pub criterion: BreakerCriterion,
    /// α_max of Eq. 30 (default 1/1.8, regular waves).
    pub alpha_max: f64,
    /// a_imp of Eq. 30 (default 1).
    pub a_imp: f64,
    /// α_qs in Eq. 29 (default 0.8).
    pub alpha_qs_nonbreaking: f64,
    /// α_qs in Eq. 31 (default 1.0).
    pub alpha_qs_breaking: f64,
    pub rise_time: RiseTimeParams,
    /// Time shape of breaking waves (default Eq. 31).
    pub load_shape: LoadShape,
    /// t_d / t_r for the shapes that use t_d (default 2).
    pub duration_ratio: f64,
    pub sainflou_depth: SainflouDepth,
    /// β, wave angle to the normal, rad (Goda only; 15° rule applied there).
    pub angle_rad: f64,
    /// Goda's λ1, λ2, λ3.
    pub lambda: [f64; 3],
}

impl Default for WaveLoadOptions {
    fn default() -> Self {
        WaveLoadOptions {
            regime: RegimeChoice::Auto,
            breaking_load: BreakingLoad::Cuomo2010,
            criterion: BreakerCriterion::Miche,
            alpha_max: 1.0 / 1.8,
            a_imp: 1.0,
            alpha_qs_nonbreaking: 0.8,
            alpha_qs_breaking: 1.0,
            rise_time: RiseTimeParams::default(),
            load_shape: LoadShape::Seed,
            duration_ratio: 2.0,
            sainflou_depth: SainflouDepth::Toe,
            angle_rad: 0.0,
            lambda: [1.0; 3],
        }
    }
}

impl WaveLoadOptions {
    /// The options with the wave angle β given in degrees: a finite number strictly between −90
    /// and 90 (from the normal to the breakwater).
    pub fn with_angle_deg(mut self, angle_deg: f64) -> Result<Self, ParamError> {
        if !(angle_deg.is_finite() && angle_deg.abs() < 90.0) {
            return Err(rule(
                "angle_deg",
                angle_deg,
                "must be a finite number strictly between -90 and 90 (degrees from the normal to the breakwater)",
            ));
        }
        self.angle_rad = angle_deg.to_radians();
        Ok(self)
    }

    /// The options if every coefficient is in range: α_max in (0, 10], a_imp in [0, 10], both
    /// α_qs in [0, 2], t_d/t_r in (1, 20], |β| below 90°.
    pub fn checked(self) -> Result<Self, ParamError> {
        interval("alpha_max", self.alpha_max, 0.0, 10.0, true)?;
        interval("a_imp", self.a_imp, 0.0, 10.0, false)?;
        interval("alpha_qs_nonbreaking", self.alpha_qs_nonbreaking, 0.0, 2.0, false)?;
        interval("alpha_qs_breaking", self.alpha_qs_breaking, 0.0, 2.0, false)?;
        interval("duration_ratio", self.duration_ratio, 1.0, 20.0, true)?;
        if !(self.angle_rad.is_finite() && self.angle_rad.abs() < 0.5 * PI) {
            return Err(rule("angle_rad", self.angle_rad, "must be a finite number strictly between -π/2 and π/2"));
        }
        Ok(self)
    }
}

/// Everything about one wave, per metre of breakwater (SI).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct WaveLoads {
    /// Incident height, m.
    pub height_incident_m: f64,
    /// Height at the toe after the Miche limit, m.
    pub height_m: f64,
    /// Miche breaker height at the toe depth, m.
    pub toe_breaker_height_m: f64,
    /// True if the incident height was limited at the toe.
    pub limited_at_toe: bool,
    pub period_s: f64,
    /// L at the toe depth, m.
    pub toe_wavelength_m: f64,
    /// L0, m.
    pub deep_water_wavelength_m: f64,
    /// h_b = h_s + 5 H tan θ, m.
    pub depth_5h_seaward_m: f64,
    /// Depth used for Sainflou, m.
    pub sainflou_depth_m: f64,
    pub regime: RegimeDecision,
    /// Goda's formula as its static check takes it: α* = max(α2, α_I) with a berm width, else α2.
    pub goda: GodaResult,
    /// The pulsating load F_qs+ of the dynamic model: Goda with α* = α2 (= `goda` without a berm).
    pub pulsating: GodaResult,
    pub sainflou: SainflouResult,
    /// The impact of seed Eq. 30 and 32 (the peak of `cuomo-2010`; evaluated under every rule).
    pub impact: ImpactResult,
    /// Goda with the α* = max(α2, α_I) of `goda-takahashi` (B_M = 0 without a berm width): the
    /// peak of that rule, `None` under the others.
    pub impulsive_goda: Option<GodaResult>,
    /// The impulsive peak of the rule (zero under `none`), whether the wave breaks or not.
    pub peak: ImpulsivePeak,
    /// F* = F_x,peak / P(α2).
    pub f_star: f64,
    /// Rise-time distribution; `None` if non-impulsive (F* ≤ 1).
    pub rise_time: Option<RiseTimeDistribution>,
}

/// One wave of a train, as the campaign generator describes it.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct WaveRecord {
    /// Incident height H, m.
    pub height_m: f64,
    /// Period T, s.
    pub period_s: f64,
    pub regime: Regime,
    /// Rise time t_r, s. `None`: the median of the rise-time model. Ignored for a non-breaking or
    /// non-impulsive wave.
    pub rise_time_s: Option<f64>,
}

/// Errors of the model (bad records).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum WaveLoadError {
    #[error("wave {index}: {source}")]
    Regime { index: usize, source: RegimeError },
    #[error("wave {index}: {what} = {value} must be a finite number > 0")]
    BadWave { index: usize, what: &'static str, value: f64 },
    #[error(transparent)]
    Train(#[from] TrainError),
}

/// A site with its options: evaluates loads and builds histories.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct WaveLoadModel {
    pub site: WaveSite,
    pub options: WaveLoadOptions,
}

impl WaveLoadModel {
    /// All loads for a wave of incident height `height_m` and period `period_s`, with the regime
    /// chosen by the model options (error if a forced regime contradicts the criterion).
    pub fn evaluate(&self, height_m: f64, period_s: f64) -> Result<WaveLoads, RegimeError> {
        self.evaluate_with(height_m, period_s, self.options.regime)
    }

    /// H_br: the breaker height at the wall depth d by the model's criterion, m.
    pub fn breaker_height_at_wall_m(&self, period_s: f64) -> f64 {
        match self.options.criterion {
            BreakerCriterion::Miche => miche_breaker_height_m(self.site.depth_at_wall_m, period_s),
            c => c.breaker_height_m(self.site.depth_at_wall_m, period_s),
        }
    }

    /// The Miche breaker height at the toe depth h_s (the limit of the incident height), m.
    pub fn toe_breaker_height_m(&self, period_s: f64) -> f64 {
        miche_breaker_height_from_wavenumber_m(wavenumber(period_s, self.site.depth_at_toe_m), period_s)
    }

    /// As [`Self::evaluate`] with an explicit regime choice.
    pub fn evaluate_with(&self, height_m: f64, period_s: f64, choice: RegimeChoice) -> Result<WaveLoads, RegimeError> {
        self.at_period(period_s).evaluate_with(height_m, choice)
    }

    /// The model at one period: what does not depend on the height (the dispersion solves, the
    /// breaker heights, the height-free parts of Goda, Sainflou and the impact) computed once
    /// (Sainflou's and the impact's when a height first needs them), for many heights of one
    /// period (the waves of a storm).
    pub fn at_period(&self, period_s: f64) -> PeriodLoads<'_> {
        self.at_period_with_toe_wavenumber(period_s, wavenumber(period_s, self.site.depth_at_toe_m))
    }

    /// [`Self::at_period`] with the wave number at the toe depth h_s given (rad/m; the same numbers
    /// when it is [`wavenumber`]`(period_s, h_s)`: a caller that needs it too, for the storm's
    /// shoaling, solves the dispersion relation once).
    pub fn at_period_with_toe_wavenumber(&self, period_s: f64, k_toe: f64) -> PeriodLoads<'_> {
        let s = &self.site;
        let o = &self.options;
        // Two dispersion solves: at the toe (L, Miche limit; given) and at the wall (Miche H_br).
        let l_toe = 2.0 * PI / k_toe;
        let hb_toe = miche_breaker_height_from_wavenumber_m(k_toe, period_s);
        let hbr = self.breaker_height_at_wall_m(period_s);
        let goda = GodaPeriod::new(&GodaInput {
            height_m: f64::NAN,
            wavelength_m: l_toe,
            depth_m: s.depth_at_toe_m,
            depth_5h_seaward_m: f64::NAN,
            wall_depth_m: s.depth_at_wall_m,
            base_depth_m: s.base_depth_m,
            crest_freeboard_m: s.crest_freeboard_m,
            width_m: s.width_m,
            angle_rad: o.angle_rad,
            berm_width_m: s.berm_width_m,
            lambda: o.lambda,
            rho_w: s.rho_w,
        });
        let (sf_depth, sf_l) = match o.sainflou_depth {
            SainflouDepth::Toe => (s.depth_at_toe_m, l_toe),
            SainflouDepth::Wall => (s.depth_at_wall_m, wavelength_m(period_s, s.depth_at_wall_m)),
        };
        let sainflou_input = SainflouInput {
            height_m: f64::NAN,
            wavelength_m: sf_l,
            depth_m: sf_depth,
            base_depth_m: s.base_depth_m,
            crest_freeboard_m: s.crest_freeboard_m,
            width_m: s.width_m,
            rho_w: s.rho_w,
        };
        let impact_input = ImpactInput {
            height_m: f64::NAN,
            period_s,
            toe_wavelength_m: l_toe,
            wall_depth_m: s.depth_at_wall_m,
            base_depth_m: s.base_depth_m,
            crest_freeboard_m: s.crest_freeboard_m,
            width_m: s.width_m,
            criterion: o.criterion,
            alpha_max: o.alpha_max,
            a_imp: o.a_imp,
            rho_w: s.rho_w,
        };
        let alpha_i1_rule = match o.breaking_load {
            BreakingLoad::GodaTakahashi => Some(goda.alpha_i1_for(s.berm_width_m.unwrap_or(0.0))),
            BreakingLoad::Cuomo2010 | BreakingLoad::None => None,
        };
        PeriodLoads {
            model: self,
            period_s,
            l_toe,
            hb_toe,
            hbr,
            l0: deep_water_wavelength_m(period_s),
            sf_depth,
            goda,
            alpha_i1_rule,
            sainflou_input,
            sainflou: OnceCell::new(),
            impact_input,
            impact: OnceCell::new(),
        }
    }

    /// Goda's static checks for the loads of one wave (per metre). `weight_in_water_n` is the
    /// caisson's total weight in water, `mu` the friction coefficient; the centre of gravity is
    /// taken at B/2 from the heel (symmetric caisson, seed Eq. 11).
    pub fn safety(&self, loads: &WaveLoads, weight_in_water_n: f64, mu: f64) -> SafetyFactors {
        let g = &loads.goda;
        safety_factors(&SafetyInput {
            weight_in_water_n_per_m: weight_in_water_n / self.site.length_m,
            cog_from_heel_m: 0.5 * self.site.width_m,
            width_m: self.site.width_m,
            mu,
            horizontal_force_n_per_m: g.horizontal_force_n_per_m,
            horizontal_moment_base_nm_per_m: g.horizontal_moment_base_nm_per_m,
            uplift_force_n_per_m: g.uplift_force_n_per_m,
            uplift_moment_heel_nm_per_m: g.uplift_moment_heel_nm_per_m,
        })
    }

    /// The load event of one wave starting at `start_s` (totals). `rise_time_s` as in
    /// [`WaveRecord`].
    pub fn event(&self, loads: &WaveLoads, rise_time_s: Option<f64>, start_s: f64) -> WaveEvent {
        let sf = &loads.sainflou;
        let trough = SainflouTrough {
            force_n_per_m: sf.trough_force_n_per_m,
            lever_m: sf.trough_lever_m,
            suction_n_per_m: sf.suction_uplift_n_per_m,
            suction_from_heel_m: sf.suction_from_heel_m,
        };
        let breaking = loads.regime.regime == Regime::Breaking;
        let rise_s = match (breaking, loads.rise_time) {
            (true, Some(dist)) => Some(rise_time_s.unwrap_or_else(|| dist.median_clamped_s())),
            _ => None,
        };
        self.event_of(start_s, loads.period_s, &loads.pulsating, &trough, breaking, rise_s.map(|r| (r, &loads.peak)))
    }

    /// [`Self::event`] from its parts: the pulsating Goda load, Sainflou's trough, the regime and,
    /// for an impulsive breaking wave, its rise time and impulsive peak (the peak of any other
    /// wave is not part of its event).
    fn event_of(
        &self,
        start_s: f64,
        period_s: f64,
        goda: &GodaResult,
        sf: &SainflouTrough,
        breaking: bool,
        impulsive: Option<(f64, &ImpulsivePeak)>,
    ) -> WaveEvent {
        let s = &self.site;
        let (l, b) = (s.length_m, s.width_m);
        let quasi = self.quasi_component(goda);
        let trough = LoadComponent::from_levers(
            -sf.force_n_per_m * l,
            sf.lever_m,
            -sf.suction_n_per_m * l,
            sf.suction_from_heel_m,
            b,
        );
        let impulse = impulsive.map(|(rise_s, _)| Impulse {
            shape: self.options.load_shape,
            rise_s,
            duration_s: self.options.duration_ratio * rise_s.min(0.25 * period_s),
        });
        let impact = impulsive.map_or_else(LoadComponent::default, |(_, im)| self.impact_component(im));
        let alpha_qs = if breaking { self.options.alpha_qs_breaking } else { self.options.alpha_qs_nonbreaking };
        WaveEvent::new(start_s, period_s, quasi, alpha_qs, trough, impact, impulse)
    }

    /// The pulsating component F_qs+ (unscaled) of a wave's event (totals).
    #[inline]
    fn quasi_component(&self, g: &GodaResult) -> LoadComponent {
        let (l, b) = (self.site.length_m, self.site.width_m);
        LoadComponent::from_levers(
            g.horizontal_force_n_per_m * l,
            g.horizontal_lever_m,
            g.uplift_force_n_per_m * l,
            g.uplift_from_heel_m,
            b,
        )
    }

    /// The impulsive component of a wave's event (totals).
    #[inline]
    fn impact_component(&self, im: &ImpulsivePeak) -> LoadComponent {
        let (l, b) = (self.site.length_m, self.site.width_m);
        LoadComponent::from_levers(
            im.horizontal_force_n_per_m * l,
            im.horizontal_lever_m,
            im.uplift_force_n_per_m * l,
            im.uplift_from_heel_m,
            b,
        )
    }

    /// A train of waves from per-wave records, one after the other from t = 0.
    pub fn train(&self, records: &[WaveRecord]) -> Result<WaveTrain, WaveLoadError> {
        let mut events = Vec::with_capacity(records.len());
        let mut t = 0.0;
        for (index, r) in records.iter().enumerate() {
            for (what, v) in [("height_m", r.height_m), ("period_s", r.period_s)] {
                if !(v > 0.0 && v.is_finite()) {
                    return Err(WaveLoadError::BadWave { index, what, value: v });
                }
            }
            if let Some(tr) = r.rise_time_s {
                if !(tr > 0.0 && tr.is_finite()) {
                    return Err(WaveLoadError::BadWave { index, what: "rise_time_s", value: tr });
                }
            }
            let loads = self
                .evaluate_with(r.height_m, r.period_s, RegimeChoice::Forced(r.regime))
                .map_err(|source| WaveLoadError::Regime { index, source })?;
            events.push(self.event(&loads, r.rise_time_s, t));
            t += r.period_s;
        }
        Ok(WaveTrain::new(events)?)
    }

    /// Records of `n` regular waves (H, T) in the regime of `loads`, with rise times drawn from
    /// the rise-time distribution (one standard-normal draw from `rng` per wave, clamped to T/4).
    pub fn regular_records(&self, loads: &WaveLoads, n: usize, rng: &mut LoadRng) -> Vec<WaveRecord> {
        (0..n)
            .map(|_| {
                let z: f64 = rng.sample(StandardNormal);
                WaveRecord {
                    height_m: loads.height_incident_m,
                    period_s: loads.period_s,
                    regime: loads.regime.regime,
                    rise_time_s: loads.rise_time.map(|d| d.at_deviate(z)),
                }
            })
            .collect()
    }
}

/// A [`WaveLoadModel`] at one period ([`WaveLoadModel::at_period`]): the loads of any height by
/// the same floating-point operations as [`WaveLoadModel::evaluate_with`], without repeating
/// the work that depends on the period only. Sainflou's and the impact's parts are computed when
/// a wave first needs them (a storm's screen needs neither Sainflou nor, below the breaker height
/// at the wall, the impact).
#[derive(Debug, Clone)]
pub struct PeriodLoads<'a> {
    model: &'a WaveLoadModel,
    period_s: f64,
    /// L at the toe depth, m.
    l_toe: f64,
    /// Miche breaker height at the toe depth, m.
    hb_toe: f64,
    /// H_br, the breaker height at the wall, m.
    hbr: f64,
    /// L0, m.
    l0: f64,
    /// Depth used for Sainflou, m.
    sf_depth: f64,
    /// Goda's height-free parts, with the berm width's α_I1 for the static check.
    goda: GodaPeriod,
    /// α_I1 of the `goda-takahashi` peak (`None` under the other rules).
    alpha_i1_rule: Option<f64>,
    sainflou_input: SainflouInput,
    sainflou: OnceCell<SainflouPeriod>,
    impact_input: ImpactInput,
    impact: OnceCell<ImpactPeriod>,
}

/// The peak load components of one wave that decide whether it can slide or lift the caisson
/// ([`PeriodLoads::peaks`]): the same numbers as the `quasi` and `impact` components of
/// [`WaveLoadModel::event`] (totals), without the trough and the rise time.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PeakComponents {
    /// α_qs F_qs+.
    pub quasi: LoadComponent,
    /// The impulsive peak (zero unless the wave is breaking and impulsive, F* > 1).
    pub impact: LoadComponent,
}

impl PeakComponents {
    /// Both components multiplied by `k` (as [`WaveEvent::scaled`]).
    pub fn scaled(&self, k: f64) -> PeakComponents {
        PeakComponents { quasi: self.quasi.scaled(k), impact: self.impact.scaled(k) }
    }
}

impl PeriodLoads<'_> {
    /// Sainflou's height-free parts.
    #[inline]
    fn sainflou(&self) -> &SainflouPeriod {
        self.sainflou.get_or_init(|| SainflouPeriod::new(&self.sainflou_input))
    }

    /// The impact's height-free parts.
    #[inline]
    fn impact(&self) -> &ImpactPeriod {
        self.impact.get_or_init(|| ImpactPeriod::new(&self.impact_input, self.hbr))
    }

    /// The wave period, s.
    pub fn period_s(&self) -> f64 {
        self.period_s
    }

    /// H_br, the breaker height at the wall depth (as [`WaveLoadModel::breaker_height_at_wall_m`]), m.
    pub fn breaker_height_at_wall_m(&self) -> f64 {
        self.hbr
    }

    /// The Miche-limited height at the toe, the regime, h_b and the pulsating Goda load (α* = α2):
    /// the steps every load of a wave starts from. `depth_5h_m`: Goda's h_b if given (an
    /// irregular sea's design wave takes it 5 H1/3 seaward, [`crate::analysis::conventional`]);
    /// `None`: h_s + 5 H tan θ with the wave's own height.
    #[inline]
    fn goda_of(
        &self,
        height_m: f64,
        depth_5h_m: Option<f64>,
        choice: RegimeChoice,
    ) -> Result<(f64, RegimeDecision, f64, GodaResult), RegimeError> {
        let s = &self.model.site;
        let h = height_m.min(self.hb_toe);
        let regime = decide_with_limit(choice, h, self.hbr, s.depth_at_wall_m, self.model.options.criterion)?;
        let depth_5h = depth_5h_m.unwrap_or(s.depth_at_toe_m + 5.0 * h * s.seabed_slope);
        Ok((h, regime, depth_5h, self.goda.at_with(h, depth_5h, None)))
    }

    /// The impulsive peak of a breaking wave of height `h` at the toe under the model's rule
    /// ([`super::breaking_load`]) and its F* over the pulsating Goda force of `pulsating`.
    #[inline]
    fn peak_of(&self, h: f64, depth_5h: f64, pulsating: &GodaResult) -> (ImpulsivePeak, f64) {
        let peak = match self.model.options.breaking_load {
            BreakingLoad::Cuomo2010 => ImpulsivePeak::of_impact(&self.impact().at(h)),
            BreakingLoad::GodaTakahashi => ImpulsivePeak::of_goda(&self.goda.at_with(h, depth_5h, self.alpha_i1_rule)),
            BreakingLoad::None => ImpulsivePeak::default(),
        };
        (peak, f_star(pulsating, &peak))
    }

    /// All loads of a wave of incident height `height_m` at this period (as
    /// [`WaveLoadModel::evaluate_with`]).
    pub fn evaluate_with(&self, height_m: f64, choice: RegimeChoice) -> Result<WaveLoads, RegimeError> {
        self.evaluate_at(height_m, None, choice)
    }

    /// As [`Self::evaluate_with`], with Goda's h_b given (`None`: from the wave's own height): the
    /// design wave H_max of an irregular sea, whose h_b is taken 5 H1/3 seaward (Goda 2000).
    pub fn evaluate_at(
        &self,
        height_m: f64,
        depth_5h_m: Option<f64>,
        choice: RegimeChoice,
    ) -> Result<WaveLoads, RegimeError> {
        let (h, regime, depth_5h, pulsating) = self.goda_of(height_m, depth_5h_m, choice)?;
        let goda = self.goda.at(h, depth_5h);
        let sainflou = self.sainflou().at(h);
        let impact = self.impact().at(h);
        let impulsive_goda = self.alpha_i1_rule.map(|a| self.goda.at_with(h, depth_5h, Some(a)));
        let (peak, f_star) = self.peak_of(h, depth_5h, &pulsating);
        Ok(WaveLoads {
            height_incident_m: height_m,
            height_m: h,
            toe_breaker_height_m: self.hb_toe,
            limited_at_toe: height_m > self.hb_toe,
            period_s: self.period_s,
            toe_wavelength_m: self.l_toe,
            deep_water_wavelength_m: self.l0,
            depth_5h_seaward_m: depth_5h,
            sainflou_depth_m: self.sf_depth,
            regime,
            goda,
            pulsating,
            sainflou,
            impact,
            impulsive_goda,
            peak,
            f_star,
            rise_time: self.model.options.rise_time.distribution(f_star, self.period_s),
        })
    }

    /// Upper bounds of the components [`Self::peaks`] gives with the automatic regime, for every
    /// incident height up to `max_height_m`, each ≥ 0 and with a relative margin of 1e-9 for
    /// rounding: the pulsating component from [`GodaPeriod::upper_bounds`] (α* = α2) at the
    /// largest height at the toe (min(H, H_b,toe)) and its h_b, times the larger α_qs; the
    /// impulsive peak, if that height reaches the breaker height at the wall (a lower wave is
    /// non-breaking: no peak), by the rule: [`ImpactPeriod::upper_bounds`] (`cuomo-2010`),
    /// [`GodaPeriod::upper_bounds`] with the rule's α_I (`goda-takahashi`), zero (`none`); else
    /// zero. The moments use the levers of [`WaveLoadModel::event`] (uplift B/6 shoreward of the
    /// base centre). `None` where the bounds' assumptions do not hold (negative λ, α_qs,
    /// a_imp α_max, seabed slope, depths or widths): then only the heights themselves tell.
    pub fn peak_bound(&self, max_height_m: f64) -> Option<PeakComponents> {
        let s = &self.model.site;
        let o = &self.model.options;
        const MARGIN: f64 = 1.0 + 1e-9;
        let positive = o.alpha_qs_breaking >= 0.0 && o.alpha_qs_nonbreaking >= 0.0 && s.seabed_slope >= 0.0;
        if !(positive && s.length_m > 0.0 && s.width_m > 0.0) {
            return None;
        }
        let h = (max_height_m * MARGIN).min(self.hb_toe * MARGIN);
        let depth_5h = (s.depth_at_toe_m + 5.0 * h * s.seabed_slope) * MARGIN;
        let [p, m, u] = self.goda.upper_bounds(h, depth_5h, None)?;
        let may_break = h >= self.hbr;
        let alpha_qs = if may_break { o.alpha_qs_breaking.max(o.alpha_qs_nonbreaking) } else { o.alpha_qs_nonbreaking };
        let [ix, im, iy] = match (may_break, o.breaking_load) {
            (false, _) | (true, BreakingLoad::None) => [0.0; 3],
            (true, BreakingLoad::Cuomo2010) => self.impact().upper_bounds(h)?,
            (true, BreakingLoad::GodaTakahashi) => self.goda.upper_bounds(h, depth_5h, self.alpha_i1_rule)?,
        };
        let (l, k) = (s.length_m, MARGIN * MARGIN);
        let component = |fx: f64, m: f64, fy: f64| LoadComponent {
            x: WaveForce { fx_n: k * fx * l, fy_n: 0.0, m_nm: k * (m + fy * s.width_m / 6.0) * l },
            y: WaveForce { fx_n: 0.0, fy_n: k * fy * l, m_nm: 0.0 },
        };
        Some(PeakComponents {
            quasi: component(alpha_qs * p, alpha_qs * m, alpha_qs * u),
            impact: component(ix, im, iy),
        })
    }

    /// The peak components of the event of a wave of incident height `height_m` (totals; as the
    /// `quasi` and `impact` of [`WaveLoadModel::event`] of [`Self::evaluate_with`], bit for bit):
    /// what a screen of the waves that can slide the caisson needs, without the trough pressures
    /// and the rise-time distribution.
    #[inline]
    pub fn peaks(&self, height_m: f64, choice: RegimeChoice) -> Result<PeakComponents, RegimeError> {
        let (h, regime, depth_5h, goda) = self.goda_of(height_m, None, choice)?;
        let o = &self.model.options;
        let breaking = regime.regime == Regime::Breaking;
        let alpha_qs = if breaking { o.alpha_qs_breaking } else { o.alpha_qs_nonbreaking };
        let quasi = self.model.quasi_component(&goda).scaled(alpha_qs);
        // WaveLoadModel::event keeps the peak of a breaking wave with a rise-time distribution,
        // which exists exactly when F* > 1 and finite (RiseTimeParams::distribution): the peak
        // of a non-breaking wave is not even computed.
        let mut impact = LoadComponent::default();
        if breaking {
            let (peak, fs) = self.peak_of(h, depth_5h, &goda);
            if fs > 1.0 && fs.is_finite() {
                impact = self.model.impact_component(&peak);
            }
        }
        Ok(PeakComponents { quasi, impact })
    }

    /// The load event of a wave of incident height `height_m` starting at 0 (totals), whose
    /// rise time is at the standard-normal `deviate` of its distribution: bit for bit
    /// [`WaveLoadModel::event`] of [`Self::evaluate_with`] with the rise time
    /// [`RiseTimeDistribution::at_deviate`], computing only what the event holds (Sainflou's
    /// trough, not its crest; the impulsive peak and the rise-time distribution of a breaking
    /// wave only).
    pub fn event(&self, height_m: f64, choice: RegimeChoice, deviate: f64) -> Result<WaveEvent, RegimeError> {
        let (h, regime, depth_5h, goda) = self.goda_of(height_m, None, choice)?;
        let trough = self.sainflou().trough(h);
        let breaking = regime.regime == Regime::Breaking;
        let mut impulsive = None;
        if breaking {
            let (peak, fs) = self.peak_of(h, depth_5h, &goda);
            let rise = self.model.options.rise_time.distribution(fs, self.period_s);
            impulsive = rise.map(|d| (d.at_deviate(deviate), peak));
        }
        Ok(self.model.event_of(0.0, self.period_s, &goda, &trough, breaking, impulsive.as_ref().map(|(r, p)| (*r, p))))
    }
}

/// F* = F_x,peak / P (0 without a positive P).
#[inline]
fn f_star(goda: &GodaResult, peak: &ImpulsivePeak) -> f64 {
    if goda.horizontal_force_n_per_m > 0.0 {
        peak.horizontal_force_n_per_m / goda.horizontal_force_n_per_m
    } else {
        0.0
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// The PARI flume of the seed's breaking tests (h_s 1.14 m, d 0.4 m, h' 0.8 m).
    pub(crate) fn pari_site() -> WaveSite {
        WaveSite {
            rho_w: 1000.0,
            depth_at_toe_m: 1.14,
            depth_at_wall_m: 0.4,
            base_depth_m: 0.8,
            crest_freeboard_m: 0.32,
            width_m: 0.78,
            length_m: 1.0,
            seabed_slope: 0.0,
            berm_width_m: None,
        }
    }

    #[test]
    fn a_site_refuses_each_quantity_out_of_range_naming_it() {
        let ok = pari_site();
        assert_eq!(ok.checked(), Ok(ok));
        let named = |site: WaveSite| match site.checked() {
            Err(WaveParamError::Param(e)) => e.quantity,
            other => panic!("{other:?}"),
        };
        assert_eq!(named(WaveSite { rho_w: 100.0, ..ok }), "rho_w");
        assert_eq!(named(WaveSite { depth_at_toe_m: f64::NAN, ..ok }), "depth_at_toe_m");
        assert_eq!(named(WaveSite { seabed_slope: -0.1, ..ok }), "seabed_slope");
        assert_eq!(named(WaveSite { berm_width_m: Some(-1.0), ..ok }), "berm_width_m");
        // The rules between depths carry both values.
        assert_eq!(
            WaveSite { depth_at_wall_m: 1.5, ..ok }.checked(),
            Err(WaveParamError::WallDepth { depth_at_wall_m: 1.5, depth_at_toe_m: 1.14 })
        );
        assert_eq!(
            WaveSite { base_depth_m: 0.3, ..ok }.checked(),
            Err(WaveParamError::BaseAboveWall { base_depth_m: 0.3, depth_at_wall_m: 0.4 })
        );
        assert_eq!(
            WaveSite { base_depth_m: 1.2, ..ok }.checked(),
            Err(WaveParamError::BaseBelowToe { base_depth_m: 1.2, depth_at_toe_m: 1.14 })
        );
    }

    #[test]
    fn options_refuse_each_coefficient_out_of_range_naming_it() {
        let d = WaveLoadOptions::default();
        assert_eq!(d.checked(), Ok(d));
        let named = |o: WaveLoadOptions| o.checked().unwrap_err().quantity;
        assert_eq!(named(WaveLoadOptions { alpha_max: 0.0, ..d }), "alpha_max");
        assert_eq!(named(WaveLoadOptions { a_imp: 11.0, ..d }), "a_imp");
        assert_eq!(named(WaveLoadOptions { alpha_qs_nonbreaking: -0.1, ..d }), "alpha_qs_nonbreaking");
        assert_eq!(named(WaveLoadOptions { alpha_qs_breaking: f64::INFINITY, ..d }), "alpha_qs_breaking");
        assert_eq!(named(WaveLoadOptions { duration_ratio: 1.0, ..d }), "duration_ratio");
        assert_eq!(named(WaveLoadOptions { angle_rad: 2.0, ..d }), "angle_rad");
        let e = d.with_angle_deg(90.0).unwrap_err();
        assert_eq!((e.quantity, e.value), ("angle_deg", 90.0));
        assert_eq!(d.with_angle_deg(30.0).unwrap().angle_rad, 30f64.to_radians());
    }

    /// A period's event is the event of the period's loads, to the bit (Debug prints every f64
    /// exactly, signed zeros included): two sites (the PARI flume flat, and a prototype on a 1:50
    /// slope with Sainflou at the wall and a berm), 4 periods, 40 heights from 1 % to 200 % of the
    /// wall's breaker height, 3 regime choices and 3 rise-time deviates; breaking impulsive and
    /// non-breaking waves both among them, and a forced regime refused by both alike.
    #[test]
    fn a_periods_event_is_the_event_of_its_loads_to_the_bit() {
        let prototype = WaveSite {
            rho_w: 1030.0,
            depth_at_toe_m: 20.0,
            depth_at_wall_m: 14.0,
            base_depth_m: 17.5,
            crest_freeboard_m: 7.0,
            width_m: 20.0,
            length_m: 1.0,
            seabed_slope: 0.02,
            berm_width_m: Some(10.0),
        };
        let wall = WaveLoadOptions { sainflou_depth: SainflouDepth::Wall, ..WaveLoadOptions::default() };
        let sites = [
            (pari_site(), WaveLoadOptions::default(), [1.5, 2.2, 3.04, 4.0]),
            (prototype, wall, [6.0, 9.0, 12.0, 16.0]),
        ];
        let choices =
            [RegimeChoice::Auto, RegimeChoice::Forced(Regime::Breaking), RegimeChoice::Forced(Regime::NonBreaking)];
        let (mut checked, mut impulsive, mut refused) = (0, 0, 0);
        for (site, options, periods) in sites {
            let model = WaveLoadModel { site, options };
            for period_s in periods {
                let at = model.at_period(period_s);
                for k in 1..=40 {
                    let h = at.breaker_height_at_wall_m() * 0.05 * k as f64;
                    for choice in choices {
                        for z in [-1.7, 0.0, 2.3] {
                            let old = at
                                .evaluate_with(h, choice)
                                .map(|loads| model.event(&loads, loads.rise_time.map(|d| d.at_deviate(z)), 0.0));
                            let new = at.event(h, choice, z);
                            assert_eq!(format!("{old:?}"), format!("{new:?}"), "T {period_s} H {h} {choice:?} z {z}");
                            checked += 1;
                            impulsive += usize::from(new.is_ok_and(|e| e.impulse.is_some()));
                            refused += usize::from(new.is_err());
                        }
                    }
                }
            }
        }
        assert_eq!(checked, 2 * 4 * 40 * 3 * 3);
        assert!(impulsive > 100 && refused > 100 && checked - impulsive - refused > 100, "{impulsive} {refused}");
    }
}
