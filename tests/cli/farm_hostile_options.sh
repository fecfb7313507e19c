# rt-farm writes its options into bash scripts and "#SBATCH" lines, which sbatch splits into words
# (honouring quotes and backslashes, "#" beginning a comment) and whose file names Slurm expands
# (%j, %A). So --partition, --time and --cpus-per-task must have Slurm's shapes, the output folder
# may hold no character that these readers would change, and the pre-check covers every split:
# each refusal is exit 2 with one error line and nothing submitted. A folder with a space, a
# letter beyond ASCII and "%" is written so that sbatch reads it back unchanged.
source "$(dirname "$0")/common.bash"
farm="$RT_SOURCE_DIR/tools/farm/rt-farm"
scene="$RT_SOURCE_DIR/scenes/demo.xml"
mkdir "$WORK/bin"
printf '#!/bin/bash\necho "sbatch $*" >>"$SBATCH_LOG"\necho 100\n' >"$WORK/bin/sbatch"
chmod +x "$WORK/bin/sbatch"
export PATH="$WORK/bin:$PATH" SBATCH_LOG="$WORK/sbatch.log"
small=(-x 16 -y 12)

# refused SLURM_OPTION VALUE TEXT: submit refuses the value with one error line holding TEXT.
refused() {
    expect_exit 2 "$farm" submit "$scene" "${small[@]}" --tiles 2x2 -o "$WORK/out" "$1" "$2"
    expect_one_error rt-farm "$3"
}
refused --time $'1:00\nrm -rf /' "is not a value Slurm accepts"
refused --time '1:00 --wrap=evil' "is not a value Slurm accepts"
refused --time '1-00:00:00:00' "is not a value Slurm accepts"
refused --partition 'gpu --wrap=evil' "is not a value Slurm accepts"
refused --partition "gpu'" "is not a value Slurm accepts"
refused --partition 'gpu#x' "is not a value Slurm accepts"
refused --partition 'gpu%x' "is not a value Slurm accepts"
refused --partition '' "is not a value Slurm accepts"
refused --cpus-per-task $'4\necho hi' "is not a value Slurm accepts"
refused --cpus-per-task 0 "is not a value Slurm accepts"
refused --cpus-per-task 2000 "at most 1024"
refused --cpus-per-task 8x "is not a value Slurm accepts"
expect_exit 2 "$farm" submit "$scene" "${small[@]}" --tiles 2x2 -o "$WORK/out" --partition='a b'
expect_one_error rt-farm "--partition: .* is not a value Slurm accepts"

# rt-render's options that rt-farm sets, also with the value attached or after short flags.
for option in -fout.exr -Kf -ofoo --file=x.exr --seed=3; do
    expect_exit 2 "$farm" submit "$scene" "${small[@]}" "$option" --tiles 2x2 -o "$WORK/out"
    expect_one_error rt-farm "$option: rt-farm sets it"
done

# The pre-check covers every split: frames need --orbit, seeds are 32-bit, ranges stay in range.
expect_exit 2 "$farm" submit "$scene" "${small[@]}" --frames 0..5 -o "$WORK/out"
grep -q -- "--frames needs --orbit" "$WORK/stderr" || fail "frames without --orbit passed: $(cat "$WORK/stderr")"
expect_exit 2 "$farm" submit "$scene" "${small[@]}" --orbit 4 --frames 2..9 -o "$WORK/out"
grep -q "nothing submitted" "$WORK/stderr" || fail "frames beyond the orbit passed: $(cat "$WORK/stderr")"
expect_exit 2 "$farm" submit "$scene" "${small[@]}" --seeds 4294967290..4294967296 -o "$WORK/out"
grep -q "nothing submitted" "$WORK/stderr" || fail "a seed beyond 32 bits passed: $(cat "$WORK/stderr")"
expect_exit 2 "$farm" submit "$scene" "${small[@]}" --seeds 0..99999999999999999999 -o "$WORK/out"
expect_one_error rt-farm "--seeds: expected A..B or A (whole numbers of at most 10 digits)"

# Output folders: refused when Slurm or rt-render would read them otherwise.
for folder in $'a\nb' 'a"b' 'a\b' 'a#b'; do
    expect_exit 2 "$farm" submit "$scene" "${small[@]}" --tiles 2x2 -o "$WORK/$folder"
    expect_one_error rt-farm "an output folder for Slurm may not hold"
done
[ ! -e "$SBATCH_LOG" ] || fail "a refused submit called sbatch: $(cat "$SBATCH_LOG")"

# Accepted: Slurm's time formats and partition lists; a folder with a space, "é" and "%".
for time in 30 30:00 1:00:00 2-0 2-12:00 2-12:00:00 UNLIMITED; do
    expect_exit 0 "$farm" submit "$scene" "${small[@]}" --tiles 2x2 -o "$WORK/dry" --time "$time" \
        --partition main,gpu --cpus-per-task 8 --dry-run
done
folder="$WORK/my farm é 100%"
expect_exit 0 "$farm" submit "$scene" "${small[@]}" --tiles 2x2 -o "$folder" --partition main
# sbatch's reading of an "#SBATCH" line (Slurm's src/sbatch/opt.c, _get_argument): words split at
# unquoted white space, quotes and backslashes taken out, "#" outside quotes ends the line; then
# Slurm's file pattern turns %% into %. Played here by python.
python3 - "$folder/task.sbatch" "$folder" <<'PY' || fail "sbatch would read another log path"
import re, shlex, sys
line = next(l for l in open(sys.argv[1], encoding="utf-8") if l.startswith("#SBATCH --output="))
words = shlex.split(line[len("#SBATCH "):], comments=True)
assert len(words) == 1, words
expand = lambda s: re.sub(r"%([%Aa])", lambda m: "%" if m[1] == "%" else "<" + m[1] + ">", s)
got = expand(words[0][len("--output="):])
assert got == sys.argv[2] + "/logs/task_<A>_<a>.log", (got, sys.argv[2])
PY
grep -q '^out=' "$folder/task.sbatch" || fail "no out= line in the task script"
SLURM_ARRAY_TASK_ID=1 bash "$folder/task.sbatch" 2>"$WORK/task.log" || fail "the task failed: $(cat "$WORK/task.log")"
[ -f "$folder/parts/part_1.exr" ] || fail "the task of a folder with a space, é and % wrote no part: $(ls -R "$folder")"
echo "farm_hostile_options: ok"
