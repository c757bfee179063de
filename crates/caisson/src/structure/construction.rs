//! The caisson as built: its mass, weight in water, centre of gravity and inertia from its
//! construction (docs/model.md §8.4).
//!
//! A caisson is a reinforced-concrete box: a base slab, outer walls and partition walls that
//! divide it into cells, the cells filled with sand (or rubble), and a concrete cap on top (Goda
//! 2000, ch. 4; OCDI 2009, Part III ch. 4 "Breakwaters"). Here the box is B wide (cross-shore) and
//! H tall, and one caisson is L_u long alongshore:
//!
//! * base slab, thickness t_s, the whole plan B × L_u, from the base up;
//! * outer walls of thickness t_w all round; `cells_across` (n_x) × `cells_along` (n_y) equal
//!   cells separated by partitions of thickness t_p, so each cell is
//!   c_x = (B − 2t_w − (n_x − 1)t_p)/n_x by c_y = (L_u − 2t_w − (n_y − 1)t_p)/n_y;
//! * the fill in the cells from the slab (y = t_s) to the underside of the cap (y = H − h_cap):
//!   density ρ_f below still water (saturated: grains and the pore water), ρ_f' above it (moist);
//! * the cap, h_cap thick, the whole plan, density ρ_cap (plain concrete); walls and slab ρ_c.
//!
//! Mass (a sum over the parts, kg, for one caisson of length L_u):
//!
//! ```text
//! m_u = ρ_c B L_u (H − h_cap) + ρ_cap B L_u h_cap
//!       + (ρ_f − ρ_c) A_c h_f + (ρ_f' − ρ_c) A_c h_f'
//! ```
//!
//! with A_c = n_x c_x · n_y c_y the plan area of the cells, h_f the fill height below still water
//! (from t_s to min(h', H − h_cap)) and h_f' above it. The mass includes the water in the pores of
//! the fill (it moves with the caisson); the buoyancy acts on the outer volume below still water,
//! so W' = g (m − ρ_w B l h'), the relation of every other route (docs/model.md §8.2 item 5). The
//! same W' follows from submerged unit weights (ρ − ρ_w for every part below still water), the
//! form of the Japanese standards.
//!
//! The centre of gravity y_G = Σ m_i y_i / m; the inertia about it for rotation in the
//! cross-section (about the alongshore axis through G), I_G = Σ ∫ (x² + y²) dm − m y_G², each
//! part a rectangular prism (∫ x² dm = m (x_c² + a²/12) for a width a centred at x_c). A model of
//! `length_m` = l takes l/L_u of one caisson (per metre of breakwater with l = 1).
//!
//! Footings (slab projections beyond the walls), haunches, the superstructure's parapet and the
//! reinforcement's detail are not modelled: a caisson with them is described by equivalent
//! thicknesses, or given by its weight.

use crate::check::{between, count, non_negative, positive, positive_up_to, rule};
use crate::{ParamError, G_M_PER_S2};

/// A caisson as built (SI): thicknesses, cells and densities (module docs). The outer dimensions
/// (width, height, base depth, modelled length) are the [`super::CaissonSpec`]'s, so the mass
/// properties follow any width it is built with.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Construction {
    /// t_w, thickness of the outer walls, m.
    pub wall_thickness_m: f64,
    /// t_s, thickness of the base slab, m.
    pub slab_thickness_m: f64,
    /// t_p, thickness of the partition walls between cells, m (unused with a single cell).
    pub partition_thickness_m: f64,
    /// n_x, cells across (in the wave direction).
    pub cells_across: usize,
    /// n_y, cells along one caisson (alongshore).
    pub cells_along: usize,
    /// L_u, alongshore length of one caisson as built, m; `None`: the modelled length.
    pub unit_length_m: Option<f64>,
    /// h_cap, height of the concrete cap above the fill, up to the crest, m (0: none).
    pub cap_height_m: f64,
    /// ρ_c, walls and slab (reinforced concrete), kg/m³.
    pub concrete_density_kg_per_m3: f64,
    /// ρ_cap, the cap (plain concrete), kg/m³.
    pub cap_density_kg_per_m3: f64,
    /// ρ_f, the fill below still water (saturated bulk density, pore water included), kg/m³.
    pub fill_density_kg_per_m3: f64,
    /// ρ_f', the fill above still water (moist bulk density), kg/m³.
    pub fill_density_above_water_kg_per_m3: f64,
}

/// Mass, weight in water, centre of gravity and inertia of a caisson (SI, totals for the modelled
/// length).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct MassProperties {
    /// m, mass in air (concrete, fill and the fill's water), kg.
    pub mass_kg: f64,
    /// W' = g (m − ρ_w B l h'), N.
    pub weight_in_water_n: f64,
    /// y_G, m above the base.
    pub cog_height_m: f64,
    /// I_G, kg·m² about the centre of gravity (rotation in the cross-section).
    pub inertia_cog_kg_m2: f64,
}

impl Construction {
    /// ρ_c default: reinforced concrete, 24.0 kN/m³ (OCDI 2009, unit weights of materials) / g.
    pub const CONCRETE_DENSITY_KG_PER_M3: f64 = 2450.0;
    /// ρ_cap default: plain concrete, 22.6 kN/m³ (OCDI 2009) / g.
    pub const CAP_DENSITY_KG_PER_M3: f64 = 2300.0;
    /// ρ_f default: saturated sand, 20 kN/m³ (OCDI 2009) / g, rounded down.
    pub const FILL_DENSITY_KG_PER_M3: f64 = 2000.0;
    /// ρ_f' default: moist (wet) sand, 18 kN/m³ (OCDI 2009) / g, rounded down.
    pub const FILL_DENSITY_ABOVE_WATER_KG_PER_M3: f64 = 1800.0;

    /// Walls `wall_thickness_m` and a slab `slab_thickness_m` around one cell, no cap, the
    /// default densities; change the other fields with struct update syntax.
    pub fn new(wall_thickness_m: f64, slab_thickness_m: f64) -> Self {
        Construction {
            wall_thickness_m,
            slab_thickness_m,
            partition_thickness_m: 0.0,
            cells_across: 1,
            cells_along: 1,
            unit_length_m: None,
            cap_height_m: 0.0,
            concrete_density_kg_per_m3: Self::CONCRETE_DENSITY_KG_PER_M3,
            cap_density_kg_per_m3: Self::CAP_DENSITY_KG_PER_M3,
            fill_density_kg_per_m3: Self::FILL_DENSITY_KG_PER_M3,
            fill_density_above_water_kg_per_m3: Self::FILL_DENSITY_ABOVE_WATER_KG_PER_M3,
        }
    }

    /// The construction with every field checked on its own: thicknesses > 0 (the cap ≥ 0; the
    /// partitions > 0 when there is more than one cell), 1 to 100 cells each way, concrete
    /// densities 1000-5000 kg/m³, fill densities 0-5000 kg/m³ (0: empty cells). Whether it fits
    /// the caisson's outer dimensions is checked by [`Self::mass_properties`].
    pub fn checked(&self) -> Result<Construction, ParamError> {
        let cells_across = count("cells_across", self.cells_across, 1, 100)?;
        let cells_along = count("cells_along", self.cells_along, 1, 100)?;
        let partition_thickness_m = if cells_across > 1 || cells_along > 1 {
            positive("partition_thickness_m", self.partition_thickness_m)?
        } else {
            non_negative("partition_thickness_m", self.partition_thickness_m)?
        };
        Ok(Construction {
            wall_thickness_m: positive("wall_thickness_m", self.wall_thickness_m)?,
            slab_thickness_m: positive("slab_thickness_m", self.slab_thickness_m)?,
            partition_thickness_m,
            cells_across,
            cells_along,
            unit_length_m: match self.unit_length_m {
                Some(v) => Some(positive_up_to("unit_length_m", v, 1e4)?),
                None => None,
            },
            cap_height_m: non_negative("cap_height_m", self.cap_height_m)?,
            concrete_density_kg_per_m3: between(
                "concrete_density_kg_per_m3",
                self.concrete_density_kg_per_m3,
                1000.0,
                5000.0,
            )?,
            cap_density_kg_per_m3: between("cap_density_kg_per_m3", self.cap_density_kg_per_m3, 1000.0, 5000.0)?,
            fill_density_kg_per_m3: between("fill_density_kg_per_m3", self.fill_density_kg_per_m3, 0.0, 5000.0)?,
            fill_density_above_water_kg_per_m3: between(
                "fill_density_above_water_kg_per_m3",
                self.fill_density_above_water_kg_per_m3,
                0.0,
                5000.0,
            )?,
        })
    }

    /// The mass properties of a caisson of this construction, `width_m` wide, `height_m` tall,
    /// its base `base_depth_m` below still water (0 to the height), modelled over `length_m`, in
    /// water of density `rho_w` (module docs). The outer dimensions are taken as checked by
    /// [`super::CaissonSpec::build`]; refused: walls and partitions that leave no room for the cells
    /// (named by `width_m`, or `unit_length_m` / `length_m` alongshore), a slab and cap as tall as
    /// the caisson (`height_m`), a caisson that floats.
    pub fn mass_properties(
        &self,
        width_m: f64,
        length_m: f64,
        height_m: f64,
        base_depth_m: f64,
        rho_w: f64,
    ) -> Result<MassProperties, ParamError> {
        let c = self.checked()?;
        let (b, h) = (width_m, height_m);
        let unit_m = c.unit_length_m.unwrap_or(length_m);
        let (nx, ny) = (c.cells_across as f64, c.cells_along as f64);
        let walls_across = 2.0 * c.wall_thickness_m + (nx - 1.0) * c.partition_thickness_m;
        let walls_along = 2.0 * c.wall_thickness_m + (ny - 1.0) * c.partition_thickness_m;
        let cells_width_m = b - walls_across;
        if cells_width_m.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return Err(rule(
                "width_m",
                b,
                format!(
                    "must exceed the walls and partitions across the caisson, 2 wall_thickness_m + (cells_across − 1) partition_thickness_m = {} m",
                    crate::fmt_number(walls_across)
                ),
            ));
        }
        let cells_length_m = unit_m - walls_along;
        if cells_length_m.partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            let (key, what) = match c.unit_length_m {
                Some(_) => ("unit_length_m", "one caisson"),
                None => (
                    "length_m",
                    "the caisson (a model per metre of breakwater gives the length of one caisson as unit_length_m)",
                ),
            };
            return Err(rule(
                key,
                unit_m,
                format!(
                    "must exceed the walls and partitions along {what}: 2 wall_thickness_m + (cells_along − 1) partition_thickness_m = {} m",
                    crate::fmt_number(walls_along)
                ),
            ));
        }
        let fill_top_m = h - c.cap_height_m;
        if (fill_top_m - c.slab_thickness_m).partial_cmp(&0.0) != Some(std::cmp::Ordering::Greater) {
            return Err(rule(
                "height_m",
                h,
                format!(
                    "must exceed slab_thickness_m + cap_height_m = {} m (the cells need a height)",
                    crate::fmt_number(c.slab_thickness_m + c.cap_height_m)
                ),
            ));
        }

        // One caisson of length L_u as a solid block of concrete and cap, plus the cells with
        // (fill − concrete) density below and above still water (module docs).
        let mut s = Moments::default();
        s.add(c.concrete_density_kg_per_m3, (-0.5 * b, 0.5 * b), (0.0, fill_top_m), unit_m);
        s.add(c.cap_density_kg_per_m3, (-0.5 * b, 0.5 * b), (fill_top_m, h), unit_m);
        let water_m = base_depth_m.clamp(c.slab_thickness_m, fill_top_m);
        let cell_x = cells_width_m / nx;
        for i in 0..c.cells_across {
            let x0 = -0.5 * b + c.wall_thickness_m + i as f64 * (cell_x + c.partition_thickness_m);
            let across = (x0, x0 + cell_x);
            let below = c.fill_density_kg_per_m3 - c.concrete_density_kg_per_m3;
            let above = c.fill_density_above_water_kg_per_m3 - c.concrete_density_kg_per_m3;
            s.add(below, across, (c.slab_thickness_m, water_m), cells_length_m);
            s.add(above, across, (water_m, fill_top_m), cells_length_m);
        }
        let scale = length_m / unit_m;
        let mass_kg = s.mass_kg * scale;
        let cog_height_m = s.first_moment_kg_m / s.mass_kg;
        let inertia_cog_kg_m2 = (s.second_moment_kg_m2 - s.mass_kg * cog_height_m * cog_height_m) * scale;
        let displaced = super::Caisson::displaced_water_kg(b, length_m, base_depth_m, h, rho_w);
        if mass_kg.partial_cmp(&displaced) != Some(std::cmp::Ordering::Greater) {
            return Err(rule(
                "concrete_density_kg_per_m3",
                c.concrete_density_kg_per_m3,
                format!(
                    "gives with this construction a caisson of {mass_kg:.1} kg that does not exceed the {displaced:.1} kg of water it displaces: it floats (check the densities and thicknesses)"
                ),
            ));
        }
        Ok(MassProperties {
            mass_kg,
            weight_in_water_n: (mass_kg - displaced) * G_M_PER_S2,
            cog_height_m,
            inertia_cog_kg_m2,
        })
    }
}

/// Mass, first moment about the base and second moment about the alongshore axis through the
/// base centre, summed over rectangular prisms.
#[derive(Debug, Default)]
struct Moments {
    mass_kg: f64,
    first_moment_kg_m: f64,
    second_moment_kg_m2: f64,
}

impl Moments {
    /// A prism of density `rho` (kg/m³, negative to remove material) over x ∈ `across`,
    /// y ∈ `up` (m), `along_m` long: m = ρ a h l; ∫ y dm = m y_c; ∫ (x² + y²) dm =
    /// m (x_c² + a²/12 + y_c² + h²/12). An empty range adds nothing.
    fn add(&mut self, rho: f64, across: (f64, f64), up: (f64, f64), along_m: f64) {
        let (a, h) = (across.1 - across.0, up.1 - up.0);
        if a <= 0.0 || h <= 0.0 {
            return;
        }
        let (xc, yc) = (0.5 * (across.0 + across.1), 0.5 * (up.0 + up.1));
        let m = rho * a * h * along_m;
        self.mass_kg += m;
        self.first_moment_kg_m += m * yc;
        self.second_moment_kg_m2 += m * (xc * xc + a * a / 12.0 + yc * yc + h * h / 12.0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::structure::{CaissonSpec, MassSpec};
    use crate::Profile;

    /// The worked example of docs/model.md §8.4: B = 20 m, H = 20 m, h' = 14 m, one caisson
    /// 20 m long modelled per metre, walls 0.5 m, slab 0.8 m, 4 × 4 cells, partitions 0.2 m, a
    /// 2 m cap, the default densities, sea water 1030 kg/m³.
    fn worked_example() -> (Construction, [f64; 4]) {
        let c = Construction {
            partition_thickness_m: 0.2,
            cells_across: 4,
            cells_along: 4,
            unit_length_m: Some(20.0),
            cap_height_m: 2.0,
            ..Construction::new(0.5, 0.8)
        };
        // width, length, height, base depth.
        (c, [20.0, 1.0, 20.0, 14.0])
    }

    fn rel(a: f64, b: f64) -> f64 {
        (a - b).abs() / b.abs()
    }

    #[test]
    fn worked_example_matches_the_hand_arithmetic() {
        let (c, [b, l, h, hd]) = worked_example();
        let p = c.mass_properties(b, l, h, hd, 1030.0).unwrap();
        // The hand arithmetic of docs/model.md §8.4, part by part (slab, walls, cap, fill below
        // and above still water) for one caisson 20 m long, not the superposition of the code.
        // Cells 4.6 m square: 4 × 4.6 = 18.4 m net each way, plan 18.4² = 338.56 m².
        let cells_plan = 18.4 * 18.4;
        let walls_plan = 20.0 * 20.0 - cells_plan; // 61.44 m²
                                                   // (mass kg, centroid height m, mean y² m², mean x² m²)
        let cells_x2 = (2.0 * 7.2f64.powi(2) + 2.0 * 2.4f64.powi(2)) / 4.0 + 4.6f64.powi(2) / 12.0;
        let walls_x2 = (20.0 * 20.0f64.powi(3) / 12.0 - cells_plan * cells_x2) / walls_plan;
        let layer = |y0: f64, y1: f64| ((y0 + y1) / 2.0, ((y0 + y1) / 2.0).powi(2) + (y1 - y0).powi(2) / 12.0);
        let parts = [
            (2450.0 * 400.0 * 0.8, layer(0.0, 0.8), 400.0 / 12.0),
            (2450.0 * walls_plan * 17.2, layer(0.8, 18.0), walls_x2),
            (2300.0 * 400.0 * 2.0, layer(18.0, 20.0), 400.0 / 12.0),
            (2000.0 * cells_plan * 13.2, layer(0.8, 14.0), cells_x2),
            (1800.0 * cells_plan * 4.0, layer(14.0, 18.0), cells_x2),
        ];
        let m: f64 = parts.iter().map(|p| p.0).sum();
        let yg = parts.iter().map(|p| p.0 * p.1 .0).sum::<f64>() / m;
        let j: f64 = parts.iter().map(|p| p.0 * (p.1 .1 + p.2)).sum();
        let ig = j - m * yg * yg;
        // Per metre (÷ 20 m); the numbers printed in docs/model.md §8.4.
        assert!(rel(m / 20.0, 829_434.88) < 1e-12, "{}", m / 20.0);
        assert!(rel(yg, 9.931_712) < 1e-7, "{yg}");
        assert!(rel(ig / 20.0, 5.644_017_6e7) < 1e-7, "{}", ig / 20.0);
        // W' = g (m − ρ_w B l h') = 9.81 × (829 434.88 − 288 400) = 5 307 552.17 N/m; and from
        // submerged densities (ρ − ρ_w below still water): concrete below 1131.008 m³,
        // walls above 245.76 m³, the cap, fill below 4468.992 m³ and above 1354.24 m³.
        let submerged = (1131.008 * (2450.0 - 1030.0)
            + 245.76 * 2450.0
            + 800.0 * 2300.0
            + 4468.992 * (2000.0 - 1030.0)
            + 1354.24 * 1800.0)
            / 20.0;
        assert!(rel(submerged, 541_034.88) < 1e-12, "{submerged}");
        // The code against the hand arithmetic: rounding only.
        assert!(rel(p.mass_kg, m / 20.0) < 1e-12, "{}", p.mass_kg);
        assert!(rel(p.weight_in_water_n, 5_307_552.172_8) < 1e-12, "{}", p.weight_in_water_n);
        assert!(rel(p.weight_in_water_n, 9.81 * submerged) < 1e-12);
        assert!(rel(p.cog_height_m, yg) < 1e-12, "{}", p.cog_height_m);
        assert!(rel(p.inertia_cog_kg_m2, ig / 20.0) < 1e-10, "{}", p.inertia_cog_kg_m2);
    }

    #[test]
    fn a_solid_block_is_a_uniform_block() {
        // Fill and cap of the walls' density: a solid block of concrete, B × H, whatever the
        // cells. Crest at still water: W' = (ρ_c − ρ_w) g B H l; half-way up: ρ_c g B (H − h') l
        // above water plus (ρ_c − ρ_w) g B h' l below. y_G = H/2, I_G = m (B² + H²)/12.
        let mut checked = 0;
        for (b, h, hd, l, cells) in [(20.0, 20.0, 20.0, 1.0, 4), (20.0, 20.0, 10.0, 3.0, 2), (0.78, 1.12, 0.8, 1.0, 1)]
        {
            let rho = 2400.0;
            let c = Construction {
                partition_thickness_m: 0.01 * b,
                cells_across: cells,
                cells_along: cells,
                unit_length_m: Some(b),
                cap_height_m: 0.1 * h,
                concrete_density_kg_per_m3: rho,
                cap_density_kg_per_m3: rho,
                fill_density_kg_per_m3: rho,
                fill_density_above_water_kg_per_m3: rho,
                ..Construction::new(0.02 * b, 0.04 * h)
            };
            let p = c.mass_properties(b, l, h, hd, 1025.0).unwrap();
            let m = rho * b * h * l;
            let w = 9.81 * (rho * b * (h - hd) * l + (rho - 1025.0) * b * hd * l);
            assert!(rel(p.mass_kg, m) < 1e-12, "{b}: {}", p.mass_kg);
            assert!(rel(p.weight_in_water_n, w) < 1e-12, "{b}: {}", p.weight_in_water_n);
            assert!(rel(p.cog_height_m, h / 2.0) < 1e-12, "{b}: {}", p.cog_height_m);
            assert!(rel(p.inertia_cog_kg_m2, m * (b * b + h * h) / 12.0) < 1e-12, "{b}: {}", p.inertia_cog_kg_m2);
            checked += 1;
        }
        assert_eq!(checked, 3);
    }

    #[test]
    fn a_fill_as_dense_as_the_water_adds_no_weight_in_water() {
        // Fully submerged (crest at still water), no cap: a fill of the water's density weighs
        // nothing in water, so W' = (ρ_c − ρ_w) g × the concrete's volume: the box B l H less
        // the cells n_x c_x × n_y c_y × (H − t_s).
        let (b, l, h, rho_w) = (16.0, 12.0, 18.0, 1025.0);
        let c = Construction {
            partition_thickness_m: 0.25,
            cells_across: 3,
            cells_along: 2,
            concrete_density_kg_per_m3: 2400.0,
            fill_density_kg_per_m3: rho_w,
            fill_density_above_water_kg_per_m3: 0.0, // no fill above water: not used here
            ..Construction::new(0.45, 0.7)
        };
        let p = c.mass_properties(b, l, h, h, rho_w).unwrap();
        let cells = (16.0 - 0.9 - 2.0 * 0.25) * (12.0 - 0.9 - 0.25) * (18.0 - 0.7);
        let concrete = b * l * h - cells;
        assert!(rel(p.weight_in_water_n, (2400.0 - rho_w) * 9.81 * concrete) < 1e-12, "{}", p.weight_in_water_n);
    }

    #[test]
    fn a_cap_of_another_density_shifts_the_centre_of_gravity_as_two_stacked_blocks() {
        // Solid walls and fill (all ρ_c) under a cap ρ_cap: two stacked uniform blocks. y_G and
        // I_G by the parallel-axis theorem: I_G = Σ m_i ((B² + h_i²)/12 + (y_i − y_G)²).
        let (b, h, cap, rc, rcap) = (18.0, 22.0, 3.0, 2450.0, 2000.0);
        let c = Construction {
            unit_length_m: Some(20.0),
            cap_height_m: cap,
            concrete_density_kg_per_m3: rc,
            cap_density_kg_per_m3: rcap,
            fill_density_kg_per_m3: rc,
            fill_density_above_water_kg_per_m3: rc,
            ..Construction::new(0.5, 0.8)
        };
        let p = c.mass_properties(b, 1.0, h, 15.0, 1030.0).unwrap();
        let (m1, y1, h1) = (rc * b * (h - cap), (h - cap) / 2.0, h - cap);
        let (m2, y2, h2) = (rcap * b * cap, h - cap / 2.0, cap);
        let yg = (m1 * y1 + m2 * y2) / (m1 + m2);
        let ig =
            m1 * ((b * b + h1 * h1) / 12.0 + (y1 - yg).powi(2)) + m2 * ((b * b + h2 * h2) / 12.0 + (y2 - yg).powi(2));
        assert!(rel(p.mass_kg, m1 + m2) < 1e-12);
        assert!(rel(p.cog_height_m, yg) < 1e-12, "{} against {yg}", p.cog_height_m);
        assert!(rel(p.inertia_cog_kg_m2, ig) < 1e-12, "{} against {ig}", p.inertia_cog_kg_m2);
        assert!(p.cog_height_m < h / 2.0, "a lighter cap lowers the centre of gravity");
    }

    #[test]
    fn per_metre_is_the_whole_caisson_over_its_length() {
        // One caisson 20 m long modelled whole (length_m = 20) and per metre (length_m = 1,
        // unit_length_m = 20): masses and inertias in the ratio 20, the same centre of gravity.
        let (c, [b, _, h, hd]) = worked_example();
        let per_metre = c.mass_properties(b, 1.0, h, hd, 1030.0).unwrap();
        let whole = Construction { unit_length_m: None, ..c }.mass_properties(b, 20.0, h, hd, 1030.0).unwrap();
        assert!(rel(whole.mass_kg, 20.0 * per_metre.mass_kg) < 1e-12);
        assert!(rel(whole.weight_in_water_n, 20.0 * per_metre.weight_in_water_n) < 1e-12);
        assert!(rel(whole.inertia_cog_kg_m2, 20.0 * per_metre.inertia_cog_kg_m2) < 1e-12);
        assert!(rel(whole.cog_height_m, per_metre.cog_height_m) < 1e-12);
    }

    #[test]
    fn with_one_fill_density_the_water_level_moves_only_the_buoyancy() {
        // ρ_f' = ρ_f: the mass does not depend on where still water is; W' falls by ρ_w g B l Δh'.
        let (c, [b, l, h, _]) = worked_example();
        let c = Construction { fill_density_above_water_kg_per_m3: c.fill_density_kg_per_m3, ..c };
        let mut n = 0;
        let p0 = c.mass_properties(b, l, h, 10.0, 1030.0).unwrap();
        for hd in [0.0, 0.5, 12.0, 14.0, 19.0, 20.0] {
            let p = c.mass_properties(b, l, h, hd, 1030.0).unwrap();
            assert!(rel(p.mass_kg, p0.mass_kg) < 1e-12, "{hd}");
            let dw = p0.weight_in_water_n - p.weight_in_water_n;
            assert!((dw - 1030.0 * 9.81 * b * l * (hd - 10.0)).abs() < 1e-9 * p0.weight_in_water_n, "{hd}: {dw}");
            n += 1;
        }
        assert_eq!(n, 6);
    }

    #[test]
    fn weight_in_water_grows_with_the_width_as_the_formula_says() {
        // dW'/dB = g [ (l/L_u) (L_u (ρ_c (H − h_cap) + ρ_cap h_cap) + L_f ((ρ_f − ρ_c) h_f
        // + (ρ_f' − ρ_c) h_f')) − ρ_w l h' ], docs/model.md §8.4: for the worked example
        // 9.81 × (48 700 − 0.92 × 8540 − 14 420) = 259 211.592 N/m per metre of width.
        let (c, [_, l, h, hd]) = worked_example();
        let spec = CaissonSpec {
            width_m: 20.0,
            length_m: l,
            height_m: h,
            base_depth_m: hd,
            mass: MassSpec::Construction(c),
            cog_height_m: None,
            inertia_cog_kg_m2: None,
            mass_matrix: None,
        };
        let at = |b: f64| spec.with_width_m(b).build(1030.0, Profile::Consistent).unwrap();
        let slope = 259_211.592;
        let w20 = at(20.0).weight_in_water_n;
        let mut n = 0;
        for b in [2.0, 12.0, 18.0, 22.0, 30.0, 60.0] {
            let w = at(b).weight_in_water_n;
            assert!((w - w20 - slope * (b - 20.0)).abs() < 1e-9 * w20, "B = {b}: {w}");
            n += 1;
        }
        assert_eq!(n, 6);
        // The built caisson takes the construction's centre of gravity and inertia.
        let k = at(20.0);
        assert!(rel(k.cog_height_m, 9.931_712) < 1e-7 && rel(k.inertia_cog_kg_m2, 5.644_017_6e7) < 1e-7);
    }

    #[test]
    fn what_does_not_fit_or_floats_names_its_quantity() {
        let (c, [b, l, h, hd]) = worked_example();
        let q = |c: Construction, b: f64, h: f64| c.mass_properties(b, l, h, hd, 1030.0).unwrap_err().quantity;
        // Across: 2 × 0.5 + 3 × 0.2 = 1.6 m of walls.
        assert_eq!(q(c, 1.6, h), "width_m");
        assert!(c.mass_properties(1.61, l, h, hd.min(1.0), 1030.0).is_ok());
        // Along one caisson, and (without unit_length_m) along the modelled length.
        assert_eq!(q(Construction { unit_length_m: Some(1.5), ..c }, b, h), "unit_length_m");
        assert_eq!(q(Construction { unit_length_m: None, ..c }, b, h), "length_m");
        // Up: slab 0.8 + cap 2.0.
        assert_eq!(q(c, b, 2.8), "height_m");
        // Empty cells below a thin deep box float.
        let light = Construction { fill_density_kg_per_m3: 0.0, fill_density_above_water_kg_per_m3: 0.0, ..c };
        assert_eq!(light.mass_properties(b, l, h, 19.0, 1030.0).unwrap_err().quantity, "concrete_density_kg_per_m3");
        // Ranges of the fields themselves.
        assert_eq!(q(Construction { partition_thickness_m: 0.0, ..c }, b, h), "partition_thickness_m");
        assert_eq!(q(Construction { cells_across: 0, ..c }, b, h), "cells_across");
        assert_eq!(q(Construction { cells_along: 101, ..c }, b, h), "cells_along");
        assert_eq!(q(Construction { wall_thickness_m: f64::NAN, ..c }, b, h), "wall_thickness_m");
        assert_eq!(q(Construction { slab_thickness_m: -0.1, ..c }, b, h), "slab_thickness_m");
        assert_eq!(q(Construction { cap_height_m: f64::INFINITY, ..c }, b, h), "cap_height_m");
        assert_eq!(q(Construction { fill_density_kg_per_m3: 2e4, ..c }, b, h), "fill_density_kg_per_m3");
        assert_eq!(q(Construction { concrete_density_kg_per_m3: 245.0, ..c }, b, h), "concrete_density_kg_per_m3");
        // One cell needs no partitions.
        let one = Construction { cells_across: 1, cells_along: 1, partition_thickness_m: 0.0, ..c };
        assert!(one.mass_properties(b, l, h, hd, 1030.0).is_ok());
    }

    #[test]
    fn a_construction_gives_the_centre_of_gravity_and_inertia() {
        let (c, [b, l, h, hd]) = worked_example();
        let spec = CaissonSpec {
            width_m: b,
            length_m: l,
            height_m: h,
            base_depth_m: hd,
            mass: MassSpec::Construction(c),
            cog_height_m: Some(10.0),
            inertia_cog_kg_m2: None,
            mass_matrix: None,
        };
        assert_eq!(spec.build(1030.0, Profile::Consistent).unwrap_err().quantity, "cog_height_m");
        let spec = CaissonSpec { cog_height_m: None, inertia_cog_kg_m2: Some(1e7), ..spec };
        assert_eq!(spec.build(1030.0, Profile::Consistent).unwrap_err().quantity, "inertia_cog_kg_m2");
    }
}
