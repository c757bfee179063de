//! A measured or computed force time series (flume, CFD), linearly interpolated.
//!
//! CSV header: `time_s,fx_kn,fy_kn,moment_knm` (moment of the wave forces about the centre of the
//! base, positive clockwise = shoreward overturning), or `time_s,fx_kn,fy_kn,horizontal_lever_m,
//! uplift_lever_m` (height of the horizontal resultant above the base; distance of the uplift
//! resultant from the heel). Forces are totals on the caisson in kN. Time must be strictly
//! increasing. Before the first sample and after the last, the first and last values are held.

use super::{LoadHistory, WaveForce};
use thiserror::Error;

/// Errors reading a force series. Line numbers are 1-based lines of the CSV file.
#[derive(Debug, Error, PartialEq)]
pub enum SeriesError {
    #[error("the header is `{found}`; expected `time_s,fx_kn,fy_kn,moment_knm` or `time_s,fx_kn,fy_kn,horizontal_lever_m,uplift_lever_m`")]
    BadHeader { found: String },
    #[error("line {line}: column `{column}` has `{value}`; expected a finite number")]
    BadNumber { line: usize, column: String, value: String },
    #[error("line {line}: column `{column}` has `{value}`; at most 1e300 in magnitude (a number this large overflows once converted to SI units)")]
    TooLarge { line: usize, column: String, value: String },
    #[error("line {line}: expected {expected} columns, found {found}")]
    WrongColumnCount { line: usize, expected: usize, found: usize },
    #[error("line {line}: time_s = {value} is not greater than the previous time {previous}; times must be strictly increasing")]
    Unsorted { line: usize, value: f64, previous: f64 },
    #[error("the series has {rows} data rows; at least 2 are needed")]
    TooShort { rows: usize },
    #[error("{0}")]
    Csv(String),
}

/// Sampled force series, stored in SI totals.
/// Most samples a force series may have: what the largest series file
/// (`scenario::validate::MAX_SERIES_BYTES`, 128 MiB) can hold at 8 bytes a row (`0,1,2,3`). A
/// longer series (the Python `run(t_s=...)`) is refused before anything is copied.
pub const MAX_SAMPLES: usize = (128 << 20) / 8;

#[derive(Debug, Clone)]
pub struct ForceSeries {
    t_s: Vec<f64>,
    f: Vec<WaveForce>,
    /// Samples per second on average, (n − 1)/(t_last − t_first): the first guess of the sample
    /// after a time (exact for evenly spaced samples).
    rate_per_s: f64,
}

impl ForceSeries {
    /// Parse CSV text. `width_m` is the base width, needed only for the lever-arm form.
    pub fn from_csv_str(text: &str, width_m: f64) -> Result<Self, SeriesError> {
        // Fields are trimmed here rather than by the reader (`csv::Trim::All` rebuilds every
        // record), and one record is reused for every row: the parse allocates nothing per row.
        let mut rdr = csv::ReaderBuilder::new().flexible(true).from_reader(text.as_bytes());
        let headers = rdr.headers().map_err(|e| SeriesError::Csv(e.to_string()))?.clone();
        let names: Vec<&str> = headers.iter().map(str::trim).collect();
        let levers = match names.as_slice() {
            ["time_s", "fx_kn", "fy_kn", "moment_knm"] => false,
            ["time_s", "fx_kn", "fy_kn", "horizontal_lever_m", "uplift_lever_m"] => true,
            _ => return Err(SeriesError::BadHeader { found: names.join(",") }),
        };
        let ncol = names.len();
        let mut t_s = Vec::new();
        let mut f = Vec::new();
        let mut rec = csv::StringRecord::new();
        for line in 2.. {
            match rdr.read_record(&mut rec) {
                Ok(true) => {}
                Ok(false) => break,
                Err(e) => return Err(SeriesError::Csv(format!("line {line}: {e}"))),
            }
            if rec.len() != ncol {
                return Err(SeriesError::WrongColumnCount { line, expected: ncol, found: rec.len() });
            }
            let mut v = [0.0; 5];
            for (j, field) in rec.iter().map(str::trim).enumerate() {
                let (column, value) = (|| names[j].to_string(), || field.to_string());
                v[j] = match field.parse::<f64>() {
                    Ok(x) if x.is_finite() && x.abs() <= crate::MAX_MAGNITUDE => x,
                    Ok(x) if x.is_finite() => {
                        return Err(SeriesError::TooLarge { line, column: column(), value: value() })
                    }
                    _ => return Err(SeriesError::BadNumber { line, column: column(), value: value() }),
                };
            }
            if let Some(&prev) = t_s.last() {
                if v[0] <= prev {
                    return Err(SeriesError::Unsorted { line, value: v[0], previous: prev });
                }
            }
            t_s.push(v[0]);
            let force = if levers {
                WaveForce::from_levers(v[1] * 1e3, v[3], v[2] * 1e3, v[4], width_m)
            } else {
                WaveForce { fx_n: v[1] * 1e3, fy_n: v[2] * 1e3, m_nm: v[3] * 1e3 }
            };
            f.push(force);
        }
        if t_s.len() < 2 {
            return Err(SeriesError::TooShort { rows: t_s.len() });
        }
        Ok(Self::from_samples(t_s, f))
    }

    /// Build directly from samples (SI): at least two, times strictly increasing.
    pub fn from_samples(t_s: Vec<f64>, f: Vec<WaveForce>) -> Self {
        assert!(t_s.len() == f.len() && t_s.len() >= 2, "two samples or more, one force per time");
        let rate_per_s = (t_s.len() - 1) as f64 / (t_s[t_s.len() - 1] - t_s[0]);
        ForceSeries { t_s, f, rate_per_s }
    }

    /// The index of the first sample strictly after `t_s` (`t_s.len()` if none): the binary
    /// search's answer, found from a guess by the mean sampling rate and a short walk (evenly
    /// spaced samples need at most one step), or by bisection if the walk is long.
    #[inline]
    fn index_after(&self, t_s: f64) -> usize {
        let n = self.t_s.len();
        let guess = ((t_s - self.t_s[0]) * self.rate_per_s).floor();
        let mut j = if guess.is_finite() { (guess.max(0.0) as usize + 1).min(n) } else { 0 };
        for _ in 0..4 {
            if j > 0 && self.t_s[j - 1] > t_s {
                j -= 1;
            } else if j < n && self.t_s[j] <= t_s {
                j += 1;
            } else {
                return j;
            }
        }
        self.t_s.partition_point(|&x| x <= t_s)
    }

    /// The largest |F_x|, |F_y| and |M| over the samples (each on its own), N and N·m.
    pub fn peak_abs(&self) -> WaveForce {
        self.f.iter().fold(WaveForce::ZERO, |p, f| WaveForce {
            fx_n: p.fx_n.max(f.fx_n.abs()),
            fy_n: p.fy_n.max(f.fy_n.abs()),
            m_nm: p.m_nm.max(f.m_nm.abs()),
        })
    }

    pub fn first_time_s(&self) -> f64 {
        self.t_s[0]
    }
    pub fn last_time_s(&self) -> f64 {
        *self.t_s.last().unwrap()
    }
}

impl LoadHistory for ForceSeries {
    fn at(&self, t_s: f64) -> WaveForce {
        let n = self.t_s.len();
        if t_s <= self.t_s[0] {
            return self.f[0];
        }
        if t_s >= self.t_s[n - 1] {
            return self.f[n - 1];
        }
        let j = self.index_after(t_s);
        let (t0, t1) = (self.t_s[j - 1], self.t_s[j]);
        let w = (t_s - t0) / (t1 - t0);
        self.f[j - 1].scaled(1.0 - w) + self.f[j].scaled(w)
    }
    fn end_time_s(&self) -> Option<f64> {
        Some(self.last_time_s())
    }
    fn next_breakpoint_s(&self, t_s: f64) -> f64 {
        self.t_s.get(self.index_after(t_s)).copied().unwrap_or(f64::INFINITY)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The guessed index is the binary search's, for even and uneven sampling, at and between
    /// samples and beyond both ends.
    #[test]
    fn the_index_guess_is_the_binary_search() {
        let even: Vec<f64> = (0..1000).map(|k| 0.01 * k as f64).collect();
        let uneven: Vec<f64> = (0..1000).map(|k| (k as f64).powf(1.7) * 1e-3).collect();
        let mut checked = 0;
        for t in [even, uneven] {
            let s = ForceSeries::from_samples(t.clone(), vec![WaveForce::ZERO; t.len()]);
            let (lo, hi) = (t[0] - 1.0, t[t.len() - 1] + 1.0);
            for k in 0..20_000 {
                let x = lo + (hi - lo) * k as f64 / 19_999.0;
                for x in [x, t[k % t.len()]] {
                    assert_eq!(s.index_after(x), t.partition_point(|&v| v <= x), "t = {x}");
                    checked += 1;
                }
            }
        }
        assert_eq!(checked, 80_000);
    }

    #[test]
    fn interpolates_linearly_and_holds_ends() {
        let s = ForceSeries::from_csv_str("time_s,fx_kn,fy_kn,moment_knm\n0,0,0,0\n1,2,1,4\n", 1.0).unwrap();
        let f = s.at(0.25);
        assert!((f.fx_n - 500.0).abs() < 1e-9 && (f.fy_n - 250.0).abs() < 1e-9 && (f.m_nm - 1000.0).abs() < 1e-9);
        assert_eq!(s.at(5.0).fx_n, 2000.0);
    }

    #[test]
    fn lever_form_gives_clockwise_moment() {
        // 1 kN at 0.5 m, 1 kN uplift at 2B/3 from the heel of B = 0.9 m: M = 0.5 + 0.15 kN·m.
        let s = ForceSeries::from_csv_str(
            "time_s,fx_kn,fy_kn,horizontal_lever_m,uplift_lever_m\n0,1,1,0.5,0.6\n1,1,1,0.5,0.6\n",
            0.9,
        )
        .unwrap();
        assert!((s.at(0.5).m_nm - 650.0).abs() < 1e-9);
    }

    #[test]
    fn rejects_unsorted_time_with_line_number() {
        let e =
            ForceSeries::from_csv_str("time_s,fx_kn,fy_kn,moment_knm\n0,0,0,0\n1,0,0,0\n0.5,0,0,0\n", 1.0).unwrap_err();
        assert_eq!(e, SeriesError::Unsorted { line: 4, value: 0.5, previous: 1.0 });
    }

    #[test]
    fn rejects_bad_number_and_header() {
        let e = ForceSeries::from_csv_str("time_s,fx_kn,fy_kn,moment_knm\n0,abc,0,0\n1,0,0,0\n", 1.0).unwrap_err();
        assert!(matches!(e, SeriesError::BadNumber { line: 2, .. }));
        let e = ForceSeries::from_csv_str("t,fx,fy,m\n0,0,0,0\n", 1.0).unwrap_err();
        assert!(matches!(e, SeriesError::BadHeader { .. }));
    }
}
