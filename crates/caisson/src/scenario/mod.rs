//! The scenario file: its TOML schema (serde) and its validation into typed parameters.
//!
//! Every key is documented in `docs/scenario.md` with unit, default and allowed range. Keys carry
//! their unit (`weight_in_water_kn`); values are converted to SI here and nowhere else. Unknown
//! keys are rejected. Validation errors name the key, the value and what is allowed
//! ([`ScenarioError`]).
//!
//! This is the only module that knows the file format. [`load`] reads and parses a file once and
//! validates every table it holds into a [`Scenario`]: the typed parameters each module owns
//! ([`CaissonSpec`] and [`FoundationSpec`] with the [`Structure`] built from them,
//! [`SolverParams`], [`LoadSpec`], [`WaveSetup`], the campaign conditions, [`DesignParams`],
//! [`FragilityParams`]). Anything that varies a scenario (campaigns, the validation report, sweeps)
//! changes those typed fields ([`Scenario::with_caisson`], [`Scenario::with_foundation`], ...),
//! never the file's text.

pub mod campaign;
mod coherence;
pub mod design;
pub mod fragility;
pub mod size;
mod validate;
pub mod waves;

use crate::analysis::campaign::Campaign;
use crate::analysis::fragility::FragilityParams;
use crate::analysis::lifetime::{DesignParams, StormCase, WaveDraws};
use crate::analysis::site::WaveSetup;
use crate::analysis::sizing::SizeParams;
use crate::analysis::train::TrainCase;
use crate::analysis::Structure;
use crate::dynamics::SolverParams;
use crate::foundation::{Foundation, FoundationSpec};
use crate::loads::breaking_load::BreakingLoad;
use crate::loads::LoadSpec;
use crate::structure::{Caisson, CaissonSpec};
use crate::{ParamError, Profile};
use serde::Deserialize;
use std::path::{Path, PathBuf};
use thiserror::Error;

/// Errors in a scenario file. `Display` gives a message that says what to fix.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ScenarioError {
    #[error("cannot read scenario file {path}: {message}")]
    Read { path: PathBuf, message: String },
    #[error("{path} line {line}, column {column}: {message}{}", if source_line.is_empty() { String::new() } else { format!(" (in `{source_line}`)") })]
    Syntax { path: PathBuf, line: usize, column: usize, message: String, source_line: String },
    /// A value of the wrong kind (text for a number, a decimal for a whole number, ...).
    #[error("{path}{}: `{key}` must be {expected}, got {got}", line.map_or(String::new(), |l| format!(" line {l}")))]
    WrongType { path: PathBuf, line: Option<usize>, key: String, expected: String, got: String },
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
    /// `key` = `value` is refused: `allowed` says what may be given. A number of `value` written
    /// out long (1e-300 as Rust writes an `f64`: 300 digits; also in a list) is shown by
    /// [`fmt_value`].
    pub(crate) fn range(key: &str, value: impl std::fmt::Display, allowed: impl Into<String>) -> Self {
        ScenarioError::OutOfRange {
            key: key.to_string(),
            value: short_numbers(&value.to_string()),
            allowed: allowed.into(),
        }
    }
    pub(crate) fn missing(key: &str, hint: impl Into<String>) -> Self {
        ScenarioError::Missing { key: key.to_string(), hint: hint.into() }
    }
    /// The key this error is about, if it is about one key.
    pub fn key(&self) -> Option<&str> {
        match self {
            ScenarioError::Missing { key, .. }
            | ScenarioError::OutOfRange { key, .. }
            | ScenarioError::WrongType { key, .. } => Some(key),
            _ => None,
        }
    }
}

/// How the quantities of a parameter type are named in a table of the file: (quantity, key,
/// divisor from SI to the key's unit, the key's unit).
type KeyMap = &'static [(&'static str, &'static str, f64, &'static str)];

const CAISSON_KEYS: KeyMap = &[
    ("width_m", "width_m", 1.0, "m"),
    ("length_m", "length_m", 1.0, "m"),
    ("height_m", "height_m", 1.0, "m"),
    ("base_depth_m", "base_depth_m", 1.0, "m"),
    ("weight_in_water_n", "weight_in_water_kn", 1e3, "kN"),
    ("mass_kg", "mass_kg", 1.0, "kg"),
    ("cog_height_m", "cog_height_m", 1.0, "m above the base"),
    ("inertia_cog_kg_m2", "inertia_kg_m2", 1.0, "kg·m² about the centre of gravity"),
    ("wall_thickness_m", "wall_thickness_m", 1.0, "m"),
    ("slab_thickness_m", "slab_thickness_m", 1.0, "m"),
    ("partition_thickness_m", "partition_thickness_m", 1.0, "m"),
    ("cells_across", "cells_across", 1.0, ""),
    ("cells_along", "cells_along", 1.0, ""),
    ("unit_length_m", "unit_length_m", 1.0, "m"),
    ("cap_height_m", "cap_height_m", 1.0, "m"),
    ("concrete_density_kg_per_m3", "concrete_density_kg_per_m3", 1.0, "kg/m³"),
    ("cap_density_kg_per_m3", "cap_density_kg_per_m3", 1.0, "kg/m³"),
    ("fill_density_kg_per_m3", "fill_density_kg_per_m3", 1.0, "kg/m³"),
    ("fill_density_above_water_kg_per_m3", "fill_density_above_water_kg_per_m3", 1.0, "kg/m³"),
];

const FOUNDATION_KEYS: KeyMap = &[
    ("springs", "springs", 1.0, ""),
    ("mu_static", "mu_static", 1.0, "-"),
    ("mu_dynamic", "mu_dynamic", 1.0, "-"),
    ("e100_pa", "e100_kpa", 1e3, "kPa"),
    ("poisson", "poisson", 1.0, "-"),
    ("density_kg_per_m3", "density_kg_per_m3", 1.0, "kg/m³"),
    ("reference_stress_pa", "reference_stress_kpa", 1e3, "kPa"),
    ("kx_n_per_m", "kx_kn_per_m", 1e3, "kN/m"),
    ("ky_n_per_m", "ky_kn_per_m", 1e3, "kN/m"),
    ("damping_ns_per_m", "damping_kns_per_m", 1e3, "kN·s/m"),
    ("vertical_damping_factor", "vertical_damping_factor", 1.0, "-"),
    ("added_mass_depth_m", "added_mass_depth_m", 1.0, "m"),
];

const SOLVER_KEYS: KeyMap = &[
    ("dt_s", "dt_s", 1.0, "s"),
    ("gamma", "gamma", 1.0, "-"),
    ("beta", "beta", 1.0, "-"),
    ("max_iterations", "max_iterations", 1.0, ""),
    ("max_substep_levels", "max_substep_levels", 1.0, ""),
    ("tolerance", "tolerance", 1.0, "relative to the weight in water"),
    ("output_interval_s", "output_interval_s", 1.0, "s"),
    ("dt_min_s", "dt_min_s", 1.0, "s"),
    ("dt_max_s", "dt_max_s", 1.0, "s"),
    ("error_tolerance_m", "error_tolerance_m", 1.0, "m of local displacement error per step"),
];

const LOAD_KEYS: KeyMap = &[
    ("rise_time_s", "rise_time_s", 1.0, "s"),
    ("start_time_s", "start_time_s", 1.0, "s"),
    ("ramp_time_s", "ramp_time_s", 1.0, "s"),
    ("peak_horizontal_n", "peak_horizontal_kn", 1e3, "kN"),
    ("peak_uplift_n", "peak_uplift_kn", 1e3, "kN"),
    ("peak_moment_nm", "peak_horizontal_kn", 1e3, "kN"),
    ("horizontal_lever_m", "horizontal_lever_m", 1.0, "m above the base, at most the caisson height"),
    ("uplift_lever_m", "uplift_lever_m", 1.0, "m from the heel, at most the base width"),
];

/// A parameter error reported under the key of `table` (e.g. `[caisson]`), in the key's unit,
/// the value as a key's is read ([`fmt_value`]).
pub(crate) fn keyed(table: &str, map: KeyMap, e: ParamError) -> ScenarioError {
    let (key, divisor, unit) =
        map.iter().find(|(q, ..)| *q == e.quantity).map(|(_, k, d, u)| (*k, *d, *u)).unwrap_or((e.quantity, 1.0, ""));
    ScenarioError::range(
        &format!("{table} {key}"),
        fmt_value(e.value / divisor),
        e.allowed.describe(1.0 / divisor, unit),
    )
}

/// The keys of quantities over several tables: (quantity, `[table] key`, the key's unit), for
/// quantities in SI that the file gives in the same unit.
type NamedKeys = &'static [(&'static str, &'static str, &'static str)];

/// A parameter error under its key of `keys`, the value as a key's is read ([`fmt_value`]).
pub(crate) fn keyed_in(keys: NamedKeys, e: ParamError) -> ScenarioError {
    let (key, unit) = keys.iter().find(|(q, ..)| *q == e.quantity).map_or((e.quantity, ""), |(_, k, u)| (*k, *u));
    ScenarioError::range(key, fmt_value(e.value), e.allowed.describe(1.0, unit))
}

/// The whole scenario file as written (units as in the keys).
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct ScenarioFile {
    #[serde(default)]
    pub model: ModelTable,
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
    pub size: Option<size::SizeTable>,
}

/// `[model]`: which reading of the seed sets the defaults.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct ModelTable {
    /// `"consistent"` (default) or `"seed-2011"` ([`crate::Profile`]).
    pub profile: Option<String>,
}

/// `[caisson]`: geometry and mass (docs/model.md §8.2), or geometry and construction (§8.4).
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
    /// `"coupled"` (exact rigid-body mass matrix about the base centre) or `"diagonal"` (the
    /// seed's Eq. 24). Default: the profile's.
    pub mass_matrix: Option<String>,
    // The construction route (instead of the weight and mass; docs/model.md §8.4).
    /// Thickness of the outer walls, m.
    pub wall_thickness_m: Option<f64>,
    /// Thickness of the base slab, m.
    pub slab_thickness_m: Option<f64>,
    /// Thickness of the partition walls, m (needed with more than one cell).
    pub partition_thickness_m: Option<f64>,
    /// Cells across (in the wave direction). Default 1.
    pub cells_across: Option<i64>,
    /// Cells along one caisson (alongshore). Default 1.
    pub cells_along: Option<i64>,
    /// Alongshore length of one caisson as built, m. Default `length_m`.
    pub unit_length_m: Option<f64>,
    /// Height of the concrete cap, m. Default 0.
    pub cap_height_m: Option<f64>,
    /// Walls and slab, kg/m³. Default 2450 (reinforced concrete).
    pub concrete_density_kg_per_m3: Option<f64>,
    /// The cap, kg/m³. Default 2300 (plain concrete).
    pub cap_density_kg_per_m3: Option<f64>,
    /// The fill below still water, kg/m³. Default 2000 (saturated sand).
    pub fill_density_kg_per_m3: Option<f64>,
    /// The fill above still water, kg/m³. Default 1800 (moist sand).
    pub fill_density_above_water_kg_per_m3: Option<f64>,
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
    /// The accelerators: `"auto"` (every one, the default) or `"none"` (the plain path).
    pub accel: Option<String>,
}

/// Parse scenario text. `path` is used in messages only.
pub fn parse_str(text: &str, path: &Path) -> Result<ScenarioFile, ScenarioError> {
    let file = parse_file(text, path)?;
    if let Ok(table) = toml::from_str::<toml::Table>(text) {
        check_magnitudes("", &toml::Value::Table(table))?;
    }
    Ok(file)
}

pub use crate::MAX_MAGNITUDE;

/// Refuse a number beyond [`MAX_MAGNITUDE`] anywhere in `v` (`key`: its place, `[table] key`).
fn check_magnitudes(key: &str, v: &toml::Value) -> Result<(), ScenarioError> {
    match v {
        toml::Value::Float(x) if x.is_finite() && x.abs() > MAX_MAGNITUDE => Err(ScenarioError::range(
            key,
            format!("{x:e}"),
            format!("must be at most {MAX_MAGNITUDE:e} in magnitude (a number this large overflows once converted to SI units)"),
        )),
        toml::Value::Table(t) => t.iter().try_for_each(|(k, x)| {
            let here = match (key, x) {
                ("", toml::Value::Table(_)) => format!("[{k}]"),
                ("", _) => k.to_string(),
                (_, _) if key.starts_with('[') && !key.contains(' ') && !matches!(x, toml::Value::Table(_)) => {
                    format!("{key} {k}")
                }
                (_, _) => format!("{key}.{k}"),
            };
            check_magnitudes(&here, x)
        }),
        toml::Value::Array(a) => a.iter().enumerate().try_for_each(|(i, x)| check_magnitudes(&format!("{key}[{i}]"), x)),
        _ => Ok(()),
    }
}

/// `text` with each number written out in more than 20 characters (an `f64` as Rust's `Display`
/// writes 1e-300 or 1.0999999999999999e-11) in its short form ([`fmt_value`]); the rest as it is
/// (a whole number of 20 digits, as a seed is given, too).
fn short_numbers(text: &str) -> String {
    let number_char = |c: char| c.is_ascii_digit() || matches!(c, '.' | 'e' | 'E' | '-' | '+');
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(start) = rest.find(|c: char| c.is_ascii_digit() || c == '-' || c == '.') {
        out.push_str(&rest[..start]);
        let len = rest[start..].find(|c: char| !number_char(c)).unwrap_or(rest.len() - start);
        let token = &rest[start..start + len];
        match token.parse::<f64>() {
            Ok(v) if token.len() > 20 => out.push_str(&fmt_value(v)),
            _ => out.push_str(token),
        }
        rest = &rest[start + len..];
    }
    out.push_str(rest);
    out
}

/// A value as the messages print it ([`crate::fmt_value`]).
pub(crate) fn fmt_value(v: f64) -> String {
    crate::fmt_value(v)
}

fn parse_file(text: &str, path: &Path) -> Result<ScenarioFile, ScenarioError> {
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
        if let Some(wrong) = wrong_type(text, path, e.message(), line) {
            return wrong;
        }
        if let Some(large) = too_large(text, e.message(), line) {
            return large;
        }
        // A carriage return alone (old Mac line ends, a line end lost in a transfer): TOML ends
        // lines with LF or CR LF, and the parser says only what it expected.
        if let Some(at) = text.match_indices('\r').map(|(i, _)| i).find(|&i| !text[i + 1..].starts_with('\n')) {
            let line = text[..at].matches('\n').count() + 1;
            return ScenarioError::Syntax {
                path: path.to_path_buf(),
                line,
                column: at - text[..at].rfind('\n').map_or(0, |i| i + 1) + 1,
                message: "a carriage return (CR) without a line feed: TOML lines end in LF or CR LF; convert the file's line ends (`mac2unix`, or save it with Unix or Windows line ends)".into(),
                source_line: String::new(),
            };
        }
        let source_line =
            if line > 0 { text.lines().nth(line - 1).unwrap_or("").trim().to_string() } else { String::new() };
        ScenarioError::Syntax {
            path: path.to_path_buf(),
            line,
            column,
            message: match e.message().trim() {
                "" => "this is not valid TOML (a line is `key = value` or a `[table]` header)".to_string(),
                m => m.to_string(),
            },
            source_line,
        }
    })
}

/// A whole number beyond TOML's integers (a seed of 20 digits), named by its key: the parser
/// says only "number too large to fit in target type". `line`: where it points (1-based).
fn too_large(text: &str, message: &str, line: usize) -> Option<ScenarioError> {
    if !message.contains("too large to fit") || line == 0 {
        return None;
    }
    let lines: Vec<&str> = text.lines().collect();
    let (key, value) = lines.get(line - 1)?.split('#').next()?.split_once('=')?;
    let table = lines[..line - 1].iter().rev().map(|l| l.trim()).find(|l| l.starts_with('['))?;
    Some(ScenarioError::range(
        &format!("{table} {}", key.trim()),
        value.trim(),
        format!("must be a whole number of at most {} (the largest a TOML file holds)", i64::MAX),
    ))
}

/// A value of the wrong kind, in engineering words: "`[caisson] width_m` must be a number (m), got
/// the string \"20\"" instead of serde's "invalid type: string \"20\", expected f64". `message` is
/// the parser's, `line` where it points (0: unknown). The parser does not say which key it was
/// reading; the file is read again as plain TOML values, whose deserializer names the key path.
/// `None` if the error is of another kind.
fn wrong_type(text: &str, path: &Path, message: &str, line: usize) -> Option<ScenarioError> {
    message.strip_prefix("invalid type: ")?;
    let table: toml::Table = toml::from_str(text).ok()?;
    let root = toml::Value::Table(table);
    let again = ScenarioFile::deserialize(root.clone()).err()?;
    let shown = again.to_string();
    let first = shown.lines().next()?.trim();
    let keys: Vec<&str> = shown.lines().find_map(|l| l.strip_prefix("in `")?.strip_suffix('`'))?.split('.').collect();
    let (got, expected) = first.strip_prefix("invalid type: ")?.rsplit_once(", expected ")?;
    let last = *keys.last()?;
    let key = match keys.len() {
        1 => format!("[{last}]"),
        n => format!("[{}] {last}", keys[..n - 1].join(".")),
    };
    let unit = unit_of(last).map_or(String::new(), |u| format!(" ({u})"));
    let kind = |e: &str| -> String {
        match e {
            "f64" | "f32" => format!("a number{unit}"),
            "i64" | "i32" | "u64" | "u32" | "usize" => format!("a whole number{unit}"),
            "a boolean" => "true or false (without quotes)".into(),
            "a string" => "text in quotes".into(),
            "a sequence" if unit.is_empty() => "a list in brackets".into(),
            "a sequence" => format!("a list of numbers in brackets{unit}"),
            e if e.starts_with("struct ") => "a table".into(),
            e => e.into(),
        }
    };
    // A wrong element of a list: the value at the key is a list.
    let value = keys.iter().try_fold(&root, |v, k| v.get(k));
    let in_list = matches!(value, Some(toml::Value::Array(_))) && expected != "a sequence" && got != "sequence";
    // serde's words for the value: string "20", floating point `2.5`, integer `5`, boolean `true`,
    // sequence, map.
    let mut got = match (got.strip_prefix("string "), got.split('`').nth(1)) {
        (Some(s), _) => format!("the string {s}"),
        // A number written out long by serde (5e-324: 324 digits) in its short form.
        (None, Some(v)) if v.len() > 20 => v.parse::<f64>().map_or_else(|_| v.to_string(), fmt_value),
        (None, Some(v)) => v.to_string(),
        _ if got == "sequence" => "a list".into(),
        _ if got == "map" => "a table".into(),
        _ => got.to_string(),
    };
    let expected = if in_list {
        got.push_str(" in the list");
        match expected {
            "f64" | "f32" => format!("a list of numbers{unit}"),
            e => format!("a list of {}", kind(e)),
        }
    } else {
        kind(expected)
    };
    // The line is the parser's when both readings stopped at the same error.
    let line = (line > 0 && first == message.trim()).then_some(line);
    Some(ScenarioError::WrongType { path: path.to_path_buf(), line, key, expected, got })
}

/// The unit of a key from its suffix (docs/scenario.md: key names carry their unit).
fn unit_of(key: &str) -> Option<&'static str> {
    const SUFFIXES: [(&str, &str); 14] = [
        ("_kg_per_m3", "kg/m³"),
        ("_kns_per_m", "kN·s/m"),
        ("_kn_per_m", "kN/m"),
        ("_kg_m2", "kg·m²"),
        ("_knm", "kN·m"),
        ("_kpa", "kPa"),
        ("_kn", "kN"),
        ("_kg", "kg"),
        ("_deg", "degrees"),
        ("_years", "years"),
        ("_h", "h"),
        ("_m", "m"),
        ("_s", "s"),
        ("_pa", "Pa"),
    ];
    SUFFIXES.iter().find(|(s, _)| key.ends_with(s)).map(|(_, u)| *u)
}

/// Read a scenario file, parse it once and validate every table it holds. Relative file names
/// in it (a force series) are taken from the file's directory.
pub fn load(path: &Path) -> Result<Scenario, ScenarioError> {
    let text = read_text(path)?;
    Scenario::from_toml(&text, path, path.parent().unwrap_or(Path::new(".")))
}

/// The text of the scenario file at `path` (at most [`MAX_SCENARIO_BYTES`], a regular file):
/// what [`load`] parses, for a caller that keeps the text (the Python `Scenario.from_toml`).
pub fn read_text(path: &Path) -> Result<String, ScenarioError> {
    read_limited(path, MAX_SCENARIO_BYTES, "a scenario file", "a TOML file")
        .map_err(|message| ScenarioError::Read { path: path.to_path_buf(), message })
}

/// Largest scenario file read, bytes: a thousand times the largest example; a file that never
/// ends (`/dev/zero`) or a data file given by mistake is refused after reading at most this much.
pub const MAX_SCENARIO_BYTES: u64 = 1 << 20;

/// The UTF-8 text of the file at `path` if it holds at most `max` bytes: checked on its size
/// first (a large file is refused without reading it), then while reading (a device or pipe
/// that never ends is read no further than `max` + 1 bytes). `what` names the kind of file in
/// the message, `expected` what it should be.
pub(crate) fn read_limited(path: &Path, max: u64, what: &str, expected: &str) -> Result<String, String> {
    use std::io::Read;
    let limit = || {
        let size = if max >= 1 << 20 { format!("{} MiB", max >> 20) } else { format!("{} KiB", max >> 10) };
        format!("is larger than {size}, the most {what} may be")
    };
    // A FIFO would block the open until a writer comes (for ever, without one), a directory is no
    // file: each is refused before it is opened. A device (`/dev/zero`) is read up to the limit.
    if let Ok(m) = std::fs::metadata(path) {
        if m.is_dir() {
            return Err(format!("is a directory; {expected} is expected"));
        }
        #[cfg(unix)]
        {
            use std::os::unix::fs::FileTypeExt;
            if m.file_type().is_fifo() || m.file_type().is_socket() {
                return Err(format!("is a FIFO or a socket, which could block for ever; {expected} is expected"));
            }
        }
    }
    let file = std::fs::File::open(path).map_err(|e| e.to_string())?;
    if file.metadata().map_err(|e| e.to_string())?.len() > max {
        return Err(limit());
    }
    let mut bytes = Vec::new();
    file.take(max + 1).read_to_end(&mut bytes).map_err(|e| e.to_string())?;
    if bytes.len() as u64 > max {
        return Err(limit());
    }
    String::from_utf8(bytes).map_err(|_| format!("is not UTF-8 text ({expected} is expected)"))
}

/// A validated scenario: the typed parameters of every table of the file (module docs).
///
/// The caisson and the foundation are kept as specified ([`CaissonSpec`], [`FoundationSpec`]) and
/// as built ([`Structure`]); change them with [`Self::with_caisson`] and [`Self::with_foundation`],
/// which rebuild what depends on them (the mass from the weight, a soil-derived stiffness, the
/// wave site), so the two never disagree.
#[derive(Debug, Clone)]
pub struct Scenario {
    profile: Profile,
    water_density_kg_per_m3: f64,
    caisson_spec: CaissonSpec,
    foundation_spec: FoundationSpec,
    structure: Structure,
    /// The `[load]` table; `None` for a scenario that only describes waves.
    pub load: Option<LoadSpec>,
    /// Simulated time of a `[load]` run, s.
    pub duration_s: f64,
    /// `[water]` and `[waves]`.
    pub waves: Option<WaveSetup>,
    /// `[waves] breaking_load` as the file gives it (`None`: the profile's rule).
    breaking_load: Option<BreakingLoad>,
    /// `[campaign]`: its title and conditions ([`Self::campaign`] builds their setups).
    pub campaign: Option<campaign::CampaignSpec>,
    /// `[design]`.
    pub design: Option<DesignParams>,
    /// `[fragility]`.
    pub fragility: Option<FragilityParams>,
    /// Why a `[fragility]` table was refused: only a fragility run says so
    /// ([`Self::fragility_for`]); the other commands do not use the table.
    fragility_refused: Option<ScenarioError>,
    /// Why a `[campaign]` table was refused: only a campaign says so ([`Self::campaign`]).
    campaign_refused: Option<ScenarioError>,
    /// `[size]`.
    pub size: Option<SizeParams>,
    /// Why a `[size]` table was refused: only a sizing says so ([`Self::size_for`]).
    size_refused: Option<ScenarioError>,
}

impl Scenario {
    /// Parse and validate scenario text. `path` names the file in messages; `base_dir` resolves
    /// relative file names (the force series).
    pub fn from_toml(text: &str, path: &Path, base_dir: &Path) -> Result<Scenario, ScenarioError> {
        validate::validate(&parse_str(text, path)?, base_dir)
    }

    /// Refuse `load` on this caisson as a `[load]` of the file is refused (its peaks at most
    /// 10³ W', `coherence.rs`): for a load built outside the file (the Python force series).
    pub fn check_load(&self, load: &LoadSpec) -> Result<(), ScenarioError> {
        coherence::check_load(self.caisson(), load)
    }

    /// The profile that sets the defaults (`[model] profile`).
    pub fn profile(&self) -> Profile {
        self.profile
    }

    /// The scenario under another profile: every choice the file left to the profile changes
    /// (the keys it gave stay), and everything is rebuilt.
    pub fn with_profile(mut self, profile: Profile) -> Result<Scenario, ScenarioError> {
        self.profile = profile;
        self.structure.solver = self.structure.solver.for_profile(profile);
        if let Some(w) = self.waves.as_mut() {
            w.model.options.breaking_load = waves::breaking_load(self.breaking_load, profile);
        }
        let (c, f) = (self.caisson_spec, self.foundation_spec);
        self.rebuilt(c, f)
    }

    /// ρ_w, kg/m³.
    pub fn water_density_kg_per_m3(&self) -> f64 {
        self.water_density_kg_per_m3
    }
    /// The structure (caisson, foundation, solver) every analysis runs on.
    pub fn structure(&self) -> &Structure {
        &self.structure
    }
    pub fn caisson(&self) -> &Caisson {
        &self.structure.caisson
    }
    pub fn foundation(&self) -> &Foundation {
        &self.structure.foundation
    }
    pub fn solver(&self) -> SolverParams {
        self.structure.solver
    }
    /// The caisson as specified.
    pub fn caisson_spec(&self) -> &CaissonSpec {
        &self.caisson_spec
    }
    /// The foundation as specified.
    pub fn foundation_spec(&self) -> &FoundationSpec {
        &self.foundation_spec
    }

    /// The scenario with the caisson changed by `change`: the caisson, its foundation (a
    /// soil-derived stiffness follows the weight and base) and the wave site are rebuilt. Errors
    /// name the `[caisson]` or `[foundation]` key.
    pub fn with_caisson(self, change: impl FnOnce(&mut CaissonSpec)) -> Result<Scenario, ScenarioError> {
        let (mut spec, foundation) = (self.caisson_spec, self.foundation_spec);
        change(&mut spec);
        self.rebuilt(spec, foundation)
    }

    /// The scenario with the foundation changed by `change` (rebuilt for the same caisson).
    pub fn with_foundation(self, change: impl FnOnce(&mut FoundationSpec)) -> Result<Scenario, ScenarioError> {
        let (caisson, mut spec) = (self.caisson_spec, self.foundation_spec);
        change(&mut spec);
        self.rebuilt(caisson, spec)
    }

    /// The scenario with other solver controls, checked against the run's duration.
    pub fn with_solver(mut self, solver: SolverParams) -> Result<Scenario, ScenarioError> {
        solver.check_run(self.duration_s).map_err(|e| keyed("[solver]", SOLVER_KEYS, e))?;
        self.structure.solver = solver;
        coherence::check_time_step(&self.structure)?;
        Ok(self)
    }

    fn rebuilt(
        mut self,
        caisson_spec: CaissonSpec,
        foundation_spec: FoundationSpec,
    ) -> Result<Scenario, ScenarioError> {
        let (rho_w, profile) = (self.water_density_kg_per_m3, self.profile);
        let caisson = caisson_spec.build(rho_w, profile).map_err(|e| keyed("[caisson]", CAISSON_KEYS, e))?;
        let foundation =
            foundation_spec.build(&caisson, rho_w, profile).map_err(|e| keyed("[foundation]", FOUNDATION_KEYS, e))?;
        if let Some(w) = self.waves.as_mut() {
            crate::analysis::site::place_caisson(&mut w.model.site, &caisson);
        }
        self.caisson_spec = caisson_spec;
        self.foundation_spec = foundation_spec;
        self.structure.caisson = caisson;
        self.structure.foundation = foundation;
        self.structure.profile = profile;
        coherence::check_time_step(&self.structure)?;
        if let Some(d) = &self.design {
            coherence::check_floating(&self.structure.caisson, rho_w, d)?;
        }
        Ok(self)
    }

    /// The `[waves]` of the scenario, or an error saying that `what` needs them.
    pub fn waves_for(&self, what: &str) -> Result<&WaveSetup, ScenarioError> {
        self.waves.as_ref().ok_or_else(|| {
            ScenarioError::missing(
                "[waves]",
                format!("{what} needs a [waves] table (kind, height, period_s) and the depths of [water]"),
            )
        })
    }

    /// The `[design]` of the scenario, or an error saying it is missing.
    pub fn design_for(&self, what: &str) -> Result<&DesignParams, ScenarioError> {
        self.design.as_ref().ok_or_else(|| {
            ScenarioError::missing(
                "[design]",
                format!("{what} needs a [design] table: storm_distribution, its parameters, life_years, lives"),
            )
        })
    }

    /// Whether the file has a `[fragility]` table (valid or not: [`Self::fragility_for`] says).
    pub fn has_fragility_table(&self) -> bool {
        self.fragility.is_some() || self.fragility_refused.is_some()
    }

    /// The `[fragility]` of the scenario, or why not: missing, or refused.
    pub fn fragility_for(&self, what: &str) -> Result<&FragilityParams, ScenarioError> {
        if let Some(e) = &self.fragility_refused {
            return Err(e.clone());
        }
        self.fragility.as_ref().ok_or_else(|| {
            ScenarioError::missing(
                "[fragility]",
                format!("{what} needs a [fragility] table with significant_heights_m (and storms, limits_m, ...)"),
            )
        })
    }

    /// The `[size]` of the scenario, or an error saying it is missing.
    pub fn size_for(&self, what: &str) -> Result<&SizeParams, ScenarioError> {
        if let Some(e) = &self.size_refused {
            return Err(e.clone());
        }
        self.size.as_ref().ok_or_else(|| {
            ScenarioError::missing(
                "[size]",
                format!("{what} needs a [size] table: range_m and a criterion (expected_sliding_m, ...)"),
            )
        })
    }

    /// The wave-train test of the scenario's `[waves]`.
    pub fn train_case(&self) -> Result<TrainCase<'_>, ScenarioError> {
        Ok(TrainCase { structure: &self.structure, waves: self.waves_for("a wave-train run")? })
    }

    /// The storms' case of a design or fragility run: the structure, the site's wave loads,
    /// the rigid-block μ (`[waves] rigid_block_mu`, default μ_s), where a life ends (the
    /// failure limits of `[design]`, if any, for this caisson's width) and the lifetime's fast
    /// paths of `[solver] accel` ([`crate::dynamics::Accel`]): the screen if both `screen` (the
    /// design's `[design] screen`, or the caller's) and the policy have it, and the screen's load
    /// bound, drawing above the threshold and stick bound as the policy has them (they act only
    /// with the screen; so `[design] screen = false` keeps the fingerprint it had).
    pub fn storm_case(&self, screen: bool) -> Result<StormCase<'_>, ScenarioError> {
        let w = self.waves_for("a design or fragility run")?;
        if let Some(d) = &self.design {
            // At high tide the caisson is more submerged: its weight in water must stay positive.
            coherence::check_high_water(&self.structure.caisson, self.water_density_kg_per_m3, d)?;
        }
        let accel = self.structure.solver.accel;
        let screen = screen && accel.screen;
        Ok(StormCase {
            structure: &self.structure,
            model: &w.model,
            rigid_block_mu: w.rigid_block_mu(&self.structure.foundation),
            screen,
            screen_load_bound: accel.screen_load_bound,
            stick_bound: accel.stick_bound,
            settle_rotation: true,
            draws: if accel.draw_above_threshold { WaveDraws::AboveThreshold } else { WaveDraws::EveryWave },
            failure: self.design.as_ref().map(|d| d.failure_limits(self.structure.caisson.width_m)),
            heel_screen_pa: self.design.as_ref().map_or(f64::INFINITY, DesignParams::heel_screen_pa),
        })
    }

    /// The conditions of `[campaign]` with their structures and waves (each condition's height,
    /// weight in water and regime set on this scenario's typed parameters).
    pub fn campaign(&self) -> Result<Campaign, ScenarioError> {
        if let Some(e) = &self.campaign_refused {
            return Err(e.clone());
        }
        let spec = self.campaign.as_ref().ok_or_else(|| {
            ScenarioError::missing(
                "[campaign]",
                "add a [campaign] table with heights_m and weights_in_water_kn (a grid) or a conditions list",
            )
        })?;
        campaign::build(self, spec)
    }

    /// Whether the file has a `[campaign]` table (valid or not: [`Self::campaign`] says).
    pub fn has_campaign_table(&self) -> bool {
        self.campaign.is_some() || self.campaign_refused.is_some()
    }
}
