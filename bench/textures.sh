#!/usr/bin/env bash
# Image textures: speed against the same scenes untextured, first render against a second, and
# peak memory (docs/benchmarks.md, "Textures").
#
#   bench/textures.sh [rt-render [rt-convert]]   (default: build/release's; models from $RT_SHARED_DIR
#                                                 or ../shared)
#
# Environment: RT_TEXTURES_MODELS, more model files to measure after the shared ones (paths
# separated by spaces, e.g. a copy of Khronos' DamagedHelmet, whose five textures no shared model
# has); RT_TEXTURES_MEMORY=off leaves out the memory measurement (the 12 generated pictures).
#
# Any rt-render may be measured (an older build, to compare); $RT_TX_CACHE points into the
# script's own folder, so that a build with the old tx cache makes its copies there.
#
# Speed: textured models of ../shared rendered straight from the model file, and the same scene
# converted to XML with every texture attribute taken out (same geometry, lights and materials);
# 640x480, by the Whitted tracer (shadows, reflection depth 2) and the path tracer (4 samples a
# pixel), best of 3 render times (--stats-json's renderSeconds). "first/second": the wall-clock
# time of a whole first rt-render process over that of a second one (no cache to warm: near 1).
# "peak": the Whitted render's maximum resident memory (/usr/bin/time -v).
#
# Memory: a generated OBJ of 12 quads in a 4 x 3 grid filling the picture, each with its own
# 2048 x 2048 noise picture (8-bit RGB PNG: 12 MB decoded each, 16 MB with MIP levels, 192 MB in
# all), rendered by the Whitted tracer and the path tracer; peak resident memory against
# rt-render's start-up (`rt-render --version`).
set -euo pipefail
cd "$(dirname "$0")/.."
render=$(realpath "${1:-build/release/tools/render/rt-render}")
convert=$(realpath "${2:-build/release/tools/convert/rt-convert}")
shared=${RT_SHARED_DIR:-../shared}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export RT_TX_CACHE="$work/tx"
whitted=(-x 640 -y 480 -s -d 2)
path=(-x 640 -y 480 --integrator path --spp 4)

# The render's seconds (--stats-json's renderSeconds), best of 3.
seconds() { "$render" "$@" -o null -q --stats-json - | jq .renderSeconds; }
best_of_3() { for _ in 1 2 3; do seconds "$@"; done | sort -g | head -1; }

# The wall-clock seconds and peak resident kB of one whole rt-render process: "SECONDS KB".
process() {
    /usr/bin/time -f '%e %M' -o "$work/time" "$render" "$@" -o null -q || { cat "$work/time" >&2; exit 1; }
    cat "$work/time"
}

models=()
for model in glb/Duck/Duck.glb gltf/Suzanne/Suzanne.gltf gltf/LightsPunctualLamp/LightsPunctualLamp.gltf \
    obj/scrub-pine/scrubPine.obj glb/NormalTangentMirrorTest/NormalTangentMirrorTest.glb; do
    models+=("$shared/models/$model")
done
# shellcheck disable=SC2206
models+=(${RT_TEXTURES_MODELS:-})

printf '%-56s %-8s %9s %9s %6s %13s %7s\n' model tracer textured plain ratio first/second peak
for file in "${models[@]}"; do
    model=${file#"$shared/models/"}
    "$convert" "$file" -o "$work/scene.xml" 2>/dev/null
    sed -E -i 's/ [a-z_]*texture="[^"]*"//g' "$work/scene.xml"
    rm -rf "$RT_TX_CACHE"
    read -r first kb < <(process "$file" "${whitted[@]}")
    read -r second _ < <(process "$file" "${whitted[@]}")
    for tracer in whitted path; do
        declare -n options=$tracer
        textured=$(best_of_3 "$file" "${options[@]}")
        plain=$(best_of_3 "$work/scene.xml" "${options[@]}")
        awk -v m="$model" -v r="$tracer" -v t="$textured" -v p="$plain" -v f="$first" -v s="$second" -v k="$kb" \
            'BEGIN { printf "%-56s %-8s %8.3fs %8.3fs %5.2fx %5.2fs/%5.2fs %6.0fM\n", m, r, t, p, p / t, f, s, k / 1024 }'
    done
done

[ "${RT_TEXTURES_MEMORY:-on}" = off ] && exit 0
mkdir -p "$work/big"
: >"$work/big/quads.mtl"
{
    echo "mtllib quads.mtl"
    for i in $(seq 0 11); do
        x=$((i % 4)) y=$((i / 4))
        oiiotool --pattern noise:min=0:max=1 2048x2048 3 -d uint8 -o "$work/big/t$i.png"
        printf 'newmtl m%d\nKd 1 1 1\nmap_Kd t%d.png\n' "$i" "$i" >>"$work/big/quads.mtl"
        printf 'v %d %d 0\nv %d %d 0\nv %d %d 0\nv %d %d 0\n' "$x" "$y" $((x + 1)) "$y" $((x + 1)) $((y + 1)) "$x" $((y + 1))
        printf 'vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl m%d\n' "$i"
        b=$((4 * i + 1))
        printf 'f %d/%d %d/%d %d/%d\nf %d/%d %d/%d %d/%d\n' $b $b $((b + 1)) $((b + 1)) $((b + 2)) $((b + 2)) \
            $b $b $((b + 2)) $((b + 2)) $((b + 3)) $((b + 3))
    done
} >"$work/big/quads.obj"
read -r _ base < <(/usr/bin/time -f '%e %M' "$render" --version 2>&1 >/dev/null)
camera=(--look-from 2,1.5,3.2 --look-at 2,1.5,0 --fov 70 -x 1200 -y 900)
printf '\n%-42s %9s %9s %9s %9s\n' "12 textures of 2048x2048, 8-bit RGB" seconds peak start-up work
rm -rf "$RT_TX_CACHE"
for run in "whitted, first:" "whitted, second:" "path -S 1:--integrator path -S 1"; do
    name=${run%%:*} options=${run#*:}
    # shellcheck disable=SC2086
    read -r s kb < <(process "$work/big/quads.obj" "${camera[@]}" $options)
    awk -v n="$name" -v s="$s" -v k="$kb" -v b="$base" \
        'BEGIN { printf "%-42s %8.2fs %8.0fM %8.0fM %8.0fM\n", n, s, k / 1024, b / 1024, (k - b) / 1024 }'
done
