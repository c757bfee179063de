//! Wave trains of one test condition: N_z waves per realization, with the height variability of
//! the seed's PARI simulations or Rayleigh heights, the regime of each wave and its rise time
//! (seed §6 "Comparison of predictions"; docs/model.md §5.3, §6.4 step 5, §10 item 26).
//!
//! * **Regular** waves of nominal height H and period T. Each wave's height is H (1 + δ):
//!   - `Normal` (default): δ = c z, z standard normal truncated at ±k (rejection), c = 0.2, k = 2
//!     (docs/model.md §10 item 26: "about 20 % of the nominal height" read as a COV);
//!   - `Uniform`: δ uniform on [−c, c] (the other reading, ±20 %);
//!   - `None`: δ = 0 (the monochromatic test as specified).
//! * **Irregular** waves: Rayleigh heights from the significant height H1/3,
//!   P(H > x) = exp[−2 (x/H1/3)²], i.e. H = H1/3 √(−ln U / 2) with U uniform on (0, 1]
//!   (docs/model.md §6.4 step 5); every wave has the period T1/3. A height below 10⁻³ H1/3 is raised to
//!   it (a wave must have a height; such a wave carries no load that matters).
//!
//! The regime of each wave follows the model's choice: `auto` decides per wave by the breaking
//! criterion at the wall; a forced `breaking` applies to every wave; a forced `non-breaking`
//! applies to every wave, and a drawn height at or above the breaker height at the wall H_br is
//! **limited** to just below H_br (a standing wave cannot be higher in that depth) and counted.
//! The rise time of an impulsive wave is drawn from the seed's log-normal model (Eqs. 34-36).
//!
//! Random numbers: one ChaCha8 generator per realization, seeded with the scenario's seed and the
//! realization index as the stream, so that a realization's waves do not depend on which thread
//! runs it or on the other realizations. Per wave, in this order: the height draw(s), then one
//! standard-normal draw for the rise time (always drawn, so that wave j uses the same numbers
//! whatever the regime of the others). The same seed and realization give the same train under
//! every condition of a campaign (common random numbers: differences between conditions are not
//! blurred by different draws).

use super::model::{WaveLoadModel, WaveParamError, WaveRecord, MIN_LENGTH_M, MIN_PERIOD_S};
use super::regime::{Regime, RegimeChoice, RegimeError};
use super::risetime::LoadRng;
use crate::check::{count, interval, rule};
use crate::waves::breaking::MICHE_STEEPNESS;
use crate::waves::dispersion::deep_water_wavelength_m;
use crate::waves::statistics::sample_rayleigh_m;
use crate::ParamError;
use rand::{Rng, SeedableRng};
use rand_distr::StandardNormal;

/// Most waves of all the realizations of a train together (`waves` × `realizations`).
pub const MAX_TRAIN_WAVES: usize = 10_000_000;

/// Variability of the individual heights of a regular-wave test.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum HeightVariability {
    /// H (1 + c z), z ~ N(0, 1) truncated at ±`truncation_sigmas`.
    Normal { cov: f64, truncation_sigmas: f64 },
    /// H (1 + δ), δ ~ U[−half_width, half_width].
    Uniform { half_width: f64 },
    /// Every wave has the nominal height.
    None,
}

impl Default for HeightVariability {
    fn default() -> Self {
        HeightVariability::Normal { cov: 0.2, truncation_sigmas: 2.0 }
    }
}

impl HeightVariability {
    /// The variability if in range: the fraction c (COV or half-width) from 0 to 0.9, the
    /// truncation k from 0.5 to 10 standard deviations, and c k below 1 (a drawn height could
    /// otherwise be zero or negative). Quantities are named as the scenario's keys.
    pub fn checked(self) -> Result<Self, ParamError> {
        match self {
            HeightVariability::Normal { cov, truncation_sigmas } => {
                interval("height_variability_fraction", cov, 0.0, 0.9, false)?;
                interval("height_truncation_sigmas", truncation_sigmas, 0.5, 10.0, false)?;
                if cov * truncation_sigmas >= 1.0 {
                    return Err(rule(
                        "height_variability_fraction",
                        cov,
                        format!("times height_truncation_sigmas = {truncation_sigmas} must be below 1, or a drawn height could be zero or negative"),
                    ));
                }
            }
            HeightVariability::Uniform { half_width } => {
                interval("height_variability_fraction", half_width, 0.0, 0.9, false)?;
            }
            HeightVariability::None => {}
        }
        Ok(self)
    }
}

/// How the individual heights are drawn.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum TrainKind {
    /// Nominal height H (m) with the given variability.
    Regular { height_m: f64, variability: HeightVariability },
    /// Rayleigh heights of significant height H1/3 (m).
    Irregular { significant_height_m: f64 },
}

/// A test condition's wave trains.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct TrainSpec {
    pub kind: TrainKind,
    /// Period of every wave, s (T, or T1/3 for irregular waves).
    pub period_s: f64,
    /// Waves per realization N_z.
    pub waves: usize,
    /// Number of realizations.
    pub realizations: usize,
    pub seed: u64,
}

impl TrainSpec {
    /// The nominal (regular) or significant (irregular) height, m.
    pub fn height_m(&self) -> f64 {
        match self.kind {
            TrainKind::Regular { height_m, .. } => height_m,
            TrainKind::Irregular { significant_height_m } => significant_height_m,
        }
    }

    /// The spec if every quantity is in range: the period from [`MIN_PERIOD_S`] to 1000 s; the
    /// height from [`MIN_LENGTH_M`] to 1000 m and below the deep-water breaking limit 0.142 L0;
    /// 1 to 10⁶ waves and realizations, at most [`MAX_TRAIN_WAVES`] in all; the variability
    /// ([`HeightVariability::checked`]).
    pub fn checked(self) -> Result<Self, WaveParamError> {
        self.checked_wave()?;
        self.checked_counts()
    }

    /// The period and the height of the spec's waves ([`Self::checked`]).
    pub(crate) fn checked_wave(&self) -> Result<(), ParamError> {
        let period_s = interval("period_s", self.period_s, MIN_PERIOD_S, 1e3, false)?;
        let quantity = match self.kind {
            TrainKind::Regular { .. } => "height_m",
            TrainKind::Irregular { .. } => "significant_height_m",
        };
        let height_m = interval(quantity, self.height_m(), MIN_LENGTH_M, 1e3, false)?;
        let limit = MICHE_STEEPNESS * deep_water_wavelength_m(period_s);
        if height_m >= limit {
            return Err(rule(
                quantity,
                height_m,
                format!("must be below the deep-water breaking limit 0.142 L0 = {limit:.4} m for period_s = {period_s} s (no wave is steeper)"),
            ));
        }
        Ok(())
    }

    /// The counts and the height variability of the spec ([`Self::checked`]).
    pub(crate) fn checked_counts(self) -> Result<Self, WaveParamError> {
        let waves = count("waves", self.waves, 1, 1_000_000)?;
        let realizations = count("realizations", self.realizations, 1, 1_000_000)?;
        // Every wave of every realization is integrated and reported (a row of `waves.csv`, an
        // object of the JSON): bounded in all, not only per realization.
        if waves * realizations > MAX_TRAIN_WAVES {
            return Err(WaveParamError::TooManyWaves { waves, realizations });
        }
        if let TrainKind::Regular { variability, .. } = self.kind {
            variability.checked()?;
        }
        Ok(self)
    }

    /// The same spec with another nominal (regular) or significant (irregular) height `h` (m): a
    /// finite number > 0 below the deep-water breaking limit 0.142 L0 for the period (no wave is
    /// steeper).
    pub fn with_height_m(mut self, h: f64) -> Result<Self, ParamError> {
        let limit = MICHE_STEEPNESS * deep_water_wavelength_m(self.period_s);
        if !(h.is_finite() && h > 0.0 && h < limit) {
            return Err(rule(
                "height_m",
                h,
                format!(
                    "must be a finite number > 0 and below the deep-water breaking limit 0.142 L0 = {limit:.4} m for period_s = {} s (no wave is steeper)",
                    self.period_s
                ),
            ));
        }
        match &mut self.kind {
            TrainKind::Regular { height_m, .. } => *height_m = h,
            TrainKind::Irregular { significant_height_m } => *significant_height_m = h,
        }
        Ok(self)
    }
}

/// The waves of one realization.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct RealizationWaves {
    pub records: Vec<WaveRecord>,
    /// Waves of a forced non-breaking train whose drawn height was limited to H_br.
    pub limited_waves: usize,
}

/// The generator of realization `index` (see the module docs).
pub fn realization_rng(seed: u64, index: usize) -> LoadRng {
    let mut rng = LoadRng::seed_from_u64(seed);
    rng.set_stream(index as u64);
    rng
}

/// A standard normal truncated at ±k (rejection; k ≥ 0.5 keeps the acceptance above 38 %).
fn truncated_normal(rng: &mut LoadRng, k: f64) -> f64 {
    loop {
        let z: f64 = rng.sample(StandardNormal);
        if z.abs() <= k {
            return z;
        }
    }
}

/// The waves of realization `index` of `spec` at the site of `model`, regime chosen by `choice`.
pub fn realization_waves(
    model: &WaveLoadModel,
    spec: &TrainSpec,
    choice: RegimeChoice,
    index: usize,
) -> Result<RealizationWaves, RegimeError> {
    let mut rng = realization_rng(spec.seed, index);
    let mut records = Vec::with_capacity(spec.waves);
    let mut limited_waves = 0;
    let t = spec.period_s;
    for _ in 0..spec.waves {
        let mut h = match spec.kind {
            TrainKind::Regular { height_m, variability } => match variability {
                HeightVariability::Normal { cov, truncation_sigmas } => {
                    height_m * (1.0 + cov * truncated_normal(&mut rng, truncation_sigmas))
                }
                HeightVariability::Uniform { half_width } => {
                    height_m * (1.0 + half_width * (2.0 * rng.gen::<f64>() - 1.0))
                }
                HeightVariability::None => height_m,
            },
            TrainKind::Irregular { significant_height_m } => {
                sample_rayleigh_m(significant_height_m, &mut rng).max(1e-3 * significant_height_m)
            }
        };
        let z: f64 = rng.sample(StandardNormal);
        if choice == RegimeChoice::Forced(Regime::NonBreaking) {
            let hbr = model.breaker_height_at_wall_m(t);
            // The comparison is made on the toe height (Miche-limited), as in the model.
            if h.min(model.toe_breaker_height_m(t)) >= hbr {
                h = hbr * (1.0 - 1e-9);
                limited_waves += 1;
            }
        }
        let loads = model.evaluate_with(h, t, choice)?;
        records.push(WaveRecord {
            height_m: h,
            period_s: t,
            regime: loads.regime.regime,
            // Only an impulsive (breaking) wave uses its rise time; z is drawn for every wave.
            rise_time_s: if loads.regime.regime == Regime::Breaking {
                loads.rise_time.map(|d| d.at_deviate(z))
            } else {
                None
            },
        });
    }
    Ok(RealizationWaves { records, limited_waves })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn truncated_normal_stays_within_its_bounds_and_is_centred() {
        let mut rng = realization_rng(7, 0);
        let n = 20_000;
        let mut sum = 0.0;
        for _ in 0..n {
            let z = truncated_normal(&mut rng, 2.0);
            assert!(z.abs() <= 2.0);
            sum += z;
        }
        // Mean 0, sd of the truncated normal 0.880: 5 standard errors = 5·0.88/√n = 0.031.
        assert!((sum / n as f64).abs() < 0.031);
    }

    #[test]
    fn streams_differ_and_repeat() {
        let a: Vec<u64> = (0..4).map(|_| realization_rng(1, 0).gen()).collect();
        assert!(a.iter().all(|&x| x == a[0]));
        let b: u64 = realization_rng(1, 1).gen();
        assert_ne!(a[0], b);
    }
}

#[cfg(test)]
mod checks {
    use super::*;

    fn spec() -> TrainSpec {
        let kind = TrainKind::Regular { height_m: 0.428, variability: HeightVariability::default() };
        TrainSpec { kind, period_s: 3.04, waves: 15, realizations: 10, seed: 1 }
    }

    fn quantity(s: TrainSpec) -> &'static str {
        match s.checked() {
            Err(WaveParamError::Param(e)) => e.quantity,
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn a_train_refuses_each_quantity_out_of_range_naming_it() {
        assert_eq!(spec().checked(), Ok(spec()));
        assert_eq!(quantity(TrainSpec { period_s: 0.0, ..spec() }), "period_s");
        assert_eq!(quantity(TrainSpec { waves: 0, ..spec() }), "waves");
        assert_eq!(quantity(TrainSpec { realizations: 2_000_000, ..spec() }), "realizations");
        assert_eq!(quantity(spec().with_kind_height(-1.0)), "height_m");
        let irregular = TrainSpec { kind: TrainKind::Irregular { significant_height_m: 1e4 }, ..spec() };
        assert_eq!(quantity(irregular), "significant_height_m");
        // Steeper than 0.142 L0 (L0 = g T²/2π = 14.4 m at 3.04 s: the limit is 2.04 m).
        let e = match spec().with_kind_height(2.1).checked() {
            Err(WaveParamError::Param(e)) => e,
            other => panic!("{other:?}"),
        };
        assert!(matches!(e.allowed, crate::Allowed::Rule(ref r) if r.contains("2.04")), "{e}");
        assert_eq!(
            TrainSpec { waves: 1000, realizations: 100_000, ..spec() }.checked(),
            Err(WaveParamError::TooManyWaves { waves: 1000, realizations: 100_000 })
        );
    }

    #[test]
    fn a_height_variability_refuses_its_fraction_and_truncation_naming_them() {
        let named = |v: HeightVariability| v.checked().unwrap_err().quantity;
        assert_eq!(
            named(HeightVariability::Normal { cov: 0.95, truncation_sigmas: 1.0 }),
            "height_variability_fraction"
        );
        assert_eq!(named(HeightVariability::Normal { cov: 0.2, truncation_sigmas: 0.4 }), "height_truncation_sigmas");
        assert_eq!(named(HeightVariability::Uniform { half_width: -0.1 }), "height_variability_fraction");
        // c k = 0.6 × 2 ≥ 1: a drawn height could be negative.
        let e = HeightVariability::Normal { cov: 0.6, truncation_sigmas: 2.0 }.checked().unwrap_err();
        assert_eq!((e.quantity, e.value), ("height_variability_fraction", 0.6));
        assert!(HeightVariability::None.checked().is_ok());
    }

    impl TrainSpec {
        fn with_kind_height(mut self, h: f64) -> Self {
            if let TrainKind::Regular { height_m, .. } = &mut self.kind {
                *height_m = h;
            }
            self
        }
    }
}
