//! Wave-force time histories acting on the caisson, and the pressure models behind them.
//!
//! # Conventions (used everywhere in the crate)
//!
//! * x is positive **shoreward**, y is positive **upward** (uplift positive).
//! * Moments and the rotation θ are about the **centre of the caisson base**, positive
//!   **clockwise when looking alongshore with the sea on the left**: the sense in which a shoreward
//!   wave force overturns the caisson (the seaward toe lifts). A horizontal force `fx` acting at a
//!   height `y_l` above the base gives `m = fx · y_l`; an upward force `fy` acting a distance
//!   `x_l` from the heel (the shoreward rear corner) gives `m = fy · (x_l − B/2)`.
//! * Forces returned by a [`LoadHistory`] are **totals on the caisson** (N and N·m), already
//!   multiplied by the alongshore length where the underlying model is per metre.
//!
//! The engine (`dynamics`) only sees the [`LoadHistory`] trait; new load models plug in there.

pub mod breaking_load;
pub mod generator;
pub mod goda;
pub mod history;
pub mod impact;
pub mod model;
pub mod profile;
pub mod pulse;
pub mod regime;
pub mod risetime;
pub mod safety;
pub mod sainflou;
pub mod series;
pub mod shapes;

/// The load of a single run (a `[load]` table): an analytic pulse or a measured series.
#[derive(Debug, Clone)]
pub enum LoadSpec {
    Triangle(pulse::TrianglePulse),
    Static(pulse::StaticRamp),
    Series(series::ForceSeries),
}

impl LoadSpec {
    /// The largest |F_x|, |F_y| and |M| of the load over time (each on its own), N and N·m.
    pub fn peak_abs(&self) -> WaveForce {
        let abs = |w: WaveForce| WaveForce { fx_n: w.fx_n.abs(), fy_n: w.fy_n.abs(), m_nm: w.m_nm.abs() };
        match self {
            LoadSpec::Triangle(l) => abs(l.peak),
            LoadSpec::Static(l) => abs(l.peak),
            LoadSpec::Series(l) => l.peak_abs(),
        }
    }
}

impl LoadHistory for LoadSpec {
    #[inline]
    fn at(&self, t_s: f64) -> WaveForce {
        match self {
            LoadSpec::Triangle(l) => l.at(t_s),
            LoadSpec::Static(l) => l.at(t_s),
            LoadSpec::Series(l) => l.at(t_s),
        }
    }
    fn end_time_s(&self) -> Option<f64> {
        match self {
            LoadSpec::Triangle(l) => l.end_time_s(),
            LoadSpec::Static(l) => l.end_time_s(),
            LoadSpec::Series(l) => l.end_time_s(),
        }
    }
    fn next_breakpoint_s(&self, t_s: f64) -> f64 {
        match self {
            LoadSpec::Triangle(l) => l.next_breakpoint_s(t_s),
            LoadSpec::Static(l) => l.next_breakpoint_s(t_s),
            LoadSpec::Series(l) => l.next_breakpoint_s(t_s),
        }
    }
}

/// Wave forces on the caisson at one instant (SI, totals; sign conventions in the module docs).
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct WaveForce {
    /// Horizontal force, N, positive shoreward.
    pub fx_n: f64,
    /// Vertical force (uplift), N, positive upward.
    pub fy_n: f64,
    /// Moment about the centre of the base, N·m, positive clockwise (shoreward overturning).
    pub m_nm: f64,
}

impl WaveForce {
    pub const ZERO: WaveForce = WaveForce { fx_n: 0.0, fy_n: 0.0, m_nm: 0.0 };

    /// Force from a horizontal component acting `lever_m` above the base and an uplift acting
    /// `uplift_from_heel_m` from the heel of a base of width `width_m`.
    pub fn from_levers(fx_n: f64, lever_m: f64, fy_n: f64, uplift_from_heel_m: f64, width_m: f64) -> Self {
        WaveForce { fx_n, fy_n, m_nm: fx_n * lever_m + fy_n * (uplift_from_heel_m - 0.5 * width_m) }
    }

    /// The peak of a pulse on a caisson of height `height_m` and base width `width_m`, as
    /// [`Self::from_levers`] if its parts hold: finite forces, the horizontal force's lever from
    /// 0 to the caisson height and the uplift's from 0 to the base width (from the heel).
    pub fn from_levers_on(
        fx_n: f64,
        lever_m: f64,
        fy_n: f64,
        uplift_from_heel_m: f64,
        height_m: f64,
        width_m: f64,
    ) -> Result<Self, crate::ParamError> {
        use crate::check::{between, finite};
        let fx_n = finite("peak_horizontal_n", fx_n)?;
        let fy_n = finite("peak_uplift_n", fy_n)?;
        let lever_m = between("horizontal_lever_m", lever_m, 0.0, height_m)?;
        let uplift_from_heel_m = between("uplift_lever_m", uplift_from_heel_m, 0.0, width_m)?;
        Ok(Self::from_levers(fx_n, lever_m, fy_n, uplift_from_heel_m, width_m))
    }

    pub fn scaled(self, k: f64) -> Self {
        WaveForce { fx_n: self.fx_n * k, fy_n: self.fy_n * k, m_nm: self.m_nm * k }
    }
}

impl std::ops::Add for WaveForce {
    type Output = WaveForce;
    fn add(self, o: WaveForce) -> WaveForce {
        WaveForce { fx_n: self.fx_n + o.fx_n, fy_n: self.fy_n + o.fy_n, m_nm: self.m_nm + o.m_nm }
    }
}

/// A force time history. `at` must be cheap and must not allocate: the engine calls it once per
/// time step (and per sub-step).
pub trait LoadHistory: Send + Sync {
    /// Wave forces at time `t_s` (s, measured from the start of the simulation).
    fn at(&self, t_s: f64) -> WaveForce;
    /// Time after which the load is identically zero, if any (used for default durations).
    fn end_time_s(&self) -> Option<f64> {
        None
    }
    /// The first time strictly after `t_s` at which the load has a kink or a jump (the start,
    /// peak and end of an impulse, a sample of a series), or infinity. The adaptive stepper lands
    /// on these times so that no step straddles the onset of a short impulse.
    fn next_breakpoint_s(&self, _t_s: f64) -> f64 {
        f64::INFINITY
    }
}

impl<T: LoadHistory + ?Sized> LoadHistory for Box<T> {
    fn at(&self, t_s: f64) -> WaveForce {
        (**self).at(t_s)
    }
    fn end_time_s(&self) -> Option<f64> {
        (**self).end_time_s()
    }
    fn next_breakpoint_s(&self, t_s: f64) -> f64 {
        (**self).next_breakpoint_s(t_s)
    }
}

/// The first of `times` strictly after `t_s`, or infinity (`times` in any order).
#[inline]
pub(crate) fn first_after(t_s: f64, times: &[f64]) -> f64 {
    times.iter().copied().filter(|&b| b > t_s).fold(f64::INFINITY, f64::min)
}

#[cfg(test)]
mod tests {
    use super::WaveForce;

    #[test]
    fn a_pulse_peak_refuses_non_finite_forces_and_levers_off_the_caisson_naming_them() {
        // A caisson 2 m high with a 1 m base: the levers are at most 2 m and 1 m.
        let at = |fx: f64, lever: f64, fy: f64, uplift: f64| WaveForce::from_levers_on(fx, lever, fy, uplift, 2.0, 1.0);
        let named = |r: Result<WaveForce, crate::ParamError>| r.unwrap_err().quantity;
        assert_eq!(named(at(f64::NAN, 1.0, 0.0, 0.5)), "peak_horizontal_n");
        assert_eq!(named(at(1e3, 1.0, f64::INFINITY, 0.5)), "peak_uplift_n");
        assert_eq!(named(at(1e3, 2.5, 0.0, 0.5)), "horizontal_lever_m");
        assert_eq!(named(at(1e3, 1.0, 0.0, -0.1)), "uplift_lever_m");
        // In range: M = F_x y_l + F_y (x_l − B/2) = 1000·1.5 + 400·(0.9 − 0.5) = 1660 N·m.
        let f = at(1e3, 1.5, 400.0, 0.9).unwrap();
        assert_eq!((f.fx_n, f.fy_n), (1e3, 400.0));
        assert!((f.m_nm - 1660.0).abs() < 1e-9, "{}", f.m_nm);
    }
}
