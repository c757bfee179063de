//! The caisson: geometry, mass, rotational inertia and the rigid-body mass matrix.
//!
//! Degrees of freedom q = (u_x, u_y, θ) of the **centre of the base**: u_x shoreward, u_y upward,
//! θ clockwise (shoreward overturning) positive. With the centre of gravity a height y_G above the
//! base, its horizontal displacement is u_x + y_G θ (small rotations), so the exact mass matrix
//! about the base centre is (docs/model.md §10 item 9)
//!
//! ```text
//!     | m      0   m y_G          |
//! M = | 0      m   0              |
//!     | m y_G  0   I_G + m y_G²   |
//! ```
//!
//! The seed's Eq. 24 drops the coupling: M = diag(m, m, I_G + m y_G²) ([`MassMatrix::Diagonal`]).
//!
//! Mass and weight in water are related through the displaced water (docs/model.md §8.2, item 5):
//! m_c = W'/g + ρ_w B l h', with h' the base depth below still water. The caisson is given by its
//! weight in water, its mass, or both ([`MassSpec`]), or by its construction ([`Construction`]:
//! walls, slab, cells, fill and cap, docs/model.md §8.4), from which W', the mass, the centre of
//! gravity and the inertia follow for whatever width it is built with.

pub mod construction;

pub use construction::{Construction, MassProperties};

use crate::check::{between, positive, positive_up_to, rule};
use crate::{ParamError, Profile, G_M_PER_S2};

/// How the rigid-body mass matrix is formed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum MassMatrix {
    /// Exact rigid-body coupling between u_x and θ about the base centre (profile `consistent`).
    Coupled,
    /// The seed's diagonal form (Eq. 24; profile `seed-2011`). Its θ entry is the inertia about
    /// the base, I_G + m y_G² (+ the water's), not the seed's m_c + m_hyd,θ, which is not an
    /// inertia (docs/model.md §10 item 9).
    Diagonal,
}

/// How the caisson's mass is given: the other of mass and weight in water follows from the
/// displaced water, m_c = W'/g + ρ_w B l h' (docs/model.md §8.2 item 5).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum MassSpec {
    /// Weight in water W', N; the mass follows.
    WeightInWater { weight_in_water_n: f64 },
    /// Mass in air, kg; the weight in water follows.
    MassInAir { mass_kg: f64 },
    /// Both given (no check that they agree with the displaced water).
    Both { mass_kg: f64, weight_in_water_n: f64 },
    /// The construction: the mass, the weight in water, the centre of gravity and the inertia
    /// follow from it and the outer dimensions ([`Construction::mass_properties`]).
    Construction(Construction),
}

/// The caisson as specified (SI, totals): what [`Caisson`] is derived from. Vary a field and
/// [`CaissonSpec::build`] again to get a consistent caisson (the mass follows the weight, the
/// default inertia follows the mass; a caisson given by its construction gets the weight, mass,
/// centre of gravity and inertia of its new width, height or base depth).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct CaissonSpec {
    /// B, base width in the wave direction, m.
    pub width_m: f64,
    /// Alongshore length, m.
    pub length_m: f64,
    pub height_m: f64,
    /// h', depth of the base below still water, m (0 to the height).
    pub base_depth_m: f64,
    pub mass: MassSpec,
    /// y_G, m above the base; `None`: half the height, or the construction's. Refused with a
    /// construction (which gives it).
    pub cog_height_m: Option<f64>,
    /// I_G, kg·m² about the centre of gravity; `None`: a uniform block, m (B² + h²)/12, or the
    /// construction's. Refused with a construction (which gives it).
    pub inertia_cog_kg_m2: Option<f64>,
    /// `None`: the profile's (coupled for `consistent`, diagonal for `seed-2011`).
    pub mass_matrix: Option<MassMatrix>,
}

/// The smallest width, length or height of a caisson, m (a thousandth of a flume model's).
pub const MIN_DIMENSION_M: f64 = 1e-3;
/// The largest height over base width of a caisson.
pub const MAX_SLENDERNESS: f64 = 100.0;
/// The lightest weight in water W' of a caisson, as a fraction of the weight of the water it
/// displaces, ρ_w g B l min(h', h). A concrete caisson filled with sand or stone weighs 0.8 to 2
/// times that in water (the design example 1.56, the construction example 1.88, the flume models
/// of PARI 1.2 to 2.6); an unfilled shell with its cells flooded and air above still water 0.29
/// (walls 0.3 m, slab 0.5 m) to 0.44 (the construction example's walls): no caisson that stands
/// on its bed is lighter than about a quarter. Lighter is a unit slip (tonnes for kN gives 9.81
/// times less: 0.16 for the design example; a weight per metre over a caisson 20 m long, 20
/// times less), and its results are absurd (the design example at W' = 500 kN, 0.14, slid 52 km
/// in a life).
pub const MIN_WEIGHT_OVER_DISPLACED: f64 = 0.2;

/// The rule a weight in water `w_n` (N) breaks against the water displaced, `displaced_kg`, of a
/// caisson `width_m` × `length_m` with `submerged_m` under still water, if it does.
fn too_light(w_n: f64, displaced_kg: f64, width_m: f64, length_m: f64, submerged_m: f64) -> Option<String> {
    let buoyancy_n = displaced_kg * G_M_PER_S2;
    let least_n = MIN_WEIGHT_OVER_DISPLACED * buoyancy_n;
    // kN to a tenth, or to three significant digits below 1 kN (a flume model's millinewtons).
    let kn = |n: f64| {
        let k = n / 1e3;
        if k >= 1.0 {
            format!("{k:.1}")
        } else {
            crate::fmt_number(format!("{k:.2e}").parse().unwrap_or(k))
        }
    };
    let (b, l, h) = (crate::fmt_value(width_m), crate::fmt_value(length_m), crate::fmt_value(submerged_m));
    (w_n < least_n).then(|| {
        format!(
            "must be at least {} kN, {MIN_WEIGHT_OVER_DISPLACED} of the {} kN of water the caisson displaces (ρ_w g B l h' with B = {b} m, l = {l} m, h' = {h} m under still water; this is {:.3} of it): a caisson filled with sand or stone weighs 0.8 to 2 times that in water, even an unfilled concrete shell about 0.3 to 0.5, and a lighter one is a unit slip: tonnes instead of kN (9.81 times less), or a weight per metre for a caisson longer than 1 m (give the total over `length_m`)",
            kn(least_n),
            kn(buoyancy_n),
            w_n / buoyancy_n
        )
    })
}

impl CaissonSpec {
    /// The caisson in water of density `rho_w` (kg/m³), every quantity checked, with the
    /// defaults of `profile`.
    pub fn build(&self, rho_w: f64, profile: Profile) -> Result<Caisson, ParamError> {
        // Bounds far beyond any breakwater, so that an absurd number (a unit slip by 10^k) is an
        // input error naming its key rather than an overflow deep in a run: 1 mm to 1 km (10 km
        // alongshore), and a base at least 1/100 of the height (a flume caisson is about as wide
        // as tall, a prototype 0.5 to 1.5 times; a post 10^4 times taller than wide rocks over
        // at once and its run fails to converge).
        let size = |q, v, hi| positive(q, v).and_then(|v| between(q, v, MIN_DIMENSION_M, hi));
        let width_m = size("width_m", self.width_m, 1e3)?;
        let length_m = size("length_m", self.length_m, 1e4)?;
        let height_m = size("height_m", self.height_m, 1e3)?;
        if height_m > MAX_SLENDERNESS * width_m {
            return Err(rule(
                "width_m",
                width_m,
                format!(
                    "must be at least 1/{MAX_SLENDERNESS} of the caisson height {height_m} m (a caisson is not {MAX_SLENDERNESS} times taller than wide)"
                ),
            ));
        }
        let base_depth_m = self.base_depth_m;
        if !(base_depth_m.is_finite() && (0.0..=height_m).contains(&base_depth_m)) {
            return Err(rule(
                "base_depth_m",
                base_depth_m,
                format!("must be between 0 and the caisson height {height_m} m (a base deeper than the caisson is tall leaves it under water)"),
            ));
        }
        let displaced = Caisson::displaced_water_kg(width_m, length_m, base_depth_m, height_m, rho_w);
        // The centre of gravity and inertia of a construction.
        let mut built = None;
        let (mass_kg, weight_in_water_n) = match self.mass {
            MassSpec::WeightInWater { weight_in_water_n } => {
                let w = positive_up_to("weight_in_water_n", weight_in_water_n, 1e11)?;
                if let Some(r) = too_light(w, displaced, width_m, length_m, base_depth_m.min(height_m)) {
                    return Err(rule("weight_in_water_n", w, r));
                }
                (Caisson::mass_from_weight_in_water(w, displaced), w)
            }
            MassSpec::Construction(c) => {
                let p = c.mass_properties(width_m, length_m, height_m, base_depth_m, rho_w)?;
                built = Some(p);
                (p.mass_kg, p.weight_in_water_n)
            }
            MassSpec::MassInAir { mass_kg } => {
                let m = positive("mass_kg", mass_kg)?;
                if m <= displaced {
                    return Err(rule(
                        "mass_kg",
                        m,
                        format!("must exceed the {displaced:.1} kg of water the caisson displaces, or it floats"),
                    ));
                }
                let w = (m - displaced) * G_M_PER_S2;
                if too_light(w, displaced, width_m, length_m, base_depth_m.min(height_m)).is_some() {
                    return Err(rule(
                        "mass_kg",
                        m,
                        format!(
                            "must be at least {:.1} kg, {} times the {displaced:.1} kg of water the caisson displaces: lighter, its weight in water is below {MIN_WEIGHT_OVER_DISPLACED} of the water's, less than an unfilled concrete shell weighs (a unit slip: tonnes for kg?)",
                            (1.0 + MIN_WEIGHT_OVER_DISPLACED) * displaced,
                            1.0 + MIN_WEIGHT_OVER_DISPLACED
                        ),
                    ));
                }
                (m, w)
            }
            MassSpec::Both { mass_kg, weight_in_water_n } => {
                let (m, w) = (positive("mass_kg", mass_kg)?, positive("weight_in_water_n", weight_in_water_n)?);
                if let Some(r) = too_light(w, displaced, width_m, length_m, base_depth_m.min(height_m)) {
                    return Err(rule("weight_in_water_n", w, r));
                }
                (m, w)
            }
        };
        let given = |quantity: &'static str, v: f64| {
            rule(
                quantity,
                v,
                "is computed from the construction (wall and slab thicknesses, cells, densities); remove it",
            )
        };
        let cog_height_m = match (self.cog_height_m, built) {
            (Some(v), Some(_)) => return Err(given("cog_height_m", v)),
            (Some(v), None) => between("cog_height_m", v, 0.0, height_m)?,
            (None, Some(p)) => p.cog_height_m,
            (None, None) => 0.5 * height_m,
        };
        let inertia_cog_kg_m2 = match (self.inertia_cog_kg_m2, built) {
            (Some(v), Some(_)) => return Err(given("inertia_cog_kg_m2", v)),
            (Some(v), None) => positive("inertia_cog_kg_m2", v)?,
            (None, Some(p)) => p.inertia_cog_kg_m2,
            (None, None) => Caisson::uniform_block_inertia_kg_m2(mass_kg, width_m, height_m),
        };
        Ok(Caisson {
            width_m,
            length_m,
            height_m,
            base_depth_m,
            mass_kg,
            weight_in_water_n,
            cog_height_m,
            inertia_cog_kg_m2,
            mass_matrix: self.mass_matrix.unwrap_or(match profile {
                Profile::Consistent => MassMatrix::Coupled,
                Profile::Seed2011 => MassMatrix::Diagonal,
            }),
        })
    }

    /// The same caisson with another weight in water (N): the mass then follows from the
    /// displaced water, as for a caisson given by its weight (a construction is replaced by the
    /// weight; its centre of gravity and inertia then take their defaults).
    pub fn with_weight_in_water_n(mut self, weight_in_water_n: f64) -> Self {
        self.mass = MassSpec::WeightInWater { weight_in_water_n };
        self
    }

    /// The same caisson with another base width B (m). Built, a caisson given by its
    /// construction gets the weight in water, mass, centre of gravity and inertia of that width;
    /// one given by its weight or mass keeps it (the default inertia follows the width).
    pub fn with_width_m(mut self, width_m: f64) -> Self {
        self.width_m = width_m;
        self
    }

    /// The construction, if the caisson is given by it.
    pub fn construction(&self) -> Option<&Construction> {
        match &self.mass {
            MassSpec::Construction(c) => Some(c),
            _ => None,
        }
    }
}

/// Validated caisson parameters (SI, totals).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Caisson {
    /// B, base width in the wave direction, m.
    pub width_m: f64,
    /// Alongshore length, m.
    pub length_m: f64,
    pub height_m: f64,
    /// h', depth of the base below still water, m.
    pub base_depth_m: f64,
    /// Mass in air, kg.
    pub mass_kg: f64,
    /// Weight in water W', N.
    pub weight_in_water_n: f64,
    /// y_G, height of the centre of gravity above the base, m.
    pub cog_height_m: f64,
    /// I_G, rotational inertia about the centre of gravity, kg·m².
    pub inertia_cog_kg_m2: f64,
    pub mass_matrix: MassMatrix,
}

impl Caisson {
    /// The weight in water the caisson loses when the water rises `rise_m` above the still
    /// water level it was given at, ρ_w g B l rise, N (docs/model.md §6.4 step 3: a tide lowers
    /// W' by the water it adds around the walls). W' minus this ≤ 0: the caisson floats.
    pub fn weight_lost_to_rise_n(&self, rho_w: f64, rise_m: f64) -> f64 {
        rho_w * G_M_PER_S2 * self.width_m * self.length_m * rise_m
    }

    /// Mass of the water displaced by the caisson, kg: ρ_w B l min(h', height).
    pub fn displaced_water_kg(width_m: f64, length_m: f64, base_depth_m: f64, height_m: f64, rho_w: f64) -> f64 {
        rho_w * width_m * length_m * base_depth_m.min(height_m)
    }

    /// Inertia of a uniform block B × height about its centre of gravity: m (B² + h²)/12.
    pub fn uniform_block_inertia_kg_m2(mass_kg: f64, width_m: f64, height_m: f64) -> f64 {
        mass_kg * (width_m * width_m + height_m * height_m) / 12.0
    }

    /// Mass in air from the weight in water (docs/model.md §8.2 item 5).
    pub fn mass_from_weight_in_water(weight_in_water_n: f64, displaced_kg: f64) -> f64 {
        weight_in_water_n / G_M_PER_S2 + displaced_kg
    }

    /// Rigid-body mass matrix about the base centre (row-major 3×3), kg, kg·m, kg·m².
    pub fn mass_matrix(&self) -> [[f64; 3]; 3] {
        let m = self.mass_kg;
        let s = m * self.cog_height_m;
        let i_base = self.inertia_cog_kg_m2 + m * self.cog_height_m * self.cog_height_m;
        let c = match self.mass_matrix {
            MassMatrix::Coupled => s,
            MassMatrix::Diagonal => 0.0,
        };
        [[m, 0.0, c], [0.0, m, 0.0], [c, 0.0, i_base]]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table6_mass_from_weight_in_water() {
        // docs/model.md §8.2 item 5: 8.24 kN in water, 0.78 × 1.0 × 0.8 m displaced → 1463.96 kg.
        let disp = Caisson::displaced_water_kg(0.78, 1.0, 0.8, 1.12, 1000.0);
        let m = Caisson::mass_from_weight_in_water(8240.0, disp);
        assert!((m - 1463.96).abs() < 0.01, "{m}");
        // Inertia about the base mid-point 686 kg·m², about the CoG 227 kg·m² (docs/model.md §8.3).
        let ig = Caisson::uniform_block_inertia_kg_m2(1464.0, 0.78, 1.12);
        assert!((ig - 227.3).abs() < 0.5, "{ig}");
        assert!((ig + 1464.0 * 0.56 * 0.56 - 686.0).abs() < 1.0);
    }

    #[test]
    fn a_rise_of_the_water_costs_the_weight_of_the_water_it_adds_around_the_walls() {
        // The PARI caisson (B 0.78 m, l 1 m) as a uniform block of 16.17 kN in water: 0.1 m of
        // fresh water costs 1000 · 9.81 · 0.78 · 1.0 · 0.1 = 765.18 N (by hand, g as the crate's).
        let c = CaissonSpec {
            width_m: 0.78,
            length_m: 1.0,
            height_m: 1.12,
            base_depth_m: 0.8,
            mass: MassSpec::WeightInWater { weight_in_water_n: 16170.0 },
            cog_height_m: None,
            inertia_cog_kg_m2: None,
            mass_matrix: None,
        }
        .build(1000.0, Profile::default())
        .unwrap();
        let by_hand = 1000.0 * G_M_PER_S2 * 0.78 * 1.0 * 0.1;
        assert!((by_hand - 765.18).abs() < 0.1, "{by_hand}");
        assert_eq!(c.weight_lost_to_rise_n(1000.0, 0.1), by_hand);
        assert_eq!(c.weight_lost_to_rise_n(1000.0, 0.0), 0.0);
    }
}
