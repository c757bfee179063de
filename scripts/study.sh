#!/usr/bin/env bash
# The study of the breaking-wave load (docs/design.md, "The breaking-wave load: a study"): every
# scenario of examples/study/ sized under each `[waves] breaking_load` (`caisson size`: the dynamic
# model's and the rigid block's required widths, Goda's width with Takahashi's α_I), the 15 m
# site's lives at Goda's width (`caisson design`), and the PARI breaking campaign
# (examples/pari_breaking_campaign.toml) under each rule, with its 20 % height variability and with
# nominal heights. Then scripts/study.py prints the tables of docs/design.md and writes the plots
# docs/figures/study_*.svg.
#
#   scripts/study.sh [OUT]        # OUT: where the runs' JSON go (default out/study); about
#                                 # 30 minutes of CPU on 2 cores
#
# The runs are deterministic (a fixed seed per scenario): the same build gives the same numbers
# on any machine and thread count.
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
cd "$top"
out=${1:-out/study}
mkdir -p "$out"
cargo build --release -q -p caisson-cli
bin="$top/target/release/caisson"
rules=(cuomo-2010 goda-takahashi none)

# `variant FILE RULE [WATER_LINE]`: FILE with `breaking_load = "RULE"` in [waves] (in place of
# the file's own) and WATER_LINE in [water], on stdout.
variant() {
    local file=$1 rule=$2 water=${3:-}
    awk -v rule="$rule" -v water="$water" '
        /^breaking_load *=/ { next }
        { print }
        /^\[waves\]/ { print "breaking_load = \"" rule "\"" }
        /^\[water\]/ && water != "" { print water }
    ' "$file"
}

for file in examples/study/*.toml; do
    name=$(basename "$file" .toml)
    for rule in "${rules[@]}"; do
        json="$out/size_${name}_${rule}.json"
        if [ ! -s "$json" ]; then
            variant "$file" "$rule" > "$out/${name}_${rule}.toml"
            echo "size $name $rule"
            "$bin" size "$out/${name}_${rule}.toml" --json --threads 2 > "$json.tmp" 2>/dev/null
            mv "$json.tmp" "$json"
        fi
    done
done

# The depth series once more under `goda-takahashi` with α_qs = 1 on every wave
# (`alpha_qs_nonbreaking = 1.0`): Goda's full force on the non-breaking waves too, as the expected
# sliding distance method loads them (the seed's Eq. 29 takes 0.8, Kim et al. 2004).
for file in examples/study/depth_*.toml; do
    name=$(basename "$file" .toml)
    json="$out/size_${name}_goda-takahashi-aqs1.json"
    if [ ! -s "$json" ]; then
        variant "$file" goda-takahashi | sed 's/^breaking_load = .*/&\nalpha_qs_nonbreaking = 1.0/' \
            > "$out/${name}_goda-takahashi-aqs1.toml"
        echo "size $name goda-takahashi, alpha_qs_nonbreaking = 1"
        "$bin" size "$out/${name}_goda-takahashi-aqs1.toml" --json --threads 2 > "$json.tmp" 2>/dev/null
        mv "$json.tmp" "$json"
    fi
done

# The 15 m site's lives at Goda's width (the width of each rule's size run: Goda's does not depend
# on the rule), with their lives.csv (the standard errors).
for rule in "${rules[@]}"; do
    json="$out/design_site_15m_${rule}/design.json"
    if [ ! -s "$json" ]; then
        width=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["goda"]["width_m"])' \
            "$out/size_site_15m_${rule}.json")
        variant examples/study/site_15m.toml "$rule" \
            | sed "s/^width_m = .*/width_m = $width/" > "$out/site_15m_goda_${rule}.toml"
        echo "design site_15m at Goda's width $width m, $rule"
        rm -rf "$out/design_site_15m_${rule}"
        "$bin" design "$out/site_15m_goda_${rule}.toml" --threads 2 --out "$out/design_site_15m_${rule}" >/dev/null 2>&1
    fi
done

# The PARI breaking campaign. `goda-takahashi` needs the berm width, which the seed does not give:
# B_M = 1.12 m = 0.12 L (L = 9.32 m at the toe), the width of the most impulsive berm of
# Takahashi's coefficient.
for heights in varied nominal; do
    for rule in "${rules[@]}"; do
        json="$out/campaign_${heights}_${rule}.json"
        if [ ! -s "$json" ]; then
            berm=""
            [ "$rule" = goda-takahashi ] && berm="berm_width_m = 1.12"
            variant examples/pari_breaking_campaign.toml "$rule" "$berm" > "$out/campaign_${heights}_${rule}.toml"
            if [ "$heights" = nominal ]; then
                sed -i 's/^height_variability = .*/height_variability = "none"/' "$out/campaign_${heights}_${rule}.toml"
            fi
            echo "campaign $heights $rule"
            "$bin" campaign "$out/campaign_${heights}_${rule}.toml" --json --threads 2 > "$json.tmp" 2>/dev/null
            mv "$json.tmp" "$json"
        fi
    done
done

python3 scripts/study.py "$out" docs/figures
