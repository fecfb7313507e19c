# rt-inspect dumps: leaf boxes as OBJ, the tree as DOT and JSON, one file per tree with --tree all.
source "$(dirname "$0")/common.bash"
source "$(dirname "$0")/inspect_scenes.bash"

# check_obj FILE: only comments, one object, vertices and two-index line elements that
# point at existing vertices; 8 vertices and 12 lines per box. Prints the box count.
check_obj() {
    awk '
        /^#/ || /^$/ { next }
        $1 == "o" { objects++; next }
        $1 == "v" { if (NF != 4) bad = bad "\n" $0; v++; next }
        $1 == "l" {
            if (NF != 3 || $2 < 1 || $3 < 1) bad = bad "\n" $0
            l++; maxi = $2 > maxi ? $2 : maxi; maxi = $3 > maxi ? $3 : maxi; next
        }
        { bad = bad "\n" $0 }
        END {
            if (bad != "") { print "bad lines:" bad > "/dev/stderr"; exit 1 }
            if (objects != 1 || v != 8 * (l / 12) || l % 12 != 0 || maxi > v) {
                print "objects " objects ", vertices " v ", lines " l ", max index " maxi > "/dev/stderr"; exit 1 }
            print l / 12
        }' "$1"
}


expect_exit 0 "$RT_INSPECT" --tree kd --json "$WORK/two_clusters.xml"
leaves=$(json_number leaves "$WORK/stdout")
empty=$(json_number emptyLeaves "$WORK/stdout")

expect_exit 0 "$RT_INSPECT" --tree kd --dump-leaves "$WORK/leaves.obj" "$WORK/two_clusters.xml"
boxes=$(check_obj "$WORK/leaves.obj") || fail "leaves.obj is not a wireframe OBJ"
[ "$boxes" = "$leaves" ] || fail "$boxes boxes for $leaves leaves"
grep -q "^statistic" "$WORK/stdout" || fail "the table should still go to standard output"

expect_exit 0 "$RT_INSPECT" --tree kd --dump-leaves - --leaves nonempty "$WORK/two_clusters.xml"
boxes=$(check_obj "$WORK/stdout") || fail "nonempty leaves are not a wireframe OBJ"
[ "$boxes" = "$((leaves - empty))" ] || fail "$boxes non-empty boxes, expected $((leaves - empty))"

expect_exit 0 "$RT_INSPECT" --tree kd --dump-leaves - --max-depth 1 "$WORK/two_clusters.xml"
boxes=$(check_obj "$WORK/stdout") || fail "cut leaves are not a wireframe OBJ"
[ "$boxes" -ge 1 ] && [ "$boxes" -le 2 ] || fail "a tree cut at depth 1 has 1 or 2 boxes, not $boxes"

# DOT: a digraph whose edges join declared nodes; one edge fewer than nodes (a tree).
expect_exit 0 "$RT_INSPECT" --tree bsp --dump dot "$WORK/two_clusters.xml"
head -1 "$WORK/stdout" | grep -q '^digraph "bsp tree" {$' || fail "not a DOT digraph: $(head -1 "$WORK/stdout")"
[ "$(tail -1 "$WORK/stdout")" = "}" ] || fail "DOT not closed"
nodes=$(grep -c '^  n[0-9]* \[label=' "$WORK/stdout")
edges=$(grep -c '^  n[0-9]* -> n[0-9]*;$' "$WORK/stdout")
[ "$edges" = "$((nodes - 1))" ] || fail "$nodes nodes but $edges edges"
awk '/\[label=/ { sub(/^  /, ""); split($0, a, " "); declared[a[1]] = 1 }
     / -> / { sub(/;$/, ""); if (!declared[$1] || !declared[$3]) { print "undeclared: " $0; exit 1 } }' \
    "$WORK/stdout" || fail "DOT edge to an undeclared node"
if command -v dot >/dev/null; then dot -Tsvg "$WORK/stdout" >/dev/null || fail "Graphviz rejects the DOT"; fi

# --tree all writes one file per tree, and -f names them.
expect_exit 0 "$RT_INSPECT" --tree all --dump json -f "$WORK/tree.json" --dump-leaves "$WORK/l.obj" \
    "$WORK/two_clusters.xml"
for t in bsp kd bvh; do
    [ -s "$WORK/tree-$t.json" ] || fail "no tree-$t.json"
    grep -q "\"structure\": \"$t" "$WORK/tree-$t.json" || fail "tree-$t.json is not the $t tree"
    check_obj "$WORK/l-$t.obj" >/dev/null || fail "l-$t.obj is not a wireframe OBJ"
done
echo "inspect_dumps: ok"
