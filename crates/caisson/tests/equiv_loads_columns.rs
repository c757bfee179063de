//! `LoadsReport::columns` (the Python package's `caisson.loads.evaluate` table) against the
//! report's JSON (`caisson loads --json`): the same keys, none missing and none extra, and every
//! value exactly (numbers bit for bit, `null` as `None`), for the bundled wave examples over
//! heights that cover both regimes, nulls and numbers, both rise-time models and the three
//! breaking-wave loads.

mod support;

use caisson::analysis::conventional::{DesignWave, StaticCheck};
use caisson::report::loads::{ColumnSink, LoadsReport};
use caisson::scenario::Scenario;
use serde_json::Value;
use std::path::Path;

/// The sink's (name, value) pairs, values as JSON.
#[derive(Default)]
struct Collect(Vec<(&'static str, Value)>);

impl ColumnSink for Collect {
    fn number(&mut self, name: &'static str, x: Option<f64>) {
        self.0.push((name, x.map_or(Value::Null, Value::from)));
    }
    fn flag(&mut self, name: &'static str, b: bool) {
        self.0.push((name, Value::Bool(b)));
    }
    fn text(&mut self, name: &'static str, s: &'static str) {
        self.0.push((name, Value::from(s)));
    }
}

/// The JSON's leaves, keys joined by ".".
fn flatten(prefix: &str, v: &Value, out: &mut Vec<(String, Value)>) {
    match v {
        Value::Object(m) => {
            for (k, v) in m {
                let key = if prefix.is_empty() { k.clone() } else { format!("{prefix}.{k}") };
                flatten(&key, v, out);
            }
        }
        _ => out.push((prefix.to_string(), v.clone())),
    }
}

/// The report of the wave `h_m` of the scenario's `[waves]`.
fn report(sc: &Scenario, h_m: f64) -> LoadsReport {
    let ws = sc.waves_for("test").unwrap();
    let (w, mu) = (sc.caisson().weight_in_water_n, sc.foundation().mu_static);
    let check = StaticCheck::new(ws, DesignWave::with_height(ws, h_m, ws.period_s()), w, mu, ws.regime()).unwrap();
    LoadsReport::new(ws, &check, w, mu)
}

#[test]
fn columns_are_the_json_keys_and_values() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../examples");
    let literal = std::fs::read_to_string(dir.join("pari_breaking_loads.toml"))
        .unwrap()
        .replace("[waves]\n", "[waves]\nrise_time_model = \"literal\"\n");
    let mut scenarios: Vec<Scenario> =
        ["pari_breaking_loads.toml", "pari_nonbreaking_loads.toml", "design_breakwater.toml", "fragility.toml"]
            .iter()
            .map(|n| support::example(n))
            .collect();
    scenarios.push(Scenario::from_toml(&literal, Path::new("literal.toml"), &dir).unwrap());
    // The 15 m site of the study (a berm: Goda's check with α_I) under the other breaking loads.
    let site = std::fs::read_to_string(dir.join("study/site_15m.toml")).unwrap();
    for rule in ["goda-takahashi", "none"] {
        let text = site.replace("[waves]\n", &format!("[waves]\nbreaking_load = \"{rule}\"\n"));
        scenarios.push(Scenario::from_toml(&text, Path::new("site.toml"), &dir).unwrap());
    }
    let (mut rows, mut values, mut nulls) = (0, 0, 0);
    let mut seen = std::collections::BTreeSet::new();
    for sc in &scenarios {
        let h0 = sc.waves_for("test").unwrap().height_m();
        for h in [0.05, 0.3, 0.5, 1.0, 2.0, 5.0, 10.0].map(|f| f * h0) {
            let r = report(sc, h);
            let mut want = Vec::new();
            flatten("", &serde_json::to_value(&r).unwrap(), &mut want);
            want.retain(|(k, _)| k != "caisson_version" && k != "results_version");
            want.sort_by(|a, b| a.0.cmp(&b.0)); // serde_json's map sorts the keys
            let mut got = Collect::default();
            r.columns(&mut got);
            let mut got: Vec<(String, Value)> = got.0.into_iter().map(|(k, v)| (k.to_string(), v)).collect();
            got.sort_by(|a, b| a.0.cmp(&b.0));
            assert_eq!(got.len(), 95, "h = {h}");
            assert_eq!(got, want, "h = {h}");
            rows += 1;
            values += got.len();
            nulls += got.iter().filter(|(_, v)| v.is_null()).count();
            seen.extend(got.iter().filter_map(|(k, v)| v.as_str().map(|s| format!("{k}={s}"))));
        }
    }
    assert_eq!((rows, values), (49, 49 * 95));
    assert!(nulls > 0, "no null value was checked");
    for text in [
        "regime.regime=breaking",
        "regime.regime=non-breaking",
        "rise_time.model=median",
        "rise_time.model=literal",
        "design_wave.rule=regular-height",
        "design_wave.rule=goda-breaking-limited",
        "wave.kind=irregular",
        "breaking_load.rule=cuomo-2010",
        "breaking_load.rule=goda-takahashi",
        "breaking_load.rule=none",
    ] {
        assert!(seen.contains(text), "{text} not checked: {seen:?}");
    }
}
