# The structure rt-render traces with when none is named (docs/trees.md, "The path tracer's structure"):
# the KD tree for the Whitted tracer, the BVH for the path tracer, whichever comes first on the command
# line; -B, -K and --accel still choose; --stats-json records the default used as --accel's value.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/spheres.xml"
# The tree's name and the --accel value the statistics record, for the options $@.
structure() {
    "$RT_RENDER" "$scene" -q -x 8 -y 6 -S 1 -o null "$@" --stats-json "$WORK/s.json" || fail "rt-render $* failed"
    echo "$(jq -r .tree.name "$WORK/s.json") $(jq -r .options.accel "$WORK/s.json")"
}
check() {  # expected options...
    local want=$1 got
    shift
    got=$(structure "$@")
    [ "$got" = "$want" ] || fail "rt-render $*: tree and --accel '$got', expected '$want'"
}
check "kd kd"
check "bvh bvh" --integrator path
check "kd kd" --integrator whitted
check "kd kd" --accel kd --integrator path
check "naive naive" --integrator path --accel naive
check "kd kd" --integrator path -K
[ "$(structure --integrator path -B | cut -d' ' -f1)" = bsp ] || fail "-B with the path tracer: $(structure --integrator path -B)"
