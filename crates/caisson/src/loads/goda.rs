//! Goda (1974, 2000) pressure formula on an upright section, with Takahashi, Tanimoto &
//! Shimosako's (1994) impulsive coefficient α_I (docs/model.md §1; verified there against the
//! `breakwater` package and the Deltares toolbox).
//!
//! ```text
//! α1 = 0.6 + 0.5 [ (4πh/L) / sinh(4πh/L) ]²
//! α2 = min{ (h_b − d)/(3 h_b) · (H_D/d)²,  2d/H_D }
//! α3 = 1 − (h'/h) [ 1 − 1/cosh(2πh/L) ]
//! η* = 0.75 (1 + cos β) λ1 H_D
//! p1 = ½ (1 + cos β)(λ1 α1 + λ2 α* cos²β) ρ_w g H_D        α* = α2, or max(α2, α_I)
//! p2 = p1 / cosh(2πh/L)     p3 = α3 p1     p4 = p1 (1 − h_c/η*) if η* > h_c, else 0
//! pu = ½ (1 + cos β) λ3 α1 α3 ρ_w g H_D                     (front toe; zero at the heel)
//! P   = ½ (p1 + p3) h' + ½ (p1 + p4) h_c*,   h_c* = min(η*, h_c)
//! M_P = (1/6)(2p1 + p3) h'² + ½ (p1 + p4) h' h_c* + (1/6)(p1 + 2p4) h_c*²     (about the base)
//! U   = ½ pu B,   M_U = (2/3) B U                                             (about the heel)
//! ```
//!
//! h is the depth at the toe (wavelength L taken there), h_b the depth 5 H1/3 seaward
//! (h + 5 H tan θ for regular waves), d the depth above the berm, h' the base depth, h_c the crest
//! freeboard, B the base width. β is rotated by up to 15° toward the normal:
//! β_use = max(0, |β| − 15°) (docs/model.md §1.1). λ1 = λ2 = λ3 = 1 for a plain caisson.
//!
//! Takahashi's α_I (docs/model.md §1.4), in Goda's static check when the berm width B_M is given
//! ([`GodaPeriod::at`]), and in the impulsive peak of a breaking wave under `goda-takahashi`
//! ([`GodaPeriod::at_with`] with the rule's α_I1, [`super::breaking_load`]):
//! δ11 = 0.93 (B_M/L − 0.12) + 0.36 (0.4 − d/h), δ22 = −0.36 (B_M/L − 0.12) + 0.93 (0.4 − d/h);
//! δ1 = 20 δ11 (δ11 ≤ 0) or 15 δ11; δ2 = 4.9 δ22 (δ22 ≤ 0) or 3 δ22;
//! α_I1 = cos δ2 / cosh δ1 (δ22 ≤ 0) or 1/(cosh δ1 √cosh δ2); α_I0 = H/d (H ≤ 2d) or 2;
//! α_I = α_I0 α_I1.
//!
//! Results are per metre of breakwater (N/m, N·m/m). The closed forms above are checked in the
//! tests against the exact integral of the pressure profile ([`GodaResult::profile`]).

use super::profile::Profile;
use crate::G_M_PER_S2;
use std::f64::consts::PI;

/// Inputs of Goda's formula (SI; per metre).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GodaInput {
    /// Design wave height H_D, m.
    pub height_m: f64,
    /// Wavelength L at the toe depth h for the design period, m.
    pub wavelength_m: f64,
    /// h, depth at the toe, m.
    pub depth_m: f64,
    /// h_b, depth 5 H1/3 seaward of the structure, m (= h on a flat bed).
    pub depth_5h_seaward_m: f64,
    /// d, depth above the berm in front of the wall, m.
    pub wall_depth_m: f64,
    /// h', depth of the caisson base below still water, m.
    pub base_depth_m: f64,
    /// h_c, crest elevation above still water, m.
    pub crest_freeboard_m: f64,
    /// B, base width, m.
    pub width_m: f64,
    /// β, angle between wave direction and the normal to the breakwater, rad (before the 15° rule).
    pub angle_rad: f64,
    /// B_M, berm width, m. `Some` enables Takahashi's α_I.
    pub berm_width_m: Option<f64>,
    /// λ1, λ2, λ3 (1, 1, 1 for a plain caisson).
    pub lambda: [f64; 3],
    /// ρ_w, kg/m³.
    pub rho_w: f64,
}

/// Goda pressures, forces and moments (per metre).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct GodaResult {
    pub alpha1: f64,
    pub alpha2: f64,
    pub alpha3: f64,
    /// Takahashi's α_I, when it was evaluated (a berm width given).
    pub alpha_i: Option<f64>,
    /// α* used in p1: α2 or max(α2, α_I).
    pub alpha_star: f64,
    /// β after the 15° rotation, rad.
    pub angle_used_rad: f64,
    /// η*, elevation above still water where the pressure vanishes, m.
    pub eta_star_m: f64,
    /// h_c* = min(η*, h_c), m.
    pub hc_star_m: f64,
    pub p1_pa: f64,
    pub p2_pa: f64,
    pub p3_pa: f64,
    pub p4_pa: f64,
    pub pu_pa: f64,
    /// P, horizontal force, N/m (shoreward).
    pub horizontal_force_n_per_m: f64,
    /// M_P, moment of P about the base, N·m/m.
    pub horizontal_moment_base_nm_per_m: f64,
    /// y_L = M_P / P, height of the horizontal resultant above the base, m.
    pub horizontal_lever_m: f64,
    /// U, uplift force, N/m.
    pub uplift_force_n_per_m: f64,
    /// M_U = (2/3) B U, moment of U about the heel, N·m/m.
    pub uplift_moment_heel_nm_per_m: f64,
    /// x_L = 2B/3, distance of the uplift resultant from the heel, m.
    pub uplift_from_heel_m: f64,
    /// h', kept to place the profile, m.
    pub base_depth_m: f64,
}

/// Takahashi's impulsive pressure coefficient α_I (docs/model.md §1.4).
pub fn takahashi_alpha_i(height_m: f64, wavelength_m: f64, depth_m: f64, wall_depth_m: f64, berm_width_m: f64) -> f64 {
    takahashi_alpha_i0(height_m, wall_depth_m) * takahashi_alpha_i1(wavelength_m, depth_m, wall_depth_m, berm_width_m)
}

/// α_I0 = H/d (H ≤ 2d) or 2.
#[inline]
fn takahashi_alpha_i0(height_m: f64, wall_depth_m: f64) -> f64 {
    if height_m <= 2.0 * wall_depth_m {
        height_m / wall_depth_m
    } else {
        2.0
    }
}

/// α_I1, the part of α_I that does not depend on the height: B_M `berm_width_m` and L
/// `wavelength_m` at the toe depth h `depth_m`, d `wall_depth_m` (docs/model.md §1.4).
pub fn takahashi_alpha_i1(wavelength_m: f64, depth_m: f64, wall_depth_m: f64, berm_width_m: f64) -> f64 {
    let bl = berm_width_m / wavelength_m - 0.12;
    let dh = 0.4 - wall_depth_m / depth_m;
    let d11 = 0.93 * bl + 0.36 * dh;
    let d22 = -0.36 * bl + 0.93 * dh;
    let d1 = if d11 <= 0.0 { 20.0 * d11 } else { 15.0 * d11 };
    let d2 = if d22 <= 0.0 { 4.9 * d22 } else { 3.0 * d22 };
    if d22 <= 0.0 {
        d2.cos() / d1.cosh()
    } else {
        1.0 / (d1.cosh() * d2.cosh().sqrt())
    }
}

/// Goda's formula (module docs).
pub fn goda(i: &GodaInput) -> GodaResult {
    GodaPeriod::new(i).at(i.height_m, i.depth_5h_seaward_m)
}

/// The part of Goda's formula that does not depend on the wave height: the site, the angle and
/// the wavelength (α1, α3, cosh kh, Takahashi's α_I1). [`GodaPeriod::at`] finishes it for one
/// height with the same floating-point operations as [`goda`], so a storm's waves (one period,
/// many heights) share it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct GodaPeriod {
    input: GodaInput,
    beta: f64,
    cb: f64,
    alpha1: f64,
    cosh_kh: f64,
    alpha3: f64,
    /// α_I1 of Takahashi's α_I = α_I0 α_I1, when a berm width was given ([`Self::at`]).
    alpha_i1: Option<f64>,
    gamma_w: f64,
}

impl GodaPeriod {
    /// Everything of `i` but its height and h_b (`height_m` and `depth_5h_seaward_m` are ignored).
    pub fn new(i: &GodaInput) -> Self {
        let (h, d) = (i.depth_m, i.wall_depth_m);
        let kh = 2.0 * PI * h / i.wavelength_m;
        let beta = (i.angle_rad.abs() - 15f64.to_radians()).max(0.0);
        let cb = beta.cos();
        let x = 2.0 * kh;
        let alpha1 = 0.6 + 0.5 * if x > 700.0 { 0.0 } else { (x / x.sinh()).powi(2) };
        let cosh_kh = kh.cosh();
        let alpha3 = 1.0 - i.base_depth_m / h * (1.0 - 1.0 / cosh_kh);
        let alpha_i1 = i.berm_width_m.map(|bm| takahashi_alpha_i1(i.wavelength_m, h, d, bm));
        GodaPeriod { input: *i, beta, cb, alpha1, cosh_kh, alpha3, alpha_i1, gamma_w: i.rho_w * G_M_PER_S2 }
    }

    /// α_I1 of Takahashi's α_I = α_I0 α_I1 at this period and site for a berm `berm_width_m` wide
    /// (m): what [`Self::at_with`] takes.
    pub fn alpha_i1_for(&self, berm_width_m: f64) -> f64 {
        let i = &self.input;
        takahashi_alpha_i1(i.wavelength_m, i.depth_m, i.wall_depth_m, berm_width_m)
    }

    /// Upper bounds [P, M_P, U] (per metre, each ≥ 0) of Goda's force, its moment about the base
    /// and the uplift over every design height 0 < H_D ≤ `max_height_m` whose h_b ≤
    /// `max_depth_5h_m`, with α* = max(α2, α_I0 `alpha_i1`) (α2 alone for `None`, as
    /// [`Self::at_with`]), or `None` unless λ ≥ 0, h' ≥ 0, h_c ≥ 0 and d > 0 (what the bounds
    /// assume). Term by term (module docs' formulas): α1 H_D and η* grow with H_D;
    /// α2 H_D ≤ min{2d, (h_b − d)/(3 h_b) · H_D³/d²}, whose factor grows with h_b;
    /// α_I H_D = α_I0 α_I1 H_D ≤ 2 |α_I1| H_D (α_I0 ≤ 2); so p1 ≤ p̄1 at the largest H_D and h_b;
    /// p3 = α3 p1 ≤ max(α3, 0) p̄1; p4 = p1 (1 − h_c/η*) ≤ p1; h_c* ≤ min(η̄*, h_c);
    /// pu ≤ its value at the largest H_D with max(α3, 0).
    pub fn upper_bounds(&self, max_height_m: f64, max_depth_5h_m: f64, alpha_i1: Option<f64>) -> Option<[f64; 3]> {
        let i = &self.input;
        let (d, hc, hp) = (i.wall_depth_m, i.crest_freeboard_m, i.base_depth_m);
        if !(i.lambda.iter().all(|&l| l >= 0.0) && hp >= 0.0 && hc >= 0.0 && d > 0.0 && max_depth_5h_m > 0.0) {
            return None;
        }
        let (cb, [l1, l2, l3], h) = (self.cb, i.lambda, max_height_m.max(0.0));
        let a2h = (((max_depth_5h_m - d) / (3.0 * max_depth_5h_m)).max(0.0) * h.powi(3) / (d * d)).min(2.0 * d);
        let aih = alpha_i1.map_or(0.0, |a1| 2.0 * a1.abs() * h);
        let p1 = 0.5 * (1.0 + cb) * (l1 * self.alpha1 * h + l2 * a2h.max(aih) * cb * cb) * self.gamma_w;
        let alpha3 = self.alpha3.max(0.0);
        let p3 = alpha3 * p1;
        let hcs = (0.75 * (1.0 + cb) * l1 * h).min(hc);
        let force = 0.5 * (p1 + p3) * hp + p1 * hcs;
        let moment = (2.0 * p1 + p3) * hp * hp / 6.0 + p1 * hp * hcs + 0.5 * p1 * hcs * hcs;
        let uplift = 0.25 * (1.0 + cb) * l3 * self.alpha1 * alpha3 * self.gamma_w * h * i.width_m;
        Some([force, moment, uplift.max(0.0)])
    }

    /// Goda's formula for the design height `height_m` (H_D) with h_b = `depth_5h_seaward_m`:
    /// with Takahashi's α_I when the input's berm width was given (Goda's static check).
    #[inline(always)]
    pub fn at(&self, height_m: f64, depth_5h_seaward_m: f64) -> GodaResult {
        self.at_with(height_m, depth_5h_seaward_m, self.alpha_i1)
    }

    /// Goda's formula for the design height `height_m` (H_D) with h_b = `depth_5h_seaward_m` and
    /// α* = max(α2, α_I) with α_I = α_I0 `alpha_i1` ([`Self::alpha_i1_for`]), or α* = α2 for
    /// `None` (the same floating-point operations as [`goda`] with and without a berm width).
    #[inline(always)]
    pub fn at_with(&self, height_m: f64, depth_5h_seaward_m: f64, alpha_i1: Option<f64>) -> GodaResult {
        let i = &self.input;
        let (hd, d) = (height_m, i.wall_depth_m);
        let (cb, [l1, l2, l3]) = (self.cb, i.lambda);
        let alpha1 = self.alpha1;
        let hb = depth_5h_seaward_m;
        let alpha2 = ((hb - d) / (3.0 * hb) * (hd / d).powi(2)).min(2.0 * d / hd);
        let alpha3 = self.alpha3;
        let alpha_i = alpha_i1.map(|a1| takahashi_alpha_i0(hd, d) * a1);
        let alpha_star = alpha_i.map_or(alpha2, |ai| alpha2.max(ai));
        let gamma_w = self.gamma_w;
        let eta_star_m = 0.75 * (1.0 + cb) * l1 * hd;
        let p1 = 0.5 * (1.0 + cb) * (l1 * alpha1 + l2 * alpha_star * cb * cb) * gamma_w * hd;
        let p2 = p1 / self.cosh_kh;
        let p3 = alpha3 * p1;
        let hc = i.crest_freeboard_m;
        let p4 = if eta_star_m > hc { p1 * (1.0 - hc / eta_star_m) } else { 0.0 };
        let pu = 0.5 * (1.0 + cb) * l3 * alpha1 * alpha3 * gamma_w * hd;
        let hcs = eta_star_m.min(hc);
        let hp = i.base_depth_m;
        let force = 0.5 * (p1 + p3) * hp + 0.5 * (p1 + p4) * hcs;
        let moment = (2.0 * p1 + p3) * hp * hp / 6.0 + 0.5 * (p1 + p4) * hp * hcs + (p1 + 2.0 * p4) * hcs * hcs / 6.0;
        let uplift = 0.5 * pu * i.width_m;
        let x_u = 2.0 * i.width_m / 3.0;
        GodaResult {
            alpha1,
            alpha2,
            alpha3,
            alpha_i,
            alpha_star,
            angle_used_rad: self.beta,
            eta_star_m,
            hc_star_m: hcs,
            p1_pa: p1,
            p2_pa: p2,
            p3_pa: p3,
            p4_pa: p4,
            pu_pa: pu,
            horizontal_force_n_per_m: force,
            horizontal_moment_base_nm_per_m: moment,
            horizontal_lever_m: if force > 0.0 { moment / force } else { 0.0 },
            uplift_force_n_per_m: uplift,
            uplift_moment_heel_nm_per_m: x_u * uplift,
            uplift_from_heel_m: x_u,
            base_depth_m: hp,
        }
    }
}

impl GodaResult {
    /// The pressure on the wetted face, from the crest of the pressure (or the caisson crest) to
    /// the base: p4 at −h_c* (p4 = 0 at −η* when not overtopped), p1 at still water, p3 at h'.
    pub fn profile(&self) -> Profile {
        let top = if self.hc_star_m < self.eta_star_m { self.p4_pa } else { 0.0 };
        Profile::new(&[(-self.hc_star_m, top), (0.0, self.p1_pa), (self.base_depth_m, self.p3_pa)])
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::waves::dispersion::wavelength_m;

    fn pari(h_wave: f64, d: f64) -> GodaInput {
        GodaInput {
            height_m: h_wave,
            wavelength_m: wavelength_m(3.04, 1.14),
            depth_m: 1.14,
            depth_5h_seaward_m: 1.14,
            wall_depth_m: d,
            base_depth_m: 0.8,
            crest_freeboard_m: 0.32,
            width_m: 0.78,
            angle_rad: 0.0,
            berm_width_m: None,
            lambda: [1.0; 3],
            rho_w: 1000.0,
        }
    }

    #[test]
    fn closed_forms_equal_the_integral_of_the_profile() {
        // Overtopped (η* > h_c) and not overtopped (η* < h_c): exact polyline integrals agree
        // with P and M_P to rounding (1e-12 relative).
        for (h, hc) in [(0.524, 0.32), (0.3, 0.5)] {
            let mut i = pari(h, 0.4);
            i.crest_freeboard_m = hc;
            let r = goda(&i);
            let p = r.profile();
            assert!((p.force() - r.horizontal_force_n_per_m).abs() < 1e-12 * r.horizontal_force_n_per_m);
            let m = p.moment_about(0.8);
            assert!(
                (m - r.horizontal_moment_base_nm_per_m).abs() < 1e-12 * m,
                "{m} vs {}",
                r.horizontal_moment_base_nm_per_m
            );
        }
    }

    #[test]
    fn fifteen_degree_rule_and_obliquity() {
        // |β| ≤ 15° gives exactly the normal-incidence result; 30° reduces p1 (cos 15° < 1).
        let r0 = goda(&pari(0.524, 0.8));
        let mut i = pari(0.524, 0.8);
        i.angle_rad = (-12f64).to_radians();
        assert_eq!(goda(&i).p1_pa, r0.p1_pa);
        i.angle_rad = 30f64.to_radians();
        let r30 = goda(&i);
        assert!((r30.angle_used_rad - 15f64.to_radians()).abs() < 1e-15);
        assert!(r30.p1_pa < r0.p1_pa && r30.eta_star_m < r0.eta_star_m);
    }

    #[test]
    fn takahashi_alpha_i_raises_p1_only_when_larger_than_alpha2() {
        // Berm: B_M/L ≈ 0.12 and d/h = 0.35 give a strong impulsive coefficient (δ11, δ22 ≈ 0):
        // α_I1 ≈ cos 0 / cosh 0 = 1 → α_I ≈ H/d.
        let mut i = pari(0.524, 0.4);
        i.berm_width_m = Some(0.12 * i.wavelength_m);
        let r = goda(&i);
        let ai = r.alpha_i.unwrap();
        assert!(ai > r.alpha2 && r.alpha_star == ai);
        // Exact formula at this point: δ11 = 0.36·(0.4−0.4/1.14), δ22 = 0.93·(0.4−0.4/1.14) > 0.
        let dh = 0.4 - 0.4 / 1.14;
        let (d1, d2) = (15.0 * 0.36 * dh, 3.0 * 0.93 * dh);
        let expected = (0.524 / 0.4) / (f64::cosh(d1) * f64::cosh(d2).sqrt());
        assert!((ai - expected).abs() < 1e-12, "{ai} vs {expected}");
        // A very wide berm makes α_I tiny and α* falls back to α2.
        i.berm_width_m = Some(2.0 * i.wavelength_m);
        let r = goda(&i);
        assert_eq!(r.alpha_star, r.alpha2);
    }
}
