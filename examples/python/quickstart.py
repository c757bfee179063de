"""caisson from Python in ten steps (notebook style: run it as a script or cell by cell).

    python examples/python/quickstart.py [--out DIR]
"""

# %% Set-up
import argparse
import pathlib
import tempfile

import numpy as np

import caisson

EXAMPLES = pathlib.Path(__file__).resolve().parents[1]
parser = argparse.ArgumentParser()
parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path(tempfile.mkdtemp(prefix="caisson-quickstart-")))
out = parser.parse_args().out
out.mkdir(parents=True, exist_ok=True)

# %% 1. A scenario: the seed's Table 5 caisson under a triangular impact (validated on reading).
sc = caisson.Scenario.from_toml(EXAMPLES / "table5_triangle.toml")
print(sc)

# %% 2. One dynamic run: the summary has the keys of `caisson run --json`.
r = caisson.run(sc)
print(f"permanent sliding {r.summary['permanent_sliding_m'] * 1e3:.3f} mm, "
      f"peak base reaction {r.summary['max_horizontal_reaction_kn']:.2f} kN")

# %% 3. Time histories (pandas) and spring forces (xarray), units in the names.
print(r.history[["time_s", "fx_kn", "reaction_x_kn", "ux_m"]].iloc[::100])
print(r.springs["normal_kn"].sel(spring=1).max().item(), "kN on the seaward spring at most")

# %% 4. Change the caisson: a new validated scenario (errors name the file key).
heavier = sc.replace(caisson={"weight_in_water_kn": 10.0})
print("heavier:", caisson.run(heavier).summary["permanent_sliding_m"], "m")
try:
    sc.replace(caisson={"width_m": -1.0})
except caisson.ScenarioError as e:
    print("refused:", e.key, "=", e.value, "->", e.allowed)

# %% 5. Your own force series (numpy): a half-sine of 12 kN for 0.2 s.
t = np.linspace(0.0, 0.6, 601)
fx = np.where(t < 0.2, 12.0 * np.sin(np.pi * t / 0.2), 0.0)
print("half-sine:", caisson.run(sc, t_s=t, fx_kn=fx).summary["permanent_sliding_m"], "m")

# %% 6. Wave loads on the PARI caisson for 1000 heights at once (columns as `caisson loads --json`).
pari = caisson.Scenario.from_toml(EXAMPLES / "pari_breaking_loads.toml")
loads = caisson.loads.evaluate(pari, np.linspace(0.05, 0.5, 1000))
print(loads[["wave.incident_height_m", "regime.regime", "goda.horizontal_force_kn_per_m", "impact.horizontal_force_kn_per_m"]].iloc[::250])

# %% 7. Wave functions broadcast like ufuncs.
print(caisson.waves.wavelength_m(np.array([[6.0], [12.0]]), np.array([5.0, 10.0, 20.0])))

# %% 8. A campaign: an xarray Dataset (condition × realization).
ds = caisson.campaign(caisson.Scenario.from_toml(EXAMPLES / "pari_nonbreaking_campaign.toml"))
print(ds[["height_m", "weight_in_water_kn", "sliding_mean_m"]].to_dataframe().head())

# %% 9. Performance-based design: lives in any order, statistics as design.json.
design = caisson.Design(caisson.Scenario.from_toml(EXAMPLES / "design_breakwater.toml"), lives=20)
lives = design.simulate_lives()
stats = design.statistics(lives)
print(f"{stats['lives']} lives: expected sliding {stats['dynamic']['expected_sliding_m']:.4f} m")

# %% 10. A plot.
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

fig, ax = plt.subplots(figsize=(6, 3))
ax.plot(r.history["time_s"], r.history["fx_kn"], label="wave force F_x (kN)")
ax.plot(r.history["time_s"], r.history["reaction_x_kn"], label="base reaction R_x (kN)")
ax.set_xlabel("time (s)")
ax.legend()
fig.tight_layout()
fig.savefig(out / "quickstart.png", dpi=80)
print("wrote", out / "quickstart.png")
