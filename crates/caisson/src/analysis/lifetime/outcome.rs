//! What a storm (or, summed, a life) did: the columns of `lives.csv` and of the checkpoint lines.

use super::params::FailureLimits;
use super::storm::StormError;

/// The outcome of one storm (or, summed, of one life). Sign convention: sliding is positive
/// shoreward (the direction of the wave's push), negative seaward. The field names are the
/// columns of `lives.csv` and of the checkpoint lines ([`LIFE_COLUMNS`]).
#[derive(Debug, Clone, Copy, PartialEq, Default, serde::Serialize, serde::Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StormOutcome {
    /// Net sliding of the dynamic model: the sum of every wave's permanent sliding, signed, m.
    pub sliding_m: f64,
    /// The sum of the shoreward wave slides (≥ 0), m.
    pub shoreward_sliding_m: f64,
    /// The sum of the seaward wave slides, as a magnitude (≥ 0), m:
    /// `sliding_m = shoreward_sliding_m − seaward_sliding_m`.
    pub seaward_sliding_m: f64,
    /// The largest distance of the caisson from its place at the start (of the life, for a life)
    /// after any wave (≥ |sliding_m|), m. A life fails when it exceeds the failure limit.
    pub max_excursion_m: f64,
    /// Rigid block (Shimosako model; it slides shoreward only), m.
    pub rigid_block_sliding_m: f64,
    /// The storm's net sliding of the largest magnitude, with its sign (for a life), m.
    pub max_storm_sliding_m: f64,
    pub waves: u64,
    /// Waves run through the dynamic model.
    pub simulated_waves: u64,
    /// Waves skipped by the screen (and those after the wave that failed a life, which are not
    /// run either).
    pub screened_waves: u64,
    /// Simulated waves during which part of the base lifted off (a spring out of contact).
    pub rocking_waves: u64,
    /// Simulated waves that rotated the caisson beyond [`ROCKING_LIMIT_RAD`]: the model does
    /// not follow overturning itself (large rotations, the mound's bearing capacity under the
    /// heel), so a life with such a wave is outside its validity (docs/design.md).
    pub large_rotation_waves: u64,
    /// The largest rotation |θ| of the caisson during any simulated wave, rad. A life fails when
    /// it exceeds the rotation limit ([`FailureLimits`]).
    pub max_rotation_rad: f64,
    /// The waves with an impulsive load (their load event has an impulse: a breaking wave with
    /// an impact under the load model) that may slide the caisson or lift its base (they pass the
    /// screen's friction or lift-off test: the others slide neither model, module docs
    /// "Impulsive waves"); each runs through both models.
    pub impulsive_waves: u64,
    /// The dynamic model's net sliding under those waves, signed (shoreward +), m.
    pub impulsive_sliding_m: f64,
    /// The rigid block's sliding under those waves, m.
    pub rigid_block_impulsive_sliding_m: f64,
    /// The largest heel pressure of the dynamic model, kPa (module docs, "Heel pressure"): of the
    /// caisson at rest at still water and of every wave run; exact at and above the screen's heel
    /// pressure ([`StormCase::heel_screen_pa`](super::params::StormCase::heel_screen_pa)), every
    /// wave that may reach it being run.
    pub max_heel_pressure_kpa: f64,
    /// The year (from 1) of the storm in which the life failed; 0 if it did not (a storm alone:
    /// 0; its failure is the flags below).
    pub failure_year: u64,
    /// 1 if the wave that failed the life (or storm) took the caisson beyond the sliding limit,
    /// else 0 (module docs, "Failure"; a failing wave may count in several modes).
    pub failed_by_sliding: u64,
    /// 1 if the failing wave rotated the caisson beyond the rotation limit.
    pub failed_by_rotation: u64,
    /// 1 if the failing wave pressed the heel beyond the failure heel pressure.
    pub failed_by_heel_pressure: u64,
    /// 1 if the failing wave had an impulsive load.
    pub failing_wave_impulsive: u64,
    /// 1 if the wave that took the rigid block beyond the sliding limit had an impulsive load.
    pub rigid_block_failing_wave_impulsive: u64,
    /// 1 if, after the failure, a wave did not converge in the dynamic model (far outside its
    /// validity) and the dynamic model ran no further wave of the life: its columns stop there
    /// (module docs, "Failure").
    pub run_on_stopped: u64,
}

/// One column of a life's outcome: its value as metres or as a count.
#[derive(Debug, Clone, Copy)]
pub enum LifeColumn {
    Metres(fn(&StormOutcome) -> f64),
    Count(fn(&StormOutcome) -> u64),
    Radians(fn(&StormOutcome) -> f64),
    Kilopascals(fn(&StormOutcome) -> f64),
}

/// The columns of a life's outcome (after `life`) in `lives.csv` and the Python `DataFrame`,
/// named as the [`StormOutcome`] fields.
pub const LIFE_COLUMNS: [(&str, LifeColumn); 23] = [
    ("sliding_m", LifeColumn::Metres(|o| o.sliding_m)),
    ("shoreward_sliding_m", LifeColumn::Metres(|o| o.shoreward_sliding_m)),
    ("seaward_sliding_m", LifeColumn::Metres(|o| o.seaward_sliding_m)),
    ("max_excursion_m", LifeColumn::Metres(|o| o.max_excursion_m)),
    ("rigid_block_sliding_m", LifeColumn::Metres(|o| o.rigid_block_sliding_m)),
    ("max_storm_sliding_m", LifeColumn::Metres(|o| o.max_storm_sliding_m)),
    ("waves", LifeColumn::Count(|o| o.waves)),
    ("simulated_waves", LifeColumn::Count(|o| o.simulated_waves)),
    ("screened_waves", LifeColumn::Count(|o| o.screened_waves)),
    ("rocking_waves", LifeColumn::Count(|o| o.rocking_waves)),
    ("large_rotation_waves", LifeColumn::Count(|o| o.large_rotation_waves)),
    ("max_rotation_rad", LifeColumn::Radians(|o| o.max_rotation_rad)),
    ("impulsive_waves", LifeColumn::Count(|o| o.impulsive_waves)),
    ("impulsive_sliding_m", LifeColumn::Metres(|o| o.impulsive_sliding_m)),
    ("rigid_block_impulsive_sliding_m", LifeColumn::Metres(|o| o.rigid_block_impulsive_sliding_m)),
    ("max_heel_pressure_kpa", LifeColumn::Kilopascals(|o| o.max_heel_pressure_kpa)),
    ("failure_year", LifeColumn::Count(|o| o.failure_year)),
    ("failed_by_sliding", LifeColumn::Count(|o| o.failed_by_sliding)),
    ("failed_by_rotation", LifeColumn::Count(|o| o.failed_by_rotation)),
    ("failed_by_heel_pressure", LifeColumn::Count(|o| o.failed_by_heel_pressure)),
    ("failing_wave_impulsive", LifeColumn::Count(|o| o.failing_wave_impulsive)),
    ("rigid_block_failing_wave_impulsive", LifeColumn::Count(|o| o.rigid_block_failing_wave_impulsive)),
    ("run_on_stopped", LifeColumn::Count(|o| o.run_on_stopped)),
];

impl StormOutcome {
    /// Append storm `o`, which started where this life's caisson now stands.
    pub(super) fn add(&mut self, o: &StormOutcome) {
        self.sliding_m += o.sliding_m;
        self.shoreward_sliding_m += o.shoreward_sliding_m;
        self.seaward_sliding_m += o.seaward_sliding_m;
        self.max_excursion_m = self.max_excursion_m.max(o.max_excursion_m);
        self.rigid_block_sliding_m += o.rigid_block_sliding_m;
        if o.sliding_m.abs() > self.max_storm_sliding_m.abs() {
            self.max_storm_sliding_m = o.sliding_m;
        }
        self.waves += o.waves;
        self.simulated_waves += o.simulated_waves;
        self.screened_waves += o.screened_waves;
        self.rocking_waves += o.rocking_waves;
        self.large_rotation_waves += o.large_rotation_waves;
        self.max_rotation_rad = self.max_rotation_rad.max(o.max_rotation_rad);
        self.impulsive_waves += o.impulsive_waves;
        self.impulsive_sliding_m += o.impulsive_sliding_m;
        self.rigid_block_impulsive_sliding_m += o.rigid_block_impulsive_sliding_m;
        self.max_heel_pressure_kpa = self.max_heel_pressure_kpa.max(o.max_heel_pressure_kpa);
        // A storm records a failure only in a life that had not failed (and the rigid block's
        // failing wave only once).
        self.failed_by_sliding |= o.failed_by_sliding;
        self.failed_by_rotation |= o.failed_by_rotation;
        self.failed_by_heel_pressure |= o.failed_by_heel_pressure;
        self.failing_wave_impulsive |= o.failing_wave_impulsive;
        self.rigid_block_failing_wave_impulsive |= o.rigid_block_failing_wave_impulsive;
        self.run_on_stopped |= o.run_on_stopped;
    }

    /// Whether the life (or storm) failed: a wave took it beyond a failure limit (module docs,
    /// "Failure"); the modes are those of that wave.
    pub fn failed(&self) -> bool {
        (self.failed_by_sliding | self.failed_by_rotation | self.failed_by_heel_pressure) != 0
    }

    /// The failure modes that the caisson's state now reaches: beyond the sliding limit from its
    /// place, rotated beyond the rotation limit, the heel pressed beyond the failure pressure.
    pub(super) fn beyond(&self, f: &FailureLimits) -> [bool; 3] {
        [
            self.max_excursion_m > f.sliding_m,
            self.max_rotation_rad > f.rotation_rad,
            f.heel_pressure_pa.is_some_and(|q| self.max_heel_pressure_kpa * 1e3 > q),
        ]
    }

    /// Whether the rigid block's sliding exceeds the sliding limit (it fails by sliding only).
    pub fn rigid_block_failed(&self, f: &FailureLimits) -> bool {
        self.rigid_block_sliding_m.abs() > f.sliding_m
    }
}

impl StormOutcome {
    /// `Ok` if every column is a finite number, else the first that is not
    /// ([`StormError::NonFinite`]).
    pub(super) fn finite(self) -> Result<Self, StormError> {
        for (column, c) in LIFE_COLUMNS {
            let value = match c {
                LifeColumn::Metres(f) | LifeColumn::Radians(f) | LifeColumn::Kilopascals(f) => f(&self),
                LifeColumn::Count(_) => continue,
            };
            if !value.is_finite() {
                return Err(StormError::NonFinite { column, value });
            }
        }
        Ok(self)
    }
}
