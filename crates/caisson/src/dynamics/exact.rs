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
//! The step is taken only from a committed state where every spring in contact sticks (all in
//! contact, or some lifted: "Partial contact" below), when no load breakpoint falls inside it,
//! and kept only if every spring sticks at its end and in its middle by the spring law's own
//! test (`sticking`), and if its error estimate is within the adaptive tolerance:
//! the middle y(h/2) follows exactly from the same interpolated force (the blocks of the
//! exponential for h/2), R there against its interpolation there, δR, is a force through
//! σ = 0, h/2, h vanishing at the ends, which moves the end by δR times the middle value's
//! weights (the largest of the u_x, u_y and θ B/2 rows, m, and of their rates over ω_x = 2π/T_x,
//! `Model::natural_period_s`). The rates count because a force error through the middle of a
//! step moves the end's velocity by about 2/h times its displacement, and a velocity error δv
//! becomes a displacement of amplitude δv/ω a quarter period later, so that the end's
//! displacement alone sees 1/5 to 1/10 of the error a step of dt_max/4 to dt_max/8 leaves:
//! measured on the random family of `tests/verify_adaptive_accuracy.rs` (case 22, every exact
//! step also integrated from its start by fixed steps of 2.5e-7 s) the estimate was within 30 %
//! of the true error of the end's displacement and the true velocity error over ω_x was 10 and
//! 5 times it (2/(ω_x h)); summed over the rocking phases of case 16 (6 springs, undamped,
//! lifted and re-contacting), an estimate of the displacement alone leaves the state 1e-7 m and
//! 1e-4 m/s off the converged run at its main slip, and its peak 1.27 % over it, the estimate
//! with the rates 0.02 % (`random_family_meets_converged_fixed_steps`). The load's own
//! interpolation error is not held to the tolerance, only guarded ([`LOAD_GUARD`]): through the
//! previous step's start, a fourth point of the load is known without evaluating it (the start of
//! the step before that one, or its middle), the cubic through the four departs from the
//! quadratic in the middle by −(3/8) h³ times their divided difference, and that with δR, through
//! the same weights, refuses the step beyond 30 tolerances: a load the step cannot follow (held
//! to one tolerance, the design example takes 24 % more instructions for 6e-6 m in E|S|).
//! Otherwise the Newmark step is taken from the same state (which locates the onset of slip).
//! Its end is committed as an all-sticking Newmark step would be.
//!
//! **The ladder**: the step lengths are h_k = dt_max/2^k, k = 0 … 3 ([`RUNGS`]). A step tries the
//! rung its predecessor chose (the longest at a run's start and when full contact is entered,
//! dt_max/4 when a set with springs lifted is: [`PARTIAL_ENTRY_RUNG`]), or the longest rung that
//! ends by the load's next breakpoint (and by the run's end): the gap left before a breakpoint,
//! shorter than dt_max/8, is one Newmark step. The rung follows the error estimate ε of the last
//! step tried, as a fraction of the tolerance ([`CLIMB`] = 2): after an accepted step the next
//! climbs one rung, n rungs if ε ≤ 2^−n; a step refused by its estimate is retried one rung
//! shorter, n + 1 rungs if ε > 2^n. A step refused because a spring slips, lifts or touches down
//! in it is retried on the next shorter rung, and until its end the steps go at most half the way
//! to it ([`Ladder`]'s ceiling), so that the event is bracketed by halving in exact steps (on the
//! design example, the fourth rung and this refusal rule take 9 % fewer instructions than three
//! rungs and Newmark steps from h/2 of the refused step). A step refused on the shortest rung is
//! taken by Newmark from the same state, starting at h/2, and no exact step is tried again in the
//! same contact set before the refused step's end (the Newmark steps locate the event). **The
//! hand-over back**: once the event has come, a spring slipping at a committed step or the
//! contact set changed, that wait and the ceiling end, so the first committed state after it in
//! which every spring in contact sticks is advanced exactly again
//! (`exact_steps_resume_as_soon_as_a_slip_ends`): the Newmark steps end with the event, not at
//! the refused step's end (fewer Newmark steps a lifting wave: docs/history.md). Shorter rungs
//! (dt_max/16 … dt_max/128) do not pay on the design example: used for the gap before a
//! breakpoint, +8 % instructions; for the steps under the ceiling, +4 %; to bracket an event one
//! rung further, +0.8 %; entered after an event at the rung of the Newmark step, +0.4 %.
//!
//! **Partial contact** (docs/model.md §9.1): a lifted spring carries nothing
//! (no force, no dashpot) and its slip position follows u_x, so with springs lifted and every
//! spring in contact sticking the equations above hold with the sums over the springs in contact
//! C only, m = |C|:
//!
//! ```text
//! K_L(C) = [K_x, 0, 0; 0, m k_y, −k_y Σ_C x; 0, −k_y Σ_C x, k_y Σ_C x²]
//! C_L(C) = C + [m c_d, 0, 0; 0, m c_y, −c_y Σ_C x; 0, −c_y Σ_C x, c_y Σ_C x²]
//! R(q)   = κ [(a − a_r) Σ_C e_i + b Σ_C x_i e_i],  a_r = W'/m,  q_0 = u_x − s_ref
//! ```
//!
//! (κ m a_r = κ W' = K_x for every set; s_ref the slip position of the first spring of C, d_i
//! and the gravity term κ a_r Σ_C d_i over C). The contact set is the run of springs with
//! u_y,i = u_y − θ x_i < 0: linear in x_i, so a run from one edge ([`ContactSet`]: full contact
//! and 1 … n − 1 springs lifted from either edge, 2n − 1 sets). Each set has its own ladder of
//! propagators, built on first use and shared per thread (the cache's key holds the spring
//! positions: two models with equal Σx and Σx² share the full set's matrices, not a partial
//! set's). A step may start from any committed state with springs lifted and none of those in
//! contact slipping (with [`super::SolverParams::locate_contact`], whose Newmark steps locate
//! the contact changes: re-contact and the dashpots' jump stay on their side), and the rung
//! (dt_max/4, "The ladder") and the interpolation through the previous step's start
//! ([`Third::Before`]) start afresh when the set changes. The events the step checks, besides the error estimate:
//!
//! 1. every spring of C sticks, by the spring law's own test, at σ = h/4, h/2, 3h/4 and h;
//! 2. the set holds: the springs at its boundaries (the innermost lifted and the outermost
//!    contacting spring at each edge; by linearity in x_i they decide for all) keep the side of
//!    u_y,i = 0 they started on, at those points and between each two on the cubic through
//!    their values and rates (at a quarter, half and three quarters of the way: `keeps_side`).
//!
//! Quarter points, because the middle and the end alone pass over a bounce of the innermost
//! lifted spring shorter than h/2 (its touch-down and lift again between them), and a lift or a
//! slip that is over by the end; they come from the same force coefficients and two more blocks
//! of the exponential per rung (σ = h/4 and 3h/4). The cubic between them costs no exponential
//! and sees a touch-down deeper than its interpolation error; a graze whose depth is within the
//! tolerance may be missed, as Newmark at the same tolerance misses it
//! (`crates/caisson/tests/verify_partial_contact.rs`). A step kept is committed spring by spring
//! (the general path), as the Newmark step that would end there.

use super::{Converged, Model, Observer, Simulation};
use crate::loads::{LoadHistory, WaveForce};
use nalgebra::{Matrix3, SMatrix, Vector3};
use std::cell::Cell;
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
    /// The largest of the u_x, u_y and θ rows of each column of the middle value's weights
    /// (`middle[1]`): a bound of the load guard's deviation without the rows.
    middle_max: [f64; 3],
    /// The error estimate's weights of R's departure from its interpolation in the middle: of
    /// u_x, u_y and their rates over ω_x, m/N, and of θ and its rate over ω_x, rad/N.
    r_weight: [f64; 2],
    /// e^{hA/2}, column by column: to the step's middle.
    half_e0: [[f64; 6]; 6],
    /// The weights of c_0, c_1 and c_2 (g = c_0 + c_1 σ + c_2 σ²) at σ = h/2.
    half_c: [Block; 3],
    /// A partial contact set's: e^{σA} and the weights of c_0, c_1, c_2 at σ = h/4 and 3h/4
    /// (module docs, "Partial contact"); `None` for full contact.
    quarters: Option<[Sample; 2]>,
    minv: Matrix3<f64>,
    k_l: Matrix3<f64>,
    c_l: Matrix3<f64>,
}

/// The state at a point σ inside a step: e^{σA} and the weights of c_0, c_1 and c_2 there.
#[derive(Debug, Clone)]
struct Sample {
    e0: [[f64; 6]; 6],
    c: [Block; 3],
}

/// Rungs of the ladder of step lengths: dt_max / 2^k, k = 0 .. RUNGS − 1.
pub(super) const RUNGS: usize = 4;

/// The propagators of every rung of every contact set (index [`ContactSet::index`]), each built
/// when a step first needs it (`None` if it cannot be: a singular mass matrix or an exponential
/// that is not finite); shared by the ladders of one thread with the same matrices and springs.
type Rungs = Arc<[[OnceLock<Option<Propagator>>; RUNGS]]>;

/// The springs in contact, lo..hi (module docs, "Partial contact"): u_y,i = u_y − θ x_i is
/// linear in x_i and the positions ascend, so the springs in contact are a run from one edge.
/// `index` 0 is full contact, 1..n−1 the sets with the `index` seaward springs lifted, n..2n−2
/// those with `index` − n + 1 shoreward springs lifted.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct ContactSet {
    pub lo: usize,
    pub hi: usize,
    pub index: usize,
}

impl ContactSet {
    /// The set of springs lo..hi of `n` (lo = 0 or hi = n, lo < hi).
    fn new(lo: usize, hi: usize, n: usize) -> Self {
        let index = if lo > 0 {
            lo
        } else if hi < n {
            2 * n - 1 - hi
        } else {
            0
        };
        ContactSet { lo, hi, index }
    }

    /// Every spring in contact.
    fn full(&self) -> bool {
        self.index == 0
    }
}

/// The propagators of every step length of the ladder (module docs, "The ladder"), and the rung
/// to try next.
#[derive(Debug, Clone)]
pub(super) struct Ladder {
    /// The step length of each rung, dt_max/2^k, s.
    h_s: [f64; RUNGS],
    rungs: Rungs,
    /// a_r = W'/n, N.
    a_ref: f64,
    /// The rung to try first, and the contact set it is for.
    k: usize,
    set: usize,
    /// The end of the last step refused at an event: the steps before it go at most half the
    /// way to it, s.
    ceiling_s: f64,
    /// No exact step before this time in contact set `retry_set`, after one refused on the
    /// shortest rung (Newmark steps locate the event), s.
    retry_s: f64,
    retry_set: usize,
    /// The error estimate of the last step tried over the tolerance: how many rungs the next
    /// step climbs, or a refused one descends ([`CLIMB`]).
    ratio: Cell<f64>,
}

/// The rung a set with springs lifted is entered on: dt_max/4, which takes the fewest
/// instructions on the design example (0.2 % more from dt_max/2, 0.9 % more from dt_max/8; the
/// counts in docs/history.md).
const PARTIAL_ENTRY_RUNG: usize = 2;

/// The error estimate's growth per doubling of the step assumed by the rung choice: an accepted
/// step climbs one rung, n rungs if its estimate is within CLIMB^−n of the tolerance; a refused
/// one descends one rung, n + 1 rungs if its estimate exceeds CLIMB^n tolerances (module docs,
/// "The ladder"). The estimate grows as h⁵ where the force is smooth, but the design example
/// takes the fewest instructions with a factor 2 (with 4, 0.2 % more; with 32, nearly always one
/// rung, 0.7 % more; never climbing while the estimate is above 1/32 of the tolerance, 9 % more;
/// the counts in docs/history.md).
const CLIMB: f64 = 2.0;

/// The exact step's error estimate with the load's interpolation error in it refuses a step only
/// beyond this many tolerances: a load that the step cannot follow (a dip of 2 s under a step of
/// 0.5 s, 24 % of it: `tests/verify_partial_contact.rs`). Below that it is not held to the
/// tolerance (module docs, the error estimate): held to 1 tolerance, the design example takes
/// 24 % more instructions (design_500) for a change of 6e-6 m in E|S|; at 30 none more, at 10
/// 0.5 % more.
const LOAD_GUARD: f64 = 30.0;

/// M, K_L, C_L and dt_max, the numbers the propagators of a ladder come from (with the spring
/// positions: those of the partial contact sets).
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
    /// Its contact set's index: R is a function of the set.
    set: usize,
    r_start_n: f64,
    /// The load (gravity included) at its start, N.
    p_start: Vector3<f64>,
    /// One more point of the load before its end, and its time: the start of the step before it
    /// (a step through the previous step's start), or its middle (s, N).
    extra: (f64, Vector3<f64>),
}

/// Where the step's load is known besides its start and end: at its middle, or at the start of
/// the previous (exact) step, σ = −h.
#[derive(Debug, Clone, Copy)]
pub(super) enum Third {
    Middle(Vector3<f64>),
    Before(Vector3<f64>),
}

impl Third {
    /// Its time in a step of length `h` from `t_s`, and its load.
    fn point(self, t_s: f64, h: f64) -> (f64, Vector3<f64>) {
        match self {
            Third::Before(pb) => (t_s - h, pb),
            Third::Middle(pm) => (t_s + 0.5 * h, pm),
        }
    }
}

/// Ladders kept per thread, the most recent last: the caissons of a design life's storms share
/// their matrices (their weight in water changes with the tide, the propagators do not), and a
/// sizing run alternates among a few widths.
const CACHED_LADDERS: usize = 4;

/// A cached ladder: its key, the spring positions and the propagators.
type Cached = (Key, Vec<f64>, Rungs);

thread_local! {
    static LADDERS: std::cell::RefCell<[Option<Cached>; CACHED_LADDERS]> =
        const { std::cell::RefCell::new([const { None }; CACHED_LADDERS]) };
}

/// Σ_k m_ik x_k for the six rows i of a matrix stored column by column (`columns[k][i]` = m_ik):
/// each row's sum from −0.0 in the order of k, the operations of `Iterator::sum` over the row
/// one for one (the same bits), with the six rows side by side, which the compiler vectorizes.
#[inline(always)]
fn mul<const K: usize>(columns: &[[f64; 6]; K], x: &[f64; K]) -> [f64; 6] {
    rows(columns, x)
}

/// The first `R` rows of [`mul`], each with the same operations (the same bits): the positions
/// of a state without its velocities.
#[inline(always)]
fn rows<const R: usize, const K: usize>(columns: &[[f64; 6]; K], x: &[f64; K]) -> [f64; R] {
    let mut y = [-0.0; R];
    for (column, &xk) in columns.iter().zip(x) {
        for (yi, &m) in y.iter_mut().zip(column) {
            *yi += m * xk;
        }
    }
    y
}

impl Propagator {
    /// M, K_L and C_L of `model` with the springs lo..hi in contact (module docs).
    fn matrices(model: &Model, lo: usize, hi: usize) -> (Matrix3<f64>, Matrix3<f64>, Matrix3<f64>) {
        let law = model.law;
        let x_m = &model.x_m[lo..hi];
        let n = x_m.len() as f64;
        let (sx, sx2) = x_m.iter().fold((0.0, 0.0), |(a, b), x| (a + x, b + x * x));
        let ky = law.ky_n_per_m;
        let (cd, cy) = (model.spring_dashpot_ns_per_m, model.spring_vertical_dashpot_ns_per_m);
        // κ m a_r with a_r = W'/m: κ W' = K_x for every set.
        let k_l = Matrix3::new(model.kx_n_per_m, 0.0, 0.0, 0.0, n * ky, -ky * sx, 0.0, -ky * sx, ky * sx2);
        let c_l = model.damping + Matrix3::new(n * cd, 0.0, 0.0, 0.0, n * cy, -cy * sx, 0.0, -cy * sx, cy * sx2);
        (model.mass, k_l, c_l)
    }

    /// The propagators of `model` with the springs of `set` in contact for steps of `h`; `None`
    /// if the mass matrix is singular or the exponential is not finite.
    fn new(model: &Model, set: ContactSet, h: f64) -> Option<Self> {
        let (mass, k_l, c_l) = Self::matrices(model, set.lo, set.hi);
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
        // To a point σ inside the step: e^{σA} and the weights of c_0, c_1, c_2 (E_1, E_2, 2 E_3
        // at σ).
        let sample = |x: &SMatrix<f64, 15, 15>| Sample {
            e0: std::array::from_fn(|j| std::array::from_fn(|i| x[(i, j)])),
            c: std::array::from_fn(|k| {
                let w = if k == 2 { 2.0 } else { 1.0 };
                std::array::from_fn(|j| std::array::from_fn(|i| w * x[(i, 6 + 3 * k + j)]))
            }),
        };
        let Sample { e0: half_e0, c: half_c } = sample(&hx);
        let quarters = match set.full() {
            true => None,
            false => Some([sample(&van_loan(0.25 * h)?), sample(&van_loan(0.75 * h)?)]),
        };
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
        let middle_max = middle[1].map(|w| w[0].abs().max(w[1].abs()).max(w[2].abs()));
        // The error estimate's weights of R's departure in the middle (module docs, the error
        // estimate): the end's displacement, and its velocity over ω_x (M and K_x are in the
        // cache's key), the amplitude of the displacement that a velocity error becomes.
        let w = &middle[1][0];
        let inv_omega = model.natural_period_s() / (2.0 * std::f64::consts::PI);
        let r_weight = [
            w[0].abs().max(w[1].abs()).max(inv_omega * w[3].abs().max(w[4].abs())),
            w[2].abs().max(inv_omega * w[5].abs()),
        ];
        Some(Propagator {
            e0,
            before,
            middle,
            hermite_x,
            middle_max,
            r_weight,
            half_e0,
            half_c,
            quarters,
            minv,
            k_l,
            c_l,
        })
    }
}

impl Model {
    /// M, K_L and C_L of the all-sticking equations of motion (module docs): the linear system
    /// whose response the design run's screen bounds (`analysis::stick_bound`).
    pub fn sticking_matrices(&self) -> (Matrix3<f64>, Matrix3<f64>, Matrix3<f64>) {
        Propagator::matrices(self, 0, self.x_m.len())
    }
}

impl Ladder {
    /// The ladder of `model` for steps up to `dt_max_s`, with `shared` sharing the propagators of
    /// this thread's ladder of the same matrices and dt_max (the same numbers: nothing else enters
    /// them; `Accel::cached_propagators`), else its own. `None` if the longest step's cannot be
    /// built (a singular mass matrix).
    pub fn cached(model: &Model, dt_max_s: f64, shared: bool) -> Option<Self> {
        let n = model.x_m.len();
        let (m, k, c) = Propagator::matrices(model, 0, n);
        let mut key = [0.0; 28];
        key[..9].copy_from_slice(m.as_slice());
        key[9..18].copy_from_slice(k.as_slice());
        key[18..27].copy_from_slice(c.as_slice());
        key[27] = dt_max_s;
        // Full contact and the sets lifted from either edge, 2n − 1 (at least one).
        let fresh = || -> Rungs { (0..(2 * n).max(2) - 1).map(|_| [const { OnceLock::new() }; RUNGS]).collect() };
        let rungs = if !shared {
            fresh()
        } else {
            LADDERS.with(|l| {
                let mut l = l.borrow_mut();
                if let Some((_, _, r)) = l.iter().flatten().find(|(k, x, _)| *k == key && *x == model.x_m) {
                    return r.clone();
                }
                let r = fresh();
                l.rotate_left(1);
                l[CACHED_LADDERS - 1] = Some((key, model.x_m.clone(), r.clone()));
                r
            })
        };
        let h_s = std::array::from_fn(|k| dt_max_s / (1u32 << k) as f64);
        let ladder = Ladder {
            h_s,
            rungs,
            a_ref: model.weight_n / n as f64,
            k: 0,
            set: 0,
            ceiling_s: f64::NEG_INFINITY,
            retry_s: f64::NEG_INFINITY,
            retry_set: 0,
            ratio: Cell::new(1.0),
        };
        ladder.rung(model, ContactSet::new(0, n, n), 0)?;
        Some(ladder)
    }

    /// After an exact step of rung `k` was kept: the next step climbs one rung, n rungs if the
    /// estimate was within CLIMB^−n of the tolerance.
    fn climb_after(&mut self, k: usize) {
        let (mut up, mut r) = (1, self.ratio.get() * CLIMB * CLIMB);
        while up < k && r <= 1.0 {
            up += 1;
            r *= CLIMB;
        }
        self.k = k.saturating_sub(up);
    }

    /// After an exact step of rung `k` was refused by its error estimate: one rung shorter, n + 1
    /// if the estimate exceeds CLIMB^n tolerances (at most the shortest); the rung to try.
    fn descend_after(&mut self, k: usize) -> usize {
        let r = self.ratio.get();
        let mut k = k + 1;
        let mut r = r / CLIMB;
        while k + 1 < RUNGS && r > 1.0 {
            k += 1;
            r /= CLIMB;
        }
        self.k = k;
        k
    }

    /// The step length of rung `k`, s.
    #[inline]
    pub fn h(&self, k: usize) -> f64 {
        self.h_s[k]
    }

    /// The propagators of rung `k` of contact set `set`, built if they are not yet.
    #[inline]
    fn rung(&self, model: &Model, set: ContactSet, k: usize) -> Option<&Propagator> {
        self.rungs[set.index][k].get_or_init(|| Propagator::new(model, set, self.h(k))).as_ref()
    }

    /// Back to the longest step (a new run from rest).
    pub fn restart(&mut self) {
        (self.k, self.set, self.ceiling_s, self.retry_s) = (0, 0, f64::NEG_INFINITY, f64::NEG_INFINITY);
    }
}

impl Simulation {
    /// Whether an exact step may start from the committed state: every spring in contact and
    /// sticking (the last step all-sticking, or the static equilibrium), or, with
    /// [`super::SolverParams::locate_contact`], springs lifted and none of those in contact
    /// slipping (module docs, "Partial contact").
    #[inline]
    pub(super) fn exact_may_start(&self) -> bool {
        self.fast.direct
            || (self.solver.locate_contact
                && self.exact.is_some()
                && self.committed_lifted()
                && !self.committed_sliding())
    }

    /// The contact set of the committed state: full contact after an all-sticking step, else the
    /// springs with u_y,i < 0 (a run from one edge); `None` if no spring is in contact.
    fn contact_set(&self) -> Option<ContactSet> {
        let n = self.model.x_m.len();
        if self.fast.direct {
            return Some(ContactSet::new(0, n, n));
        }
        let (uy, th) = (self.state.u[1], self.state.u[2]);
        let touch = |x: f64| uy - th * x < 0.0;
        let lo = self.model.x_m.iter().position(|&x| touch(x))?;
        let hi = lo + self.model.x_m[lo..].iter().take_while(|&&x| touch(x)).count();
        (lo == 0 || hi == n).then(|| ContactSet::new(lo, hi, n))
    }

    /// From the committed state with every spring in contact sticking, one exact step of the
    /// ladder of its contact set if one fits before the load's next breakpoint `bp_s` and
    /// `t_end_s` (module docs, "The ladder"): the rung to try first, or the longest that fits;
    /// shorter while the error estimate refuses it, or while an event falls within it (each
    /// shorter rung at most half the way to the refused step's end). Whether a step was
    /// committed; if not, the Newmark step is next, from `h_next`. From any other state: none,
    /// and the event that the last refused step saw has come (a spring slips): the steps after
    /// it are neither held back nor kept short on its account.
    pub(super) fn exact_advance<L: LoadHistory + ?Sized, O: Observer + ?Sized>(
        &mut self,
        bp_s: f64,
        t_end_s: f64,
        tolerance_m: f64,
        load: &L,
        obs: &mut O,
    ) -> bool {
        let t = self.state.t_s;
        let Some((set, first)) = self.exact_first_rung(bp_s, t_end_s) else {
            return false;
        };
        // The load at the start: the committed step's, if it is known.
        let p0 = match self.run.last_load {
            Some((tl, p)) if tl == t => p,
            _ => self.load_vector(load.at(t)),
        };
        // The wave at a refused try's middle: the end of the next rung's.
        let mut middle: Option<(f64, WaveForce)> = None;
        let mut k = first;
        while k < RUNGS {
            let ladder = self.exact.as_ref().expect("checked above");
            let h = ladder.h(k);
            let t1 = t + h;
            let known = middle.take().filter(|&(tm, _)| tm == t1);
            let third = match self.run.exact_prev.filter(|p| p.t_end_s == t && p.h_s == h && p.set == set.index) {
                Some(p) => Third::Before(p.p_start),
                None => {
                    let tm = t + 0.5 * h;
                    let w = load.at(tm);
                    middle = Some((tm, w));
                    Third::Middle(self.load_vector(w))
                }
            };
            let w1 = known.map_or_else(|| load.at(t1), |(_, w)| w);
            match self.exact_sticking_step(set, k, p0, self.load_vector(w1), third, tolerance_m) {
                Ok(c) => {
                    self.stats.exact_steps += 1;
                    self.stats.exact_partial_steps += u64::from(!set.full());
                    self.commit_observed(h, c, t1, w1, obs);
                    self.exact.as_mut().expect("checked above").climb_after(k);
                    self.run.h_next = h;
                    return true;
                }
                Err(Refused::Error) if k + 1 < RUNGS => {
                    k = self.exact.as_mut().expect("checked above").descend_after(k);
                    continue;
                }
                Err(Refused::Stick) if k + 1 < RUNGS => {
                    // A spring slips, lifts or touches down within the step: the next rung, half
                    // of it, and the steps after it at most half the way to its end.
                    self.exact.as_mut().expect("checked above").ceiling_s = t1;
                }
                Err(_) => {
                    // A spring slips or lifts within the shortest step (or the shortest rung is
                    // too long for the error estimate): Newmark steps over it, and locate the
                    // event.
                    let ladder = self.exact.as_mut().expect("checked above");
                    (ladder.retry_s, ladder.retry_set) = (t1, set.index);
                    self.run.h_next = 0.5 * h;
                    return false;
                }
            }
            k += 1;
        }
        false
    }

    /// The contact set of the committed state and the rung of its ladder to try first (module
    /// docs, "The ladder"), or `None` where no exact step is tried: the state is not one where
    /// every spring in contact sticks (and then the event a refused step saw has come: the steps
    /// after it are neither held back nor kept short on its account), the springs in contact are
    /// not one run, the set's last step was refused on its shortest rung and its end has not come,
    /// or no rung fits before the breakpoint `bp_s` and `t_end_s` (and half the way to the end of
    /// a step refused at an event).
    #[inline(always)]
    fn exact_first_rung(&mut self, bp_s: f64, t_end_s: f64) -> Option<(ContactSet, usize)> {
        let t = self.state.t_s;
        if !self.exact_may_start() {
            if let Some(l) = self.exact.as_mut() {
                (l.retry_s, l.ceiling_s) = (f64::NEG_INFINITY, f64::NEG_INFINITY);
            }
            return None;
        }
        let set = self.contact_set()?;
        let ladder = self.exact.as_mut()?;
        // After a step refused on the shortest rung, Newmark steps to its end in the same set.
        if t < ladder.retry_s && set.index == ladder.retry_set {
            return None;
        }
        if ladder.set != set.index {
            // Another contact set (a lift or a touch-down has come): its own ladder, from the
            // longest step in full contact and from dt_max/4 with springs lifted.
            (ladder.set, ladder.k) = (set.index, if set.full() { 0 } else { PARTIAL_ENTRY_RUNG });
            ladder.ceiling_s = f64::NEG_INFINITY;
        }
        let room = bp_s.min(t_end_s) - t;
        // After a step refused at an event, at most half the way to that step's end (the event
        // is bracketed by halving).
        let half_way = if ladder.ceiling_s > t { 0.5 * (ladder.ceiling_s - t) * (1.0 + 1e-9) } else { f64::INFINITY };
        // Less than the shortest rung to the breakpoint: Newmark steps to it.
        let first = (ladder.k..RUNGS).find(|&k| ladder.h(k) <= room && ladder.h(k) <= half_way)?;
        Some((set, first))
    }

    /// One step of rung `k` of the ladder of contact set `set` from the committed state (module
    /// docs), every spring in contact sticking, with the loads (gravity included) `p0` at its
    /// start, `p1` at its end and a `third` point. Refused if a spring in contact does not stick
    /// at one of the points tested, or the contact set changes, or the root is not real
    /// ([`Refused::Stick`]), or if the error estimate of R's interpolation exceeds `tolerance_m`
    /// ([`Refused::Error`]): nothing is changed then but the fast path's iterate (and, for a
    /// partial set, the springs' trial responses).
    pub(super) fn exact_sticking_step(
        &mut self,
        set: ContactSet,
        k: usize,
        p0: Vector3<f64>,
        p1: Vector3<f64>,
        third: Third,
        tolerance_m: f64,
    ) -> Result<Converged, Refused> {
        let full = set.full();
        let [n, sx, s1, sum_d, sum_xd] = if full { self.slip_sums() } else { self.set_slip_sums(set.lo, set.hi) };
        let (ladder, model) = (self.exact.as_ref().ok_or(Refused::Stick)?, &self.model);
        let h = ladder.h(k);
        // a_r = W'/m, the normal force of a spring of the set at rest (W'/n in full contact).
        let a_ref = if full { ladder.a_ref } else { model.weight_n / n };
        let pr = ladder.rung(model, set, k).ok_or(Refused::Stick)?;
        let (ky, kappa) = (self.model.law.ky_n_per_m, self.model.law.kappa_per_m);
        let rem = Remainder { n, sx, sum_d, sum_xd, a_ref, ky, kappa };
        let (un, vn) = (self.state.u, self.state.v);
        let y0 = [un[0] - s1, un[1], un[2], vn[0], vn[1], vn[2]];
        let r0 = rem.at(&y0);
        // Ṙ at the start (needed with a middle third only).
        let r0_rate = if let Third::Before(_) = third { 0.0 } else { rem.rate(&y0) };
        // The force g = p + (κ a_r Σd, 0, 0) − R e_x.
        let shift = kappa * a_ref * sum_d;
        let g = |p: Vector3<f64>, r: f64| [p[0] + shift - r, p[1], p[2]];
        // y(h) = y* + γ R(h).
        let prev = self.run.exact_prev.filter(|p| p.t_end_s == self.state.t_s && p.h_s == h && p.set == set.index);
        let (mut y, gamma) = match (third, prev) {
            (Third::Before(pb), Some(p)) => free_response(pr, &y0, [g(p0, r0), g(p1, 0.0), g(pb, p.r_start_n)], None),
            (Third::Middle(pm), _) => free_response(pr, &y0, [g(p0, 0.0), g(pm, 0.0), g(p1, 0.0)], Some([r0, r0_rate])),
            (Third::Before(_), None) => return Err(Refused::Stick),
        };
        // R(y* + γ R) = R: a quadratic in R.
        let r1 = rem.root(&y, &gamma).ok_or(Refused::Stick)?;
        y.iter_mut().zip(gamma).for_each(|(a, w)| *a += w * r1);
        let (q1, v1) = (Vector3::new(y[0], y[1], y[2]), Vector3::new(y[3], y[4], y[5]));
        let (u, v) = ([q1[0] + s1, q1[1], q1[2]], [v1[0], v1[1], v1[2]]);
        // The step's middle under the same interpolated force: its quadratic through the three
        // points (R linear on the first step of a phase: its value in the middle is the mean).
        let r_prev = prev.map_or(0.0, |p| p.r_start_n);
        let r_mid = match third {
            Third::Before(_) => (3.0 * r1 + 6.0 * r0 - r_prev) / 8.0,
            Third::Middle(_) => 0.75 * r0 + 0.25 * r1 + 0.25 * h * r0_rate,
        };
        let (g0, g1) = (g(p0, r0), g(p1, r1));
        let c = match third {
            Third::Before(pb) => force_through_before(h, g0, g1, g(pb, r_prev)),
            Third::Middle(pm) => force_through_middle(h, [g(p0, 0.0), g(pm, 0.0), g(p1, 0.0)], [r0, r0_rate, r1]),
        };
        let (ym, qm) = middle(pr, &y0, &c, full);
        // The error estimate: R in the middle against its interpolation there, as a force through
        // σ = 0, h/2, h that is 0 at the ends, moves the step's end by the middle's weights.
        let dr = rem.at(&qm) - r_mid;
        let err = dr.abs() * pr.r_weight[0].max(pr.r_weight[1] * 0.5 * self.model.width_m);
        // Through the previous step's start, the load's own interpolation guarded too.
        let err = match (third, prev) {
            (Third::Before(pb), Some(p)) => {
                self.load_guarded_error_m(pr, h, (pb, &p), [p0, p1], (dr, err), tolerance_m)
            }
            _ => err,
        };
        ladder.ratio.set(err / tolerance_m);
        if err > tolerance_m || err.is_nan() {
            return Err(Refused::Error);
        }
        let extra = third.point(self.state.t_s, h);
        // The acceleration at the end (not for a step refused by its error estimate).
        let acc = pr.minv * (Vector3::from(g1) - pr.k_l * q1 - pr.c_l * v1);
        let converged = Converged { u, v, a: [acc[0], acc[1], acc[2]], iterations: 0, residual: 0.0 };
        if !self.exact_step_holds(set, k, h, &Sampled { s1, y0, ym, qm, y, c }) {
            return Err(Refused::Stick);
        }
        self.run.exact_prev =
            Some(Previous { t_end_s: self.state.t_s + h, h_s: h, set: set.index, r_start_n: r0, p_start: p0, extra });
        Ok(converged)
    }

    /// Whether the exact step of rung `k` of contact set `set` (length `h`), sampled as `s`,
    /// holds: in full contact every spring sticks in its middle and at its end (the spring law's
    /// own test; the last one records the sums of the commit and the base reaction); in a partial
    /// set [`Self::partial_set_holds`], and then no spring slips at the end, committed spring by
    /// spring (the lifted springs' slip positions follow u_x).
    fn exact_step_holds(&mut self, set: ContactSet, k: usize, h: f64, s: &Sampled) -> bool {
        let Sampled { s1, y0, ym, qm, y, c } = *s;
        let to_u = |y: &[f64; 6]| [y[0] + s1, y[1], y[2]];
        let (u, v) = (to_u(&y), [y[3], y[4], y[5]]);
        if set.full() {
            if !self.all_stick_at([([qm[0] + s1, qm[1], qm[2]], 0.5 * h), (u, h)]) {
                return false;
            }
            self.stick_sums(u, v, h);
            return true;
        }
        let ym = ym.expect("computed for a partial set");
        let Some(pr) = self.exact.as_ref().and_then(|l| l.rung(&self.model, set, k)) else {
            return false;
        };
        let quarters = || pr.quarters.as_ref().map(|[a, b]| [at(&y0, &c, &a.e0, &a.c), at(&y0, &c, &b.e0, &b.c)]);
        if !self.partial_set_holds(set, h, s1, [&y0, &ym, &y], quarters) {
            return false;
        }
        self.general_trial(u, h);
        !self.trial_slips
    }

    /// The error estimate `err` of an exact step of length `h` through the previous step's start
    /// (`pb`, the load there, and `prev`), with the load's departure from its interpolation in
    /// the middle: the cubic through a fourth point of the load (the start of the step before, or
    /// its middle), −(3/8) h³ times its leading coefficient (the divided difference), with δR
    /// (`dr`) through the middle's weights; a step whose load the interpolation misses by more
    /// than LOAD_GUARD tolerances is refused too (module docs, the error estimate). `ends`: the
    /// loads at the step's start and end.
    fn load_guarded_error_m(
        &self,
        pr: &Propagator,
        h: f64,
        (pb, prev): (Vector3<f64>, &Previous),
        [p0, p1]: [Vector3<f64>; 2],
        (dr, err): (f64, f64),
        tolerance_m: f64,
    ) -> f64 {
        let (a, pa) = (prev.extra.0 - self.state.t_s, prev.extra.1);
        let (k, h2) = (-0.375 * h * h * h, 2.0 * h * h);
        let dp = pa * (k / ((a + h) * a * (a - h))) - pb * (k / ((h + a) * h2))
            + p0 * (2.0 * k / (a * h2))
            + p1 * (k / ((h - a) * h2));
        let dg = [dp[0] - dr, dp[1], dp[2]];
        let (half_b, m) = (0.5 * self.model.width_m, &pr.middle_max);
        // The rows only where their bound passes the guard (the same answer).
        let bound = (dg[0].abs() * m[0] + dg[1].abs() * m[1] + dg[2].abs() * m[2]) * half_b.max(1.0);
        if bound <= LOAD_GUARD * tolerance_m {
            return err;
        }
        let dy = rows::<3, 3>(&pr.middle[1], &dg);
        let load_err = dy[0].abs().max(dy[1].abs()).max(dy[2].abs() * half_b);
        if load_err > LOAD_GUARD * tolerance_m {
            load_err
        } else {
            err
        }
    }

    /// Whether an exact step of length `h` in the partial contact set `set` holds (module docs,
    /// "Partial contact"): the springs of the set stick, and the set holds, at the quarter points,
    /// the middle and the end, and between them too. `states`: y at the start, the middle and the
    /// end; `quarters` y at h/4 and 3h/4 (`None`: refused), computed only if the middle and the
    /// end pass (a step refused there is refused by the whole test too: the same verdict, for
    /// less); `s1` the first spring's slip position (u_x = q_0 + s1).
    fn partial_set_holds(
        &self,
        set: ContactSet,
        h: f64,
        s1: f64,
        [y0, ym, y]: [&[f64; 6]; 3],
        quarters: impl FnOnce() -> Option<[[f64; 6]; 2]>,
    ) -> bool {
        let to_u = |y: &[f64; 6]| [y[0] + s1, y[1], y[2]];
        let (x_m, springs) = (&self.model.x_m, self.model.x_m.len());
        let boundary = [(set.lo.wrapping_sub(1), false), (set.lo, true), (set.hi - 1, true), (set.hi, false)];
        let boundary = || boundary.iter().filter(|(i, _)| *i < springs);
        if !boundary().all(|&(i, contact)| on_side(x_m[i], contact, ym) && on_side(x_m[i], contact, y)) {
            return false;
        }
        if !self.set_sticks(set.lo, set.hi, to_u(y), h) || !self.set_sticks(set.lo, set.hi, to_u(ym), 0.5 * h) {
            return false;
        }
        let Some([yq1, yq3]) = quarters() else {
            return false;
        };
        let samples = [(0.0, *y0), (0.25 * h, yq1), (0.5 * h, *ym), (0.75 * h, yq3), (h, *y)];
        if !boundary().all(|&(i, contact)| keeps_side(x_m[i], contact, &samples)) {
            return false;
        }
        [&samples[1], &samples[3]].iter().all(|(s, ys)| self.set_sticks(set.lo, set.hi, to_u(ys), *s))
    }
}

/// The free response of an exact step and the weight of R(h) in it, y(h) = y* + γ R(h): y* the
/// propagated start `y0` plus the weights of the forces `g` at the interpolation's points
/// (R in them where it is known): through the previous step's start (`hermite` `None`, R0 and R
/// there in `g`), or through the step's middle less R's Hermite part from R0 and Ṙ0 (`hermite`
/// `Some([R0, Ṙ0])`).
#[inline(always)]
fn free_response(pr: &Propagator, y0: &[f64; 6], g: [[f64; 3]; 3], hermite: Option<[f64; 2]>) -> ([f64; 6], [f64; 6]) {
    let mut y = mul(&pr.e0, y0);
    let w = if hermite.is_some() { &pr.middle } else { &pr.before };
    for (w, g) in w.iter().zip(&g) {
        let d = mul(w, g);
        y.iter_mut().zip(d).for_each(|(a, b)| *a += b);
    }
    let Some(r) = hermite else {
        return (y, pr.before[1][0].map(|w| -w));
    };
    y.iter_mut().zip(pr.hermite_x[0]).for_each(|(a, w)| *a -= w * r[0]);
    y.iter_mut().zip(pr.hermite_x[1]).for_each(|(a, w)| *a -= w * r[1]);
    (y, std::array::from_fn(|i| -pr.hermite_x[2][i]))
}

/// An exact step sampled: the first spring's slip position `s1` (q_0 = u_x − s1), the state at
/// its start, middle (whole for a partial set) and end, the middle's positions, and its force's
/// quadratic coefficients.
#[derive(Clone, Copy)]
struct Sampled {
    s1: f64,
    y0: [f64; 6],
    ym: Option<[f64; 6]>,
    qm: [f64; 3],
    y: [f64; 6],
    c: [[f64; 3]; 3],
}

/// The shear's bilinear remainder R = κ [(a − a_r) Σe_i + b Σx_i e_i] of a contact set (module
/// docs) as a function of q = (u_x − s_1, u_y, θ): a = −k_y u_y, b = k_y θ, Σe_i = n q_0 − Σd_i,
/// Σx_i e_i = Σx_i q_0 − Σx_i d_i over the set's n springs.
#[derive(Clone, Copy)]
struct Remainder {
    n: f64,
    sx: f64,
    sum_d: f64,
    sum_xd: f64,
    a_ref: f64,
    ky: f64,
    kappa: f64,
}

impl Remainder {
    /// R at the positions of `q`.
    #[inline(always)]
    fn at(&self, q: &[f64]) -> f64 {
        let (a, b) = (-self.ky * q[1], self.ky * q[2]);
        self.kappa * ((a - self.a_ref) * (self.n * q[0] - self.sum_d) + b * (self.sx * q[0] - self.sum_xd))
    }

    /// Ṙ at the state `y` = (q, q̇): R's gradient in q times q̇.
    #[inline(always)]
    fn rate(&self, y: &[f64; 6]) -> f64 {
        let (ky, n, sx) = (self.ky, self.n, self.sx);
        let (a, b) = (-ky * y[1], ky * y[2]);
        let (se, sxe) = (n * y[0] - self.sum_d, sx * y[0] - self.sum_xd);
        self.kappa * (-ky * y[4] * se + (a - self.a_ref) * n * y[3] + ky * y[5] * sxe + b * sx * y[3])
    }

    /// R(h), the root of R(y* + γ R) = R, a quadratic in R (module docs), taken without
    /// cancellation; `None` if it is not real.
    #[inline(always)]
    fn root(&self, y: &[f64; 6], gamma: &[f64; 6]) -> Option<f64> {
        let Remainder { n, sx, sum_d, sum_xd, a_ref, ky, kappa } = *self;
        let (a, b) = (-ky * y[1], ky * y[2]);
        let (se, sxe) = (n * y[0] - sum_d, sx * y[0] - sum_xd);
        let qc = kappa * ((a - a_ref) * se + b * sxe);
        let qb =
            kappa * ((a - a_ref) * n * gamma[0] - ky * gamma[1] * se + b * sx * gamma[0] + ky * gamma[2] * sxe) - 1.0;
        let qa = kappa * ky * gamma[0] * (gamma[2] * sx - gamma[1] * n);
        let disc = qb * qb - 4.0 * qa * qc;
        if !(disc >= 0.0 && qb != 0.0) {
            return None;
        }
        Some(-2.0 * qc / (qb + qb.signum() * disc.sqrt()))
    }
}

/// The step's force as a quadratic in σ, c_0 + c_1 σ + c_2 σ², through its start `g0`, its end
/// `g1` and the previous step's start `gb` (σ = −h), R in each.
#[inline(always)]
fn force_through_before(h: f64, g0: [f64; 3], g1: [f64; 3], gb: [f64; 3]) -> [[f64; 3]; 3] {
    let h2 = h * h;
    [
        g0,
        std::array::from_fn(|i| (g1[i] - gb[i]) / (2.0 * h)),
        std::array::from_fn(|i| (g1[i] - 2.0 * g0[i] + gb[i]) / (2.0 * h2)),
    ]
}

/// The step's force as a quadratic in σ: the load through σ = 0, h/2, h (`[l0, lm, l1]`, without
/// R), less R through R0, Ṙ0 and R1 (`r`).
#[inline(always)]
fn force_through_middle(h: f64, [l0, lm, l1]: [[f64; 3]; 3], [r0, r0_rate, r1]: [f64; 3]) -> [[f64; 3]; 3] {
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

/// The step's middle under its interpolated force `c` from the start `y0`: all of it for a
/// partial set's samples (not `full`), and its positions.
#[inline(always)]
fn middle(pr: &Propagator, y0: &[f64; 6], c: &[[f64; 3]; 3], full: bool) -> (Option<[f64; 6]>, [f64; 3]) {
    let ym = (!full).then(|| at::<6>(y0, c, &pr.half_e0, &pr.half_c));
    let qm: [f64; 3] = match &ym {
        Some(y) => [y[0], y[1], y[2]],
        None => at::<3>(y0, c, &pr.half_e0, &pr.half_c),
    };
    (ym, qm)
}

/// The state at σ inside the step under the same interpolated force (`c`), from the start `y0`
/// by the propagator `e0` and the weights `w` of that point: its first `R` rows.
fn at<const R: usize>(y0: &[f64; 6], c: &[[f64; 3]; 3], e0: &[[f64; 6]; 6], w: &[Block; 3]) -> [f64; R] {
    let mut ys = rows::<R, 6>(e0, y0);
    for (w, ck) in w.iter().zip(c) {
        ys.iter_mut().zip(rows::<R, 3>(w, ck)).for_each(|(a, b)| *a += b);
    }
    ys
}

/// Whether u_y,i = u_y − θ x_i of the spring at `x` is on its side (in contact, < 0, if
/// `contact`; else ≥ 0) at the state `y` ([`keeps_side`]'s test at a sample).
#[inline(always)]
fn on_side(x: f64, contact: bool, y: &[f64; 6]) -> bool {
    (y[1] - y[2] * x < 0.0) == contact
}

/// Whether u_y,i = u_y − θ x_i of the spring at `x` stays on its side (in contact, < 0, if
/// `contact`; else ≥ 0) through a step sampled at (σ, y(σ)): at the samples, and between each
/// two on the cubic through their values and rates, at a quarter, half and three quarters of
/// the way (module docs, "Partial contact").
fn keeps_side(x: f64, contact: bool, samples: &[(f64, [f64; 6]); 5]) -> bool {
    let side = |g: f64| (g < 0.0) == contact;
    let uy = |y: &[f64; 6]| (y[1] - y[2] * x, y[4] - y[5] * x);
    on_side(x, contact, &samples[0].1)
        && samples.windows(2).all(|w| {
            let ((sa, ya), (sb, yb)) = (&w[0], &w[1]);
            let (l, (ga, da), (gb, db)) = (sb - sa, uy(ya), uy(yb));
            on_side(x, contact, yb)
                && [0.25, 0.5, 0.75].iter().all(|&s: &f64| {
                    let (s2, s3) = (s * s, s * s * s);
                    side(
                        (2.0 * s3 - 3.0 * s2 + 1.0) * ga
                            + (s3 - 2.0 * s2 + s) * l * da
                            + (3.0 * s2 - 2.0 * s3) * gb
                            + (s3 - s2) * l * db,
                    )
                })
        })
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
            let springs = sim.model.x_m.len();
            let full = ContactSet::new(0, springs, springs);
            for i in 0..(10 << rung) {
                let t = sim.state.t_s;
                let third = if i == 0 { Third::Middle(p(t + 0.5 * h)) } else { Third::Before(p(t - h)) };
                let (p0, p1) = (p(t), p(t + h));
                let step = sim
                    .exact_sticking_step(full, rung, p0, p1, third, 1.0)
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

    /// A touch-down between the samples of a step is seen on the cubic through their values and
    /// rates (oracle: a parabola, which the cubic reproduces exactly): u_y,i = A ((σ − σ_c)² − w²)
    /// of a lifted spring at x = 0 over a step of 0.5 s, below 0 for σ within w = 0.02 s of
    /// σ_c = 0.28 s, between the samples at h/2 and 3h/4, all five of which are above 0; and
    /// the same without the touch-down (w² < 0) keeps its side, and so does the mirror image for
    /// a spring in contact, which would lift between the samples.
    #[test]
    fn a_touch_down_between_the_samples_is_seen() {
        let h = 0.5;
        let sampled = |sign: f64, w2: f64| -> [(f64, [f64; 6]); 5] {
            std::array::from_fn(|k| {
                let s = 0.25 * h * k as f64;
                let (g, rate) = (sign * 1e-4 * ((s - 0.28).powi(2) - w2), sign * 2e-4 * (s - 0.28));
                (s, [0.0, g, 0.0, 0.0, rate, 0.0])
            })
        };
        let mut checked = 0;
        for (contact, sign) in [(false, 1.0), (true, -1.0)] {
            let bounce = sampled(sign, 0.02f64.powi(2));
            assert!(bounce.iter().all(|(_, y)| (y[1] < 0.0) == contact), "every sample on its side");
            assert!(!keeps_side(0.0, contact, &bounce), "contact {contact}: the bounce is seen");
            assert!(keeps_side(0.0, contact, &sampled(sign, -0.02f64.powi(2))), "contact {contact}: none");
            // The other side's spring does not keep it at all.
            assert!(!keeps_side(0.0, !contact, &bounce));
            checked += 1;
        }
        assert_eq!(checked, 2);
    }

    /// One pulsating wave of period `period_s` pushing the caisson of `sim` shoreward with a peak
    /// of `share` μ W′ (μ = 0.6), its resultant at the levers of the tests below.
    fn push_wave(sim: &Simulation, share: f64, period_s: f64) -> crate::loads::history::WaveTrain {
        use crate::loads::history::{LoadComponent, WaveEvent, WaveTrain};
        let push = LoadComponent::from_levers(share * 0.6 * sim.model.weight_n, 0.0, 0.0, 0.39, 0.78);
        let wave = WaveEvent::new(0.0, period_s, push, 1.0, LoadComponent::default(), LoadComponent::default(), None);
        WaveTrain::new(vec![wave]).unwrap()
    }

    /// A sticking phase from rest to the end of a wave is crossed in exact steps, but for the gap
    /// before each of the wave's two breakpoints (T/2 and T: one Newmark step each): the Table 5
    /// caisson with a diagonal mass matrix under a pulsating wave through its base centre (R = 0,
    /// so no error estimate refuses a step) reaching a fifth of μ W', T = 2.03 s, dt_max = 50 ms.
    /// Counted: 20 steps of dt_max and one of dt_max/4 to T/2 = 1.015 s, the 2.5 ms left in one
    /// Newmark step; after it one step of dt_max/4, whose error estimate (0: R = 0) lets the next
    /// climb to the top, 20 steps of dt_max to 2.0275 s, and one Newmark step of 2.5 ms to T: 42
    /// exact steps; no spring slips.
    #[test]
    fn a_sticking_wave_takes_exact_steps_to_its_breakpoints() {
        let (dt_max, period) = (0.05, 2.03);
        let solver = SolverParams { dt_s: 1e-4, ..SolverParams::default() }
            .with_adaptive(AdaptiveParams { dt_max_s: dt_max, ..AdaptiveParams::for_first_step(1e-4) })
            .unwrap();
        let mut sim = simulation_with(DampingMode::Elastic, VerticalDamping::Springs, MassMatrix::Diagonal, solver);
        let train = push_wave(&sim, 0.2, period);
        sim.reset(&train);
        sim.run_until(period, &train, &mut ()).unwrap();
        let s = sim.stats;
        assert!((sim.state.t_s - period).abs() < 1e-12, "t = {}", sim.state.t_s);
        assert_eq!(s.exact_steps, 21 + 21, "{s:?}");
        assert_eq!(s.steps - s.exact_steps, 2, "{s:?}");
        assert_eq!(s.rejected_steps, 0, "{s:?}");
        assert!(sim.state.springs.iter().all(|c| c.slip_m == 0.0 && !c.sliding), "no spring slips");
    }

    /// The hand-over back to exact steps after a slip (module docs, "The ladder"): the Table 5
    /// caisson (diagonal mass matrix) under a pulsating wave through its base centre reaching
    /// 1.2 μ W' (T = 2.03 s, dt_max = 50 ms, tolerance 1e-6 m) slides 55 mm in one episode near
    /// the crest (0.32 s to 0.895 s, Newmark steps). The committed state that ends the slip is
    /// advanced by an exact step at once (counted: the one episode, 0 Newmark steps between its
    /// end and the next exact step; 32 exact steps of 85). The run agrees with
    /// Newmark steps alone at a 100 times tighter tolerance (1e-8 m, the oracle) within 0.5 % of
    /// the slip (measured 0.21 %, 1.1e-4 m: the Newmark steps of the slip at 1e-6 m).
    #[test]
    fn exact_steps_resume_as_soon_as_a_slip_ends() {
        /// Every committed step: whether it was exact (no Newton iteration) and any spring slips.
        #[derive(Default)]
        struct Steps(Vec<(f64, bool, bool)>);
        impl Observer for Steps {
            fn observe(&mut self, s: &super::super::StepView<'_>) {
                self.0.push((s.t_s, s.iterations == 0, s.state.springs.iter().any(|c| c.sliding)));
            }
            fn reads_reaction(&self) -> bool {
                false
            }
        }
        let (dt_max, period) = (0.05, 2.03);
        let run = |exact: bool, tolerance_m: f64| {
            let solver = SolverParams {
                dt_s: 1e-4,
                accel: crate::dynamics::Accel { exact_sticking: exact, ..Default::default() },
                ..SolverParams::default()
            }
            .with_adaptive(AdaptiveParams { dt_max_s: dt_max, tolerance_m, ..AdaptiveParams::for_first_step(1e-4) })
            .unwrap();
            let mut sim = simulation_with(DampingMode::Elastic, VerticalDamping::Springs, MassMatrix::Diagonal, solver);
            let train = push_wave(&sim, 1.2, period);
            sim.reset(&train);
            let mut steps = Steps::default();
            sim.run_until(period, &train, &mut steps).unwrap();
            (sim.state.u[0], sim.state.springs[0].slip_m, sim.stats, steps.0)
        };
        let (ux, slip, stats, steps) = run(true, 1e-6);
        let (ux_ref, slip_ref, _, _) = run(false, 1e-8);
        println!("{stats:?}; slip {slip:e} m, oracle {slip_ref:e} m; u_x {ux:e}, {ux_ref:e}");
        let mut ends = 0;
        for (i, w) in steps.windows(2).enumerate() {
            if w[0].2 && !w[1].2 {
                // The slip is over at step i + 1: the next step is exact.
                ends += 1;
                let next = steps[i + 2..].iter().position(|s| s.1).expect("exact steps again");
                assert_eq!(next, 0, "Newmark steps after the slip ended at {} s", w[1].0);
            }
        }
        assert!(ends >= 1 && slip.abs() > 1e-6, "{ends} slip episodes, slip {slip:e} m");
        assert_eq!(ends, 1, "one slip episode");
        assert!((slip - slip_ref).abs() < 5e-3 * slip_ref.abs(), "slip {slip:e} m, oracle {slip_ref:e} m");
    }
}
