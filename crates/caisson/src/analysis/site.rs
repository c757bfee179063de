//! The waves of a site, as every driver meets them: the wave-load model (with its regime choice),
//! the trains drawn from it and the friction coefficient of the rigid-block reference
//! ([`super::rigid`]). A model piece: it imports no driver.

use crate::check::between;
use crate::foundation::{Foundation, MIN_FRICTION};
use crate::loads::generator::TrainSpec;
use crate::loads::model::{WaveLoadModel, WaveParamError, WaveSite};
use crate::loads::regime::RegimeChoice;
use crate::structure::Caisson;

/// The waves of a site: its load model (with the regime choice), the trains, and the friction
/// coefficient of the rigid-block reference.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct WaveSetup {
    pub model: WaveLoadModel,
    pub train: TrainSpec,
    /// μ of the rigid block; `None`: the foundation's μ_s.
    pub rigid_block_mu: Option<f64>,
}

impl WaveSetup {
    /// The waves of a site if they hold together: the site ([`WaveSite::checked`]), the trains'
    /// period and height ([`TrainSpec::checked`]), the load options
    /// ([`crate::loads::model::WaveLoadOptions::checked`]), the trains' counts and variability, a
    /// forced regime that the breaking criterion allows at the trains' height, and the
    /// rigid-block μ from [`MIN_FRICTION`] to 2.
    pub fn new(model: WaveLoadModel, train: TrainSpec, rigid_block_mu: Option<f64>) -> Result<Self, WaveParamError> {
        model.site.checked()?;
        train.checked_wave()?;
        model.options.checked()?;
        train.checked_counts()?;
        // A forced regime must agree with the breaking criterion (non-breaking above the limit).
        model.evaluate(train.height_m(), train.period_s)?;
        if let Some(mu) = rigid_block_mu {
            between("rigid_block_mu", mu, MIN_FRICTION, 2.0)?;
        }
        Ok(WaveSetup { model, train, rigid_block_mu })
    }

    /// The nominal (regular) or significant (irregular) wave height, m.
    pub fn height_m(&self) -> f64 {
        self.train.height_m()
    }
    /// The wave period (T1/3 for irregular waves), s.
    pub fn period_s(&self) -> f64 {
        self.train.period_s
    }
    /// How the regime of each wave is chosen.
    pub fn regime(&self) -> RegimeChoice {
        self.model.options.regime
    }
    /// μ of the rigid-block reference on `foundation`.
    pub fn rigid_block_mu(&self, foundation: &Foundation) -> f64 {
        self.rigid_block_mu.unwrap_or(foundation.mu_static)
    }
}

/// Put `caisson` at `site`: the geometry the wave loads see (base depth, crest freeboard h_c =
/// height − base depth, width, length) follows the caisson.
pub fn place_caisson(site: &mut WaveSite, caisson: &Caisson) {
    site.base_depth_m = caisson.base_depth_m;
    site.crest_freeboard_m = caisson.height_m - caisson.base_depth_m;
    site.width_m = caisson.width_m;
    site.length_m = caisson.length_m;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::loads::generator::{HeightVariability, TrainKind};
    use crate::loads::model::WaveLoadOptions;
    use crate::loads::regime::Regime;

    /// The PARI breaking test (H 0.428 m, T 3.04 s at h_s 1.14 m, d 0.4 m).
    fn pari() -> (WaveLoadModel, TrainSpec) {
        let site = crate::loads::model::tests::pari_site();
        let kind = TrainKind::Regular { height_m: 0.428, variability: HeightVariability::default() };
        let train = TrainSpec { kind, period_s: 3.04, waves: 15, realizations: 10, seed: 1 };
        (WaveLoadModel { site, options: WaveLoadOptions::default() }, train)
    }

    #[test]
    fn a_wave_setup_refuses_a_forced_regime_the_criterion_contradicts_and_a_bad_mu() {
        let (model, train) = pari();
        assert!(WaveSetup::new(model, train, Some(0.6)).is_ok());
        // 0.428 m breaks in front of a wall in 0.4 m of water: non-breaking is refused.
        let mut forced = model;
        forced.options.regime = RegimeChoice::Forced(Regime::NonBreaking);
        assert!(matches!(WaveSetup::new(forced, train, None), Err(WaveParamError::Regime(_))));
        match WaveSetup::new(model, train, Some(0.0)) {
            Err(WaveParamError::Param(e)) => assert_eq!((e.quantity, e.value), ("rigid_block_mu", 0.0)),
            other => panic!("{other:?}"),
        }
        // Each part is checked: the site, the options, the train.
        let mut bad_site = model;
        bad_site.site.seabed_slope = 1.0;
        assert!(
            matches!(WaveSetup::new(bad_site, train, None), Err(WaveParamError::Param(e)) if e.quantity == "seabed_slope")
        );
        let mut bad_options = model;
        bad_options.options.a_imp = -1.0;
        assert!(
            matches!(WaveSetup::new(bad_options, train, None), Err(WaveParamError::Param(e)) if e.quantity == "a_imp")
        );
        let bad_train = TrainSpec { period_s: f64::NAN, ..train };
        assert!(
            matches!(WaveSetup::new(model, bad_train, None), Err(WaveParamError::Param(e)) if e.quantity == "period_s")
        );
    }
}
