//! The stick bound of an impulsive wave (the parent's module docs, "Impulsive waves"): its load
//! as pieces a + b τ + P sin ωτ, the all-sticking response piece by piece, and the functionals'
//! ranges on short intervals from their exact values at the ends.

use super::{
    arc_range, modulus, AtPeriod, Margins, Modes, StickBound, C64, EDGES, FUNCTIONALS, INTERVALS, LIFT_RESERVE, SLIP_RESERVE, THETA,
    TOTAL, UX, VX,
};
use crate::loads::history::WaveEvent;
use crate::loads::shapes::{Impulse, LoadShape};
use crate::loads::WaveForce;
use nalgebra::Vector3;
use std::f64::consts::PI;

/// The most pieces a wave's load has: the seed's shape cut at t_r, 2 t_r, T/2 and one crossing
/// of its two branches on each axis and each side of t_r (four), and its trough.
const MAX_PIECES: usize = 8;

/// A mode is followed exactly on an interval of length h (its values at the ends, its excess
/// between them from its second derivative) if |λ_m| h is at most this; else by its envelope.
const EXACT_MODE: f64 = 2.0;

/// After each kink of the load the steps start at h_coarse / 2^DOUBLINGS and double.
pub(super) const DOUBLINGS: usize = 5;

/// One piece of a wave's load, a + b τ + P sin ωτ on [start, end) (τ the wave's local time, s;
/// the vectors (F_x, F_y, M), N and N·m).
#[derive(Debug, Clone, Copy, Default)]
struct Piece {
    start_s: f64,
    end_s: f64,
    a: Vector3<f64>,
    b: Vector3<f64>,
    p: Vector3<f64>,
}

/// A wave's load as pieces in time order.
#[derive(Debug, Clone, Copy)]
struct Pieces {
    list: [Piece; MAX_PIECES],
    len: usize,
}

impl Pieces {
    fn new() -> Self {
        Pieces { list: [Piece::default(); MAX_PIECES], len: 0 }
    }

    /// Add the piece [start, end) unless it is empty; `None` if there is no room.
    fn push(&mut self, start_s: f64, end_s: f64, a: Vector3<f64>, b: Vector3<f64>, p: Vector3<f64>) -> Option<()> {
        if end_s > start_s {
            *self.list.get_mut(self.len)? = Piece { start_s, end_s, a, b, p };
            self.len += 1;
        }
        Some(())
    }
}

fn vector(w: WaveForce) -> Vector3<f64> {
    Vector3::new(w.fx_n, w.fy_n, w.m_nm)
}

/// The load of `event` (impulsive, of timing `imp`) as pieces, exactly as
/// [`WaveEvent::at_local`] has it ([`crate::loads::shapes::weights`]); `None` for Lundgren's
/// cosine bell (not of that form) and for the seed's shape with a negative force among its peaks
/// (the branches' crossings are found only for those that are not).
fn pieces(event: &WaveEvent, imp: Impulse) -> Option<Pieces> {
    let (period, tr, td) = (event.period_s, imp.rise_s, imp.duration_s);
    let half = 0.5 * period;
    let (i, q) = (vector(event.impact.total()), vector(event.quasi.total()));
    let zero = Vector3::zeros();
    let mut out = Pieces::new();
    match imp.shape {
        LoadShape::Seed => return seed_pieces(event, tr),
        LoadShape::Lundgren => return None,
        LoadShape::Goda1994 => {
            out.push(0.0, tr, zero, i / tr, zero)?;
            // I (1 − w) + Q w, w = (τ − t_r)/(t_d − t_r).
            let slope = (q - i) / (td - tr);
            out.push(tr, td, i - slope * tr, slope, zero)?;
            out.push(td, half, q, zero, zero)?;
            out.push(half, period, zero, zero, zero)?;
        }
        LoadShape::OumeraciKortenhaus1994 | LoadShape::ShimosakoTakahashi1994 | LoadShape::Oumeraci2001 => {
            // The asymmetric triangle (t_d = 2 t_r for Shimosako & Takahashi's), then F_qs+ to T/2
            // (Oumeraci et al. 2001) or nothing.
            let end = if imp.shape == LoadShape::ShimosakoTakahashi1994 { 2.0 * tr } else { td };
            out.push(0.0, tr, zero, i / tr, zero)?;
            out.push(tr, end, i * (end / (end - tr)), -i / (end - tr), zero)?;
            if imp.shape == LoadShape::Oumeraci2001 {
                out.push(end, half, q, zero, zero)?;
                out.push(half, period, zero, zero, zero)?;
            } else {
                out.push(end, period, zero, zero, zero)?;
            }
        }
    }
    Some(out)
}

/// The seed's shape (Eq. 31): on each axis the larger of the triangle F_max tri(τ) and F_qs+ sin
/// ωτ for τ < T/2, the trough after. On an axis with both peaks ≥ 0, h(τ) = F_max tri(τ) − F_qs+
/// sin ωτ is convex on [0, t_r] and on [t_r, 2 t_r] (t_r ≤ T/4: sin is concave there), h(0) = 0
/// and h(2 t_r) ≤ 0, so it crosses 0 at most once inside each: on [0, t_r] iff h'(0) < 0 < h(t_r),
/// on [t_r, 2 t_r] iff h(t_r) > 0 > h(2 t_r), found by Newton's method from t_r (monotone on a
/// convex function from where it is positive). Between the cuts the branch of each axis is the
/// one `weights` takes at the piece's middle.
fn seed_pieces(event: &WaveEvent, tr: f64) -> Option<Pieces> {
    let period = event.period_s;
    let (half, omega) = (0.5 * period, 2.0 * PI / period);
    let axes = [
        (event.impact.x, event.quasi.x, event.impact.x.fx_n, event.quasi.x.fx_n),
        (event.impact.y, event.quasi.y, event.impact.y.fy_n, event.quasi.y.fy_n),
    ];
    let mut cuts = [0.0, tr, 2.0 * tr, half, f64::NAN, f64::NAN, f64::NAN, f64::NAN];
    let mut n_cuts = 4;
    for &(_, _, fi, fq) in &axes {
        if !(fi >= 0.0 && fq >= 0.0) {
            return None;
        }
        // h and h' on the rising (`up`) or the falling side of the triangle.
        let h = |t: f64, up: bool| -> (f64, f64) {
            let (s, c) = (omega * t).sin_cos();
            let (tri, slope) = if up { (t / tr, 1.0 / tr) } else { (2.0 - t / tr, -1.0 / tr) };
            (tri * fi - s * fq, slope * fi - omega * c * fq)
        };
        let at_peak = h(tr, true).0;
        let rising = fi / tr - omega * fq < 0.0 && at_peak > 0.0;
        let falling = at_peak > 0.0 && h(2.0 * tr, false).0 < 0.0;
        for (found, up, lo, hi) in [(rising, true, 0.0, tr), (falling, false, tr, 2.0 * tr)] {
            if found {
                cuts[n_cuts] = crossing(&|t| h(t, up), tr, lo, hi, period);
                n_cuts += 1;
            }
        }
    }
    let cuts = &mut cuts[..n_cuts];
    cuts.sort_unstable_by(f64::total_cmp);
    let mut out = Pieces::new();
    let zero = Vector3::zeros();
    for w in cuts.windows(2) {
        let (lo, hi) = (w[0], w[1]);
        let mid = 0.5 * (lo + hi);
        let (s, tri) = (((omega * mid).sin()), crate::loads::shapes::triangle(mid, tr));
        let (mut a, mut b, mut p) = (zero, zero, zero);
        for &(imp, quasi, fi, fq) in &axes {
            if tri * fi > s * fq {
                let v = vector(imp);
                if mid < tr {
                    b += v / tr;
                } else if mid < 2.0 * tr {
                    a += 2.0 * v;
                    b -= v / tr;
                }
            } else {
                p += vector(quasi);
            }
        }
        out.push(lo, hi, a, b, p)?;
    }
    out.push(half, period, zero, zero, vector(event.trough.total()))?;
    Some(out)
}

/// The zero of the convex `h` (value and slope) in [lo, hi] by Newton's method from `from`, where
/// h > 0: the iterates stay on its positive side and move monotonically to the zero.
fn crossing(h: &impl Fn(f64) -> (f64, f64), from: f64, lo: f64, hi: f64, period_s: f64) -> f64 {
    let mut t = from;
    for _ in 0..100 {
        let (v, d) = h(t);
        if !(d != 0.0 && v.is_finite()) {
            break;
        }
        let next = (t - v / d).clamp(lo, hi);
        let done = (next - t).abs() <= 1e-14 * period_s;
        t = next;
        if done {
            break;
        }
    }
    t
}

/// What the intervals of a wave give: the functionals' extremes and the friction demand interval
/// by interval (the parent's module docs, "slip").
struct Tally<'b> {
    bound: &'b StickBound,
    n_min: f64,
    total_min: f64,
    ux: f64,
    vx: f64,
    theta: f64,
    demand: f64,
}

impl Tally<'_> {
    /// Take interval ranges `r` in; `false` if the outer springs' normal force or the total may
    /// fall below the reserve (the wave may lift: the rest need not be computed).
    fn take(&mut self, r: &[(f64, f64); FUNCTIONALS]) -> bool {
        let b = self.bound;
        let n = b.n_ref + r[EDGES[0]].0.min(r[EDGES[1]].0);
        let total = b.weight_n + r[TOTAL].0;
        self.n_min = self.n_min.min(n);
        self.total_min = self.total_min.min(total);
        if n < LIFT_RESERVE * b.n_ref || total <= 0.0 {
            return false;
        }
        let abs = |f: usize| r[f].0.abs().max(r[f].1.abs());
        let (u, v) = (abs(UX), abs(VX));
        self.ux = self.ux.max(u);
        self.vx = self.vx.max(v);
        self.theta = self.theta.max(abs(THETA));
        self.demand = self.demand.max(b.kappa_per_m * u * b.weight_n / total + b.dashpot_ns_per_m * v / n);
        true
    }
}

impl StickBound {
    /// The margins of an impulsive wave (the parent's module docs, "Impulsive waves"), as
    /// [`Self::margins`] gives them of a pulsating one: `None` if its shape is not one the bound
    /// takes (Lundgren's, or the seed's with a negative peak) or `at` is not at its period.
    pub fn impulse_margins(&self, at: &AtPeriod, event: &WaveEvent) -> Option<Margins> {
        let imp = event.impulse?;
        let period = event.period_s;
        let omega = 2.0 * PI / period;
        if (omega - at.omega).abs() > 1e-12 * omega {
            return None;
        }
        let pieces = pieces(event, imp)?;
        let md = &*self.modes;
        let mut tally = Tally {
            bound: self,
            n_min: f64::INFINITY,
            total_min: f64::INFINITY,
            ux: 0.0,
            vx: 0.0,
            theta: 0.0,
            demand: 0.0,
        };
        // The free vibration's modal coordinates now, and the particular state it adds to.
        let mut alpha = [C64::new(0.0, 0.0); 6];
        let mut y_prev = [0.0; 6];
        for piece in &pieces.list[..pieces.len] {
            let response = PieceResponse::new(md, at, piece);
            // The state is continuous: the free vibration takes the particular state's jump.
            let y0 = response.state(piece.start_s);
            let jump: [f64; 6] = std::array::from_fn(|i| y_prev[i] - y0[i]);
            for (m, a) in alpha.iter_mut().enumerate() {
                let dot = |row: &[f64; 6]| row.iter().zip(&jump).map(|(u, v)| u * v).sum::<f64>();
                *a += C64::new(dot(&md.winv[m]), dot(&md.winv_im[m]));
            }
            if !response.walk(&mut tally, &mut alpha, y0) {
                return Some(Margins {
                    normal_share: tally.n_min / self.n_ref,
                    friction_share: f64::INFINITY,
                    friction_share_of_maxima: f64::INFINITY,
                    rotation_rad: f64::INFINITY,
                });
            }
            y_prev = response.state(piece.end_s);
        }
        let maxima = self.kappa_per_m * tally.ux * self.weight_n / tally.total_min
            + self.dashpot_ns_per_m * tally.vx / tally.n_min;
        let friction_share = tally.demand / self.mu_static;
        Some(Margins {
            normal_share: tally.n_min / self.n_ref,
            friction_share,
            friction_share_of_maxima: maxima / self.mu_static,
            rotation_rad: if friction_share > SLIP_RESERVE { f64::INFINITY } else { tally.theta },
        })
    }
}

/// The all-sticking response on one piece: its particular solution and what the steps need.
struct PieceResponse<'a> {
    md: &'a Modes,
    at: &'a AtPeriod,
    piece: &'a Piece,
    /// X = Z⁻¹ P; q_p = Re X sin ωτ + Im X cos ωτ + q0 + q1 τ.
    x: Vector3<C64>,
    q0: Vector3<f64>,
    q1: Vector3<f64>,
    /// Each functional's harmonic part Re(G e^{iωτ}) and its amplitude times ω².
    harmonic: [C64; FUNCTIONALS],
    curvature: [f64; FUNCTIONALS],
}

impl<'a> PieceResponse<'a> {
    fn new(md: &'a Modes, at: &'a AtPeriod, piece: &'a Piece) -> Self {
        let x: Vector3<C64> = Vector3::from_fn(|r, _| (0..3).map(|j| at.zinv[(r, j)] * piece.p[j]).sum::<C64>());
        let q1 = md.kinv * piece.b;
        let q0 = md.kinv * piece.a - md.kinv_c_kinv * piece.b;
        let omega = at.omega;
        // Re X sin ψ + Im X cos ψ = Re(−i X e^{iψ}); u̇_x's: ω Re(X_x e^{iψ}).
        let harmonic: [C64; FUNCTIONALS] = std::array::from_fn(|f| {
            if f == VX {
                x[0] * omega
            } else {
                (0..3).map(|i| x[i] * md.rows[f][i]).sum::<C64>() * C64::new(0.0, -1.0)
            }
        });
        let curvature = harmonic.map(|g| modulus(g) * omega * omega);
        PieceResponse { md, at, piece, x, q0, q1, harmonic, curvature }
    }

    /// The particular state y_p(τ) = (q_p, q̇_p).
    #[inline]
    fn state(&self, t: f64) -> [f64; 6] {
        let (s, c) = (self.at.omega * t).sin_cos();
        let (x, q0, q1, w) = (&self.x, &self.q0, &self.q1, self.at.omega);
        std::array::from_fn(|i| {
            if i < 3 {
                x[i].re * s + x[i].im * c + q0[i] + q1[i] * t
            } else {
                w * (x[i - 3].re * c - x[i - 3].im * s) + q1[i - 3]
            }
        })
    }

    /// The functionals at particular state `y` and modal coordinates `alpha`: (u, v), u the
    /// particular part and the oscillating modes of `exact`, v the real modes (each monotone in
    /// time: its range on a step is that of its ends).
    #[inline]
    fn value(&self, y: &[f64; 6], alpha: &[C64; 6], exact: &[bool; 6]) -> [(f64, f64); FUNCTIONALS] {
        let md = self.md;
        std::array::from_fn(|f| {
            let mut u = if f == VX { y[3] } else { (0..3).map(|i| md.rows[f][i] * y[i]).sum() };
            let mut v = 0.0;
            for m in 0..6 {
                let c = (md.modal[f][m] * alpha[m]).re;
                if md.real[m] {
                    v += c;
                } else if exact[m] {
                    u += c;
                }
            }
            (u, v)
        })
    }

    /// Walk the piece from `y0` (the particular state at its start) with the free vibration
    /// `alpha` (left at the piece's end), taking each step's ranges into `tally`; `false` if
    /// the tally stopped (the wave may lift).
    fn walk(&self, tally: &mut Tally<'_>, alpha: &mut [C64; 6], y0: [f64; 6]) -> bool {
        let (md, at, piece) = (self.md, self.at, self.piece);
        let h_coarse = 0.5 * at.period_s / INTERVALS as f64;
        let mut t0 = piece.start_s;
        let mut y_t0 = y0;
        let mut exact0 = [false; 6];
        let mut g0 = [(f64::NAN, f64::NAN); FUNCTIONALS];
        let mut doubling = 0;
        // The coarse steps' size and growth factors, once computed.
        let mut coarse: Option<(f64, [C64; 6])> = None;
        while t0 < piece.end_s {
            let rest = piece.end_s - t0;
            if doubling > DOUBLINGS && piece.b == Vector3::zeros() && rest <= 0.5 * at.period_s {
                // The free vibration has had h_coarse to die down and the load is P sin ωτ + a:
                // the rest of the piece in one, the harmonic part's exact range on its arc.
                return tally.take(&self.arc(t0, alpha));
            }
            let (step, grow) = if doubling <= DOUBLINGS {
                let h = at.h_fine_s * (1u32 << doubling) as f64;
                doubling += 1;
                if rest <= 1.5 * h {
                    (rest, md.lambda.map(|l| (l * rest).exp()))
                } else {
                    (h, at.grow[doubling - 1])
                }
            } else {
                let (h, g) = *coarse.get_or_insert_with(|| {
                    let h = rest / (rest / h_coarse).ceil();
                    (h, md.lambda.map(|l| (l * h).exp()))
                });
                if rest <= 1.5 * h {
                    (rest, md.lambda.map(|l| (l * rest).exp()))
                } else {
                    (h, g)
                }
            };
            let t1 = if step == rest { piece.end_s } else { t0 + step };
            let exact: [bool; 6] = std::array::from_fn(|m| !md.real[m] && md.lambda_abs[m] * step <= EXACT_MODE);
            if exact != exact0 || g0[0].0.is_nan() {
                g0 = self.value(&y_t0, alpha, &exact);
                exact0 = exact;
            }
            let size: [f64; 6] = alpha.map(modulus);
            for (a, g) in alpha.iter_mut().zip(&grow) {
                *a *= g;
            }
            let y_t1 = self.state(t1);
            let g1 = self.value(&y_t1, alpha, &exact);
            let ranges: [(f64, f64); FUNCTIONALS] = std::array::from_fn(|f| {
                let (mut curvature, mut envelope) = (self.curvature[f], 0.0);
                for m in 0..6 {
                    if md.real[m] {
                        continue;
                    }
                    let c = md.modal_abs[f][m] * size[m];
                    if exact[m] {
                        curvature += c * md.lambda_abs[m] * md.lambda_abs[m];
                    } else {
                        envelope += c;
                    }
                }
                let slack = 0.125 * step * step * curvature + envelope;
                let ((u0, v0), (u1, v1)) = (g0[f], g1[f]);
                (u0.min(u1) + v0.min(v1) - slack, u0.max(u1) + v0.max(v1) + slack)
            });
            if !tally.take(&ranges) {
                return false;
            }
            (t0, y_t0, g0) = (t1, y_t1, g1);
        }
        true
    }

    /// The ranges of the functionals from `t0` to the piece's end (at most T/2 on, the load P sin
    /// ωτ + a), advancing `alpha` there: the harmonic part's exact range on its arc
    /// ([`arc_range`]), the constant, the real modes' ends and the oscillating modes' envelopes.
    fn arc(&self, t0: f64, alpha: &mut [C64; 6]) -> [(f64, f64); FUNCTIONALS] {
        let (md, at, piece) = (self.md, self.at, self.piece);
        let rest = piece.end_s - t0;
        let size: [f64; 6] = alpha.map(modulus);
        let start = [false; 6];
        let v0 = self.value(&[0.0; 6], alpha, &start);
        for (a, l) in alpha.iter_mut().zip(&md.lambda) {
            *a *= (l * rest).exp();
        }
        let v1 = self.value(&[0.0; 6], alpha, &start);
        // Re(G e^{iψ}) for ψ from ωt0 to ωt1 = ψ1 is Re(g e^{iφ}) for φ from π − ω rest to π, with
        // g = −G e^{iψ1}.
        let end = C64::from_polar(1.0, at.omega * piece.end_s);
        let from = C64::from_polar(1.0, PI - at.omega * rest);
        std::array::from_fn(|f| {
            let g = -self.harmonic[f] * end;
            let (lo, hi) = arc_range(g, from, (g * from).re);
            let constant = if f == VX { self.q1[0] } else { (0..3).map(|i| md.rows[f][i] * self.q0[i]).sum() };
            let envelope: f64 = (0..6).filter(|&m| !md.real[m]).map(|m| md.modal_abs[f][m] * size[m]).sum();
            let (r0, r1) = (v0[f].1, v1[f].1);
            (constant + lo + r0.min(r1) - envelope, constant + hi + r0.max(r1) + envelope)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::loads::history::LoadComponent;

    /// The pieces give the load of `WaveEvent::at_local` at 2 001 times of each wave, on waves of
    /// every shape the bound takes.
    #[test]
    fn the_pieces_are_the_load() {
        let mut worst = 0.0_f64;
        let mut checked = 0;
        for shape in [
            LoadShape::Seed,
            LoadShape::Goda1994,
            LoadShape::OumeraciKortenhaus1994,
            LoadShape::ShimosakoTakahashi1994,
            LoadShape::Oumeraci2001,
        ] {
            for (k, (rise, dur, impact)) in
                [(0.3, 0.9, 1.0), (1.0, 2.5, 0.8), (2.0, 4.0, 2.0), (0.05, 3.0, 0.3), (3.0, 6.0, 1.5)].into_iter().enumerate()
            {
                let quasi = LoadComponent::from_levers(1.0e6, 8.0, 4.0e5, 13.0, 20.0);
                let trough = LoadComponent::from_levers(6.0e5, 6.0, 1.0e5, 10.0, 20.0);
                let peak = LoadComponent::from_levers(1.0e6 * impact, 6.0 + k as f64, 3.0e5 * impact, 12.0, 20.0);
                let imp = Impulse { shape, rise_s: rise, duration_s: dur };
                let e = WaveEvent::new(0.0, 10.0, quasi, 0.9, trough, peak, Some(imp));
                let p = pieces(&e, e.impulse.unwrap()).unwrap();
                for i in 0..=2000 {
                    let t = 10.0 * i as f64 / 2000.0 * (1.0 - 1e-12);
                    let q = p.list[..p.len].iter().find(|q| q.start_s <= t && t < q.end_s).unwrap();
                    let v = q.a + q.b * t + q.p * (2.0 * PI * t / 10.0).sin();
                    let w = vector(e.at_local(t));
                    let err = (v - w).abs().max() / 1.0e7;
                    worst = worst.max(err);
                    assert!(err < 1e-9, "{shape:?} {k} τ {t}: {v:?} against {w:?}");
                    checked += 1;
                }
            }
        }
        assert_eq!(checked, 5 * 5 * 2001);
        eprintln!("worst {worst:e}");
    }
}
