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
    /// after the impulse and the crest and the trough cannot start it (the same number, sooner).
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
        // After the impulse and the crest, a block at rest stays so if the trough cannot start it
        // ([`Self::trough_cannot_start`]): the rest of the wave moves nothing.
        let calm_from = if stop_at_rest && self.trough_cannot_start(e) { span.max(0.5 * t) } else { f64::INFINITY };
        while tau < t {
            if !moving && tau >= calm_from {
                break;
            }
            let mut h = if tau < span { h_fast } else { h_slow };
            let next_bp = crate::loads::first_after(tau, &bps);
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

    /// Whether the load after the impulse and the crest (the trough F_qs− sin ωt, or nothing)
    /// cannot start a block at rest: |F_qs−,x| ≤ μ_s (W' − |F_qs−,y|). After max(t_d, 2 t_r, T/2)
    /// every shape's weight but the trough's is zero and |sin ωt| ≤ 1, so the load there is at
    /// most that in size, and the rounded test of the step as well (rounding is monotone): the
    /// block stays at rest to the bit.
    fn trough_cannot_start(&self, e: &WaveEvent) -> bool {
        let trough = e.trough.total();
        self.mu_static >= 0.0 && trough.fx_n.abs() <= self.mu_static * (self.weight_n - trough.fy_n.abs())
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

    /// Ending the integration once the block rests after the crest gives the number of the whole
    /// wave to the bit: pulsating and impulsive waves from just sliding to far past it, with
    /// troughs from none to one that starts the block seaward-loaded (the shortcut then off).
    #[test]
    fn stopping_at_rest_moves_no_bit() {
        let (m, w, mu) = (1800.0, 8240.0, 0.6);
        let block = RigidBlock { mass_kg: m, weight_n: w, mu_static: mu, mu_dynamic: mu };
        let (mut sliding, mut shortcut) = (0, 0);
        for shape in [None, Some(LoadShape::Seed), Some(LoadShape::Goda1994), Some(LoadShape::Lundgren)] {
            for ratio in [1.02, 1.2, 1.6, 2.5, 4.0] {
                for trough_share in [0.0, 0.5, 1.5] {
                    let fx = ratio * mu * w;
                    let quasi = LoadComponent::from_levers(fx, 0.5, 0.1 * fx, 0.52, 0.78);
                    let trough = LoadComponent::from_levers(trough_share * mu * w, 0.4, 0.05 * fx, 0.52, 0.78);
                    let impulse = shape.map(|shape| Impulse { shape, rise_s: 0.08, duration_s: 0.4 });
                    let impact = LoadComponent::from_levers(1.5 * fx, 0.6, 0.2 * fx, 0.52, 0.78);
                    let e = WaveEvent::new(0.0, 3.04, quasi, 0.9, trough, impact, impulse);
                    let whole = block.sliding_m(&e, false);
                    assert_eq!(
                        block.sliding_m(&e, true).to_bits(),
                        whole.to_bits(),
                        "{shape:?} {ratio} {trough_share}"
                    );
                    sliding += usize::from(whole > 0.0);
                    shortcut += usize::from(block.trough_cannot_start(&e));
                }
            }
        }
        // 60 waves, 57 of which slide; the shortcut is on for the 40 with troughs up to
        // 0.5 μ W', off for the 20 of 1.5 μ W'.
        assert_eq!(sliding, 57);
        assert_eq!(shortcut, 40);
    }
}
