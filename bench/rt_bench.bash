# What the benchmarks that compare rt's renders with a reference share (sourced by
# bench/noise_threshold.sh and bench/light_tree.sh, after they set `here` and `keep`): the shared
# models, a work directory, a release rt-render, and the error of a render against a reference.

# readOptions SCRIPT "NAME..." -- ARGUMENT...: each `--NAME VALUE` among the arguments, NAME one of
# the listed names, sets the variable NAME; `--keep DIR` sets keep (the directory, made); -h or
# --help prints the script's leading comment. Anything else ends the script with a usage error.
readOptions() {
    local script="$1" names=" $2 "
    shift 3
    while [[ $# -gt 0 ]]; do
        case "$1" in
            -h | --help) awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0"; exit 0 ;;
            --keep) keep="$(realpath "$2")"; mkdir -p "$keep"; shift 2 ;;
            *)
                if [[ $# -lt 2 || "$names" != *" ${1#--} "* ]]; then
                    echo "$script ERROR: unknown argument '$1' (see --help)" >&2
                    exit 2
                fi
                printf -v "${1#--}" '%s' "$2"
                shift 2
                ;;
        esac
    done
}

# benchSetup SCRIPT: sets `models`, `work` (--keep's directory, or a temporary one removed at the
# end) and `render` (built if need be), and moves to the repository; without the shared models,
# ends the script with SCRIPT's error line.
benchSetup() {
    models="$here/../shared/models"
    if [[ ! -d "$models" ]]; then
        echo "$1 ERROR: $models: no shared models" >&2
        exit 1
    fi
    work="${keep:-$(mktemp -d)}"
    [[ -n "$keep" ]] || trap 'rm -rf "$work"' EXIT
    cd "$here"
    cmake --preset release >/dev/null
    cmake --build --preset release --target rt-render >/dev/null
    render=build/release/tools/render/rt-render
}

# The mean of the three channels' averages of the picture oiiotool's arguments make.
channelMean() { oiiotool "$@" --printstats | awk '/Avg:/ { printf "%.8g\n", ($3 + $4 + $5) / 3; exit }'; }

# The mean over pixels and channels of |x - reference| / (reference + 0.01) (as
# bench/compare_images.py): meanRelativeError X.exr REFERENCE.exr.
meanRelativeError() { printf "%.5f\n" "$(channelMean "$1" "$2" --absdiff "$2" --addc 0.01 --div)"; }
