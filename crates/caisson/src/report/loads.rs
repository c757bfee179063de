//! `caisson loads`: `loads.json` (keys in docs/waves.md). Per metre of breakwater; kN, kPa, m.
//!
//! [`LoadsReport::columns`] hands the same values, without serde, to a [`ColumnSink`]: the table
//! of many waves of the Python package's `caisson.loads.evaluate` (tests/equiv_loads_columns.rs keeps
//! it in step with the JSON: every key, in order, every value bit for bit).

use super::{kn, NotFinite, Provenance};
use crate::analysis::checks::{structure_warnings, wave_load_warnings, Warning};
use crate::analysis::conventional::{DesignWaveRule, StaticCheck};
use crate::analysis::site::WaveSetup;
use crate::analysis::Structure;
use crate::loads::breaking_load::BreakingLoad;
use crate::loads::regime::Regime;
use crate::loads::risetime::RiseTimeModel;
use serde::Serialize;

#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct WaveInfo {
    pub kind: &'static str,
    pub incident_height_m: f64,
    pub height_at_toe_m: f64,
    pub limited_at_toe: bool,
    pub toe_breaker_height_m: f64,
    pub period_s: f64,
    pub angle_deg: f64,
    pub toe_wavelength_m: f64,
    pub deep_water_wavelength_m: f64,
}

/// How the height of Goda's check was found (docs/model.md §1.3; the keys of
/// [`crate::analysis::conventional::DesignWave`]).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DesignWaveInfo {
    pub rule: DesignWaveRule,
    pub significant_height_m: Option<f64>,
    pub hmax_from_significant_m: Option<f64>,
    pub equivalent_deep_water_height_m: Option<f64>,
    pub breaking_limited_hmax_m: Option<f64>,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SiteInfo {
    pub water_density_kg_per_m3: f64,
    pub depth_at_toe_m: f64,
    pub depth_at_wall_m: f64,
    pub base_depth_m: f64,
    pub crest_freeboard_m: f64,
    pub width_m: f64,
    pub length_m: f64,
    pub seabed_slope: f64,
    pub berm_width_m: Option<f64>,
    pub depth_5h_seaward_m: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RegimeInfo {
    pub regime: Regime,
    pub forced: bool,
    pub breaker_criterion: &'static str,
    pub breaker_height_at_wall_m: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct GodaInfo {
    /// H_D, the height in Goda's formula (regular waves: H; irregular: H_max), m.
    pub design_height_m: f64,
    pub alpha1: f64,
    pub alpha2: f64,
    pub alpha3: f64,
    pub alpha_i: Option<f64>,
    pub alpha_star: f64,
    pub eta_star_m: f64,
    pub p1_kpa: f64,
    pub p2_kpa: f64,
    pub p3_kpa: f64,
    pub p4_kpa: f64,
    pub pu_kpa: f64,
    pub horizontal_force_kn_per_m: f64,
    pub horizontal_moment_base_kn_m_per_m: f64,
    pub horizontal_lever_m: f64,
    pub uplift_force_kn_per_m: f64,
    pub uplift_moment_heel_kn_m_per_m: f64,
    pub uplift_from_heel_m: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SainflouInfo {
    pub depth_m: f64,
    pub h0_m: f64,
    pub pb_kpa: f64,
    pub crest_force_kn_per_m: f64,
    pub crest_moment_base_kn_m_per_m: f64,
    pub trough_base_pressure_kpa: f64,
    pub trough_force_kn_per_m: f64,
    pub trough_moment_base_kn_m_per_m: f64,
    pub trough_lever_m: f64,
    pub suction_uplift_kn_per_m: f64,
    pub suction_moment_heel_kn_m_per_m: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ImpactInfo {
    pub applied: bool,
    pub breaking_depth_m: Option<f64>,
    pub breaker_height_m: f64,
    pub reduction: f64,
    pub alpha_max: f64,
    pub a_imp: f64,
    pub horizontal_force_kn_per_m: f64,
    pub p1_kpa: f64,
    pub horizontal_moment_base_kn_m_per_m: f64,
    pub horizontal_lever_m: f64,
    pub uplift_force_kn_per_m: f64,
    pub uplift_moment_heel_kn_m_per_m: f64,
    pub uplift_from_heel_m: f64,
}

/// The impulsive peak of a breaking wave under the rule of `[waves] breaking_load`
/// ([`crate::loads::breaking_load`]), beside the pulsating force F* divides it by.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BreakingLoadInfo {
    pub rule: BreakingLoad,
    /// Whether the wave gets it: breaking, and impulsive (F* > 1).
    pub applied: bool,
    /// B_M of Takahashi's α_I under `goda-takahashi` (0 where no berm width is given), m.
    pub berm_width_m: Option<f64>,
    /// α_I and α* = max(α2, α_I) of `goda-takahashi`.
    pub alpha_i: Option<f64>,
    pub alpha_star: Option<f64>,
    pub horizontal_force_kn_per_m: f64,
    pub horizontal_lever_m: f64,
    pub uplift_force_kn_per_m: f64,
    pub uplift_from_heel_m: f64,
    /// P with α* = α2: the pulsating force of the dynamic model (F* = peak / this).
    pub pulsating_force_kn_per_m: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RiseTimeInfo {
    pub model: RiseTimeModel,
    pub f_star: f64,
    pub impulsive: bool,
    pub median_s: Option<f64>,
    pub log_std: Option<f64>,
    pub max_s: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TimeHistoryInfo {
    pub load_shape: &'static str,
    pub alpha_qs: f64,
    pub duration_ratio: f64,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SafetyInfo {
    pub mu: f64,
    pub weight_in_water_kn_per_m: f64,
    pub sliding: Option<f64>,
    pub overturning: Option<f64>,
    pub heel_pressure_kpa: Option<f64>,
    pub resultant_from_heel_m: Option<f64>,
}

/// A generated force history (`--history`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct HistoryInfo {
    pub waves: usize,
    pub seed: u64,
    pub rise_times_s: Vec<Option<f64>>,
    pub csv: &'static str,
    pub svg: &'static str,
}

/// The loads of one wave on the caisson.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LoadsReport {
    #[serde(flatten)]
    pub provenance: Provenance,
    pub wave: WaveInfo,
    pub design_wave: DesignWaveInfo,
    pub site: SiteInfo,
    pub regime: RegimeInfo,
    pub goda: GodaInfo,
    pub sainflou: SainflouInfo,
    pub impact: ImpactInfo,
    pub breaking_load: BreakingLoadInfo,
    pub rise_time: RiseTimeInfo,
    pub time_history: TimeHistoryInfo,
    pub safety: SafetyInfo,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub history: Option<HistoryInfo>,
    /// Plausibility warnings of the structure and of the waves ([`LoadsReport::of_structure`];
    /// none in a row of a table, [`LoadsReport::new`]); left out when there is none, so that a table of many waves' reports has a fixed set of numeric columns.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub warnings: Vec<Warning>,
}

/// `caisson loads` refuses a report with a number that is not finite: the loads are closed forms
/// of the scenario's numbers, so one that overflows is the input's (a huge weight or wave).
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error(
    "the scenario's loads are not finite numbers ({0}): the [caisson], [water] or [waves] numbers are too large or too small for the formulas"
)]
pub struct LoadsNotFinite(pub NotFinite);

impl LoadsReport {
    /// The report of `caisson loads` (and Python's `caisson.loads.report`): Goda's static check
    /// `c` of the scenario's waves on `structure`, with the warnings of the structure and of the
    /// waves and the generated `history`'s description; refused if a number is not finite.
    pub fn of_structure(
        structure: &Structure,
        waves: &WaveSetup,
        c: &StaticCheck,
        history: Option<HistoryInfo>,
    ) -> Result<Self, LoadsNotFinite> {
        let (w, mu) = (structure.caisson.weight_in_water_n, structure.foundation.mu_static);
        let mut report = LoadsReport::new(waves, c, w, mu);
        report.warnings = structure_warnings(structure);
        report.warnings.extend(wave_load_warnings(structure, waves));
        report.history = history;
        super::encode::check_finite(&report, "loads").map_err(LoadsNotFinite)?;
        Ok(report)
    }

    /// One wave's row of a table of many (no warnings, no history, not checked for finite
    /// numbers: the table's are checked as its columns): Goda's static check `c` (the design
    /// wave of the scenario's waves, its loads and safety factors) at the site of `waves`, for a
    /// caisson of weight in water `weight_in_water_n` (total, N) and friction `mu`.
    pub fn new(waves: &WaveSetup, c: &StaticCheck, weight_in_water_n: f64, mu: f64) -> Self {
        let (l, sf, dw) = (&c.loads, &c.safety, &c.design_wave);
        let site = &waves.model.site;
        let o = &waves.model.options;
        let (g, s, i) = (&l.goda, &l.sainflou, &l.impact);
        let breaking = l.regime.regime == Regime::Breaking;
        LoadsReport {
            provenance: Provenance::CURRENT,
            wave: WaveInfo {
                kind: dw.kind,
                incident_height_m: l.height_incident_m,
                height_at_toe_m: l.height_m,
                limited_at_toe: l.limited_at_toe,
                toe_breaker_height_m: l.toe_breaker_height_m,
                period_s: l.period_s,
                angle_deg: o.angle_rad.to_degrees(),
                toe_wavelength_m: l.toe_wavelength_m,
                deep_water_wavelength_m: l.deep_water_wavelength_m,
            },
            design_wave: DesignWaveInfo {
                rule: dw.rule,
                significant_height_m: dw.significant_height_m,
                hmax_from_significant_m: dw.hmax_from_significant_m,
                equivalent_deep_water_height_m: dw.equivalent_deep_water_height_m,
                breaking_limited_hmax_m: dw.breaking_limited_hmax_m,
            },
            site: SiteInfo {
                water_density_kg_per_m3: site.rho_w,
                depth_at_toe_m: site.depth_at_toe_m,
                depth_at_wall_m: site.depth_at_wall_m,
                base_depth_m: site.base_depth_m,
                crest_freeboard_m: site.crest_freeboard_m,
                width_m: site.width_m,
                length_m: site.length_m,
                seabed_slope: site.seabed_slope,
                berm_width_m: site.berm_width_m,
                depth_5h_seaward_m: l.depth_5h_seaward_m,
            },
            regime: RegimeInfo {
                regime: l.regime.regime,
                forced: l.regime.forced,
                breaker_criterion: o.criterion.name(),
                breaker_height_at_wall_m: l.regime.breaker_height_at_wall_m,
            },
            goda: GodaInfo {
                design_height_m: l.height_m,
                alpha1: g.alpha1,
                alpha2: g.alpha2,
                alpha3: g.alpha3,
                alpha_i: g.alpha_i,
                alpha_star: g.alpha_star,
                eta_star_m: g.eta_star_m,
                p1_kpa: kn(g.p1_pa),
                p2_kpa: kn(g.p2_pa),
                p3_kpa: kn(g.p3_pa),
                p4_kpa: kn(g.p4_pa),
                pu_kpa: kn(g.pu_pa),
                horizontal_force_kn_per_m: kn(g.horizontal_force_n_per_m),
                horizontal_moment_base_kn_m_per_m: kn(g.horizontal_moment_base_nm_per_m),
                horizontal_lever_m: g.horizontal_lever_m,
                uplift_force_kn_per_m: kn(g.uplift_force_n_per_m),
                uplift_moment_heel_kn_m_per_m: kn(g.uplift_moment_heel_nm_per_m),
                uplift_from_heel_m: g.uplift_from_heel_m,
            },
            sainflou: SainflouInfo {
                depth_m: l.sainflou_depth_m,
                h0_m: s.h0_m,
                pb_kpa: kn(s.pb_pa),
                crest_force_kn_per_m: kn(s.crest_force_n_per_m),
                crest_moment_base_kn_m_per_m: kn(s.crest_moment_base_nm_per_m),
                trough_base_pressure_kpa: kn(s.trough_base_pressure_pa),
                trough_force_kn_per_m: kn(s.trough_force_n_per_m),
                trough_moment_base_kn_m_per_m: kn(s.trough_moment_base_nm_per_m),
                trough_lever_m: s.trough_lever_m,
                suction_uplift_kn_per_m: kn(s.suction_uplift_n_per_m),
                suction_moment_heel_kn_m_per_m: kn(s.suction_moment_heel_nm_per_m),
            },
            impact: ImpactInfo {
                applied: breaking && l.rise_time.is_some() && o.breaking_load == BreakingLoad::Cuomo2010,
                breaking_depth_m: i.breaking_depth_m,
                breaker_height_m: i.breaker_height_m,
                reduction: i.reduction,
                alpha_max: o.alpha_max,
                a_imp: o.a_imp,
                horizontal_force_kn_per_m: kn(i.horizontal_force_n_per_m),
                p1_kpa: kn(i.p1_pa),
                horizontal_moment_base_kn_m_per_m: kn(i.horizontal_moment_base_nm_per_m),
                horizontal_lever_m: i.horizontal_lever_m,
                uplift_force_kn_per_m: kn(i.uplift_force_n_per_m),
                uplift_moment_heel_kn_m_per_m: kn(i.uplift_moment_heel_nm_per_m),
                uplift_from_heel_m: i.uplift_from_heel_m,
            },
            breaking_load: BreakingLoadInfo {
                rule: o.breaking_load,
                applied: breaking && l.rise_time.is_some(),
                berm_width_m: l.impulsive_goda.map(|_| site.berm_width_m.unwrap_or(0.0)),
                alpha_i: l.impulsive_goda.and_then(|g| g.alpha_i),
                alpha_star: l.impulsive_goda.map(|g| g.alpha_star),
                horizontal_force_kn_per_m: kn(l.peak.horizontal_force_n_per_m),
                horizontal_lever_m: l.peak.horizontal_lever_m,
                uplift_force_kn_per_m: kn(l.peak.uplift_force_n_per_m),
                uplift_from_heel_m: l.peak.uplift_from_heel_m,
                pulsating_force_kn_per_m: kn(l.pulsating.horizontal_force_n_per_m),
            },
            rise_time: RiseTimeInfo {
                model: o.rise_time.model,
                f_star: l.f_star,
                impulsive: l.rise_time.is_some(),
                median_s: l.rise_time.map(|d| d.median_clamped_s()),
                log_std: l.rise_time.map(|d| d.log_std),
                max_s: 0.25 * l.period_s,
            },
            time_history: TimeHistoryInfo {
                load_shape: if breaking { o.load_shape.name() } else { "eq29" },
                alpha_qs: if breaking { o.alpha_qs_breaking } else { o.alpha_qs_nonbreaking },
                duration_ratio: o.duration_ratio,
            },
            safety: SafetyInfo {
                mu,
                weight_in_water_kn_per_m: kn(weight_in_water_n / site.length_m),
                sliding: sf.sliding,
                overturning: sf.overturning,
                heel_pressure_kpa: sf.heel_pressure_pa.map(kn),
                resultant_from_heel_m: sf.resultant_from_heel_m,
            },
            history: None,
            warnings: Vec::new(),
        }
    }
}

/// Where [`LoadsReport::columns`] puts a report's values, in the order of the JSON (struct order)
/// and named by the keys joined by "." (`goda.horizontal_force_kn_per_m`). Left out: the
/// provenance (`caisson_version`, `results_version`: the same for every row), `history` and
/// `warnings` (not columns). The names are constants: a sink that only writes values ignores
/// them at no cost.
pub trait ColumnSink {
    /// A number; `None` where the JSON has `null`.
    fn number(&mut self, name: &'static str, x: Option<f64>);
    /// A boolean.
    fn flag(&mut self, name: &'static str, b: bool);
    /// A text value (one of a few names per column).
    fn text(&mut self, name: &'static str, s: &'static str);
}

/// A value of a report that is one column.
trait Column {
    fn put<S: ColumnSink>(self, name: &'static str, sink: &mut S);
}

/// `impl Column for T` calling `sink.method(name, value)`, for each `T => method(value)`.
macro_rules! columns_of {
    ($($t:ty => $method:ident(|$v:ident| $value:expr)),* $(,)?) => {
        $(impl Column for $t {
            #[inline(always)]
            fn put<S: ColumnSink>(self, name: &'static str, sink: &mut S) {
                let $v = self;
                sink.$method(name, $value)
            }
        })*
    };
}

columns_of!(
    f64 => number(|x| Some(x)),
    Option<f64> => number(|x| x),
    bool => flag(|b| b),
    &'static str => text(|s| s),
    Regime => text(|r| r.name()),
);

impl Column for DesignWaveRule {
    #[inline(always)]
    fn put<S: ColumnSink>(self, name: &'static str, sink: &mut S) {
        // serde's names of the variants (checked against the JSON by the test).
        let text = match self {
            DesignWaveRule::RegularHeight => "regular-height",
            DesignWaveRule::OutsideSurfZone => "1.8-significant-height",
            DesignWaveRule::BreakingLimited => "goda-breaking-limited",
        };
        sink.text(name, text)
    }
}

impl Column for BreakingLoad {
    #[inline(always)]
    fn put<S: ColumnSink>(self, name: &'static str, sink: &mut S) {
        sink.text(name, self.name())
    }
}

impl Column for RiseTimeModel {
    #[inline(always)]
    fn put<S: ColumnSink>(self, name: &'static str, sink: &mut S) {
        // serde's lowercase names of the variants (checked against the JSON by the test).
        let text = match self {
            RiseTimeModel::Median => "median",
            RiseTimeModel::Literal => "literal",
        };
        sink.text(name, text)
    }
}

/// `sink` gets `report.group.field` named `"group.field"`, for each group and its fields.
macro_rules! put_columns {
    ($report:expr, $sink:expr; $($group:ident { $($field:ident),* $(,)? })*) => {
        $($(
            Column::put($report.$group.$field, concat!(stringify!($group), ".", stringify!($field)), $sink);
        )*)*
    };
}

impl LoadsReport {
    /// Every value of the report's JSON but the provenance, `history` and `warnings`, in the
    /// order of the JSON, to `sink` (see [`ColumnSink`]).
    #[inline]
    pub fn columns<S: ColumnSink>(&self, sink: &mut S) {
        put_columns!(self, sink;
            wave {
                kind, incident_height_m, height_at_toe_m, limited_at_toe, toe_breaker_height_m, period_s,
                angle_deg, toe_wavelength_m, deep_water_wavelength_m,
            }
            design_wave {
                rule, significant_height_m, hmax_from_significant_m, equivalent_deep_water_height_m,
                breaking_limited_hmax_m,
            }
            site {
                water_density_kg_per_m3, depth_at_toe_m, depth_at_wall_m, base_depth_m, crest_freeboard_m,
                width_m, length_m, seabed_slope, berm_width_m, depth_5h_seaward_m,
            }
            regime { regime, forced, breaker_criterion, breaker_height_at_wall_m }
            goda {
                design_height_m, alpha1, alpha2, alpha3, alpha_i, alpha_star, eta_star_m, p1_kpa, p2_kpa, p3_kpa, p4_kpa,
                pu_kpa, horizontal_force_kn_per_m, horizontal_moment_base_kn_m_per_m, horizontal_lever_m,
                uplift_force_kn_per_m, uplift_moment_heel_kn_m_per_m, uplift_from_heel_m,
            }
            sainflou {
                depth_m, h0_m, pb_kpa, crest_force_kn_per_m, crest_moment_base_kn_m_per_m,
                trough_base_pressure_kpa, trough_force_kn_per_m, trough_moment_base_kn_m_per_m,
                trough_lever_m, suction_uplift_kn_per_m, suction_moment_heel_kn_m_per_m,
            }
            impact {
                applied, breaking_depth_m, breaker_height_m, reduction, alpha_max, a_imp,
                horizontal_force_kn_per_m, p1_kpa, horizontal_moment_base_kn_m_per_m, horizontal_lever_m,
                uplift_force_kn_per_m, uplift_moment_heel_kn_m_per_m, uplift_from_heel_m,
            }
            breaking_load {
                rule, applied, berm_width_m, alpha_i, alpha_star, horizontal_force_kn_per_m, horizontal_lever_m,
                uplift_force_kn_per_m, uplift_from_heel_m, pulsating_force_kn_per_m,
            }
            rise_time { model, f_star, impulsive, median_s, log_std, max_s }
            time_history { load_shape, alpha_qs, duration_ratio }
            safety { mu, weight_in_water_kn_per_m, sliding, overturning, heel_pressure_kpa, resultant_from_heel_m }
        );
    }
}
