//! The stratified sampling of a design run (issue 35, item 3; `analysis::lifetime::sampling`,
//! `analysis::stratified`) against plain Monte Carlo on 100 000 lives of the design example: every
//! headline statistic of the stratified estimate within 3 standard errors of the plain one. The
//! stratified run's lives are the plain run's lives of its sample (a sampled life is the life of
//! the same index), so the plain lives are simulated once and the sample picked from them.
//! The two estimates share their sampled lives, which makes their difference vary less than
//! the two errors together: σ = √(SE_plain² + SE_stratified²) is the conservative bound.
//! And the sample does not depend on how the pool is split or on the thread count.

mod support;

use caisson::analysis::lifetime::sampling::{Pool, Strata};
use caisson::analysis::lifetime::StormOutcome;
use caisson::drive::design::{DesignOptions, Designer};
use caisson::report::design::DesignReport;
use std::ops::ControlFlow;

const LIVES: usize = 100_000;

#[test]
fn stratified_estimates_meet_plain_monte_carlo_on_100000_lives() {
    let sc = support::example("design_breakwater.toml");
    let run = Designer::new(&sc, "test", DesignOptions { lives: Some(LIVES), brute_force: false }).unwrap();
    let indices: Vec<usize> = (0..LIVES).collect();
    let all: Vec<StormOutcome> =
        run.run(&indices, &|_, _| ControlFlow::Continue(())).unwrap().into_iter().map(|(_, o)| o).collect();
    let sample = run.sample_of(0..LIVES);
    let picked: Vec<StormOutcome> = sample.pool.selected.iter().map(|&(i, _)| all[i]).collect();
    let failure_m = run.failure_limits().sliding_m;
    let plain = DesignReport::statistics(&run.design, run.case.rigid_block_mu, failure_m, &all);
    let strat = DesignReport::stratified_statistics(
        &run.design,
        run.case.rigid_block_mu,
        failure_m,
        &picked,
        &sample.strata,
        &sample.pool,
    );
    let mut checked = 0;
    let mut within = |what: &str, p: (f64, f64), s: (f64, f64)| {
        let sigma = (p.1 * p.1 + s.1 * s.1).sqrt();
        println!(
            "{what}: plain {:.5} ± {:.5}, stratified {:.5} ± {:.5}, {:.2} σ",
            p.0,
            p.1,
            s.0,
            s.1,
            (p.0 - s.0) / sigma
        );
        assert!(sigma > 0.0, "{what}: no error");
        assert!((p.0 - s.0).abs() <= 3.0 * sigma, "{what}: plain {p:?}, stratified {s:?}");
        checked += 1;
    };
    // The standard error of a proportion from its Wilson interval's half-width (p̂ inside).
    let se_of = |ci: [f64; 2]| (ci[1] - ci[0]) / (2.0 * caisson::analysis::estimate::Z95);
    for (name, p, s) in [
        ("dynamic", &plain.dynamic.sliding, &strat.dynamic.sliding),
        ("rigid block", &plain.rigid_block, &strat.rigid_block),
    ] {
        within(
            &format!("{name} E|S|"),
            (p.expected_sliding_m, p.expected_sliding_standard_error_m),
            (s.expected_sliding_m, s.expected_sliding_standard_error_m),
        );
        within(
            &format!("{name} E|S| as simulated"),
            (p.expected_sliding_uncapped_m, p.expected_sliding_uncapped_standard_error_m),
            (s.expected_sliding_uncapped_m, s.expected_sliding_uncapped_standard_error_m),
        );
        within(
            &format!("{name} P(failure)"),
            (p.failure.probability, se_of(p.failure.probability_ci95)),
            (s.failure.probability, se_of(s.failure.probability_ci95)),
        );
        for (a, b) in p.exceedance_probability.iter().zip(&s.exceedance_probability) {
            within(
                &format!("{name} P(|S| > {} m)", a.threshold_m),
                (a.probability, se_of(a.ci95)),
                (b.probability, se_of(b.ci95)),
            );
        }
    }
    let (hp, hs) = (&plain.dynamic.heel_pressure_exceedance, &strat.dynamic.heel_pressure_exceedance);
    within("P(q_heel > q_a)", (hp.probability, hp.standard_error), (hs.probability, hs.standard_error));
    // 2 models × (3 + 5 thresholds) + the heel pressure.
    assert_eq!(checked, 17);
    // The sample: Σ_h share_h f_h = 0.6 · 0.01 + 0.2 · 0.03 + 0.1 · 0.1 + 0.06 · 0.2 + 0.03 · 0.3 +
    // 0.01 · 0.4 = 4.7 % of the pool (the shares are the pilot's quantiles: about).
    let n = sample.pool.selected.len();
    assert!((4000..5500).contains(&n), "{n} lives sampled");
}

/// The same sample from any split of the pool and on any thread count.
#[test]
fn the_sample_does_not_depend_on_the_split_or_the_threads() {
    let sc = support::example("design_breakwater.toml");
    let run = Designer::new(&sc, "test", DesignOptions::default()).unwrap();
    let pool = |threads: usize, range: std::ops::Range<usize>| {
        let p = rayon::ThreadPoolBuilder::new().num_threads(threads).build().unwrap();
        p.install(|| {
            let strata = Strata::pilot(&run.case, &run.design.life, run.design.seed);
            Pool::of(&run.case, &run.design.life, run.design.seed, &strata, range)
        })
    };
    let whole = pool(1, 0..3000);
    let (a, b) = (pool(2, 0..1234), pool(1, 1234..3000));
    let mut joined = a.selected.clone();
    joined.extend(&b.selected);
    assert_eq!(whole.selected, joined);
    let counts: Vec<usize> = a.counts.iter().zip(&b.counts).map(|(x, y)| x + y).collect();
    assert_eq!(whole.counts.to_vec(), counts);
    assert_eq!(pool(2, 0..3000), whole);
    assert!(whole.selected.len() > 100, "{} lives sampled", whole.selected.len());
}
