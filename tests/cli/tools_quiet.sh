# -q in every tool: nothing on standard error (no summary, notes, warnings or progress) when
# all goes well, and still the error line when it does not. rt-render's is tested with its
# progress output; here rt-convert and rt-inspect, on an OBJ whose conversion has notes
# (no camera, no light).
source "$(dirname "$0")/common.bash"
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n' >"$WORK/t.obj"

expect_exit 0 "$RT_CONVERT" "$WORK/t.obj" -o "$WORK/loud.xml"
grep -q "note: " "$WORK/stderr" || fail "rt-convert without -q printed no notes: $(cat "$WORK/stderr")"
expect_exit 0 "$RT_CONVERT" "$WORK/t.obj" -o "$WORK/quiet.xml" -q
[ ! -s "$WORK/stderr" ] || fail "rt-convert -q printed: $(cat "$WORK/stderr")"
[ -s "$WORK/quiet.xml" ] || fail "rt-convert -q wrote no scene"
expect_exit 0 "$RT_CONVERT" "$WORK/t.obj" --json --quiet
grep -q '"modelTriangles": 1' "$WORK/stdout" || fail "rt-convert -q --json: $(cat "$WORK/stdout")"
[ ! -s "$WORK/stderr" ] || fail "rt-convert --quiet printed: $(cat "$WORK/stderr")"
expect_exit 2 "$RT_CONVERT" "$WORK/absent.obj" -q
expect_one_error rt-convert "absent.obj"

expect_exit 0 "$RT_INSPECT" "$WORK/t.obj"
grep -q "warning: " "$WORK/stderr" || fail "rt-inspect without -q printed no warnings: $(cat "$WORK/stderr")"
expect_exit 0 "$RT_INSPECT" "$WORK/t.obj" -q --rays -x 16 -y 12
[ ! -s "$WORK/stderr" ] || fail "rt-inspect -q printed: $(cat "$WORK/stderr")"
grep -q "^scene .*: 1 triangles" "$WORK/stdout" || fail "rt-inspect -q: no report: $(cat "$WORK/stdout")"
expect_exit 2 "$RT_INSPECT" "$WORK/absent.xml" --quiet
expect_one_error rt-inspect "absent.xml"
echo "tools_quiet: ok"
