//! The caisson: geometry, mass, rotational inertia and the rigid-body mass matrix.
//!
//! Degrees of freedom q = (u_x, u_y, θ) of the **centre of the base**: u_x shoreward, u_y upward,
//! θ clockwise (shoreward overturning) positive. With the centre of gravity a height y_G above the
//! base, its horizontal displacement is u_x + y_G θ (small rotations), so the exact mass matrix
//! about the base centre is (PHYSICS.md §10 item 9)
//!
//! ```text
//!     | m      0   m y_G          |
//! M = | 0      m   0              |
//!     | m y_G  0   I_G + m y_G²   |
//! ```
//!
//! The seed's Eq. 24 drops the coupling: M = diag(m, m, I_G + m y_G²) ([`MassMatrix::Diagonal`]).
//!
//! Mass and weight in water are related through the displaced water (PHYSICS.md §8.2, item 5):
//! m_c = W'/g + ρ_w B l h', with h' the base depth below still water.

use crate::G_M_PER_S2;

/// How the rigid-body mass matrix is formed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum MassMatrix {
    /// Exact rigid-body coupling between u_x and θ about the base centre (default).
    Coupled,
    /// The seed's diagonal form (Eq. 24).
    Diagonal,
}

/// Validated caisson parameters (SI, totals).
#[derive(Debug, Clone, Copy, PartialEq)]
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
    /// Mass of the water displaced by the caisson, kg: ρ_w B l min(h', height).
    pub fn displaced_water_kg(width_m: f64, length_m: f64, base_depth_m: f64, height_m: f64, rho_w: f64) -> f64 {
        rho_w * width_m * length_m * base_depth_m.min(height_m)
    }

    /// Inertia of a uniform block B × height about its centre of gravity: m (B² + h²)/12.
    pub fn uniform_block_inertia_kg_m2(mass_kg: f64, width_m: f64, height_m: f64) -> f64 {
        mass_kg * (width_m * width_m + height_m * height_m) / 12.0
    }

    /// Mass in air from the weight in water (PHYSICS.md §8.2 item 5).
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
        // PHYSICS.md §8.2 item 5: 8.24 kN in water, 0.78 × 1.0 × 0.8 m displaced → 1463.96 kg.
        let disp = Caisson::displaced_water_kg(0.78, 1.0, 0.8, 1.12, 1000.0);
        let m = Caisson::mass_from_weight_in_water(8240.0, disp);
        assert!((m - 1463.96).abs() < 0.01, "{m}");
        // Inertia about the base mid-point 686 kg·m², about the CoG 227 kg·m² (PHYSICS.md §8.3).
        let ig = Caisson::uniform_block_inertia_kg_m2(1464.0, 0.78, 1.12);
        assert!((ig - 227.3).abs() < 0.5, "{ig}");
        assert!((ig + 1464.0 * 0.56 * 0.56 - 686.0).abs() < 1.0);
    }
}
