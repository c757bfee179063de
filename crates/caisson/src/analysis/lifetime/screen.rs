//! The screen (module docs, "The screen"): the effective-load bounds that skip the waves that
//! cannot slide, lift or press the heel, and the per-storm grid over heights and periods.

use super::params::{StormCase, StormInput};
use super::storm::StormSite;
use crate::dynamics::Model;
use crate::loads::model::{PeakComponents, PeriodLoads};
use crate::loads::regime::RegimeChoice;
use crate::loads::safety::heel_pressure_pa;
use crate::waves::periods::{self, WavePeriods};

/// Dynamic amplification bound on impulsive components (module docs).
pub const PSI_IMPULSE: f64 = 2.0;
/// Cells of the per-storm screen grid over the heights.
const SCREEN_CELLS: usize = 64;
/// Cells of the per-storm screen grid over the periods, when the waves have periods of their own
/// (module docs, "Wave periods"): uniform in u = 1 − τ̄/τ over the periods drawn.
const PERIOD_CELLS: usize = 8;

/// The screen's amplifications and resistance at one wave period (module docs).
#[derive(Debug, Clone, Copy)]
pub(super) struct ScreenBound {
    /// Ψ_q on the pulsating horizontal and vertical components.
    pub(super) psi_q: f64,
    /// Ψ_m on the pulsating moment (the longer of the horizontal and rocking periods).
    pub(super) psi_m: f64,
    /// W', N.
    pub(super) weight_n: f64,
    /// The smaller friction coefficient of the two models.
    pub(super) mu: f64,
    /// B, m.
    pub(super) width_m: f64,
    /// f of [`Model::lift_off_factor`].
    pub(super) lift_factor: f64,
    /// The caisson's length l, m, and the heel pressure the screen lets through, Pa
    /// ([`StormCase::heel_screen_pa`]).
    pub(super) length_m: f64,
    pub(super) heel_screen_pa: f64,
}

/// The effective peak loads of one wave's event for the screen (module docs): the horizontal
/// force P_eff, the uplift U_eff, the moment M_eff, and the uplift's overshoot above the weight
/// when it falls off, (Ψ − 1) U, N and N·m.
pub(super) fn effective(e: &PeakComponents, b: &ScreenBound) -> [f64; 4] {
    let p = (PSI_IMPULSE * e.impact.x.fx_n).max(b.psi_q * e.quasi.x.fx_n);
    let u = (PSI_IMPULSE * e.impact.y.fy_n).max(b.psi_q * e.quasi.y.fy_n).max(0.0);
    let m = (PSI_IMPULSE * e.impact.total().m_nm).max(b.psi_m * e.quasi.total().m_nm).max(0.0);
    let overshoot = ((PSI_IMPULSE - 1.0) * e.impact.y.fy_n).max((b.psi_q - 1.0) * e.quasi.y.fy_n).max(0.0);
    [p, u, m, overshoot]
}

/// The screen's friction and lift-off tests of one wave's event: whether it may slide the
/// caisson (either model) or lift its seaward spring.
pub(super) fn may_slide(e: &PeakComponents, b: &ScreenBound) -> bool {
    let [p, u, m, _] = effective(e, b);
    // Sliding, or the seaward spring lifting off ((6 M/B) f ≥ W' − U): a rocking caisson
    // ratchets shoreward a little as its springs re-contact.
    p > b.mu * (b.weight_n - u) || 6.0 * m / b.width_m * b.lift_factor >= b.weight_n - u
}

/// The screen's bound on the heel pressure of one wave's event, Pa (module docs, "Heel
/// pressure"): the largest of [`heel_pressure_pa`] with M_eff and the springs' normal force at
/// either end of its range, W' − U_eff to W' + (Ψ − 1) U (for a fixed moment it is largest at an
/// end of a range of normal forces); infinite where W' − U_eff ≤ 0.
pub(super) fn heel_bound_pa(e: &PeakComponents, b: &ScreenBound) -> f64 {
    let [_, u, m, overshoot] = effective(e, b);
    let at = |v: f64| {
        if v <= 0.0 {
            f64::INFINITY
        } else {
            heel_pressure_pa(v / b.length_m, 0.5 * b.width_m - m / v, b.width_m)
        }
    };
    at(b.weight_n - u).max(at(b.weight_n + overshoot))
}

/// Whether the screen lets a wave through: it may slide or lift the caisson ([`may_slide`]), or
/// press its heel to the screen's heel pressure ([`heel_bound_pa`]).
fn may_pass(e: &PeakComponents, b: &ScreenBound) -> bool {
    may_slide(e, b) || heel_bound_pa(e, b) >= b.heel_screen_pa
}

/// What the screen's bound reads of the dynamic model ([`StormSite::bound`]): the same at every
/// storm of a caisson, whose tide and friction error change the caisson's weight in water, its
/// base depth and its friction, not its mass, added mass, stiffness or springs' places (the
/// still-water model's numbers to the bit, `tests::the_screen_reads_the_still_water_modes`), so
/// taken once per life from the still-water model.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct ScreenModes {
    /// T0 of the horizontal mode, and the longer of T0 and the rocking period, s.
    pub(super) t0_s: f64,
    pub(super) t_moment_s: f64,
    /// f of [`Model::lift_off_factor`].
    pub(super) lift_factor: f64,
}

impl ScreenModes {
    pub(super) fn of(m: &Model) -> Self {
        let t0_s = m.natural_period_s();
        ScreenModes { t0_s, t_moment_s: t0_s.max(m.rocking_period_s()), lift_factor: m.lift_off_factor() }
    }

    /// Those of the still-water model of `st`'s caisson.
    pub(super) fn still_water(st: &StormCase<'_>) -> Self {
        Self::of(&Model::new(&st.structure.caisson, &st.structure.foundation))
    }
}

/// The screen's grid of one storm (module docs, "The screen"): whether a wave may slide or lift
/// the caisson, at the nodes of a grid over the heights [0, H_max] (plus the breaker height at the
/// wall) and, for waves with periods of their own, over the storm's periods.
pub(super) struct StormScreen {
    /// Bit i of `node[j]`: at period node j, height i · dh (`SCREEN_CELLS` + 1 bits a row).
    pub(super) node: [u128; PERIOD_CELLS + 1],
    /// Period nodes: 1 (every wave at T1/3) or `PERIOD_CELLS + 1`.
    pub(super) periods: usize,
    /// The lowest height node that may slide at any period node (`None`: no node may, in a calm
    /// storm or without the screen).
    pub(super) first_node: Option<usize>,
    pub(super) dh: f64,
    /// τ̄, and u = 1 − τ̄/τ at the first period node and its step.
    mean_period_s: f64,
    u0: f64,
    du: f64,
    /// Nodes of the rows run that the bound left false without their loads (what the tests see
    /// of the bisection).
    #[cfg_attr(not(test), allow(dead_code))]
    pub(super) bound_nodes: usize,
}

impl StormScreen {
    /// The grid of storm `s` on `site` (every node false without the screen); `t13` are the
    /// loads and the bound at the storm's T1/3 (the one period node of waves at T1/3). The bound
    /// of the loads is used where [`StormCase::screen_load_bound`] has it.
    pub(super) fn new(
        st: &StormCase<'_>,
        s: &StormInput,
        site: &StormSite,
        t13: (&PeriodLoads<'_>, ScreenBound),
    ) -> Self {
        Self::grid(st, s, site, t13, st.screen_load_bound)
    }

    /// [`Self::new`]; `bisect`: leave the rows and the nodes the bound of the loads up to their
    /// height holds false without their loads (`false`: every node's loads, the tests' reference
    /// and [`StormCase::screen_load_bound`] off).
    pub(super) fn grid(
        st: &StormCase<'_>,
        s: &StormInput,
        site: &StormSite,
        t13: (&PeriodLoads<'_>, ScreenBound),
        bisect: bool,
    ) -> Self {
        let hmax = s.hmax_m.max(1e-6);
        let dh = hmax / SCREEN_CELLS as f64;
        let (periods, [u0, u1]) = match s.periods {
            WavePeriods::Significant => (1, [0.0, 0.0]),
            WavePeriods::LonguetHiggins { .. } => (PERIOD_CELLS + 1, periods::u_range()),
        };
        let mean_period_s = periods::MEAN_PERIOD_RATIO * s.period_s;
        let du = (u1 - u0) / PERIOD_CELLS as f64;
        let mut node = [0_u128; PERIOD_CELLS + 1];
        let mut bound_nodes = 0;
        for (j, row) in node.iter_mut().enumerate().take(if st.screen { periods } else { 0 }) {
            let own;
            let (loads_at, bound) = if periods == 1 {
                t13
            } else {
                let period_s = mean_period_s / (1.0 - (u0 + j as f64 * du));
                own = site.model.at_period(period_s);
                (&own, site.bound(period_s))
            };
            // Where even the bounds of the loads over all heights up to h cannot slide or lift the
            // caisson, every node up to h is false: at a period where that holds for H_max the
            // row is not needed, else the nodes up to the highest node height where it holds (by
            // bisection; the bound covers every lower node whatever the others give) are false
            // without their loads.
            let still_up_to = |h: f64| loads_at.peak_bound(h).is_some_and(|b| !may_pass(&s.scaled(&b), &bound));
            if bisect && still_up_to(hmax) {
                continue;
            }
            let node_h = |i: usize| (i as f64 * dh).max(1e-3 * hmax);
            // Nodes below `first` are false; the bound does not hold the caisson at node `last`.
            let (mut first, mut last) = (0, SCREEN_CELLS + 1);
            while bisect && last - first > 1 {
                let mid = (first + last) / 2;
                if still_up_to(node_h(mid - 1)) {
                    first = mid;
                } else {
                    last = mid;
                }
            }
            let node_may_slide =
                |h: f64| loads_at.peaks(h, RegimeChoice::Auto).map_or(true, |p| may_pass(&s.scaled(&p), &bound));
            bound_nodes += first;
            for i in first..=SCREEN_CELLS {
                *row |= u128::from(node_may_slide(node_h(i))) << i;
            }
            let hbr = loads_at.breaker_height_at_wall_m();
            if hbr < hmax {
                let i = (hbr / dh) as usize;
                let flag = node_may_slide(hbr);
                *row |= (u128::from(flag) << i) | (u128::from(flag) << (i + 1).min(SCREEN_CELLS));
            }
        }
        // Only the rows of the period nodes can hold a flag (the others stay false).
        let first_node = node[..periods].iter().map(|row| row.trailing_zeros() as usize).min().filter(|&i| i < 128);
        StormScreen { node, periods, first_node, dh, mean_period_s, u0, du, bound_nodes }
    }

    /// The period cells of the grid.
    #[cfg(test)]
    fn period_cells(&self) -> usize {
        (self.periods - 1).max(1)
    }

    /// Cell (c, j) = [c dh, (c + 1) dh] × [period node j, j + 1] may slide if a node within one
    /// cell of it may, in both directions.
    fn cell_may_slide(&self, c: usize, j: usize) -> bool {
        // Nodes c − 1 to c + 2 (within the grid): the bits below c + 3 less those below c − 1.
        let below = |i: usize| (1_u128 << i) - 1;
        let window = below((c + 3).min(SCREEN_CELLS + 1)) & !below(c.saturating_sub(1));
        self.node[j.saturating_sub(1)..=(j + 2).min(self.periods - 1)].iter().any(|row| row & window != 0)
    }

    /// Whether the cell of a wave of height `h` and period `period_s` may slide.
    pub(super) fn may_slide_at(&self, h: f64, period_s: f64) -> bool {
        let c = ((h / self.dh) as usize).min(SCREEN_CELLS - 1);
        let j = if self.periods == 1 {
            0
        } else {
            (((1.0 - self.mean_period_s / period_s - self.u0) / self.du).max(0.0) as usize).min(PERIOD_CELLS - 1)
        };
        self.cell_may_slide(c, j)
    }

    /// The lowest height cell that may slide at some period: two cells below the lowest node that
    /// may. Cell c reads the nodes c − 1 to c + 2 ([`Self::cell_may_slide`]), and the period cells
    /// together read every period node, so c may slide if and only if a node from c − 1 to c + 2
    /// may at some period: the lowest is max(0, i − 2) for the lowest such node i (at most
    /// `SCREEN_CELLS` − 2, a cell of the grid).
    pub(super) fn lowest_cell(&self) -> Option<usize> {
        self.first_node.map(|i| i.saturating_sub(2))
    }

    /// [`Self::lowest_cell`] cell by cell (the tests' reference).
    #[cfg(test)]
    pub(super) fn lowest_cell_by_cells(&self) -> Option<usize> {
        (0..SCREEN_CELLS).find(|&c| (0..self.period_cells()).any(|j| self.cell_may_slide(c, j)))
    }
}
