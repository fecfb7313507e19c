# docs/render-farm.md's commands, run as written (its Slurm array at a small size, sbatch's
# part played by a loop): the tiles folder need not exist, the merged float tiles equal a
# direct render, and the PNG made from them equals a PNG rendered directly, bit for bit.
source "$(dirname "$0")/common.bash"
doc="$RT_SOURCE_DIR/docs/render-farm.md"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
mkdir "$WORK/bin" "$WORK/farm"
ln -s "$RT_RENDER" "$WORK/bin/rt-render"
export PATH="$WORK/bin:$PATH"

# The code block that contains the line matching $1, without its fences.
block() { awk -v line="$1" '/^```/ { if (inside && found) exit; inside = !inside; body = ""; next }
                             inside { body = body $0 "\n"; if ($0 ~ line) found = 1 }
                             END { printf "%s", found ? body : "" }' "$doc"; }
block '^# tiles.sbatch' | sed 's/^W=1920 H=1080 /W=64 H=48 /' >"$WORK/tiles.sbatch"
grep -q '^W=64 H=48 COLS=4 ROWS=4' "$WORK/tiles.sbatch" || fail "the doc's tile script changed: $(cat "$WORK/tiles.sbatch")"
block '^# after the array' >"$WORK/merge.sh"
block '^oiiotool --colorconfig' | sed "s|config/ocio/config.ocio|$RT_SOURCE_DIR/config/ocio/config.ocio|" >"$WORK/png.sh"
[ -s "$WORK/merge.sh" ] && [ -s "$WORK/png.sh" ] || fail "the doc's merge commands were not found"

cd "$WORK/farm"
for i in $(seq 0 15); do
    SLURM_ARRAY_TASK_ID=$i SLURM_CPUS_PER_TASK=1 bash "$WORK/tiles.sbatch" "$scene" 2>"$WORK/task.log" ||
        fail "task $i failed: $(cat "$WORK/task.log")"
done
grep -q '% of .* samples' "$WORK/task.log" || fail "no progress lines in the task's log: $(cat "$WORK/task.log")"
bash "$WORK/merge.sh"
bash "$WORK/png.sh"

direct=(-K -q -s -d 5 -S 16 -x 64 -y 48)  # the script's options at the same size
"$RT_RENDER" "$scene" "${direct[@]}" --exr-pixels float -f direct.exr
"$RT_RENDER" "$scene" "${direct[@]}" -f direct.png
idiff -fail 0 -warn 0 direct.exr full.exr >"$WORK/idiff.txt" || fail "merged tiles differ: $(cat "$WORK/idiff.txt")"
idiff -fail 0 -warn 0 direct.png full.png >"$WORK/idiff.txt" || fail "the PNG of the tiles differs: $(cat "$WORK/idiff.txt")"
echo "render_farm_doc: ok"
