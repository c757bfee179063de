#!/usr/bin/env bash
# Regenerate the rendered example of every kind of plot the commands write, into docs/figures/
# (listed with what each shows in docs/figures/README.md), from the bundled examples:
#
#   scripts/figures.sh            # about 2 minutes on 2 cores (the sizing example dominates)
#
# The validation report's figures (docs/figures/validation_*.svg) come from `caisson validation
# --out docs` instead.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
cargo build --release -q -p caisson-cli
bin="$top/target/release/caisson"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fig="$top/docs/figures"

# `figure NAME COMMAND ARGS... -- FILE...`: run the command into a scratch directory and copy
# each FILE it wrote to docs/figures/NAME_FILE.
figure() {
    local name=$1
    shift
    local args=()
    while [ "$1" != "--" ]; do
        args+=("$1")
        shift
    done
    shift
    rm -rf "${work:?}/$name"
    "$bin" "${args[@]}" --out "$work/$name" >/dev/null 2>&1
    for f in "$@"; do
        cp "$work/$name/$f" "$fig/${name}_$f"
    done
    echo "docs/figures/${name}_{$(echo "$@" | tr ' ' ',')}"
}

figure breakwater_impact run examples/breakwater_impact.toml -- loads.svg displacements.svg
figure table5_triangle run examples/table5_triangle.toml -- loads.svg displacements.svg
figure wave_train run examples/pari_breaking_loads.toml -- sliding.svg springs.svg
figure spectrum spectrum examples/table5_triangle.toml -- spectrum.svg
figure loads loads examples/pari_breaking_loads.toml --history -- wave_loads.svg
figure campaign campaign examples/pari_breaking_campaign.toml -- campaign.svg campaign_vs_height.svg
figure design design examples/design_breakwater.toml -- histogram.svg exceedance.svg
figure design design examples/breaking_site_15m.toml -- heel_pressure.svg
figure fragility fragility examples/fragility.toml -- fragility.svg
figure size size examples/size_breakwater.toml -- design_curve.svg
