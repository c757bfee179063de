//! Sainflou (1928) standing-wave (clapotis) pressures, simplified linear form (SPM/CEM, ACES),
//! on a composite caisson (docs/model.md §2). The seed (§4.1-4.2) takes the seaward force F_qs− and
//! the suction under the base from it.
//!
//! ```text
//! h0  = (π H²/L) coth(2πh/L)          rise of the clapotis mean level            (§2.1)
//! p_b = ρ_w g H / cosh(2πh/L)         dynamic pressure amplitude at the seabed
//! crest (net, z depth below still water, positive down):                        (§2.2)
//!   p1c = (ρ_w g h + p_b)(H + h0)/(h + H + h0)
//!   −(H+h0) ≤ z ≤ 0:  p_c = p1c (1 + z/(H + h0));     0 ≤ z ≤ h:  p_c = p1c + (p_b − p1c) z/h
//! trough (net):
//!   0 ≤ z ≤ H − h0:   p_t = −ρ_w g z
//!   H − h0 ≤ z ≤ h:   p_t = −[ρ_w g (H−h0) + (p_b − ρ_w g (H−h0)) (z − (H−h0))/(h − (H−h0))]
//! ```
//!
//! i.e. the actual trough pressure is linear from 0 at the trough surface z = H − h0 to
//! ρ_w g h − p_b at the seabed, minus the still-water hydrostatic pressure. (If H < h0 the trough
//! surface lies above still water; the same definition is used, and the net pressure is then
//! positive between the trough surface and still water.)
//!
//! Composite caisson (§2.4): the forces are the exact integrals of these polylines over the wetted
//! face, from the base z = h' up to z = −min(h_c, H + h0) (crest) or up to still water (trough;
//! above it the net trough pressure is zero; if h' < H − h0 only z ∈ [0, h'] is wetted by the
//! net pressure). Moments are about the base. The suction under the base is triangular, p_t(h') at
//! the seaward toe and zero at the heel: U_t = ½ p_t(h') B < 0, acting 2B/3 from the heel,
//! M_Ut = (2/3) B U_t about the heel.
//!
//! Depth h: the seed does not say whether h is the toe depth h_s or the depth d in front of the
//! wall (docs/model.md §10 item 21). The caller chooses; the default (scenario key
//! `sainflou_depth = "toe"`) is h = h_s, the depth Goda uses. With h = d < h' the seabed pressure
//! is held constant down the embedded part of the face (d < z ≤ h'); this is an assumption.
//!
//! Signs: the trough results are stored with their physical signs (seaward force < 0, suction
//! < 0). The time histories use their magnitudes as F_qs− (docs/model.md §10 item 16).

use super::profile::{at_points, force_of, moment_of, Profile};
use crate::G_M_PER_S2;
use std::f64::consts::PI;

/// Inputs (SI, per metre).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SainflouInput {
    /// Incident wave height H (full reflection), m.
    pub height_m: f64,
    /// Wavelength at depth h, m.
    pub wavelength_m: f64,
    /// h, depth in which the standing wave forms, m.
    pub depth_m: f64,
    /// h', depth of the caisson base, m.
    pub base_depth_m: f64,
    /// h_c, crest freeboard, m.
    pub crest_freeboard_m: f64,
    /// B, base width, m.
    pub width_m: f64,
    pub rho_w: f64,
}

/// Sainflou pressures, forces and moments on the composite caisson (per metre; signs physical).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SainflouResult {
    /// h0, rise of the clapotis mean level, m.
    pub h0_m: f64,
    /// p_b, pressure amplitude at the seabed, Pa.
    pub pb_pa: f64,
    /// Crest pressure at still water p1c, Pa.
    pub crest_swl_pressure_pa: f64,
    /// Crest (shoreward) force on the wetted face, N/m (> 0).
    pub crest_force_n_per_m: f64,
    /// Its moment about the base, N·m/m.
    pub crest_moment_base_nm_per_m: f64,
    /// Net trough pressure at the base depth p_t(h'), Pa (< 0).
    pub trough_base_pressure_pa: f64,
    /// Trough (seaward) force, N/m (< 0).
    pub trough_force_n_per_m: f64,
    /// Its moment about the base, N·m/m (< 0).
    pub trough_moment_base_nm_per_m: f64,
    /// Height of the trough resultant above the base, m.
    pub trough_lever_m: f64,
    /// Suction under the base U_t = ½ p_t(h') B, N/m (< 0).
    pub suction_uplift_n_per_m: f64,
    /// M_Ut = (2/3) B U_t about the heel, N·m/m.
    pub suction_moment_heel_nm_per_m: f64,
    /// Distance of the suction resultant from the heel, 2B/3, m.
    pub suction_from_heel_m: f64,
    #[serde(skip)]
    crest: Profile,
    #[serde(skip)]
    trough: Profile,
}

/// h0 (m) and p_b (Pa) of §2.1.
#[inline]
pub fn clapotis_quantities(height_m: f64, wavelength_m: f64, depth_m: f64, rho_w: f64) -> (f64, f64) {
    let kh = 2.0 * PI * depth_m / wavelength_m;
    let h0 = PI * height_m * height_m / wavelength_m / kh.tanh();
    let pb = rho_w * G_M_PER_S2 * height_m / kh.cosh();
    (h0, pb)
}

/// Sainflou on the composite caisson (module docs).
pub fn sainflou(i: &SainflouInput) -> SainflouResult {
    SainflouPeriod::new(i).at(i.height_m)
}

/// The part of Sainflou's pressures that does not depend on the height (tanh kh and cosh kh of
/// the depth and wavelength); [`SainflouPeriod::at`] finishes it for one height with the same
/// floating-point operations as [`sainflou`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SainflouPeriod {
    input: SainflouInput,
    tanh_kh: f64,
    cosh_kh: f64,
}

impl SainflouPeriod {
    /// Everything of `i` but its height (`height_m` is ignored).
    pub fn new(i: &SainflouInput) -> Self {
        let kh = 2.0 * PI * i.depth_m / i.wavelength_m;
        SainflouPeriod { input: *i, tanh_kh: kh.tanh(), cosh_kh: kh.cosh() }
    }

    /// Sainflou for the incident height `height_m`.
    pub fn at(&self, height_m: f64) -> SainflouResult {
        let i = &self.input;
        let (hw, h, hp) = (height_m, i.depth_m, i.base_depth_m);
        let gw = i.rho_w * G_M_PER_S2;
        let (h0, pb) = self.clapotis(hw);
        // Crest.
        let top = hw + h0;
        let p1c = (gw * h + pb) * top / (h + top);
        let crest_full = Profile::new(&[(-top, 0.0), (0.0, p1c), (h, pb)]);
        let crest = crest_full.clipped(-top.min(i.crest_freeboard_m), hp);
        let t = self.trough_of(hw, h0, pb);
        SainflouResult {
            h0_m: h0,
            pb_pa: pb,
            crest_swl_pressure_pa: p1c,
            crest_force_n_per_m: crest.force(),
            crest_moment_base_nm_per_m: crest.moment_about(hp),
            trough_base_pressure_pa: t.pt_base,
            trough_force_n_per_m: t.loads.force_n_per_m,
            trough_moment_base_nm_per_m: t.moment,
            trough_lever_m: t.loads.lever_m,
            suction_uplift_n_per_m: t.loads.suction_n_per_m,
            suction_moment_heel_nm_per_m: t.loads.suction_from_heel_m * t.loads.suction_n_per_m,
            suction_from_heel_m: t.loads.suction_from_heel_m,
            crest,
            trough: t.profile,
        }
    }

    /// The trough's loads of [`Self::at`] for the incident height `height_m`, bit for bit,
    /// without the crest (what a wave's load event takes from Sainflou).
    ///
    /// Where the trough's profile keeps its three points (finite, in order) and its clipped
    /// profile its every point, the clipped profile's points are taken on the stack, as
    /// [`Profile::clipped`] would take them, and integrated by the same functions (the same bits,
    /// without building the two profiles: the test `trough_alone_is_at_bit_for_bit`); otherwise
    /// through [`Profile`].
    pub fn trough(&self, height_m: f64) -> SainflouTrough {
        let (h0, pb) = self.clapotis(height_m);
        let hp = self.input.base_depth_m;
        let (full, top) = self.trough_points(height_m, h0, pb);
        let kept = full.iter().all(|&(z, p)| z.is_finite() && p.is_finite())
            && full[0].0 <= full[1].0
            && full[1].0 <= full[2].0;
        if !(kept && hp > top && top.is_finite() && hp.is_finite()) {
            return self.trough_of(height_m, h0, pb).loads;
        }
        let (p_top, pt_base) = (at_points(&full, top), at_points(&full, hp));
        if !(p_top.is_finite() && pt_base.is_finite()) {
            return self.trough_of(height_m, h0, pb).loads;
        }
        // `Profile::clipped(top, hp)`: every push kept (finite, in order, at most 5 points).
        let mut pts = [(0.0, 0.0); 5];
        pts[0] = (top, p_top);
        let mut n = 1;
        for &(z, p) in &full {
            if z > top && z < hp {
                pts[n] = (z, p);
                n += 1;
            }
        }
        pts[n] = (hp, pt_base);
        let pts = &pts[..n + 1];
        self.trough_loads(force_of(pts), moment_of(pts, hp), pt_base)
    }

    /// The trough's profile before clipping (three points: the clapotis' trough at the height
    /// `hw`) and the top it is clipped at.
    fn trough_points(&self, hw: f64, h0: f64, pb: f64) -> ([(f64, f64); 3], f64) {
        let i = &self.input;
        let h = i.depth_m;
        let gw = i.rho_w * G_M_PER_S2;
        let zt = hw - h0;
        if zt >= 0.0 {
            ([(0.0, 0.0), (zt, -gw * zt), (h, -pb)], 0.0)
        } else {
            let p0 = (gw * h - pb) * (-zt) / (h - zt);
            ([(zt, 0.0), (0.0, p0), (h, -pb)], zt.max(-i.crest_freeboard_m))
        }
    }

    /// The trough's loads of its clipped profile's force `tf` and moment `tm` about the base and
    /// its pressure at the base `pt_base`.
    fn trough_loads(&self, tf: f64, tm: f64, pt_base: f64) -> SainflouTrough {
        let i = &self.input;
        SainflouTrough {
            force_n_per_m: tf,
            lever_m: if tf != 0.0 { tm / tf } else { 0.0 },
            suction_n_per_m: 0.5 * pt_base * i.width_m,
            suction_from_heel_m: 2.0 * i.width_m / 3.0,
        }
    }

    /// h0 and p_b: [`clapotis_quantities`] with the height-independent tanh and cosh.
    #[inline]
    fn clapotis(&self, hw: f64) -> (f64, f64) {
        let i = &self.input;
        (PI * hw * hw / i.wavelength_m / self.tanh_kh, i.rho_w * G_M_PER_S2 * hw / self.cosh_kh)
    }

    /// The trough's profile and loads for height `hw` with its `h0` and `pb`.
    #[inline(always)]
    fn trough_of(&self, hw: f64, h0: f64, pb: f64) -> TroughParts {
        let hp = self.input.base_depth_m;
        let (points, trough_top) = self.trough_points(hw, h0, pb);
        let trough_full = Profile::new(&points);
        let profile = trough_full.clipped(trough_top, hp);
        let pt_base = trough_full.at(hp);
        let tm = profile.moment_about(hp);
        let loads = self.trough_loads(profile.force(), tm, pt_base);
        TroughParts { profile, pt_base, moment: tm, loads }
    }
}

/// The trough's loads on the caisson (per metre; signs physical), as in [`SainflouResult`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SainflouTrough {
    /// Trough (seaward) force, N/m (< 0).
    pub force_n_per_m: f64,
    /// Height of its resultant above the base, m.
    pub lever_m: f64,
    /// Suction under the base U_t = ½ p_t(h') B, N/m (< 0).
    pub suction_n_per_m: f64,
    /// Distance of the suction resultant from the heel, 2B/3, m.
    pub suction_from_heel_m: f64,
}

/// The trough's part of [`SainflouPeriod::at`].
struct TroughParts {
    profile: Profile,
    pt_base: f64,
    moment: f64,
    loads: SainflouTrough,
}

impl SainflouResult {
    /// Net crest pressure on the wetted face (z from the top of the wetted face to the base).
    pub fn crest_profile(&self) -> Profile {
        self.crest
    }
    /// Net trough pressure on the wetted face.
    pub fn trough_profile(&self) -> Profile {
        self.trough
    }
}

/// Closed forms for a wall reaching the seabed (docs/model.md §2.3), magnitudes, moments about the
/// seabed: (F_crest, M_crest, F_trough, M_trough).
pub fn full_depth_closed_forms(height_m: f64, wavelength_m: f64, depth_m: f64, rho_w: f64) -> (f64, f64, f64, f64) {
    let (h0, pb) = clapotis_quantities(height_m, wavelength_m, depth_m, rho_w);
    let (gw, h, hw) = (rho_w * G_M_PER_S2, depth_m, height_m);
    let a = h + h0 + hw;
    let b = h + h0 - hw;
    (
        (gw * h + pb) * a / 2.0 - gw * h * h / 2.0,
        (gw * h + pb) * a * a / 6.0 - gw * h.powi(3) / 6.0,
        gw * h * h / 2.0 - b * (gw * h - pb) / 2.0,
        gw * h.powi(3) / 6.0 - b * b * (gw * h - pb) / 6.0,
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::waves::dispersion::wavelength_m;

    #[test]
    fn full_depth_wall_matches_closed_forms_and_physics_md_2_3() {
        // Wall to the seabed (h' = h) with a tall crest: polyline integrals = §2.3 closed forms to
        // rounding (1e-12), and the §2.3 check values 7.277 and 3.619 kN/m (given to 4 digits → 5e-4).
        let l = wavelength_m(3.04, 1.14);
        let r = sainflou(&SainflouInput {
            height_m: 0.524,
            wavelength_m: l,
            depth_m: 1.14,
            base_depth_m: 1.14,
            crest_freeboard_m: 10.0,
            width_m: 0.78,
            rho_w: 1000.0,
        });
        let (fc, mc, ft, mt) = full_depth_closed_forms(0.524, l, 1.14, 1000.0);
        assert!((r.crest_force_n_per_m - fc).abs() < 1e-12 * fc);
        assert!((r.crest_moment_base_nm_per_m - mc).abs() < 1e-12 * mc);
        assert!((r.trough_force_n_per_m + ft).abs() < 1e-12 * ft);
        assert!((r.trough_moment_base_nm_per_m + mt).abs() < 1e-12 * mt);
        assert!((fc / 1e3 - 7.277).abs() / 7.277 < 5e-4, "F_crest = {fc}");
        assert!((ft / 1e3 - 3.619).abs() / 3.619 < 5e-4, "F_trough = {ft}");
    }

    #[test]
    fn base_above_trough_integrates_only_to_the_base() {
        // h' < H − h0: the net trough pressure is −ρ g z on [0, h'], so F = −ρ g h'²/2 exactly.
        let l = wavelength_m(3.04, 1.14);
        let r = sainflou(&SainflouInput {
            height_m: 0.524,
            wavelength_m: l,
            depth_m: 1.14,
            base_depth_m: 0.2,
            crest_freeboard_m: 1.0,
            width_m: 0.78,
            rho_w: 1000.0,
        });
        let expected = -1000.0 * G_M_PER_S2 * 0.04 / 2.0;
        assert!((r.trough_force_n_per_m - expected).abs() < 1e-12 * expected.abs());
        assert!((r.trough_base_pressure_pa + 1000.0 * G_M_PER_S2 * 0.2).abs() < 1e-9);
    }

    #[test]
    fn trough_alone_is_at_bit_for_bit() {
        // The trough's fast path (points on the stack) against `at` (through `Profile`), bit for
        // bit: heights from 0 to past breaking, bases above, at and below the trough and at the
        // seabed, crests below and above the trough's top, and a depth of 0 (the fallback).
        let mut cases = 0;
        for depth in [0.0_f64, 0.4, 1.14, 10.0] {
            for base_share in [0.0, 0.2, 0.7, 1.0, 1.3] {
                for freeboard in [0.0, 0.05, 0.32, 5.0] {
                    let l = wavelength_m(3.04, depth.max(0.1));
                    let input = SainflouInput {
                        height_m: 0.0,
                        wavelength_m: l,
                        depth_m: depth,
                        base_depth_m: base_share * depth,
                        crest_freeboard_m: freeboard,
                        width_m: 0.78,
                        rho_w: 1025.0,
                    };
                    let period = SainflouPeriod::new(&input);
                    for k in 0..=60 {
                        let hw = 0.05 * k as f64 * depth.max(0.1);
                        let (fast, full) = (period.trough(hw), period.at(hw));
                        let bits = |x: f64| x.to_bits();
                        assert_eq!(bits(fast.force_n_per_m), bits(full.trough_force_n_per_m), "{input:?} {hw}");
                        assert_eq!(bits(fast.lever_m), bits(full.trough_lever_m), "{input:?} {hw}");
                        assert_eq!(bits(fast.suction_n_per_m), bits(full.suction_uplift_n_per_m), "{input:?} {hw}");
                        assert_eq!(bits(fast.suction_from_heel_m), bits(full.suction_from_heel_m), "{input:?} {hw}");
                        cases += 1;
                    }
                }
            }
        }
        assert_eq!(cases, 4 * 5 * 4 * 61);
    }

    #[test]
    fn crest_is_cut_at_the_caisson_crest() {
        let l = wavelength_m(3.04, 1.14);
        let base = SainflouInput {
            height_m: 0.524,
            wavelength_m: l,
            depth_m: 1.14,
            base_depth_m: 0.8,
            crest_freeboard_m: 0.32,
            width_m: 0.78,
            rho_w: 1000.0,
        };
        let low = sainflou(&base);
        let tall = sainflou(&SainflouInput { crest_freeboard_m: 5.0, ..base });
        assert!(low.crest_force_n_per_m < tall.crest_force_n_per_m);
        assert_eq!(low.crest_profile().points()[0].0, -0.32);
    }
}
