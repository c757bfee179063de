//! The stick bound of an impulsive wave (the parent's module docs, "Impulsive waves"): the
//! peak-to-peak gains of the all-sticking system, the L1 norms ‖k_fj‖₁ = ∫₀^∞ |k_fj(t)| dt of
//! the impulse responses k_fj of each functional f to each load component j, and the largest
//! magnitude of each component over the wave.

use super::{modulus, Margins, StickBound, C64, EDGES, FUNCTIONALS, SLIP_RESERVE, THETA, TOTAL, UX};
use crate::loads::history::WaveEvent;
use crate::loads::shapes::LoadShape;
use crate::loads::WaveForce;
use nalgebra::Matrix3;
use std::f64::consts::PI;

/// The cells of the integration are 1/CELLS of the time scale 1/|λ| of the fastest mode still
/// alive (its envelope above `ALIVE` of the start's).
const CELLS: f64 = 20.0;
const ALIVE: f64 = 1e-12;
/// The integration stops when the tail, bounded by the modes' envelopes, is at most this share
/// of the integral so far (the tail is added).
const TAIL: f64 = 1e-6;
/// The most cells: a mode so slow that more are needed leaves the gains infinite (no bound).
const MAX_CELLS: usize = 1_000_000;

/// The L1 norms ‖k_fj‖₁ of the functionals' impulse responses (the parent's module docs): the
/// response of f to a unit impulse of load component j (F_x, F_y, M) is the free vibration from
/// the velocity jump M⁻¹ e_j, k_fj(t) = Re Σ_m (f·w_m) β_jm e^{λ_m t}, β_j = W⁻¹ (0, M⁻¹ e_j).
/// Each is bounded above: on a cell [t, t + d], ∫|k| ≤ d (|k(t)| + |k(t + d)|)/2 + d³/8 max|k''|
/// (|k| is at most the linear interpolation of its ends' moduli plus the interpolation error,
/// at most d²/8 max|k''|, with max|k''| ≤ Σ_m |c_m| |λ_m|² e^{Re λ_m t}); past the last cell,
/// ∫|k| ≤ Σ_m |c_m| e^{Re λ_m t}/|Re λ_m|. Infinite if the integration does not end. Each
/// sup |k_fj| likewise.
pub(super) fn gains(
    lambda: &[C64; 6],
    modal: &[[C64; 6]; FUNCTIONALS],
    winv: &nalgebra::SMatrix<C64, 6, 6>,
    minv: &Matrix3<f64>,
) -> Gains {
    // c[f][j][m] = (f·w_m) β_jm.
    let c: [[[C64; 6]; 3]; FUNCTIONALS] = std::array::from_fn(|f| {
        std::array::from_fn(|j| {
            std::array::from_fn(|m| {
                let beta: C64 = (0..3).map(|i| winv[(m, 3 + i)] * minv[(i, j)]).sum();
                modal[f][m] * beta
            })
        })
    });
    let size: [[[f64; 6]; 3]; FUNCTIONALS] = c.map(|cf| cf.map(|cj| cj.map(modulus)));
    let start: [f64; 6] = std::array::from_fn(|m| {
        (0..FUNCTIONALS).flat_map(|f| (0..3).map(move |j| (f, j))).map(|(f, j)| size[f][j][m]).sum()
    });
    let total: f64 = start.iter().sum();
    let mut sum = [[0.0; 3]; FUNCTIONALS];
    let mut sup = [[0.0; 3]; FUNCTIONALS];
    if total == 0.0 {
        return Gains { l1: sum, sup };
    }
    if !total.is_finite() {
        return Gains { l1: [[f64::INFINITY; 3]; FUNCTIONALS], sup: [[f64::INFINITY; 3]; FUNCTIONALS] };
    }
    let value = |t: f64| -> [[f64; 3]; FUNCTIONALS] {
        let e: [C64; 6] = lambda.map(|l| (l * t).exp());
        std::array::from_fn(|f| std::array::from_fn(|j| (0..6).map(|m| (c[f][j][m] * e[m]).re).sum::<f64>().abs()))
    };
    let (mut t, mut k0) = (0.0, value(0.0));
    for _ in 0..MAX_CELLS {
        let decay: [f64; 6] = lambda.map(|l| (l.re * t).exp());
        let fastest =
            (0..6).filter(|&m| start[m] * decay[m] > ALIVE * total).map(|m| modulus(lambda[m])).fold(0.0, f64::max);
        let mut done = true;
        let tails: [[f64; 3]; FUNCTIONALS] = std::array::from_fn(|f| {
            std::array::from_fn(|j| {
                let tail: f64 = (0..6).map(|m| size[f][j][m] * decay[m] / -lambda[m].re).sum();
                done &= tail <= TAIL * sum[f][j] || tail == 0.0;
                tail
            })
        });
        if done {
            for f in 0..FUNCTIONALS {
                for j in 0..3 {
                    sum[f][j] += tails[f][j];
                }
            }
            // Past t the modes' envelopes bound |k| too.
            for f in 0..FUNCTIONALS {
                for j in 0..3 {
                    let envelope: f64 = (0..6).map(|m| size[f][j][m] * decay[m]).sum();
                    sup[f][j] = f64::max(sup[f][j], envelope);
                }
            }
            return Gains { l1: sum, sup };
        }
        let d = 1.0 / (CELLS * fastest);
        let k1 = value(t + d);
        for f in 0..FUNCTIONALS {
            for j in 0..3 {
                let curvature: f64 =
                    (0..6).map(|m| size[f][j][m] * decay[m] * modulus(lambda[m]) * modulus(lambda[m])).sum();
                sum[f][j] += 0.5 * d * (k0[f][j] + k1[f][j]) + 0.125 * d * d * d * curvature;
                let slope: f64 = (0..6).map(|m| size[f][j][m] * decay[m] * modulus(lambda[m])).sum();
                sup[f][j] = f64::max(sup[f][j], k0[f][j].max(k1[f][j]) + 0.5 * d * slope);
            }
        }
        (t, k0) = (t + d, k1);
    }
    Gains { l1: [[f64::INFINITY; 3]; FUNCTIONALS], sup: [[f64::INFINITY; 3]; FUNCTIONALS] }
}

/// The all-sticking system's gains from the load components j to the functionals f: the L1
/// norms ‖k_fj‖₁ of the impulse responses and their largest magnitudes sup |k_fj| (on a cell,
/// |k| ≤ max(|k(t)|, |k(t + d)|) + d/2 max|k'|; past the last, the envelopes).
#[derive(Debug, Clone, Copy)]
pub(super) struct Gains {
    pub(super) l1: [[f64; 3]; FUNCTIONALS],
    pub(super) sup: [[f64; 3]; FUNCTIONALS],
}

/// The largest magnitude of each load component (F_x, F_y, M) over an impulsive wave, whatever
/// its shape: on the crest half each axis carries its impact or its crest part times a weight in
/// [0, 1] (`loads::shapes::weights`: every shape, and the seed's larger of the two), so at most
/// the larger of the two parts' magnitudes, summed over the two axes; on the trough half the
/// trough's magnitude (the shapes without a trough carry none: the bound takes it all the same).
fn peak_load(event: &WaveEvent) -> [f64; 3] {
    let parts = |w: WaveForce| [w.fx_n.abs(), w.fy_n.abs(), w.m_nm.abs()];
    let (ix, iy, qx, qy, tr) = (
        parts(event.impact.x),
        parts(event.impact.y),
        parts(event.quasi.x),
        parts(event.quasi.y),
        parts(event.trough.total()),
    );
    std::array::from_fn(|j| (ix[j].max(qx[j]) + iy[j].max(qy[j])).max(tr[j]))
}

/// The largest rate |ṗ_j| of each load component over an impulsive wave and the sum of the
/// magnitudes of its jumps |Δp_j| (every shape starts from 0): per shape
/// ([`crate::loads::shapes`]), on each axis the larger of the impact's slopes and the crest's
/// largest rate ω |F_qs+|, summed over the axes, or the trough's ω |F_qs−|. The seed's shape
/// jumps only in the moment, where an axis changes branch (the compared forces are equal there,
/// the lever arms are not): at most twice on (0, 2 t_r) per axis with both forces ≥ 0, four times
/// otherwise (each branch of the triangle crosses the sine at most twice: h = F_max tri − F_qs+
/// sin is convex or concave there), each jump |F| |a_impact − a_crest| with |F| ≤ |F_qs+| (sin ≤
/// 1); with a force of 0, |M_max| + |M_qs+| each. Goda's (1994) plateau ends at T/2 (a jump of
/// F_qs+), Oumeraci et al.'s (2001) starts at t_d and ends at T/2 (two); a triangle of t_d = t_r
/// falls at once (a jump of F_max).
fn rates_and_jumps(event: &WaveEvent) -> Option<([f64; 3], [f64; 3])> {
    let imp = event.impulse?;
    let omega = 2.0 * PI / event.period_s;
    let (tr, td) = (imp.rise_s, imp.duration_s);
    let parts = |w: WaveForce| [w.fx_n.abs(), w.fy_n.abs(), w.m_nm.abs()];
    let (i, q, tr_) = (parts(event.impact.total()), parts(event.quasi.total()), parts(event.trough.total()));
    let fall = td - tr;
    let mut rate = [0.0; 3];
    let mut jump = [0.0; 3];
    match imp.shape {
        LoadShape::Seed => {
            for (im, qu, fi, fq) in [
                (event.impact.x, event.quasi.x, event.impact.x.fx_n, event.quasi.x.fx_n),
                (event.impact.y, event.quasi.y, event.impact.y.fy_n, event.quasi.y.fy_n),
            ] {
                let (a, b) = (parts(im), parts(qu));
                for j in 0..3 {
                    rate[j] += (a[j] / tr).max(b[j] * omega);
                }
                let crossings = if fi >= 0.0 && fq >= 0.0 { 2.0 } else { 4.0 };
                jump[2] += crossings
                    * if fi != 0.0 && fq != 0.0 {
                        fq.abs() * (im.m_nm / fi - qu.m_nm / fq).abs()
                    } else {
                        im.m_nm.abs() + qu.m_nm.abs()
                    };
            }
            for j in 0..3 {
                rate[j] = rate[j].max(tr_[j] * omega);
            }
        }
        LoadShape::Lundgren => rate = i.map(|x| x * PI / (2.0 * tr)),
        LoadShape::Goda1994 => {
            for j in 0..3 {
                let down = (q[j] - i[j]).abs();
                rate[j] = (i[j] / tr).max(if fall > 0.0 { down / fall } else { 0.0 });
                jump[j] = q[j] + if fall > 0.0 { 0.0 } else { down };
            }
        }
        LoadShape::OumeraciKortenhaus1994 | LoadShape::ShimosakoTakahashi1994 | LoadShape::Oumeraci2001 => {
            let fall = if imp.shape == LoadShape::ShimosakoTakahashi1994 { tr } else { fall };
            for j in 0..3 {
                rate[j] = (i[j] / tr).max(if fall > 0.0 { i[j] / fall } else { 0.0 });
                jump[j] = if fall > 0.0 { 0.0 } else { i[j] };
                if imp.shape == LoadShape::Oumeraci2001 {
                    jump[j] += 2.0 * q[j];
                }
            }
        }
    }
    Some((rate, jump))
}

impl StickBound {
    /// The margins of an impulsive wave (the parent's module docs, "Impulsive waves"), as
    /// [`Self::margins`] gives them of a pulsating one, from the peak-to-peak gains: each
    /// functional's magnitude at every instant is at most Σ_j ‖k_fj‖₁ max|p_j|.
    pub fn impulse_margins(&self, event: &WaveEvent) -> Margins {
        let p = peak_load(event);
        let l1 = &self.modes.gains.l1;
        let peak = |f: usize| -> f64 { (0..3).map(|j| l1[f][j] * p[j]).sum() };
        let n_min = self.n_ref - peak(EDGES[0]).max(peak(EDGES[1]));
        let total_min = self.weight_n - peak(TOTAL);
        let mut margins = Margins {
            normal_share: n_min / self.n_ref,
            friction_share: f64::INFINITY,
            friction_share_of_maxima: f64::INFINITY,
            rotation_rad: f64::INFINITY,
        };
        if !(n_min > 0.0 && total_min > 0.0) {
            return margins;
        }
        // u̇_x = ∫ k_ux(t − s) ṗ(s) ds + Σ k_ux(t − s_i) Δp_i (the load starts from 0).
        let Some((rate, jump)) = rates_and_jumps(event) else {
            return margins;
        };
        let gains = &self.modes.gains;
        let vx: f64 = (0..3).map(|j| gains.l1[UX][j] * rate[j] + gains.sup[UX][j] * jump[j]).sum();
        let friction = self.kappa_per_m * peak(UX) * self.weight_n / total_min + self.dashpot_ns_per_m * vx / n_min;
        margins.friction_share = friction / self.mu_static;
        margins.friction_share_of_maxima = margins.friction_share;
        if margins.friction_share <= SLIP_RESERVE {
            margins.rotation_rad = peak(THETA);
        }
        margins
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::SMatrix;

    /// The gains against a plain integral of |k_fj| and the largest |k_fj| sampled every 10 µs to
    /// 40 s (past which every envelope is below 1e-17 of its start), on a made-up system of a
    /// fast and a slow real mode, an oscillating pair and two more real modes: each gain at least
    /// the sampled one (the bound's rigour) and within 0.1 % of it (the cells' error, about
    /// (1/CELLS)²/8 = 0.03 %, and the tail's 1e-6), for all 18 pairs of a functional and a load
    /// component.
    #[test]
    fn the_gains_are_the_integrals_of_the_impulse_responses() {
        let lambda = [
            C64::new(-300.0, 0.0),
            C64::new(-3.0, 4.0),
            C64::new(-3.0, -4.0),
            C64::new(-1.2, 0.0),
            C64::new(-40.0, 0.0),
            C64::new(-7.0, 0.0),
        ];
        // Functionals and modal inverse with the pair's entries conjugate (a real system).
        let pair = |a: f64, b: f64| [C64::new(a, b), C64::new(a, -b)];
        let modal: [[C64; 6]; FUNCTIONALS] = std::array::from_fn(|f| {
            let x = 1.0 + f as f64;
            let [p, q] = pair(0.3 * x, -0.2);
            [C64::new(0.5, 0.0), p, q, C64::new(-0.7 + 0.1 * x, 0.0), C64::new(0.2 * x, 0.0), C64::new(-0.4, 0.0)]
        });
        let winv = SMatrix::<C64, 6, 6>::from_fn(|m, i| {
            let v = 0.1 * (1.0 + m as f64) - 0.05 * i as f64;
            match m {
                1 => C64::new(v, 0.3),
                2 => C64::new(v, -0.3),
                _ => C64::new(v, 0.0),
            }
        });
        let minv = Matrix3::new(1.0, 0.1, 0.0, 0.1, 2.0, 0.3, 0.0, 0.3, 0.5);
        let g = gains(&lambda, &modal, &winv, &minv);
        // The impulse responses sampled: k_fj(t) = Re Σ_m (f·w_m) (W⁻¹ (0, M⁻¹ e_j))_m e^{λ_m t}.
        let c: Vec<[C64; 6]> = (0..FUNCTIONALS)
            .flat_map(|f| (0..3).map(move |j| (f, j)))
            .map(|(f, j)| {
                std::array::from_fn(|m| modal[f][m] * (0..3).map(|i| winv[(m, 3 + i)] * minv[(i, j)]).sum::<C64>())
            })
            .collect();
        let dt = 1e-5;
        let step = lambda.map(|l| (l * dt).exp());
        let mut e = [C64::new(1.0, 0.0); 6];
        let mut integral = vec![0.0; c.len()];
        let mut largest = vec![0.0_f64; c.len()];
        let mut prev: Vec<f64> = c.iter().map(|cm| cm.iter().map(|x| x.re).sum::<f64>().abs()).collect();
        for (k, p) in prev.iter().enumerate() {
            largest[k] = *p;
        }
        for _ in 0..4_000_000 {
            for (x, s) in e.iter_mut().zip(&step) {
                *x *= s;
            }
            for (k, cm) in c.iter().enumerate() {
                let v = (0..6).map(|m| (cm[m] * e[m]).re).sum::<f64>().abs();
                integral[k] += 0.5 * dt * (prev[k] + v);
                largest[k] = largest[k].max(v);
                prev[k] = v;
            }
        }
        let mut checked = 0;
        for (k, (&sampled, &top)) in integral.iter().zip(&largest).enumerate() {
            let (f, j) = (k / 3, k % 3);
            let (l1, sup) = (g.l1[f][j], g.sup[f][j]);
            // The trapezoids of a convex-decaying |k| lie above it by at most dt²/8 |k''|: 1e-9 relative.
            assert!(l1 >= sampled * (1.0 - 1e-9) && l1 <= sampled * 1.001, "f {f}, j {j}: {l1} against {sampled}");
            assert!(sup >= top && sup <= top * 1.05, "f {f}, j {j}: sup {sup} against {top}");
            checked += 1;
        }
        assert_eq!(checked, 18);
    }
}
