# rt-inspect statistics: the table, --json, --rays and the depth histogram, on scenes whose
# trees are known; the scene from a file and from standard input.
source "$(dirname "$0")/common.bash"
source "$(dirname "$0")/inspect_scenes.bash"


# One sphere: a single leaf holding it, in every structure.
for tree in naive bsp kd; do
    expect_exit 0 "$RT_INSPECT" --tree $tree --json "$WORK/one_sphere.xml"
    cp "$WORK/stdout" "$WORK/one_$tree.json"
    [ "$(json_number nodes "$WORK/one_$tree.json")" = 1 ] || fail "$tree: one sphere should give one node"
    [ "$(json_number leaves "$WORK/one_$tree.json")" = 1 ] || fail "$tree: one sphere should give one leaf"
    [ "$(json_number primitiveReferences "$WORK/one_$tree.json")" = 1 ] || fail "$tree: one reference expected"
    grep -q "\"name\": \"$tree\"" "$WORK/one_$tree.json" || fail "$tree: tree not named"
done

# The scene's primitives are counted per kind, in the text and in the JSON.
{
    echo '    <cylinder x0="0" y0="0" z0="10" x1="0" y1="2" z1="10" r="1" material="white" />'
    echo '    <cone x0="3" y0="0" z0="10" r0="1" x1="3" y1="2" z1="10" r1="0" material="white" />'
    echo '    <cone x0="-3" y0="0" z0="10" r0="1" x1="-3" y1="2" z1="10" r1="0.5" material="white" />'
    echo '    <disk x="0" y="4" z="10" nx="0" ny="0" nz="1" r="1" material="white" />'
} | scene "$WORK/cylinder_cones.xml" 60
expect_exit 0 "$RT_INSPECT" --tree kd "$WORK/cylinder_cones.xml"
grep -q "0 triangles, 0 spheres, 1 cylinders, 2 cones, 1 disks," "$WORK/stdout" || fail "counts per kind: $(head -1 "$WORK/stdout")"
expect_exit 0 "$RT_INSPECT" --tree kd --json "$WORK/cylinder_cones.xml"
[ "$(json_number cones "$WORK/stdout")" = 2 ] || fail "JSON: 2 cones expected"
[ "$(json_number cylinders "$WORK/stdout")" = 1 ] || fail "JSON: 1 cylinder expected"
[ "$(json_number disks "$WORK/stdout")" = 1 ] || fail "JSON: 1 disk expected"

# The least gain (--kd-min-gain, docs/trees.md): a speck of 512 tiny spheres over a ground 2,000
# units wide, so that the speck's splits save almost nothing per ray entering the root. A bound
# above any split's saving leaves the root a leaf; the default cuts the speck's deep splits, which
# 0 lets through; the JSON reports the bound used.
{
    cluster 0 0 20 8 0.05 0.02
    echo '    <triangle material="white"><vertex x="-1000" y="-1" z="-1000" /><vertex x="1000" y="-1" z="-1000" />'
    echo '      <vertex x="0" y="-1" z="1000" /></triangle>'
} | scene "$WORK/speck.xml" 60
expect_exit 0 "$RT_INSPECT" --tree kd --json --kd-min-gain 1000 "$WORK/speck.xml"
[ "$(json_number nodes "$WORK/stdout")" = 1 ] || fail "--kd-min-gain 1000: one leaf expected"
[ "$(json_number minimumGain "$WORK/stdout")" = 1000 ] || fail "--kd-min-gain 1000 not in the JSON"
expect_exit 0 "$RT_INSPECT" --tree kd --json --kd-min-gain 0 "$WORK/speck.xml"
ungated=$(json_number nodes "$WORK/stdout")
expect_exit 0 "$RT_INSPECT" --tree kd --json "$WORK/speck.xml"
gated=$(json_number nodes "$WORK/stdout")
[ "$gated" -gt 1 ] || fail "the default least gain left the speck's root a leaf"
[ "$ungated" -gt "$gated" ] || fail "--kd-min-gain 0 built $ungated nodes, the default $gated: the bound did nothing"

# Two separated clusters: both trees split between them at the root, on x, and every
# sphere is referenced at least once.
for tree in bsp kd; do
    expect_exit 0 "$RT_INSPECT" --tree $tree --json --depth-histogram "$WORK/two_clusters.xml"
    cp "$WORK/stdout" "$WORK/two_$tree.json"
    nodes=$(json_number nodes "$WORK/two_$tree.json")
    refs=$(json_number primitiveReferences "$WORK/two_$tree.json")
    [ "$nodes" -ge 3 ] || fail "$tree: two clusters gave $nodes nodes"
    [ "$refs" -ge 128 ] || fail "$tree: 128 spheres but $refs references"
    # The histogram's references add up to the total.
    sum=$(awk '/"depthHistogram"/ {h = 1} h && /"primitiveReferences"/ {gsub(",", ""); s += $2} END {print s}' \
          "$WORK/two_$tree.json")
    [ "$sum" = "$refs" ] || fail "$tree: depth histogram sums to $sum references, the tree has $refs"

    expect_exit 0 "$RT_INSPECT" --tree $tree --dump json --max-depth 0 "$WORK/two_clusters.xml"
    grep -q '"axis": "x"' "$WORK/stdout" || fail "$tree: root does not split x: $(cat "$WORK/stdout")"
    split=$(json_number split "$WORK/stdout")
    # The clusters span x in [-10.95, -9.05] and [9.05, 10.95]; a split on a cluster's face counts.
    awk -v s="$split" 'BEGIN { exit !(s >= -9.051 && s <= 9.051) }' || fail "$tree: root split $split is not in the gap"
done

# The table: one column per tree; the thesis's Table 4.3 with --rays.
expect_exit 0 "$RT_INSPECT" --tree all --rays -s -d 2 -x 80 -y 60 "$WORK/two_clusters.xml"
grep -q "^statistic  *bsp  *kd-sweep  *bvh$" "$WORK/stdout" || fail "no bsp, kd and bvh columns: $(head -5 "$WORK/stdout")"
for row in "nodes" "empty leaves" "SAH cost" "camera rays" "shadow rays" "intersection tests per ray"; do
    grep -q "^$row  " "$WORK/stdout" || fail "no row '$row'"
done
grep -q "^camera rays  *4800  *4800  *4800$" "$WORK/stdout" || fail "80x60 should be 4800 camera rays"
grep -q "^Table 4.3" "$WORK/stdout" || fail "no Table 4.3"
grep -q "^two_clusters  " "$WORK/stdout" || fail "Table 4.3 has no row for the scene"

# Standard input gives the same statistics as the file (build time aside).
expect_exit 0 "$RT_INSPECT" --tree kd --json - <"$WORK/two_clusters.xml"
grep -v -e buildSeconds -e '"file"' "$WORK/stdout" >"$WORK/from_stdin.json"
expect_exit 0 "$RT_INSPECT" --tree kd --json "$WORK/two_clusters.xml"
grep -v -e buildSeconds -e '"file"' "$WORK/stdout" >"$WORK/from_file.json"
cmp -s "$WORK/from_stdin.json" "$WORK/from_file.json" || fail "statistics differ between standard input and file"

# Tree parameters reach the trees: a BSP depth limit of 1 gives at most 3 nodes.
expect_exit 0 "$RT_INSPECT" --tree bsp --json --bsp-max-depth 1 "$WORK/two_clusters.xml"
[ "$(json_number nodes "$WORK/stdout")" -le 3 ] || fail "--bsp-max-depth 1 ignored"
grep -q '"maxDepth": 1' "$WORK/stdout" || fail "settings not reported"
expect_exit 0 "$RT_INSPECT" --tree kd --json --kd-split sample --kd-samples 8 "$WORK/two_clusters.xml"
grep -q '"split": "sample"' "$WORK/stdout" || fail "--kd-split not reported"
# The rays are rt-render's: the same counts, under the same names, as its --stats-json for
# the same flags, also with supersampling and distributed ray tracing.
compare_with_render() {
    expect_exit 0 "$RT_RENDER" "$RT_SOURCE_DIR/scenes/demo.xml" --accel kd "$@" -q -o null --stats-json -
    cp "$WORK/stdout" "$WORK/render.json"
    expect_exit 0 "$RT_INSPECT" "$RT_SOURCE_DIR/scenes/demo.xml" --tree kd --rays "$@" --json
    for key in cameraRays shadowRays reflectionRays rays intersectionTests traversalSteps; do
        theirs=$(json_number $key "$WORK/render.json")
        ours=$(json_number $key "$WORK/stdout")
        [ -n "$ours" ] && [ "$ours" = "$theirs" ] || fail "$*: $key: rt-inspect counts $ours, rt-render $theirs"
    done
}
compare_with_render -s -d 3 -x 64 -y 48
hard=$(json_number shadowRays "$WORK/stdout")
compare_with_render -D s -r 4 -d 3 -x 64 -y 48
# Every demo light has a size: each hard shadow ray becomes a bundle of 4.
[ "$(json_number shadowRays "$WORK/stdout")" = $((4 * hard)) ] || fail "-D s -r 4: not 4 shadow rays for each of $hard"
compare_with_render -D b -r 3 -S 4 -d 2 -x 32 -y 24
[ "$(json_number cameraRays "$WORK/stdout")" = $((4 * 32 * 24)) ] || fail "-S 4: not 4 camera rays per pixel"
# --threads is the build's thread count too (1 below the 16,384 primitives from which it starts threads).
awk 'BEGIN { for (i = 0; i < 130; ++i) for (j = 0; j < 130; ++j)
    printf "    <sphere x=\"%d\" y=\"%d\" z=\"40\" r=\"0.3\" material=\"white\" />\n", i - 65, j - 65 }' |
    scene "$WORK/grid.xml" 90
for threads in 1 2; do
    expect_exit 0 "$RT_INSPECT" --tree kd --json --threads $threads "$WORK/grid.xml"
    [ "$(json_number buildThreads "$WORK/stdout")" = $threads ] || fail "--threads $threads: the build ran on $(json_number buildThreads "$WORK/stdout")"
done
expect_exit 0 "$RT_INSPECT" --tree kd --json --threads 2 "$WORK/one_sphere.xml"
[ "$(json_number buildThreads "$WORK/stdout")" = 1 ] || fail "one sphere: the build should start no thread"
echo "inspect_stats: ok"
