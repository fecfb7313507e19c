# --watertight (docs/trees.md, "Watertight triangles") reaches rt-render's and rt-inspect's
# structures, and their JSON records it: settings.watertight, false without the option.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/spheres.xml"
watertight() {  # rt-render's settings.watertight with the options $@
    "$RT_RENDER" "$scene" -q -x 8 -y 6 -S 1 -o null "$@" --stats-json "$WORK/s.json" || fail "rt-render $* failed"
    jq -r .tree.settings.watertight "$WORK/s.json"
}
[ "$(watertight --accel bvh --watertight)" = true ] || fail "rt-render --watertight: not recorded"
[ "$(watertight)" = false ] || fail "rt-render without --watertight: settings.watertight is not false"
expect_exit 0 "$RT_INSPECT" "$scene" --watertight -t all --json
[ "$(jq -r '[.trees[].settings.watertight] | join(" ")' "$WORK/stdout")" = "true true true" ] ||
    fail "rt-inspect --watertight -t all: $(jq -c '[.trees[].settings]' "$WORK/stdout")"
