# rt-farm on a real Slurm: munged, slurmctld and slurmd started on localhost with everything in
# a temporary folder (SLURM_CONF), a 4x4 tile array of a thesis scene with supersampling, soft
# shadows and glossy reflections merged bit for bit equal to a render on one machine; a task
# cancelled while it runs is resubmitted alone and the picture is still exact; a frames array
# and a seeds array give the frames and the seeds' mean one machine gives. Skips (77) where
# Slurm cannot start: not root, or slurm-wlm and munge not installed (scripts/install-deps.sh).
source "$(dirname "$0")/common.bash"
farm="$RT_SOURCE_DIR/tools/farm/rt-farm"
skip() { echo "SKIP: $*" >&2; exit 77; }
[ "$(id -u)" = 0 ] || skip "starting munged, slurmctld and slurmd needs root (CI runs as root)"
export PATH="$PATH:/usr/sbin"
for program in munged munge slurmctld slurmd sbatch squeue scancel sinfo; do
    command -v "$program" >/dev/null || skip "$program not found: scripts/install-deps.sh installs slurm-wlm and munge"
done

# ---- a one-node cluster in $WORK/slurm (../shared/research/slurm.md) -----------------------
D="$WORK/slurm"
mkdir -p "$D"/{state,spool,log}
stop_cluster() {
    local pid_file
    for pid_file in "$D/slurmd.pid" "$D/slurmctld.pid" "$D/munged.pid"; do
        [ -f "$pid_file" ] && kill "$(cat "$pid_file")" 2>/dev/null || true
    done
    sleep 1  # the daemons remove their sockets and pid files before $WORK goes
    rm -rf "$WORK"
}
trap stop_cluster EXIT

head -c 1024 /dev/urandom >"$D/munge.key"
chmod 600 "$D/munge.key"
munged --force --socket="$D/munge.socket" --key-file="$D/munge.key" --pid-file="$D/munged.pid" \
    --log-file="$D/log/munged.log" --seed-file="$D/munged.seed" 2>"$D/log/munged.err" ||
    skip "munged does not start: $(cat "$D/log/munged.err")"
port=$((20000 + RANDOM % 20000))  # not Slurm's default ports, which a real cluster may use
host=$(hostname)
cpus=$(nproc)
cat >"$D/slurm.conf" <<EOF
ClusterName=rttest
SlurmctldHost=$host
SlurmctldPort=$port
SlurmdPort=$((port + 1))
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
AuthInfo=socket=$D/munge.socket
CredType=cred/munge
StateSaveLocation=$D/state
SlurmdSpoolDir=$D/spool
SlurmctldPidFile=$D/slurmctld.pid
SlurmdPidFile=$D/slurmd.pid
SlurmctldLogFile=$D/log/slurmctld.log
SlurmdLogFile=$D/log/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SchedulerType=sched/backfill
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
ReturnToService=2
MpiDefault=none
JobAcctGatherType=jobacct_gather/none
KillWait=5
NodeName=$host CPUs=$cpus RealMemory=1000 State=UNKNOWN
PartitionName=main Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF
export SLURM_CONF="$D/slurm.conf"
slurmctld 2>"$D/log/slurmctld.err" || skip "slurmctld does not start: $(cat "$D/log/slurmctld.err")"
slurmd 2>"$D/log/slurmd.err" || skip "slurmd does not start: $(cat "$D/log/slurmd.err")"
for _ in $(seq 100); do
    [ "$(sinfo -h -o %T 2>/dev/null)" = idle ] && break
    sleep 0.2
done
[ "$(sinfo -h -o %T 2>/dev/null)" = idle ] ||
    fail "the node never became idle: $(sinfo 2>&1); $(tail -5 "$D/log/slurmctld.log")"

# wait_for SECONDS CONDITION...: polls every 0.1 s until the condition holds.
wait_for() {
    local tenths=$(($1 * 10)); shift
    for _ in $(seq "$tenths"); do "$@" && return 0; sleep 0.1; done
    return 1
}
jobs_gone() { [ -z "$(squeue -h -j "$1" 2>/dev/null)" ]; }

# ---- the render --------------------------------------------------------------------------
"$RT_CONVERT" --generate balls -o "$WORK/balls.xml" 2>/dev/null
opts=(-K -s -d 3 -x 96 -y 64 -S 2 -D b -r 4)
"$RT_RENDER" "$WORK/balls.xml" "${opts[@]}" -q --exr-pixels float -f "$WORK/direct.exr"

# Task 5's first run holds its finished picture 60 s before renaming it (the test hook of
# os/atomic_file.h), through a wrapper given to rt-farm as $RT_RENDER; the test cancels it once
# that temporary exists, so the task is caught mid-write however slow the machine is. (A hold
# on every task's writes left a window that a loaded CI machine missed.)
cat >"$WORK/render-holding-task-5" <<EOF
#!/bin/bash
if [ "\${SLURM_ARRAY_TASK_ID:-}" = 5 ] && mkdir "$WORK/task-5-held" 2>/dev/null; then
    export RT_TEST_WRITE_DELAY_MS=60000
fi
exec $(printf '%q' "$(readlink -f "$RT_RENDER")") "\$@"
EOF
chmod +x "$WORK/render-holding-task-5"
RT_RENDER="$WORK/render-holding-task-5" "$farm" submit "$WORK/balls.xml" "${opts[@]}" --tiles 4x4 -o "$WORK/out" \
    --cpus-per-task 1 >"$WORK/ids" 2>"$WORK/submit.log" || fail "submit failed: $(cat "$WORK/submit.log")"
read -r array merge_job <"$WORK/ids"
part_5_being_written() { compgen -G "$WORK/out/parts/.part_5.rt-tmp-*.exr" >/dev/null; }
wait_for 60 part_5_being_written || fail "task 5 never wrote its part: $(squeue 2>&1)"
scancel "${array}_5"
wait_for 90 jobs_gone "$array" || fail "the array did not finish: $(squeue 2>&1)"

[ ! -e "$WORK/out/parts/part_5.exr" ] || fail "task 5 finished before it was cancelled: this test tests nothing"
leftovers=$(ls -A "$WORK/out/parts" | grep -v '^part_[0-9]*\.\(exr\|json\)$' || true)
[ -z "$leftovers" ] || fail "the cancelled task left $leftovers"
"$farm" status "$WORK/out" >"$WORK/status" 2>/dev/null
grep -qx '5 failed' "$WORK/status" || fail "status does not say task 5 failed: $(cat "$WORK/status")"
[ "$(grep -c ' done$' "$WORK/status")" = 15 ] || fail "15 tasks should be done: $(cat "$WORK/status")"
[ ! -e "$WORK/out/image.exr" ] || fail "the merge ran without task 5"
expect_exit 1 "$farm" merge "$WORK/out"
grep -q 'part_5.exr: missing' "$WORK/stderr" || fail "merge does not name the missing tile: $(cat "$WORK/stderr")"

# Only task 5 runs again; the new merge job makes the picture.
"$farm" resubmit "$WORK/out" >"$WORK/ids" 2>"$WORK/resubmit.log" || fail "resubmit failed: $(cat "$WORK/resubmit.log")"
read -r again merge_job <"$WORK/ids"
jobs_gone "$merge_job" || wait_for 60 jobs_gone "$merge_job" || fail "the merge job did not end: $(squeue 2>&1)"
ls "$WORK/out/logs" | grep -q "^task_${again}_5.log$" || fail "task 5 was not resubmitted: $(ls "$WORK/out/logs")"
[ "$(ls "$WORK/out/logs" | grep -c "^task_${again}_")" = 1 ] || fail "resubmit ran more than task 5: $(ls "$WORK/out/logs")"
[ -f "$WORK/out/image.exr" ] || fail "no merged image: $(cat "$WORK/out/logs"/merge_*.log)"
idiff -fail 0 -warn 0 "$WORK/direct.exr" "$WORK/out/image.exr" >"$WORK/idiff.txt" ||
    fail "the farm's picture differs from one render: $(cat "$WORK/idiff.txt")"
grep -q '% of .* samples' "$WORK/out/logs/task_${again}_5.log" || fail "no progress lines in the task's log"

# ---- a frames array and a seeds array, both at once on a small picture --------------------
# A turntable's frames are each the frame one machine renders; the seeds' mean is the mean of
# the renders one machine makes with those seeds (the same sums in the same order).
small=(-K -s -x 40 -y 30 -S 4)
demo="$RT_SOURCE_DIR/scenes/demo.xml"
"$farm" submit "$demo" "${small[@]}" --orbit 3 --frames 0..2 -o "$WORK/turn" --cpus-per-task 1 >"$WORK/ids" \
    2>"$WORK/submit.log" || fail "submit --frames failed: $(cat "$WORK/submit.log")"
read -r _ frames_merge <"$WORK/ids"
"$farm" submit "$demo" "${small[@]}" --seeds 1..4 -o "$WORK/seeds" --cpus-per-task 1 >"$WORK/ids" \
    2>"$WORK/submit.log" || fail "submit --seeds failed: $(cat "$WORK/submit.log")"
read -r _ seeds_merge <"$WORK/ids"
"$RT_RENDER" "$demo" "${small[@]}" -q --exr-pixels float --orbit 3 -f "$WORK/direct_####.exr"
for seed in 1 2 3 4; do "$RT_RENDER" "$demo" "${small[@]}" -q --exr-pixels float --seed $seed -f "$WORK/seed$seed.exr"; done
oiiotool "$WORK"/seed1.exr "$WORK"/seed2.exr --add "$WORK"/seed3.exr --add "$WORK"/seed4.exr --add --divc 4 \
    -d float -o "$WORK/mean.exr"
wait_for 90 jobs_gone "$frames_merge" && wait_for 90 jobs_gone "$seeds_merge" ||
    fail "the frames or seeds jobs did not end: $(squeue 2>&1)"
for frame in 0000 0001 0002; do
    idiff -fail 0 -warn 0 "$WORK/direct_$frame.exr" "$WORK/turn/frames/frame_$frame.exr" >"$WORK/idiff.txt" ||
        fail "frame $frame from the farm differs: $(cat "$WORK/idiff.txt" "$WORK"/turn/logs/* 2>&1 | tail -5)"
done
grep -q "all 3 frames are in" "$WORK"/turn/logs/merge_*.log || fail "the frames' merge job: $(cat "$WORK"/turn/logs/merge_*.log)"
idiff -fail 0 -warn 0 "$WORK/mean.exr" "$WORK/seeds/image.exr" >"$WORK/idiff.txt" ||
    fail "the seeds' mean from the farm differs: $(cat "$WORK/idiff.txt" "$WORK"/seeds/logs/merge_*.log 2>&1 | tail -5)"
echo "farm_slurm: ok"
