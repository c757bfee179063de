//! The waves of a site, as every driver meets them: the wave-load model (with its regime choice),
//! the trains drawn from it and the friction coefficient of the rigid-block reference
//! ([`super::rigid`]). A model piece: it imports no driver.

use crate::foundation::Foundation;
use crate::loads::generator::TrainSpec;
use crate::loads::model::WaveLoadModel;
use crate::loads::regime::RegimeChoice;

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
