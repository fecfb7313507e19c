# rt-render's tx cache (docs/rt-render.md, "Texture copies"): a PNG texture is read through a
# tiled, MIP-mapped copy made once in --tx-cache, else $RT_TX_CACHE; "off" makes none; a folder
# that cannot be made is one warning and the same picture. A maker killed while writing a copy
# leaves nothing a later render trusts; two makers of the same copy both succeed with one copy.
source "$(dirname "$0")/common.bash"
oiiotool --pattern checker:width=4:height=4 16x16 3 -d uint8 -o "$WORK/checker.png"
printf 'newmtl m\nKd 1 1 1\nmap_Kd checker.png\n' >"$WORK/square.mtl"
printf 'mtllib square.mtl\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nusemtl m\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n' \
    >"$WORK/square.obj"
# render NAME OPTION...: the scene to NAME.png; exit 0 required.
render() {
    local name=$1
    shift
    "$RT_RENDER" "$WORK/square.obj" --look-from 0,0,3 --look-at 0,0,0 --fov 60 -x 40 -y 30 -f "$WORK/$name.png" --progress none "$@" 2>"$WORK/stderr" ||
        fail "exit $?: $(cat "$WORK/stderr")"
}
copies() { find "$1" -name '*.tx' 2>/dev/null | wc -l; }
published() { find "$1" -maxdepth 1 -name '*.tx' ! -name '.*' | wc -l; }  # not in temporaries

render plain --tx-cache off
[ ! -e "$WORK/tx" ] || fail "--tx-cache off made a folder"
render first --tx-cache "$WORK/tx"
[ "$(copies "$WORK/tx")" = 1 ] || fail "expected one copy in $WORK/tx: $(ls -a "$WORK/tx")"
copy=$(find "$WORK/tx" -name '*.tx')
touch -d '2000-01-01' "$copy"
render again --tx-cache "$WORK/tx"
[ "$(stat -c %Y "$copy")" = "$(date -d 2000-01-01 +%s)" ] || fail "the copy was made again"
# Making a copy is said on standard error (it takes seconds for a large picture), once: not when
# the copy is found, and not with -q (issue 36, item 15).
made="rt-render: making a tiled, MIP-mapped copy of $WORK/checker.png (16 x 16) in $WORK/said, once for every later render"
said() { expect_exit 0 "$RT_RENDER" "$WORK/square.obj" -x 40 -y 30 -f "$WORK/said.png" "$@"; }
said --tx-cache "$WORK/said" --progress lines
grep -qxF "$made" "$WORK/stderr" || fail "no line saying the copy is made: $(cat "$WORK/stderr")"
said --tx-cache "$WORK/said" --progress lines
grep -q "making a tiled" "$WORK/stderr" && fail "the copy was found, yet said to be made: $(cat "$WORK/stderr")"
said --tx-cache "$WORK/quiet" -q
[ "$(copies "$WORK/quiet")" = 1 ] || fail "-q made no copy"
grep -q "making a tiled" "$WORK/stderr" && fail "-q said it: $(cat "$WORK/stderr")"
RT_TX_CACHE="$WORK/env" render fromEnv
[ "$(copies "$WORK/env")" = 1 ] || fail "\$RT_TX_CACHE: no copy in $WORK/env"
render fallback --tx-cache "$WORK/checker.png/tx"
grep -q "warning: texture 'checker': no tiled copy (.*): textures are read as they are" "$WORK/stderr" ||
    fail "no fallback warning: $(cat "$WORK/stderr")"
expect_exit 2 "$RT_RENDER" "$WORK/square.obj" --tx-cache-size 0 -f "$WORK/never.png"
expect_one_error rt-render "tx-cache-size"

# kill_maker SIGNAL: starts a render whose copy the test hook RT_TEST_WRITE_DELAY_MS (core/atomic_file.h)
# holds in its temporary folder in $WORK/killed, sends SIGNAL there and checks the exit status.
kill_maker() {
    RT_TEST_WRITE_DELAY_MS=60000 env --default-signal=INT "$RT_RENDER" "$WORK/square.obj" -x 40 -y 30 \
        --tx-cache "$WORK/killed" -f "$WORK/killed.png" --progress none 2>"$WORK/stderr" &
    local pid=$! got=0 temporary
    mkdir -p "$WORK/killed"
    temporary=$(wait_for_temporary "$WORK/killed" 'rt-tmp-')
    wait_for_temporary "$WORK/killed/$temporary" '^checker-[0-9a-f]*\.tx$' >/dev/null  # made, not yet renamed
    kill "-$1" "$pid"
    wait "$pid" 2>/dev/null || got=$?  # without the shell's "Killed" line
    [ "$got" = $((128 + $(kill -l "$1"))) ] || fail "$1: exited $got, expected 128+SIG$1"
    [ "$(published "$WORK/killed")" = 0 ] || fail "$1: a copy was published: $(ls -A "$WORK/killed")"
}
for signal in INT TERM; do
    kill_maker "$signal"
    [ -z "$(ls -A "$WORK/killed" | grep rt-tmp)" ] || fail "$signal: left behind: $(ls -A "$WORK/killed")"
done
kill_maker KILL
leftover=$(ls -A "$WORK/killed" | grep rt-tmp)
render afterKill --tx-cache "$WORK/killed"  # makes the copy afresh beside the leftover
[ "$(published "$WORK/killed")" = 1 ] && [ -e "$WORK/killed/$leftover" ] || fail "expected a copy beside the leftover: $(ls -AR "$WORK/killed")"
# Removed by a render making a copy once its process is gone and nothing changed in it for 10 minutes.
find "$WORK/killed/$leftover" -exec touch -d '1 hour ago' {} +
cp "$WORK/checker.png" "$WORK/other.png"
sed 's/checker.png/other.png/' "$WORK/square.mtl" >"$WORK/other.mtl"
sed 's/square.mtl/other.mtl/' "$WORK/square.obj" >"$WORK/other.obj"
"$RT_RENDER" "$WORK/other.obj" -x 8 -y 8 --tx-cache "$WORK/killed" -f "$WORK/other.png.png" -q ||
    fail "a render of another picture failed"
[ ! -e "$WORK/killed/$leftover" ] || fail "the stale temporary $leftover was not removed"

# Two renders making the same copy at once (the hook holds each made copy 2 s before its rename):
# both succeed, with one copy and no temporary left.
for name in one two; do
    RT_TEST_WRITE_DELAY_MS=2000 "$RT_RENDER" "$WORK/square.obj" --look-from 0,0,3 --look-at 0,0,0 --fov 60 \
        -x 40 -y 30 --tx-cache "$WORK/both" -f "$WORK/$name.png" --progress none 2>"$WORK/$name.stderr" &
    eval "pid_$name=$!"
done
wait "$pid_one" || fail "the first of two concurrent makers failed: $(cat "$WORK/one.stderr")"
wait "$pid_two" || fail "the second of two concurrent makers failed: $(cat "$WORK/two.stderr")"
[ "$(published "$WORK/both")" = 1 ] && [ -z "$(ls -A "$WORK/both" | grep rt-tmp)" ] ||
    fail "two makers left: $(ls -AR "$WORK/both")"

for name in first again fromEnv fallback afterKill one two; do
    idiff -fail 0.004 "$WORK/plain.png" "$WORK/$name.png" >/dev/null || fail "$name.png differs from plain.png"
done
echo "render_tx_cache: ok"
