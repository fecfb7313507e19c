#!/usr/bin/env bash
# Adaptive subsampling (thesis 2.3) against a full render on the five thesis scenes and the demo:
# camera rays and render time saved, and the quality of the picture (PSNR from idiff, SSIM
# computed here over 8x8 windows of luminance, on the 8-bit PNGs a user sees). The table of
# docs/thesis-results.md ("Adaptive subsampling") is this script's output.
#
#   bench/adaptive_quality.sh [--grid 8] [--threshold 0.02] [--threads 0] [--keep DIR]
#   (--keep DIR: leave both pictures of each scene there, SCENE-full.png and SCENE-adaptive.png)
#
# Method: 800x600, shadows on, reflections to depth 3 (-s -d 3) as the thesis's tables, the KD
# tree; one render each (the times are the render's wall clock, rt-render's -b figure).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
grid=8 threshold=0.02 threads=0 keep=""
while [[ $# -gt 0 ]]; do
    case "$1" in
        --grid) grid="$2"; shift 2 ;;
        --threshold) threshold="$2"; shift 2 ;;
        --threads) threads="$2"; shift 2 ;;
        --keep) keep="$(realpath "$2")"; mkdir -p "$keep"; shift 2 ;;
        -h|--help) sed -n '2,12p' "$0"; exit 0 ;;
        *) echo "adaptive_quality.sh ERROR: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
done
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$here"
cmake --preset release >/dev/null
cmake --build --preset release --target rt-render rt-convert >/dev/null
render=build/release/tools/render/rt-render
for s in balls balls2 ships tree pyramid5; do
    build/release/tools/convert/rt-convert --generate "$s" -o "$work/$s.xml" -q
done
cp scenes/demo.xml "$work/demo.xml"

# SSIM (Wang et al. 2004) of two binary PPMs, on Rec.709 luma, over non-overlapping 8x8 windows.
ssim() {
    python3 - "$1" "$2" <<'PY'
import sys
def read(path):
    data = open(path, "rb").read()
    fields, i = [], 0
    while len(fields) < 4:
        while data[i:i+1].isspace(): i += 1
        j = i
        while not data[j:j+1].isspace(): j += 1
        fields.append(data[i:j]); i = j
    w, h = int(fields[1]), int(fields[2])
    px = data[i + 1:]
    return w, h, [0.2126 * px[k] + 0.7152 * px[k + 1] + 0.0722 * px[k + 2] for k in range(0, 3 * w * h, 3)]
w, h, a = read(sys.argv[1]); _, _, b = read(sys.argv[2])
c1, c2 = (0.01 * 255) ** 2, (0.03 * 255) ** 2
total, n = 0.0, 0
for y0 in range(0, h - 7, 8):
    for x0 in range(0, w - 7, 8):
        xs = [a[y * w + x] for y in range(y0, y0 + 8) for x in range(x0, x0 + 8)]
        ys = [b[y * w + x] for y in range(y0, y0 + 8) for x in range(x0, x0 + 8)]
        mx, my = sum(xs) / 64, sum(ys) / 64
        vx = sum((v - mx) ** 2 for v in xs) / 63
        vy = sum((v - my) ** 2 for v in ys) / 63
        cov = sum((p - mx) * (q - my) for p, q in zip(xs, ys)) / 63
        total += ((2 * mx * my + c1) * (2 * cov + c2)) / ((mx * mx + my * my + c1) * (vx + vy + c2))
        n += 1
print(f"{total / n:.4f}")
PY
}

# field FILE NAME: a number from rt-render's --stats-json.
field() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$1" "$2"; }

echo "| scene | camera rays, full | camera rays, adaptive | saved | render s, full | render s, adaptive | PSNR dB | SSIM |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
for s in balls balls2 ships tree pyramid5 demo; do
    opts=(-K -s -d 3 -x 800 -y 600 -q --threads "$threads" --alpha off)
    "$render" "$work/$s.xml" "${opts[@]}" -f "$work/full.png" --stats-json "$work/full.json"
    "$render" "$work/$s.xml" "${opts[@]}" -f "$work/adaptive.png" --stats-json "$work/adaptive.json" \
        --adaptive="$grid" --adaptive-threshold "$threshold"
    psnr=$( (idiff -a "$work/full.png" "$work/adaptive.png" 2>&1 || true) | sed -n 's/.*Peak SNR = \([0-9.inf]*\).*/\1/p' | head -1)
    oiiotool "$work/full.png" -o "$work/full.ppm"
    oiiotool "$work/adaptive.png" -o "$work/adaptive.ppm"
    full_rays=$(field "$work/full.json" 'd["rays"]["cameraRays"]')
    rays=$(field "$work/adaptive.json" 'd["rays"]["cameraRays"]')
    printf "| %s | %s | %s | %.1f %% | %.2f | %.2f | %s | %s |\n" "$s" "$full_rays" "$rays" \
        "$(python3 -c "print(100 * (1 - $rays / $full_rays))")" \
        "$(field "$work/full.json" 'd["renderSeconds"]')" "$(field "$work/adaptive.json" 'd["renderSeconds"]')" \
        "${psnr:-?}" "$(ssim "$work/full.ppm" "$work/adaptive.ppm")"
    [ -z "$keep" ] || { cp "$work/full.png" "$keep/$s-full.png"; cp "$work/adaptive.png" "$keep/$s-adaptive.png"; }
done
