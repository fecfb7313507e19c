#!/usr/bin/env bash
# The layers of libtrace, and the check that its #include lines keep to them: a file may include
# headers of its own folder, of the layers the table lets its folder use, and of the third-party
# libraries the table gives its folder. The table below is the one statement of the layering;
# libtrace/CMakeLists.txt links each folder's library the same way, and docs/architecture.md
# shows the table (the check fails when the two differ).
#   scripts/check-layers.sh               checks libtrace/ and docs/architecture.md
#   scripts/check-layers.sh DIR           checks the libtrace tree at DIR (a copy, in the tests)
#   scripts/check-layers.sh --table       prints the table as Markdown
# Exits 1 with one line "check-layers ERROR: file:line: what is wrong" per forbidden include.
set -euo pipefail

# folder   | layers it may use (lowest first)  | third-party headers it may include
readonly TABLE='
core       |                                      |
os         | core                                 |
geometry   | core                                 |
accel      | core geometry                        |
scene      | core os geometry                     |
io         | core os geometry scene               | pugixml.hpp assimp/ tiny_gltf.h tiny_obj_loader.h
render     | core os geometry accel scene         |
image      | core os geometry accel scene render  | OpenImageIO/ OpenColorIO/
inspect    | core geometry accel scene render     |
'
# Sub-folders that come below the rest of their layer, and the headers of the layer outside
# them that they may include (besides their own folder and the layers of their layer's row; an
# entry ending in / is a whole sub-folder), lowest first: the BSDFs and material evaluation
# (materials/), the lights and how a light is picked (lights/) and the pixels' store and
# statistics (film/) know nothing of the integrators; of each other, only lights/ reads
# materials/ (an emissive surface is a light, weighed by its material's emission); the
# integrators (integrators/) use all three. What is left in render/ is what they share (surfaces, textures,
# sampling, camera rays, the settings) and what drives them (the renderer, adaptive subsampling).
readonly INNER='
render/materials   | render/refraction.h render/sampling.h render/sobol_sampler.h render/surface.h render/texture.h
render/lights      | render/materials/ render/render_settings.h render/texture.h
render/film        | render/render_settings.h render/render_stats.h render/surface.h
render/integrators | render/film/ render/lights/ render/materials/ render/camera_rays.h render/normal_map.h render/refraction.h render/render_settings.h render/render_stats.h render/sampling.h render/sobol_sampler.h render/surface.h render/texture.h
'
# Headers CMake generates into the build folder, which any layer may include.
readonly GENERATED='version.h builtin_color_config.h'

declare -A MAY_USE THIRD_PARTY
FOLDERS=()
GUARDED=()  # every third-party header named in the table
while IFS='|' read -r folder layers headers; do
    folder=$(echo $folder)
    [ -n "$folder" ] || continue
    FOLDERS+=("$folder")
    MAY_USE[$folder]=$(echo $layers)
    THIRD_PARTY[$folder]=$(echo $headers)
    GUARDED+=($headers)
done <<<"$TABLE"

declare -A INNER_MAY_USE
INNER_FOLDERS=()
while IFS='|' read -r inner headers; do
    inner=$(echo $inner)
    [ -n "$inner" ] || continue
    INNER_FOLDERS+=("$inner")
    INNER_MAY_USE[$inner]=$(echo $headers)
done <<<"$INNER"

print_table() {
    echo "| folder | may use | third-party headers |"
    echo "|---|---|---|"
    local folder inner
    for folder in "${FOLDERS[@]}"; do
        echo "| \`$folder/\` | ${MAY_USE[$folder]:--} | ${THIRD_PARTY[$folder]:--} |"
        for inner in "${INNER_FOLDERS[@]}"; do
            [ "${inner%%/*}" != "$folder" ] ||
                echo "| \`$inner/\` | ${MAY_USE[$folder]:--}; of $folder/ only ${INNER_MAY_USE[$inner]//$folder\//} | ${THIRD_PARTY[$folder]:--} |"
        done
    done
}

# inner_folder FILE: sets INNER_OF to the sub-folder of INNER that the libtrace path FILE lies in,
# or empty. (It and guarded_header set a variable rather than print: a $(...) for every file and
# header forks a shell, which made the check take half a minute.)
inner_folder() {
    local inner
    INNER_OF=
    for inner in "${INNER_FOLDERS[@]}"; do
        [[ $1 == "$inner"/* ]] && INNER_OF=$inner && return
    done
    return 0
}

# contains WORD LIST...: true when WORD is one of LIST.
contains() {
    local word=$1; shift
    local item
    for item in "$@"; do [ "$item" = "$word" ] && return 0; done
    return 1
}

# listed HEADER ENTRY...: true when HEADER is one of the ENTRYs or lies in one that names a
# folder (ends in /).
listed() {
    local header=$1; shift
    local entry
    for entry in "$@"; do
        [[ $entry == */ && $header == "$entry"* ]] || [ "$header" = "$entry" ] && return 0
    done
    return 1
}

# guarded_header HEADER: sets GUARD to the table's entry HEADER falls under (assimp/ for
# assimp/scene.h), or empty.
guarded_header() {
    local entry
    GUARD=
    for entry in "${GUARDED[@]}"; do
        if [[ $entry == */ && $1 == "$entry"* ]] || [ "$1" = "$entry" ]; then
            GUARD=$entry
            return
        fi
    done
}

# owners ENTRY: the folders the table gives the third-party header ENTRY.
owners() {
    local folder list=()
    for folder in "${FOLDERS[@]}"; do
        contains "$1" ${THIRD_PARTY[$folder]} && list+=("$folder/")
    done
    echo "${list[*]}"
}

ERRORS=0
error() {
    echo "check-layers ERROR: $1" >&2
    ERRORS=$((ERRORS + 1))
}

# check_include FILE LINE FOLDER INNER INCLUDE-LINE (INNER: the file's sub-folder in INNER, or empty)
check_include() {
    local file=$1 line=$2 folder=$3 inner=$4 text=$5
    if [[ $text =~ \#[[:space:]]*include[[:space:]]*\"([^\"]+)\" ]]; then
        local header=${BASH_REMATCH[1]}
        if [[ $header != */* ]]; then
            contains "$header" $GENERATED ||
                error "$file:$line: \"$header\": include libtrace's headers by folder (\"$folder/$header\")"
            return
        fi
        local layer=${header%%/*}
        if [ "$layer" = "$folder" ]; then
            [ -z "$inner" ] || [[ $header == "$inner"/* ]] || listed "$header" ${INNER_MAY_USE[$inner]} ||
                error "$file:$line: $inner/ may not include \"$header\" (of $folder/ it may use: ${INNER_MAY_USE[$inner]})"
            return
        fi
        contains "$layer" "${FOLDERS[@]}" || { error "$file:$line: \"$header\" is in no layer of libtrace"; return; }
        contains "$layer" ${MAY_USE[$folder]} ||
            error "$file:$line: $folder/ may not include \"$header\" ($folder/ may use: ${MAY_USE[$folder]:-nothing})"
    elif [[ $text =~ \#[[:space:]]*include[[:space:]]*\<([^\>]+)\> ]]; then
        guarded_header "${BASH_REMATCH[1]}"
        [ -z "$GUARD" ] || contains "$GUARD" ${THIRD_PARTY[$folder]} ||
            error "$file:$line: $folder/ may not include <${BASH_REMATCH[1]}> (only $(owners "$GUARD") may)"
    fi
}

check_tree() {
    local root=${1%/} file relative folder line text
    local -a files
    mapfile -t files < <(find "$root" -type f \( -name '*.h' -o -name '*.cpp' -o -name '*.h.in' \) | sort)
    for file in "${files[@]}"; do
        relative=${file#"$root"/}
        [[ $relative == */* ]] || continue  # CMakeLists.txt, version.h.in
        contains "${relative%%/*}" "${FOLDERS[@]}" ||
            error "$file:1: folder ${relative%%/*}/ is not in the layer table of scripts/check-layers.sh"
    done
    # One grep picks every file's #include lines ("file:line:text"), so that bash's slow loop
    # reads only those.
    while IFS=: read -r file line text; do
        relative=${file#"$root"/}
        folder=${relative%%/*}
        [[ $relative == */* ]] && contains "$folder" "${FOLDERS[@]}" || continue
        inner_folder "$relative"
        check_include "$file" "$line" "$folder" "$INNER_OF" "$text"
    done < <(grep -n -H '^[[:space:]]*#[[:space:]]*include' "${files[@]}" || true)
}

check_docs() {
    local docs=$1
    [[ $(<"$docs") == *"$(print_table)"* ]] ||
        error "$docs:1: the layer table differs from scripts/check-layers.sh's; paste the output of scripts/check-layers.sh --table"
}

if [ "${1:-}" = "--table" ]; then
    print_table
    exit 0
fi
if [ $# -gt 0 ]; then
    check_tree "$1"
else
    cd "$(dirname "$0")/.."
    check_tree libtrace
    check_docs docs/architecture.md
fi
[ "$ERRORS" = 0 ] || exit 1
