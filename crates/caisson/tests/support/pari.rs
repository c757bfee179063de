//! The PARI flume of the seed's tests (§6, Table 4) as a wave-load site, shared by the wave-load
//! tests, the allocation contract and the loads benchmark (`#[path]`-included there).

use caisson::loads::model::WaveSite;

/// Water depth at the toe of the PARI flume, m (h_s).
pub const PARI_DEPTH_AT_TOE_M: f64 = 1.14;

/// The PARI caisson site (h_s 1.14 m, h' 0.8 m, h_c 0.32 m, B 0.78 m, fresh water, a flat bed)
/// with depth `depth_at_wall_m` over the mound at the wall (0.4 m with the breaking tests'
/// extra berm, 0.8 m without).
pub fn pari_site(depth_at_wall_m: f64) -> WaveSite {
    WaveSite {
        rho_w: 1000.0,
        depth_at_toe_m: PARI_DEPTH_AT_TOE_M,
        depth_at_wall_m,
        base_depth_m: 0.8,
        crest_freeboard_m: 0.32,
        width_m: 0.78,
        length_m: 1.0,
        seabed_slope: 0.0,
        berm_width_m: None,
    }
}
