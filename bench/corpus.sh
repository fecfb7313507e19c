#!/usr/bin/env bash
# The BVH against Embree, and the KD tree's intersection tests per ray, on a corpus wider than
# vs_embree's nine scenes (issue 37): the five thesis scenes (rt-convert --generate) and real models
# from the shared test set, each from several views, so that the figures say how the structures do on
# scenes and cameras they were not tuned on, not how they do on their best view.
#
#   bench/corpus.sh [build-dir] [passes] [accel]   (default: build/release, 1, bvh)
#
# Environment: RT_MODELS, the shared models' folder (default /work/shared/models, else ../shared/models);
# CORPUS_VIEWS, the views to take (default all seven below); CORPUS_SCENES, the thesis scenes (default all
# five); CORPUS_MODELS, the models (paths under RT_MODELS; default the list below); CORPUS_RT_OPTIONS, options
# for rt's structure in vs_embree and rt-render (as --watertight; default none).
#
# Views, from the scene's bounding box (min, max, centre c, size s), as rt-render's camera options, in
# (x, up, z) (up: see view_options):
#   file      the file's own camera (a model without one: rt's framing camera)
#   overview  from outside a corner, c + (0.8 s_x, 0.5 max(s_up, wide / 2), 0.9 s_z), at c, fov 60
#   close     a close-up of the centre, from c + (0.2, 0.1, 0.2) s, fov 40
#   inside    from the centre along +x, fov 90
#   inside-z  from a quarter of the way from the centre to the -x,-z corner, at 30 % of the height, along +z,
#             fov 90
#   grazing   along the floor, from just outside min x at 2 % of the height, fov 70
#   top       straight down from above, fov 60
#
# For each scene and view: one run of bench/vs_embree --scene (single rays of one thread against
# rtcIntersect1/rtcOccluded1, packets against rtcIntersect8/rtcOccluded8; the best of `passes`), and one
# KD frame of rt-render at 800x600 -s -d 3 (thesis 4.3) for its intersection tests per ray, the figure
# of thesis Table 4.3. Out: one row per scene and view, then the spread (min / median / max) of each
# ratio over the thesis views and over the model views. vs_embree's own disagreement check still
# applies: a run that fails it is reported on stderr and its row is marked.
# Needs vs_embree (Embree: scripts/install-bench-deps.sh), rt-render, rt-convert, rt-inspect and jq.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
passes=${2:-1}
accel=${3:-bvh}
models_root=${RT_MODELS:-/work/shared/models}
[ -d "$models_root" ] || models_root=../shared/models
read -r -a views <<<"${CORPUS_VIEWS:-file overview close inside inside-z grazing top}"
read -r -a rt_options <<<"${CORPUS_RT_OPTIONS:-}"
read -r -a thesis <<<"${CORPUS_SCENES:-balls balls2 ships tree pyramid5}"
read -r -a models <<<"${CORPUS_MODELS:-glb/Duck/Duck.glb glb/2CylinderEngine/2CylinderEngine.glb \
glb/TransmissionRoughnessTest/TransmissionRoughnessTest.glb gltf/LightsPunctualLamp/LightsPunctualLamp.gltf \
obj/teapot/teapot.obj obj/stanford-bunny/stanford-bunny.obj obj/CornellBox-Sphere/CornellBox-Sphere.obj \
obj/spd-balls/balls_s2.obj 3ds/jeep1/jeep1.3ds}"
# shellcheck source=bench/corpus_views.bash
source bench/corpus_views.bash
require_built corpus.sh "$build/bench/vs_embree" "$build/tools/render/rt-render" "$build/tools/convert/rt-convert" \
    "$build/tools/inspect/rt-inspect"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# "camera shadow reflection camera8 shadow8 tests" of a vs_embree table: rt single / Embree single per ray
# kind, rt packets / Embree packets for camera and shadow rays, and rt's tests per camera ray; "-" for a
# set without rays.
ratios() {
    awk -F'|' '$4 ~ /camera|shadow|reflection/ {
            k = $4; gsub(/ /, "", k); n = $5; gsub(/ /, "", n)
            one[k] = n == "0" ? "-" : $8 + 0; eight[k] = $12; gsub(/ /, "", eight[k]); t[k] = $14 + 0 }
        END { if (eight["camera"] == "" ) exit 1
              printf "%s %s %s %s %s %.2f\n", one["camera"], one["shadow"], one["reflection"],
                     n8(eight["camera"]), n8(eight["shadow"]), t["camera"] }
        function n8(x) { return x == "-" || x == "" ? "-" : x + 0 }' "$1"
}

# rt-render's KD intersection tests per ray of a frame at 800x600 -s -d 3.
kd_tests() {
    local file=$1
    shift
    nice "$build/tools/render/rt-render" "$file" "$@" "${rt_options[@]}" -K -s -d 3 -x 800 -y 600 -o null -q --stats-json - |
        jq '.rays.intersectionTestsPerRay * 100 | round / 100'
}

measure() {  # group scene-name file
    local group=$1 name=$2 file=$3 box view
    box=$(bounds "$build" "$file")
    for view in "${views[@]}"; do
        local -a options
        read -r -a options <<<"$(view_options "$box" "$view")"
        local mark=""
        echo "corpus.sh: $name $view" >&2
        nice "$build/bench/vs_embree" --scene "$file" --accel "$accel" --passes "$passes" "${options[@]}" "${rt_options[@]}" \
            >"$work/table.md" 2>"$work/err.txt" || mark=" (vs_embree failed its agreement check)"
        if ! row=$(ratios "$work/table.md"); then
            echo "corpus.sh: $name $view: vs_embree failed: $(tail -1 "$work/err.txt")" >&2
            continue
        fi
        echo "$group $name $view $row $(kd_tests "$file" "${options[@]}")$mark" >>"$work/rows"
    done
}

for scene in "${thesis[@]}"; do
    "$build/tools/convert/rt-convert" --generate "$scene" -o "$work/$scene.xml" 2>/dev/null
    measure thesis "$scene" "$work/$scene.xml"
done
for model in "${models[@]}"; do
    if [ ! -f "$models_root/$model" ]; then
        echo "corpus.sh: $models_root/$model is missing, skipped" >&2
        continue
    fi
    measure models "$(basename "$model")" "$models_root/$model"
done

kind=$(echo "$accel" | tr '[:lower:]' '[:upper:]')
echo "rt's $kind against Embree $(date -u +%Y-%m-%d), vs_embree best of $passes passes, 800x600, one thread"
echo
echo "| Group | Scene | View | camera | shadow | reflection | camera packets | shadow packets | $kind tests / camera ray | KD tests / ray (-s -d 3) |"
echo "|---|---|---|---|---|---|---|---|---|---|"
awk '{ printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s", $1, $2, $3, $4, $5, $6, $7, $8, $9, $10
       for (i = 11; i <= NF; ++i) printf " %s", $i; print " |" }' "$work/rows"

# min / median / max of column $2 of the rows of group $1 ("-" values left out).
spread() {
    awk -v g="$1" -v c="$2" '$1 == g && $c != "-" { print $c }' "$work/rows" | sort -g |
        awk '{ v[NR] = $1 } END { if (!NR) { print "-"; exit }
                                  m = NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2
                                  printf "%.2f / %.2f / %.2f (%d)\n", v[1], m, v[NR], NR }'
}

echo
echo "Spread, min / median / max (views): rt $kind / Embree > 1 is rt faster"
echo
echo "| Group | camera | shadow | reflection | camera packets | shadow packets | KD tests / ray |"
echo "|---|---|---|---|---|---|---|"
for group in thesis models; do
    echo "| $group | $(spread $group 4) | $(spread $group 5) | $(spread $group 6) | $(spread $group 7) | $(spread $group 8) | $(spread $group 10) |"
done
