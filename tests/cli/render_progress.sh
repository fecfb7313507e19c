# --progress lines (what a log gets): the tree build is announced when it starts and ends,
# then one line per tenth of the work with elapsed time, rate and time left, in order.
source "$(dirname "$0")/common.bash"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
opts=(-K -x 200 -y 150 -S 2 -o null)  # 7 x 5 blocks: every tenth of the work is passed

check_lines() {
    awk '
        /building the kd tree/ { started = NR }
        /tree built: [0-9]+ nodes in/ { built = NR }
        /% of [0-9]+ samples, [0-9.]+ s elapsed, [0-9.e+-]+ M samples\/s/ {
            if (!built || !started || built < started) { print "progress before the build was announced"; exit 1 }
            p = $2 + 0
            if (p <= last) { print "not increasing: " p " after " last; exit 1 }
            if (p < 100 && $0 !~ / s left$/) { print "no time left: " $0; exit 1 }
            last = p; lines++
        }
        END { if (lines < 9 || last != 100) { print lines " lines, last " last "%"; exit 1 } }
    ' "$WORK/stderr" || fail "bad progress lines: $(cat "$WORK/stderr")"
}

expect_exit 0 "$RT_RENDER" "$scene" "${opts[@]}" --progress lines
check_lines
# auto: lines, since standard error is not a terminal here.
expect_exit 0 "$RT_RENDER" "$scene" "${opts[@]}"
check_lines
# -q implies none; none prints no progress but the summary.
expect_exit 0 "$RT_RENDER" "$scene" "${opts[@]}" --progress lines -q
[ ! -s "$WORK/stderr" ] || fail "-q printed: $(cat "$WORK/stderr")"
expect_exit 0 "$RT_RENDER" "$scene" "${opts[@]}" --progress none
if grep -q "samples,\|building" "$WORK/stderr"; then fail "--progress none printed progress"; fi
expect_exit 2 "$RT_RENDER" "$scene" "${opts[@]}" --progress sometimes
echo "render_progress: ok"
