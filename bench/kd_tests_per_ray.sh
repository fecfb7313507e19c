#!/usr/bin/env bash
# The KD tree's work per ray on the thesis scenes from the corpus's seven views (bench/corpus.sh),
# with the tools of any commit, so that two commits can be compared (issue 37: tests per ray no worse
# than at 2210e5c from any view). The counts are deterministic: the machine's load does not matter.
#
#   bench/kd_tests_per_ray.sh [measured-build] [tools-build] [rt-inspect option ...]
#       (default: build/release for both; the options, as --kd-intersection-cost 1, go to the tree)
#
# tools-build's rt-convert generates the scenes and its rt-inspect finds their bounds (tools a commit
# before rt-convert --generate lacks); measured-build's rt-inspect builds the tree and renders the frame
# (-s -d 3, thesis 4.3). Each view's camera is written into the scene's XML, which every commit reads
# (rt-inspect's --look-from is newer than 2210e5c). Environment: CORPUS_VIEWS, CORPUS_SCENES as in
# bench/corpus.sh; KD_SIZE, the frame (default 800x600).
#
# Out: one line per scene and view: tests and nodes (traversal steps) per ray of all rays, then of the
# camera rays alone. Both commits count a leaf's primitives for a nearest-hit query (not a SIMD block's
# padding lanes), so camera rays compare exactly; a shadow ray counts the primitives up to the one that
# blocks it at 2210e5c, the whole blocks up to the one that blocks it since the leaf blocks (a little more).
# Needs jq.
set -euo pipefail
cd "$(dirname "$0")/.."
measured=${1:-build/release}
tools=${2:-build/release}
shift $(($# < 2 ? $# : 2))
tree_options=("$@")
read -r -a views <<<"${CORPUS_VIEWS:-file overview close inside inside-z grazing top}"
read -r -a scenes <<<"${CORPUS_SCENES:-balls balls2 ships tree pyramid5}"
size=${KD_SIZE:-800x600}
# shellcheck source=bench/corpus_views.bash
source bench/corpus_views.bash
require_built kd_tests_per_ray.sh "$measured/tools/inspect/rt-inspect" "$tools/tools/inspect/rt-inspect" \
    "$tools/tools/convert/rt-convert"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# The scene $1 with its <camera> replaced by the one of rt-render's camera options $2 (none: as it is).
with_camera() {
    awk -v options="$2" 'BEGIN { n = split(options, o, " ")
            for (i = 1; i < n; i += 2) { key = o[i]; sub(/^--/, "", key); value[key] = o[i + 1] } }
        function point(tag, v,    c) { split(v, c, ","); printf "    <%s x=\"%s\" y=\"%s\" z=\"%s\" />\n", tag, c[1], c[2], c[3] }
        n && /<camera[ >]/ { skip = 1
            printf "  <camera fov=\"%s\">\n", value["fov"]
            point("origin", value["look-from"]); point("destination", value["look-at"]); point("up", value["up"])
            print "  </camera>" }
        !skip { print }
        skip && /<\/camera>/ { skip = 0 }' "$1"
}

echo "| Scene | View | tests / ray | nodes / ray | camera tests / ray | camera nodes / ray |"
echo "|---|---|---|---|---|---|"
for scene in "${scenes[@]}"; do
    "$tools/tools/convert/rt-convert" --generate "$scene" -o "$work/$scene.xml" 2>/dev/null
    box=$(bounds "$tools" "$work/$scene.xml")
    for view in "${views[@]}"; do
        with_camera "$work/$scene.xml" "$(view_options "$box" "$view")" >"$work/$scene-$view.xml"
        nice "$measured/tools/inspect/rt-inspect" "$work/$scene-$view.xml" --tree kd --rays -s -d 3 \
            -x "${size%x*}" -y "${size#*x}" --json "${tree_options[@]}" |
            jq -r --arg s "$scene" --arg v "$view" '.trees[0].rays |
                def r: . * 100 | round / 100;
                "| \($s) | \($v) | \(.intersectionTestsPerRay | r) | \(.traversalStepsPerRay | r) | \(.cameraIntersectionTestsPerRay | r) | \(.cameraTraversalStepsPerRay | r) |"'
    done
done
