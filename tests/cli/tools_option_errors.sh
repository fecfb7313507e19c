# A bad command line gives one line "tool ERROR: what is wrong" and exit 2, in every tool: a
# value that is no number says so, a range reads as one, and an unknown option is named
# before anything else (a missing scene or input, a bad value), with the option it is nearest
# to (edit distance) when that is near enough to be a typo, and the pointer to --help.
source "$(dirname "$0")/common.bash"
SCENE="$RT_SOURCE_DIR/scenes/demo.xml"

for tool in "$RT_RENDER" "$RT_INSPECT"; do
    name=$(basename "$tool")
    expect_exit 2 "$tool" "$SCENE" -x abc
    expect_one_error "$name" "--width: abc is not a number"
    expect_exit 2 "$tool" "$SCENE" -x 1.5
    expect_one_error "$name" "--width: 1.5 is not a whole number"
    expect_exit 2 "$tool" "$SCENE" -y 0
    expect_one_error "$name" "--height: 0 is not in 1-65536"
    # --threads: 0 (every core) up to a bound; a negative count is no huge number.
    expect_exit 2 "$tool" "$SCENE" --threads -1
    expect_one_error "$name" "--threads: -1 is not in 0-1024"
    expect_exit 2 "$tool" "$SCENE" --threads 1025
    expect_one_error "$name" "--threads: 1025 is not in 0-1024"
    expect_exit 2 "$tool" "$SCENE" --kd-traversal-cost -2
    expect_one_error "$name" "--kd-traversal-cost: -2 is not in 0.001-1000"
    expect_exit 2 "$tool" "$SCENE" --kd-min-gain -1
    expect_one_error "$name" "--kd-min-gain: -1 is not in 0-1000"
    expect_exit 2 "$tool" "$SCENE" --kd-min-gain 1001
    expect_one_error "$name" "--kd-min-gain: 1001 is not in 0-1000"
    # What was left over is named in the order given.
    expect_exit 2 "$tool" "$SCENE" --treads 2
    expect_one_error "$name" "not expected: --treads 2; did you mean --threads?"
done

for tool in "$RT_RENDER" "$RT_INSPECT" "$RT_CONVERT"; do
    name=$(basename "$tool")
    # An unknown option is the first thing to fix, with or without the scene or input.
    expect_exit 2 "$tool" --no-such-option
    expect_one_error "$name" "not expected: --no-such-option"
    expect_exit 2 "$tool" --no-such-option "$SCENE"
    expect_one_error "$name" "not expected: --no-such-option"
    # A typo is answered with the option meant; every command-line error ends with the pointer to --help.
    expect_exit 2 "$tool" "$SCENE" --quite
    expect_one_error "$name" "The following argument was not expected: --quite; did you mean --quiet? ($name --help lists the options)"
    expect_exit 2 "$tool" --max-inptu=64 "$SCENE"
    expect_one_error "$name" "did you mean --max-input?"
    expect_exit 2 "$tool" --no-such-option
    grep -q "did you mean" "$WORK/stderr" && fail "$name suggested an option for --no-such-option: $(cat "$WORK/stderr")"
    grep -q "($name --help lists the options)$" "$WORK/stderr" || fail "$name: no pointer to --help: $(cat "$WORK/stderr")"
    expect_exit 2 "$tool"
    # rt-convert's input may be a model file or --generate NAME: it names both.
    if [ "$name" = rt-convert ]; then expect_one_error "$name" "give either a model file or --generate NAME"
    else expect_one_error "$name" "is required"; fi
done
# rt-convert's numbers read the same way.
expect_exit 2 "$RT_CONVERT" --generate ships --scale abc
expect_one_error rt-convert "--scale: abc is not a number"
expect_exit 2 "$RT_CONVERT" --generate ships --aspect -1
expect_one_error rt-convert "--aspect: -1 is not a positive number"
expect_exit 2 "$RT_CONVERT" --generate ships --scene -1
expect_one_error rt-convert "--scene: -1 is not in 0-1073741824"
# rt-inspect's heat-map maximum too, and a name outside the library's table is named with the valid ones.
expect_exit 2 "$RT_INSPECT" "$SCENE" --heatmap-max -3
expect_one_error rt-inspect "--heatmap-max: -3 is not in 0.001-1e+09"
expect_exit 2 "$RT_INSPECT" "$SCENE" --heatmap-scale cubic
expect_one_error rt-inspect "--heatmap-scale: cubic not in {linear,log}"
expect_exit 2 "$RT_RENDER" "$SCENE" -x abc --no-such-option
expect_one_error rt-render "not expected: --no-such-option"
expect_exit 2 "$RT_RENDER" "$SCENE" --widht 100 --heigth 80
expect_one_error rt-render "did you mean --width?"
expect_exit 2 "$RT_INSPECT" "$SCENE" -x abc
expect_one_error rt-inspect "--width: abc is not a number (rt-inspect --help lists the options)"
# rt-render's -o is the thesis's output type: a file name there is answered with -f.
expect_exit 2 "$RT_RENDER" "$SCENE" -o out.png
expect_one_error rt-render "--output: out.png is a file name, and -o takes an output type {.*}: did you mean -f out.png?"
expect_exit 2 "$RT_RENDER" "$SCENE" -o pgn
expect_one_error rt-render "--output: pgn not in {"
echo "tools_option_errors: ok"
