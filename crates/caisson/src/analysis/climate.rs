//! The site's climate of a lifetime run beyond the one model of Shimosako & Takahashi (1999): how
//! many storms a year bring, how long they last, where the waves come from, how the estimation
//! errors are drawn and how the still-water level rises over the life (docs/design.md, "Climate").
//! Every default is today's model ([`Climate::default`]: one storm a year, a fixed duration,
//! head-on waves, errors per storm, no rise), and a default climate draws no number: a run with
//! the defaults is Shimosako & Takahashi's model alone, and a file without climate keys keeps its
//! checkpoint fingerprint (`tests/verify_climate.rs`,
//! `default_climate_leaves_the_fingerprint_unchanged`).
//!
//! **Storms** ([`StormModel`]). Annual maxima (the default): one storm a year, its deep-water H0 the
//! annual maximum of `[design] storm_distribution`. Peaks over threshold (the partial-duration
//! series of extreme-value analysis: the storms above a threshold, fitted by an extreme-value
//! distribution, their yearly number Poisson; Goda 2000, ch. 11; Coles 2001, ch. 4): the number
//! of storms in a year is Poisson with mean λ (`storm_rate_per_year`), P(n) = e^−λ λ^n / n!,
//! drawn by inversion of one uniform; each storm's H0 is an exceedance of the
//! threshold u (`storm_threshold_m`) from the fitted distribution F: H0 = F⁻¹(F(u) + U (1 − F(u))),
//! the distribution of H given H > u.
//!
//! **Durations** ([`StormDuration`]). Fixed (the default): every storm's peak lasts
//! `storm_duration_h`. Lognormal: the duration D of each storm is lognormal with mean D̄
//! (`storm_duration_h`) and coefficient of variation c (`storm_duration_cov`):
//! ln D ~ N(μ, σ²), σ² = ln(1 + c²), μ = ln D̄ − σ²/2, so E[D] = D̄ and Var D = (c D̄)²; D is
//! limited to [`MAX_STORM_DURATION_S`] (72 h, the largest fixed duration; at c ≤ 0.5 and
//! D̄ ≤ 6 h the limit moves the mean by less than 10⁻⁶ of it, at c = 1 and D̄ = 12 h by 1 %).
//! N = round(D / T1/3) waves as before.
//!
//! **Sea level** ([`SeaLevelRise`]). The still-water level rises over the life by r(t), t the time
//! of the storm in years from the start of the life (the storms of year y at t = y + ½, the middle
//! of their year): linearly, r(t) = R t / N_y with R the rise at the end of the life
//! (`sea_level_rise_m`), or by linear interpolation in a table of years and metres
//! (`sea_level_rise_table`; constant beyond its ends), as sea-level-rise scenarios are given
//! (IPCC AR6 WG1 ch. 9 gives projections by year). The rise is added to the tide: every depth
//! grows by ζ + r(t), the crest freeboard and the weight in water fall with it (docs/model.md §6.4
//! step 3). No number is drawn.
//!
//! **Directions** ([`WaveDirection`]). Head-on (the default): every storm's waves meet the
//! breakwater along its normal. Otherwise each storm draws its angle θ to the normal: normal about
//! a mean θ̄ with standard deviation σ_θ (θ = θ̄ + σ_θ z), or uniform on θ̄ ± w (θ = θ̄ + w (2U − 1)),
//! limited to ±90° (the variability of the wave direction that Hong, Suh & Kweon 2004 found to
//! change the expected sliding markedly; the distribution they used was not recovered, so both
//! shapes are offered). The angle acts through Goda's β ([`crate::loads::goda`]: η* = 0.75
//! (1 + cos β) H, p1 = ½ (1 + cos β)(α1 + α2 cos²β) ρ g H, pu = ½ (1 + cos β) α1 α3 ρ g H, with
//! β = max(0, |θ| − 15°), the direction rotated by up to 15° toward the normal; docs/model.md §1.1,
//! Goda 2000) on the quasi-static and uplift loads of every wave of the storm. The
//! impact of a breaking wave (the seed's Eq. 30, Cuomo et al. 2010) has no angle: it was fitted to
//! flume tests, all under normal incidence, and no rule for oblique waves comes with it; caisson
//! applies it unreduced to oblique waves (on the safe side: oblique breaking waves strike the wall
//! along its length, not all at once). The breaking criterion and the surf-zone transformation
//! stay those of normal incidence (no refraction).
//!
//! **Periods** ([`WavePeriods`], [`crate::waves::periods`]). Every wave at the storm's T1/3 (the
//! default), or each wave's period given its height from the joint distribution of Longuet-Higgins
//! (1983); drawn per wave from the storm's part of the stream ([`super::lifetime`]).

use crate::check::{self, interval};
use crate::loads::risetime::LoadRng;
pub use crate::waves::periods::WavePeriods;
use crate::ParamError;
use rand::Rng;
use rand_distr::StandardNormal;
use std::f64::consts::FRAC_PI_2;

/// The climate's choices (module docs); the default is today's model.
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize)]
pub struct Climate {
    pub storms: StormModel,
    pub duration: StormDuration,
    pub sea_level: SeaLevelRise,
    pub direction: WaveDirection,
    /// The waves' periods: every wave at T1/3, or each its own ([`crate::waves::periods`]); not
    /// serialized when every wave is at T1/3, so the fingerprints of the other choices stay.
    #[serde(skip_serializing_if = "WavePeriods::is_significant")]
    pub periods: WavePeriods,
}

impl Climate {
    /// Whether every choice is today's (a run then draws exactly the numbers it drew before).
    pub fn is_default(&self) -> bool {
        *self == Climate::default()
    }

    /// The choices if their parameters are in range: the durations' ([`StormDuration::checked`]),
    /// the sea level's ([`SeaLevelRise::checked`]: a table's point refused as its quantity), the
    /// directions' ([`WaveDirection::checked`]) and the periods'
    /// ([`WavePeriods::longuet_higgins`]). (A storm model's rules need its distribution:
    /// `lifetime::StormDistribution::peaks_over_threshold`.)
    pub fn checked(self) -> Result<Self, ParamError> {
        self.duration.checked()?;
        self.sea_level.clone().checked().map_err(|e| match e {
            SeaLevelError::Points { count } => {
                check::rule("points", count as f64, format!("must list 1 to {MAX_SEA_LEVEL_POINTS} points"))
            }
            SeaLevelError::Point { error, .. } => error,
        })?;
        self.direction.checked()?;
        if let WavePeriods::LonguetHiggins { spectral_width } = self.periods {
            WavePeriods::longuet_higgins(spectral_width)?;
        }
        Ok(self)
    }
}

/// How many storms a year brings, and which distribution their peaks follow (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum StormModel {
    /// One storm a year, the annual maximum (Shimosako & Takahashi 1999).
    #[default]
    AnnualMaxima,
    /// A Poisson number of storms a year of mean `rate_per_year`, each an exceedance of
    /// `threshold_m` (deep-water H1/3, m).
    PeaksOverThreshold { rate_per_year: f64, threshold_m: f64 },
}

/// The largest `[design] storm_rate_per_year`: the Poisson inversion stays exact in f64 (e^−λ is
/// far above the smallest normal number) and a 1000-year life holds at most some 10⁵ storms.
pub const MAX_STORM_RATE_PER_YEAR: f64 = 50.0;

impl StormModel {
    /// The number of storms of one year: 1 for annual maxima (no number drawn), a Poisson number
    /// of mean λ from one uniform otherwise.
    pub fn storms_in_year(&self, rng: &mut LoadRng) -> usize {
        match *self {
            StormModel::AnnualMaxima => 1,
            StormModel::PeaksOverThreshold { rate_per_year, .. } => poisson_inverse(rate_per_year, rng.gen()),
        }
    }

    /// The mean number of storms a year.
    pub fn mean_storms_per_year(&self) -> f64 {
        match *self {
            StormModel::AnnualMaxima => 1.0,
            StormModel::PeaksOverThreshold { rate_per_year, .. } => rate_per_year,
        }
    }
}

/// How long the peak of a storm lasts (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum StormDuration {
    /// Every storm lasts `storm_duration_s` (no number drawn).
    #[default]
    Fixed,
    /// Lognormal of mean `storm_duration_s` and coefficient of variation `cov`.
    Lognormal { cov: f64 },
}

/// The longest storm, s (72 h: the largest `[design] storm_duration_h`).
pub const MAX_STORM_DURATION_S: f64 = 72.0 * 3600.0;

/// The largest `[design] storm_duration_cov`.
pub const MAX_STORM_DURATION_COV: f64 = 2.0;

impl StormDuration {
    /// Lognormal durations of coefficient of variation `cov` in (0, [`MAX_STORM_DURATION_COV`]],
    /// refused naming `duration_cov`.
    pub fn lognormal(cov: f64) -> Result<Self, ParamError> {
        StormDuration::Lognormal { cov }.checked()
    }

    /// The durations if their COV is in range ([`Self::lognormal`]).
    pub fn checked(self) -> Result<Self, ParamError> {
        if let StormDuration::Lognormal { cov } = self {
            interval("duration_cov", cov, 0.0, MAX_STORM_DURATION_COV, true)?;
        }
        Ok(self)
    }

    /// The duration of one storm of mean `mean_s`, s: `mean_s` (fixed), or one lognormal draw (one
    /// standard normal) limited to [`MAX_STORM_DURATION_S`].
    pub fn draw_s(&self, mean_s: f64, rng: &mut LoadRng) -> f64 {
        match *self {
            StormDuration::Fixed => mean_s,
            StormDuration::Lognormal { cov } => {
                let s2 = (1.0 + cov * cov).ln();
                let z: f64 = rng.sample(StandardNormal);
                (mean_s.ln() - 0.5 * s2 + s2.sqrt() * z).exp().min(MAX_STORM_DURATION_S)
            }
        }
    }
}

/// How the still-water level rises over the life (module docs).
#[derive(Debug, Clone, PartialEq, Default, serde::Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum SeaLevelRise {
    /// No rise (the default).
    #[default]
    None,
    /// r(t) = `rise_m` · t / `life_years`: `rise_m` at the end of the life.
    Linear { rise_m: f64, life_years: f64 },
    /// Linear interpolation in (year, m) points, years increasing; constant beyond the ends.
    Table { points: Vec<(f64, f64)> },
}

/// The largest rise of `[design] sea_level_rise_m` and of a table's levels, m.
pub const MAX_SEA_LEVEL_RISE_M: f64 = 5.0;

/// Most points of a sea-level table.
pub const MAX_SEA_LEVEL_POINTS: usize = 1000;

/// Why a sea-level rise is refused: too few or too many points, or the point `index`.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SeaLevelError {
    #[error("{count} points: must list 1 to {MAX_SEA_LEVEL_POINTS} points")]
    Points { count: usize },
    #[error("point {index}: {error}")]
    Point { index: usize, error: ParamError },
}

impl SeaLevelRise {
    /// A linear rise to `rise_m` at the end of a life of `life_years`: from 0 to
    /// [`MAX_SEA_LEVEL_RISE_M`], refused naming `rise_m`.
    pub fn linear(rise_m: f64, life_years: usize) -> Result<Self, ParamError> {
        interval("rise_m", rise_m, 0.0, MAX_SEA_LEVEL_RISE_M, false)?;
        Ok(SeaLevelRise::Linear { rise_m, life_years: life_years as f64 })
    }

    /// A table of (years from the start of the life, rise m) points: 1 to
    /// [`MAX_SEA_LEVEL_POINTS`] points, years from 0 to 1000 and increasing, rises from 0 to
    /// [`MAX_SEA_LEVEL_RISE_M`]; a point refused by its index and `years` or `rise_m`.
    pub fn table(points: Vec<(f64, f64)>) -> Result<Self, SeaLevelError> {
        SeaLevelRise::Table { points }.checked()
    }

    /// The rise if in range ([`Self::linear`], [`Self::table`]).
    pub fn checked(self) -> Result<Self, SeaLevelError> {
        match &self {
            SeaLevelRise::None => {}
            SeaLevelRise::Linear { rise_m, .. } => {
                interval("rise_m", *rise_m, 0.0, MAX_SEA_LEVEL_RISE_M, false)
                    .map_err(|error| SeaLevelError::Point { index: 0, error })?;
            }
            SeaLevelRise::Table { points } => {
                if points.is_empty() || points.len() > MAX_SEA_LEVEL_POINTS {
                    return Err(SeaLevelError::Points { count: points.len() });
                }
                for (index, &(y, r)) in points.iter().enumerate() {
                    let at = |error| SeaLevelError::Point { index, error };
                    interval("years", y, 0.0, 1000.0, false).map_err(at)?;
                    interval("rise_m", r, 0.0, MAX_SEA_LEVEL_RISE_M, false).map_err(at)?;
                    if let Some(&(y0, _)) = index.checked_sub(1).map(|i| &points[i]) {
                        if y <= y0 {
                            let rule =
                                format!("must be larger than the year before it ({y0}): the years must increase");
                            return Err(at(check::rule("years", y, rule)));
                        }
                    }
                }
            }
        }
        Ok(self)
    }

    /// The rise at `t_years` from the start of the life, m.
    pub fn rise_m(&self, t_years: f64) -> f64 {
        match self {
            SeaLevelRise::None => 0.0,
            SeaLevelRise::Linear { rise_m, life_years } => rise_m * t_years / life_years,
            SeaLevelRise::Table { points } => match points.iter().position(|&(y, _)| y > t_years) {
                None => points.last().map_or(0.0, |p| p.1),
                Some(0) => points[0].1,
                Some(i) => {
                    let ((y0, r0), (y1, r1)) = (points[i - 1], points[i]);
                    r0 + (r1 - r0) * (t_years - y0) / (y1 - y0)
                }
            },
        }
    }

    /// The rise at the storms of year `year` (counting from 0): at its middle, m.
    pub fn rise_in_year_m(&self, year: usize) -> f64 {
        self.rise_m(year as f64 + 0.5)
    }

    /// The highest rise over a life of `life_years` years (at the storms' times), m.
    pub fn max_rise_m(&self, life_years: usize) -> f64 {
        match self {
            SeaLevelRise::None => 0.0,
            // Piecewise linear: the largest value is at an end or at a point inside the life.
            _ => (0..life_years).map(|y| self.rise_in_year_m(y)).fold(0.0, f64::max),
        }
    }
}

/// Where a storm's waves come from: their angle θ to the breakwater's normal (module docs).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum WaveDirection {
    /// θ = 0 for every storm (no number drawn).
    #[default]
    HeadOn,
    /// θ = mean + sd · z, z standard normal, rad.
    Normal { mean_rad: f64, sd_rad: f64 },
    /// θ = mean + half_width · (2U − 1), rad.
    Uniform { mean_rad: f64, half_width_rad: f64 },
}

/// The largest |mean| angle of `[design] wave_direction_mean_deg`, degrees.
pub const MAX_MEAN_ANGLE_DEG: f64 = 75.0;
/// The largest spread (`[design] wave_direction_spread_deg`), degrees.
pub const MAX_ANGLE_SPREAD_DEG: f64 = 45.0;

impl WaveDirection {
    /// Normal angles about `mean_deg` (from −[`MAX_MEAN_ANGLE_DEG`] to [`MAX_MEAN_ANGLE_DEG`])
    /// with standard deviation `sd_deg` in (0, [`MAX_ANGLE_SPREAD_DEG`]], degrees; refused naming
    /// `mean_deg` or `sd_deg`.
    pub fn normal_deg(mean_deg: f64, sd_deg: f64) -> Result<Self, ParamError> {
        let mean_rad = mean_angle_deg(mean_deg)? * DEG;
        Ok(WaveDirection::Normal { mean_rad, sd_rad: spread_deg("sd_deg", sd_deg)? * DEG })
    }

    /// Uniform angles on `mean_deg` ± `half_width_deg`, degrees, in the ranges of
    /// [`Self::normal_deg`]; refused naming `mean_deg` or `half_width_deg`.
    pub fn uniform_deg(mean_deg: f64, half_width_deg: f64) -> Result<Self, ParamError> {
        let mean_rad = mean_angle_deg(mean_deg)? * DEG;
        Ok(WaveDirection::Uniform { mean_rad, half_width_rad: spread_deg("half_width_deg", half_width_deg)? * DEG })
    }

    /// The directions if in the ranges of [`Self::normal_deg`] (in radians; a spread may be 0,
    /// where a spread of a few 1e-324 degrees underflows).
    pub fn checked(self) -> Result<Self, ParamError> {
        let (mean_rad, spread, spread_rad) = match self {
            WaveDirection::HeadOn => return Ok(self),
            WaveDirection::Normal { mean_rad, sd_rad } => (mean_rad, "sd_rad", sd_rad),
            WaveDirection::Uniform { mean_rad, half_width_rad } => (mean_rad, "half_width_rad", half_width_rad),
        };
        let hi = MAX_MEAN_ANGLE_DEG * DEG;
        interval("mean_rad", mean_rad, -hi, hi, false)?;
        interval(spread, spread_rad, 0.0, MAX_ANGLE_SPREAD_DEG * DEG, false)?;
        Ok(self)
    }

    /// The angle of one storm, rad, limited to ±π/2: 0 (head-on, nothing drawn), or one draw (a
    /// standard normal, or a uniform).
    pub fn draw_rad(&self, rng: &mut LoadRng) -> f64 {
        let theta = match *self {
            WaveDirection::HeadOn => return 0.0,
            WaveDirection::Normal { mean_rad, sd_rad } => mean_rad + sd_rad * rng.sample::<f64, _>(StandardNormal),
            WaveDirection::Uniform { mean_rad, half_width_rad } => {
                mean_rad + half_width_rad * (2.0 * rng.gen::<f64>() - 1.0)
            }
        };
        theta.clamp(-FRAC_PI_2, FRAC_PI_2)
    }
}

/// One degree, rad.
const DEG: f64 = std::f64::consts::PI / 180.0;

/// A mean angle to the normal, degrees, from −[`MAX_MEAN_ANGLE_DEG`] to [`MAX_MEAN_ANGLE_DEG`].
fn mean_angle_deg(v: f64) -> Result<f64, ParamError> {
    interval("mean_deg", v, -MAX_MEAN_ANGLE_DEG, MAX_MEAN_ANGLE_DEG, false)
}

/// A spread of angles, degrees, in (0, [`MAX_ANGLE_SPREAD_DEG`]].
fn spread_deg(quantity: &'static str, v: f64) -> Result<f64, ParamError> {
    interval(quantity, v, 0.0, MAX_ANGLE_SPREAD_DEG, true)
}

/// The smallest n with P(N ≤ n) > u for N Poisson of mean `rate` (inversion by sequential search,
/// Devroye 1986 §X.3), u in [0, 1). Bounded: it stops at λ + 40 √λ + 40, beyond which the
/// probability left is far below the resolution of u.
pub fn poisson_inverse(rate: f64, u: f64) -> usize {
    let cap = (rate + 40.0 * rate.sqrt() + 40.0) as usize;
    let mut p = (-rate).exp();
    let mut cdf = p;
    let mut n = 0;
    while cdf <= u && n < cap {
        n += 1;
        p *= rate / n as f64;
        cdf += p;
    }
    n
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::loads::generator::realization_rng;

    /// Each constructor refuses a value outside its range by itself, naming the quantity (a
    /// table's point by its index); the ends of the ranges are allowed, and the angles of the
    /// degree constructors pass the radian check (the same conversion).
    #[test]
    fn climate_constructors_name_what_they_refuse() {
        assert_eq!(StormDuration::lognormal(2.0), Ok(StormDuration::Lognormal { cov: 2.0 }));
        assert_eq!(StormDuration::lognormal(0.0).unwrap_err().quantity, "duration_cov");
        assert_eq!(SeaLevelRise::linear(5.0, 50), Ok(SeaLevelRise::Linear { rise_m: 5.0, life_years: 50.0 }));
        assert_eq!(SeaLevelRise::linear(5.01, 50).unwrap_err().quantity, "rise_m");
        assert!(SeaLevelRise::table(vec![(0.0, 0.0), (1000.0, 5.0)]).is_ok());
        assert_eq!(SeaLevelRise::table(vec![]), Err(SeaLevelError::Points { count: 0 }));
        assert_eq!(SeaLevelRise::table(vec![(0.0, 0.0); 1001]), Err(SeaLevelError::Points { count: 1001 }));
        let point = |points: Vec<(f64, f64)>| match SeaLevelRise::table(points) {
            Err(SeaLevelError::Point { index, error }) => (index, error.quantity),
            other => panic!("{other:?}"),
        };
        assert_eq!(point(vec![(0.0, 0.0), (10.0, 0.1), (10.0, 0.2)]), (2, "years"));
        assert_eq!(point(vec![(1000.5, 0.0)]), (0, "years"));
        assert_eq!(point(vec![(0.0, 0.0), (10.0, -0.1)]), (1, "rise_m"));
        let d = WaveDirection::normal_deg(-75.0, 45.0).unwrap();
        assert_eq!(d, WaveDirection::Normal { mean_rad: -75.0 * DEG, sd_rad: 45.0 * DEG });
        assert_eq!(d.checked(), Ok(d));
        assert_eq!(WaveDirection::normal_deg(75.5, 10.0).unwrap_err().quantity, "mean_deg");
        assert_eq!(WaveDirection::normal_deg(0.0, 0.0).unwrap_err().quantity, "sd_deg");
        assert_eq!(WaveDirection::uniform_deg(0.0, 45.5).unwrap_err().quantity, "half_width_deg");
        let wide = WaveDirection::Uniform { mean_rad: 0.0, half_width_rad: 1.0 };
        assert_eq!(wide.checked().unwrap_err().quantity, "half_width_rad");
        // The smallest spread in degrees is allowed, and its 0 rad too.
        assert_eq!(WaveDirection::normal_deg(0.0, 5e-324).unwrap().checked().map(|_| ()), Ok(()));
        let climate = Climate { duration: StormDuration::Lognormal { cov: -1.0 }, ..Climate::default() };
        assert_eq!(climate.checked().unwrap_err().quantity, "duration_cov");
        let climate = Climate { periods: WavePeriods::LonguetHiggins { spectral_width: 0.9 }, ..Climate::default() };
        assert_eq!(climate.checked().unwrap_err().quantity, "spectral_width");
        assert_eq!(Climate::default().checked(), Ok(Climate::default()));
    }

    /// The counts of 200 000 years at λ = 3.7 and 0.4: the sample mean and variance are both λ
    /// (the Poisson's mean and variance) within 5 standard errors: the mean's is (λ/n)^½, the
    /// variance's (λ (1 + 2λ)/n)^½ (the fourth central moment of a Poisson is λ + 3λ²).
    #[test]
    fn storm_counts_have_the_poisson_mean_and_variance() {
        let n = 200_000;
        let mut checked = 0;
        for rate in [3.7, 0.4] {
            let m = StormModel::PeaksOverThreshold { rate_per_year: rate, threshold_m: 1.0 };
            let mut rng = realization_rng(7, 0);
            let counts: Vec<f64> = (0..n).map(|_| m.storms_in_year(&mut rng) as f64).collect();
            let mean = counts.iter().sum::<f64>() / n as f64;
            let var = counts.iter().map(|c| (c - mean).powi(2)).sum::<f64>() / (n - 1) as f64;
            assert!((mean - rate).abs() < 5.0 * (rate / n as f64).sqrt(), "λ = {rate}: mean {mean}");
            assert!((var - rate).abs() < 5.0 * (rate * (1.0 + 2.0 * rate) / n as f64).sqrt(), "λ = {rate}: var {var}");
            checked += 1;
        }
        assert_eq!(checked, 2);
    }

    /// 200 000 lognormal durations of mean 2 h and COV 0.6: the sample mean within 5 standard
    /// errors (σ_D/√n = 0.0027 h) of 2 h, the sample standard deviation within 3 % of c D̄ = 1.2 h
    /// (its standard error is about 1 % at this COV: the lognormal's kurtosis); fixed durations
    /// draw nothing.
    #[test]
    fn lognormal_durations_have_the_stated_mean_and_cov() {
        let n = 200_000;
        let d = StormDuration::Lognormal { cov: 0.6 };
        let mut rng = realization_rng(3, 1);
        let x: Vec<f64> = (0..n).map(|_| d.draw_s(7200.0, &mut rng) / 3600.0).collect();
        assert_eq!(x.len(), n);
        let mean = x.iter().sum::<f64>() / n as f64;
        let sd = (x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt();
        assert!((mean - 2.0).abs() < 5.0 * 1.2 / (n as f64).sqrt(), "mean {mean} h");
        assert!((sd / 1.2 - 1.0).abs() < 0.03, "sd {sd} h");
        let mut a = realization_rng(3, 1);
        let b = a.clone();
        assert_eq!(StormDuration::Fixed.draw_s(7200.0, &mut a), 7200.0);
        assert_eq!(a.get_word_pos(), b.get_word_pos());
    }

    /// The path by hand: 0.5 m over 100 years is 0.25 m at 50 years and 0.0025 m at the storm of
    /// year 0 (t = ½); the table [(0, 0), (50, 0.2), (100, 0.5)] gives 0.1 m at 25 years, 0.32 m
    /// at 70, 0.5 m beyond 100 and 0 before 0; its largest rise over a 60-year life is at t = 59.5
    /// years, 0.2 + 0.3 · 9.5/50 = 0.257 m.
    #[test]
    fn sea_level_paths_by_hand() {
        let lin = SeaLevelRise::Linear { rise_m: 0.5, life_years: 100.0 };
        assert!((lin.rise_m(50.0) - 0.25).abs() < 1e-15);
        assert!((lin.rise_in_year_m(0) - 0.0025).abs() < 1e-15);
        assert!((lin.max_rise_m(100) - 0.4975).abs() < 1e-12);
        let tab = SeaLevelRise::Table { points: vec![(0.0, 0.0), (50.0, 0.2), (100.0, 0.5)] };
        let cases = [(25.0, 0.1), (70.0, 0.32), (100.0, 0.5), (130.0, 0.5), (-1.0, 0.0), (0.0, 0.0), (50.0, 0.2)];
        for (t, r) in cases {
            assert!((tab.rise_m(t) - r).abs() < 1e-12, "t = {t}: {}", tab.rise_m(t));
        }
        assert!((tab.max_rise_m(60) - 0.257).abs() < 1e-12);
        assert_eq!(SeaLevelRise::None.max_rise_m(50), 0.0);
        assert_eq!(cases.len(), 7);
    }

    /// 200 000 storm angles: normal about 20° with σ 10° (the ±90° limit is 7σ away), mean within
    /// 5 standard errors (σ/√n), standard deviation within 1 %; uniform on 30° ± 20°, mean within
    /// 5 standard errors (w/√(3n)), variance w²/3 within 1 %, none outside; head-on draws nothing.
    #[test]
    fn direction_moments() {
        let n = 200_000;
        let deg = std::f64::consts::PI / 180.0;
        let cases = [
            (WaveDirection::Normal { mean_rad: 20.0 * deg, sd_rad: 10.0 * deg }, 20.0, 10.0),
            (WaveDirection::Uniform { mean_rad: 30.0 * deg, half_width_rad: 20.0 * deg }, 30.0, 20.0 / 3f64.sqrt()),
        ];
        for (d, mean_deg, sd_deg) in cases {
            let mut rng = realization_rng(11, 4);
            let x: Vec<f64> = (0..n).map(|_| d.draw_rad(&mut rng) / deg).collect();
            let mean = x.iter().sum::<f64>() / n as f64;
            let sd = (x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt();
            assert!((mean - mean_deg).abs() < 5.0 * sd_deg / (n as f64).sqrt(), "{d:?}: mean {mean}");
            assert!((sd / sd_deg - 1.0).abs() < 0.01, "{d:?}: sd {sd}");
            if let WaveDirection::Uniform { .. } = d {
                assert!(x.iter().all(|&v| (10.0 - 1e-9..=50.0 + 1e-9).contains(&v)));
            }
        }
        let mut a = realization_rng(11, 4);
        let b = a.clone();
        assert_eq!(WaveDirection::HeadOn.draw_rad(&mut a), 0.0);
        assert_eq!(a.get_word_pos(), b.get_word_pos());
        assert_eq!(cases.len(), 2);
    }

    /// The inversion against the Poisson CDF by hand at λ = 2: P(0) = e^−2 = 0.1353,
    /// P(≤1) = 3 e^−2 = 0.4060, P(≤2) = 5 e^−2 = 0.6767.
    #[test]
    fn poisson_inversion_by_hand() {
        let e = (-2.0f64).exp();
        assert_eq!(poisson_inverse(2.0, 0.0), 0);
        assert_eq!(poisson_inverse(2.0, e - 1e-12), 0);
        assert_eq!(poisson_inverse(2.0, e + 1e-12), 1);
        assert_eq!(poisson_inverse(2.0, 3.0 * e + 1e-12), 2);
        assert_eq!(poisson_inverse(2.0, 5.0 * e - 1e-12), 2);
        assert_eq!(poisson_inverse(2.0, 5.0 * e + 1e-12), 3);
        assert_eq!(StormModel::AnnualMaxima.storms_in_year(&mut realization_rng(1, 0)), 1);
    }
}
