# The thesis's test scenes through the tools (scenes/thesis/README.md): rt-convert --generate
# writes each, and rt-render -p -b on the file prints the objects and lights of thesis
# Table 4.1. tree and balls2 are counted on the naive list: their KD builds take seconds.
source "$(dirname "$0")/common.bash"

# check NAME OBJECTS LIGHTS [RT-RENDER OPTIONS]: -b prints "build render objects lights nodes tests".
check() {
    local name=$1 objects=$2 lights=$3
    shift 3
    expect_exit 0 "$RT_CONVERT" --generate "$name" -o "$WORK/$name.xml"
    expect_exit 0 "$RT_RENDER" -q -p -b "$@" "$WORK/$name.xml"
    local got
    got=$(awk '{print $3, $4}' "$WORK/stdout")
    [ "$got" = "$objects $lights" ] || fail "$name: -b says '$got' (objects lights), Table 4.1 '$objects $lights'"
}
check balls 7383 3                     # 2 triangles, 7,381 spheres
check balls2 597873 3 --accel naive    # 2 triangles, 597,871 spheres
check ships 1017 2                     # 1,004 triangles, 13 spheres
check tree 180182 7 --accel naive
check pyramid5 18750 1

# The same scene on every run, to the byte.
expect_exit 0 "$RT_CONVERT" --generate ships -o "$WORK/again.xml"
cmp -s "$WORK/ships/ships.raw" "$WORK/again/ships.raw" || fail "ships differs between two runs"

# -o - writes the scene with its models inline, ready for a pipe.
"$RT_CONVERT" --generate pyramid5 -o - 2>/dev/null | "$RT_RENDER" -q -p -b - >"$WORK/piped" \
    || fail "rt-convert --generate pyramid5 -o - | rt-render - failed"
read -r _ _ objects _ <"$WORK/piped"
[ "$objects" = 18750 ] || fail "piped pyramid5 has $objects objects"

# A name that is not a thesis scene, or a model file as well as --generate: one error line, exit 2.
expect_exit 2 "$RT_CONVERT" --generate balls3 -o "$WORK/x.xml"
grep -q "^rt-convert ERROR: .*balls3" "$WORK/stderr" || fail "stderr: $(cat "$WORK/stderr")"
[ ! -e "$WORK/x.xml" ] || fail "a failed --generate wrote x.xml"
expect_exit 2 "$RT_CONVERT" --generate balls "$RT_SOURCE_DIR/scenes/demo.xml"
expect_exit 2 "$RT_CONVERT"
