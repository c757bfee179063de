//! Analytic load pulses used to verify the engine.
//!
//! * [`TrianglePulse`]: the symmetric triangle of the seed's Eq. 37, peak at `t_r`, zero at `2 t_r`
//!   (also Shimosako & Takahashi 1994 in the seed's Table 2). The uplift, if any, has the same
//!   time shape (docs/model.md §6.3, §10 item 18).
//! * [`StaticRamp`]: a force raised linearly from zero to its peak over a ramp time and then
//!   held, for the quasi-static push of the seed's §5.1 (Fig. 6).

use super::{LoadHistory, WaveForce};
use crate::check::{between, finite, positive};
use crate::ParamError;

/// Symmetric triangular pulse (seed Eq. 37) starting at `start_s`.
#[derive(Debug, Clone, Copy)]
pub struct TrianglePulse {
    /// Peak forces (totals, SI) reached at `start_s + rise_s`.
    pub peak: WaveForce,
    /// Rise time t_r, s (> 0). Duration is 2 t_r.
    pub rise_s: f64,
    /// Start time, s.
    pub start_s: f64,
}

impl TrianglePulse {
    /// A pulse of finite peak forces rising over `rise_s` > 0 from `start_s` (0 to 1e6 s).
    pub fn new(peak: WaveForce, rise_s: f64, start_s: f64) -> Result<Self, ParamError> {
        finite_force(&peak)?;
        Ok(TrianglePulse {
            peak,
            rise_s: positive("rise_time_s", rise_s)?,
            start_s: between("start_time_s", start_s, 0.0, 1e6)?,
        })
    }

    /// Unit shape of Eq. 37 at time `t` after the start.
    #[inline]
    pub fn shape(t: f64, rise_s: f64) -> f64 {
        if t <= 0.0 || t >= 2.0 * rise_s {
            0.0
        } else if t <= rise_s {
            t / rise_s
        } else {
            2.0 - t / rise_s
        }
    }
}

impl LoadHistory for TrianglePulse {
    #[inline]
    fn at(&self, t_s: f64) -> WaveForce {
        self.peak.scaled(Self::shape(t_s - self.start_s, self.rise_s))
    }
    fn end_time_s(&self) -> Option<f64> {
        Some(self.start_s + 2.0 * self.rise_s)
    }
    fn next_breakpoint_s(&self, t_s: f64) -> f64 {
        let s = self.start_s;
        super::first_after(t_s, &[s, s + self.rise_s, s + 2.0 * self.rise_s])
    }
}

/// Force ramped linearly from zero at t = 0 to `peak` at `ramp_s`, then held.
#[derive(Debug, Clone, Copy)]
pub struct StaticRamp {
    pub peak: WaveForce,
    /// Ramp time, s (> 0).
    pub ramp_s: f64,
}

impl StaticRamp {
    /// Finite peak forces reached after `ramp_s` > 0.
    pub fn new(peak: WaveForce, ramp_s: f64) -> Result<Self, ParamError> {
        finite_force(&peak)?;
        Ok(StaticRamp { peak, ramp_s: positive("ramp_time_s", ramp_s)? })
    }
}

fn finite_force(w: &WaveForce) -> Result<(), ParamError> {
    finite("peak_horizontal_n", w.fx_n)?;
    finite("peak_uplift_n", w.fy_n)?;
    finite("peak_moment_nm", w.m_nm)?;
    Ok(())
}

impl LoadHistory for StaticRamp {
    #[inline]
    fn at(&self, t_s: f64) -> WaveForce {
        self.peak.scaled((t_s / self.ramp_s).clamp(0.0, 1.0))
    }
    fn next_breakpoint_s(&self, t_s: f64) -> f64 {
        super::first_after(t_s, &[0.0, self.ramp_s])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triangle_shape_peaks_at_rise_time_and_has_unit_area_times_rise() {
        let tr = 0.37;
        assert_eq!(TrianglePulse::shape(tr, tr), 1.0);
        assert_eq!(TrianglePulse::shape(2.0 * tr, tr), 0.0);
        assert_eq!(TrianglePulse::shape(-0.1, tr), 0.0);
        // Trapezoidal integral of the piecewise-linear shape is exact on a grid containing the kinks.
        let n = 1000;
        let h = 2.0 * tr / n as f64;
        let area: f64 = (0..n)
            .map(|i| 0.5 * h * (TrianglePulse::shape(i as f64 * h, tr) + TrianglePulse::shape((i + 1) as f64 * h, tr)))
            .sum();
        assert!((area - tr).abs() < 1e-12, "area {area}");
    }
}
