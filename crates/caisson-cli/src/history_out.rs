//! The files of one run's history, for `caisson run` on a `[load]` and on wave trains
//! (`train_out.rs`): `history.csv` and `springs.csv` streamed row by row, and the SVG plots drawn
//! from their bounded envelope.

use crate::output::TempFile;
use crate::plot::{panels, Panel, Series};
use anyhow::{Context, Result};
use caisson::analysis::envelope::{Column, HistoryEnvelope};
use caisson::analysis::run::HistoryRow;
use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

/// `history.csv` and `springs.csv` written row by row while the run proceeds, each to a
/// temporary file of its own ([`TempFile`]: created exclusively, removed if the run fails or is
/// stopped, renamed into place by [`Self::finish`]), and the bounded picture of the histories
/// that the plots are drawn from ([`HistoryEnvelope`]): a run of any length holds no history in
/// memory.
pub struct HistoryFiles {
    dir: PathBuf,
    history: (TempFile, BufWriter<File>),
    springs: (TempFile, BufWriter<File>),
    envelope: HistoryEnvelope,
    /// The first write error and its file; later rows are not written, and `finish` reports it.
    error: Option<(&'static str, std::io::Error)>,
}

const HISTORY_COLUMNS: [&str; 13] = [
    "time_s",
    "ux_m",
    "uy_m",
    "theta_rad",
    "vx_m_per_s",
    "fx_kn",
    "fy_kn",
    "moment_knm",
    "reaction_x_kn",
    "reaction_y_kn",
    "reaction_moment_knm",
    "sliding_resistance_kn",
    "sliding_springs",
];

impl HistoryFiles {
    /// Start both files in `dir` (which exists) with their header rows, for `springs` springs.
    pub fn create(dir: &Path, springs: usize) -> Result<Self> {
        let open = |name: &str| -> Result<(TempFile, BufWriter<File>)> {
            let (tmp, f) = TempFile::create(&dir.join(name))?;
            Ok((tmp, BufWriter::with_capacity(1 << 16, f)))
        };
        let mut files = HistoryFiles {
            dir: dir.to_path_buf(),
            history: open("history.csv")?,
            springs: open("springs.csv")?,
            envelope: HistoryEnvelope::new(),
            error: None,
        };
        let mut header = String::from("time_s");
        for (what, unit) in [("normal", "kn"), ("shear", "kn"), ("uy", "m")] {
            for i in 1..=springs {
                header.push_str(&format!(",{what}_{i}_{unit}"));
            }
        }
        let h = &mut files.history.1;
        let r = writeln!(h, "{}", HISTORY_COLUMNS.join(",")).and_then(|_| writeln!(files.springs.1, "{header}"));
        r.with_context(|| format!("writing {}", dir.join("history.csv").display()))?;
        Ok(files)
    }

    /// Write one row to both files (the same numbers, in the same text, as the whole-history
    /// writer of earlier versions) and add it to the picture.
    pub fn row(&mut self, r: &HistoryRow<'_>) {
        self.envelope.push(r);
        if self.error.is_none() {
            if let Err(e) = self.write_row(r) {
                self.error = Some(e);
            }
        }
    }

    fn write_row(&mut self, r: &HistoryRow<'_>) -> Result<(), (&'static str, std::io::Error)> {
        Self::history_row(&mut self.history.1, r).map_err(|e| ("history.csv", e))?;
        Self::springs_row(&mut self.springs.1, r).map_err(|e| ("springs.csv", e))
    }

    fn history_row(h: &mut impl Write, r: &HistoryRow<'_>) -> std::io::Result<()> {
        write!(h, "{},{:e},{:e},{:e},{:e}", r.t_s, r.ux_m, r.uy_m, r.theta_rad, r.vx_m_per_s)?;
        for v in [r.fx_n, r.fy_n, r.m_nm, r.reaction_x_n, r.reaction_y_n, r.reaction_m_nm, r.sliding_resistance_n] {
            write!(h, ",{}", v / 1e3)?;
        }
        writeln!(h, ",{}", r.sliding_springs)
    }

    fn springs_row(s: &mut impl Write, r: &HistoryRow<'_>) -> std::io::Result<()> {
        write!(s, "{}", r.t_s)?;
        for x in r.springs {
            write!(s, ",{}", x.normal_n / 1e3)?;
        }
        for x in r.springs {
            write!(s, ",{}", x.shear_n / 1e3)?;
        }
        for i in 0..r.springs.len() {
            write!(s, ",{:e}", r.spring_uy_m(i))?;
        }
        writeln!(s)
    }

    /// Flush both files and rename them into place; the picture of the histories for the plots.
    pub fn finish(self) -> Result<HistoryEnvelope> {
        let HistoryFiles { dir, history, springs, envelope, error } = self;
        if let Some((name, e)) = error {
            return Err(anyhow::Error::new(e).context(format!("writing {}", dir.join(name).display())));
        }
        for ((tmp, mut w), name) in [(history, "history.csv"), (springs, "springs.csv")] {
            let path = dir.join(name);
            w.flush().with_context(|| format!("writing {}", path.display()))?;
            drop(w);
            tmp.commit(&path)?;
        }
        Ok(envelope)
    }
}

pub fn write_plots(dir: &std::path::Path, h: &HistoryEnvelope, title: &str) -> Result<()> {
    let kn = |c: Column| -> Vec<(f64, f64)> { h.series(c).into_iter().map(|(t, v)| (t, v * 1e-3)).collect() };
    let scaled = |c: Column, k: f64| -> Vec<(f64, f64)> { h.series(c).into_iter().map(|(t, v)| (t, v * k)).collect() };
    panels(
        &dir.join("loads.svg"),
        &format!("Loads and reactions\n{title}"),
        "time (s)",
        &[
            Panel {
                y_label: "horizontal (kN)".into(),
                series: vec![
                    Series::line("wave force F_x", kn(Column::Fx)),
                    Series::line("base reaction R_x", kn(Column::ReactionX)),
                    Series::dashed("static sliding resistance", kn(Column::SlidingResistance)),
                ],
            },
            Panel {
                y_label: "vertical (kN)".into(),
                series: vec![
                    Series::line("uplift F_y", kn(Column::Fy)),
                    Series::line("Σ spring reactions", kn(Column::ReactionY)),
                ],
            },
            Panel {
                y_label: "moment (kN·m)".into(),
                series: vec![
                    Series::line("wave moment (clockwise +)", kn(Column::Moment)),
                    Series::line("base reaction moment", kn(Column::ReactionMoment)),
                ],
            },
        ],
    )?;
    panels(
        &dir.join("displacements.svg"),
        &format!("Displacements\n{title}"),
        "time (s)",
        &[
            Panel {
                y_label: "u_x (mm)".into(),
                series: vec![Series::line("horizontal (shoreward +)", scaled(Column::Ux, 1e3))],
            },
            Panel {
                y_label: "v_x (m/s)".into(),
                series: vec![Series::line("horizontal velocity", scaled(Column::Vx, 1.0))],
            },
            Panel {
                y_label: "u_y (mm)".into(),
                series: vec![Series::line("vertical (up +)", scaled(Column::Uy, 1e3))],
            },
            Panel {
                y_label: "θ (mrad)".into(),
                series: vec![Series::line("rotation (clockwise +)", scaled(Column::Theta, 1e3))],
            },
        ],
    )?;
    let per_spring = |column: fn(usize) -> Column| -> Vec<Series> {
        (0..h.springs()).map(|i| Series::line(format!("x = {:+.3} m", h.spring_x_m()[i]), kn(column(i)))).collect()
    };
    panels(
        &dir.join("springs.svg"),
        &format!("Spring reactions (seaward → shoreward)\n{title}"),
        "time (s)",
        &[
            Panel { y_label: "normal N_i (kN)".into(), series: per_spring(Column::Normal) },
            Panel { y_label: "shear F_i (kN)".into(), series: per_spring(Column::Shear) },
        ],
    )?;
    Ok(())
}
