#!/usr/bin/env bash
# Image textures: speed against the same scenes untextured, and memory against the texture cache.
#
#   bench/textures.sh [build-dir] [speed]   (default: build/release; models from $RT_SHARED_DIR or ../shared;
#                                            speed: the speed table alone)
#
# Speed: textured models of ../shared rendered straight from the model file, and the same scene
# converted to XML with every texture attribute taken out (same geometry, lights and materials);
# 640x480, shadows, reflection depth 3, best of 3 wall-clock render times (--stats-json's renderSeconds),
# the textures read through their tiled copies (a tx cache of the script's own, emptied first). "copies":
# the seconds the first run takes longer than a later one as a whole process, making the copies.
#
# Memory: a generated OBJ of 12 quads in a 4 x 3 grid filling the picture, each with its own
# 2048 x 2048 noise picture (8-bit RGB PNG: 12 MB each, 16 MB with mip levels, 192 MB in all),
# rendered with --texture-cache 32 (six times less than the textures), by the Whitted tracer
# (filtered: coarse mip levels) and the path tracer (the finest level everywhere). Peak resident
# memory from /usr/bin/time -v, against rt-render's start-up (`rt-render --version`); first the
# run that makes the copies, then runs that read them, then (--tx-cache off) the pictures as they are.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
render="$build/tools/render/rt-render"
convert="$build/tools/convert/rt-convert"
shared=${RT_SHARED_DIR:-../shared}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
export RT_TX_CACHE="$work/tx"

# The render's wall-clock seconds (--stats-json's renderSeconds).
seconds() { "$render" "$@" -x 640 -y 480 -s -d 3 -o null -q --stats-json - | jq .renderSeconds; }
best_of_3() { for _ in 1 2 3; do seconds "$@"; done | sort -g | head -1; }

# Wall-clock seconds of a whole rt-render process.
process_seconds() {
    local start
    start=$(date +%s.%N)
    "$render" "$@" -x 640 -y 480 -s -d 3 -o null -q
    awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }'
}

printf '%-48s %10s %10s %8s %8s\n' model textured untextured ratio copies
for model in glb/Duck/Duck.glb gltf/Suzanne/Suzanne.gltf gltf/LightsPunctualLamp/LightsPunctualLamp.gltf \
    obj/scrub-pine/scrubPine.obj glb/NormalTangentMirrorTest/NormalTangentMirrorTest.glb; do
    "$convert" "$shared/models/$model" -o "$work/scene.xml" 2>/dev/null
    sed -E -i 's/ [a-z_]*texture="[^"]*"//g' \
        "$work/scene.xml"
    rm -rf "$RT_TX_CACHE"
    first=$(process_seconds "$shared/models/$model")
    later=$(process_seconds "$shared/models/$model")
    textured=$(best_of_3 "$shared/models/$model")
    plain=$(best_of_3 "$work/scene.xml")
    awk -v m="$model" -v t="$textured" -v p="$plain" -v c="$(awk -v a="$first" -v b="$later" 'BEGIN { print a - b }')" \
        'BEGIN { printf "%-48s %9.3fs %9.3fs %7.2fx %7.2fs\n", m, t, p, p / t, c }'
done
[[ ${2:-} == speed ]] && exit 0

# rss_kb of one run
peak_kb() {
    /usr/bin/time -v "$@" 2>"$work/time" >/dev/null || { cat "$work/time" >&2; exit 1; }
    awk -F': ' '/Maximum resident/ {print $2}' "$work/time"
}
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
total=$(du -cb "$work"/big/t*.png | tail -1 | cut -f1)
base=$(peak_kb "$render" --version)
camera=(--look-from 2,1.5,3.2 --look-at 2,1.5,0 --fov 70)
printf '\n%-48s %10s %10s %10s\n' "12 textures of 2048x2048 (PNG $((total / 1000000)) MB)" peak start-up work
rm -rf "$RT_TX_CACHE"
for run in "whitted, making the copies:" "whitted:" "path:--integrator path -S 1" \
    "whitted, --tx-cache off:--tx-cache off"; do
    name=${run%%:*} options=${run#*:}
    for cache in 32 256; do
        [[ $name == *making* && $cache == 256 ]] && continue  # made once
        # shellcheck disable=SC2086
        kb=$(peak_kb "$render" "$work/big/quads.obj" "${camera[@]}" -x 1200 -y 900 $options --texture-cache $cache -o null -q)
        awk -v n="$name, --texture-cache $cache" -v k="$kb" -v b="$base" \
            'BEGIN { printf "%-48s %9.0fM %9.0fM %9.0fM\n", n, k / 1024, b / 1024, (k - b) / 1024 }'
    done
done
