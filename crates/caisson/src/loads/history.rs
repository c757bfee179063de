//! Force time histories of trains of waves: F_x, F_y and the moment, consistently (seed Eqs. 29
//! and 31 and the Table 2 shapes of [`super::shapes`]; docs/model.md §6.1, §10 items 16-18).
//!
//! Each wave is a [`WaveEvent`]: its start time, period, the three load components (totals on the
//! caisson, already multiplied by the alongshore length) and, for an impulsive wave, its
//! [`Impulse`] timing. A component carries its horizontal force with its moment (force × height of
//! the resultant above the base) and its vertical force with its moment (force × (distance from
//! the heel − B/2)), so that a weighted sum of components gives forces and the moment about the
//! centre of the base together (sign conventions of [`super`]):
//!
//! * `quasi`: α_qs F_qs+ (Goda P and U with their lever arms, scaled by α_qs of the regime);
//! * `trough`: F_qs− as positive magnitudes (minus the Sainflou trough force and suction), so that
//!   F_qs− sin(2πτ/T) < 0 for τ in (T/2, T) (docs/model.md §10 item 16);
//! * `impact`: F_x,max (seed Eq. 30) and F_y,max (Eq. 32) with the lever arms of docs/model.md §4.3.
//!
//! A [`WaveTrain`] is a list of events ordered by start time; `at(t)` finds the wave by binary
//! search and evaluates its shape. Nothing is allocated after construction. Between events (if the
//! caller leaves gaps) and after the last one the load is zero.

use super::shapes::{weights, Impulse};
use super::{LoadHistory, WaveForce};
use std::f64::consts::PI;
use thiserror::Error;

/// One load component: horizontal and vertical parts, each with its moment about the base centre
/// (totals, N and N·m).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct LoadComponent {
    /// Horizontal part: `fx_n` and `m_nm` = fx · lever (`fy_n` = 0).
    pub x: WaveForce,
    /// Vertical part: `fy_n` and `m_nm` = fy · (distance from the heel − B/2) (`fx_n` = 0).
    pub y: WaveForce,
}

impl LoadComponent {
    /// From forces and lever arms: `fx_n` acting `lever_m` above the base, `fy_n` acting
    /// `uplift_from_heel_m` from the heel of a base `width_m` wide.
    pub fn from_levers(fx_n: f64, lever_m: f64, fy_n: f64, uplift_from_heel_m: f64, width_m: f64) -> Self {
        LoadComponent {
            x: WaveForce::from_levers(fx_n, lever_m, 0.0, 0.0, width_m),
            y: WaveForce::from_levers(0.0, 0.0, fy_n, uplift_from_heel_m, width_m),
        }
    }

    /// Both parts together.
    pub fn total(&self) -> WaveForce {
        self.x + self.y
    }

    /// Both parts multiplied by `k`.
    pub fn scaled(&self, k: f64) -> LoadComponent {
        LoadComponent { x: self.x.scaled(k), y: self.y.scaled(k) }
    }
}

/// One wave of a train.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct WaveEvent {
    /// Start time of the wave, s.
    pub start_s: f64,
    /// Period T, s.
    pub period_s: f64,
    /// α_qs F_qs+ (Goda), totals.
    pub quasi: LoadComponent,
    /// F_qs− magnitudes (Sainflou trough force and suction, positive), totals.
    pub trough: LoadComponent,
    /// F_x,max and F_y,max, totals (zero for a pulsating wave).
    pub impact: LoadComponent,
    /// `None`: pulsating (Eq. 29 shape). `Some`: impulsive, with shape and timing.
    pub impulse: Option<Impulse>,
}

impl WaveEvent {
    /// Build an event. `quasi_plus` is F_qs+ (unscaled) and `alpha_qs` its reduction factor
    /// (docs/model.md §10 item 17); `trough_magnitude` is F_qs− (positive). For an impulsive wave,
    /// t_r is clamped to T/4 and t_d to [t_r, T/2] here (t_d = 2 t_r for the symmetric shapes).
    pub fn new(
        start_s: f64,
        period_s: f64,
        quasi_plus: LoadComponent,
        alpha_qs: f64,
        trough_magnitude: LoadComponent,
        impact: LoadComponent,
        impulse: Option<Impulse>,
    ) -> Self {
        let impulse = impulse.map(|i| {
            let rise_s = i.rise_s.min(0.25 * period_s);
            let duration_s =
                if i.shape.uses_duration() { i.duration_s.clamp(rise_s, 0.5 * period_s) } else { 2.0 * rise_s };
            Impulse { shape: i.shape, rise_s, duration_s }
        });
        WaveEvent {
            start_s,
            period_s,
            quasi: quasi_plus.scaled(alpha_qs),
            trough: trough_magnitude,
            impact: if impulse.is_some() { impact } else { LoadComponent::default() },
            impulse,
        }
    }

    /// The same wave with every force and moment multiplied by `k` (an estimation error of the
    /// wave force, docs/model.md §6.4 step 4).
    pub fn scaled(&self, k: f64) -> WaveEvent {
        WaveEvent { quasi: self.quasi.scaled(k), trough: self.trough.scaled(k), impact: self.impact.scaled(k), ..*self }
    }

    /// End of the wave, s.
    pub fn end_s(&self) -> f64 {
        self.start_s + self.period_s
    }

    /// Local times (from the start of the wave) at which the load may have a kink or a jump: the
    /// start, the impulse's peak, 2 t_r and t_d, the zero crossing T/2 and the end.
    #[inline]
    pub fn breakpoints_local(&self) -> [f64; 6] {
        let (r, d) = self.impulse.map_or((0.0, 0.0), |i| (i.rise_s, i.duration_s));
        [0.0, r, 2.0 * r, d, 0.5 * self.period_s, self.period_s]
    }

    /// Forces at local time `tau_s` (0 ≤ τ < T; zero outside).
    #[inline]
    pub fn at_local(&self, tau_s: f64) -> WaveForce {
        let peaks = [self.impact.x.fx_n, self.quasi.x.fx_n, self.impact.y.fy_n, self.quasi.y.fy_n];
        let w = weights(tau_s, self.period_s, self.impulse.as_ref(), peaks);
        self.impact.x.scaled(w.impact_x)
            + self.quasi.x.scaled(w.quasi_x)
            + self.impact.y.scaled(w.impact_y)
            + self.quasi.y.scaled(w.quasi_y)
            + self.trough.total().scaled(w.trough)
    }

    /// Whether [`Self::at_local_plain`] gives [`Self::at_local`]: a pulsating wave whose impact
    /// is +0 to the bit (as [`Self::new`] leaves it) and whose crest and trough parts are finite.
    pub(crate) fn is_plain(&self) -> bool {
        let zero = |w: WaveForce| [w.fx_n, w.fy_n, w.m_nm].iter().all(|v| v.to_bits() == 0);
        let finite = |w: WaveForce| [w.fx_n, w.fy_n, w.m_nm].iter().all(|v| v.is_finite());
        self.impulse.is_none()
            && zero(self.impact.x)
            && zero(self.impact.y)
            && finite(self.quasi.x)
            && finite(self.quasi.y)
            && finite(self.trough.total())
    }

    /// [`Self::at_local`] of a wave that [`Self::is_plain`], bit for bit, without the terms of
    /// weight 0. Each component of `at_local` is ((((I_x·0 + a) + I_y·0) + b) + T·0) on the crest
    /// half (a, b the crest's parts times sin ωτ, T the trough's total) and ((((I_x·0 + Q_x·0) +
    /// I_y·0) + Q_y·0) + T sin ωτ) on the trough half. With I = +0 and Q, T finite, every zero
    /// product is ±0 and the first +0: +0 + a is a with −0 made +0, and adding ±0 to a sum that is
    /// not −0 leaves it, so the crest half is (a + b) + 0 and the trough half T sin ωτ + 0 (IEEE
    /// 754 round to nearest: x + (±0) = x for x ≠ 0, +0 + (−0) = +0).
    #[inline]
    pub(crate) fn at_local_plain(&self, tau_s: f64) -> WaveForce {
        PlainWave::new(self).at_local(tau_s)
    }
}

/// A wave that [`WaveEvent::is_plain`], with what its evaluation needs held ready: the start,
/// the period and its half, the crest's two parts and the trough's total.
#[derive(Debug, Clone, Copy, PartialEq)]
struct PlainWave {
    start_s: f64,
    period_s: f64,
    half_s: f64,
    crest: LoadComponent,
    trough: WaveForce,
}

impl PlainWave {
    #[inline]
    fn new(e: &WaveEvent) -> Self {
        PlainWave {
            start_s: e.start_s,
            period_s: e.period_s,
            half_s: 0.5 * e.period_s,
            crest: e.quasi,
            trough: e.trough.total(),
        }
    }

    /// [`WaveEvent::at_local_plain`].
    #[inline]
    fn at_local(&self, tau_s: f64) -> WaveForce {
        if !(tau_s >= 0.0 && tau_s < self.period_s) {
            return WaveForce::ZERO;
        }
        let s = (2.0 * PI * tau_s / self.period_s).sin();
        if tau_s < self.half_s {
            let (x, y) = (self.crest.x, self.crest.y);
            WaveForce {
                fx_n: (x.fx_n * s + y.fx_n * s) + 0.0,
                fy_n: (x.fy_n * s + y.fy_n * s) + 0.0,
                m_nm: (x.m_nm * s + y.m_nm * s) + 0.0,
            }
        } else {
            let t = self.trough;
            WaveForce { fx_n: t.fx_n * s + 0.0, fy_n: t.fy_n * s + 0.0, m_nm: t.m_nm * s + 0.0 }
        }
    }
}

/// Errors building a wave train.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum TrainError {
    #[error("wave {index}: {what} = {value} must be a finite number{need}")]
    BadNumber { index: usize, what: &'static str, value: f64, need: &'static str },
    #[error("wave {index} starts at {start_s} s, before the previous wave ends at {previous_end_s} s")]
    Overlap { index: usize, start_s: f64, previous_end_s: f64 },
}

/// A train of waves ordered in time: the [`LoadHistory`] of the wave-load models.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct WaveTrain {
    events: Vec<WaveEvent>,
    /// [`WaveEvent::is_plain`] of each event.
    plain: Vec<bool>,
    /// The one wave of a train of one plain wave (the lifetime's trains), evaluated without the
    /// search for the wave and the checks of its kind.
    single: Option<PlainWave>,
}

impl WaveTrain {
    /// Check and wrap events: finite numbers, periods > 0, starts ≥ the previous wave's end
    /// (a relative tolerance of 1e-12 absorbs round-off in summed periods).
    pub fn new(events: Vec<WaveEvent>) -> Result<Self, TrainError> {
        let mut prev_end = f64::NEG_INFINITY;
        for (index, e) in events.iter().enumerate() {
            check_event(index, e)?;
            if e.start_s < prev_end - 1e-12 * prev_end.abs().max(1.0) {
                return Err(TrainError::Overlap { index, start_s: e.start_s, previous_end_s: prev_end });
            }
            prev_end = e.end_s();
        }
        let plain: Vec<bool> = events.iter().map(WaveEvent::is_plain).collect();
        let single = (plain == [true]).then(|| PlainWave::new(&events[0]));
        Ok(WaveTrain { events, plain, single })
    }

    /// Make this the train of the one wave `event` (checked as by [`Self::new`]), reusing the
    /// train's storage: no allocation once it has held a wave. On error the train is unchanged.
    pub fn set_single(&mut self, event: WaveEvent) -> Result<(), TrainError> {
        check_event(0, &event)?;
        self.events.clear();
        self.plain.clear();
        let plain = event.is_plain();
        self.plain.push(plain);
        self.single = plain.then(|| PlainWave::new(&event));
        self.events.push(event);
        Ok(())
    }

    pub fn events(&self) -> &[WaveEvent] {
        &self.events
    }

    /// End of the last wave, s (0 for an empty train).
    pub fn duration_s(&self) -> f64 {
        self.events.last().map_or(0.0, |e| e.end_s())
    }
}

/// The checks of one event of a train (finite numbers, positive period and rise time).
fn check_event(index: usize, e: &WaveEvent) -> Result<(), TrainError> {
    if !e.start_s.is_finite() {
        return Err(TrainError::BadNumber { index, what: "start_s", value: e.start_s, need: "" });
    }
    if !(e.period_s > 0.0 && e.period_s.is_finite()) {
        return Err(TrainError::BadNumber { index, what: "period_s", value: e.period_s, need: " > 0" });
    }
    for (what, v) in [
        ("impact fx", e.impact.x.fx_n),
        ("impact fy", e.impact.y.fy_n),
        ("quasi-static fx", e.quasi.x.fx_n),
        ("quasi-static fy", e.quasi.y.fy_n),
        ("trough fx", e.trough.x.fx_n),
        ("trough fy", e.trough.y.fy_n),
        ("impact moment", e.impact.total().m_nm),
        ("quasi-static moment", e.quasi.total().m_nm),
        ("trough moment", e.trough.total().m_nm),
    ] {
        if !v.is_finite() {
            return Err(TrainError::BadNumber { index, what, value: v, need: "" });
        }
    }
    if let Some(i) = e.impulse {
        if !(i.rise_s > 0.0 && i.rise_s.is_finite()) {
            return Err(TrainError::BadNumber { index, what: "rise time", value: i.rise_s, need: " > 0" });
        }
    }
    Ok(())
}

impl WaveTrain {
    /// [`LoadHistory::at`] of a train that is not one plain wave: the wave by binary search.
    #[inline(never)]
    fn at_searched(&self, t_s: f64) -> WaveForce {
        let j = self.events.partition_point(|e| e.start_s <= t_s);
        if j == 0 {
            return WaveForce::ZERO;
        }
        let e = &self.events[j - 1];
        if self.plain[j - 1] {
            e.at_local_plain(t_s - e.start_s)
        } else {
            e.at_local(t_s - e.start_s)
        }
    }
}

impl LoadHistory for WaveTrain {
    /// The one plain wave of a train inline (the lifetime's waves, at every time step), any
    /// other train out of line.
    #[inline(always)]
    fn at(&self, t_s: f64) -> WaveForce {
        match &self.single {
            // The one wave: zero before its start, as the search finds.
            Some(w) if w.start_s <= t_s => w.at_local(t_s - w.start_s),
            Some(_) => WaveForce::ZERO,
            None => self.at_searched(t_s),
        }
    }
    fn end_time_s(&self) -> Option<f64> {
        Some(self.duration_s())
    }
    fn next_breakpoint_s(&self, t_s: f64) -> f64 {
        let j = self.events.partition_point(|e| e.start_s <= t_s);
        if j == 0 {
            return self.events.first().map_or(f64::INFINITY, |e| e.start_s);
        }
        let e = &self.events[j - 1];
        let tau = t_s - e.start_s;
        let local = super::first_after(tau, &e.breakpoints_local());
        let next_start = self.events.get(j).map_or(f64::INFINITY, |n| n.start_s);
        (e.start_s + local).min(next_start)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::loads::shapes::LoadShape;

    fn comp(fx: f64, fy: f64) -> LoadComponent {
        LoadComponent::from_levers(fx, 0.3, fy, 0.52, 0.78)
    }

    #[test]
    fn moment_follows_levers() {
        let c = comp(1000.0, 200.0);
        let t = c.total();
        assert!((t.m_nm - (1000.0 * 0.3 + 200.0 * (0.52 - 0.39))).abs() < 1e-12);
    }

    #[test]
    fn train_finds_each_wave_and_is_zero_outside() {
        let mk =
            |start| WaveEvent::new(start, 2.0, comp(100.0, 10.0), 1.0, comp(50.0, 5.0), LoadComponent::default(), None);
        let train = WaveTrain::new(vec![mk(0.0), mk(2.0), mk(5.0)]).unwrap();
        // Quarter period of each wave: the sine peak, α_qs F_qs+.
        for t0 in [0.0, 2.0, 5.0] {
            assert!((train.at(t0 + 0.5).fx_n - 100.0).abs() < 1e-9);
            assert!((train.at(t0 + 1.5).fx_n + 50.0).abs() < 1e-9);
        }
        assert_eq!(train.at(-1.0), WaveForce::ZERO);
        assert_eq!(train.at(4.5), WaveForce::ZERO);
        assert_eq!(train.at(7.0), WaveForce::ZERO);
        assert_eq!(train.end_time_s(), Some(7.0));
    }

    #[test]
    fn overlapping_or_bad_waves_are_rejected() {
        let mk =
            |start, t| WaveEvent::new(start, t, comp(1.0, 1.0), 1.0, comp(1.0, 1.0), LoadComponent::default(), None);
        assert!(matches!(WaveTrain::new(vec![mk(0.0, 2.0), mk(1.0, 2.0)]), Err(TrainError::Overlap { index: 1, .. })));
        assert!(matches!(WaveTrain::new(vec![mk(0.0, 0.0)]), Err(TrainError::BadNumber { .. })));
        assert!(matches!(WaveTrain::new(vec![mk(f64::NAN, 1.0)]), Err(TrainError::BadNumber { .. })));
    }

    /// The plain evaluation of a pulsating wave gives `at_local`'s bits, signed zeros included:
    /// crest and trough parts of either sign and zero (the sums then ±0), at 2 001 local times
    /// from before the start to after the end (both halves, T/2 and T themselves), and on a train.
    #[test]
    fn plain_pulsating_waves_give_the_same_bits() {
        let values = [0.0, -0.0, 1234.5, -987.25, 3.0e-300];
        let mut checked = 0;
        for (i, &a) in values.iter().enumerate() {
            for &b in &values[i..] {
                let quasi = LoadComponent {
                    x: WaveForce { fx_n: a, fy_n: -0.0, m_nm: a * 0.3 },
                    y: WaveForce { fx_n: 0.0, fy_n: b, m_nm: -b },
                };
                let trough = LoadComponent {
                    x: WaveForce { fx_n: b, fy_n: 0.0, m_nm: -0.0 },
                    y: WaveForce { fx_n: -0.0, fy_n: a, m_nm: b * 0.1 },
                };
                let e = WaveEvent::new(0.0, 2.5, quasi, 0.9, trough, LoadComponent::default(), None);
                assert!(e.is_plain());
                for k in 0..=2000 {
                    let tau = -0.1 + 2.7 * k as f64 / 2000.0;
                    for tau in [tau, 1.25, 2.5, 0.0] {
                        let (w, p) = (e.at_local(tau), e.at_local_plain(tau));
                        for (u, v) in [(w.fx_n, p.fx_n), (w.fy_n, p.fy_n), (w.m_nm, p.m_nm)] {
                            assert_eq!(u.to_bits(), v.to_bits(), "a {a} b {b} tau {tau}: {u} vs {v}");
                        }
                        checked += 1;
                    }
                }
                let train = WaveTrain::new(vec![e]).unwrap();
                assert_eq!(train.at(0.7), e.at_local(0.7));
            }
        }
        assert_eq!(checked, 15 * 2001 * 4);
        // An impulsive wave, or one with an impact that is not +0, takes the general path.
        let imp = Impulse { shape: LoadShape::Seed, rise_s: 0.1, duration_s: 0.2 };
        assert!(!WaveEvent::new(0.0, 3.0, comp(1.0, 1.0), 1.0, comp(1.0, 1.0), comp(5.0, 1.0), Some(imp)).is_plain());
        let mut e = WaveEvent::new(0.0, 3.0, comp(1.0, 1.0), 1.0, comp(1.0, 1.0), LoadComponent::default(), None);
        e.impact.x.m_nm = -0.0;
        assert!(!e.is_plain());
    }

    /// A train of one plain wave (its own evaluation, [`PlainWave`]) gives the bits of the same
    /// wave in a train of two (the search and the general dispatch) and of `at_local`: waves
    /// starting at 0 and at 3.7 s, set by `new` and by `set_single`, at 4 001 times from before
    /// the start to after the end plus the start, T/2 and the end themselves.
    #[test]
    fn a_single_plain_wave_gives_the_bits_of_the_general_path() {
        let mut checked = 0;
        for start in [0.0, 3.7] {
            let e = WaveEvent::new(
                start,
                2.5,
                comp(1234.5, -98.25),
                0.8,
                comp(-77.0, 3.0e-3),
                LoadComponent::default(),
                None,
            );
            let later = WaveEvent { start_s: start + 10.0, ..e };
            let one = WaveTrain::new(vec![e]).unwrap();
            let mut set = WaveTrain::default();
            set.set_single(e).unwrap();
            let two = WaveTrain::new(vec![e, later]).unwrap();
            assert!(one.single.is_some() && set.single.is_some() && two.single.is_none());
            let times = (0..=4000).map(|k| start - 0.5 + 3.5 * k as f64 / 4000.0);
            for t in times.chain([start, start + 1.25, start + 2.5]) {
                let (a, b, c, d) = (one.at(t), set.at(t), two.at(t), e.at_local(t - start));
                let d = if t < start { WaveForce::ZERO } else { d };
                for w in [b, c, d] {
                    for (u, v) in [(a.fx_n, w.fx_n), (a.fy_n, w.fy_n), (a.m_nm, w.m_nm)] {
                        assert_eq!(u.to_bits(), v.to_bits(), "start {start} t {t}: {u} vs {v}");
                    }
                }
                checked += 1;
            }
        }
        assert_eq!(checked, 2 * 4004);
        // An impulsive wave alone takes the general path.
        let imp = Impulse { shape: LoadShape::Seed, rise_s: 0.1, duration_s: 0.2 };
        let e = WaveEvent::new(0.0, 3.0, comp(1.0, 1.0), 1.0, comp(1.0, 1.0), comp(5.0, 1.0), Some(imp));
        let mut set = WaveTrain::default();
        set.set_single(e).unwrap();
        assert!(set.single.is_none());
        assert_eq!(set.at(0.1), e.at_local(0.1));
    }

    #[test]
    fn rise_and_duration_are_clamped() {
        let imp = Impulse { shape: LoadShape::Oumeraci2001, rise_s: 2.0, duration_s: 9.0 };
        let e = WaveEvent::new(0.0, 3.0, comp(1.0, 1.0), 1.0, comp(1.0, 1.0), comp(5.0, 1.0), Some(imp));
        let i = e.impulse.unwrap();
        assert_eq!((i.rise_s, i.duration_s), (0.75, 1.5));
    }
}
