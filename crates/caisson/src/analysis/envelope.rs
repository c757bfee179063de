//! A bounded picture of a run's time histories, for plots: the smallest and the largest value of
//! every column in each of at most [`MAX_BUCKETS`] groups of consecutive rows, and the first and
//! last rows. A run of any length keeps at most `MAX_BUCKETS` × (11 + 2 n) × 4 numbers (n
//! springs): about 2 MB for ten springs, however many rows it writes.
//!
//! Rows are grouped in index order. While a run has at most [`MAX_BUCKETS`] rows each group is
//! one row and the picture is the history itself; at the next row every two neighbouring groups
//! are merged (the group doubles), and so on. Merging keeps each group's extremes, so every peak
//! of the history (a short impact, a slip) is in the picture however long the run; what a group
//! loses is the order of values between its extremes, narrower than a pixel of a plot once the
//! groups are more than the plot is wide.

use super::run::HistoryRow;

/// Most groups of rows kept (more than the ~800 pixel columns of a plot).
pub const MAX_BUCKETS: usize = 2048;

/// The scalar columns, in storage order.
const SCALARS: usize = 11;

/// A column of the picture.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Column {
    /// u_x, m.
    Ux,
    /// u_y, m.
    Uy,
    /// θ, rad.
    Theta,
    /// v_x, m/s.
    Vx,
    /// Horizontal wave force, N.
    Fx,
    /// Uplift, N.
    Fy,
    /// Wave moment, N·m.
    Moment,
    /// Horizontal reaction, N.
    ReactionX,
    /// Sum of the spring normal forces, N.
    ReactionY,
    /// Moment of the spring normal forces, N·m.
    ReactionMoment,
    /// μ_s (W' − F_y(t)), N.
    SlidingResistance,
    /// Normal force of spring i (0-based, seaward first), N.
    Normal(usize),
    /// Shear force of spring i, N.
    Shear(usize),
}

/// The bounded picture of a run's histories (module docs). Feed it every row with [`Self::push`].
#[derive(Debug, Clone, Default)]
pub struct HistoryEnvelope {
    springs: usize,
    spring_x_m: Vec<f64>,
    rows: u64,
    rows_per_bucket: u64,
    /// Per group, per column: time of the minimum, the minimum, time of the maximum, the maximum.
    buckets: Vec<f64>,
    /// The first and the latest row: time, then the columns.
    first: Vec<f64>,
    last: Vec<f64>,
}

impl HistoryEnvelope {
    pub fn new() -> Self {
        HistoryEnvelope { rows_per_bucket: 1, ..Default::default() }
    }

    fn columns(&self) -> usize {
        SCALARS + 2 * self.springs
    }

    fn index(&self, c: Column) -> usize {
        match c {
            Column::Ux => 0,
            Column::Uy => 1,
            Column::Theta => 2,
            Column::Vx => 3,
            Column::Fx => 4,
            Column::Fy => 5,
            Column::Moment => 6,
            Column::ReactionX => 7,
            Column::ReactionY => 8,
            Column::ReactionMoment => 9,
            Column::SlidingResistance => 10,
            Column::Normal(i) => {
                assert!(i < self.springs, "spring {i} of {}", self.springs);
                SCALARS + i
            }
            Column::Shear(i) => {
                assert!(i < self.springs, "spring {i} of {}", self.springs);
                SCALARS + self.springs + i
            }
        }
    }

    /// Add the next row (rows come in time order, all with the same springs).
    pub fn push(&mut self, r: &HistoryRow<'_>) {
        if self.rows == 0 {
            self.springs = r.springs.len();
            self.spring_x_m = r.spring_x_m.to_vec();
            self.rows_per_bucket = 1;
            self.buckets = Vec::with_capacity(MAX_BUCKETS * 4 * self.columns());
        }
        debug_assert_eq!(r.springs.len(), self.springs);
        let scalars = [
            r.ux_m,
            r.uy_m,
            r.theta_rad,
            r.vx_m_per_s,
            r.fx_n,
            r.fy_n,
            r.m_nm,
            r.reaction_x_n,
            r.reaction_y_n,
            r.reaction_m_nm,
            r.sliding_resistance_n,
        ];
        let values = || {
            scalars
                .iter()
                .copied()
                .chain(r.springs.iter().map(|s| s.normal_n))
                .chain(r.springs.iter().map(|s| s.shear_n))
        };
        self.last.clear();
        self.last.push(r.t_s);
        self.last.extend(values());
        if self.rows == 0 {
            self.first.clone_from(&self.last);
        }
        if (self.rows / self.rows_per_bucket) as usize == MAX_BUCKETS {
            self.halve();
        }
        let t = r.t_s;
        if self.rows.is_multiple_of(self.rows_per_bucket) {
            for v in values() {
                self.buckets.extend_from_slice(&[t, v, t, v]);
            }
        } else {
            let start = self.buckets.len() - 4 * self.columns();
            for (g, v) in self.buckets[start..].chunks_exact_mut(4).zip(values()) {
                if v < g[1] {
                    g[0] = t;
                    g[1] = v;
                }
                if v > g[3] {
                    g[2] = t;
                    g[3] = v;
                }
            }
        }
        self.rows += 1;
    }

    /// Merge every two neighbouring groups (the count of groups is even: `MAX_BUCKETS`).
    fn halve(&mut self) {
        let width = 4 * self.columns();
        let groups = self.buckets.len() / width;
        for j in 0..groups / 2 {
            for c in 0..self.columns() {
                let a = 2 * j * width + 4 * c;
                let b = a + width;
                let (at, av, bt, bv) = (self.buckets[a], self.buckets[a + 1], self.buckets[b], self.buckets[b + 1]);
                let (min_t, min_v) = if bv < av { (bt, bv) } else { (at, av) };
                let (at, av, bt, bv) =
                    (self.buckets[a + 2], self.buckets[a + 3], self.buckets[b + 2], self.buckets[b + 3]);
                let (max_t, max_v) = if bv > av { (bt, bv) } else { (at, av) };
                let o = j * width + 4 * c;
                self.buckets[o..o + 4].copy_from_slice(&[min_t, min_v, max_t, max_v]);
            }
        }
        self.buckets.truncate(groups / 2 * width);
        self.rows_per_bucket *= 2;
    }

    /// Rows pushed.
    pub fn rows(&self) -> u64 {
        self.rows
    }
    /// Groups of rows kept (at most [`MAX_BUCKETS`]).
    pub fn buckets(&self) -> usize {
        if self.rows == 0 {
            0
        } else {
            self.buckets.len() / (4 * self.columns())
        }
    }
    /// Numbers held (the memory the picture takes, in f64).
    pub fn numbers_held(&self) -> usize {
        self.buckets.capacity() + self.first.capacity() + self.last.capacity() + self.spring_x_m.capacity()
    }
    /// Springs of the rows.
    pub fn springs(&self) -> usize {
        self.springs
    }
    /// Spring positions, m.
    pub fn spring_x_m(&self) -> &[f64] {
        &self.spring_x_m
    }

    /// The points (t, value) of column `c` in time order: the first row, each group's minimum
    /// and maximum (one point if they are the same row), the last row. With at most
    /// [`MAX_BUCKETS`] rows, exactly the rows.
    pub fn series(&self, c: Column) -> Vec<(f64, f64)> {
        if self.rows == 0 {
            return Vec::new();
        }
        let k = self.index(c);
        let width = 4 * self.columns();
        let mut out: Vec<(f64, f64)> = Vec::with_capacity(2 * self.buckets() + 2);
        let mut add = |p: (f64, f64)| {
            if out.last() != Some(&p) {
                out.push(p);
            }
        };
        add((self.first[0], self.first[1 + k]));
        for g in self.buckets.chunks_exact(width) {
            let g = &g[4 * k..4 * k + 4];
            let (lo, hi) = ((g[0], g[1]), (g[2], g[3]));
            if lo == hi {
                add(lo);
            } else if lo.0 <= hi.0 {
                add(lo);
                add(hi);
            } else {
                add(hi);
                add(lo);
            }
        }
        add((self.last[0], self.last[1 + k]));
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::foundation::SpringResponse;

    fn row<'a>(t: f64, v: f64, springs: &'a [SpringResponse], x: &'a [f64]) -> HistoryRow<'a> {
        HistoryRow {
            t_s: t,
            ux_m: v,
            uy_m: -v,
            theta_rad: 0.0,
            vx_m_per_s: 0.0,
            fx_n: 2.0 * v,
            fy_n: 0.0,
            m_nm: 0.0,
            reaction_x_n: 0.0,
            reaction_y_n: 0.0,
            reaction_m_nm: 0.0,
            sliding_resistance_n: 0.0,
            sliding_springs: 0,
            springs,
            spring_x_m: x,
        }
    }

    /// A short history is kept exactly, row for row.
    #[test]
    fn a_short_history_is_the_history() {
        let springs = [SpringResponse::default(); 3];
        let x = [-0.2, 0.0, 0.2];
        let mut e = HistoryEnvelope::new();
        let n = MAX_BUCKETS;
        let value = |k: usize| ((k * 7919) % 1000) as f64 - 500.0;
        for k in 0..n {
            e.push(&row(k as f64 * 1e-3, value(k), &springs, &x));
        }
        let s = e.series(Column::Ux);
        assert_eq!(s.len(), n);
        for (k, p) in s.iter().enumerate() {
            assert_eq!(*p, (k as f64 * 1e-3, value(k)), "row {k}");
        }
        assert_eq!(e.series(Column::Normal(2)).len(), n, "a constant column too");
        assert_eq!(e.spring_x_m(), &x);
    }

    /// However many rows, the picture holds at most MAX_BUCKETS groups (the same memory after
    /// 10⁶ rows as after 10⁴), keeps the first and last rows and every extreme: a one-row spike
    /// anywhere, the global minimum, and each group's range.
    #[test]
    fn a_long_history_is_bounded_and_keeps_its_peaks() {
        let springs = [SpringResponse::default(); 10];
        let x = [0.0; 10];
        let mut e = HistoryEnvelope::new();
        let spike = 654_321usize;
        let dip = 999_000usize;
        let value = |k: usize| {
            if k == spike {
                1e3
            } else if k == dip {
                -1e3
            } else {
                (k as f64 * 0.01).sin()
            }
        };
        let n = 1_000_000usize;
        let mut held_at_10k = 0;
        for k in 0..n {
            e.push(&row(k as f64 * 1e-3, value(k), &springs, &x));
            assert!(e.buckets() <= MAX_BUCKETS, "row {k}: {} groups", e.buckets());
            if k == 10_000 {
                held_at_10k = e.numbers_held();
            }
        }
        assert_eq!(e.rows(), n as u64);
        assert!(e.buckets() > MAX_BUCKETS / 2, "{} groups", e.buckets());
        assert_eq!(e.numbers_held(), held_at_10k, "no growth from 10⁴ to 10⁶ rows");
        // 2048 groups × 31 columns × 4 numbers, and the two rows.
        assert!(e.numbers_held() <= MAX_BUCKETS * 31 * 4 + 2 * 32 + 10, "{}", e.numbers_held());
        for c in [Column::Ux, Column::Fx] {
            let s = e.series(c);
            let scale = if c == Column::Fx { 2.0 } else { 1.0 };
            assert!(s.len() <= 2 * MAX_BUCKETS + 2, "{} points", s.len());
            assert_eq!(s[0], (0.0, scale * value(0)));
            assert_eq!(*s.last().unwrap(), ((n - 1) as f64 * 1e-3, scale * value(n - 1)));
            assert!(s.windows(2).all(|w| w[0].0 < w[1].0), "in time order");
            assert!(s.contains(&(spike as f64 * 1e-3, scale * 1e3)), "the spike is kept");
            assert!(s.contains(&(dip as f64 * 1e-3, -scale * 1e3)), "the dip is kept");
        }
        // The sine's extremes (±1 within 1e-4 at this sampling) are in the picture.
        let s = e.series(Column::Uy);
        let top = s.iter().filter(|p| p.1 < 999.0).map(|p| p.1).fold(f64::MIN, f64::max);
        assert!((top - 1.0).abs() < 1e-4, "{top}");
        let bottom = s.iter().filter(|p| p.1 > -999.0).map(|p| p.1).fold(f64::MAX, f64::min);
        assert!((bottom + 1.0).abs() < 1e-4, "{bottom}");
    }
}
