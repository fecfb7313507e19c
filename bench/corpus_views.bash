# The corpus's views of a scene (issue 37), shared by bench/corpus.sh and bench/kd_tests_per_ray.sh:
# view_options BOUNDS VIEW gives rt-render's camera options of a view, bounds BUILD FILE a scene's
# bounding box (with rt-inspect of BUILD); require_built SCRIPT TOOL... stops SCRIPT if a tool is not built. The views are described in bench/corpus.sh's header.

# The camera options of view $2 for the bounds "minx miny minz maxx maxy maxz" in $1 (none for "file").
# Up is +y, or the box's shortest axis where that is under a quarter of its longest (a landscape such as
# tree, whose ground is the xy plane); the views are written in (first horizontal, up, second horizontal).
view_options() {
    awk -v view="$2" -v b="$1" 'BEGIN {
        split(b, v, " "); for (i = 1; i <= 3; ++i) { lo[i] = v[i]; s[i] = v[i + 3] - v[i]; c[i] = (v[i] + v[i + 3]) / 2 }
        short = 1; big = s[1]; for (i = 2; i <= 3; ++i) { if (s[i] < s[short]) short = i; if (s[i] > big) big = s[i] }
        u = s[short] < big / 4 ? short : 2
        h = u == 1 ? 2 : 1; k = 6 - u - h
        wide = s[h] > s[k] ? s[h] : s[k]
        if (view == "overview") { put(f, c[h] + .8 * s[h], c[u] + .5 * (s[u] > wide / 2 ? s[u] : wide / 2), c[k] + .9 * s[k]); put(a, c[h], c[u], c[k]); fov = 60 }
        else if (view == "close") { put(f, c[h] + .2 * s[h], c[u] + .1 * s[u], c[k] + .2 * s[k]); put(a, c[h], c[u], c[k]); fov = 40 }
        else if (view == "inside") { put(f, c[h], c[u], c[k]); put(a, c[h] + s[h] + 1, c[u], c[k]); fov = 90 }
        else if (view == "inside-z") { put(f, c[h] - .25 * s[h], lo[u] + .3 * s[u], c[k] - .25 * s[k]); put(a, f[h], f[u], c[k] + s[k] + 1); fov = 90 }
        else if (view == "grazing") { put(f, lo[h] - .05 * s[h], lo[u] + .02 * s[u], c[k]); put(a, lo[h] + s[h], lo[u] + .02 * s[u], c[k]); fov = 70 }
        else if (view == "top") { put(f, c[h], c[u] + s[u] + wide, c[k]); put(a, c[h], c[u], c[k]); fov = 60; put(up, 0, 0, -1) }
        else exit
        if (!(1 in up)) put(up, 0, 1, 0)
        printf "--look-from %g,%g,%g --look-at %g,%g,%g --up %g,%g,%g --fov %g\n", f[1], f[2], f[3], a[1], a[2], a[3],
               up[1], up[2], up[3], fov
    }
    function put(p, x, y, z) { p[h] = x; p[u] = y; p[k] = z }'
}

bounds() {  # build-dir file
    "$1/tools/inspect/rt-inspect" "$2" --tree naive --json -q |
        jq -r '.scene.bounds | "\(.min[0]) \(.min[1]) \(.min[2]) \(.max[0]) \(.max[1]) \(.max[2])"'
}

require_built() {  # script tool...
    local script=$1 tool
    shift
    for tool; do
        [ -x "$tool" ] || { echo "$script ERROR: $tool is not built" >&2; exit 2; }
    done
}
