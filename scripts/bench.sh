#!/usr/bin/env bash
# The headline figures of BENCHMARKS.md ("Current figures"), end to end through the CLI, in one
# command anyone can rerun:
#
#   scripts/bench.sh                      # build HEAD's release binary and time it
#   scripts/bench.sh OLD_BIN              # time OLD_BIN and HEAD's binary in the same run (before/after)
#   RUNS=5 scripts/bench.sh               # runs per command (default 3; sizing and validation 1/3 of it, at least 1)
#   ONLY=design scripts/bench.sh          # only the rows whose description contains "design"
#
# Every command runs with `--threads 2` (validation has no such option) (the project's machine class) under hyperfine; the table
# gives the median wall time and the mean user CPU time of the runs, with the load average before
# and after, the machine and the revision, as markdown to paste into BENCHMARKS.md. On a
# shared machine the CPU time is the figure to compare (the wall time depends on whether the second
# core was free). About 3 minutes per binary at RUNS=3.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
command -v hyperfine >/dev/null || { echo "Error: hyperfine is not installed (cargo install hyperfine, or your package manager)" >&2; exit 2; }
command -v python3 >/dev/null || { echo "Error: python3 is needed to read hyperfine's JSON" >&2; exit 2; }

runs=${RUNS:-3}
case $runs in ''|*[!0-9]*|0) echo "Error: RUNS='$runs' must be a positive whole number" >&2; exit 2 ;; esac
size_runs=$(( runs / 3 > 0 ? runs / 3 : 1 ))

cargo build --release -q -p caisson-cli
new_bin="$top/target/release/caisson"
bins=("$new_bin")
labels=("HEAD")
if [ $# -ge 1 ]; then
    [ -x "$1" ] || { echo "Error: OLD_BIN '$1' is not an executable file" >&2; exit 2; }
    bins=("$(realpath "$1")" "$new_bin")
    labels=("before" "after")
fi

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# "name|runs|arguments": what the headline table times.
cases=(
    "15-wave test, fixed dt = 1e-4 s, 456 000 steps (\`run examples/fifteen_waves.toml\`, incl. reading the CSV series)|$((runs * 3))|run examples/fifteen_waves.toml --threads 2"
    "PARI non-breaking campaign (2 250 waves)|$runs|campaign examples/pari_nonbreaking_campaign.toml --out @ --threads 2"
    "PARI breaking campaign (2 250 waves)|$runs|campaign examples/pari_breaking_campaign.toml --out @ --threads 2"
    "design example (5000 lives x 50 years)|$runs|design examples/design_breakwater.toml --out @ --threads 2"
    "climate example (\`design examples/design_climate.toml\`)|$runs|design examples/design_climate.toml --out @ --threads 2"
    "fragility example (9 heights x 100 storms)|$runs|fragility examples/fragility.toml --out @ --threads 2"
    "sizing example (\`size examples/size_breakwater.toml\`)|$size_runs|size examples/size_breakwater.toml --out @ --threads 2"
    "validation report (\`validation --out DIR\`)|$size_runs|validation --out @"
)

echo "Machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(awk '/MemTotal/ {printf "%.0f GiB", $2/1048576}' /proc/meminfo)"
echo "Revision: $(git rev-parse --short HEAD)$(git diff --quiet || echo ' (with uncommitted changes)'); $("$new_bin" --version)"
echo "Load average before: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
if [ ${#bins[@]} -eq 2 ]; then
    echo "| what (2 threads) | runs | before: wall (median) | before: user CPU | after: wall (median) | after: user CPU | CPU ratio |"
    echo "|---|---|---|---|---|---|---|"
else
    echo "| what (2 threads) | runs | wall (median) | user CPU (mean) |"
    echo "|---|---|---|---|"
fi
for c in "${cases[@]}"; do
    IFS='|' read -r name n args <<<"$c"
    case $name in *"${ONLY:-}"*) ;; *) continue ;; esac
    warmup=$(( n >= 3 ? 1 : 0 ))
    cmds=()
    for i in "${!bins[@]}"; do
        cmds+=("${bins[$i]} ${args//@/$scratch/out/${labels[$i]}}")
    done
    # A fresh output directory for every run: a design or sizing run would resume its checkpoint.
    hyperfine -w "$warmup" -r "$n" --prepare "rm -rf $scratch/out" \
        --export-json "$scratch/h.json" "${cmds[@]}" >/dev/null 2>&1 \
        || { echo "Error: '$args' failed; run it by hand to see why" >&2; exit 1; }
    python3 - "$scratch/h.json" "$name" "$n" <<'EOF'
import json, sys
results = json.load(open(sys.argv[1]))["results"]
cells = []
for r in results:
    cells += [f"{r['median']:.3g} s", f"{r['user']:.3g} s"]
if len(results) == 2:
    cells.append(f"{results[0]['user'] / results[1]['user']:.2f} x")
print(f"| {sys.argv[2]} | {sys.argv[3]} | " + " | ".join(cells) + " |")
EOF
done
echo
echo "Load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
