// The five test scenes of the thesis (Table 4.1), rebuilt with exactly its counts of
// triangles, spheres and lights. The thesis names them and counts them but does not print
// them; scenes/thesis/README.md says what each reconstruction follows (Haines's Standard
// Procedural Databases for balls, balls2 and tree; the example of thesis 3.4.2 for ships)
// and what was chosen where the thesis is silent. Every scene is built without randomness,
// so it is the same on every run and machine (up to the rounding of Real).
//
// Each function returns a flattened scene (scene.primitives is ready to trace) that keeps
// its description: the large geometry sits in one model instanced once, so that the scene
// saves as a short XML file and a RAW model (saveSceneXml).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace rt {

// balls: Haines's sphereflake at level 4 (7,381 spheres) over a square floor (2 triangles), 3 lights.
Scene thesisBalls();
// balls2: the same sphereflake at level 6 (597,871 spheres), 2 triangles, 3 lights.
Scene thesisBalls2();
// ships: a fleet of four ships (1,004 triangles, 12 spheres) and a planet (1 sphere), 2 lights,
// placed as the example scene of thesis 3.4.2 places its model.
Scene thesisShips();
// tree: Haines's tree of 4,095 branches, tessellated (180,180 triangles) over a field (2), 7 lights.
Scene thesisTree();
// pyramid5: a Sierpinski square pyramid of 5 levels (3,125 pyramids of 6 triangles), 1 light.
Scene thesisPyramid5();

// The names above in the order of thesis Table 4.1: balls, balls2, ships, tree, pyramid5.
const std::vector<std::string_view>& thesisSceneNames();
// The scene of that name; throws InputError naming the valid ones for any other name.
Scene thesisScene(std::string_view name);

}  // namespace rt
