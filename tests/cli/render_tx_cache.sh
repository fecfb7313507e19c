# rt-render's tx cache (docs/rt-render.md, "Texture copies"): a PNG texture is read through a
# tiled, MIP-mapped copy made once in --tx-cache, else $RT_TX_CACHE; "off" makes none; a folder
# that cannot be made is one warning and the same picture. A maker killed while writing a copy
# leaves nothing a later render trusts; two makers of the same copy both succeed with one copy.
# The cache removes only the copies it made, in its own subfolder; a copy is keyed by the
# picture's bytes, and one that does not read back whole is made again.
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
published() { find "$1/rt-tx-copies" -maxdepth 1 -name '*.tx' ! -name '.*' | wc -l; }  # not in temporaries

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

# kill_maker SIGNAL: starts a render whose copy the test hook RT_TEST_WRITE_DELAY_MS (os/atomic_file.h)
# holds in its temporary folder in $WORK/killed, sends SIGNAL there and checks the exit status.
kill_maker() {
    RT_TEST_WRITE_DELAY_MS=60000 env --default-signal=INT "$RT_RENDER" "$WORK/square.obj" -x 40 -y 30 \
        --tx-cache "$WORK/killed" -f "$WORK/killed.png" --progress none 2>"$WORK/stderr" &
    local pid=$! got=0 temporary
    mkdir -p "$WORK/killed/rt-tx-copies"
    temporary=$(wait_for_temporary "$WORK/killed/rt-tx-copies" 'rt-tmp-')
    wait_for_temporary "$WORK/killed/rt-tx-copies/$temporary" '^checker-[0-9a-f]*\.tx$' >/dev/null  # made, not yet renamed
    kill "-$1" "$pid"
    wait "$pid" 2>/dev/null || got=$?  # without the shell's "Killed" line
    [ "$got" = $((128 + $(kill -l "$1"))) ] || fail "$1: exited $got, expected 128+SIG$1"
    [ "$(published "$WORK/killed")" = 0 ] || fail "$1: a copy was published: $(ls -A "$WORK/killed")"
}
for signal in INT TERM; do
    kill_maker "$signal"
    [ -z "$(ls -A "$WORK/killed/rt-tx-copies" | grep rt-tmp)" ] || fail "$signal: left behind: $(ls -AR "$WORK/killed")"
done
kill_maker KILL
leftover=rt-tx-copies/$(ls -A "$WORK/killed/rt-tx-copies" | grep rt-tmp)
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
[ "$(published "$WORK/both")" = 1 ] && [ -z "$(ls -A "$WORK/both/rt-tx-copies" | grep rt-tmp)" ] ||
    fail "two makers left: $(ls -AR "$WORK/both")"

# textured NAME PICTURE: $WORK/NAME.obj, the square coloured by PICTURE.
textured() {
    sed "s|checker.png|$2|" "$WORK/square.mtl" >"$WORK/$1.mtl"
    sed "s|square.mtl|$1.mtl|" "$WORK/square.obj" >"$WORK/$1.obj"
}
# render_obj NAME OPTION...: $WORK/NAME.obj to $WORK/NAME-render.png; exit 0 and no warning required.
render_obj() {
    local name=$1
    shift
    "$RT_RENDER" "$WORK/$name.obj" -x 40 -y 30 -f "$WORK/$name-render.png" --progress none "$@" 2>"$WORK/stderr" ||
        fail "$name: exit $?: $(cat "$WORK/stderr")"
    ! grep -q "warning: texture" "$WORK/stderr" || fail "$name: $(cat "$WORK/stderr")"
}

# A folder holding a user's files: maketx output and a text file named project.tx. Copies of two
# pictures of about 1 MB each under a bound of 1 MB: the first copy goes, the user's files stay.
mkdir "$WORK/user"
oiiotool --pattern checker 64x64 3 -d uint8 -otex "$WORK/user/theirs.tx"
printf 'notes, not a texture\n' >"$WORK/user/project.tx"
for seed in 1 2; do
    oiiotool --pattern noise:seed=$seed 512x512 3 -d uint8 -o "$WORK/noise$seed.png"
    textured noise$seed noise$seed.png
    render_obj noise$seed --tx-cache "$WORK/user" --tx-cache-size 1
done
[ -e "$WORK/user/theirs.tx" ] && [ -e "$WORK/user/project.tx" ] || fail "the cache removed a user's files: $(ls -AR "$WORK/user")"
[ "$(published "$WORK/user")" = 1 ] || fail "the bound was not kept: $(ls -AR "$WORK/user")"

# Another picture of the same size and modification time (unpacked from an archive, touch -r) gets
# its own copy: the two differ in colour, so the old copy would show.
oiiotool --pattern constant:color=1,0,0 16x16 3 -d uint8 -o "$WORK/red.png"
oiiotool --pattern constant:color=0,0,1 16x16 3 -d uint8 -o "$WORK/blue.png"
python3 - "$WORK/red.png" "$WORK/blue.png" <<'PY'
import sys  # the same size: the shorter is padded after its IEND chunk, which readers ignore
a, b = (open(p, "rb").read() for p in sys.argv[1:])
n = max(len(a), len(b))
for p, data in zip(sys.argv[1:], (a, b)):
    open(p, "wb").write(data + bytes(n - len(data)))
PY
cp -p "$WORK/red.png" "$WORK/picture.png"
textured picture picture.png
render_obj picture --tx-cache "$WORK/keyed"
cp "$WORK/blue.png" "$WORK/picture.png"
touch -r "$WORK/red.png" "$WORK/picture.png"
render_obj picture --tx-cache "$WORK/keyed"
textured blue blue.png
render_obj blue --tx-cache off
idiff -fail 0.004 "$WORK/blue-render.png" "$WORK/picture-render.png" >/dev/null || fail "the copy of the old picture was used"

# A copy cut short (a full disk, a damaged file) is made again, not used nor read around.
copy=$(find "$WORK/tx/rt-tx-copies" -name 'checker-*.tx')
size=$(stat -c %s "$copy")
truncate -s $((size / 2)) "$copy"
render remade --tx-cache "$WORK/tx"
! grep -q "warning: texture" "$WORK/stderr" || fail "a cut copy: $(cat "$WORK/stderr")"
[ "$(stat -c %s "$copy")" = "$size" ] || fail "the cut copy was not made again: $(stat -c %s "$copy") bytes of $size"

for name in first again fromEnv fallback afterKill one two remade; do
    idiff -fail 0.004 "$WORK/plain.png" "$WORK/$name.png" >/dev/null || fail "$name.png differs from plain.png"
done
echo "render_tx_cache: ok"
