//! Time shapes of one wave's load (seed §2.3 Table 2, Eqs. 29 and 31; docs/model.md §6.1, §4.4,
//! §10 items 16-18). Local time τ runs from 0 at the start of the wave to its period T.
//!
//! | name | source | shape (F_max impact, F_qs+ quasi-static, t_r rise, t_d duration) |
//! |---|---|---|
//! | `seed` | seed Eq. 31 (Shimosako et al. 1994 as used by the seed) | max{F_max tri(τ), F_qs+ sin(2πτ/T)} for τ < T/2, tri the symmetric triangle (peak t_r, zero at 2t_r); F_qs− sin(2πτ/T) for τ ≥ T/2 |
//! | `lundgren` | Lundgren (1969) | F_max ½ [1 − cos(π τ/t_r)] for τ ≤ 2 t_r, else 0 |
//! | `goda-1994` | Goda (1994) | F_max τ/t_r (τ < t_r); linear from F_max to F_qs+ (t_r ≤ τ < t_d); F_qs+ (t_d ≤ τ < T/2); 0 after |
//! | `oumeraci-kortenhaus-1994` | Oumeraci & Kortenhaus (1994) | F_max τ/t_r (τ < t_r); F_max (t_d − τ)/(t_d − t_r) (t_r ≤ τ < t_d); 0 after |
//! | `shimosako-takahashi-1994` | Shimosako & Takahashi (1994) | F_max τ/t_r (τ < t_r); F_max (2 − τ/t_r) (t_r ≤ τ < 2t_r); 0 after |
//! | `oumeraci-2001` | Oumeraci et al. (2001), the "church roof" (docs/model.md §4.4) | as `oumeraci-kortenhaus-1994` for τ < t_d, then F_qs+ for t_d ≤ τ < T/2; 0 after |
//!
//! Choices where Table 2 is silent or garbled (documented, configurable through t_d):
//! * Goda (1994): the table gives only the rise and the F_qs+ plateau "for t ≥ t_d"; the segment
//!   t_r…t_d is taken as a linear decay from F_max to F_qs+.
//! * The F_qs+ plateaus (Goda 1994, Oumeraci et al. 2001) end at T/2, the end of the shoreward
//!   half-wave; the table gives no end.
//! * t_d defaults to 2 t_r (docs/model.md §4.4, §12: the seed's symmetric triangle); t_r ≤ T/4 and
//!   t_d ≤ T/2 (docs/model.md §5.3, §10 item 18).
//! * Eq. 31 is continuous: at τ = t_r both triangle branches give F_max, at 2t_r the triangle is
//!   zero and the sine takes over, at T/2 both halves are zero. The max in Eq. 31 is taken per
//!   axis (F_x and F_y separately, as the seed applies Eq. 31 to each); the moment follows the
//!   branch chosen on each axis with that branch's lever arm.
//!
//! The Table 2 shapes other than `seed` describe the shoreward event only: they have no seaward
//! (Sainflou) half, exactly as printed. Non-breaking waves always use Eq. 29:
//! α_qs F_qs+ sin(2πτ/T) for τ < T/2, F_qs− sin(2πτ/T) for τ ≥ T/2.

use std::f64::consts::PI;

/// The time shape of a breaking (impulsive) wave.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
pub enum LoadShape {
    /// Seed Eq. 31 (default).
    Seed,
    Lundgren,
    Goda1994,
    OumeraciKortenhaus1994,
    ShimosakoTakahashi1994,
    Oumeraci2001,
}

impl LoadShape {
    /// Every shape with its scenario name.
    pub const ALL: [(&'static str, LoadShape); 6] = [
        ("seed", LoadShape::Seed),
        ("lundgren", LoadShape::Lundgren),
        ("goda-1994", LoadShape::Goda1994),
        ("oumeraci-kortenhaus-1994", LoadShape::OumeraciKortenhaus1994),
        ("shimosako-takahashi-1994", LoadShape::ShimosakoTakahashi1994),
        ("oumeraci-2001", LoadShape::Oumeraci2001),
    ];

    pub fn name(self) -> &'static str {
        Self::ALL.iter().find(|(_, s)| *s == self).map(|(n, _)| *n).unwrap_or("seed")
    }

    pub fn from_name(name: &str) -> Option<LoadShape> {
        Self::ALL.iter().find(|(n, _)| *n == name).map(|(_, s)| *s)
    }

    /// Whether the shape uses t_d (otherwise the duration is fixed by t_r).
    pub fn uses_duration(self) -> bool {
        matches!(self, LoadShape::Goda1994 | LoadShape::OumeraciKortenhaus1994 | LoadShape::Oumeraci2001)
    }
}

/// Symmetric triangle of unit peak at t_r, zero at 0 and 2 t_r (seed Eq. 31/37).
#[inline]
pub fn triangle(tau: f64, rise_s: f64) -> f64 {
    if tau <= 0.0 || tau >= 2.0 * rise_s {
        0.0
    } else if tau <= rise_s {
        tau / rise_s
    } else {
        2.0 - tau / rise_s
    }
}

/// Asymmetric triangle of unit peak at t_r, zero at 0 and t_d (> t_r).
#[inline]
pub fn asymmetric_triangle(tau: f64, rise_s: f64, duration_s: f64) -> f64 {
    if tau <= 0.0 || tau >= duration_s {
        0.0
    } else if tau <= rise_s {
        tau / rise_s
    } else {
        (duration_s - tau) / (duration_s - rise_s)
    }
}

/// Lundgren's cosine bell of unit peak at t_r, zero outside [0, 2 t_r].
#[inline]
pub fn cosine_bell(tau: f64, rise_s: f64) -> f64 {
    if tau <= 0.0 || tau >= 2.0 * rise_s {
        0.0
    } else {
        0.5 * (1.0 - (PI * tau / rise_s).cos())
    }
}

/// Weights of the three load components at local time τ of one wave: the load is
/// `impact·a + quasi·b + trough·c`, with separate (a, b) on the horizontal and vertical axes.
/// `trough` is the positive magnitude F_qs− and `c` = sin(2πτ/T) ≤ 0 in the seaward half.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Weights {
    pub impact_x: f64,
    pub quasi_x: f64,
    pub impact_y: f64,
    pub quasi_y: f64,
    pub trough: f64,
}

impl Weights {
    fn same(impact: f64, quasi: f64) -> Self {
        Weights { impact_x: impact, quasi_x: quasi, impact_y: impact, quasi_y: quasi, trough: 0.0 }
    }
}

/// Timing of an impulsive wave: shape, rise time and duration (already clamped).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Impulse {
    pub shape: LoadShape,
    /// t_r, s (≤ T/4).
    pub rise_s: f64,
    /// t_d, s (t_r < t_d ≤ T/2; 2 t_r for the symmetric shapes).
    pub duration_s: f64,
}

/// Weights at local time `tau` of a wave of period `period_s`. `impulse` is `None` for the
/// pulsating Eq. 29. `peaks` = (impact fx, quasi fx, impact fy, quasi fy) decides the per-axis
/// max of Eq. 31.
#[inline]
pub fn weights(tau: f64, period_s: f64, impulse: Option<&Impulse>, peaks: [f64; 4]) -> Weights {
    if !(tau >= 0.0 && tau < period_s) {
        return Weights::default();
    }
    let half = 0.5 * period_s;
    let s = (2.0 * PI * tau / period_s).sin();
    let Some(imp) = impulse else {
        return if tau < half { Weights::same(0.0, s) } else { Weights { trough: s, ..Weights::default() } };
    };
    let (tr, td) = (imp.rise_s, imp.duration_s);
    match imp.shape {
        LoadShape::Seed => {
            if tau >= half {
                return Weights { trough: s, ..Weights::default() };
            }
            let tri = triangle(tau, tr);
            let (ix, qx, iy, qy) = (peaks[0], peaks[1], peaks[2], peaks[3]);
            let (impact_x, quasi_x) = if tri * ix > s * qx { (tri, 0.0) } else { (0.0, s) };
            let (impact_y, quasi_y) = if tri * iy > s * qy { (tri, 0.0) } else { (0.0, s) };
            Weights { impact_x, quasi_x, impact_y, quasi_y, trough: 0.0 }
        }
        LoadShape::Lundgren => Weights::same(cosine_bell(tau, tr), 0.0),
        LoadShape::ShimosakoTakahashi1994 => Weights::same(triangle(tau, tr), 0.0),
        LoadShape::OumeraciKortenhaus1994 => Weights::same(asymmetric_triangle(tau, tr, td), 0.0),
        LoadShape::Goda1994 => {
            if tau < tr {
                Weights::same(tau / tr, 0.0)
            } else if tau < td {
                let w = (tau - tr) / (td - tr);
                Weights::same(1.0 - w, w)
            } else if tau < half {
                Weights::same(0.0, 1.0)
            } else {
                Weights::default()
            }
        }
        LoadShape::Oumeraci2001 => {
            if tau < td {
                Weights::same(asymmetric_triangle(tau, tr, td), 0.0)
            } else if tau < half {
                Weights::same(0.0, 1.0)
            } else {
                Weights::default()
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for (n, s) in LoadShape::ALL {
            assert_eq!(LoadShape::from_name(n), Some(s));
            assert_eq!(s.name(), n);
        }
        assert_eq!(LoadShape::from_name("church"), None);
    }

    #[test]
    fn unit_shapes_peak_at_rise_time() {
        assert_eq!(triangle(0.1, 0.1), 1.0);
        assert_eq!(asymmetric_triangle(0.1, 0.1, 0.5), 1.0);
        assert!((cosine_bell(0.1, 0.1) - 1.0).abs() < 1e-15);
        assert_eq!(triangle(0.2, 0.1), 0.0);
        assert_eq!(weights(-0.1, 1.0, None, [0.0; 4]), Weights::default());
        assert_eq!(weights(f64::NAN, 1.0, None, [0.0; 4]), Weights::default());
    }
}
