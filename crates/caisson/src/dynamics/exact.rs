//! The all-sticking phase advanced by exponential integration (docs/model.md §9.1, "Sticking
//! phases"): while every spring is in contact and sticks, the equations of motion are linear but
//! for one bilinear term, and a step of one of the ladder's lengths h is the exact solution of the
//! linear part with the rest as an interpolated force.
//!
//! With N_i = a + b x_i (a = −k_y u_y, b = k_y θ) and e_i = u_x − s_i, every sticking spring's
//! force is κ N_i e_i plus its dashpot c_d ė_i = c_d u̇_x (`elastic` mode; `foundation::spring`),
//! so with a_r = W'/n, the normal force of a spring at rest:
//!
//! ```text
//! M q̈ + C_L q̇ + K_L q = p(t) + (0, −W', 0) + (κ a_r Σd_i, 0, 0) − R(q) e_x,
//! R(q) = κ [(a − a_r) Σe_i + b Σx_i e_i]           (the shear's departure from K_x u_x)
//! K_L = [κ W', 0, 0; 0, n k_y, −k_y Σx; 0, −k_y Σx, k_y Σx²]
//! C_L = C + [n c_d, 0, 0; 0, n c_y, −c_y Σx; 0, −c_y Σx, c_y Σx²]
//! ```
//!
//! in q = (u_x − s_1, u_y, θ) (d_i = s_i − s_1; C the linear dashpots, c_y the vertical dashpots
//! beside the springs). R vanishes at rest and stays small beside K_x u_x (the normal force's
//! departure from a_r times the elastic displacement). In first-order form y = (q, q̇),
//! y' = A y + B g(t), B = (0; M⁻¹), and for a force g quadratic in the step's time σ,
//! g = c_0 + c_1 σ + c_2 σ², the exact solution at σ = h is
//!
//! ```text
//! y(h) = e^{hA} y_0 + E_1 c_0 + E_2 c_1 + 2 E_3 c_2,   E_k = ∫_0^h e^{(h−σ)A} B σ^{k−1}/(k−1)! dσ
//! ```
//!
//! all four blocks of the exponential of one 15 × 15 matrix (Â = [A, B, 0, 0; 0, 0, I, 0;
//! 0, 0, 0, I; 0]·h: Van Loan 1978), computed once per thread and matrices for each length h of
//! the ladder, when a step first needs it. The load is
//! interpolated through the step's start, middle and end (third order); R through the step's end,
//! its start and the previous step's start when that step was exact too (otherwise through its
//! value and rate Ṙ = ∇R·q̇ at the start and its value at the end), so that R(h) is the one unknown: y(h) is affine in it, R quadratic in y, and R(h) the root of a
//! quadratic (the one that tends to the linear solution, as in `sticking`).
//!
//! The step is taken only from a committed all-sticking state, when no load breakpoint falls
//! inside it, and kept only if every spring sticks at its end and in its middle by the spring
//! law's own test (`sticking`), and if its error estimate is within the adaptive tolerance:
//! the middle y(h/2) follows exactly from the same interpolated force (the blocks of the
//! exponential for h/2), R there against its interpolation there, δR, is a force through
//! σ = 0, h/2, h vanishing at the ends, which moves the end by δR times the middle value's
//! weights (the largest of the u_x, u_y and θ B/2 rows, m). Otherwise the Newmark step is taken
//! from the same state (which locates the onset of slip).
//! Its end is committed as an all-sticking Newmark step would be.
//!
//! **The ladder** (results version 17): the step lengths are h_k = dt_max/2^k, k = 0, 1, 2
//! ([`RUNGS`]). A step tries the rung above the last accepted one (the longest at a run's
//! start), or the longest rung that ends by the load's next breakpoint (and by the run's end):
//! the gap left before a breakpoint, shorter than dt_max/4, is one Newmark step. A step refused
//! by its error estimate is retried on the next shorter rung; one refused on the shortest rung,
//! or because a spring slips or lifts in it, is taken by Newmark from the same state, starting
//! at h/2 (no exact step is tried again before the refused step's end), and the exact steps
//! resume from the rung they left. Before (results versions 14-16) only dt_max was exact: the
//! stretch between the last step of dt_max and a breakpoint, and every step after a refused
//! one, were Newmark steps from the stepper's last Newmark length (at a wave's start the first
//! step, 1 ms), which then doubled step by step.

use super::{Converged, Model, Observer, Simulation};
use crate::loads::LoadHistory;
use nalgebra::{Matrix3, SMatrix, Vector3};
use std::sync::{Arc, OnceLock};

/// A 6 × 3 block, column by column.
type Block = [[f64; 6]; 3];

/// The propagators of an all-sticking step of length `h` (module docs).
#[derive(Debug, Clone)]
pub(super) struct Propagator {
    /// e^{hA}, column by column.
    e0: [[f64; 6]; 6],
    /// The weights F_j of the force at σ = 0, h and −h (the previous step exact).
    before: [Block; 3],
    /// The weights of the load at σ = 0, h/2 and h (the first exact step of a phase).
    middle: [Block; 3],
    /// The x columns of the weights of R and Ṙ at σ = 0 and R at h, R quadratic in σ through
    /// them (the first exact step of a phase).
    hermite_x: [[f64; 6]; 3],
    /// e^{hA/2}, column by column: to the step's middle.
    half_e0: [[f64; 6]; 6],
    /// The weights of c_0, c_1 and c_2 (g = c_0 + c_1 σ + c_2 σ²) at σ = h/2.
    half_c: [Block; 3],
    minv: Matrix3<f64>,
    k_l: Matrix3<f64>,
    c_l: Matrix3<f64>,
}

/// Rungs of the ladder of step lengths: dt_max / 2^k, k = 0 .. RUNGS − 1.
pub(super) const RUNGS: usize = 3;

/// The propagators of every rung, each built when a step first needs it (`None` if it cannot
/// be: a singular mass matrix or an exponential that is not finite); shared by the ladders of
/// one thread with the same matrices.
type Rungs = Arc<[OnceLock<Option<Propagator>>; RUNGS]>;

/// The propagators of every step length of the ladder (module docs, "The ladder"), and the rung
/// to try next.
#[derive(Debug, Clone)]
pub(super) struct Ladder {
    dt_max_s: f64,
    rungs: Rungs,
    /// a_r = W'/n, N.
    a_ref: f64,
    /// The rung to try first.
    k: usize,
}

/// M, K_L, C_L and dt_max, the numbers the propagators of a ladder come from.
type Key = [f64; 28];

/// How an exact step failed.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Refused {
    /// A spring slips or lifts at the step's end or in its middle, or the root is not real: the
    /// Newmark step locates the event.
    Stick,
    /// The error estimate exceeds the tolerance: a shorter step may do.
    Error,
}

/// What an exact step keeps for the next one: its end time, R and the load at its start.
#[derive(Debug, Clone, Copy)]
pub(super) struct Previous {
    t_end_s: f64,
    h_s: f64,
    r_start_n: f64,
    /// The load (gravity included) at its start, N.
    p_start: Vector3<f64>,
}

/// Where the step's load is known besides its start and end: at its middle, or at the start of
/// the previous (exact) step, σ = −h.
#[derive(Debug, Clone, Copy)]
pub(super) enum Third {
    Middle(Vector3<f64>),
    Before(Vector3<f64>),
}

/// Ladders kept per thread, the most recent last: the caissons of a design life's storms share
/// their matrices (their weight in water changes with the tide, the propagators do not), and a
/// sizing run alternates among a few widths.
const CACHED_LADDERS: usize = 4;

thread_local! {
    static LADDERS: std::cell::RefCell<[Option<(Key, Rungs)>; CACHED_LADDERS]> =
        const { std::cell::RefCell::new([const { None }; CACHED_LADDERS]) };
}

/// Σ_k m_ik x_k for the six rows i of a matrix stored column by column (`columns[k][i]` = m_ik):
/// each row's sum from −0.0 in the order of k, the operations of `Iterator::sum` over the row
/// one for one (the same bits), with the six rows side by side, which the compiler vectorizes.
#[inline(always)]
fn mul<const K: usize>(columns: &[[f64; 6]; K], x: &[f64; K]) -> [f64; 6] {
    let mut y = [-0.0; 6];
    for (column, &xk) in columns.iter().zip(x) {
        for (yi, &m) in y.iter_mut().zip(column) {
            *yi += m * xk;
        }
    }
    y
}

impl Propagator {
    /// M, K_L and C_L of `model` (module docs).
    fn matrices(model: &Model) -> (Matrix3<f64>, Matrix3<f64>, Matrix3<f64>) {
        let law = model.law;
        let n = model.x_m.len() as f64;
        let (sx, sx2) = model.x_m.iter().fold((0.0, 0.0), |(a, b), x| (a + x, b + x * x));
        let ky = law.ky_n_per_m;
        let (cd, cy) = (model.spring_dashpot_ns_per_m, model.spring_vertical_dashpot_ns_per_m);
        let k_l = Matrix3::new(model.kx_n_per_m, 0.0, 0.0, 0.0, n * ky, -ky * sx, 0.0, -ky * sx, ky * sx2);
        let c_l = model.damping + Matrix3::new(n * cd, 0.0, 0.0, 0.0, n * cy, -cy * sx, 0.0, -cy * sx, cy * sx2);
        (model.mass, k_l, c_l)
    }

    /// The propagators of `model` for steps of `h`; `None` if the mass matrix is singular or the
    /// exponential is not finite.
    pub fn new(model: &Model, h: f64) -> Option<Self> {
        let (mass, k_l, c_l) = Self::matrices(model);
        let minv = mass.try_inverse()?;
        let (mk, mc) = (-minv * k_l, -minv * c_l);
        // e^{h Â} (module docs): y = (q, q̇), then the chain z0' = z1, z1' = z2 of the force.
        let van_loan = |h: f64| {
            let mut big = SMatrix::<f64, 15, 15>::zeros();
            for i in 0..3 {
                big[(i, 3 + i)] = h;
                for j in 0..3 {
                    big[(3 + i, j)] = h * mk[(i, j)];
                    big[(3 + i, 3 + j)] = h * mc[(i, j)];
                    big[(3 + i, 6 + j)] = h * minv[(i, j)];
                }
                big[(6 + i, 9 + i)] = h;
                big[(9 + i, 12 + i)] = h;
            }
            let ex = big.exp();
            ex.iter().all(|v| v.is_finite()).then_some(ex)
        };
        let (ex, hx) = (van_loan(h)?, van_loan(0.5 * h)?);
        // To the middle: e^{hA/2} and the weights of c_0, c_1, c_2 (E_1, E_2, 2 E_3 at h/2).
        let half_e0 = std::array::from_fn(|j| std::array::from_fn(|i| hx[(i, j)]));
        let half_c = std::array::from_fn(|k| {
            let w = if k == 2 { 2.0 } else { 1.0 };
            std::array::from_fn(|j| std::array::from_fn(|i| w * hx[(i, 6 + 3 * k + j)]))
        });
        let e0 = std::array::from_fn(|j| std::array::from_fn(|i| ex[(i, j)]));
        // E_1, E_2, E_3 (module docs) and the weights of g = c_0 + c_1 σ + c_2 σ² as
        // E_1 c_0 + E_2 c_1 + 2 E_3 c_2, combined per interpolation point.
        let e = |k: usize, i: usize, j: usize| ex[(i, 6 + 3 * k + j)];
        let block = |w: [f64; 3]| -> Block {
            std::array::from_fn(|j| std::array::from_fn(|i| w[0] * e(0, i, j) + w[1] * e(1, i, j) + w[2] * e(2, i, j)))
        };
        let h2 = h * h;
        // Through σ = 0, h, −h: c_0 = g0, c_1 = (g1 − g−)/(2h), c_2 = (g1 − 2 g0 + g−)/(2h²).
        let before = [block([1.0, 0.0, -2.0 / h2]), block([0.0, 0.5 / h, 1.0 / h2]), block([0.0, -0.5 / h, 1.0 / h2])];
        // Through σ = 0, h/2, h: c_1 = (4 gm − 3 g0 − g1)/h, c_2 = 2 (g0 − 2 gm + g1)/h².
        let middle =
            [block([1.0, -3.0 / h, 4.0 / h2]), block([0.0, 4.0 / h, -8.0 / h2]), block([0.0, -1.0 / h, 4.0 / h2])];
        // Through R and Ṙ at σ = 0 and R at h: c_0 = R0, c_1 = Ṙ0, c_2 = (R1 − R0 − Ṙ0 h)/h².
        let hermite_x = [
            std::array::from_fn(|i| e(0, i, 0) - 2.0 * e(2, i, 0) / h2),
            std::array::from_fn(|i| e(1, i, 0) - 2.0 * e(2, i, 0) / h),
            std::array::from_fn(|i| 2.0 * e(2, i, 0) / h2),
        ];
        Some(Propagator { e0, before, middle, hermite_x, half_e0, half_c, minv, k_l, c_l })
    }
}

impl Model {
    /// M, K_L and C_L of the all-sticking equations of motion (module docs): the linear system
    /// whose response the design run's screen bounds (`analysis::stick_bound`).
    pub fn sticking_matrices(&self) -> (Matrix3<f64>, Matrix3<f64>, Matrix3<f64>) {
        Propagator::matrices(self)
    }
}

impl Ladder {
    /// The ladder of `model` for steps up to `dt_max_s`, sharing the propagators of this
    /// thread's ladder of the same matrices and dt_max (the same numbers: nothing else enters
    /// them). `None` if the longest step's cannot be built (a singular mass matrix).
    pub fn cached(model: &Model, dt_max_s: f64) -> Option<Self> {
        let (m, k, c) = Propagator::matrices(model);
        let mut key = [0.0; 28];
        key[..9].copy_from_slice(m.as_slice());
        key[9..18].copy_from_slice(k.as_slice());
        key[18..27].copy_from_slice(c.as_slice());
        key[27] = dt_max_s;
        let rungs = LADDERS.with(|l| {
            let mut l = l.borrow_mut();
            if let Some((_, r)) = l.iter().flatten().find(|(k, _)| *k == key) {
                return r.clone();
            }
            let r: Rungs = Arc::new([const { OnceLock::new() }; RUNGS]);
            l.rotate_left(1);
            l[CACHED_LADDERS - 1] = Some((key, r.clone()));
            r
        });
        let ladder = Ladder { dt_max_s, rungs, a_ref: model.weight_n / model.x_m.len() as f64, k: 0 };
        ladder.rung(model, 0)?;
        Some(ladder)
    }

    /// The step length of rung `k`, s.
    #[inline]
    pub fn h(&self, k: usize) -> f64 {
        self.dt_max_s / (1u32 << k) as f64
    }

    /// The propagators of rung `k`, built if they are not yet.
    #[inline]
    fn rung(&self, model: &Model, k: usize) -> Option<&Propagator> {
        self.rungs[k].get_or_init(|| Propagator::new(model, self.h(k))).as_ref()
    }

    /// Back to the longest step (a new run from rest).
    pub fn restart(&mut self) {
        self.k = 0;
    }
}

impl Simulation {
    /// From the committed all-sticking state, one exact step of the ladder if one fits before
    /// the load's next breakpoint `bp_s` and `t_end_s` (module docs, "The ladder"): the rung to
    /// try first, or the longest that fits; halved while the error estimate refuses it. Whether a
    /// step was committed; if not, the Newmark step is next, from `h_next`.
    pub(super) fn exact_advance<L: LoadHistory + ?Sized, O: Observer + ?Sized>(
        &mut self,
        bp_s: f64,
        t_end_s: f64,
        tolerance_m: f64,
        load: &L,
        obs: &mut O,
    ) -> bool {
        let t = self.state.t_s;
        let Some(ladder) = self.exact.as_ref() else {
            return false;
        };
        let room = bp_s.min(t_end_s) - t;
        // Less than the shortest rung to the breakpoint: Newmark steps to it.
        let Some(first) = (ladder.k..RUNGS).find(|&k| ladder.h(k) <= room) else {
            return false;
        };
        // The load at the start: the committed step's, if it is known.
        let p0 = match self.last_load {
            Some((tl, p)) if tl == t => p,
            _ => self.load_vector(load.at(t)),
        };
        for k in first..RUNGS {
            let ladder = self.exact.as_ref().expect("checked above");
            let h = ladder.h(k);
            let t1 = t + h;
            let third = match self.exact_prev.filter(|p| p.t_end_s == t && p.h_s == h) {
                Some(p) => Third::Before(p.p_start),
                None => Third::Middle(self.load_vector(load.at(t + 0.5 * h))),
            };
            let w1 = load.at(t1);
            match self.exact_sticking_step(k, p0, self.load_vector(w1), third, tolerance_m) {
                Ok(c) => {
                    self.stats.exact_steps += 1;
                    self.commit_observed(h, c, t1, w1, obs);
                    let ladder = self.exact.as_mut().expect("checked above");
                    // The next step tries the rung above (measured on the design example: the
                    // rung above whatever the estimate costs fewer instructions than waiting
                    // until it is within 1/16 of the tolerance, 1.893 G against 1.970 G).
                    ladder.k = k.saturating_sub(1);
                    self.h_next = h;
                    return true;
                }
                Err(Refused::Error) if k + 1 < RUNGS => {
                    self.exact.as_mut().expect("checked above").k = k + 1;
                }
                Err(_) => {
                    // A spring slips or lifts within the step (or the shortest rung is too
                    // long): Newmark steps over it, and locate the event.
                    self.exact_retry_s = t1;
                    self.h_next = 0.5 * h;
                    return false;
                }
            }
        }
        false
    }

    /// One all-sticking step of rung `k` of the ladder from the committed state (module docs),
    /// with the loads (gravity included) `p0` at its start, `p1` at its end and a `third` point.
    /// Refused if a spring does not stick at its end or in
    /// its middle or the root is not real ([`Refused::Stick`]), or if the error estimate of R's
    /// interpolation exceeds `tolerance_m` ([`Refused::Error`]): nothing is changed then but the
    /// fast path's iterate.
    pub(super) fn exact_sticking_step(
        &mut self,
        k: usize,
        p0: Vector3<f64>,
        p1: Vector3<f64>,
        third: Third,
        tolerance_m: f64,
    ) -> Result<Converged, Refused> {
        let [n, sx, s1, sum_d, sum_xd] = self.slip_sums();
        let (ladder, model) = (self.exact.as_ref().ok_or(Refused::Stick)?, &self.model);
        let h = ladder.h(k);
        let a_ref = ladder.a_ref;
        let pr = ladder.rung(model, k).ok_or(Refused::Stick)?;
        let law = self.model.law;
        let (ky, kappa) = (law.ky_n_per_m, law.kappa_per_m);
        // R at q = (u_x − s_1, u_y, θ).
        let r_of = |q: &[f64]| {
            let (a, b) = (-ky * q[1], ky * q[2]);
            kappa * ((a - a_ref) * (n * q[0] - sum_d) + b * (sx * q[0] - sum_xd))
        };
        let (un, vn) = (self.state.u, self.state.v);
        let y0 = [un[0] - s1, un[1], un[2], vn[0], vn[1], vn[2]];
        let r0 = r_of(&y0);
        // Ṙ at the start: R's gradient in q times q̇.
        let r0_rate = {
            let (a, b) = (-ky * y0[1], ky * y0[2]);
            let (se, sxe) = (n * y0[0] - sum_d, sx * y0[0] - sum_xd);
            kappa * (-ky * y0[4] * se + (a - a_ref) * n * y0[3] + ky * y0[5] * sxe + b * sx * y0[3])
        };
        // The force g = p + (κ a_r Σd, 0, 0) − R e_x.
        let shift = kappa * a_ref * sum_d;
        let g = |p: Vector3<f64>, r: f64| [p[0] + shift - r, p[1], p[2]];
        let mut y = mul(&pr.e0, &y0);
        let mut add = |w: &Block, g: [f64; 3]| {
            let d = mul(w, &g);
            y.iter_mut().zip(d).for_each(|(a, b)| *a += b);
        };
        // y(h) = y* + γ R(h).
        let prev = self.exact_prev.filter(|p| p.t_end_s == self.state.t_s && p.h_s == h);
        let gamma: [f64; 6] = match (third, prev) {
            (Third::Before(pb), Some(p)) => {
                add(&pr.before[0], g(p0, r0));
                add(&pr.before[1], g(p1, 0.0));
                add(&pr.before[2], g(pb, p.r_start_n));
                pr.before[1][0].map(|w| -w)
            }
            (Third::Middle(pm), _) => {
                add(&pr.middle[0], g(p0, 0.0));
                add(&pr.middle[1], g(pm, 0.0));
                add(&pr.middle[2], g(p1, 0.0));
                y.iter_mut().zip(pr.hermite_x[0]).for_each(|(a, w)| *a -= w * r0);
                y.iter_mut().zip(pr.hermite_x[1]).for_each(|(a, w)| *a -= w * r0_rate);
                std::array::from_fn(|i| -pr.hermite_x[2][i])
            }
            (Third::Before(_), None) => return Err(Refused::Stick),
        };
        // R(y* + γ R) = R: a quadratic in R.
        let (a, b) = (-ky * y[1], ky * y[2]);
        let (se, sxe) = (n * y[0] - sum_d, sx * y[0] - sum_xd);
        let qc = kappa * ((a - a_ref) * se + b * sxe);
        let qb =
            kappa * ((a - a_ref) * n * gamma[0] - ky * gamma[1] * se + b * sx * gamma[0] + ky * gamma[2] * sxe) - 1.0;
        let qa = kappa * ky * gamma[0] * (gamma[2] * sx - gamma[1] * n);
        let disc = qb * qb - 4.0 * qa * qc;
        if !(disc >= 0.0 && qb != 0.0) {
            return Err(Refused::Stick);
        }
        let r1 = -2.0 * qc / (qb + qb.signum() * disc.sqrt());
        y.iter_mut().zip(gamma).for_each(|(a, w)| *a += w * r1);
        let q1 = Vector3::new(y[0], y[1], y[2]);
        let v1 = Vector3::new(y[3], y[4], y[5]);
        let u = [q1[0] + s1, q1[1], q1[2]];
        let v = [v1[0], v1[1], v1[2]];
        // The step's middle under the same interpolated force: its quadratic through the three
        // points (R linear on the first step of a phase: its value in the middle is the mean).
        let r_prev = prev.map_or(0.0, |p| p.r_start_n);
        let r_mid = match third {
            Third::Before(_) => (3.0 * r1 + 6.0 * r0 - r_prev) / 8.0,
            Third::Middle(_) => 0.75 * r0 + 0.25 * r1 + 0.25 * h * r0_rate,
        };
        let (g0, g1) = (g(p0, r0), g(p1, r1));
        let c: [[f64; 3]; 3] = match third {
            Third::Before(pb) => {
                let gb = g(pb, r_prev);
                let h2 = h * h;
                [
                    g0,
                    std::array::from_fn(|i| (g1[i] - gb[i]) / (2.0 * h)),
                    std::array::from_fn(|i| (g1[i] - 2.0 * g0[i] + gb[i]) / (2.0 * h2)),
                ]
            }
            Third::Middle(pm) => {
                // The load through σ = 0, h/2, h, less R through R0, Ṙ0 and R1.
                let (l0, lm, l1) = (g(p0, 0.0), g(pm, 0.0), g(p1, 0.0));
                let mut c = [
                    l0,
                    std::array::from_fn(|i| (4.0 * lm[i] - 3.0 * l0[i] - l1[i]) / h),
                    std::array::from_fn(|i| 2.0 * (l0[i] - 2.0 * lm[i] + l1[i]) / (h * h)),
                ];
                c[0][0] -= r0;
                c[1][0] -= r0_rate;
                c[2][0] -= (r1 - r0 - r0_rate * h) / (h * h);
                c
            }
        };
        let mut ym = mul(&pr.half_e0, &y0);
        for (w, ck) in pr.half_c.iter().zip(&c) {
            ym.iter_mut().zip(mul(w, ck)).for_each(|(a, b)| *a += b);
        }
        // The error estimate: R in the middle against its interpolation there, as a force through
        // σ = 0, h/2, h that is 0 at the ends, moves the step's end by the middle's weights.
        let dr = r_of(&ym) - r_mid;
        let w = &pr.middle[1][0];
        let err = dr.abs() * w[0].abs().max(w[1].abs()).max(w[2].abs() * 0.5 * self.model.width_m);
        if err > tolerance_m || err.is_nan() {
            return Err(Refused::Error);
        }
        // The acceleration at the end (not for a step refused by its error estimate).
        let acc = pr.minv * (Vector3::from(g1) - pr.k_l * q1 - pr.c_l * v1);
        // Every spring must stick in the middle of the step and at its end (the spring law's own
        // test; the last one records the sums of the commit and the base reaction).
        if !self.all_stick([ym[0] + s1, ym[1], ym[2]], 0.5 * h) {
            return Err(Refused::Stick);
        }
        self.sticking_force(u, v, h).ok_or(Refused::Stick)?;
        self.exact_prev = Some(Previous { t_end_s: self.state.t_s + h, h_s: h, r_start_n: r0, p_start: p0 });
        Ok(Converged { u, v, a: [acc[0], acc[1], acc[2]], iterations: 0, residual: 0.0 })
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::simulation_with;
    use super::super::{AdaptiveParams, SolverParams};
    use super::*;
    use crate::foundation::{DampingMode, VerticalDamping};
    use crate::loads::WaveForce;
    use crate::structure::MassMatrix;

    /// Exact steps against the closed form (oracle) of a damped oscillator under a ramp from rest
    /// (Chopra 2012, §4.5: u = (F/(K t_r)) [t − 2ζ/ω + e^{−ζωt} ((2ζ/ω) cos ω_D t
    /// − ((1 − 2ζ²)/ω_D) sin ω_D t)]): the Table 5 caisson with a diagonal mass matrix under a
    /// horizontal force through its base centre, so that u_y and θ stay at rest, R = 0 and u_x is
    /// that oscillator (K_x, m_x, the dashpots beside the springs: ζ = 0.64). On every rung of the
    /// ladder (dt_max = 5 ms), exact steps of its length to 50 ms while the springs stick (the
    /// force reaches a fifth of μ W'): each within 1e-12 of the largest displacement of the closed
    /// form (the exponential is exact to rounding, and a linear load is interpolated exactly;
    /// measured 8e-16).
    #[test]
    fn exact_steps_are_the_closed_form_of_a_ramp() {
        let dt_max = 5e-3;
        let solver = SolverParams::default()
            .with_adaptive(AdaptiveParams { dt_max_s: dt_max, ..AdaptiveParams::for_first_step(1e-4) })
            .unwrap();
        let (mut checked, mut worst) = (0, 0.0f64);
        for rung in 0..RUNGS {
            let mut sim = simulation_with(DampingMode::Elastic, VerticalDamping::Springs, MassMatrix::Diagonal, solver);
            let h = sim.exact.as_ref().expect("adaptive stepping builds the propagators").h(rung);
            assert_eq!(h, dt_max / (1 << rung) as f64);
            let (m, k) = (sim.model.horizontal_mass_kg(), sim.model.kx_n_per_m);
            let c = sim.model.spring_dashpot_ns_per_m * sim.model.x_m.len() as f64;
            let (w, zeta) = ((k / m).sqrt(), c / (2.0 * (k * m).sqrt()));
            let wd = w * (1.0 - zeta * zeta).sqrt();
            let (force, rise) = (0.2 * 0.6 * sim.model.weight_n, 0.05);
            let exact_u = |t: f64| {
                let e = (-zeta * w * t).exp();
                force / (k * rise)
                    * (t - 2.0 * zeta / w
                        + e * (2.0 * zeta / w * (wd * t).cos() - (1.0 - 2.0 * zeta * zeta) / wd * (wd * t).sin()))
            };
            let gravity = Vector3::new(0.0, -sim.model.weight_n, 0.0);
            let p = |t: f64| {
                let w = WaveForce::from_levers(force * t / rise, 0.0, 0.0, 0.0, 0.78);
                Vector3::new(w.fx_n, w.fy_n, w.m_nm) + gravity
            };
            let scale = exact_u(10.0 * dt_max);
            for i in 0..(10 << rung) {
                let t = sim.state.t_s;
                let third = if i == 0 { Third::Middle(p(t + 0.5 * h)) } else { Third::Before(p(t - h)) };
                let (p0, p1) = (p(t), p(t + h));
                let step = sim
                    .exact_sticking_step(rung, p0, p1, third, 1.0)
                    .unwrap_or_else(|e| panic!("rung {rung}, step {i}: {e:?} at {:?}", sim.state));
                sim.commit(h, step);
                let u = sim.state.u[0];
                worst = worst.max((u - exact_u(t + h)).abs() / scale);
                assert!(
                    (u - exact_u(t + h)).abs() <= 1e-12 * scale,
                    "rung {rung}, t = {}: {u} m, closed form {} m",
                    t + h,
                    exact_u(t + h)
                );
                assert!(sim.state.u[2].abs() < 1e-15, "no rotation");
                checked += 1;
            }
            assert!(zeta > 0.3 && zeta < 1.0, "ζ = {zeta}");
            assert!(scale > 1e-6, "it moves: {scale} m");
        }
        println!("largest difference {worst:.2e} of the largest displacement");
        assert_eq!(checked, (0..RUNGS).map(|k| 10 << k).sum::<usize>());
    }

    /// A sticking phase from rest to the end of a wave is crossed in exact steps, but for the gap
    /// before each of the wave's two breakpoints (T/2 and T: one Newmark step each, where the
    /// stepper once restarted from its first step and doubled): the Table 5 caisson with a
    /// diagonal mass matrix under a pulsating wave through its base centre (R = 0, so no error
    /// estimate refuses a step) reaching a fifth of μ W', T = 2.03 s, dt_max = 50 ms. Counted:
    /// 20 steps of dt_max and one of dt_max/4 to T/2 = 1.015 s, the 2.5 ms left in one Newmark
    /// step; after it the rungs climb again, dt_max/4, dt_max/2, then 19 steps of dt_max and one
    /// of dt_max/2 to T, and one Newmark step of 2.5 ms: 43 exact steps; no spring slips.
    #[test]
    fn a_sticking_wave_takes_exact_steps_to_its_breakpoints() {
        use crate::loads::history::{LoadComponent, WaveEvent, WaveTrain};
        let (dt_max, period) = (0.05, 2.03);
        let solver = SolverParams { dt_s: 1e-4, ..SolverParams::default() }
            .with_adaptive(AdaptiveParams { dt_max_s: dt_max, ..AdaptiveParams::for_first_step(1e-4) })
            .unwrap();
        let mut sim = simulation_with(DampingMode::Elastic, VerticalDamping::Springs, MassMatrix::Diagonal, solver);
        let push = LoadComponent::from_levers(0.2 * 0.6 * sim.model.weight_n, 0.0, 0.0, 0.39, 0.78);
        let wave = WaveEvent::new(0.0, period, push, 1.0, LoadComponent::default(), LoadComponent::default(), None);
        let train = WaveTrain::new(vec![wave]).unwrap();
        sim.reset(&train);
        sim.run_until(period, &train, &mut ()).unwrap();
        let s = sim.stats;
        assert!((sim.state.t_s - period).abs() < 1e-12, "t = {}", sim.state.t_s);
        assert_eq!(s.exact_steps, 21 + 22, "{s:?}");
        assert_eq!(s.steps - s.exact_steps, 2, "{s:?}");
        assert_eq!(s.rejected_steps, 0, "{s:?}");
        assert!(sim.state.springs.iter().all(|c| c.slip_m == 0.0 && !c.sliding), "no spring slips");
    }
}
