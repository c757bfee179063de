//! `[waves]`: the incident waves (wave-loads issue). Owned by the `waves`/`loads` work; the
//! dynamic engine does not read it yet.

use serde::Deserialize;

/// `[waves]` as written in the scenario file.
#[derive(Debug, Clone, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct WavesTable {
    /// `"regular"`.
    pub kind: String,
    /// Wave height H at the structure (regular waves), m.
    pub height_m: Option<f64>,
    /// Wave period T, s.
    pub period_s: Option<f64>,
    /// Angle between the wave direction and the normal to the breakwater, degrees. Default 0.
    pub angle_deg: Option<f64>,
}
