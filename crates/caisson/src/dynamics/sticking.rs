//! The all-sticking fast path of the resisting force (docs/model.md §9.1): while every spring is
//! in contact and sticks, the sums over the springs are closed forms in the displacements.
//!
//! With N_i = −k_y (u_y − θ x_i) = a + b x_i (a = −k_y u_y, b = k_y θ), e_i = u_x − s_i and, in
//! the `elastic` damping mode, the dashpot term c' (e_i − ē_n,i) = c' (u_x − u_x,n − (h/2) ė_n,i)
//! of every sticking spring (c' = 2 c_d/h, ė_n,i = u̇_x,n unless the spring was slipping:
//! [`crate::foundation::spring`]):
//!
//! ```text
//! Σ N_i     = n a + b Σx_i                      Σ x_i N_i = a Σx_i + b Σx_i²
//! Σ e_i     = n E − Σd_i                        Σ x_i e_i = E Σx_i − Σx_i d_i
//! Σ F_i     = κ (a Σe_i + b Σx_i e_i) + c' (n (u_x − u_x,n) − (h/2) Σė_n,i)
//! E = u_x − s_1,  d_i = s_i − s_1               (slips relative to the first spring's)
//! Σė_n,i    = Σ_slipping ė_n,i + n_sticking u̇_x,n
//! ```
//!
//! and the vertical dashpots of the `springs` form add c_y (n v_y − θ̇ Σx_i) to the vertical force
//! and −c_y (v_y Σx_i − θ̇ Σx_i²) to the moment. The tangent's entries are the same sums:
//! ∂ΣF/∂u_x = κ ΣN_i + n c', ∂ΣF/∂u_y = −κ k_y Σe_i, ∂ΣF/∂θ = κ k_y Σx_i e_i, and the
//! vertical block (k_y + γ c_y/(β h)) (n, −Σx_i; −Σx_i, Σx_i²).
//!
//! n, Σx_i and Σx_i² are the model's (summed once); Σd_i, Σx_i d_i and the slipping springs'
//! Σė_n,i change only when a spring's slip state does, i.e. after a step committed by the general
//! path; they are recomputed (in one pass over the springs) before the next iterate that needs
//! them, not while a spring is lifted at the committed state (the general path then). A step that
//! the fast path found all-sticking from a state with slipping springs is committed through the
//! general path (their responses need their own rates).
//!
//! Whether every spring sticks is decided spring by spring by the spring law's own test
//! ([`SpringLaw::sticks`], the same operations as its `sticking` branch), so the path
//! is taken exactly when the general one would find every spring in contact and sticking; the
//! sums are then the same quantities added in another order (equal to rounding). The per-spring
//! responses of an all-sticking step ([`Simulation::springs`]) are built only when asked for: for
//! an observer that reads them ([`super::Observer::reads_springs`]), and at the end of a run; its
//! base reaction ([`Simulation::reaction`]) is the closed form.
//!
//! **The all-sticking step solved directly** ([`Simulation::direct_sticking_step`], docs/model.md
//! §9.1): after a step that left every spring in contact and sticking, the next step is first
//! solved as all-sticking, without iterating. With q̈ = a* + c1 δ and q̇ = v* + g δ (Newmark;
//! c1 = 1/(β h²), g = γ/(β h)) the residual is r(δ) = r0 − K_lin δ − f_S(δ), K_lin = c1 M + g C.
//! The vertical and rocking rows of f_S are linear in δ (above), so they give
//! (δ_y, δ_θ) = P + Q δ_x (a 2 × 2 solve); the horizontal row holds the bilinear shear
//! κ (a Σe_i + b Σx_i e_i) with a = a_n − k_y δ_y, b = b_n + k_y δ_θ, Σe_i = Σe_n + n δ_x and
//! Σx_i e_i = Σxe_n + Σx_i δ_x, so it becomes A δ_x² + B δ_x + C = 0, solved by
//! δ_x = −2C / (B + sign(B) √(B² − 4AC)) (the root that tends to −C/B as A vanishes, without
//! cancellation). The step is accepted if every spring sticks there (the test above, which also
//! records the sums of the commit and the reaction) and its residual meets the Newton tolerance;
//! otherwise the caller iterates. Newton would stop anywhere inside that tolerance; this lands
//! on the root (to rounding), which is why the fast path now moves results within the
//! tolerance's reach rather than to rounding (`crates/caisson/tests/equiv_sticking_fast_path.rs`).
//!
//! [`SpringLaw::sticks`]: crate::foundation::SpringLaw::sticks

use super::{Converged, Reaction, Simulation};
use nalgebra::{Matrix3, Vector3};

/// The fast path's scratch, sized when the simulation is built.
#[derive(Debug, Clone, Default)]
pub(super) struct FastPath {
    /// The sums of the committed slip positions are up to date, and so are `slip_m` and
    /// `limit_m`.
    valid: bool,
    /// A spring of the committed state was slipping (its limit is e_d, not e_s).
    any_sliding: bool,
    /// A spring was lifted in the committed state while re-contact is placed within the step
    /// ([`super::SolverParams::locate_contact`]): its trial needs the general path.
    any_lifted: bool,
    /// Every spring has the same slip position, the positions x_i ascend and there is a spring:
    /// with equal limits, the stick test of the two outermost springs decides for all.
    same_slips: bool,
    /// The positions x_i ascend and there is a spring (the model's, fixed).
    ascending: bool,
    /// n, Σx_i and Σx_i² (the model's, fixed).
    n: f64,
    sum_x: f64,
    sum_x2: f64,
    /// s_1, the first spring's slip position, m.
    s_ref_m: f64,
    /// Σ d_i and Σ x_i d_i, d_i = s_i − s_1.
    sum_d: f64,
    sum_xd: f64,
    /// The committed slip positions and stick limits ([`SpringLaw::limit_m`]), spring by
    /// spring, for a stick test over plain slices.
    ///
    /// [`SpringLaw::limit_m`]: crate::foundation::SpringLaw::limit_m
    slip_m: Vec<f64>,
    limit_m: Vec<f64>,
    /// The committed elastic rate ė_n,i of a slipping spring, 0 for the others, m/s; and 1 for a
    /// spring whose rate is the caisson's velocity u̇_x,n (sticking or lifted), 0 for the others.
    rate_m: Vec<f64>,
    follows_v: Vec<f64>,
    /// Σ of `rate_m` and of `follows_v`.
    sum_rate: f64,
    n_follow: f64,
    /// The last iterate, if it took the fast path.
    pub iterate: Option<StickIterate>,
    /// Try [`Simulation::direct_sticking_step`] first: the last committed step left every
    /// spring sticking (or the state is the static equilibrium).
    pub direct: bool,
    /// The committed step, if all-sticking (its base reaction in closed form).
    committed: Option<StickIterate>,
    /// The committed all-sticking step's per-spring responses are not built yet.
    pending: Option<PendingResponses>,
}

/// The sums of an all-sticking iterate that the tangent and the base reaction need.
#[derive(Debug, Clone, Copy)]
pub(super) struct StickIterate {
    sum_n: f64,
    sum_xn: f64,
    sum_e: f64,
    sum_xe: f64,
    shear_n: f64,
    /// c' = 2 c_d/h, N/m.
    c_prime: f64,
}

/// An all-sticking step committed without its per-spring responses: its length and the
/// horizontal displacement and velocity it started from (e_n,i = u_x,n − s_i, ė_n,i = u̇_x,n).
#[derive(Debug, Clone, Copy)]
struct PendingResponses {
    h: f64,
    ux_prev_m: f64,
    vx_prev_m_per_s: f64,
}

impl FastPath {
    /// The scratch of springs at the positions `x_m`, with their sums n, Σx_i and Σx_i².
    pub fn new(x_m: &[f64]) -> Self {
        let springs = x_m.len();
        let (mut n, mut sum_x, mut sum_x2) = (0.0, 0.0, 0.0);
        for &x in x_m {
            n += 1.0;
            sum_x += x;
            sum_x2 += x * x;
        }
        FastPath {
            ascending: springs > 0 && x_m.windows(2).all(|w| w[0] <= w[1]),
            n,
            sum_x,
            sum_x2,
            slip_m: vec![0.0; springs],
            limit_m: vec![0.0; springs],
            rate_m: vec![0.0; springs],
            follows_v: vec![0.0; springs],
            ..FastPath::default()
        }
    }

    /// Forget everything derived from the committed spring states (they changed).
    #[inline]
    pub fn invalidate(&mut self) {
        self.valid = false;
        self.committed = None;
        self.pending = None;
    }
}

impl Simulation {
    /// Whether every spring is in contact and sticks at the trial displacement `u` of a step of
    /// length `h` (the test of [`Self::sticking_force`], module docs), without its sums.
    #[inline]
    pub(super) fn all_stick(&mut self, u: [f64; 3], h: f64) -> bool {
        self.all_stick_at([(u, h)])
    }

    /// [`Self::all_stick`] at each of the trial displacements and step lengths `points`, in
    /// turn (the same tests, one preamble): the exact step's middle and end (`exact`).
    #[inline]
    pub(super) fn all_stick_at<const P: usize>(&mut self, points: [([f64; 3], f64); P]) -> bool {
        if !self.fast.valid {
            // A lifted spring needs the general path: the sums are not needed yet.
            if self.solver.locate_contact && self.committed_lifted() {
                return false;
            }
            self.refresh_fast_path();
        }
        let law = self.model.law;
        let (ux_n, vx_n) = (self.state.u[0], self.state.v[0]);
        let fs = &self.fast;
        if fs.any_lifted {
            return false;
        }
        // Indexed over slices of one length, so that the compiler vectorizes the test.
        let n = fs.slip_m.len();
        let (x_m, slip_m, limit_m) = (&self.model.x_m[..n], &fs.slip_m[..n], &fs.limit_m[..n]);
        let (rate_m, follows_v) = (&fs.rate_m[..n], &fs.follows_v[..n]);
        for (u, h) in points {
            let c_prime = 2.0 * self.model.spring_dashpot_ns_per_m / h;
            let half_h = 0.5 * h;
            // Shared slip position and limit: κ N_i is monotonic in x_i (each rounded operation of
            // N_i = −k_y (u_y − θ x_i) is), so the outermost springs have its extremes, and their
            // test with a margin decides for every spring ([`SpringLaw::sticks_with_margin`]).
            // Otherwise, or within the margin, every spring's own test.
            //
            // [`SpringLaw::sticks_with_margin`]: crate::foundation::SpringLaw::sticks_with_margin
            let outer_stick = fs.same_slips && !fs.any_sliding && {
                let (s, limit) = (slip_m[0], limit_m[0]);
                let e_bar = ux_n - s + half_h * vx_n;
                let sticks = |x: f64| law.sticks_with_margin(s, limit, u[0], u[1] - u[2] * x, e_bar, c_prime);
                sticks(x_m[0]) & sticks(x_m[n - 1])
            };
            if !outer_stick {
                let mut fails = 0u32;
                if fs.any_sliding {
                    for i in 0..n {
                        let (x, s) = (x_m[i], slip_m[i]);
                        let e_bar = ux_n - s + half_h * (rate_m[i] + follows_v[i] * vx_n);
                        fails += u32::from(!law.sticks(s, limit_m[i], u[0], u[1] - u[2] * x, e_bar, c_prime));
                    }
                } else {
                    // Every rate is u̇_x,n: the same operations without the slices of the rates.
                    let shift = half_h * vx_n;
                    for i in 0..n {
                        let (x, s) = (x_m[i], slip_m[i]);
                        let e_bar = ux_n - s + shift;
                        fails += u32::from(!law.sticks(s, limit_m[i], u[0], u[1] - u[2] * x, e_bar, c_prime));
                    }
                }
                if fails != 0 {
                    return false;
                }
            }
        }
        true
    }

    /// f_S at the trial (`u`, `v`) of a step of length `h` if every spring is in contact and
    /// sticks there (module docs), recording the sums [`Self::sticking_tangent`] needs; `None`
    /// otherwise.
    #[inline]
    pub(super) fn sticking_force(&mut self, u: [f64; 3], v: [f64; 3], h: f64) -> Option<Vector3<f64>> {
        if !self.all_stick(u, h) {
            return None;
        }
        Some(self.stick_sums(u, v, h))
    }

    /// [`Self::sticking_force`] at a trial where every spring is known to stick
    /// ([`Self::all_stick`]): f_S, and the sums recorded.
    #[inline]
    pub(super) fn stick_sums(&mut self, u: [f64; 3], v: [f64; 3], h: f64) -> Vector3<f64> {
        let law = self.model.law;
        let c_prime = 2.0 * self.model.spring_dashpot_ns_per_m / h;
        let half_h = 0.5 * h;
        let (ux_n, vx_n) = (self.state.u[0], self.state.v[0]);
        let fs = &self.fast;
        let (a, b) = (-law.ky_n_per_m * u[1], law.ky_n_per_m * u[2]);
        let e_ref = u[0] - fs.s_ref_m;
        let sum_e = fs.n * e_ref - fs.sum_d;
        let sum_xe = e_ref * fs.sum_x - fs.sum_xd;
        let sum_n = fs.n * a + b * fs.sum_x;
        let sum_xn = a * fs.sum_x + b * fs.sum_x2;
        let dashpot = c_prime * (fs.n * (u[0] - ux_n) - half_h * (fs.sum_rate + fs.n_follow * vx_n));
        let shear_n = law.kappa_per_m * (a * sum_e + b * sum_xe) + dashpot;
        let (mut f1, mut f2) = (-sum_n, sum_xn);
        let cdy = self.model.spring_vertical_dashpot_ns_per_m;
        if cdy > 0.0 {
            f1 += cdy * (fs.n * v[1] - v[2] * fs.sum_x);
            f2 -= cdy * (v[1] * fs.sum_x - v[2] * fs.sum_x2);
        }
        self.fast.iterate = Some(StickIterate { sum_n, sum_xn, sum_e, sum_xe, shear_n, c_prime });
        self.stats.sticking_iterates += 1;
        Vector3::new(shear_n, f1, f2)
    }

    /// The Newmark step of length `h` to load `p` solved directly while every spring sticks
    /// (module docs, "The all-sticking step solved directly"): the vertical and rocking rows
    /// give (δ_y, δ_θ) affine in δ_x, the horizontal row is then a quadratic in δ_x, and its
    /// root (the one that tends to the linear solution as the quadratic term vanishes) is the
    /// step. It is accepted only if every spring sticks there (the fast path's own test) and the
    /// residual meets the Newton tolerance `tol`; `None` otherwise (the caller iterates).
    pub(super) fn direct_sticking_step(&mut self, h: f64, p: Vector3<f64>, tol: f64) -> Option<Converged> {
        if !self.fast.valid {
            self.refresh_fast_path();
        }
        let (beta, gamma) = (self.solver.beta, self.solver.gamma);
        let (c1, c2, c3) = (1.0 / (beta * h * h), 1.0 / (beta * h), 0.5 / beta - 1.0);
        // q̈ = a* + c1 δ and q̇ = v* + g δ (Newmark), so r(δ) = r0 − K_lin δ − f_S(δ) with
        // r0 = p − M a* − C v* and K_lin = c1 M + g C (C is diagonal).
        let g = gamma / (beta * h);
        let (un, vn, an) = (self.state.u, self.state.v, self.state.a);
        let m = self.model.mass;
        let cd = [self.model.damping[(0, 0)], self.model.damping[(1, 1)], self.model.damping[(2, 2)]];
        let a_star: [f64; 3] = std::array::from_fn(|i| -c2 * vn[i] - c3 * an[i]);
        let v_star: [f64; 3] = std::array::from_fn(|i| vn[i] + h * ((1.0 - gamma) * an[i] + gamma * a_star[i]));
        let ma = |acc: &[f64; 3], i: usize| m[(i, 0)] * acc[0] + m[(i, 1)] * acc[1] + m[(i, 2)] * acc[2];
        let r0: [f64; 3] = std::array::from_fn(|i| p[i] - ma(&a_star, i) - cd[i] * v_star[i]);
        let k_lin = |i: usize, j: usize| c1 * m[(i, j)] + if i == j { g * cd[i] } else { 0.0 };
        let law = self.model.law;
        let fs = &self.fast;
        let (ky, kappa) = (law.ky_n_per_m, law.kappa_per_m);
        let kk = kappa * ky;
        let cdy = self.model.spring_vertical_dashpot_ns_per_m;
        let c_prime = 2.0 * self.model.spring_dashpot_ns_per_m / h;
        let (n, sx, sx2) = (fs.n, fs.sum_x, fs.sum_x2);
        // N_i = a + b x_i and the sums of e_i = u_x − s_i at δ = 0.
        let (a0, b0) = (-ky * un[1], ky * un[2]);
        let e0 = un[0] - fs.s_ref_m;
        let (sum_e0, sum_xe0) = (n * e0 - fs.sum_d, e0 * sx - fs.sum_xd);
        // The vertical and rocking rows, linear in δ: A (δ_y, δ_θ) = b − K_lin[·, x] δ_x.
        let f1 = -(n * a0 + b0 * sx) + cdy * (n * v_star[1] - v_star[2] * sx);
        let f2 = (a0 * sx + b0 * sx2) - cdy * (v_star[1] * sx - v_star[2] * sx2);
        let kv = ky + cdy * g;
        let (a11, a12) = (k_lin(1, 1) + n * kv, k_lin(1, 2) - sx * kv);
        let (a21, a22) = (k_lin(2, 1) - sx * kv, k_lin(2, 2) + sx2 * kv);
        let det = a11 * a22 - a12 * a21;
        let (b1, b2) = (r0[1] - f1, r0[2] - f2);
        let (k10, k20) = (k_lin(1, 0), k_lin(2, 0));
        // (δ_y, δ_θ) = P + Q δ_x.
        let (p1, p2) = ((a22 * b1 - a12 * b2) / det, (a11 * b2 - a21 * b1) / det);
        let (q1, q2) = ((a12 * k20 - a22 * k10) / det, (a21 * k10 - a11 * k20) / det);
        // The horizontal row: κ (a Σe + b Σxe) + c' (n δ_x − (h/2) Σė_n) + K_lin[x, ·] δ = r0_x,
        // with a = a0 − k_y δ_y, b = b0 + k_y δ_θ, Σe = Σe0 + n δ_x, Σxe = Σxe0 + Σx δ_x: a
        // quadratic in δ_x once δ_y and δ_θ are put in.
        let l0 = k_lin(0, 0) + kappa * (n * a0 + b0 * sx) + c_prime * n;
        let l1 = k_lin(0, 1) - kk * sum_e0;
        let l2 = k_lin(0, 2) + kk * sum_xe0;
        let dashpot0 = -c_prime * 0.5 * h * (fs.sum_rate + fs.n_follow * vn[0]);
        let f0 = kappa * (a0 * sum_e0 + b0 * sum_xe0) + dashpot0 - r0[0];
        let qa = kk * (sx * q2 - n * q1);
        let qb = l0 + l1 * q1 + l2 * q2 + kk * (sx * p2 - n * p1);
        let qc = l1 * p1 + l2 * p2 + f0;
        let disc = qb * qb - 4.0 * qa * qc;
        if !(disc >= 0.0 && qb != 0.0 && det != 0.0) {
            return None;
        }
        // The root that tends to −qc/qb as qa vanishes, without cancellation.
        let dx = -2.0 * qc / (qb + qb.signum() * disc.sqrt());
        let delta = [dx, p1 + q1 * dx, p2 + q2 * dx];
        let u: [f64; 3] = std::array::from_fn(|i| un[i] + delta[i]);
        let v: [f64; 3] = std::array::from_fn(|i| v_star[i] + g * delta[i]);
        let a: [f64; 3] = std::array::from_fn(|i| a_star[i] + c1 * delta[i]);
        // Every spring must stick there (the fast path's own test), and the residual meet the
        // Newton tolerance (it is at rounding level: a check, not an iteration).
        let f = self.sticking_force(u, v, h)?;
        let r: [f64; 3] = std::array::from_fn(|i| p[i] - ma(&a, i) - cd[i] * v[i] - f[i]);
        let norm = r[0].abs().max(r[1].abs()).max(r[2].abs() / self.model.width_m);
        (norm <= tol).then_some(Converged { u, v, a, iterations: 1, residual: norm })
    }

    /// The tangent ∂f_S/∂q of an all-sticking iterate (module docs).
    #[inline]
    pub(super) fn sticking_tangent(&self, it: StickIterate, h: f64) -> Matrix3<f64> {
        let fs = &self.fast;
        let law = self.model.law;
        let cdy = self.model.spring_vertical_dashpot_ns_per_m;
        let kd = if cdy > 0.0 { cdy * (self.solver.gamma / (self.solver.beta * h)) } else { 0.0 };
        let kk = law.ky_n_per_m + kd;
        let kxy = law.kappa_per_m * law.ky_n_per_m;
        let k00 = law.kappa_per_m * it.sum_n + fs.n * it.c_prime;
        let (k01, k02) = (-kxy * it.sum_e, kxy * it.sum_xe);
        let (k11, k12, k22) = (fs.n * kk, -kk * fs.sum_x, kk * fs.sum_x2);
        Matrix3::new(k00, k01, k02, 0.0, k11, k12, 0.0, k12, k22)
    }

    /// The base reaction of a committed all-sticking step, in closed form (module docs); `None`
    /// if the committed step was not all-sticking.
    pub(super) fn sticking_reaction(&self) -> Option<Reaction> {
        let it = self.fast.committed?;
        let v = self.state.v;
        let cdy = self.model.spring_vertical_dashpot_ns_per_m;
        let fs = &self.fast;
        let springs = self.model.x_m.len();
        let mut dashpot_moment_nm = 0.0;
        if cdy > 0.0 {
            dashpot_moment_nm = -cdy * (v[1] * fs.sum_x - v[2] * fs.sum_x2);
        }
        let dashpot_horizontal_n = self.model.damping[(0, 0)] * v[0];
        Some(Reaction {
            horizontal_n: it.shear_n + dashpot_horizontal_n,
            normal_n: it.sum_n,
            moment_nm: it.sum_xn,
            sliding_springs: 0,
            contact_springs: springs,
            dashpot_horizontal_n,
            dashpot_moment_nm: dashpot_moment_nm + self.model.damping[(2, 2)] * v[2],
        })
    }

    /// The sums of the committed slip positions (refreshed if out of date): n, Σx_i, s_1, Σd_i
    /// and Σx_i d_i (module docs), for the exact all-sticking step (`exact`).
    pub(super) fn slip_sums(&mut self) -> [f64; 5] {
        if !self.fast.valid {
            self.refresh_fast_path();
        }
        let fs = &self.fast;
        [fs.n, fs.sum_x, fs.s_ref_m, fs.sum_d, fs.sum_xd]
    }

    /// [`Self::slip_sums`] over the springs lo..hi only, s_1 the slip position of spring lo: a
    /// partial contact set's (`exact`, "Partial contact").
    pub(super) fn set_slip_sums(&mut self, lo: usize, hi: usize) -> [f64; 5] {
        if !self.fast.valid {
            self.refresh_fast_path();
        }
        let (x_m, slip_m) = (&self.model.x_m[lo..hi], &self.fast.slip_m[lo..hi]);
        let s_ref_m = slip_m[0];
        let (mut n, mut sum_x, mut sum_d, mut sum_xd) = (0.0, 0.0, 0.0, 0.0);
        for (&x, &s) in x_m.iter().zip(slip_m) {
            let d = s - s_ref_m;
            n += 1.0;
            sum_x += x;
            sum_d += d;
            sum_xd += x * d;
        }
        [n, sum_x, s_ref_m, sum_d, sum_xd]
    }

    /// Whether the springs lo..hi, none of them slipping at the committed state, are in contact
    /// and stick at the trial displacement `u` of a step of length `h`: the spring law's own test
    /// of each ([`Self::all_stick`]'s for a partial contact set, `exact`). The committed slip
    /// positions must be up to date ([`Self::set_slip_sums`] makes them so).
    pub(super) fn set_sticks(&self, lo: usize, hi: usize, u: [f64; 3], h: f64) -> bool {
        debug_assert!(self.fast.valid, "set_slip_sums first");
        let law = self.model.law;
        let c_prime = 2.0 * self.model.spring_dashpot_ns_per_m / h;
        let (ux_n, shift) = (self.state.u[0], 0.5 * h * self.state.v[0]);
        let fs = &self.fast;
        let (x_m, slip_m, limit_m) = (&self.model.x_m[lo..hi], &fs.slip_m[lo..hi], &fs.limit_m[lo..hi]);
        let mut fails = 0u32;
        for ((&x, &s), &limit) in x_m.iter().zip(slip_m).zip(limit_m) {
            let e_bar = ux_n - s + shift;
            fails += u32::from(!law.sticks(s, limit, u[0], u[1] - u[2] * x, e_bar, c_prime));
        }
        fails == 0
    }

    /// Whether a spring was slipping at the committed state.
    #[inline]
    pub(super) fn committed_sliding(&self) -> bool {
        if self.fast.valid {
            self.fast.any_sliding
        } else {
            self.state.springs.iter().any(|s| s.sliding)
        }
    }

    /// Recompute the sums and slices of the committed slip positions, in one pass (each sum's
    /// terms in the springs' order).
    fn refresh_fast_path(&mut self) {
        self.fast.any_lifted = self.solver.locate_contact && self.committed_lifted();
        let law = self.model.law;
        let fs = &mut self.fast;
        let springs = &self.state.springs[..];
        let n = springs.len();
        let x_m = &self.model.x_m[..n];
        let (slip_m, limit_m) = (&mut fs.slip_m[..n], &mut fs.limit_m[..n]);
        let (rate_m, follows_v) = (&mut fs.rate_m[..n], &mut fs.follows_v[..n]);
        let s_ref_m = springs.first().map_or(0.0, |c| c.slip_m);
        let (mut sum_d, mut sum_xd, mut sum_rate, mut n_follow) = (0.0, 0.0, 0.0, 0.0);
        let (mut any_sliding, mut same_slips) = (false, true);
        for i in 0..n {
            let (c, x) = (springs[i], x_m[i]);
            let (rate, follows) = if c.sliding { (c.rate_m_per_s, 0.0) } else { (0.0, 1.0) };
            (rate_m[i], follows_v[i]) = (rate, follows);
            sum_rate += rate;
            n_follow += follows;
            let d = c.slip_m - s_ref_m;
            sum_d += d;
            sum_xd += x * d;
            slip_m[i] = c.slip_m;
            limit_m[i] = law.limit_m(c);
            any_sliding |= c.sliding;
            same_slips &= c.slip_m == s_ref_m;
        }
        (fs.s_ref_m, fs.sum_d, fs.sum_xd, fs.sum_rate, fs.n_follow) = (s_ref_m, sum_d, sum_xd, sum_rate, n_follow);
        fs.any_sliding = any_sliding;
        fs.same_slips = same_slips && fs.ascending;
        fs.valid = true;
    }

    /// Whether the last iterate took the fast path from a committed state where no spring was
    /// slipping: a step that can be committed by [`Self::commit_sticking`].
    #[inline]
    pub(super) fn sticking_commit_possible(&self) -> bool {
        self.fast.iterate.is_some() && !self.fast.any_sliding
    }

    /// Commit the spring states of an all-sticking step of length `h` that started at
    /// u_x,n = `ux_prev_m`, u̇_x,n = `vx_prev_m_per_s`, from a state where no spring was slipping
    /// ([`Self::sticking_commit_possible`]): every spring keeps its slip position and sticks. Its
    /// per-spring responses are built later, when asked for ([`Self::fill_sticking_responses`]).
    #[inline]
    pub(super) fn commit_sticking(&mut self, h: f64, ux_prev_m: f64, vx_prev_m_per_s: f64) {
        let fs = &mut self.fast;
        debug_assert!(!fs.any_sliding);
        fs.committed = fs.iterate;
        fs.pending = Some(PendingResponses { h, ux_prev_m, vx_prev_m_per_s });
    }

    /// The springs' responses of the committed step for an observer: empty if they are not
    /// built (an observer that does not read them, [`super::Observer::reads_springs`]).
    #[inline]
    pub(super) fn step_springs(&self) -> &[super::SpringResponse] {
        if self.fast.pending.is_some() {
            &[]
        } else {
            &self.trial
        }
    }

    /// Build the springs' responses (`self.trial`) of the committed all-sticking step, if they
    /// are not built yet: the spring law's `sticking` branch at the committed displacements, the
    /// numbers the general path would have left.
    pub(super) fn fill_sticking_responses(&mut self) {
        let Some(p) = self.fast.pending.take() else { return };
        let law = self.model.law;
        let c_prime = 2.0 * self.model.spring_dashpot_ns_per_m / p.h;
        let u = self.state.u;
        for ((&x, c), out) in self.model.x_m.iter().zip(&self.state.springs).zip(self.trial.iter_mut()) {
            let e_bar = p.ux_prev_m - c.slip_m + 0.5 * p.h * p.vx_prev_m_per_s;
            *out = law.sticking_response(*c, u[0], u[1] - u[2] * x, e_bar, c_prime);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::super::tests::simulation;
    use super::super::{Observer, StepView};
    use super::*;
    use crate::foundation::{DampingMode, SpringState, VerticalDamping};
    use crate::loads::pulse::TrianglePulse;
    use crate::loads::WaveForce;

    const MODES: [(DampingMode, VerticalDamping); 4] = [
        (DampingMode::Total, VerticalDamping::Seed),
        (DampingMode::Total, VerticalDamping::Springs),
        (DampingMode::Elastic, VerticalDamping::Seed),
        (DampingMode::Elastic, VerticalDamping::Springs),
    ];

    /// A committed state with the springs at assorted slip positions (every third one slipping
    /// at the last step, i.e. with the limit e_d) and a trial where every spring stays in contact
    /// (the caisson rotated) and sticks, unless `e_first` moves the first spring's elastic
    /// displacement (in units of e_s) or `lift` lifts the seaward edge.
    fn sticking_trial(sim: &mut Simulation, e_first: f64, lift: bool) -> ([f64; 3], [f64; 3], f64) {
        let law = sim.model.law;
        let settle = sim.model.static_settlement_m();
        sim.state.u = [2e-4, -settle, 0.0];
        for (i, s) in sim.state.springs.iter_mut().enumerate() {
            let e = law.stick_limit_m * [e_first, -0.4, 0.5, -0.2, 0.1, 0.6, -0.3, 0.45, -0.5, 0.2][i];
            *s = SpringState { slip_m: sim.state.u[0] - e, sliding: i % 3 == 0, rate_m_per_s: 0.0 };
        }
        sim.fast.invalidate();
        let theta = settle / (0.5 * sim.model.width_m) * if lift { 1.2 } else { 0.3 };
        ([2e-4 + 1e-3 * law.stick_limit_m, -settle - 1e-7, theta], [0.01, -0.002, 0.03], 1e-4)
    }

    /// The closed forms against the sums spring by spring: force and tangent to rounding, for
    /// both horizontal and both vertical dashpot placements. The oracle is the general path.
    #[test]
    fn closed_forms_equal_the_sums_over_the_springs() {
        let mut checked = 0;
        for (mode, vertical) in MODES {
            let mut sim = simulation(mode, vertical);
            let (u, v, h) = sticking_trial(&mut sim, 0.3, false);
            let fast = sim.sticking_force(u, v, h).expect("every spring sticks");
            let k_fast = sim.tangent(h);
            let general = sim.general_force(u, v, h);
            let k_general = sim.tangent(h);
            let sticking = sim.trial.iter().filter(|r| r.normal_n > 0.0 && !r.state.sliding).count();
            assert_eq!(sticking, 10, "{mode:?}/{vertical:?}: the general path finds every spring sticking");
            // Rounding of sums of ten terms of the size of W' (8240 N) and of the stiffness.
            let w = sim.model.weight_n;
            let b = sim.model.width_m;
            for (r, tol) in [(0, 1e-12 * w), (1, 1e-12 * w), (2, 1e-12 * w * b)] {
                assert!(
                    (fast[r] - general[r]).abs() <= tol,
                    "{mode:?}/{vertical:?} f_{r}: {} against {}",
                    fast[r],
                    general[r]
                );
                checked += 1;
            }
            let scale = k_general.abs().max();
            for r in 0..3 {
                for c in 0..3 {
                    let (a, g) = (k_fast[(r, c)], k_general[(r, c)]);
                    assert!((a - g).abs() <= 1e-12 * scale, "{mode:?}/{vertical:?} K_{r}{c}: {a} against {g}");
                    checked += 1;
                }
            }
        }
        assert_eq!(checked, 4 * 12);
    }

    /// The all-sticking step solved directly against Newton's iteration on the same step (the
    /// oracle; the direct solve off), for both horizontal and both vertical dashpot placements,
    /// from committed states with equal slips at rest and with assorted slips (every third spring
    /// slipping at its last step), under a load that keeps every spring sticking; and declined
    /// under one that slips them. Newton stops with a residual of at most 1e-9 W' (8.2e-6 N);
    /// over a step of 1e-4 s the stiffness is at least M/(β h²) ≈ 4e11 N/m, so the two steps
    /// may differ by about 1e-17 m (measured: 2e-17 m of steps δ of about 1e-9 m): asserted
    /// within 1e-15 m (and 1e-15 rad), 1e-11 m/s and 1e-7 m/s² (the velocity and acceleration
    /// are δ times γ/(β h) = 2e4 /s and 1/(β h²) = 4e8 /s²).
    #[test]
    fn direct_step_is_the_newton_step() {
        let mut checked = 0;
        for (mode, vertical) in MODES {
            for assorted in [false, true] {
                let mut sim = simulation(mode, vertical);
                if assorted {
                    sticking_trial(&mut sim, 0.3, false);
                    sim.state.u[2] = 1e-6;
                }
                let w = sim.model.weight_n;
                let h = 1e-4;
                let p = Vector3::new(0.05 * w, -0.1 * w, 0.02 * w * sim.model.width_m) + sim.gravity;
                let tol = sim.solver.tolerance * w;
                sim.fast.invalidate();
                let direct = sim.direct_sticking_step(h, p, tol).expect("every spring sticks");
                assert!(direct.residual <= 1e-3 * tol, "{mode:?}/{vertical:?}: residual {}", direct.residual);
                sim.fast.direct = false;
                let newton = sim.try_step(h, p).expect("Newton converges");
                assert!(sim.fast.iterate.is_some(), "{mode:?}/{vertical:?}: Newton's step is all-sticking");
                for i in 0..3 {
                    let (du, dv, da) = (
                        (direct.u[i] - newton.u[i]).abs(),
                        (direct.v[i] - newton.v[i]).abs(),
                        (direct.a[i] - newton.a[i]).abs(),
                    );
                    assert!(
                        du <= 1e-15 && dv <= 1e-11 && da <= 1e-7,
                        "{mode:?}/{vertical:?} assorted {assorted} q_{i}: {du:e} m, {dv:e} m/s, {da:e} m/s² apart"
                    );
                    checked += 1;
                }
                // A push of 2 W' held over 0.05 s (beyond μ W' on the springs' stiffness) slips
                // them: the direct solve declines.
                let push = p + Vector3::new(2.0 * w, 0.0, 0.0);
                sim.fast.invalidate();
                assert!(sim.direct_sticking_step(0.05, push, tol).is_none(), "{mode:?}/{vertical:?}: a slip");
            }
        }
        assert_eq!(checked, 4 * 2 * 3);
    }

    /// One spring beyond its friction cap, or springs lifted: the fast path declines.
    #[test]
    fn fast_path_declines_a_slip_or_a_lift_off() {
        for (mode, vertical) in MODES {
            let mut sim = simulation(mode, vertical);
            // The first spring beyond the limit e_d (= e_s: μ_d = μ_s in the default profile).
            let (u, v, h) = sticking_trial(&mut sim, 1.01, false);
            assert!(sim.sticking_force(u, v, h).is_none(), "{mode:?}/{vertical:?}: a slip");
            assert!(sim.general_force(u, v, h) != Vector3::zeros() && sim.trial[0].state.sliding);
            let (u, v, h) = sticking_trial(&mut sim, 0.7, false);
            assert!(sim.sticking_force(u, v, h).is_some(), "{mode:?}/{vertical:?}: sticks");
            let (u, v, h) = sticking_trial(&mut sim, 0.3, true);
            assert!(sim.sticking_force(u, v, h).is_none(), "{mode:?}/{vertical:?}: a lift-off");
            sim.general_force(u, v, h);
            assert!(sim.trial[0].normal_n == 0.0, "the seaward spring is lifted");
        }
    }

    /// Records what an observer sees of every step.
    #[derive(Default)]
    struct Record(Vec<[f64; 9]>, usize);
    impl Observer for Record {
        fn observe(&mut self, s: &StepView<'_>) {
            let r = s.reaction;
            let (n, f): (f64, f64) =
                (s.springs.iter().map(|x| x.normal_n).sum(), s.springs.iter().map(|x| x.shear_n).sum());
            let springs = [s.springs[0].normal_n, s.springs[9].shear_n, n, f];
            let reaction = [r.horizontal_n, r.normal_n, r.moment_nm, r.dashpot_moment_nm, r.contact_springs as f64];
            let mut row = [0.0; 9];
            row[..5].copy_from_slice(&reaction);
            row[5..].copy_from_slice(&springs);
            self.0.push(row);
            self.1 += r.sliding_springs;
        }
    }

    /// What observers see (the base reaction, in closed form on an all-sticking step, and the
    /// springs' responses, built for the observer) and what `reaction` and `springs` give after
    /// the run: the same with the fast path on and off, within 1e-9 of the largest value (the
    /// closed forms agree to rounding, the direct all-sticking step with Newton's within its
    /// residual tolerance), through a pulse that makes the caisson slide and its seaward
    /// springs lift off and one that does neither.
    #[test]
    fn observers_see_the_same_steps() {
        let (mut runs, mut slid, mut lifted) = (0, 0, 0);
        for (mode, vertical) in MODES {
            for peak_n in [2e3, 15e3] {
                let load = TrianglePulse {
                    peak: WaveForce::from_levers(peak_n, 0.8, 3e3, 0.52, 0.78),
                    rise_s: 0.05,
                    start_s: 0.0,
                };
                let record = |on: bool| {
                    let mut sim = simulation(mode, vertical);
                    sim.solver.accel.sticking_fast_path = on;
                    let mut rec = Record::default();
                    sim.run_until(0.2, &load, &mut rec).unwrap();
                    let last =
                        (sim.reaction(), sim.springs().iter().map(|r| (r.normal_n, r.shear_n)).collect::<Vec<_>>());
                    (rec, last, sim.stats.sticking_iterates)
                };
                let ((old, old_last, old_fast), (new, new_last, new_fast)) = (record(false), record(true));
                assert_eq!((old.0.len(), old.1), (new.0.len(), new.1), "steps and sliding springs");
                assert!(old_fast == 0 && new_fast > 100, "{new_fast} all-sticking iterates");
                for j in 0..9 {
                    let scale = old.0.iter().fold(0.0f64, |m, r| m.max(r[j].abs()));
                    for (o, n) in old.0.iter().zip(&new.0) {
                        assert!(
                            (o[j] - n[j]).abs() <= 1e-9 * scale,
                            "{mode:?}/{vertical:?} {peak_n} N, column {j}: {} against {}",
                            n[j],
                            o[j]
                        );
                    }
                }
                let scale = sim_scale(&old_last.1);
                assert!((old_last.0.horizontal_n - new_last.0.horizontal_n).abs() <= 1e-9 * scale);
                for (o, n) in old_last.1.iter().zip(&new_last.1) {
                    assert!(
                        (o.0 - n.0).abs() <= 1e-9 * scale && (o.1 - n.1).abs() <= 1e-9 * scale,
                        "{o:?} against {n:?}"
                    );
                }
                slid += usize::from(old.1 > 0);
                lifted += usize::from(old.0.iter().any(|r| r[4] < 10.0));
                runs += 1;
            }
        }
        assert_eq!(runs, 8);
        assert!(slid >= 2 && lifted >= 2, "{slid} runs slid, {lifted} lifted");
    }

    proptest::proptest! {
        /// The outermost springs' test with the margin never says "all stick" when a spring
        /// between would not stick by its own test: springs sharing the slip position and the
        /// limit, trials about the friction cap (|e| from 0.5 to 1.5 e_s, either sign), the
        /// normal forces from uniform to nearly lifted at either edge, dashpot terms from none to
        /// larger than the cap, either sign. Also counts that the shortcut is taken at all.
        #[test]
        fn outermost_springs_decide_for_all(
            e_rel in -1.5f64..1.5, theta_rel in -0.99f64..0.99, dashpot_rel in -1.5f64..1.5, slip in -1e-2f64..1e-2,
        ) {
            let (w, b, n) = (8240.0, 0.78, 10);
            let law = crate::foundation::SpringLaw::new(1.5e8, 1.4e8, w, n, 0.6, 0.6);
            let x: Vec<f64> = (0..n).map(|i| -0.5 * b + (i as f64 + 0.5) * b / n as f64).collect();
            let uy = -w / 1.4e8;
            let theta = theta_rel * uy.abs() / (0.5 * b);
            let ux = slip + e_rel * law.stick_limit_m;
            // c_d/h (e − e_n) = dashpot_rel × the cap of a spring at the mean normal force.
            let c_over_h = 6e8;
            let e_prev = (ux - slip) - dashpot_rel * law.kappa_per_m * (w / n as f64) * law.stick_limit_m / c_over_h;
            let limit = law.stick_limit_m;
            let each = |xi: f64| law.sticks(slip, limit, ux, uy - theta * xi, e_prev, c_over_h);
            let outer = |xi: f64| law.sticks_with_margin(slip, limit, ux, uy - theta * xi, e_prev, c_over_h);
            if outer(x[0]) && outer(x[n - 1]) {
                for &xi in &x {
                    proptest::prop_assert!(each(xi), "x = {xi}: the outermost springs stick, this one does not");
                }
            }
        }
    }

    /// The margin of [`SpringLaw::sticks_with_margin`] is only a margin: away from the friction
    /// cap (by more than 1e-9 of it) it decides as [`SpringLaw::sticks`], with and without a
    /// dashpot term, on either side of the cap.
    ///
    /// [`SpringLaw::sticks_with_margin`]: crate::foundation::SpringLaw::sticks_with_margin
    /// [`SpringLaw::sticks`]: crate::foundation::SpringLaw::sticks
    #[test]
    fn the_margin_declines_only_at_the_cap() {
        let law = crate::foundation::SpringLaw::new(1.5e8, 1.4e8, 8240.0, 10, 0.6, 0.6);
        let (uy, limit) = (-8240.0 / 1.4e8, law.stick_limit_m);
        let (mut checked, mut sticking) = (0, 0);
        for (c_over_h, de) in [(0.0, 0.0), (6e8, 1e-3 * limit), (6e8, -1e-3 * limit)] {
            for k in -200..=200 {
                // e from −1.5 to 1.5 e_s; the trial force is κ N e + c_d/h de.
                let e = limit * 0.0075 * k as f64;
                let f = law.kappa_per_m * (-law.ky_n_per_m * uy) * e + c_over_h * de;
                let cap = law.kappa_per_m * (-law.ky_n_per_m * uy) * limit;
                if (f.abs() - cap).abs() <= 1e-9 * cap {
                    continue;
                }
                let each = law.sticks(0.0, limit, e, uy, e - de, c_over_h);
                let outer = law.sticks_with_margin(0.0, limit, e, uy, e - de, c_over_h);
                assert_eq!(each, outer, "e = {e}, dashpot term {}", c_over_h * de);
                checked += 1;
                sticking += usize::from(each);
            }
        }
        assert!(checked > 1100 && sticking > 500 && sticking < checked - 200, "{sticking} of {checked} sticking");
    }

    /// An observer that does not read the springs' responses.
    #[derive(Default)]
    struct Blind {
        steps: usize,
        without_springs: usize,
    }
    impl Observer for Blind {
        fn observe(&mut self, s: &StepView<'_>) {
            self.steps += 1;
            if s.springs.is_empty() {
                // Only an all-sticking step goes without them; its reaction is still there.
                self.without_springs += 1;
                assert!(s.reaction.contact_springs == 10 && s.reaction.sliding_springs == 0);
                assert!(s.reaction.normal_n > 0.0);
            } else {
                assert_eq!(s.springs.len(), 10);
            }
        }
        fn reads_springs(&self) -> bool {
            false
        }
    }

    /// `Observer::reads_springs() == false`: the all-sticking steps come without the springs'
    /// responses (and only they), the others with them, the run's results and its final
    /// responses are those of an observer that reads them, to the last bit.
    #[test]
    fn observers_may_go_without_the_springs() {
        let load =
            TrianglePulse { peak: WaveForce::from_levers(15e3, 0.8, 3e3, 0.52, 0.78), rise_s: 0.05, start_s: 0.0 };
        let mut blind_sim = simulation(DampingMode::Elastic, VerticalDamping::Springs);
        let mut blind = Blind::default();
        blind_sim.run_until(0.2, &load, &mut blind).unwrap();
        let mut sim = simulation(DampingMode::Elastic, VerticalDamping::Springs);
        let mut rec = Record::default();
        sim.run_until(0.2, &load, &mut rec).unwrap();
        assert!(
            blind.without_springs > 100 && blind.without_springs < blind.steps,
            "{} of {}",
            blind.without_springs,
            blind.steps
        );
        assert_eq!(blind.steps, rec.0.len());
        assert_eq!((blind_sim.state(), blind_sim.springs()), (sim.state(), sim.springs()));
    }

    fn sim_scale(springs: &[(f64, f64)]) -> f64 {
        springs.iter().fold(0.0f64, |m, r| m.max(r.0.abs()).max(r.1.abs()))
    }
}
