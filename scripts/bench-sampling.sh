#!/usr/bin/env bash
# Precision per CPU-second of plain and stratified sampling (issue 35, item 3; docs/design.md,
# "Stratified sampling"; BENCHMARKS.md): each case run plain and with `[design] sampling =
# "stratified"`, one thread, the median of 3 runs' CPU time; prints the standard error of E|S| and
# of P(failure), SE²·CPU (the variance a CPU-second buys, smaller is better) and the gain plain /
# stratified.
#
#   scripts/bench-sampling.sh [PLAIN_LIVES] [POOL_LIVES]     (defaults 5000 and 60000)
#
# Cases: the design example (20 m wide), and the sizing example at its required width (21 m).
set -euo pipefail
cd "$(dirname "$0")/.."
plain_lives=${1:-5000}
pool_lives=${2:-60000}
bin=target/release/caisson
cargo build --release -q -p caisson-cli
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
sed 's/^width_m = 20.0 /width_m = 21.0 /' examples/size_breakwater.toml > "$tmp/size21.toml"
run() { # file lives sampling -> "cpu_s se_es se_pf es pf simulated"
    local file=$1 lives=$2 sampling=$3
    sed "s/^\[design\]/[design]\nsampling = \"$sampling\"/" "$file" > "$tmp/case.toml"
    local times=()
    for _ in 1 2 3; do
        /usr/bin/time -f %U -o "$tmp/t" "$bin" design "$tmp/case.toml" --lives "$lives" --threads 1 --json > "$tmp/j.json" 2>/dev/null
        times+=("$(cat "$tmp/t")")
    done
    python3 - "$tmp/j.json" "${times[@]}" <<'PY'
import json, statistics, sys
j = json.load(open(sys.argv[1])); d = j["dynamic"]
ci = d["failure"]["probability_ci95"]
se_pf = (ci[1] - ci[0]) / (2 * 1.959963984540054)
sim = j.get("sampling", {}).get("simulated_lives", j["lives"])
cpu = statistics.median(float(t) for t in sys.argv[2:])
print(cpu, d["expected_sliding_standard_error_m"], se_pf, d["expected_sliding_m"], d["failure"]["probability"], sim)
PY
}
printf '%-28s %-10s %7s %7s %9s %8s %10s %8s %10s %10s\n' case sampling lives sim cpu_s E_S_m se_E_S P_f se_P_f "SE²·cpu E|S|"
for case in "design example:examples/design_breakwater.toml" "sizing example at 21 m:$tmp/size21.toml"; do
    name=${case%%:*}; file=${case#*:}
    read -r pc pse ppse pe pp psim <<< "$(run "$file" "$plain_lives" plain)"
    read -r sc sse spse se sp ssim <<< "$(run "$file" "$pool_lives" stratified)"
    printf '%-28s %-10s %7s %7s %9.2f %8.4f %10.5f %8.4f %10.5f %10.3e\n' "$name" plain "$plain_lives" "$psim" "$pc" "$pe" "$pse" "$pp" "$ppse" "$(python3 -c "print($pse**2*$pc)")"
    printf '%-28s %-10s %7s %7s %9.2f %8.4f %10.5f %8.4f %10.5f %10.3e\n' "$name" stratified "$pool_lives" "$ssim" "$sc" "$se" "$sse" "$sp" "$spse" "$(python3 -c "print($sse**2*$sc)")"
    python3 -c "print('  gain in variance per CPU-second: E|S| %.2f, P(failure) %.2f' % (($pse**2*$pc)/($sse**2*$sc), ($ppse**2*$pc)/($spse**2*$sc)))"
done
