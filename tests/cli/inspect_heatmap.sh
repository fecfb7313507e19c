# rt-inspect --heatmap: a PNG of the picture plus its colour bar, hottest where the geometry
# is densest. Viridis's green channel rises monotonically with the value, so it stands in
# for the work in the comparisons below.
source "$(dirname "$0")/common.bash"
source "$(dirname "$0")/inspect_scenes.bash"

# green STAT FILE X Y W H: the Min, Max or Avg of the green values (0-1) in a window.
green() {
    oiiotool "$2" --cut "${5}x${6}+${3}+${4}" --printstats 2>/dev/null | awk -v s="$1" '$2 == s ":" {print $4}'
}

for tree in kd bsp; do
    expect_exit 0 "$RT_INSPECT" --tree $tree --heatmap "$WORK/heat.png" -x 120 -y 90 "$WORK/dense_left.xml"
    info=$(iinfo "$WORK/heat.png") || fail "iinfo cannot read the heat map"
    grep -q "120 x *1[0-9][0-9], 3 channel, uint8 png" <<<"$info" || fail "unexpected heat map: $info"
    iinfo -v "$WORK/heat.png" | grep -q 'Software: "rt-inspect [0-9]' || fail "the heat map does not name rt-inspect"
    # The hottest pixel is in the dense cluster, on the left of the picture.
    left=$(green Max "$WORK/heat.png" 0 0 60 90)
    right=$(green Max "$WORK/heat.png" 60 0 60 90)
    awk -v l="$left" -v r="$right" 'BEGIN { exit !(l > 0.8 && r < l - 0.2) }' \
        || fail "$tree: the dense cluster (left, $left) should be hotter than the sparse side ($right)"
    # The strip under the picture holds the colour bar: dark on the left end, bright on the right.
    low=$(green Avg "$WORK/heat.png" 10 95 4 4)
    high=$(green Avg "$WORK/heat.png" 106 95 4 4)
    awk -v a="$low" -v b="$high" 'BEGIN { exit !(b > a + 0.5) }' || fail "$tree: no colour bar ($low to $high)"
done

# Several trees: one picture each, on one shared scale.
expect_exit 0 "$RT_INSPECT" --tree all --heatmap "$WORK/pair.png" -x 64 -y 48 --heatmap-scale log "$WORK/dense_left.xml"
[ -s "$WORK/pair-bsp.png" ] && [ -s "$WORK/pair-kd.png" ] && [ -s "$WORK/pair-bvh.png" ] ||
    fail "--tree all should write pair-bsp.png, pair-kd.png and pair-bvh.png"
[ ! -e "$WORK/pair.png" ] || fail "pair.png should not exist"
# --heatmap-rays all adds each pixel's shadow rays to its camera rays: on one fixed scale
# (--heatmap-max), the picture is nowhere cooler and somewhere warmer.
for rays in camera all; do
    expect_exit 0 "$RT_INSPECT" --heatmap "$WORK/$rays.png" --heatmap-rays $rays --heatmap-max 400 -s \
        -x 120 -y 90 "$WORK/dense_left.xml"
done
camera=$(green Avg "$WORK/camera.png" 0 0 120 90)
all=$(green Avg "$WORK/all.png" 0 0 120 90)
awk -v c="$camera" -v a="$all" 'BEGIN { exit !(a > c) }' || fail "all rays ($all) not warmer than camera rays ($camera)"
expect_exit 2 "$RT_INSPECT" --heatmap "$WORK/x.png" --heatmap-rays some "$WORK/dense_left.xml"

# A heat map is a PNG: another extension is refused before any work, as rt-render refuses
# one it does not write; .PNG is a PNG.
for name in heat.jpg heat.exr heat; do
    expect_exit 2 "$RT_INSPECT" --heatmap "$WORK/$name" -x 32 -y 24 "$WORK/dense_left.xml"
    expect_one_error rt-inspect "$WORK/$name: a heat map is a PNG"
    [ ! -e "$WORK/$name" ] || fail "--heatmap $name wrote a file"
done
expect_exit 0 "$RT_INSPECT" --heatmap "$WORK/upper.PNG" -x 32 -y 24 "$WORK/dense_left.xml"
iinfo "$WORK/upper.PNG" | grep -q "png" || fail "--heatmap upper.PNG is no PNG"

# --threads as rt-render's: the same heat map and the same ray counts on one thread or two.
for threads in 1 2; do
    expect_exit 0 "$RT_INSPECT" --threads $threads --heatmap "$WORK/threads$threads.png" --heatmap-rays all -s \
        --rays --json -x 64 -y 48 "$WORK/dense_left.xml"
    cp "$WORK/stdout" "$WORK/threads$threads.json"
done
cmp -s "$WORK/threads1.png" "$WORK/threads2.png" || fail "--threads 1 and 2 give different heat maps"
for key in cameraRays shadowRays traversalSteps intersectionTests; do
    [ "$(json_number $key "$WORK/threads1.json")" = "$(json_number $key "$WORK/threads2.json")" ] ||
        fail "--threads 1 and 2 count different $key"
done
echo "inspect_heatmap: ok"
