#!/usr/bin/env bash
# Writes the thesis's "balls" test scene (thesis Table 4.1: 7381 spheres, 2 triangles, 3 lights)
# to standard output: Eric Haines's sphereflake from the Standard Procedural Databases at
# level 4 (1 + 9 + 81 + 729 + 6561 spheres) on a ground quad, seen from the SPD's viewpoint.
# Each sphere carries nine children a third of its radius: six around its equator and three
# above, in the frame of the direction it grows in. Used for the heat maps in the README
# (docs/rt-inspect.md):
#   docs/images/balls-scene.sh >balls.xml
#   rt-inspect --tree all --heatmap docs/images/heatmap.png balls.xml   # heatmap-bsp.png, heatmap-kd.png
set -euo pipefail
awk 'BEGIN {
    pi = atan2(0, -1)
    print "<?xml version=\"1.0\" ?>"
    print "<scene>"
    print "  <background r=\"0.08\" g=\"0.1\" b=\"0.15\" />"
    print "  <camera fov=\"45\"><origin x=\"2.1\" y=\"1.3\" z=\"1.7\" /><destination x=\"0\" y=\"0\" z=\"0\" />"
    print "    <up x=\"0\" y=\"0\" z=\"1\" /></camera>"
    print "  <materials>"
    print "    <material name=\"flake\" r=\"1\" g=\"0.75\" b=\"0.33\" diffuse=\"0.8\" specular=\"0.5\""
    print "      reflection=\"0.5\" />"
    print "    <material name=\"ground\" r=\"1\" g=\"0.9\" b=\"0.7\" diffuse=\"0.8\" />"
    print "  </materials>"
    print "  <objects>"
    print "    <quad material=\"ground\">"
    print "      <vertex x=\"-12\" y=\"-12\" z=\"-0.5\" /><vertex x=\"12\" y=\"-12\" z=\"-0.5\" />"
    print "      <vertex x=\"12\" y=\"12\" z=\"-0.5\" /><vertex x=\"-12\" y=\"12\" z=\"-0.5\" />"
    print "    </quad>"
    flake(0, 0, 0, 0.5, 0, 0, 1, 4)
    print "  </objects>"
    print "  <lights>"
    print "    <light x=\"4\" y=\"3\" z=\"2\" r=\"0.6\" g=\"0.6\" b=\"0.6\" />"
    print "    <light x=\"1\" y=\"-4\" z=\"4\" r=\"0.6\" g=\"0.6\" b=\"0.6\" />"
    print "    <light x=\"-3\" y=\"1\" z=\"5\" r=\"0.6\" g=\"0.6\" b=\"0.6\" />"
    print "  </lights>"
    print "</scene>"
}
# A sphere at (x, y, z) of radius r growing along the unit direction (dx, dy, dz), and its
# children down to `level` more generations.
function flake(x, y, z, r, dx, dy, dz, level,    ux, uy, uz, vx, vy, vz, n, i, polar, azimuth, cx, cy, cz, s, c, cr) {
    printf "    <sphere x=\"%.6f\" y=\"%.6f\" z=\"%.6f\" r=\"%.6f\" material=\"flake\" />\n", x, y, z, r
    if (level == 0) return
    # u, v: a frame across the growth direction.
    if (dx * dx < 0.5) { ux = 0; uy = -dz; uz = dy } else { ux = -dy; uy = dx; uz = 0 }
    n = sqrt(ux * ux + uy * uy + uz * uz); ux /= n; uy /= n; uz /= n
    vx = dy * uz - dz * uy; vy = dz * ux - dx * uz; vz = dx * uy - dy * ux
    cr = r / 3
    for (i = 0; i < 9; i++) {
        if (i < 6) { polar = pi / 2 + 0.15; azimuth = i * pi / 3 }
        else { polar = pi / 5; azimuth = (i - 6) * 2 * pi / 3 + pi / 6 }
        s = sin(polar); c = cos(polar)
        cx = s * (cos(azimuth) * ux + sin(azimuth) * vx) + c * dx
        cy = s * (cos(azimuth) * uy + sin(azimuth) * vy) + c * dy
        cz = s * (cos(azimuth) * uz + sin(azimuth) * vz) + c * dz
        flake(x + cx * (r + cr), y + cy * (r + cr), z + cz * (r + cr), cr, cx, cy, cz, level - 1)
    }
}'
