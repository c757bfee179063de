//! The sharper screen of a design run (issue 19): a bound on the all-sticking response of the
//! caisson to a pulsating wave, which answers the waves that can neither slide nor lift the
//! caisson without time-stepping them ([`super::lifetime`], module docs "The screen"); and a
//! coarser one for impulsive waves (issue 35, "Impulsive waves" below).
//!
//! While every spring is in contact and sticks, the equations of motion are linear but for the
//! shear's departure R from K_x u_x (`dynamics::exact`'s module docs; [`Model::sticking_matrices`]):
//!
//! ```text
//! M q̈ + C_L q̇ + K_L q = p(t),    q = (u_x, u_y, θ) from the static equilibrium, y = (q, q̇)
//! ```
//!
//! A pulsating wave (Goda's loads, Eq. 29 shape: no impulse) loads it with p = P₁ sin ωt for
//! 0 ≤ t < T/2 (P₁ the crest's forces and moment) and p = P₂ sin ωt for T/2 ≤ t < T (P₂ the
//! trough's magnitudes; sin ωt < 0 there), ω = 2π/T. On each half the response is exactly
//!
//! ```text
//! y = y_p + y_h,   q_p(t) = Re[−i X e^{iωt}],  X = Z⁻¹ P,  Z = K_L − ω² M + iω C_L   (steady state)
//!                  y_h(τ) = Σ_m α_m w_m e^{λ_m τ}                                      (free vibration)
//! ```
//!
//! with λ_m, w_m the eigenvalues and eigenvectors of the first-order system y' = A y (every
//! Re λ_m < 0: damped modes, else no bound), τ the time from the half's start, and the modal
//! coordinates α from rest, α¹ = −W⁻¹ y_p1(0), and at T/2 α² = α¹ e^{λ T/2} + W⁻¹ (y_p2(0) −
//! y_p1(0)) (the first half's state less the trough's steady state there; y_p(0) = (Im X, ω Re X)).
//! A functional g = f·y then is |G| cos(ωt + arg G) plus Re Σ_m (f·w_m) α_m e^{λ_m τ}, and on each
//! of the INTERVALS intervals [τ_k, τ_k+1] of a half it lies within
//!
//! ```text
//! [min, max](g_p(τ_k), g_p(τ_k+1)) ∓ |G| (1 − cos(π/(2 INTERVALS)))  ∓  Σ_m |f·w_m α_m| e^{Re λ_m τ_k}
//! ```
//!
//! (a sinusoid exceeds its values at the ends of an interval of π/INTERVALS by at most that
//! share of its amplitude; every mode's envelope decays). Once the envelopes are below the first
//! term's slack, the rest of the half takes the sinusoid's exact range (its ends' values, or ±|G|
//! where the rest of the half holds the phase of its maximum or minimum, found by the sign of two
//! cross products, no angle computed). So the bound holds at every
//! instant of the wave, not only at samples. The functionals are the normal forces' changes at
//! the two outer springs, ΔN_i = −k_y (u_y − θ x_i), and of all springs, the elastic displacement
//! u_x, its rate u̇_x and the rotation θ. The wave can neither lift nor slip a spring if
//!
//! ```text
//! lift:  N_min = N̄ + min ΔN_i ≥ LIFT_RESERVE · N̄
//! slip:  max over the intervals k of  κ U_k W'/(W' + S_k) + c_d V_k / N_k  ≤ SLIP_RESERVE · μ_s
//! ```
//!
//! with N̄ = W'/n, κ the shear stiffness per unit normal force and c_d the dashpot beside each
//! spring (`foundation::spring`: a sticking spring slips when |κ N_i u_x + c_d u̇_x| > μ_s N_i,
//! and |κ N_i u_x + c_d u̇_x|/N_i ≤ κ |u_x| + c_d |u̇_x|/N_i with N_i at least the outer springs'
//! smaller N, ΔN being linear in x_i). On interval k of either half, U_k and V_k bound |u_x| and
//! |u̇_x|, S_k bounds ΣΔN from below and N_k the outer springs' N, each from its functional's range
//! on that interval (above): the demand at every instant of the interval is at most the term.
//! The factor W'/(W' + S_k) is R's quasi-static effect: the springs' horizontal stiffness is
//! κ Σ N_i, not K_x = κ W', so u_x grows as the uplift unloads them. The test is first made on the
//! wave's maxima, max|u_x| and max|u̇_x| (the fine ranges of both halves), ΣΔN's coarse bound
//! |G| + Σ_m |f·w_m α_m| over a half and N_min, maxima that may come at different times; only a
//! wave that fails it is tested interval by interval ([`StickBound::margins`]), each interval's
//! quantities taken no worse than the wave's, so the second test answers every wave the first
//! answers and more (`tests/verify_stick_bound.rs`: 165 against 147 of 166 waves, never below the
//! engine's friction demand; on the design example 24 759 fewer waves are run with it, and every
//! output but the counts stays that of running them, `scripts/same-numbers.sh`: none of them
//! slides or lifts). The reserves cover what the bound
//! leaves out: R's dynamic part and its coupling into the rocking through the mass matrix, and
//! the engine's own time-stepping error (tolerance 1e-6 m). Measured on the design example's
//! pulsating waves simulated without the bound (216 329 of them, every functional on the fine
//! bound): every wave that lifted or slipped had a bound of N_min ≤ 0.0006 N̄ (none of those the
//! reserves would answer), and the engine's largest rotation was 95.8-99.9 % of the bound's.
//! `tests/verify_stick_bound.rs` and `tests/equiv_lifetime.rs` check the bound on other waves and
//! storms.
//!
//! **Impulsive waves** ([`StickBound::impulse_margins`], `impulse.rs`). A breaking wave's load
//! (`loads::shapes`: the seed's larger of a triangle and the sine per axis, or a Table 2 shape)
//! has no steady state; the same linear system is bounded through its peak-to-peak gains
//! (e.g. Boyd & Barratt 1991, *Linear Controller Design*, §4.2: the L∞ → L∞ gain of a stable
//! convolution is the L1 norm of its kernel). From rest, each functional is g_f(t) = Σ_j ∫₀^t
//! k_fj(t − s) p_j(s) ds, k_fj the response of f to a unit impulse of load component j (F_x, F_y,
//! M): the free vibration from the velocity jump M⁻¹ e_j, Re Σ_m (f·w_m) β_jm e^{λ_m t}, β_j =
//! W⁻¹ (0, M⁻¹ e_j). So at every instant, whatever the load's timing,
//!
//! ```text
//! |g_f(t)| ≤ Σ_j ‖k_fj‖₁ max_s |p_j(s)|,      ‖k‖₁ = ∫₀^∞ |k(t)| dt
//! |u̇_x(t)| ≤ Σ_j ‖k_ux,j‖₁ max_s |ṗ_j(s)| + sup_t |k_ux,j(t)| Σ_i |Δp_j(s_i)|
//! ```
//!
//! (the load starts from 0: u̇_x is the convolution of k_ux with the load's rate and its jumps).
//! The gains ‖k_fj‖₁ and sup |k_fj| are integrated once per caisson with the modes (an upper
//! bound cell by cell, `impulse::gains`; within 0.1 % of the integral sampled every 10 µs, unit
//! test). max|p_j| is on the crest half the larger of each axis's impact and crest parts summed
//! over the two axes (each shape weighs them by at most 1), or the trough's; the rates are the
//! impact's slopes F_max/t_r (and its fall), ω F_qs+ and ω F_qs−, the jumps the moment's where the
//! seed's shape changes branch on an axis (the forces compared are equal there, the lever arms
//! not) and the plateaus' ends (Goda 1994, Oumeraci et al. 2001). Then N_min = N̄ − max(bound of
//! ΔN at the two outer springs), W' + min ΣΔN ≥ W' − bound of |ΣΔN|, and the friction demand
//! from the wave's maxima and the rotation follow as for a pulsating wave, with the same reserves.
//! The bound ignores when the peaks come (the impact's and the crest's are summed, and the sign
//! of the response): it is coarser than the pulsating one — on 144 breaking waves of the 10 m
//! deep study site (`tests/verify_stick_bound.rs`) at least 1.15 times the engine's friction
//! demand and 1.08 times its rotation (1.25-1.5 times on most) — but costs about 40 ns a wave
//! against about 5 µs for running it, and it answers about half of those waves and, on the
//! site's lives, 93 % of the impulsive waves the screen lets through (242 281 waves simulated in
//! 300 lives before, 17 168 after; every output but the counts the same to the bit,
//! `tests/equiv_lifetime.rs`, BENCHMARKS.md). A still impulsive wave's rotation bound enters the
//! settling of the largest rotation as a pulsating one's (`lifetime`'s module docs): a looser
//! bound only settles more waves, so a life's end sharpens the bounds of the waves it may settle
//! ([`StickBound::rotation_under_history_rad`], `history.rs`: the response followed through the
//! wave's own load, piece by piece in closed form).

mod history;
mod impulse;

pub use history::{Ask, TOE_RESERVE, TOLERANCE as HISTORY_TOLERANCE};

use crate::dynamics::Model;
use crate::loads::WaveForce;
use nalgebra::{Complex, Matrix3, SMatrix, Vector3};
use std::cell::RefCell;
use std::f64::consts::PI;
use std::rc::Rc;

/// The share of N̄ = W'/n the bound must leave at the outer springs: a wave whose bound comes
/// closer to lifting one is simulated.
pub const LIFT_RESERVE: f64 = 0.05;
/// The share of μ_s the bound's friction demand may reach: a wave that comes closer to slipping
/// a spring is simulated.
pub const SLIP_RESERVE: f64 = 0.95;
/// Intervals of each half wave on which the bound is taken.
const INTERVALS: usize = 12;

type C64 = Complex<f64>;
type Matrix6c = SMatrix<C64, 6, 6>;
type Vector6c = SMatrix<C64, 6, 1>;

/// The functionals of the state y = (q, q̇) the bound tracks: ΔN at the outer springs (two), ΔN
/// of all springs, u_x, u̇_x and θ.
const FUNCTIONALS: usize = 6;
/// The functionals' indices: ΔN at the outer springs, ΔN of all springs, u_x, u̇_x (the only one
/// that reads q̇) and θ.
const EDGES: [usize; 2] = [0, 1];
const TOTAL: usize = 2;
const UX: usize = 3;
const VX: usize = 4;
const THETA: usize = 5;

/// The modes of the all-sticking system and the functionals in them: the same for every storm
/// of a caisson (the tide changes its weight in water, not M, K_L or C_L), so built once per
/// thread and caisson.
#[derive(Debug)]
struct Modes {
    mass: Matrix3<f64>,
    k_l: Matrix3<f64>,
    c_l: Matrix3<f64>,
    /// The eigenvalues λ_m of the first-order system y' = A y (every Re λ_m < 0).
    lambda: [C64; 6],
    /// The eigenvectors' inverse (the modal coordinates of a state), its real and imaginary
    /// parts.
    winv: [[f64; 6]; 6],
    winv_im: [[f64; 6]; 6],
    /// The functionals' moduli in modal coordinates, |f·w_m| (a mode's amplitude in functional f
    /// is |f·w_m| |α_m|).
    modal_abs: [[f64; 6]; FUNCTIONALS],
    /// The functionals' q rows (u̇_x's is 0: it reads q̇_x).
    rows: [Vector3<f64>; FUNCTIONALS],
    /// The peak-to-peak gains ‖k_fj‖₁ of the functionals f to the load components j (F_x, F_y,
    /// M): the impulsive waves' bound ([`impulse::gains`]).
    gains: impulse::Gains,
    /// The modes of θ's response to the load, a conjugate pair as one: the rotation under a
    /// wave's own load history ([`history`]).
    theta: history::ThetaModes,
    /// Those of ΣΔN_i and of Σ x_i ΔN_i (the heel pressure's), and Σ x_i, m.
    normal: history::ThetaModes,
    moment: history::ThetaModes,
    sum_x_m: f64,
}

/// M, K_L, C_L, k_y and the springs' lowest and highest x and Σx: what [`Modes`] come from.
type Key = [f64; 31];

/// Modes kept per thread, the most recent last (a sizing run alternates among a few caissons).
const CACHED_MODES: usize = 4;

/// A cached entry: the key and the modes it gave (`None`: none could be built).
type Cached = Option<(Key, Option<Rc<Modes>>)>;

thread_local! {
    static MODES: RefCell<[Cached; CACHED_MODES]> =
        const { RefCell::new([const { None }; CACHED_MODES]) };
}

/// The caisson's all-sticking system at a storm's water level: what every wave's bound needs.
#[derive(Debug, Clone)]
pub struct StickBound {
    modes: Rc<Modes>,
    /// N̄ = W'/n, W', N; κ, 1/m; c_d, N·s/m; μ_s.
    n_ref: f64,
    weight_n: f64,
    kappa_per_m: f64,
    dashpot_ns_per_m: f64,
    mu_static: f64,
}

/// What the bound of a wave of one period needs: Z⁻¹ = (K_L − ω² M + iω C_L)⁻¹, the phasors
/// e^{iωt_k} and the modes' decays e^{Re λ_m t_k} at the INTERVALS + 1 points of a half wave,
/// and e^{λ_m T/2}.
#[derive(Debug, Clone, Copy)]
pub struct AtPeriod {
    zinv: Matrix3<C64>,
    omega: f64,
    phasor: [C64; INTERVALS + 1],
    decay: [[f64; 6]; INTERVALS + 1],
    half: [C64; 6],
}

/// What the bound leaves of a wave's margins: the smallest normal force at the outer springs
/// as a share of N̄ (below 0: it may lift), and the friction demand as a share of μ_s (above 1:
/// it may slip).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Margins {
    pub normal_share: f64,
    pub friction_share: f64,
    /// The friction demand from the wave's maxima alone (max|u_x|, max|u̇_x|, min ΣΔN, N_min),
    /// as a share of μ_s: `friction_share` is taken interval by interval where this one exceeds
    /// [`SLIP_RESERVE`] (module docs), never above it.
    pub friction_share_of_maxima: f64,
    /// The largest rotation |θ| the wave may give the caisson, rad.
    pub rotation_rad: f64,
}

impl Margins {
    /// Whether the bound, with its reserves, shows that the wave neither lifts nor slips a
    /// spring (module docs: the reserves cover what the bound leaves out).
    pub fn still(&self) -> bool {
        self.normal_share >= LIFT_RESERVE && self.friction_share <= SLIP_RESERVE
    }
}

fn complex(v: &Vector3<f64>) -> Vector3<C64> {
    v.map(|x| C64::new(x, 0.0))
}

/// The first-order matrix A of y = (q, q̇): [0, I; −M⁻¹K, −M⁻¹C].
fn first_order(minv: &Matrix3<f64>, k: &Matrix3<f64>, c: &Matrix3<f64>) -> SMatrix<f64, 6, 6> {
    let (mk, mc) = (-minv * k, -minv * c);
    let mut a = SMatrix::<f64, 6, 6>::zeros();
    for i in 0..3 {
        a[(i, 3 + i)] = 1.0;
        for j in 0..3 {
            a[(3 + i, j)] = mk[(i, j)];
            a[(3 + i, 3 + j)] = mc[(i, j)];
        }
    }
    a
}

/// The eigenvectors of `a` for its eigenvalues `lambda`, by inverse iteration (three solves
/// from a shift a part in 1e-9 off each eigenvalue); `None` if a solve fails.
fn eigenvectors(a: &SMatrix<f64, 6, 6>, lambda: &[C64; 6]) -> Option<Matrix6c> {
    let ac = a.map(|x| C64::new(x, 0.0));
    let mut w = Matrix6c::zeros();
    for (m, &l) in lambda.iter().enumerate() {
        let shift = l + C64::new(1e-9 * l.norm().max(1e-9), 1e-9 * l.norm().max(1e-9));
        let lu = (ac - Matrix6c::identity() * shift).lu();
        let mut v = Vector6c::from_fn(|i, _| C64::new(1.0 + 0.1 * i as f64, 0.3 - 0.05 * i as f64));
        for _ in 0..3 {
            v = lu.solve(&v)?;
            let n = v.norm();
            if !(n.is_finite() && n > 0.0) {
                return None;
            }
            v /= C64::new(n, 0.0);
        }
        w.set_column(m, &v);
    }
    Some(w)
}

impl Modes {
    /// The modes of `model`'s all-sticking system; `None` if its matrices are singular, a mode
    /// is not damped, or the modes cannot be separated.
    fn new(model: &Model, (mass, k_l, c_l): (Matrix3<f64>, Matrix3<f64>, Matrix3<f64>), key: &Key) -> Option<Self> {
        let minv = mass.try_inverse()?;
        let a = first_order(&minv, &k_l, &c_l);
        let ev = a.complex_eigenvalues();
        let lambda: [C64; 6] = std::array::from_fn(|i| ev[i]);
        if lambda.iter().any(|l| !(l.re < 0.0 && l.im.is_finite())) {
            return None;
        }
        let w = eigenvectors(&a, &lambda)?;
        let winv = w.try_inverse()?;
        // The decomposition must give A back (a defective or ill-separated pair would not).
        let back = w * Matrix6c::from_diagonal(&Vector6c::from_fn(|i, _| lambda[i])) * winv;
        if (back - a.map(|x| C64::new(x, 0.0))).norm() > 1e-6 * a.norm() {
            return None;
        }
        let n = model.x_m.len() as f64;
        let [ky, x_lo, x_hi, sum_x] = [key[27], key[28], key[29], key[30]];
        let rows = [
            Vector3::new(0.0, -ky, ky * x_lo),
            Vector3::new(0.0, -ky, ky * x_hi),
            Vector3::new(0.0, -n * ky, ky * sum_x),
            Vector3::x(),
            Vector3::zeros(),
            Vector3::z(),
        ];
        let modal: [[C64; 6]; FUNCTIONALS] = std::array::from_fn(|f| {
            std::array::from_fn(|m| if f == VX { w[(3, m)] } else { (0..3).map(|i| w[(i, m)] * rows[f][i]).sum() })
        });
        let gains = impulse::gains(&lambda, &modal, &winv, &minv);
        let theta = history::ThetaModes::new(&lambda, &modal[THETA], &winv, &minv);
        let sum_x2: f64 = model.x_m.iter().map(|x| x * x).sum();
        let moment_row = Vector3::new(0.0, -ky * sum_x, ky * sum_x2);
        let in_modes =
            |row: &Vector3<f64>| -> [C64; 6] { std::array::from_fn(|m| (0..3).map(|i| w[(i, m)] * row[i]).sum()) };
        Some(Modes {
            gains,
            theta,
            normal: history::ThetaModes::new(&lambda, &modal[TOTAL], &winv, &minv),
            moment: history::ThetaModes::new(&lambda, &in_modes(&moment_row), &winv, &minv),
            sum_x_m: sum_x,
            mass,
            k_l,
            c_l,
            lambda,
            winv: std::array::from_fn(|i| std::array::from_fn(|j| winv[(i, j)].re)),
            winv_im: std::array::from_fn(|i| std::array::from_fn(|j| winv[(i, j)].im)),
            modal_abs: modal.map(|row: [C64; 6]| row.map(modulus)),
            rows,
        })
    }

    /// The modes of `model`, from this thread's cache when it has them.
    fn cached(model: &Model) -> Option<Rc<Modes>> {
        let (m, k, c) = model.sticking_matrices();
        let (x_lo, x_hi) = model.x_m.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &x| (a.min(x), b.max(x)));
        let mut key = [0.0; 31];
        key[..9].copy_from_slice(m.as_slice());
        key[9..18].copy_from_slice(k.as_slice());
        key[18..27].copy_from_slice(c.as_slice());
        key[27..].copy_from_slice(&[model.law.ky_n_per_m, x_lo, x_hi, model.x_m.iter().sum()]);
        MODES.with(|cache| {
            let mut cache = cache.borrow_mut();
            if let Some((_, modes)) = cache.iter().flatten().find(|(k, _)| *k == key) {
                return modes.clone();
            }
            let modes = Modes::new(model, (m, k, c), &key).map(Rc::new);
            cache.rotate_left(1);
            cache[CACHED_MODES - 1] = Some((key, modes.clone()));
            modes
        })
    }
}

impl StickBound {
    /// The bound of `model` (at the storm's water level and friction); `None` if its
    /// all-sticking system has no damped, separable modes.
    pub fn new(model: &Model) -> Option<Self> {
        Some(StickBound {
            modes: Modes::cached(model)?,
            n_ref: model.weight_n / model.x_m.len() as f64,
            weight_n: model.weight_n,
            kappa_per_m: model.law.kappa_per_m,
            dashpot_ns_per_m: model.spring_dashpot_ns_per_m,
            mu_static: model.mu_static,
        })
    }

    /// What the bound of a wave of period `period_s` needs; `None` if Z is singular.
    pub fn at_period(&self, period_s: f64) -> Option<AtPeriod> {
        let md = &*self.modes;
        let omega = 2.0 * PI / period_s;
        let z = md.k_l.map(|x| C64::new(x, 0.0)) - md.mass.map(|x| C64::new(omega * omega * x, 0.0))
            + md.c_l.map(|x| C64::new(0.0, omega * x));
        let dt = 0.5 * period_s / INTERVALS as f64;
        let step = C64::from_polar(1.0, omega * dt);
        let shrink: [f64; 6] = std::array::from_fn(|m| (md.lambda[m].re * dt).exp());
        let mut at = AtPeriod {
            zinv: z.try_inverse()?,
            omega,
            phasor: [C64::new(1.0, 0.0); INTERVALS + 1],
            decay: [[1.0; 6]; INTERVALS + 1],
            half: std::array::from_fn(|m| (md.lambda[m] * (0.5 * period_s)).exp()),
        };
        for k in 1..=INTERVALS {
            at.phasor[k] = at.phasor[k - 1] * step;
            at.decay[k] = std::array::from_fn(|m| at.decay[k - 1][m] * shrink[m]);
        }
        Some(at)
    }

    /// The margins of a pulsating wave of crest load `crest` and trough magnitudes `trough`
    /// (module docs), in the order the test needs them: the normal forces first (a wave that may
    /// lift a spring is left there, its friction share and rotation infinite: it is simulated),
    /// then the friction (likewise), then the rotation.
    pub fn margins(&self, at: &AtPeriod, crest: WaveForce, trough: WaveForce) -> Margins {
        let r = Response::new(&self.modes, at, crest, trough);
        // A wave whose crest alone, at T/4 and without its free vibration, leaves an outer spring
        // less than the reserve is simulated without the rest of the bound (it would fail it).
        for f in EDGES {
            let crest_at_quarter = -(complex(&r.md.rows[f]).dot(&r.x[0])).re;
            if self.n_ref + crest_at_quarter < LIFT_RESERVE * self.n_ref {
                return Margins {
                    normal_share: 1.0 + crest_at_quarter / self.n_ref,
                    friction_share: f64::INFINITY,
                    friction_share_of_maxima: f64::INFINITY,
                    rotation_rad: f64::INFINITY,
                };
            }
        }
        // The crest half first: most waves that may lift do so there.
        let edges_lo = |half: usize| r.fine_half(EDGES[0], half).0.min(r.fine_half(EDGES[1], half).0);
        let mut n_min = self.n_ref + edges_lo(0);
        let mut margins = Margins {
            normal_share: n_min / self.n_ref,
            friction_share: f64::INFINITY,
            friction_share_of_maxima: f64::INFINITY,
            rotation_rad: f64::INFINITY,
        };
        if margins.normal_share < LIFT_RESERVE {
            return margins;
        }
        n_min = n_min.min(self.n_ref + edges_lo(1));
        margins.normal_share = n_min / self.n_ref;
        if margins.normal_share < LIFT_RESERVE {
            return margins;
        }
        let total_min = self.weight_n - r.coarse(TOTAL);
        if total_min <= 0.0 {
            return margins;
        }
        let (ux, vx) = (r.peak(UX), r.peak(VX));
        let friction = self.kappa_per_m * ux * self.weight_n / total_min + self.dashpot_ns_per_m * vx / n_min;
        margins.friction_share = friction / self.mu_static;
        margins.friction_share_of_maxima = margins.friction_share;
        if margins.friction_share > SLIP_RESERVE {
            // The maxima over the wave come at different times: the demand interval by interval.
            margins.friction_share = self.friction_by_interval(&r, (ux, vx, total_min, n_min)) / self.mu_static;
            if margins.friction_share > SLIP_RESERVE {
                return margins;
            }
        }
        margins.rotation_rad = r.peak(THETA);
        margins
    }
}

impl StickBound {
    /// The friction demand of the wave (module docs, "slip") taken on each interval of each half
    /// with the interval's own ranges of u_x, u̇_x, ΣΔN and the outer springs' ΔN, each no worse
    /// than the wave's `(max|u_x|, max|u̇_x|, W' + min ΣΔN, N_min)`: the largest, N.
    fn friction_by_interval(&self, r: &Response<'_>, (ux_max, vx_max, total_min, n_min): (f64, f64, f64, f64)) -> f64 {
        let mut demand = 0.0_f64;
        for half in 0..2 {
            let [ux, vx, total, lo0, lo1] = [UX, VX, TOTAL, EDGES[0], EDGES[1]].map(|f| r.intervals(f, half));
            for k in 0..INTERVALS {
                let u = ux[k].0.abs().max(ux[k].1.abs()).min(ux_max);
                let v = vx[k].0.abs().max(vx[k].1.abs()).min(vx_max);
                let total_n = (self.weight_n + total[k].0).max(total_min);
                let n = (self.n_ref + lo0[k].0.min(lo1[k].0)).max(n_min);
                demand = demand.max(self.kappa_per_m * u * self.weight_n / total_n + self.dashpot_ns_per_m * v / n);
            }
        }
        demand
    }
}

/// The all-sticking response of one wave ([`StickBound::margins`]): the steady-state amplitudes
/// X = Z⁻¹ P of its crest and trough, and the moduli of the free vibration's modal coordinates
/// at each half's start (a mode's envelope needs no more).
struct Response<'a> {
    md: &'a Modes,
    at: &'a AtPeriod,
    x: [Vector3<C64>; 2],
    /// The moduli |α_m| of the modal coordinates at each half's start.
    alpha_abs: [[f64; 6]; 2],
}

impl<'a> Response<'a> {
    fn new(md: &'a Modes, at: &'a AtPeriod, crest: WaveForce, trough: WaveForce) -> Self {
        let w = at.omega;
        let solve = |p: WaveForce| -> Vector3<C64> {
            let p = [p.fx_n, p.fy_n, p.m_nm];
            Vector3::from_fn(|i, _| (0..3).map(|j| at.zinv[(i, j)] * p[j]).sum())
        };
        let x = [solve(crest), solve(trough)];
        // The modal coordinates of the steady state of a load P sin ωt at t = 0,
        // y_p(0) = (Im X, ω Re X).
        let modal_p0 = |x: &Vector3<C64>| -> [C64; 6] {
            let y: [f64; 6] = std::array::from_fn(|i| if i < 3 { x[i].im } else { w * x[i - 3].re });
            let dot = |row: &[f64; 6]| row.iter().zip(&y).map(|(a, b)| a * b).sum::<f64>();
            std::array::from_fn(|m| C64::new(dot(&md.winv[m]), dot(&md.winv_im[m])))
        };
        // The free vibration's modal coordinates at each half's start: from rest, −y_p1(0); at
        // T/2, its own continuation plus y_p1(T/2) − y_p2(T/2) = y_p2(0) − y_p1(0).
        let (p1, p2) = (modal_p0(&x[0]), modal_p0(&x[1]));
        let alpha0: [C64; 6] = std::array::from_fn(|m| -p1[m]);
        let alpha = [alpha0, std::array::from_fn(|m| alpha0[m] * at.half[m] + p2[m] - p1[m])];
        Response { md, at, x, alpha_abs: alpha.map(|a| a.map(modulus)) }
    }

    /// Functional f's harmonic part G on a half.
    fn harmonic(&self, f: usize, half: usize) -> C64 {
        if f == VX {
            self.x[half][0] * self.at.omega
        } else {
            complex(&self.md.rows[f]).dot(&self.x[half]) * C64::new(0.0, -1.0)
        }
    }

    /// The amplitudes |f·w_m α_m| of functional f's modes on a half.
    fn amplitudes(&self, f: usize, half: usize) -> [f64; 6] {
        std::array::from_fn(|m| self.md.modal_abs[f][m] * self.alpha_abs[half][m])
    }

    /// The fine range of a functional over a half: on each interval [t_k, t_k+1], the harmonic
    /// part within its ends' range plus the largest excess of a sinusoid over them on an interval
    /// of π/INTERVALS, 1 − cos(π/(2 INTERVALS)) of its amplitude; the free vibration within its
    /// modes' envelopes at t_k (they decay). Inlined: where only the lower end is read (the outer
    /// springs' normal forces) the upper end is not computed.
    #[inline(always)]
    fn fine_half(&self, f: usize, half: usize) -> (f64, f64) {
        let at = self.at;
        let excess = 1.0 - (0.5 * PI / INTERVALS as f64).cos();
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        // e^{iωt} on the second half is −e^{iω(t − T/2)}.
        let g = if half == 0 { self.harmonic(f, half) } else { -self.harmonic(f, half) };
        let amp = self.amplitudes(f, half);
        let a = modulus(g);
        let slack = excess * a;
        let mut prev = (g * at.phasor[0]).re;
        for k in 0..INTERVALS {
            let env: f64 = (0..6).map(|m| amp[m] * at.decay[k][m]).sum();
            if env <= slack {
                // The free vibration has died down to the slack: on the rest of the half, the
                // harmonic part's exact range (ωt from k π/INTERVALS to π) plus it.
                let (c_lo, c_hi) = arc_range(g, at.phasor[k], prev);
                lo = lo.min(c_lo - env);
                hi = hi.max(c_hi + env);
                break;
            }
            let next = (g * at.phasor[k + 1]).re;
            lo = lo.min(prev.min(next) - slack - env);
            hi = hi.max(prev.max(next) + slack + env);
            prev = next;
        }
        (lo, hi)
    }

    /// The range of functional f on each interval [t_k, t_k+1] of a half, as [`Self::fine_half`]
    /// takes it before the free vibration dies down: the harmonic part within its ends' range plus
    /// the slack, the free vibration within its modes' envelopes at t_k.
    fn intervals(&self, f: usize, half: usize) -> [(f64, f64); INTERVALS] {
        let at = self.at;
        let excess = 1.0 - (0.5 * PI / INTERVALS as f64).cos();
        let g = if half == 0 { self.harmonic(f, half) } else { -self.harmonic(f, half) };
        let amp = self.amplitudes(f, half);
        let slack = excess * modulus(g);
        let mut prev = (g * at.phasor[0]).re;
        std::array::from_fn(|k| {
            let env: f64 = (0..6).map(|m| amp[m] * at.decay[k][m]).sum();
            let next = (g * at.phasor[k + 1]).re;
            let range = (prev.min(next) - slack - env, prev.max(next) + slack + env);
            prev = next;
            range
        })
    }

    /// The largest |f| over the wave, from its fine ranges on both halves.
    fn peak(&self, f: usize) -> f64 {
        let ((lo0, hi0), (lo1, hi1)) = (self.fine_half(f, 0), self.fine_half(f, 1));
        let (lo, hi) = (lo0.min(lo1), hi0.max(hi1));
        lo.abs().max(hi.abs())
    }

    /// The coarse bound of |f| over the wave: its harmonic amplitude and every mode's at a
    /// half's start.
    fn coarse(&self, f: usize) -> f64 {
        (0..2)
            .map(|half| modulus(self.harmonic(f, half)) + self.amplitudes(f, half).iter().sum::<f64>())
            .fold(0.0, f64::max)
    }
}

/// The range of Re(g e^{iψ}) for ψ from ψ_k to π (0 ≤ ψ_k < π), `start` = e^{iψ_k} and
/// `at_start` = Re(g e^{iψ_k}): the larger and smaller of its ends' values (at π, −Re g), or |g|
/// and −|g| where the arc holds the phase of the maximum, e^{iψ} = ḡ/|g|, or of the minimum,
/// −ḡ/|g|. A direction z lies on the arc (counter-clockwise from e^{iψ_k} to −1, at most π)
/// when it is in the upper half plane and to the left of e^{iψ_k}: no angle is computed.
fn arc_range(g: C64, start: C64, at_start: f64) -> (f64, f64) {
    let on_arc = |z: C64| z.im >= 0.0 && start.re * z.im - start.im * z.re >= 0.0;
    let (a, at_end) = (modulus(g), -g.re);
    let hi = if on_arc(g.conj()) { a } else { at_start.max(at_end) };
    let lo = if on_arc(-g.conj()) { -a } else { at_start.min(at_end) };
    (lo, hi)
}

/// |z| without libm's `hypot` (the bound needs no care for overflow: its numbers are forces and
/// displacements).
#[inline]
fn modulus(z: C64) -> f64 {
    (z.re * z.re + z.im * z.im).sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The range of Re(g e^{iψ}) on ψ ∈ [kπ/INTERVALS, π] without angles against 1 001 samples of
    /// it: for g of modulus 2.5 at 720 phases (every half degree, so the extrema also fall on the
    /// arc's ends) and every k, within the samples' spacing error, 2.5 (1 − cos(π/2000)) ≈ 3e-6,
    /// above them and 1e-12 below them (rounding).
    #[test]
    fn the_range_on_an_arc_is_the_sampled_one() {
        let mut checked = 0;
        for j in 0..720 {
            let g = C64::from_polar(2.5, j as f64 * PI / 360.0);
            for k in 0..INTERVALS {
                let psi0 = PI * k as f64 / INTERVALS as f64;
                let start = C64::from_polar(1.0, psi0);
                let (lo, hi) = arc_range(g, start, (g * start).re);
                let (mut s_lo, mut s_hi) = (f64::INFINITY, f64::NEG_INFINITY);
                for i in 0..=1000 {
                    let v = (g * C64::from_polar(1.0, psi0 + (PI - psi0) * i as f64 / 1000.0)).re;
                    s_lo = s_lo.min(v);
                    s_hi = s_hi.max(v);
                }
                let spacing = 2.5 * (1.0 - (PI / 2000.0).cos()) + 1e-12;
                assert!(hi >= s_hi - 1e-12 && hi <= s_hi + spacing, "g {g}, k {k}: {hi} against {s_hi}");
                assert!(lo <= s_lo + 1e-12 && lo >= s_lo - spacing, "g {g}, k {k}: {lo} against {s_lo}");
                checked += 1;
            }
        }
        assert_eq!(checked, 720 * INTERVALS);
    }
}
