#!/usr/bin/env bash
# Prove that a change moves no number: run every bundled example through every command with two
# builds of `caisson` and compare everything they print and write.
#
#   scripts/same-numbers.sh REV                 # build REV (a git revision) and compare it with HEAD's working tree
#   scripts/same-numbers.sh OLD_BIN NEW_BIN     # compare two binaries
#   scripts/same-numbers.sh --stored            # compare the working tree's build with the stored digests
#   scripts/same-numbers.sh --bless             # store the working tree's digests (a change of numbers)
#
# The stored digests (scripts/same-numbers/digests.txt: a SHA-256 of each normalised output) let CI
# (.ci/run) prove that a commit moves no number without a second build; a commit that changes
# numbers on purpose re-blesses them with the goldens (CONTRIBUTING.md).
#
# JSON outputs are compared as data, keys sorted, without the provenance (`caisson_version`,
# `results_version`, a report's top-level `model`) that a newer build may add; text, CSV and SVG
# byte for byte (checkpoint lines sorted: lives finish in any order; the header holds no results).
# Exit 0 if all is identical, else the differences are listed and the exit code is 1. About two
# minutes per build (the design, fragility and validation examples dominate).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"

mode=compare
if [ $# -eq 1 ] && { [ "$1" = --stored ] || [ "$1" = --bless ]; }; then
    mode=${1#--}
    cargo build --release -q -p caisson-cli
    new_bin="$top/target/release/caisson"
elif [ $# -eq 1 ]; then
    rev=$1
    wt="$top/target/same-numbers/base"
    rm -rf "$wt"
    git worktree prune
    git worktree add --detach "$wt" "$rev" >/dev/null
    trap 'git -C "$top" worktree remove --force "$wt" >/dev/null 2>&1 || true' EXIT
    (cd "$wt" && CARGO_TARGET_DIR="$top/target/same-numbers/target" cargo build --release -q -p caisson-cli)
    old_bin="$top/target/same-numbers/target/release/caisson"
    cargo build --release -q -p caisson-cli
    new_bin="$top/target/release/caisson"
elif [ $# -eq 2 ]; then
    old_bin=$(realpath "$1")
    new_bin=$(realpath "$2")
else
    sed -n '2,19p' "$0"
    exit 2
fi

# Every command on every bundled example it applies to: "name|arguments" (paths relative to the top).
cases=(
    "run_table5|run examples/table5_triangle.toml --out @/files"
    "run_table5_json|run examples/table5_triangle.toml --json"
    "run_series|run examples/table5_series.toml --out @/files"
    "run_fifteen|run examples/fifteen_waves.toml --json"
    "run_trains|run examples/pari_breaking_campaign.toml --out @/files"
    "run_trains_json|run examples/pari_nonbreaking_campaign.toml --json"
    "loads_breaking|loads examples/pari_breaking_loads.toml --history --out @/files"
    "loads_breaking_json|loads examples/pari_breaking_loads.toml --json"
    "loads_nonbreaking|loads examples/pari_nonbreaking_loads.toml --json"
    "loads_design|loads examples/design_breakwater.toml"
    "spectrum|spectrum examples/table5_triangle.toml --out @/files"
    "spectrum_json|spectrum examples/table5_triangle.toml --json --tr-over-t0 0.1:3:12"
    "campaign_nonbreaking|campaign examples/pari_nonbreaking_campaign.toml --out @/files"
    "campaign_breaking_json|campaign examples/pari_breaking_campaign.toml --json"
    "design|design examples/design_breakwater.toml --out @/files"
    "design_json|design examples/design_breakwater.toml --json --lives 300"
    "fragility|fragility examples/fragility.toml --out @/files"
    "fragility_json|fragility examples/fragility.toml --json"
    "validation|validation --out @/files"
)

out="$top/target/same-numbers/out"
rm -rf "$out"
sides="old new"
[ "$mode" = compare ] || sides=new
for side in $sides; do
    bin=${side}_bin
    for c in "${cases[@]}"; do
        name=${c%%|*}
        args=${c#*|}
        dir="$out/$side/$name"
        mkdir -p "$dir"
        # shellcheck disable=SC2086
        "${!bin}" ${args//@/$dir} >"$dir/stdout" 2>"$dir/stderr" || echo "exit $?" >>"$dir/stdout"
    done
done

normalise() {
    python3 - "$1" "$2" <<'PY'
import json, sys
path, prefix = sys.argv[1], sys.argv[2].encode()
with open(path, "rb") as f:
    raw = f.read().replace(prefix, b"OUT/")
if path.endswith(".jsonl"):
    # A checkpoint: one line per finished life, in the order they finished (any order), after a
    # header that names the format and the versions (no results). Format 2 ends each life line
    # with its check (a hash of the header and the line), which is not a result: removed.
    import re
    lines = (re.sub(rb',"check":"[0-9a-f]{16}"}$', b"}", l) for l in raw.splitlines())
    sys.stdout.buffer.write(b"\n".join(sorted(l for l in lines if b"caisson_design_checkpoint" not in l)))
    sys.exit(0)
try:
    doc = json.loads(raw)
except ValueError:
    sys.stdout.buffer.write(raw)
    sys.exit(0)
def strip(v):
    if isinstance(v, dict):
        return {k: strip(x) for k, x in v.items() if k not in ("caisson_version", "results_version")}
    if isinstance(v, list):
        return [strip(x) for x in v]
    return v
# A report's top-level `model` (its profile and model choices) says which model made it, as the
# versions do: not a result, and absent from the reports of older builds.
if isinstance(doc, dict):
    doc.pop("model", None)
json.dump(strip(doc), sys.stdout, sort_keys=True, indent=1)
PY
}

stored="$top/scripts/same-numbers/digests.txt"
if [ "$mode" != compare ]; then
    # One line per output: the SHA-256 of its normalised text and its path under the outputs.
    digests=$(while IFS= read -r -d '' f; do
        rel=${f#"$out/new/"}
        case "$rel" in */stderr) continue ;; esac
        echo "$(normalise "$f" "$out/new/" | sha256sum | cut -d' ' -f1)  $rel"
    done < <(find "$out/new" -type f -print0 | sort -z))
    if [ "$mode" = bless ]; then
        mkdir -p "$(dirname "$stored")"
        echo "$digests" >"$stored"
        echo "stored $(echo "$digests" | wc -l) digests of ${#cases[@]} commands in ${stored#"$top/"}"
        exit 0
    fi
    if diff <(cat "$stored") <(echo "$digests") >"$out/digests.diff"; then
        echo "compared $(echo "$digests" | wc -l) outputs of ${#cases[@]} commands with the stored digests: identical"
        exit 0
    fi
    echo "outputs that differ from the stored digests (< stored, > this build):"
    cat "$out/digests.diff"
    echo "DIFFERENT: a change of numbers re-blesses them (scripts/same-numbers.sh --bless) with the goldens"
    exit 1
fi

status=0
compared=0
while IFS= read -r -d '' f; do
    rel=${f#"$out/old/"}
    new="$out/new/$rel"
    case "$rel" in */stderr) continue ;; esac
    if [ ! -e "$new" ]; then
        echo "missing in the new build: $rel"
        status=1
        continue
    fi
    compared=$((compared + 1))
    if ! cmp -s <(normalise "$f" "$out/old/") <(normalise "$new" "$out/new/"); then
        echo "differs: $rel"
        diff <(normalise "$f" "$out/old/") <(normalise "$new" "$out/new/") | head -n 20 || true
        status=1
    fi
done < <(find "$out/old" -type f -print0 | sort -z)
echo "compared $compared outputs of ${#cases[@]} commands: $([ $status -eq 0 ] && echo identical || echo DIFFERENT)"
exit $status
