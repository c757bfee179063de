#!/usr/bin/env bash
# Every command and the long Python calls under a 3 GiB address-space limit (`ulimit -v`, issue 21):
# each must finish or refuse with a clear error (`Error:` / a Python exception of the package or a
# MemoryError); none may panic, abort or be killed by a signal. Prints one line per case and exits
# non-zero if any case failed.
#
#   scripts/address-limit.sh            (after `cargo build --release -p caisson-cli`; the Python
#                                        cases need .venv from scripts/test.sh, skipped without it)
set -uo pipefail
cd "$(dirname "$0")/.."
LIMIT_KIB=${LIMIT_KIB:-3145728}
BIN=${CAISSON_BIN:-target/release/caisson}
[ -x "$BIN" ] || { echo "build the CLI first: cargo build --release -p caisson-cli" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
cases=0

# check NAME COMMAND...: run under the limit; a signal (exit > 128) or a panic fails the case.
check() {
    local name=$1
    shift
    cases=$((cases + 1))
    (ulimit -v "$LIMIT_KIB"; exec timeout 600 "$@") >"$work/out" 2>"$work/err"
    local rc=$?
    local first
    first=$(grep -m1 -E '^(Error|[A-Za-z]*Error|KeyboardInterrupt)' "$work/err" | cut -c1-150)
    if [ $rc -gt 128 ] || [ $rc -eq 124 ] || grep -qiE 'panicked|PanicException|memory allocation of' "$work/err"; then
        failed=$((failed + 1))
        printf 'FAIL  %-44s exit %3d  %s\n' "$name" "$rc" "$(tail -c 300 "$work/err" | tr '\n' ' ')"
    elif [ $rc -eq 0 ]; then
        printf 'ok    %-44s exit %3d  finished\n' "$name" "$rc"
    else
        printf 'ok    %-44s exit %3d  refused: %s\n' "$name" "$rc" "${first:-$(tail -n1 "$work/err" | cut -c1-150)}"
    fi
}

E=examples
sed 's/^lives = 5000/lives = 20/' $E/design_breakwater.toml >"$work/design.toml"
sed 's/^lives = 5000/lives = 10000000/' $E/design_breakwater.toml >"$work/design_huge.toml"
sed -e 's/^lives = 2000 .*/lives = 4/' -e 's/^curve_points = 8/curve_points = 2/' -e 's/^tolerance_m = 0.25/tolerance_m = 5.0/' \
    $E/size_breakwater.toml >"$work/size.toml"
sed -e 's/^life_years = 50/life_years = 500/' -e 's/^lives = 2000 .*/lives = 1000000/' $E/size_breakwater.toml >"$work/size_huge.toml"
sed 's/^storms = 100 .*/storms = 4/' $E/fragility.toml >"$work/fragility.toml"
sed 's/^duration_s = 0.6/duration_s = 1e5/' $E/table5_triangle.toml >"$work/long.toml"

check "run table5_triangle --out" "$BIN" run $E/table5_triangle.toml --out "$work/o1"
check "run fifteen_waves --out" "$BIN" run $E/fifteen_waves.toml --out "$work/o2"
check "run 1e5 s at dt 1e-4 --out (budget)" "$BIN" run "$work/long.toml" --out "$work/o3"
check "spectrum 0.1:10:20" "$BIN" spectrum $E/table5_triangle.toml --tr-over-t0 0.1:10:20
check "loads pari_breaking_loads --out" "$BIN" loads $E/pari_breaking_loads.toml --out "$work/o4"
check "campaign pari_breaking_campaign" "$BIN" campaign $E/pari_breaking_campaign.toml
check "design 20 lives --out" "$BIN" design "$work/design.toml" --out "$work/o5"
check "design 1e7 lives (budget)" "$BIN" design "$work/design_huge.toml"
check "fragility 4 storms" "$BIN" fragility "$work/fragility.toml"
check "size 4 lives" "$BIN" size "$work/size.toml" --out "$work/o6"
check "size 1e6 lives of 500 years (budget)" "$BIN" size "$work/size_huge.toml"
check "merge /dev/zero" "$BIN" merge "$work/design.toml" /dev/zero --out "$work/o7"
check "report 20 lives --no-pdf" "$BIN" report "$work/design.toml" --out "$work/o11" --no-pdf
check "run /dev/zero as scenario" "$BIN" run /dev/zero
# A checkpoint with a 256 MiB NUL tail (what a machine crash can leave), resumed.
truncate -s +256M "$work/o5/checkpoint.jsonl"
check "design --resume, 256 MiB NUL tail" "$BIN" design "$work/design.toml" --resume --out "$work/o5"
check "merge a shard with a NUL tail" "$BIN" merge "$work/design.toml" "$work/o5" --out "$work/o8"

# The third fuzz round's findings (issue 37): each finishes finite or is refused naming its key.
sed 's/^tidal_range_m = 2.0/tidal_range_m = 2.0\nerror_truncated = false\nfriction_cov = 0.25/' \
    $E/design_breakwater.toml >"$work/friction.toml"
sed 's/^width_m = 20.0 .*/width_m = 1.0/' $E/design_breakwater.toml >"$work/slender.toml"
sed 's/^storm_shape = 1.4 .*/storm_shape = 0.12/' $E/design_breakwater.toml >"$work/tail.toml"
sed 's/^e100_kpa = 3.5e5/e100_kpa = 3.5e5\nky_kn_per_m = 1e-200/' $E/table5_triangle.toml >"$work/ky.toml"
sed 's/^e100_kpa = 3.5e5/e100_kpa = 3.5e5\nkx_kn_per_m = 5e-324/' "$work/fragility.toml" >"$work/kx.toml"
sed 's/^significant_heights_m = \[7.0,/significant_heights_m = [1e-300, 7.0,/' "$work/fragility.toml" >"$work/heights.toml"
sed 's/^title = .*/title = "PARI\\u001b[31m\\ttab"/' $E/pari_breaking_campaign.toml >"$work/title.toml"
check "design friction error <= 0, shard 4278..4280" "$BIN" design "$work/friction.toml" --life-range 4278..4280 --out "$work/o9"
check "design friction shard --resume" "$BIN" design "$work/friction.toml" --life-range 4278..4280 --resume --out "$work/o9"
check "design 1 m wide, shard 1898..1900" "$BIN" design "$work/slender.toml" --life-range 1898..1900 --out "$work/o10"
check "design storm_shape 0.12 (refused)" "$BIN" design "$work/tail.toml"
check "run ky 1e-200 (refused)" "$BIN" run "$work/ky.toml"
check "fragility kx 5e-324 (refused)" "$BIN" fragility "$work/kx.toml"
check "fragility height 1e-300 (refused)" "$BIN" fragility "$work/heights.toml"
check "campaign, control characters in its title (refused)" "$BIN" campaign "$work/title.toml"

PY=.venv/bin/python
if [ -x "$PY" ]; then
    export OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1
    pycase() { check "python: $1" "$PY" -c "import caisson, numpy as np; E='$E'; $2"; }
    pycase "loads.evaluate 1e7 heights" "caisson.loads.evaluate(caisson.Scenario.from_toml(E+'/pari_breaking_loads.toml'), np.full(10_000_000, 0.2))"
    pycase "loads.evaluate 3e6 heights" "print(len(caisson.loads.evaluate(caisson.Scenario.from_toml(E+'/pari_breaking_loads.toml'), np.full(3_000_000, 0.2))))"
    pycase "run, series of 2e7 samples" "n=20_000_000; caisson.run(caisson.Scenario.from_toml(E+'/table5_triangle.toml'), t_s=np.arange(n, dtype=float), fx_kn=np.zeros(n))"
    pycase "run, 2500 s history held (2.5 GiB)" "caisson.run(caisson.Scenario.from_toml('$work/long.toml'), duration_s=2500.0)"
    pycase "run, 1e4 s history held" "caisson.run(caisson.Scenario.from_toml('$work/long.toml'), duration_s=1e4)"
    pycase "Design 1e7 lives" "caisson.Design(caisson.Scenario.from_toml('$work/design_huge.toml')).simulate_lives()"
    pycase "Design 20 lives" "print(len(caisson.Design(caisson.Scenario.from_toml('$work/design.toml')).simulate_lives(threads=2)))"
    pycase "Fragility 4 storms" "caisson.Fragility(caisson.Scenario.from_toml('$work/fragility.toml')).run(threads=2)"
    pycase "Scenario.from_toml /dev/zero" "caisson.Scenario.from_toml('/dev/zero')"
    pycase "threads=10**6" "caisson.run(caisson.Scenario.from_toml(E+'/fifteen_waves.toml'), threads=10**6)"
    pycase "Design friction error <= 0, life 4278" "print(caisson.Design(caisson.Scenario.from_toml('$work/friction.toml')).simulate_lives([4278]).rigid_block_sliding_m[0])"
    pycase "Design.statistics of another seed's lives" "d=caisson.Design(caisson.Scenario.from_toml('$work/design.toml')); d.statistics(caisson.Design(d.scenario.replace(design={'seed': 2})).simulate_lives([0]))"
else
    echo "(no .venv: the Python cases are skipped; scripts/test.sh creates it)"
fi

echo "$cases cases, $failed failed (address space limited to $((LIMIT_KIB / 1024)) MiB)"
[ "$failed" -eq 0 ]
