//! The seed's qualitative findings as computed criteria: the pass/fail rules and their thresholds,
//! once, for the validation report (`caisson validation`, docs/validation.md §4) and the tests
//! that keep the reproduced findings true (tests/verify_findings.rs). The seed is Cuomo, Lupoi, Shimosako
//! & Takahashi (2011), §5.2 and §6, Figs. 7-8, 13 and 15.
//!
//! | # | finding | criterion |
//! |---|---|---|
//! | F1 | t_r/T0 ≪ 1: no sliding even for F_x,max > μ_s W' | [`no_slide_for_short_pulses`]: every slide at t_r/T0 ≤ [`SHORT_PULSE_MAX_TR_OVER_T0`] below [`NO_SLIDE_M`] |
//! | F2 | t_r/T0 ≈ 1: sliding even for F_x,max < μ_s W' | [`slides_near_t0`]: a slide above [`NO_SLIDE_M`] at t_r/T0 in [`NEAR_T0_TR_OVER_T0`] |
//! | F3 | t_r/T0 ≈ 1: more sliding than Shimosako | [`more_than_shimosako_near_t0`]: at the point of [`NEAR_T0_TR_OVER_T0`] with the largest ratio, more than Shimosako |
//! | F4 | t_r/T0 ≫ 1: less (shoreward) sliding than Shimosako | [`less_than_shimosako_for_long_pulses`]: every slide at t_r/T0 ≥ [`LONG_PULSE_MIN_TR_OVER_T0`] in [0, Shimosako) |
//! | F5-F7 | sliding grows with H, falls with W | [`monotonic`]: every consecutive pair of tested conditions, within [`NO_SLIDE_M`] |
//! | F8 | breaking: largest sliding between H = 0.524 and 0.569 m | [`peaks_mid_height`]: for every weight tested at three or more heights, the largest mean in [`PEAK_HEIGHT_RANGE_M`] |
//! | F9 | more sliding than Shimosako's model (a safer estimate) | [`safer_than_rigid_block`]: in at least two thirds of the conditions where either slides |
//!
//! Campaign criteria judge the mean sliding over a condition's realizations.

use super::campaign::ConditionResult;
use super::spectrum::SpectrumPoint;
use std::ops::{Range, RangeInclusive};

/// Sliding counts as "none" below this (m): 1 µm, far below any slide of interest and far above
/// the elastic residue of a stuck caisson.
pub const NO_SLIDE_M: f64 = 1e-6;
/// Pulses at or below this t_r/T0 are short (F1).
pub const SHORT_PULSE_MAX_TR_OVER_T0: f64 = 0.1;
/// Pulses in this range of t_r/T0 are near the natural period (F2, F3).
pub const NEAR_T0_TR_OVER_T0: RangeInclusive<f64> = 0.5..=2.0;
/// Pulses at or above this t_r/T0 are long (F4).
pub const LONG_PULSE_MIN_TR_OVER_T0: f64 = 5.0;
/// Where the breaking campaign's sliding peaks in H, m: the tested 0.524 and 0.569 m (F8).
pub const PEAK_HEIGHT_RANGE_M: Range<f64> = 0.52..0.57;

/// A criterion's verdict: whether the finding holds, how many points, pairs, weights or
/// conditions it judged, and the numbers behind it in words (the report's cell).
#[derive(Debug, Clone, PartialEq)]
pub struct Verdict {
    pub holds: bool,
    pub checked: usize,
    pub detail: String,
}

/// F1 on a spectrum under a pulse above the static resistance.
pub fn no_slide_for_short_pulses(points: &[SpectrumPoint]) -> Verdict {
    let short = points.iter().filter(|p| p.tr_over_t0 <= SHORT_PULSE_MAX_TR_OVER_T0);
    let worst = short.clone().map(|p| p.permanent_sliding_m).fold(0.0, f64::max);
    Verdict {
        holds: worst < NO_SLIDE_M,
        checked: short.count(),
        detail: format!("largest slide for t_r/T0 ≤ 0.1: {:.4} mm", worst * 1e3),
    }
}

/// F2 on a spectrum under a pulse of peak `load_n` (0.9 × the static resistance).
pub fn slides_near_t0(points: &[SpectrumPoint], load_n: f64) -> Verdict {
    let near = points.iter().filter(|p| NEAR_T0_TR_OVER_T0.contains(&p.tr_over_t0));
    let best = near.clone().map(|p| p.permanent_sliding_m).fold(0.0, f64::max);
    let amp = near.clone().map(|p| p.max_horizontal_reaction_n).fold(0.0, f64::max) / load_n;
    Verdict {
        holds: best > NO_SLIDE_M,
        checked: near.count(),
        detail: format!(
            "largest slide for 0.5 ≤ t_r/T0 ≤ 2 at 0.9 μ_s W': {:.4} mm; largest effective reaction {:.3} × the load",
            best * 1e3,
            amp
        ),
    }
}

/// F3 on a spectrum under a pulse above the static resistance.
pub fn more_than_shimosako_near_t0(points: &[SpectrumPoint]) -> Verdict {
    let near = points.iter().filter(|p| NEAR_T0_TR_OVER_T0.contains(&p.tr_over_t0));
    let most = near.clone().max_by(|a, b| {
        (a.permanent_sliding_m / a.shimosako_sliding_m).total_cmp(&(b.permanent_sliding_m / b.shimosako_sliding_m))
    });
    let Some(p) = most else {
        return Verdict { holds: false, checked: 0, detail: "no point with 0.5 ≤ t_r/T0 ≤ 2".into() };
    };
    Verdict {
        holds: p.permanent_sliding_m > p.shimosako_sliding_m,
        checked: near.count(),
        detail: format!(
            "at t_r/T0 = {:.2}: {:.4} mm vs Shimosako {:.4} mm",
            p.tr_over_t0,
            p.permanent_sliding_m * 1e3,
            p.shimosako_sliding_m * 1e3
        ),
    }
}

/// F4 on a spectrum under a pulse above the static resistance. Judged on shoreward sliding: a
/// caisson that ends seaward (rocking landings) has not slid less in the wave's direction, it has
/// done something else.
pub fn less_than_shimosako_for_long_pulses(points: &[SpectrumPoint]) -> Verdict {
    let long: Vec<&SpectrumPoint> = points.iter().filter(|p| p.tr_over_t0 >= LONG_PULSE_MIN_TR_OVER_T0).collect();
    let Some(p) = long.last() else {
        return Verdict { holds: false, checked: 0, detail: "no point with t_r/T0 ≥ 5".into() };
    };
    let holds = long.iter().all(|p| (0.0..p.shimosako_sliding_m).contains(&p.permanent_sliding_m));
    let seaward = long.iter().filter(|p| p.permanent_sliding_m < 0.0).count();
    Verdict {
        holds,
        checked: long.len(),
        detail: format!(
            "at t_r/T0 = {:.1}: {:.3} mm shoreward vs Shimosako {:.3} mm{}",
            p.tr_over_t0,
            p.permanent_sliding_m * 1e3,
            p.shimosako_sliding_m * 1e3,
            if seaward > 0 { format!("; {seaward} of {} points end seaward", long.len()) } else { String::new() }
        ),
    }
}

/// Mean sliding (m) of the condition with height `h` (m) and weight in water `w_kn` (kN), if
/// tested.
pub fn mean_at(rs: &[ConditionResult], h: f64, w_kn: f64) -> Option<f64> {
    rs.iter()
        .find(|r| (r.condition.height_m - h).abs() < 1e-9 && (r.condition.weight_in_water_n / 1e3 - w_kn).abs() < 1e-9)
        .map(|r| r.summary.sliding_m.mean)
}

fn sorted_unique(v: impl Iterator<Item = f64>) -> Vec<f64> {
    let mut v: Vec<f64> = v.collect();
    v.sort_by(f64::total_cmp);
    v.dedup();
    v
}

/// F5-F7: for each fixed value of one variable, is the mean sliding monotonic in the other?
/// `along_height`: along H for each W, else along W for each H; `increasing` or decreasing, both
/// within [`NO_SLIDE_M`] (which absorbs the elastic residue of conditions that do not slide).
/// `checked`: the consecutive pairs judged.
pub fn monotonic(rs: &[ConditionResult], along_height: bool, increasing: bool) -> Verdict {
    let hs = sorted_unique(rs.iter().map(|r| r.condition.height_m));
    let ws = sorted_unique(rs.iter().map(|r| r.condition.weight_in_water_n / 1e3));
    let mut bad = Vec::new();
    let mut checked = 0;
    let (outer, inner) = if along_height { (&ws, &hs) } else { (&hs, &ws) };
    for &o in outer {
        let seq: Vec<(f64, f64)> = inner
            .iter()
            .filter_map(|&i| {
                let (h, w) = if along_height { (i, o) } else { (o, i) };
                mean_at(rs, h, w).map(|m| (i, m))
            })
            .collect();
        for pair in seq.windows(2) {
            checked += 1;
            let fine =
                if increasing { pair[1].1 >= pair[0].1 - NO_SLIDE_M } else { pair[1].1 <= pair[0].1 + NO_SLIDE_M };
            if !fine {
                let what = if along_height {
                    format!("W = {o} kN: H {} → {}", pair[0].0, pair[1].0)
                } else {
                    format!("H = {o} m: W {} → {}", pair[0].0, pair[1].0)
                };
                bad.push(format!("{what} gives {:.2} → {:.2} mm", pair[0].1 * 1e3, pair[1].1 * 1e3));
            }
        }
    }
    let holds = bad.is_empty();
    let detail = match (holds, along_height) {
        (true, true) => "every W".to_string(),
        (true, false) => "every H".to_string(),
        (false, _) => bad.join("; "),
    };
    Verdict { holds, checked, detail }
}

/// F8: for every weight tested at three or more heights, the largest mean sliding is at a height
/// in [`PEAK_HEIGHT_RANGE_M`] (not at the largest height): sliding is not monotonic in H.
/// `checked`: the weights judged.
pub fn peaks_mid_height(rs: &[ConditionResult]) -> Verdict {
    let ws = sorted_unique(rs.iter().map(|r| r.condition.weight_in_water_n / 1e3));
    let mut holds = true;
    let mut notes = Vec::new();
    for w in ws {
        let mut at: Vec<(f64, f64)> = rs
            .iter()
            .filter(|r| (r.condition.weight_in_water_n / 1e3 - w).abs() < 1e-9)
            .map(|r| (r.condition.height_m, r.summary.sliding_m.mean))
            .collect();
        if at.len() < 3 {
            continue;
        }
        at.sort_by(|a, b| a.0.total_cmp(&b.0));
        let best = at.iter().copied().fold((0.0, f64::NEG_INFINITY), |a, b| if b.1 > a.1 { b } else { a });
        holds &= PEAK_HEIGHT_RANGE_M.contains(&best.0);
        notes.push(format!("W = {w} kN: largest mean sliding {:.2} mm at H = {} m", best.1 * 1e3, best.0));
    }
    Verdict { holds, checked: notes.len(), detail: notes.join("; ") }
}

/// F9, "the present model generally gives a safer estimate than Shimosako": the dynamic mean at
/// least the rigid block's in at least two thirds of the conditions where either slides.
/// `checked`: those conditions.
pub fn safer_than_rigid_block(rs: &[ConditionResult]) -> Verdict {
    let sliding: Vec<&ConditionResult> = rs
        .iter()
        .filter(|r| r.summary.sliding_m.mean > NO_SLIDE_M || r.summary.rigid_block_sliding_m.mean > NO_SLIDE_M)
        .collect();
    let safer = sliding.iter().filter(|r| r.summary.sliding_m.mean >= r.summary.rigid_block_sliding_m.mean).count();
    Verdict {
        holds: 3 * safer >= 2 * sliding.len() && !sliding.is_empty(),
        checked: sliding.len(),
        detail: format!("{safer} of {} sliding conditions", sliding.len()),
    }
}
