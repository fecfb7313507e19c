#!/usr/bin/env bash
# Writes a scene in the spirit of the Khronos ClearCoatTest model (glTF-Sample-Assets,
# Models/ClearCoatTest: its materials' factors; its textures and coat normals are not read) to
# standard output: left to right, the top row, the red base (0.5, 0.02, 0.01; roughness 0.44) with clearcoat 0,
# 0.5 and 1 (coat roughness 0.03); the bottom row, the blue base (0.013, 0.022, 0.109; roughness 0.6)
# under a full coat of roughness 0, 0.25, 0.5, 0.75 and 1. A grey sky and a light panel above the
# camera, whose reflection shows the coat. Used for docs/images/path-clearcoat.png:
#   docs/images/clearcoat-scene.sh >clearcoat.xml
#   rt-render clearcoat.xml --integrator path --spp 128 -x 600 -y 300 -f docs/images/path-clearcoat.png
set -euo pipefail
cat <<'XML'
<?xml version="1.0" ?>
<scene>
  <background r="0.25" g="0.25" b="0.25" />
  <camera fov="52">
    <origin x="0" y="0.3" z="-13" />
    <destination x="0" y="0" z="0" />
  </camera>
  <materials>
    <material name="panel" r="0" g="0" b="0" emission="6 6 6" />
    <material name="floor" r="0.5" g="0.5" b="0.5" metallic="0" roughness="0.9" />
XML
for coat in 0 0.5 1; do
    echo "    <material name=\"red$coat\" r=\"0.5\" g=\"0.02\" b=\"0.01\" metallic=\"0\" roughness=\"0.44\" clearcoat=\"$coat\" clearcoat_roughness=\"0.03\" />"
done
for rough in 0 0.25 0.5 0.75 1; do
    echo "    <material name=\"blue$rough\" r=\"0.013\" g=\"0.022\" b=\"0.109\" metallic=\"0\" roughness=\"0.6\" clearcoat=\"1\" clearcoat_roughness=\"$rough\" />"
done
# quad MATERIAL Y X,Z X,Z X,Z X,Z: a horizontal quad at height Y, its front the side from which
# the corners run counter-clockwise (emitters shine from their front).
quad() {
    local material=$1 y=$2 corner
    shift 2
    echo "    <quad material=\"$material\">"
    for corner in "$@"; do echo "      <vertex x=\"${corner%,*}\" y=\"$y\" z=\"${corner#*,}\" />"; done
    echo "    </quad>"
}
echo "  </materials>"
echo "  <objects>"
quad panel 6 -3,-8 3,-8 3,-5 -3,-5          # facing down, above the camera
quad floor -2.1 -30,-30 -30,30 30,30 30,-30 # facing up
cat <<'XML'
    <sphere x="2.4" y="1.1" z="0" r="1" material="red0" />
    <sphere x="0" y="1.1" z="0" r="1" material="red0.5" />
    <sphere x="-2.4" y="1.1" z="0" r="1" material="red1" />
XML
x=4  # the camera looks along +z: +x is on the picture's left
for rough in 0 0.25 0.5 0.75 1; do
    echo "    <sphere x=\"$x\" y=\"-1.1\" z=\"0\" r=\"0.9\" material=\"blue$rough\" />"
    x=$((x - 2))
done
cat <<'XML'
  </objects>
</scene>
XML
