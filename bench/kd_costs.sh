#!/usr/bin/env bash
# The KD tree's SAH intersection cost C_I against its single-ray speed, build time and memory on
# bench/vs_embree's scenes (docs/trees.md, "Measured again"), and the thesis scenes' intersection
# tests per ray, which the issue-14 target bounds (half of thesis Table 4.3).
#
#   bench/kd_costs.sh [build-dir] [repeats] [C_I ...]   (default: build/release, 2, 0.4 0.6 0.75)
#
# Each scene is measured `repeats` times, every C_I in turn, so that all see the same load, and the
# fastest of each kept (rays per second of one thread, vs_embree's rt KD column; its build on two
# threads). Needs vs_embree (Embree installed) and jq.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
repeats=${2:-2}
shift $(($# < 2 ? $# : 2))
costs=("$@")
[ ${#costs[@]} -gt 0 ] || costs=(0.4 0.6 0.75)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# Rows "scene rays rate" of a vs_embree table, rates in rays per second; "scene build ms bytes".
rates() {
    awk -F'|' 'function num(s) { gsub(/ /, "", s); m = 1; if (s ~ /M$/) m = 1e6; else if (s ~ /k$/) m = 1e3;
                                  sub(/[Mk]$/, "", s); return s * m }
        $4 ~ /camera|shadow|reflection/ { gsub(/ /, "", $2); gsub(/ /, "", $4); print $2, $4, num($6) }
        $4 ~ / ms / { gsub(/ /, "", $2); split($4, w, " "); split($8, b, " "); print $2, "build", w[1], b[1] }' "$1"
}

echo "| Scene | C_I | camera | shadow | reflection | build, 2 threads (ms) | tree bytes per primitive |"
echo "|---|---|---|---|---|---|---|"
for scene in balls balls2 ships tree pyramid5 tri10k tri100k tri1M stadium100k; do
    for _ in $(seq "$repeats"); do
        for cost in "${costs[@]}"; do
            "$build/bench/vs_embree" --scenes "$scene" --passes 2 --kd-intersection-cost "$cost" >"$work/table.md" 2>/dev/null
            rates "$work/table.md" | sed "s/^/$cost /" >>"$work/$scene.rates"
        done
    done
    for cost in "${costs[@]}"; do
        awk -v c="$cost" -v s="$scene" '$1 == c && $3 != "build" { if ($4 > best[$3]) best[$3] = $4 }
            $1 == c && $3 == "build" { if (!ms || $4 < ms) ms = $4; bytes = $5 }
            END { printf "| %s | %s | %.2fM | %.2fM | %.2fM | %d | %s |\n", s, c, best["camera"] / 1e6,
                         best["shadow"] / 1e6, best["reflection"] / 1e6, ms, bytes }' "$work/$scene.rates"
    done
done

echo
echo "| Scene | C_I | intersection tests per ray (rt-render -s -d 3, 800x600) |"
echo "|---|---|---|"
for scene in balls balls2 ships tree pyramid5; do
    "$build/tools/convert/rt-convert" --generate "$scene" -o "$work/$scene.xml" 2>/dev/null
    for cost in "${costs[@]}"; do
        tests=$("$build/tools/render/rt-render" "$work/$scene.xml" -K -s -d 3 -x 800 -y 600 -o null -q \
            --kd-intersection-cost "$cost" --stats-json - | jq '.rays.intersectionTestsPerRay * 100 | round / 100')
        echo "| $scene | $cost | $tests |"
    done
done
