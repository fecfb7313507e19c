#!/usr/bin/env bash
# Writes the thesis's "balls" test scene (thesis Table 4.1: 7,381 spheres, 2 triangles, 3 lights;
# Haines's sphereflake, scenes/thesis/README.md) to standard output, its spheres inline. Used for
# the heat maps in the README (docs/rt-inspect.md):
#   docs/images/balls-scene.sh >balls.xml
#   rt-inspect --tree all --heatmap docs/images/heatmap.png balls.xml   # heatmap-bsp.png, -kd.png, -bvh.png
# The same as `rt-convert --generate balls -o -` (its summary goes to standard error), with
# rt-convert taken from $RT_CONVERT, the PATH or this checkout's release build.
set -euo pipefail
convert=${RT_CONVERT:-$(command -v rt-convert || echo "$(dirname "$0")/../../build/release/tools/convert/rt-convert")}
exec "$convert" --generate balls -o -
