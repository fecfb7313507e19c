# Scenes and helpers for the rt-inspect CLI tests, written into $WORK (sourced after common.bash).

# json_number KEY FILE: the first number that is the value of "KEY" in a JSON file.
json_number() { grep -o "\"$1\": [-0-9][-0-9.e+]*" "$2" | head -1 | awk '{print $2}'; }

# cluster CX CY CZ N SPACING RADIUS: N^3 spheres in a cube centred on (CX, CY, CZ).
cluster() {
    awk -v cx="$1" -v cy="$2" -v cz="$3" -v n="$4" -v s="$5" -v r="$6" 'BEGIN {
        for (i = 0; i < n; i++) for (j = 0; j < n; j++) for (k = 0; k < n; k++)
            printf "    <sphere x=\"%g\" y=\"%g\" z=\"%g\" r=\"%g\" material=\"white\" />\n",
                cx + (i - (n - 1) / 2) * s, cy + (j - (n - 1) / 2) * s, cz + (k - (n - 1) / 2) * s, r }'
}

# scene FILE FOV: a scene with the camera at the origin looking down +z, one light, and
# the objects read from standard input.
scene() {
    {
        echo '<?xml version="1.0" ?>'
        echo '<scene>'
        echo "  <camera fov=\"$2\"><origin x=\"0\" y=\"0\" z=\"0\" /><destination x=\"0\" y=\"0\" z=\"20\" /></camera>"
        echo '  <materials><material name="white" r="1" g="1" b="1" /></materials>'
        echo '  <objects>'
        cat
        echo '  </objects>'
        echo '  <lights><light x="0" y="10" z="0" r="1" g="1" b="1" /></lights>'
        echo '</scene>'
    } >"$1"
}

# Two clusters of 64 spheres, far apart on x: every tree splits between them first.
{ cluster -10 0 20 4 0.5 0.2; cluster 10 0 20 4 0.5 0.2; } | scene "$WORK/two_clusters.xml" 90
echo '    <sphere x="0" y="0" z="10" r="2" material="white" />' | scene "$WORK/one_sphere.xml" 60
# A dense cluster of 512 small spheres at x = 5 (the left of the picture: +x is left
# when looking down +z with +y up) and a few large spheres spread over the rest.
{
    cluster 5 0 20 8 0.5 0.2
    for x in -8 -4 0; do echo "    <sphere x=\"$x\" y=\"0\" z=\"20\" r=\"1.5\" material=\"white\" />"; done
} | scene "$WORK/dense_left.xml" 60
