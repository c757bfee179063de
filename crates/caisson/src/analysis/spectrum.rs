//! Shock spectrum of the caisson (seed §5.2, Figs. 7-8): sweep the rise time of a symmetric
//! triangular pulse (seed Eq. 37) over t_r/T0 and record the amplification Ψ = max|u_x|/(F/K_x)
//! (seed Eq. 38, docs/model.md §10 item 28) and the permanent sliding, with the closed forms beside
//! them (undamped SDOF Ψ, §9.2; exact rigid block and Shimosako 1999, §6.3).
//!
//! T0 = 2π sqrt(m_x/K_x), m_x the caisson mass plus the horizontal added mass. The closed-form
//! slides use the same mass m_x, A = |P_max| + μ_d U_max and B = μ_d W'. Points run in parallel
//! (rayon) and are gathered by index, so results do not depend on the thread count.
//!
//! Each run uses dt = min(scenario dt, T0/200, t_r/20) and lasts 4 t_r + 10 T0.

use super::closed_form::{rigid_block_sliding_m, shimosako_sliding_m, shock_spectrum_psi};
use super::run::run;
use super::{Progress, Structure};
use crate::dynamics::{SolveError, SolverParams};
use crate::loads::pulse::TrianglePulse;
use rayon::prelude::*;

/// Smallest and largest t_r/T0 of a sweep: below, the steps of t_r/20 make a point last about
/// 200 T0/t_r steps; above, the point lasts 4 t_r. (The limits of `caisson spectrum
/// --tr-over-t0` and of the Python `caisson.spectrum`.)
pub const RATIO_RANGE: (f64, f64) = (1e-3, 1e3);
/// Most time steps a sweep may take, all points together ([`estimated_steps`]; about a minute or
/// two on one core).
pub const MAX_STEPS: f64 = 1e8;

/// One point of the spectrum.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct SpectrumPoint {
    pub tr_over_t0: f64,
    pub rise_time_s: f64,
    /// Ψ from the dynamic model.
    pub psi: f64,
    /// Ψ of the undamped SDOF (closed form).
    pub psi_closed_form: f64,
    pub permanent_sliding_m: f64,
    /// Shimosako & Takahashi (1999) closed form (corrected seed Eq. 8).
    pub shimosako_sliding_m: f64,
    /// Exact rigid-block slide.
    pub rigid_block_sliding_m: f64,
    pub max_horizontal_reaction_n: f64,
}

/// Log-spaced ratios from `from` to `to` (inclusive), `count` ≥ 2 points.
pub fn log_space(from: f64, to: f64, count: usize) -> Vec<f64> {
    let (a, b) = (from.ln(), to.ln());
    (0..count).map(|i| (a + (b - a) * i as f64 / (count - 1) as f64).exp()).collect()
}

/// The time step and the duration of the point t_r = `ratio` · T0 (module docs).
fn point_dt_and_duration(structure_dt_s: f64, t0: f64, ratio: f64) -> (f64, f64) {
    let tr = ratio * t0;
    (structure_dt_s.min(t0 / 200.0).min(tr / 20.0), 4.0 * tr + 10.0 * t0)
}

/// The number of time steps a [`sweep`] of `ratios` takes (without the halvings of steps that do
/// not converge): the work to check before running it.
pub fn estimated_steps(structure: &Structure, ratios: &[f64]) -> f64 {
    let t0 = structure.model().natural_period_s();
    ratios
        .iter()
        .map(|&r| {
            let (dt, duration) = point_dt_and_duration(structure.solver.dt_s, t0, r);
            (duration / dt).ceil()
        })
        .sum()
}

/// Sweep `ratios` of t_r/T0 for the pulse `base` (its rise time is replaced); `progress` is
/// called once per finished point.
pub fn sweep(
    structure: &Structure,
    base: TrianglePulse,
    ratios: &[f64],
    progress: Progress<'_>,
) -> Result<Vec<SpectrumPoint>, SolveError> {
    let model = structure.model();
    let t0 = model.natural_period_s();
    let m_x = model.horizontal_mass_kg();
    let ust = base.peak.fx_n.abs() / model.kx_n_per_m;
    let mu = structure.foundation.mu_dynamic;
    let a = base.peak.fx_n.abs() + mu * base.peak.fy_n;
    let b = mu * structure.caisson.weight_in_water_n;
    let solver = structure.solver;
    ratios
        .par_iter()
        // A progress callback that unwinds (a Python call stopped by Ctrl-C) stops the items not yet begun.
        .panic_fuse()
        .map(|&ratio| {
            let tr = ratio * t0;
            let pulse = TrianglePulse { peak: base.peak, rise_s: tr, start_s: 0.0 };
            let (dt, duration) = point_dt_and_duration(solver.dt_s, t0, ratio);
            let point =
                Structure { solver: SolverParams { dt_s: dt, output_interval_s: dt, ..solver }, ..structure.clone() };
            let r = run(&point, &pulse, duration, false)?;
            progress();
            Ok(SpectrumPoint {
                tr_over_t0: ratio,
                rise_time_s: tr,
                psi: if ust > 0.0 { r.summary.max_horizontal_displacement_m / ust } else { 0.0 },
                psi_closed_form: shock_spectrum_psi(ratio),
                permanent_sliding_m: r.summary.permanent_sliding_m,
                shimosako_sliding_m: shimosako_sliding_m(a, b, m_x, 2.0 * tr),
                rigid_block_sliding_m: rigid_block_sliding_m(a, b, m_x, 2.0 * tr),
                max_horizontal_reaction_n: r.summary.max_horizontal_reaction_n,
            })
        })
        .collect()
}
