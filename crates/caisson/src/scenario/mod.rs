//! The scenario file: its TOML schema (serde) and its validation into typed parameters.
//!
//! Every key is documented in `docs/scenario.md` with unit, default and allowed range. Keys carry
//! their unit (`weight_in_water_kn`); values are converted to SI here and nowhere else. Unknown
//! keys are rejected. Validation errors name the key, the value and what is allowed
//! ([`ScenarioError`]).

pub mod campaign;
pub mod design;
pub mod fragility;
mod validate;
pub mod waves;

pub use validate::{validate, AdaptiveParams, LoadSpec, Scenario, SolverParams, Stepping};

use serde::Deserialize;
use std::path::{Path, PathBuf};
use thiserror::Error;

/// Errors in a scenario file. `Display` gives a message that says what to fix.
#[derive(Debug, Error)]
pub enum ScenarioError {
    #[error("cannot read scenario file {path}: {message}")]
    Read { path: PathBuf, message: String },
    #[error("{path} line {line}, column {column}: {message}{}", if source_line.is_empty() { String::new() } else { format!(" (in `{source_line}`)") })]
    Syntax { path: PathBuf, line: usize, column: usize, message: String, source_line: String },
    #[error("missing key `{key}`: {hint}")]
    Missing { key: String, hint: String },
    #[error("`{key}` = {value}: {allowed}")]
    OutOfRange { key: String, value: String, allowed: String },
    #[error("{message}")]
    Conflict { message: String },
    #[error("force series {path}: {message}")]
    Series { path: PathBuf, message: String },
}

impl ScenarioError {
    pub(crate) fn range(key: &str, value: impl std::fmt::Display, allowed: impl Into<String>) -> Self {
        ScenarioError::OutOfRange { key: key.to_string(), value: value.to_string(), allowed: allowed.into() }
    }
    pub(crate) fn missing(key: &str, hint: impl Into<String>) -> Self {
        ScenarioError::Missing { key: key.to_string(), hint: hint.into() }
    }
    /// The key this error is about, if it is about one key.
    pub fn key(&self) -> Option<&str> {
        match self {
            ScenarioError::Missing { key, .. } | ScenarioError::OutOfRange { key, .. } => Some(key),
            _ => None,
        }
    }
}

/// The whole scenario file as written (units as in the keys).
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct ScenarioFile {
    pub caisson: CaissonTable,
    #[serde(default)]
    pub foundation: FoundationTable,
    #[serde(default)]
    pub water: WaterTable,
    pub load: Option<LoadTable>,
    #[serde(default)]
    pub solver: SolverTable,
    pub waves: Option<waves::WavesTable>,
    pub campaign: Option<campaign::CampaignTable>,
    pub design: Option<design::DesignTable>,
    pub fragility: Option<fragility::FragilityTable>,
}

/// `[caisson]`: geometry and mass (PHYSICS.md §8.2).
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct CaissonTable {
    /// B, base width in the wave direction, m.
    pub width_m: Option<f64>,
    /// Alongshore length, m (per-metre forces and stiffnesses are multiplied by it). Default 1.0.
    pub length_m: Option<f64>,
    /// Height of the caisson, m.
    pub height_m: Option<f64>,
    /// Depth of the base below still water, m (h' = d + e).
    pub base_depth_m: Option<f64>,
    /// Weight in water, kN (total). Given alone, the mass follows from the displaced water.
    pub weight_in_water_kn: Option<f64>,
    /// Mass in air, kg (total). Given alone, the weight in water follows.
    pub mass_kg: Option<f64>,
    /// Height of the centre of gravity above the base, m. Default height/2.
    pub cog_height_m: Option<f64>,
    /// Rotational inertia about the centre of gravity, kg·m². Default a uniform block.
    pub inertia_kg_m2: Option<f64>,
    /// `"coupled"` (exact rigid-body mass matrix about the base centre, default) or `"diagonal"`
    /// (the seed's Eq. 24).
    pub mass_matrix: Option<String>,
}

/// `[foundation]`: interface springs, friction, soil stiffness and damping (seed §3.2-3.3).
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct FoundationTable {
    pub springs: Option<i64>,
    pub mu_static: Option<f64>,
    pub mu_dynamic: Option<f64>,
    pub e100_kpa: Option<f64>,
    pub poisson: Option<f64>,
    pub density_kg_per_m3: Option<f64>,
    pub reference_stress_kpa: Option<f64>,
    pub kx_kn_per_m: Option<f64>,
    pub ky_kn_per_m: Option<f64>,
    pub damping_kns_per_m: Option<f64>,
    pub vertical_damping_factor: Option<f64>,
    pub damping_mode: Option<String>,
    pub vertical_damping: Option<String>,
    pub added_mass: Option<bool>,
    pub added_mass_depth_m: Option<f64>,
}

/// `[water]`: water density and (for wave loads) the depths at the structure.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct WaterTable {
    /// Default 1000 kg/m³ (the PARI flume).
    pub density_kg_per_m3: Option<f64>,
    /// h_s: depth at the toe of the mound, m.
    pub depth_at_toe_m: Option<f64>,
    /// d: depth in front of the wall (above the berm), m.
    pub depth_at_wall_m: Option<f64>,
    /// tan θ of the seabed seaward of the structure (0 = flat flume bed).
    pub seabed_slope: Option<f64>,
    /// B_M: width of the mound berm in front of the caisson, m (enables Takahashi's α_I).
    pub berm_width_m: Option<f64>,
}

/// `[load]`: the force history driving `caisson run`.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct LoadTable {
    /// `"triangle"`, `"static"` or `"series"`.
    pub kind: Option<String>,
    pub peak_horizontal_kn: Option<f64>,
    pub rise_time_s: Option<f64>,
    pub peak_uplift_kn: Option<f64>,
    pub horizontal_lever_m: Option<f64>,
    pub uplift_lever_m: Option<f64>,
    pub start_time_s: Option<f64>,
    pub ramp_time_s: Option<f64>,
    pub file: Option<String>,
    pub duration_s: Option<f64>,
}

/// `[solver]`: time step and Newton-Raphson controls.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct SolverTable {
    pub dt_s: Option<f64>,
    pub gamma: Option<f64>,
    pub beta: Option<f64>,
    pub max_iterations: Option<i64>,
    pub max_substep_levels: Option<i64>,
    pub tolerance: Option<f64>,
    pub output_interval_s: Option<f64>,
    /// `"fixed"` or `"adaptive"`. Default: adaptive for a `[waves]` scenario, fixed for `[load]`.
    pub stepping: Option<String>,
    pub dt_min_s: Option<f64>,
    pub dt_max_s: Option<f64>,
    pub error_tolerance_m: Option<f64>,
}

/// Parse scenario text. `path` is used in messages only.
pub fn parse_str(text: &str, path: &Path) -> Result<ScenarioFile, ScenarioError> {
    toml::from_str::<ScenarioFile>(text).map_err(|e| {
        let (line, column) = e
            .span()
            .map(|s| {
                let before = &text[..s.start.min(text.len())];
                let line = before.matches('\n').count() + 1;
                let column = s.start - before.rfind('\n').map(|i| i + 1).unwrap_or(0) + 1;
                (line, column)
            })
            .unwrap_or((0, 0));
        let source_line =
            if line > 0 { text.lines().nth(line - 1).unwrap_or("").trim().to_string() } else { String::new() };
        ScenarioError::Syntax {
            path: path.to_path_buf(),
            line,
            column,
            message: e.message().trim().to_string(),
            source_line,
        }
    })
}

/// Read and parse a scenario file (no validation).
pub fn read_file(path: &Path) -> Result<ScenarioFile, ScenarioError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| ScenarioError::Read { path: path.to_path_buf(), message: e.to_string() })?;
    parse_str(&text, path)
}

/// Read, parse and validate a scenario file for the dynamic engine.
pub fn load(path: &Path) -> Result<Scenario, ScenarioError> {
    let file = read_file(path)?;
    validate(&file, path.parent().unwrap_or(Path::new(".")))
}
