//! Piecewise-linear pressure profiles on the caisson face, integrated exactly.
//!
//! A profile is a polyline of (z, p) points, z the depth below still water (m, positive down),
//! p the net wave pressure (Pa, positive = pushing the wall shoreward). Each model (Goda,
//! Sainflou, impact) describes its pressure this way; the force and its moment are then the exact
//! integrals of the polyline, segment by segment (docs/model.md §2.4, "a sum of trapezoids"):
//!
//! ```text
//! F   = Σ ℓ (p_a + p_b)/2                                  (N/m)
//! M_r = Σ ℓ [p_a (2 y_a + y_b) + p_b (y_a + 2 y_b)] / 6     (N·m/m),  y = z_r − z
//! ```
//!
//! with ℓ the segment length and y the height above the reference depth z_r (the caisson base:
//! M is the moment about the base, positive for a shoreward force above it). These formulas are
//! exact for linear p. Points are held in a fixed array: no allocation.

/// Most points a profile holds.
pub const MAX_POINTS: usize = 8;

/// A pressure polyline, ordered by increasing depth z.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Profile {
    pts: [(f64, f64); MAX_POINTS],
    n: usize,
}

impl Default for Profile {
    fn default() -> Self {
        Profile { pts: [(0.0, 0.0); MAX_POINTS], n: 0 }
    }
}

impl Profile {
    /// Build from (z, p) points ordered by non-decreasing z (at most [`MAX_POINTS`]; extra
    /// points are ignored, out-of-order points are skipped).
    pub fn new(points: &[(f64, f64)]) -> Self {
        let mut p = Profile::default();
        for &pt in points {
            p.push(pt.0, pt.1);
        }
        p
    }

    fn push(&mut self, z: f64, p: f64) {
        if self.n == MAX_POINTS || !(z.is_finite() && p.is_finite()) {
            return;
        }
        if self.n > 0 && z < self.pts[self.n - 1].0 {
            return;
        }
        self.pts[self.n] = (z, p);
        self.n += 1;
    }

    /// The points (z, p).
    pub fn points(&self) -> &[(f64, f64)] {
        &self.pts[..self.n]
    }

    /// Pressure at depth z: linear between points; outside the first/last point, the end value
    /// is held (the callers clip the profile to the wetted face first).
    pub fn at(&self, z: f64) -> f64 {
        at_points(self.points(), z)
    }

    /// The same pressure restricted to z_top ≤ z ≤ z_bottom (values held beyond the ends, so
    /// that e.g. the seabed pressure continues down a caisson face embedded in the mound).
    pub fn clipped(&self, z_top: f64, z_bottom: f64) -> Profile {
        let mut out = Profile::default();
        if z_bottom.partial_cmp(&z_top) != Some(std::cmp::Ordering::Greater) || self.n == 0 {
            return out;
        }
        out.push(z_top, self.at(z_top));
        for &(z, p) in self.points() {
            if z > z_top && z < z_bottom {
                out.push(z, p);
            }
        }
        out.push(z_bottom, self.at(z_bottom));
        out
    }

    /// Force ∫ p dz, N/m (positive shoreward).
    pub fn force(&self) -> f64 {
        force_of(self.points())
    }

    /// Moment ∫ p (z_ref − z) dz about the depth `z_ref` (the base), N·m/m.
    pub fn moment_about(&self, z_ref: f64) -> f64 {
        moment_of(self.points(), z_ref)
    }
}

/// [`Profile::at`] on the points `pts` (sorted by z).
#[inline]
pub(crate) fn at_points(pts: &[(f64, f64)], z: f64) -> f64 {
    match pts.len() {
        0 => 0.0,
        _ if z <= pts[0].0 => pts[0].1,
        n if z >= pts[n - 1].0 => pts[n - 1].1,
        _ => {
            let j = pts.partition_point(|q| q.0 <= z);
            let (a, b) = (pts[j - 1], pts[j]);
            if b.0 == a.0 {
                b.1
            } else {
                a.1 + (b.1 - a.1) * (z - a.0) / (b.0 - a.0)
            }
        }
    }
}

/// [`Profile::force`] on the points `pts`.
#[inline]
pub(crate) fn force_of(pts: &[(f64, f64)]) -> f64 {
    pts.windows(2).map(|w| (w[1].0 - w[0].0) * 0.5 * (w[0].1 + w[1].1)).sum()
}

/// [`Profile::moment_about`] on the points `pts`.
#[inline]
pub(crate) fn moment_of(pts: &[(f64, f64)], z_ref: f64) -> f64 {
    pts.windows(2)
        .map(|w| {
            let (za, pa) = w[0];
            let (zb, pb) = w[1];
            let (ya, yb) = (z_ref - za, z_ref - zb);
            (zb - za) * (pa * (2.0 * ya + yb) + pb * (ya + 2.0 * yb)) / 6.0
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn midpoint(p: &Profile, z0: f64, z1: f64, zr: f64, n: usize) -> (f64, f64) {
        let dz = (z1 - z0) / n as f64;
        let (mut f, mut m) = (0.0, 0.0);
        for i in 0..n {
            let z = z0 + (i as f64 + 0.5) * dz;
            f += p.at(z) * dz;
            m += p.at(z) * (zr - z) * dz;
        }
        (f, m)
    }

    #[test]
    fn exact_integrals_match_fine_midpoint_rule() {
        // Midpoint rule on 2e5 cells: error O(Δz²·p'') at kinks only, ≈ 1e-9 relative here.
        let p = Profile::new(&[(-0.5, 0.0), (0.0, 5.0), (0.3, 2.0), (0.8, 3.5)]);
        let (f, m) = midpoint(&p, -0.5, 0.8, 0.8, 200_000);
        assert!((p.force() - f).abs() < 1e-8 * f.abs(), "{} vs {f}", p.force());
        assert!((p.moment_about(0.8) - m).abs() < 1e-8 * m.abs(), "{} vs {m}", p.moment_about(0.8));
    }

    #[test]
    fn clipping_interpolates_and_holds_beyond_the_ends() {
        let p = Profile::new(&[(0.0, 0.0), (1.0, 10.0)]);
        let c = p.clipped(0.25, 1.5);
        assert_eq!(c.points(), &[(0.25, 2.5), (1.0, 10.0), (1.5, 10.0)]);
        assert!(p.clipped(1.0, 1.0).points().is_empty());
        // Uniform pressure 10 over 1 m: moment about the bottom = 10 · ½.
        let u = Profile::new(&[(0.0, 10.0), (1.0, 10.0)]);
        assert!((u.moment_about(1.0) - 5.0).abs() < 1e-15);
    }

    #[test]
    fn bad_points_are_skipped_not_panicking() {
        let p = Profile::new(&[(0.0, 1.0), (f64::NAN, 1.0), (-1.0, 2.0), (1.0, 1.0)]);
        assert_eq!(p.points().len(), 2);
    }
}
