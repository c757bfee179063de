//! The rigid-block reference ("Shimosako model"): the rigid-plastic block of Shimosako et al.
//! (1994) / Shimosako & Takahashi (1999), docs/model.md §6.3, that slides shoreward under
//! (m_c + M_a) ẍ = P(t) − μ (W' − U(t)) with M_a = 1.0855 ρ_w h'² l and one friction coefficient
//! μ. Its integration of one wave is described in the docs of [`super::train`], which runs it
//! beside the dynamic model; [`super::lifetime`] runs it over the storms of a life. A model piece:
//! it imports no driver.

use crate::loads::history::WaveEvent;
use crate::structure::Caisson;

/// Added-mass coefficient of the rigid-block model (both faces, docs/model.md §6.3).
pub const RIGID_BLOCK_ADDED_MASS_COEFF: f64 = 1.0855;

/// The rigid-block model of one caisson (docs/model.md §6.3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RigidBlock {
    /// m_c + M_a, kg.
    pub mass_kg: f64,
    /// W', N.
    pub weight_n: f64,
    pub mu_static: f64,
    pub mu_dynamic: f64,
}

impl RigidBlock {
    /// M = m_c + 1.0855 ρ_w h'² l, one friction coefficient `mu`.
    pub fn new(caisson: &Caisson, rho_w: f64, mu: f64) -> Self {
        let added = RIGID_BLOCK_ADDED_MASS_COEFF * rho_w * caisson.base_depth_m.powi(2) * caisson.length_m;
        RigidBlock {
            mass_kg: caisson.mass_kg + added,
            weight_n: caisson.weight_in_water_n,
            mu_static: mu,
            mu_dynamic: mu,
        }
    }

    /// Shoreward slide of the block, from rest, under the load of one wave (module docs), m.
    pub fn wave_sliding_m(&self, e: &WaveEvent) -> f64 {
        self.sliding_m(e, true)
    }

    /// [`Self::wave_sliding_m`]; `stop_at_rest`: end the integration once the block is at rest
    /// where the rest of the wave cannot start it ([`Self::rest_from`]; the same number, sooner).
    fn sliding_m(&self, e: &WaveEvent, stop_at_rest: bool) -> f64 {
        let peak_p = e.impact.x.fx_n.max(e.quasi.x.fx_n);
        let peak_u = e.impact.y.fy_n.max(e.quasi.y.fy_n).max(0.0);
        if peak_p <= self.mu_static * (self.weight_n - peak_u) {
            return 0.0;
        }
        let t = e.period_s;
        let span = e.impulse.map_or(0.0, |i| i.duration_s.max(2.0 * i.rise_s));
        let h_slow = t / 2000.0;
        let h_fast = if span > 0.0 { (span / 200.0).min(h_slow) } else { h_slow };
        let bps = e.breakpoints_local();
        let plain = e.is_plain();
        let force = |tau: f64| {
            let w = if plain { e.at_local_plain(tau) } else { e.at_local(tau) };
            (w.fx_n, w.fy_n)
        };
        let (mut tau, mut x, mut v) = (0.0f64, 0.0f64, 0.0f64);
        let (mut p, mut u) = force(0.0);
        let mut moving = p > self.mu_static * (self.weight_n - u);
        let calm_from = if stop_at_rest { self.rest_from(e, span) } else { f64::INFINITY };
        // The first breakpoint after τ, found again only once τ reaches it (τ grows: the first of
        // the breakpoints after a later τ below it is the same one).
        let mut next_bp = f64::NEG_INFINITY;
        while tau < t {
            if !moving && tau >= calm_from {
                break;
            }
            let mut h = if tau < span { h_fast } else { h_slow };
            if next_bp <= tau {
                next_bp = crate::loads::first_after(tau, &bps);
            }
            if next_bp < tau + h {
                h = next_bp - tau;
            }
            h = h.min(t - tau);
            if h <= 0.0 {
                break;
            }
            let (p1, u1) = force(tau + h);
            if moving {
                let f0 = p - self.mu_dynamic * (self.weight_n - u);
                let f1 = p1 - self.mu_dynamic * (self.weight_n - u1);
                let v1 = v + 0.5 * h * (f0 + f1) / self.mass_kg;
                if v1 <= 0.0 {
                    // Stops inside the step: v linear in time.
                    let s = if v > 0.0 { v / (v - v1) } else { 0.0 };
                    x += 0.5 * v * s * h;
                    v = 0.0;
                    moving = false;
                } else {
                    x += 0.5 * (v + v1) * h;
                    v = v1;
                }
            } else if p1 > self.mu_static * (self.weight_n - u1) {
                moving = true;
                v = 0.0;
            }
            tau += h;
            p = p1;
            u = u1;
        }
        // Still moving at the end of the wave (the load is then zero): decelerate at μ_d W'.
        if moving && v > 0.0 {
            x += 0.5 * self.mass_kg * v * v / (self.mu_dynamic * self.weight_n);
        }
        x
    }

    /// The local time from which a block at rest stays so to the end of wave `e` (`span`: the
    /// end of its impulse, max(t_d, 2 t_r), 0 without one), or infinity. After the impulse every
    /// shape's impact weight is zero and its crest weights (sin ωτ, 1 or 0) and trough weight
    /// (sin ωτ, on the trough half only) are at most 1 in size, so the load is at most the crest's
    /// |F_x| (|Q_x,x| + |Q_y,x|) and uplift on the crest half and the trough's on the trough half;
    /// where those cannot start the block, |F_x| ≤ μ_s (W' − |F_y|), neither can any step's
    /// rounded load (rounding is monotone, |a + b| ≤ |a| + |b| rounded): the rest of the wave
    /// moves nothing, to the bit. From the impulse's end if neither half can start the block,
    /// from max(span, T/2) if only the trough cannot.
    fn rest_from(&self, e: &WaveEvent, span: f64) -> f64 {
        let holds = |fx_n: f64, fy_n: f64| self.mu_static >= 0.0 && fx_n <= self.mu_static * (self.weight_n - fy_n);
        let (q, t) = (e.quasi, e.trough.total());
        if !holds(t.fx_n.abs(), t.fy_n.abs()) {
            f64::INFINITY
        } else if holds(q.x.fx_n.abs() + q.y.fx_n.abs(), q.x.fy_n.abs() + q.y.fy_n.abs()) {
            span
        } else {
            span.max(0.5 * e.period_s)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::closed_form::rigid_block_sliding_m;
    use crate::loads::history::LoadComponent;
    use crate::loads::shapes::{Impulse, LoadShape};

    /// A pure triangular impulse (Shimosako-Takahashi 1994 shape, no quasi-static or trough part)
    /// against the rigid block reproduces the exact closed form of docs/model.md §6.3 in both regimes.
    #[test]
    fn rigid_block_matches_the_exact_triangle_closed_form() {
        let (m, w, mu) = (1800.0, 8240.0, 0.6);
        let block = RigidBlock { mass_kg: m, weight_n: w, mu_static: mu, mu_dynamic: mu };
        for (peak_over_resistance, uplift) in [(1.3, 0.0), (1.5, 800.0), (2.5, 0.0), (4.0, 1500.0)] {
            let tr = 0.05;
            let fx = peak_over_resistance * mu * w;
            let impact = LoadComponent::from_levers(fx, 0.5, uplift, 0.52, 0.78);
            let e = WaveEvent::new(
                0.0,
                3.04,
                LoadComponent::default(),
                1.0,
                LoadComponent::default(),
                impact,
                Some(Impulse { shape: LoadShape::ShimosakoTakahashi1994, rise_s: tr, duration_s: 2.0 * tr }),
            );
            let s = block.wave_sliding_m(&e);
            let exact = rigid_block_sliding_m(fx + mu * uplift, mu * w, m, 2.0 * tr);
            // Trapezoidal rule with 200 steps over the pulse and the start detected on the grid:
            // second-order error of order (1/200)² relative, well inside 0.5 %.
            assert!((s - exact).abs() <= 5e-3 * exact, "F/R = {peak_over_resistance}: {s} vs {exact}");
        }
    }

    /// Ending the integration once the block rests where the rest of the wave cannot start it
    /// gives the number of the whole wave to the bit: pulsating and impulsive waves with crests
    /// from below the resistance to far past it and troughs from none to one that could start
    /// the block (the shortcut then off).
    #[test]
    fn stopping_at_rest_moves_no_bit() {
        let (m, w, mu) = (1800.0, 8240.0, 0.6);
        let block = RigidBlock { mass_kg: m, weight_n: w, mu_static: mu, mu_dynamic: mu };
        let (mut sliding, mut from_span, mut from_half) = (0, 0, 0);
        let shapes = [None, Some(LoadShape::Seed), Some(LoadShape::Goda1994), Some(LoadShape::Lundgren)];
        for shape in shapes {
            for ratio in [0.3, 0.8, 1.02, 1.2, 1.6, 2.5, 4.0] {
                for trough_share in [0.0, 0.5, 1.5] {
                    let fx = ratio * mu * w;
                    let quasi = LoadComponent::from_levers(fx, 0.5, 0.1 * fx, 0.52, 0.78);
                    let trough = LoadComponent::from_levers(trough_share * mu * w, 0.4, 0.05 * fx, 0.52, 0.78);
                    let impulse = shape.map(|shape| Impulse { shape, rise_s: 0.08, duration_s: 0.4 });
                    let impact = LoadComponent::from_levers(3.0 * mu * w, 0.6, 0.2 * mu * w, 0.52, 0.78);
                    let e = WaveEvent::new(0.0, 3.04, quasi, 0.9, trough, impact, impulse);
                    let whole = block.sliding_m(&e, false);
                    assert_eq!(
                        block.sliding_m(&e, true).to_bits(),
                        whole.to_bits(),
                        "{shape:?} {ratio} {trough_share}"
                    );
                    sliding += usize::from(whole > 0.0);
                    let span = e.impulse.map_or(0.0, |i| i.duration_s.max(2.0 * i.rise_s));
                    let rest = block.rest_from(&e, span);
                    from_span += usize::from(rest == span);
                    from_half += usize::from(rest.is_finite() && rest != span);
                }
            }
        }
        // 84 waves, 75 of which slide (the impact slides every impulsive one); the block rests
        // from the impulse's end on the 24 whose crest (times α_qs 0.9) stays below μ W' and
        // trough up to 0.5 μ W', from T/2 on the other 32 with such troughs, and the 28 with
        // troughs of 1.5 μ W' run to the end.
        assert_eq!((sliding, from_span, from_half), (75, 24, 32));
    }
}
