//! The interface spring: no-tension vertical spring plus elastic-Coulomb horizontal friction
//! (seed Eqs. 27-28, read as its Fig. 4: docs/model.md §10 item 12).
//!
//! With u_y,i the spring's vertical displacement (negative = compression) and u_x its
//! horizontal displacement:
//!
//! ```text
//! N_i   = max(0, −k_y,i u_y,i)                       normal force, compression positive (Eq. 27)
//! k_x,i = k̄_x,i N_i / N̄_i = κ N_i,   κ = K_x / W'    shear stiffness ∝ current normal force
//! F_i   = κ N_i (u_x − s_i)                          while sticking, |u_x − s_i| ≤ e_s
//! F_i   = ± κ N_i e_d = ± μ_d N_i                    while slipping (s_i follows u_x)
//! e_s   = μ_s N̄_i / k̄_x,i = μ_s W'/K_x  (= the seed's ū_x),   e_d = μ_d W'/K_x
//! ```
//!
//! Because the stiffness is proportional to N, the stick/slip test |F| ≤ μ N reduces to a test
//! on the elastic displacement e = u_x − s alone. A sticking spring (committed state) may reach
//! e_s before it slips; once slipping, its capacity is μ_d N until the slip stops (the elastic
//! trial falls back within e_d), when it sticks again with capacity μ_s N. A lifted spring
//! (N = 0) carries nothing and re-contacts with zero shear (s_i = u_x).
//!
//! **Dashpot with the spring (`damping_mode = "elastic"`, docs/model.md §10 item 30)**: the
//! horizontal dashpot c_d acts in parallel with the elastic spring and both in series with the
//! slider (a Kelvin element on a friction slider), F = κ N e + c_d ė. Over a step of length h the
//! elastic rate follows the trapezoidal rule, ė_{n+1} = 2 (e − e_n)/h − ė_n (second order, as
//! Newmark's average acceleration), so that with c' = 2 c_d/h and ē_n = e_n + (h/2) ė_n:
//!
//! ```text
//! stick:  F = κ N e + c' (e − ē_n),  e = u_x − s_n,  while |F| ≤ μ N (μ_s, or μ_d if slipping)
//! slip:   F = ± μ_d N,  e = (F + c' ē_n) / (κ N + c'),  s = u_x − e,  ė = 2 (e − ē_n)/h
//! ```
//!
//! The caller passes ē_n and c' ([`SpringLaw::trial_with_dashpot`]); the committed rate ė_n is
//! [`SpringState::rate_m_per_s`] for a spring that was slipping, and the caisson's horizontal
//! velocity u̇_x,n for one that stuck (its slider does not move, so ė = u̇_x) or was lifted (it
//! re-contacts sticking). Friction caps the whole force the foundation transmits, dashpot
//! included. With c_d = 0 this is the law above.
//!
//! **Re-contact** ([`SpringLaw::trial_recontact`], docs/model.md §9.1): a spring lifted at the
//! start of a step (its slip position following u_x) and in contact at its end touches where its
//! vertical displacement, linear in the step, crosses 0, at the fraction λ of the step; its slip
//! position is the caisson's u_x there, s_c = u_x,n + λ (u_x − u_x,n), so that only the step's
//! part after the touch-down loads it, e = (1 − λ)(u_x − u_x,n). The dashpot beside it follows the
//! trapezoidal rule over that part, from e = 0 at the rate u̇_x,n.
//!
//! Trial → commit → revert: [`SpringLaw::trial`] computes the response from the committed
//! [`SpringState`] without changing it; committing is copying [`SpringResponse::state`].

/// Committed state of one spring: the slip position and whether it was slipping.
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
pub struct SpringState {
    /// s_i, plastic (slip) position, m.
    pub slip_m: f64,
    /// The spring was slipping at the end of the last committed step.
    pub sliding: bool,
    /// ė, the rate of the elastic displacement e = u_x − s of a spring that was slipping at the
    /// end of the last committed step, m/s (module docs); 0 otherwise (the rate of a sticking or
    /// lifted spring is the caisson's horizontal velocity) and without a dashpot beside the spring.
    pub rate_m_per_s: f64,
}

/// Constitutive constants shared by all springs of a foundation.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpringLaw {
    /// k_y,i, N/m.
    pub ky_n_per_m: f64,
    /// κ = k̄_x,i / N̄_i, 1/m.
    pub kappa_per_m: f64,
    /// e_s = μ_s N̄/k̄, m.
    pub stick_limit_m: f64,
    /// e_d = μ_d N̄/k̄, m.
    pub slip_offset_m: f64,
}

/// Response of a spring to a trial displacement.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SpringResponse {
    /// N_i, normal force, N, compression positive.
    pub normal_n: f64,
    /// F_i, shear force resisting u_x, N (positive when it pushes the caisson seaward).
    pub shear_n: f64,
    /// ∂F/∂u_x, N/m.
    pub dshear_dux: f64,
    /// ∂F/∂u_y,i, N/m.
    pub dshear_duy: f64,
    /// ∂N/∂u_y,i, N/m (−k_y in contact, 0 when lifted).
    pub dnormal_duy: f64,
    /// ∂s/∂u_x (0 sticking, 1 slipping or lifted).
    pub dslip_dux: f64,
    /// The trial state (commit by copying it).
    pub state: SpringState,
}

/// The elastic displacement of a slipping spring (κN = `kn`, signed offset `g` = ±e_d) at the
/// step's end: (κ N g + c' ē_n)/(κ N + c') with the dashpot beside it (c' = `c_over_h`, ē_n =
/// `e_prev_m`), g itself without.
#[inline(always)]
fn slip_elastic_m(kn: f64, g: f64, e_prev_m: f64, c_over_h: f64) -> f64 {
    if c_over_h > 0.0 {
        (kn * g + c_over_h * e_prev_m) / (kn + c_over_h)
    } else {
        g
    }
}

impl SpringLaw {
    /// Build from totals: `kx`, `ky` (N/m), weight in water `w` (N), `n` springs, μ_s, μ_d.
    pub fn new(kx_total: f64, ky_total: f64, w_n: f64, n: usize, mu_s: f64, mu_d: f64) -> Self {
        let kbar = kx_total / n as f64;
        let nbar = w_n / n as f64;
        SpringLaw {
            ky_n_per_m: ky_total / n as f64,
            kappa_per_m: kbar / nbar,
            stick_limit_m: mu_s * nbar / kbar,
            slip_offset_m: mu_d * nbar / kbar,
        }
    }

    /// Response to the trial displacements (`ux`, `uy`) from the committed state `c`.
    #[inline]
    pub fn trial(&self, c: SpringState, ux: f64, uy: f64) -> SpringResponse {
        self.trial_with_dashpot(c, ux, uy, 0.0, 0.0)
    }

    /// As [`Self::trial`] with a dashpot beside the elastic spring: `c_over_h` = c' = 2 c_d/h
    /// (N/m) and `e_prev_m` = ē_n = e_n + (h/2) ė_n (module docs). The trial state's
    /// [`SpringState::rate_m_per_s`] is left 0: the caller, who knows h, sets it on a slip.
    #[inline]
    pub fn trial_with_dashpot(&self, c: SpringState, ux: f64, uy: f64, e_prev_m: f64, c_over_h: f64) -> SpringResponse {
        if uy >= 0.0 {
            return SpringResponse {
                dslip_dux: 1.0,
                state: SpringState { slip_m: ux, sliding: false, rate_m_per_s: 0.0 },
                ..SpringResponse::default()
            };
        }
        let (n, kn, e, f_trial, sticks) = self.elastic_trial(c.slip_m, self.limit_m(c), ux, uy, e_prev_m, c_over_h);
        let dn = -self.ky_n_per_m;
        if sticks {
            self.stick_response(c, n, kn, e, f_trial, c_over_h)
        } else {
            let g = self.slip_offset_m.copysign(f_trial);
            let e_slip = slip_elastic_m(kn, g, e_prev_m, c_over_h);
            SpringResponse {
                normal_n: n,
                shear_n: kn * g,
                dshear_dux: 0.0,
                dshear_duy: self.kappa_per_m * g * dn,
                dnormal_duy: dn,
                dslip_dux: 1.0,
                state: SpringState { slip_m: ux - e_slip, sliding: true, rate_m_per_s: 0.0 },
            }
        }
    }

    /// As [`Self::trial_with_dashpot`] for a spring lifted at the step's start (its local vertical
    /// displacement `uy_n_m` ≥ 0, its slip position the caisson's u_x,n = `ux_n_m`) and in contact
    /// at the trial (`uy` < 0), over a step whose dashpot term is c' = `c_over_h` = 2 c_d/h
    /// (module docs, "Re-contact"). It touches where u_y,i, linear in the step, crosses 0, at the
    /// fraction λ = u_y,n/(u_y,n − u_y) of the step, with its slip position the caisson's u_x
    /// there, s_c = u_x,n + λ (u_x − u_x,n), and its elastic displacement e = u_x − s_c
    /// = ρ (u_x − u_x,n) (ρ = 1 − λ) grows over the rest of the step, ρ h, from 0 at the rate
    /// u̇_x,n: the trapezoidal rule over ρ h, c'/ρ and ē = ρ `shift_m` (`shift_m` = (h/2) u̇_x,n).
    /// Sticking, its force is κ N ρ (u_x − u_x,n) + c' (u_x − u_x,n − `shift_m`), the dashpot's
    /// term that of a spring in contact throughout; the tangent takes λ's dependence on u_x and
    /// u_y. Returns the response, the ē used and ρ (a slipping spring's rate is 2 (e − ē)/(ρ h)).
    #[inline]
    pub fn trial_recontact(
        &self,
        ux_n_m: f64,
        uy_n_m: f64,
        ux: f64,
        uy: f64,
        shift_m: f64,
        c_over_h: f64,
    ) -> (SpringResponse, f64, f64) {
        let gap = uy_n_m - uy;
        let (lambda, rho) = (uy_n_m / gap, -uy / gap);
        let du = ux - ux_n_m;
        let slip_m = ux_n_m + lambda * du;
        // ρ ≥ 1e-9 in the dashpot's terms: no overflow when the spring touches at the step's end.
        let rho_d = rho.max(1e-9);
        let e_bar = rho_d * shift_m;
        let c = SpringState { slip_m, sliding: false, rate_m_per_s: 0.0 };
        let mut r = self.trial_with_dashpot(c, ux, uy, e_bar, c_over_h / rho_d);
        if !r.state.sliding {
            // e = ρ (u_x − u_x,n): ∂e/∂u_x = ρ, ∂e/∂u_y = −(u_x − u_x,n) u_y,n/gap²; the
            // dashpot's term c' (u_x − u_x,n − shift) (to rounding).
            let kn = self.kappa_per_m * r.normal_n;
            r.dshear_dux = kn * rho + c_over_h;
            r.dshear_duy -= kn * du * uy_n_m / (gap * gap);
            r.dslip_dux = lambda;
        }
        (r, e_bar, rho_d)
    }

    /// The elastic displacement a spring in state `c` may reach and still stick: e_d if it was
    /// slipping, else e_s (module docs).
    #[inline(always)]
    pub fn limit_m(&self, c: SpringState) -> f64 {
        if c.sliding {
            self.slip_offset_m
        } else {
            self.stick_limit_m
        }
    }

    /// Whether a spring with slip position `slip_m` and limit `limit_m` ([`Self::limit_m`] of its
    /// committed state) is in contact with a positive normal force and sticks at the trial
    /// (`ux`, `uy`): the `sticking` branch of [`Self::trial_with_dashpot`], decided by the same
    /// operations, so exactly when that branch would be taken with N_i > 0. Branch-free.
    #[inline(always)]
    pub fn sticks(&self, slip_m: f64, limit_m: f64, ux: f64, uy: f64, e_prev_m: f64, c_over_h: f64) -> bool {
        let (n, _, _, _, sticks) = self.elastic_trial(slip_m, limit_m, ux, uy, e_prev_m, c_over_h);
        (uy < 0.0) & (n > 0.0) & sticks
    }

    /// [`Self::sticks`] with a margin: the trial force is within the friction cap by more than
    /// 1e-12 of κ N_i (|e| + `limit_m`) + |c' (e − ē_n)|, far more than the rounding of the
    /// trial (a few units in the last place of these terms). For springs that share the slip
    /// position and the limit, and so e and the dashpot term, the test of the two with the
    /// smallest and the largest κ N_i then implies [`Self::sticks`] of every spring between: in
    /// exact arithmetic |κN e + C| − κN L plus the margin is convex in κN (a ≤ 0 at both ends is
    /// ≤ 0 between), and the margin covers the rounding of each spring's own test.
    #[inline(always)]
    pub fn sticks_with_margin(
        &self,
        slip_m: f64,
        limit_m: f64,
        ux: f64,
        uy: f64,
        e_prev_m: f64,
        c_over_h: f64,
    ) -> bool {
        let (n, kn, e, f_trial, _) = self.elastic_trial(slip_m, limit_m, ux, uy, e_prev_m, c_over_h);
        let margin = 1e-12 * (kn * (e.abs() + limit_m) + (c_over_h * (e - e_prev_m)).abs());
        (uy < 0.0) & (n > 0.0) & (f_trial.abs() + margin <= kn * limit_m)
    }

    /// The response of a spring in state `c` known to stick at the trial (`ux`, `uy`) with
    /// N_i > 0 ([`Self::sticks`]): the `sticking` branch of [`Self::trial_with_dashpot`], the
    /// same numbers to the last bit.
    #[inline(always)]
    pub fn sticking_response(&self, c: SpringState, ux: f64, uy: f64, e_prev_m: f64, c_over_h: f64) -> SpringResponse {
        let (n, kn, e, f_trial, _) = self.elastic_trial(c.slip_m, self.limit_m(c), ux, uy, e_prev_m, c_over_h);
        self.stick_response(c, n, kn, e, f_trial, c_over_h)
    }

    /// The normal force N_i (unclamped: negative when the spring would be in tension) and the
    /// friction margin κ N_i `limit_m` − |κ N_i e + c' (e − ē)| of a spring at slip position
    /// `slip_m` if it stuck at (`ux`, `uy`) (module docs): the two quantities whose sign changes
    /// are the spring's events (lift-off or re-contact, and the onset of slip).
    #[inline]
    pub fn stick_margin(&self, slip_m: f64, limit_m: f64, ux: f64, uy: f64, e_bar_m: f64, c_prime: f64) -> (f64, f64) {
        let (n, kn, _, f_trial, _) = self.elastic_trial(slip_m, limit_m, ux, uy, e_bar_m, c_prime);
        (n, kn * limit_m - f_trial.abs())
    }

    /// The slip position s a spring at slip position `slip_m` would reach at (`ux`, `uy`), with
    /// `uy` < 0, if it went on slipping in the direction of `sign` (the `slipping` branch of
    /// [`Self::trial_with_dashpot`] with its force ± μ_d N_i): u_x − e with
    /// e = (κ N_i e_d ± c' ē_n)/(κ N_i + c'), e_d itself without a dashpot. What the end of a slip
    /// is located by (docs/model.md §9.1, "Events").
    #[inline]
    pub fn slipping_position(&self, sign: f64, ux: f64, uy: f64, e_prev_m: f64, c_over_h: f64) -> f64 {
        let kn = self.kappa_per_m * (-self.ky_n_per_m * uy);
        ux - slip_elastic_m(kn, self.slip_offset_m.copysign(sign), e_prev_m, c_over_h)
    }

    /// The `sticking` branch's response from the elastic trial.
    #[inline(always)]
    fn stick_response(&self, c: SpringState, n: f64, kn: f64, e: f64, f_trial: f64, c_over_h: f64) -> SpringResponse {
        let dn = -self.ky_n_per_m;
        SpringResponse {
            normal_n: n,
            shear_n: f_trial,
            dshear_dux: kn + c_over_h,
            dshear_duy: self.kappa_per_m * e * dn,
            dnormal_duy: dn,
            dslip_dux: 0.0,
            state: SpringState { slip_m: c.slip_m, sliding: false, rate_m_per_s: 0.0 },
        }
    }

    /// The elastic trial of a spring with `uy` < 0 (module docs): N_i, κ N_i, e = u_x − s_i, the
    /// trial force κ N_i e + c' (e − ē_n) and whether it is within the friction cap
    /// κ N_i `limit_m`.
    #[inline(always)]
    fn elastic_trial(
        &self,
        slip_m: f64,
        limit_m: f64,
        ux: f64,
        uy: f64,
        e_prev_m: f64,
        c_over_h: f64,
    ) -> (f64, f64, f64, f64, bool) {
        let n = -self.ky_n_per_m * uy;
        let kn = self.kappa_per_m * n;
        let e = ux - slip_m;
        let f_trial = kn * e + c_over_h * (e - e_prev_m);
        (n, kn, e, f_trial, f_trial.abs() <= kn * limit_m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn law() -> SpringLaw {
        // Seed Table 6 scale: K_x 1.5e8, K_y 1.4e8 N/m, W' 8240 N, 10 springs, μ 0.6/0.4.
        SpringLaw::new(1.5e8, 1.4e8, 8240.0, 10, 0.6, 0.4)
    }

    #[test]
    fn friction_caps_are_mu_times_normal() {
        let l = law();
        let c = SpringState::default();
        let uy = -1e-5;
        let n = -l.ky_n_per_m * uy;
        // Just below the static limit: sticking with F = μ_s N (to rounding).
        let r = l.trial(c, 0.999999 * l.stick_limit_m, uy);
        assert!(!r.state.sliding && (r.shear_n / (0.6 * n) - 1.0).abs() < 1e-5);
        // Beyond: slipping at μ_d N, slip position moves.
        let r = l.trial(c, 2.0 * l.stick_limit_m, uy);
        assert!(r.state.sliding && (r.shear_n / (0.4 * n) - 1.0).abs() < 1e-12);
        assert!((r.state.slip_m - (2.0 * l.stick_limit_m - l.slip_offset_m)).abs() < 1e-15);
        // Lifted: nothing, and re-contact with zero shear.
        let r = l.trial(c, 1e-3, 1e-6);
        assert_eq!((r.normal_n, r.shear_n, r.state.slip_m), (0.0, 0.0, 1e-3));
        // No tension.
        assert_eq!(l.trial(c, 0.0, 1e-3).normal_n, 0.0);
    }

    #[test]
    fn sliding_spring_sticks_again_on_reversal() {
        let l = law();
        let c = SpringState { slip_m: 0.01, sliding: true, rate_m_per_s: 0.0 };
        // Trial elastic displacement smaller than e_d (reversal): sticks, slip position kept.
        let r = l.trial(c, 0.01 + 0.5 * l.slip_offset_m, -1e-5);
        assert!(!r.state.sliding && r.state.slip_m == 0.01);
    }

    /// Re-contact within the step (`trial_recontact`): a spring lifted at the start by
    /// u_y,n = 2e-6 m and pressed to u_y = −6e-6 m at the trial touches at λ = 2/8 = 0.25 of the
    /// step, so its slip position is u_x,n + 0.25 (u_x − u_x,n) and, sticking, its force
    /// κ N · 0.75 (u_x − u_x,n) plus the dashpot's c' (u_x − u_x,n − shift) (by hand); the
    /// tangent against central differences in u_x and u_y (each branch is smooth there:
    /// differences of 1e-12 m, tolerance 1e-5 of κ N + c'), with the dashpot and without.
    #[test]
    fn recontact_slips_where_the_spring_touches() {
        let l = law();
        let (ux_n, uy_n, ux, uy) = (1e-3, 2e-6, 1e-3 + 2e-7, -6e-6);
        let mut checked = 0;
        for (c_over_h, shift) in [(0.0, 0.0), (1.2e8, 3e-8)] {
            let (r, _, rho) = l.trial_recontact(ux_n, uy_n, ux, uy, shift, c_over_h);
            assert!(!r.state.sliding, "sticks");
            assert_eq!(rho, 0.75);
            assert!((r.state.slip_m - (ux_n + 0.25 * 2e-7)).abs() < 1e-18, "slip {}", r.state.slip_m);
            let n = -l.ky_n_per_m * uy;
            let by_hand = l.kappa_per_m * n * 0.75 * 2e-7 + c_over_h * (2e-7 - shift);
            assert!((r.shear_n - by_hand).abs() <= 1e-9 * by_hand.abs(), "{} against {by_hand}", r.shear_n);
            let d = 1e-12;
            let f = |ux: f64, uy: f64| l.trial_recontact(ux_n, uy_n, ux, uy, shift, c_over_h).0.shear_n;
            let fd_x = (f(ux + d, uy) - f(ux - d, uy)) / (2.0 * d);
            let fd_y = (f(ux, uy + d) - f(ux, uy - d)) / (2.0 * d);
            let scale = l.kappa_per_m * n + c_over_h;
            assert!((fd_x - r.dshear_dux).abs() <= 1e-5 * scale, "dF/dux {fd_x} against {}", r.dshear_dux);
            assert!((fd_y - r.dshear_duy).abs() <= 1e-5 * scale, "dF/duy {fd_y} against {}", r.dshear_duy);
            checked += 1;
        }
        assert_eq!(checked, 2);
    }

    /// `slipping_position` is the slip position of the `slipping` branch of the trial, with and
    /// without the dashpot, in both directions (to rounding).
    #[test]
    fn slipping_position_is_the_slip_branch() {
        let l = law();
        let mut checked = 0;
        for c_over_h in [0.0, 1.2e8] {
            for sign in [1.0, -1.0] {
                let c = SpringState { slip_m: 2e-3, sliding: true, rate_m_per_s: 0.0 };
                let (ux, uy, e_bar) = (2e-3 + sign * 3.0 * l.stick_limit_m, -1e-5, sign * 0.5 * l.slip_offset_m);
                let r = l.trial_with_dashpot(c, ux, uy, e_bar, c_over_h);
                assert!(r.state.sliding);
                let s = l.slipping_position(sign, ux, uy, e_bar, c_over_h);
                assert!((s - r.state.slip_m).abs() <= 1e-18, "{s} against {}", r.state.slip_m);
                checked += 1;
            }
        }
        assert_eq!(checked, 4);
    }

    proptest! {
        /// The tangent equals a central finite difference of the force, for every committed
        /// state, away from the kinks (points whose ±h neighbours are in another branch are
        /// skipped). h = 1e-6 of the stick limit. Each branch is linear in u_x and in u_y, so
        /// the FD truncation error is zero and the tolerance (1e-6 of the stiffness scale
        /// K_x/n = 1.5e7 N/m) only covers rounding; a wrong tangent term is off by > 1e6 N/m.
        #[test]
        fn tangent_matches_finite_difference(
            ex in -3.0f64..3.0, uy_rel in -2.0f64..0.5, slip in -1e-3f64..1e-3, sliding in any::<bool>()
        ) {
            let l = law();
            let c = SpringState { slip_m: slip, sliding, rate_m_per_s: 0.0 };
            let ux = slip + ex * l.stick_limit_m;
            let uy = uy_rel * 8240.0 / 10.0 / l.ky_n_per_m;
            let r = l.trial(c, ux, uy);
            let h = 1e-6 * l.stick_limit_m;
            let (px, mx) = (l.trial(c, ux + h, uy), l.trial(c, ux - h, uy));
            let (py, my) = (l.trial(c, ux, uy + h), l.trial(c, ux, uy - h));
            let same = |a: &SpringResponse| a.state.sliding == r.state.sliding && (a.normal_n > 0.0) == (r.normal_n > 0.0);
            prop_assume!(same(&px) && same(&mx) && same(&py) && same(&my));
            let scale = 1.5e7 * 1e-6;
            let fd_x = (px.shear_n - mx.shear_n) / (2.0 * h);
            let fd_y = (py.shear_n - my.shear_n) / (2.0 * h);
            let fd_n = (py.normal_n - my.normal_n) / (2.0 * h);
            prop_assert!((fd_x - r.dshear_dux).abs() <= scale, "dF/dux {} vs {}", fd_x, r.dshear_dux);
            prop_assert!((fd_y - r.dshear_duy).abs() <= scale, "dF/duy {} vs {}", fd_y, r.dshear_duy);
            prop_assert!((fd_n - r.dnormal_duy).abs() <= scale, "dN/duy {} vs {}", fd_n, r.dnormal_duy);
            let fd_s = (px.state.slip_m - mx.state.slip_m) / (2.0 * h);
            prop_assert!((fd_s - r.dslip_dux).abs() < 1e-5);
        }
    }
}
