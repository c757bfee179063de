//! The rotation of a still wave under its own load history (issue 35, item 4): a bound on the
//! largest |θ| of the all-sticking response over the wave, as sharp as asked, for the still
//! waves whose coarse bound may be the life's largest rotation ([`super::super::lifetime`],
//! module docs "The stick bound": those are run again at the life's end unless a bound shows
//! they cannot be the largest).
//!
//! The coarse bound of an impulsive wave, Σ_j ‖k_θj‖₁ max|p_j| (`impulse.rs`), takes the static
//! response to the peak moment; the moment's kernel is of one sign with a slow mode, so the true
//! response to a short impact lags and stays 1.25-1.5 times below it. Here the load of the wave
//! is followed in time instead. On [0, T) it is a sequence of pieces on each of which every
//! component is p_j(t₀ + s) = a_j + b_j s + Re(h_j e^{iΩs}): the seed's shape (Eq. 31) on each
//! side of its triangle and between the crossings of each axis's triangle and sine (found by a
//! safeguarded Newton iteration; h = F_max tri − F_qs+ sin is convex or concave on a side, so at
//! most two, split at the extremum, cos ωt* = F_max ṫri/(F_qs+ ω)), the trough's sine, and a
//! pulsating wave's two sines. With z̃_m = (θ·w_m) z_m the modal coordinates scaled into θ
//! (z̃' = λ_m z̃ + Σ_j c_jm p_j, c_jm = (θ·w_m) (W⁻¹ (0, M⁻¹ e_j))_m, θ = Re Σ_m z̃_m), each piece
//! has the closed-form response
//!
//! ```text
//! z̃_m(s) = P_m(s) + (z̃_m(0) − P_m(0)) e^{λ_m s},
//! P_m(s) = −α/λ − β/λ² − β s/λ + ½η e^{iΩs}/(iΩ − λ) + ½η' e^{−iΩs}/(−iΩ − λ)
//! θ(s)   = A + B s + Re(G e^{iΩs}) + Re Σ_m E_m e^{λ_m s}
//! ```
//!
//! (α, β, η, η' = c_m·a, c_m·b, c_m·h, c_m·h̄; a conjugate pair of modes taken as one term, E_m +
//! Ē_m'). Its largest |θ| is bounded by branch and bound on intervals [s₁, s₂] of the pieces:
//! |θ| ≤ max(|θ(s₁)|, |θ(s₂)|) + min(K₂ h²/8, K₁ h/2) with K₂ ≥ |θ''| = |G| Ω² + Σ_m |E_m| |λ_m|²
//! e^{Re λ_m s₁} and K₁ ≥ |θ'| likewise (the excess of a function over the chord of its ends,
//! and over its ends' values), or the piece's terms' moduli summed; an interval whose bound is at
//! most the floor asked for, or within [`TOLERANCE`] of the largest |θ| evaluated, is closed,
//! any other one halved. The bound is the largest over the closed intervals: it covers every
//! instant of [0, T] (the engine's run of the wave), up to rounding (a relative 1e-9 is added).
//! The same pieces bound the heel pressure of the springs' resultant (V = W' + ΣΔN_i, M = Σ x_i
//! N_i; Goda's p_e): while the toe's linear pressure (V/B − 6M/B²)/l stays positive (its lowest
//! value bounded likewise, kept [`TOE_RESERVE`] of its rest value above 0), the resultant is within
//! the middle third and p_e = (V/B + 6M/B²)/l, linear in the state
//! ([`StickBound::heel_under_history_pa`]). Against the engine: `tests/verify_stick_bound.rs`
//! (`the_rotation_under_the_load_history_holds_the_engines`: 226 waves for the rotation, 215 for
//! the heel pressure).

use super::{modulus, StickBound, C64};
use crate::loads::history::WaveEvent;
use crate::loads::shapes::LoadShape;
use crate::loads::WaveForce;
use nalgebra::{Matrix3, SMatrix};
use std::f64::consts::PI;

/// The bound is within this share of the largest |θ| evaluated (unless the floor is higher).
pub const TOLERANCE: f64 = 0.005;
/// The share of the toe's linear pressure at rest the heel pressure's bound keeps
/// ([`StickBound::heel_under_history_pa`]).
pub const TOE_RESERVE: f64 = 0.1;
/// The most evaluations of θ: past them, the open intervals are closed at their bounds.
const MAX_EVALUATIONS: usize = 400;
/// The most pieces of a wave's load: the seed's crest half has 0, t_r, 2 t_r, T/2 and at most two
/// crossings per axis on each side of the triangle; the trough one.
const MAX_PIECES: usize = 16;

/// One piece of a wave's load on [t₀, t₀ + len): p_j(t₀ + s) = a_j + b_j s + Re(h_j e^{iΩs}).
#[derive(Debug, Clone, Copy, Default)]
struct Piece {
    len: f64,
    a: [f64; 3],
    b: [f64; 3],
    h: [C64; 3],
    omega: f64,
}

fn parts(w: WaveForce) -> [f64; 3] {
    [w.fx_n, w.fy_n, w.m_nm]
}

/// `w` sin(ω t) on a piece starting at t₀: Re(−i e^{iωt₀} w e^{iωs}).
fn sine(w: WaveForce, omega: f64, t0: f64) -> [C64; 3] {
    let rot = C64::new(0.0, -1.0) * C64::from_polar(1.0, omega * t0);
    parts(w).map(|x| rot * x)
}

/// The crossings in (lo, hi) of f_i tri(t) − f_q sin(ωt), tri(t) = c₀ + slope t on the side:
/// convex or concave there (sin is concave on [0, π/ω]), so at most two, one on each side of the
/// extremum (cos ωt* = f_i slope/(f_q ω)); each by Newton's iteration kept in its bracket.
fn crossings(f_i: f64, f_q: f64, (c0, slope): (f64, f64), omega: f64, (lo, hi): (f64, f64), out: &mut Vec<f64>) {
    if f_i == 0.0 || f_q == 0.0 {
        return;
    }
    let g = |t: f64| f_i * (c0 + slope * t) - f_q * (omega * t).sin();
    let x = f_i * slope / (f_q * omega);
    let mut cuts = [lo, hi, hi];
    if x.abs() < 1.0 {
        let t_star = x.acos() / omega;
        if t_star > lo && t_star < hi {
            cuts[1] = t_star;
        }
    }
    // g at the cuts, each taken once (t* ends one bracket and starts the other).
    let mut at_cuts = [None; 3];
    let mut g_cut = |i: usize| *at_cuts[i].get_or_insert_with(|| g(cuts[i]));
    for k in 0..2 {
        let (mut a, mut b) = (cuts[k], cuts[k + 1]);
        if b <= a {
            continue;
        }
        // A bracket from a zero of g (the rising side's start: g monotone between the cuts) holds
        // no crossing inside it and is skipped, as ga·gb ≥ 0 skips it, without its far end.
        let ga = g_cut(k);
        if ga == 0.0 || ga.is_nan() {
            continue;
        }
        let gb = g_cut(k + 1);
        if ga * gb >= 0.0 || gb.is_nan() {
            continue;
        }
        // Newton's iteration from the secant's root (g is convex or concave on the bracket).
        let secant = a - ga * (b - a) / (gb - ga);
        let mut t = if secant > a && secant < b { secant } else { 0.5 * (a + b) };
        for _ in 0..100 {
            // g and g' at t (the same bits as `g(t)` and its derivative's closed form).
            let (sin, cos) = (omega * t).sin_cos();
            let gt = f_i * (c0 + slope * t) - f_q * sin;
            if gt == 0.0 {
                break;
            }
            if (gt < 0.0) == (ga < 0.0) {
                a = t;
            } else {
                b = t;
            }
            let d = f_i * slope - f_q * omega * cos;
            let newton = t - gt / d;
            t = if d != 0.0 && newton > a && newton < b { newton } else { 0.5 * (a + b) };
            if b - a <= 1e-13 * hi || (gt / d).abs() <= 1e-14 * hi {
                break;
            }
        }
        out.push(t);
    }
}

/// The pieces of `event`'s load on [0, T) (module docs); `None` for a shape other than the seed's
/// or a pulsating wave.
fn pieces(event: &WaveEvent, out: &mut Vec<Piece>) -> Option<()> {
    out.clear();
    let period = event.period_s;
    let omega = 2.0 * PI / period;
    let half = 0.5 * period;
    let sine_piece = |w: WaveForce, t0: f64, len: f64| Piece { len, h: sine(w, omega, t0), omega, ..Piece::default() };
    let Some(imp) = event.impulse else {
        out.push(sine_piece(event.quasi.total(), 0.0, half));
        out.push(sine_piece(event.trough.total(), half, period - half));
        return Some(());
    };
    if imp.shape != LoadShape::Seed {
        return None;
    }
    let tr = imp.rise_s;
    if !(tr > 0.0 && 2.0 * tr <= half) {
        return None;
    }
    // The triangle's corners, T/2 and at most two crossings per axis and side.
    let mut cuts = Vec::with_capacity(12);
    cuts.extend([0.0, tr, 2.0 * tr, half]);
    let axes = [
        (event.impact.x, event.quasi.x, event.impact.x.fx_n, event.quasi.x.fx_n),
        (event.impact.y, event.quasi.y, event.impact.y.fy_n, event.quasi.y.fy_n),
    ];
    for &(_, _, fi, fq) in &axes {
        crossings(fi, fq, (0.0, 1.0 / tr), omega, (0.0, tr), &mut cuts);
        crossings(fi, fq, (2.0, -1.0 / tr), omega, (tr, 2.0 * tr), &mut cuts);
    }
    cuts.sort_unstable_by(f64::total_cmp);
    for k in 0..cuts.len() - 1 {
        let (u0, u1) = (cuts[k], cuts[k + 1]);
        if u1 <= u0 {
            continue;
        }
        let mid = 0.5 * (u0 + u1);
        let (tri_mid, s_mid) = (crate::loads::shapes::triangle(mid, tr), (omega * mid).sin());
        // The triangle on the piece: its value at u0 and its slope.
        let (v0, slope) = if mid < tr {
            (u0 / tr, 1.0 / tr)
        } else if mid < 2.0 * tr {
            (2.0 - u0 / tr, -1.0 / tr)
        } else {
            (0.0, 0.0)
        };
        let mut p = Piece { len: u1 - u0, omega, ..Piece::default() };
        for &(im, qu, fi, fq) in &axes {
            // The branch of `loads::shapes::weights` at the piece's midpoint (it holds on the piece).
            if tri_mid * fi > s_mid * fq {
                for (j, w) in parts(im).into_iter().enumerate() {
                    p.a[j] += w * v0;
                    p.b[j] += w * slope;
                }
            } else {
                for (ph, h) in p.h.iter_mut().zip(sine(qu, omega, u0)) {
                    *ph += h;
                }
            }
        }
        out.push(p);
    }
    out.push(sine_piece(event.trough.total(), half, period - half));
    (out.len() <= MAX_PIECES).then_some(())
}

/// θ's response to the load in the modes (module docs): with z̃_m = (θ·w_m) z_m, θ = Re Σ_m z̃_m;
/// a conjugate pair (m, k) is one coordinate ζ = z̃_m + conj(z̃_k), ζ' = λ_m ζ + (c_m + c̄_k)·p (the
/// load is real), and a real mode's imaginary part, which θ does not read, is left out.
#[derive(Debug, Clone, Copy)]
pub(super) struct ThetaModes {
    n: usize,
    lambda: [C64; 6],
    /// |λ|, 1/λ, 1/λ², and whether λ is real.
    size: [f64; 6],
    inv: [C64; 6],
    inv2: [C64; 6],
    real: [bool; 6],
    c: [[C64; 3]; 6],
}

impl ThetaModes {
    /// From the eigenvalues, θ's row in the modes φ_m = θ·w_m, W⁻¹ and M⁻¹.
    pub(super) fn new(lambda: &[C64; 6], phi: &[C64; 6], winv: &SMatrix<C64, 6, 6>, minv: &Matrix3<f64>) -> Self {
        let c_all: [[C64; 3]; 6] = std::array::from_fn(|m| {
            std::array::from_fn(|j| phi[m] * (0..3).map(|i| winv[(m, 3 + i)] * minv[(i, j)]).sum::<C64>())
        });
        let zero = C64::new(0.0, 0.0);
        let mut t = ThetaModes {
            n: 0,
            lambda: [zero; 6],
            size: [0.0; 6],
            inv: [zero; 6],
            inv2: [zero; 6],
            real: [false; 6],
            c: [[zero; 3]; 6],
        };
        let mut used = [false; 6];
        for m in 0..6 {
            if used[m] {
                continue;
            }
            used[m] = true;
            let (l, mut c) = (lambda[m], c_all[m]);
            let real = l.im == 0.0;
            if real {
                c = c.map(|x| C64::new(x.re, 0.0));
            } else if let Some(k) = (m + 1..6).find(|&k| !used[k] && lambda[k] == l.conj()) {
                used[k] = true;
                c = std::array::from_fn(|j| c[j] + c_all[k][j].conj());
            }
            let i = t.n;
            t.lambda[i] = l;
            t.size[i] = modulus(l);
            t.inv[i] = C64::new(1.0, 0.0) / l;
            t.inv2[i] = t.inv[i] * t.inv[i];
            t.real[i] = real;
            t.c[i] = c;
            t.n += 1;
        }
        t
    }

    /// The functional a f + b g of this one (f) and `other` (g), built from the same eigenvalues.
    pub(super) fn combined(&self, a: f64, other: &ThetaModes, b: f64) -> ThetaModes {
        ThetaModes {
            c: std::array::from_fn(|m| std::array::from_fn(|j| self.c[m][j] * a + other.c[m][j] * b)),
            ..*self
        }
    }

    /// e^{λ_m s}.
    #[inline]
    fn exp(&self, m: usize, s: f64) -> C64 {
        let l = self.lambda[m];
        if self.real[m] {
            C64::new((l.re * s).exp(), 0.0)
        } else {
            (l * s).exp()
        }
    }
}

/// The factors of θ at an instant s of a piece: e^{iΩs}, e^{λ_m s} and its modulus e^{Re λ_m s}
/// (the bound's decay), each the same bits as computed alone.
#[derive(Debug, Clone, Copy)]
struct Factors {
    rot: C64,
    exp: [C64; 6],
    decay: [f64; 6],
}

impl Factors {
    fn at(md: &ThetaModes, omega: f64, s: f64) -> Self {
        let mut f = Factors { rot: C64::from_polar(1.0, omega * s), exp: [C64::new(0.0, 0.0); 6], decay: [0.0; 6] };
        for m in 0..md.n {
            let l = md.lambda[m];
            let x = l.re * s;
            let r = x.exp();
            f.decay[m] = r;
            // `ThetaModes::exp`: a complex mode's e^{λs} is `Complex::exp`, from_polar(e^{Re λs},
            // Im λs) where Re λs is finite.
            f.exp[m] = if md.real[m] {
                C64::new(r, 0.0)
            } else if x.is_finite() {
                C64::from_polar(r, l.im * s)
            } else {
                md.exp(m, s)
            };
        }
        f
    }
}

/// A wave's pieces with the factors at their ends ([`Factors`] at s = len), shared by every
/// functional built from the same eigenvalues (the rotation, the toe's and the heel's pressures).
struct PieceEnds {
    ends: Vec<Factors>,
}

impl PieceEnds {
    fn new(md: &ThetaModes, ps: &[Piece]) -> Self {
        PieceEnds { ends: ps.iter().map(|p| Factors::at(md, p.omega, p.len)).collect() }
    }
}

/// θ on one piece (module docs): A + B s + Re(G e^{iΩs}) + Re Σ_m E_m e^{λ_m s}, and |E_m|.
#[derive(Debug, Clone, Copy)]
struct PieceTheta {
    len: f64,
    a: f64,
    b: f64,
    g: C64,
    g_abs: f64,
    omega: f64,
    e: [C64; 6],
    e_abs: [f64; 6],
}

impl PieceTheta {
    /// The piece `p` from the modal coordinates `z` at its start, which are moved to its end
    /// (`end`: the factors at s = len).
    fn new(md: &ThetaModes, p: &Piece, end: &Factors, z: &mut [C64; 6]) -> Self {
        let zero = C64::new(0.0, 0.0);
        let iw = C64::new(0.0, p.omega);
        let (end_rot, len) = (end.rot, p.len);
        let harmonic = p.h.iter().any(|h| *h != zero);
        let mut th =
            PieceTheta { len, a: 0.0, b: 0.0, g: zero, g_abs: 0.0, omega: p.omega, e: [zero; 6], e_abs: [0.0; 6] };
        for (m, zm) in z.iter_mut().enumerate().take(md.n) {
            let (l, c) = (md.lambda[m], &md.c[m]);
            let dot = |v: &[f64; 3]| -> C64 { (0..3).map(|j| c[j] * v[j]).sum() };
            let (alpha, beta) = (dot(&p.a), dot(&p.b));
            let (hp, hm) = if harmonic {
                let eta: C64 = (0..3).map(|j| c[j] * p.h[j]).sum();
                let eta2: C64 = (0..3).map(|j| c[j] * p.h[j].conj()).sum();
                (eta * 0.5 / (iw - l), eta2 * 0.5 / (-iw - l))
            } else {
                (zero, zero)
            };
            let constant = -alpha * md.inv[m] - beta * md.inv2[m];
            let linear = -beta * md.inv[m];
            th.a += constant.re;
            th.b += linear.re;
            th.g += hp + hm.conj();
            let e = *zm - (constant + hp + hm);
            th.e[m] = e;
            th.e_abs[m] = modulus(e);
            *zm = constant + linear * len + hp * end_rot + hm * end_rot.conj() + e * end.exp[m];
        }
        th.g_abs = modulus(th.g);
        th
    }

    /// θ at s with the factors `f` at s ([`Factors::at`]).
    fn value(&self, md: &ThetaModes, s: f64, f: &Factors) -> f64 {
        let mut v = self.a + self.b * s;
        if self.g_abs != 0.0 {
            v += (self.g * f.rot).re;
        }
        for m in 0..md.n {
            if self.e_abs[m] != 0.0 {
                v += if md.real[m] { self.e[m].re * f.exp[m].re } else { (self.e[m] * f.exp[m]).re };
            }
        }
        v
    }

    /// A bound of `measure`(θ) on [s1, s2] from its ends' values `f1`, `f2` (module docs), with
    /// e^{Re λ_m s1} `decay1` ([`Factors`]).
    fn bound(
        &self,
        md: &ThetaModes,
        (s1, s2): (f64, f64),
        (f1, f2): (f64, f64),
        decay1: &[f64; 6],
        measure: Measure,
    ) -> f64 {
        let (g, w) = (self.g_abs, self.omega);
        let (mut k1, mut k2, mut k0) = (self.b.abs() + g * w, g * w * w, g);
        for ((&e_abs, &decay), &n) in self.e_abs.iter().zip(decay1).zip(&md.size).take(md.n) {
            if e_abs == 0.0 {
                continue;
            }
            let env = e_abs * decay;
            k0 += env;
            k1 += env * n;
            k2 += env * n * n;
        }
        let h = s2 - s1;
        let ends = measure.of(f1).max(measure.of(f2));
        let terms = measure.of(self.a + self.b * s1).max(measure.of(self.a + self.b * s2)) + k0;
        (ends + (0.125 * k2 * h * h).min(0.5 * k1 * h)).min(terms)
    }
}

/// What is bounded of a functional: its magnitude, or its value, or its negative.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Measure {
    Abs,
    Up,
    Down,
}

impl Measure {
    #[inline]
    fn of(self, x: f64) -> f64 {
        match self {
            Measure::Abs => x.abs(),
            Measure::Up => x,
            Measure::Down => -x,
        }
    }
}

/// What a sharpened bound is asked for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Ask {
    /// The bound, within [`TOLERANCE`] of the largest value evaluated.
    Tight,
    /// Only whether the largest value is at most this: a bound at most it where that is shown,
    /// +∞ as soon as a value above it is evaluated (nothing can be shown then), else the bound as
    /// [`Ask::Tight`] gives it.
    AtMost(f64),
}

/// A bound on the largest `measure` of the functional of `md` over the pieces `ps` of a wave's
/// load from rest (module docs), as `ask` asks for it.
///
/// `ends` are the factors at the pieces' ends ([`PieceEnds::new`] of the same eigenvalues): θ at a
/// piece's start and end, and the bound's decay at its start, are read from them and from the
/// factors at s = 0 rather than evaluated again (the same bits); only the midpoints take new
/// exponentials, and an interval keeps e^{Re λ_m s} at its start for its bound.
fn largest(md: &ThetaModes, ps: &[Piece], ends: &PieceEnds, ask: Ask, measure: Measure) -> f64 {
    // Intervals whose bound is at most `floor` are not refined; a value evaluated above
    // `give_up` leaves nothing to show.
    let (floor, give_up) = match ask {
        Ask::Tight => (f64::NEG_INFINITY, f64::INFINITY),
        Ask::AtMost(x) => (x, x),
    };
    let mut z = [C64::new(0.0, 0.0); 6];
    let thetas: Vec<PieceTheta> =
        ps.iter().zip(&ends.ends).map(|(p, end)| PieceTheta::new(md, p, end, &mut z)).collect();
    let mut lo = f64::NEG_INFINITY;
    let mut open: Vec<(usize, f64, f64, f64, f64, [f64; 6])> = Vec::with_capacity(64);
    let mut evaluations = 0;
    // The factors at s = 0 are the same on every piece (Ω·0 = 0).
    let start = Factors::at(md, 1.0, 0.0);
    for (i, th) in thetas.iter().enumerate() {
        let (f1, f2) = (th.value(md, 0.0, &start), th.value(md, th.len, &ends.ends[i]));
        evaluations += 2;
        lo = lo.max(measure.of(f1)).max(measure.of(f2));
        open.push((i, 0.0, th.len, f1, f2, start.decay));
    }
    if lo > give_up {
        return f64::INFINITY;
    }
    let mut upper = f64::NEG_INFINITY;
    while let Some((i, s1, s2, f1, f2, decay1)) = open.pop() {
        let th = &thetas[i];
        let b = th.bound(md, (s1, s2), (f1, f2), &decay1, measure);
        let enough = floor.max(lo + TOLERANCE * lo.abs());
        if b <= enough || evaluations >= MAX_EVALUATIONS || s2 - s1 <= 1e-9 * th.len {
            upper = upper.max(b);
            continue;
        }
        let mid = 0.5 * (s1 + s2);
        let at_mid = Factors::at(md, th.omega, mid);
        let fm = th.value(md, mid, &at_mid);
        evaluations += 1;
        lo = lo.max(measure.of(fm));
        if lo > give_up {
            return f64::INFINITY;
        }
        open.push((i, s1, mid, f1, fm, decay1));
        open.push((i, mid, s2, fm, f2, at_mid.decay));
    }
    upper + 1e-9 * upper.abs()
}

impl StickBound {
    /// A bound on the largest |θ| of the all-sticking response to `event` over [0, T] (module
    /// docs of `history.rs`), as `ask` asks for it (rad); `None` for a load shape it does not
    /// follow.
    pub fn rotation_under_history_rad(&self, event: &WaveEvent, ask: Ask) -> Option<f64> {
        let mut ps = Vec::with_capacity(MAX_PIECES);
        pieces(event, &mut ps)?;
        let ends = PieceEnds::new(&self.modes.theta, &ps);
        Some(largest(&self.modes.theta, &ps, &ends, ask, Measure::Abs))
    }

    /// A bound on the largest heel pressure of the all-sticking response to `event` over [0, T]
    /// on a base `width_m` wide and `length_m` long, Pa (the lifetime's [`base_heel_pressure_pa`]
    /// of the springs' resultant V = W' + ΣΔN_i, M = Σ x_i N_i): while the resultant is within
    /// the middle third, the toe's linear pressure (V/B − 6M/B²)/l ≥ 0, the heel's is linear in
    /// the state, (V/B + 6M/B²)/l, and bounded as θ is (module docs). `None` where the toe's
    /// pressure's bound comes within [`TOE_RESERVE`] of its value at rest of 0 (the base may
    /// open: the heel pressure is not linear there), or for a load shape it does not follow.
    ///
    /// [`base_heel_pressure_pa`]: crate::analysis::lifetime::base_heel_pressure_pa
    pub fn heel_under_history_pa(&self, event: &WaveEvent, width_m: f64, length_m: f64, ask: Ask) -> Option<f64> {
        let mut ps = Vec::with_capacity(MAX_PIECES);
        pieces(event, &mut ps)?;
        let md = &self.modes;
        let (v, b) = (1.0 / (length_m * width_m), 6.0 / (length_m * width_m * width_m));
        let moment_rest = self.n_ref * md.sum_x_m;
        let toe_rest = v * self.weight_n - b * moment_rest;
        if toe_rest <= 0.0 || toe_rest.is_nan() {
            return None;
        }
        let toe = md.normal.combined(v, &md.moment, -b);
        // The toe's and the heel's functionals share their eigenvalues, so the pieces' ends.
        let ends = PieceEnds::new(&toe, &ps);
        let toe_floor = (1.0 - TOE_RESERVE) * toe_rest;
        if largest(&toe, &ps, &ends, Ask::AtMost(toe_floor), Measure::Down) >= toe_floor {
            return None;
        }
        let heel_rest = self.heel_at_rest_pa(width_m, length_m);
        let heel = md.normal.combined(v, &md.moment, b);
        let ask = match ask {
            Ask::AtMost(pa) => Ask::AtMost(pa - heel_rest),
            Ask::Tight => Ask::Tight,
        };
        Some(heel_rest + largest(&heel, &ps, &ends, ask, Measure::Up))
    }

    /// The heel pressure at rest of the springs' resultant (W', N̄ Σ x_i) on a base `width_m` wide
    /// and `length_m` long, Pa: where [`Self::heel_under_history_pa`] starts from.
    pub fn heel_at_rest_pa(&self, width_m: f64, length_m: f64) -> f64 {
        let (v, b) = (1.0 / (length_m * width_m), 6.0 / (length_m * width_m * width_m));
        v * self.weight_n + b * self.n_ref * self.modes.sum_x_m
    }
}
