# rt-farm without a cluster: Slurm's sbatch, squeue and scancel are played by small scripts and
# the array's tasks run in a loop. The dry run prints the scripts and writes nothing; submit
# checks the options before it submits; merge makes the picture of one render bit for bit and
# refuses a missing tile (exit 1) and overlapping tiles (exit 2); status and resubmit find the
# failed task. tests/cli/farm_slurm.sh runs the same on a real Slurm.
source "$(dirname "$0")/common.bash"
farm="$RT_SOURCE_DIR/tools/farm/rt-farm"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
mkdir "$WORK/bin"
cat >"$WORK/bin/sbatch" <<'FAKE'
#!/bin/bash
echo "sbatch $*" >>"$SBATCH_LOG"
echo $(( $(wc -l <"$SBATCH_LOG") + 100 ))
FAKE
printf '#!/bin/bash\necho "scancel $*" >>"$SBATCH_LOG"\n' >"$WORK/bin/scancel"
printf '#!/bin/bash\n' >"$WORK/bin/squeue"  # nothing queued, nothing running
chmod +x "$WORK/bin"/*
export PATH="$WORK/bin:$PATH" SBATCH_LOG="$WORK/sbatch.log"
opts=(-K -s -x 70 -y 40 -S 2 -D b -r 3 -d 3)

expect_exit 0 "$farm" submit "$scene" "${opts[@]}" --tiles 4x4 -o "$WORK/dry" --partition main --time 10 --dry-run
for line in '#SBATCH --array=0-15' '#SBATCH --partition=main' '#SBATCH --time=10' '--tiles 4x4 --tile "$i/16"' \
            '--skip-existing' "merge $WORK/dry"; do
    grep -qF -- "$line" "$WORK/stdout" || fail "the dry run lacks '$line': $(cat "$WORK/stdout")"
done
[ ! -e "$WORK/dry" ] && [ ! -e "$SBATCH_LOG" ] || fail "the dry run wrote or submitted something"

expect_exit 2 "$farm" submit "$scene" "${opts[@]}" -f x.exr --tiles 4x4 -o "$WORK/bad"
expect_one_error rt-farm "-f: rt-farm sets it"
expect_exit 2 "$farm" submit "$scene" -S 0 --tiles 4x4 -o "$WORK/bad"
grep -q "nothing submitted" "$WORK/stderr" || fail "a bad rt-render option was not caught: $(cat "$WORK/stderr")"
expect_exit 2 "$farm" submit "$scene" -x 3 --tiles 4x4 -o "$WORK/bad"
grep -q "every tile needs a pixel" "$WORK/stderr" || fail "a grid larger than the image was not caught: $(cat "$WORK/stderr")"
expect_exit 2 "$farm" submit "$scene" --tiles 4 -o "$WORK/bad"
expect_one_error rt-farm "--tiles: expected CxR"
[ ! -e "$SBATCH_LOG" ] || fail "a refused submit called sbatch"

expect_exit 0 "$farm" submit "$scene" "${opts[@]}" --tiles 4x4 -o "$WORK/out" --cpus-per-task 1
[ "$(cat "$WORK/stdout")" = "101 102" ] || fail "submit does not print the array and merge ids: $(cat "$WORK/stdout")"
grep -q -- "--dependency=afterok:101 .*merge.sbatch" "$SBATCH_LOG" || fail "no merge after the array: $(cat "$SBATCH_LOG")"
for i in $(seq 0 15); do
    [ "$i" = 6 ] && continue  # a task that failed
    SLURM_ARRAY_TASK_ID=$i SLURM_CPUS_PER_TASK=1 bash "$WORK/out/task.sbatch" 2>/dev/null || fail "task $i failed"
done
expect_exit 0 "$farm" status "$WORK/out"
grep -qx '6 failed' "$WORK/stdout" && [ "$(grep -c ' done$' "$WORK/stdout")" = 15 ] ||
    fail "status should say 15 done, 6 failed: $(cat "$WORK/stdout")"
expect_exit 1 "$farm" merge "$WORK/out"
expect_one_error rt-farm "part_6.exr: missing: task 6 has not finished"
expect_exit 0 "$farm" resubmit "$WORK/out"
grep -q "scancel 102" "$SBATCH_LOG" && grep -q -- "sbatch --parsable --array=6 .*task.sbatch" "$SBATCH_LOG" ||
    fail "resubmit did not cancel the old merge and submit task 6 alone: $(cat "$SBATCH_LOG")"
SLURM_ARRAY_TASK_ID=6 bash "$WORK/out/task.sbatch" 2>/dev/null
# A requeued task whose tile is complete does not render it again.
SLURM_ARRAY_TASK_ID=6 bash "$WORK/out/task.sbatch" 2>"$WORK/again.log"
grep -q "is complete: nothing to render" "$WORK/again.log" || fail "a requeued task rendered again: $(cat "$WORK/again.log")"
bash "$WORK/out/merge.sbatch" >/dev/null 2>"$WORK/merge.log" || fail "the merge job failed: $(cat "$WORK/merge.log")"
"$RT_RENDER" "$scene" "${opts[@]}" -q --exr-pixels float -f "$WORK/direct.exr"
idiff -fail 0 -warn 0 "$WORK/direct.exr" "$WORK/out/image.exr" >"$WORK/idiff.txt" ||
    fail "the merged tiles differ from one render: $(cat "$WORK/idiff.txt")"
[ -z "$(ls -A "$WORK/out" | grep '^\.')" ] || fail "the merge left a temporary: $(ls -A "$WORK/out")"

# A merge stopped by SIGTERM (scancel, a time limit) leaves no temporary; one killed outright
# (SIGKILL, no trap runs) leaves its temporary, which the next merge removes. The fake oiiotool
# makes the merge's output and then waits to be stopped.
real_oiiotool=$(command -v oiiotool)
cat >"$WORK/bin/oiiotool" <<FAKE
#!/bin/bash
if [[ " \$* " == *" -o "* ]]; then touch "\${@: -1}"; echo \$\$ >"$WORK/oiiotool.pid"; exec sleep 60; fi
exec "$real_oiiotool" "\$@"
FAKE
chmod +x "$WORK/bin/oiiotool"
"$farm" merge "$WORK/out" >/dev/null 2>&1 &
merger=$!
for _ in $(seq 300); do [ -s "$WORK/oiiotool.pid" ] && break; sleep 0.1; done
[ -n "$(ls -A "$WORK/out" | grep '^\.image\.')" ] || fail "the held merge has no temporary: $(ls -A "$WORK/out")"
kill -TERM "$merger"
wait "$merger" || true
kill "$(cat "$WORK/oiiotool.pid")"
[ -z "$(ls -A "$WORK/out" | grep '^\.')" ] || fail "a merge stopped by SIGTERM left: $(ls -A "$WORK/out")"
rm "$WORK/bin/oiiotool"
sleep 0 &
dead=$!
wait "$dead"
touch "$WORK/out/.image.$dead.exr"
expect_exit 0 "$farm" merge "$WORK/out"
[ -z "$(ls -A "$WORK/out" | grep '^\.')" ] || fail "the merge left a killed merge's temporary: $(ls -A "$WORK/out")"

# Overlapping tiles (one rendered twice) are refused; the picture made before stays as it was.
cp "$WORK/out/parts/part_0.exr" "$WORK/out/parts/part_1.exr"
expect_exit 2 "$farm" merge "$WORK/out"
expect_one_error rt-farm "part_0.exr and .*part_1.exr overlap: tiles 0,0,17,10 and 0,0,17,10"
idiff -fail 0 -warn 0 "$WORK/direct.exr" "$WORK/out/image.exr" >/dev/null || fail "a refused merge changed the picture"
echo "farm_local: ok"
