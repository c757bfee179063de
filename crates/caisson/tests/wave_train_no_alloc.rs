//! `WaveTrain::at` (the wave-load `LoadHistory`) must not allocate: the engine calls it every
//! time step. Counted with a global allocator, as in `no_alloc.rs`.

use caisson::loads::model::{WaveLoadModel, WaveLoadOptions, WaveRecord, WaveSite};
use caisson::loads::regime::Regime;
use caisson::loads::shapes::LoadShape;
use caisson::loads::LoadHistory;
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

struct Counting;
static ALLOCS: AtomicUsize = AtomicUsize::new(0);

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, l: Layout) -> *mut u8 {
        ALLOCS.fetch_add(1, Ordering::SeqCst);
        System.alloc(l)
    }
    unsafe fn dealloc(&self, p: *mut u8, l: Layout) {
        System.dealloc(p, l)
    }
}

#[global_allocator]
static A: Counting = Counting;

#[test]
fn wave_train_at_does_not_allocate() {
    let site = WaveSite { rho_w: 1000.0, depth_at_toe_m: 1.14, depth_at_wall_m: 0.4, base_depth_m: 0.8, crest_freeboard_m: 0.32, width_m: 0.78, length_m: 1.0, seabed_slope: 0.0, berm_width_m: None };
    let mut sum = 0.0;
    for (_, shape) in LoadShape::ALL {
        let model = WaveLoadModel { site, options: WaveLoadOptions { load_shape: shape, ..WaveLoadOptions::default() } };
        let recs: Vec<WaveRecord> = (0..50)
            .map(|j| WaveRecord { height_m: 0.428, period_s: 3.04, regime: if j % 3 == 0 { Regime::NonBreaking } else { Regime::Breaking }, rise_time_s: Some(0.01 + 1e-3 * j as f64) })
            .map(|r| if r.regime == Regime::NonBreaking { WaveRecord { height_m: 0.3, ..r } } else { r })
            .collect();
        let train = model.train(&recs).unwrap();
        let before = ALLOCS.load(Ordering::SeqCst);
        for k in 0..200_000 {
            sum += train.at(k as f64 * 1e-3).fx_n;
        }
        assert_eq!(ALLOCS.load(Ordering::SeqCst), before, "{shape:?}: at() allocated");
    }
    assert!(sum.is_finite());
}
