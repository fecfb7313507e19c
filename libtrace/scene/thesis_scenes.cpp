#include "scene/thesis_scenes.h"

#include <array>
#include <cmath>
#include <initializer_list>
#include <utility>

#include "core/error.h"

namespace rt {

namespace {

// ---------------------------------------------------------------------------------------
// Building blocks: models in float, as RAW holds them, and scenes made of them.

Model namedModel(std::string name) {
    Model model;
    model.name = std::move(name);
    return model;
}

void addTriangle(Model& model, const Vec3& a, const Vec3& b, const Vec3& c) {
    for (const Vec3& p : {a, b, c})
        model.triangleVertices.insert(model.triangleVertices.end(), {float(p.x), float(p.y), float(p.z)});
}

// Two triangles, as the XML <quad> makes them; corners in order around the quad.
void addQuad(Model& model, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    addTriangle(model, a, b, c);
    addTriangle(model, a, c, d);
}

void addSphere(Model& model, const Vec3& centre, Real radius) {
    model.sphereData.insert(model.sphereData.end(), {float(centre.x), float(centre.y), float(centre.z), float(radius)});
}

std::uint32_t addMaterial(Scene& scene, const Material& material) {
    scene.materials.push_back(material);
    return std::uint32_t(scene.materials.size() - 1);
}

void place(Scene& scene, Model model, std::uint32_t material, const Transform& transform = {}) {
    scene.models.push_back(std::move(model));
    scene.instances.push_back({std::uint32_t(scene.models.size() - 1), material, transform});
}

// A square of half-size `half` in the plane z = height (the Z-up floors of the SPD scenes).
void addFloor(Scene& scene, Real half, Real height, std::uint32_t material) {
    Primitives& loose = scene.looseObjects;
    const Vec3 a{half, half, height}, b{-half, half, height}, c{-half, -half, height}, d{half, -half, height};
    loose.add<Triangle>({a, b, c}, material);
    loose.add<Triangle>({a, c, d}, material);
}

// The SPD's viewpoints have a 45 degree angle of view for a square picture; the thesis
// renders 800 x 600, and rt's fov is horizontal: 58 degrees keeps the 45 vertically.
constexpr Real kSpdFovAt4To3 = 58;

// White lights that add up to 1: the SPD gives each 1/sqrt(N) for renderers that do not
// scale lights themselves, which washes the floors out to white in rt's Phong sum.
void addSpdLights(Scene& scene, std::initializer_list<Vec3> positions) {
    const float share = 1.0f / float(positions.size());
    for (const Vec3& p : positions) scene.lights.push_back({p, {share, share, share}});
}

Scene finished(Scene scene) {
    scene.droppedDegenerate = scene.flatten();
    return scene;
}

// Rodrigues' rotation of v about a unit axis, right-handed.
Vec3 rotateAbout(const Vec3& v, const Vec3& axis, Real angle) {
    const Real c = std::cos(angle), s = std::sin(angle);
    return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1 - c));
}

// ---------------------------------------------------------------------------------------
// balls, balls2: Haines's sphereflake (SPD "balls"). Each sphere carries nine children a
// third of its radius, touching it: three leaning up at 54.7 degrees and six around its
// equator, in the frame that turns +Z into the direction the sphere grew in.

// The nine directions around +Z: a trio at 45 degrees between the axes, tilted so that one
// points up, then turned by 0, 120 and 240 degrees about Z.
std::array<Vec3, 9> flakeDirections() {
    const Real d = 1 / std::sqrt(Real(2));
    const Vec3 tilt = normalize(Vec3{1, -1, 0});
    const Real tiltAngle = std::asin(2 / std::sqrt(Real(6)));
    const std::array<Vec3, 3> trio{Vec3{d, d, 0}, Vec3{d, 0, -d}, Vec3{0, d, -d}};
    std::array<Vec3, 9> directions;
    for (int set = 0; set < 3; ++set)
        for (int i = 0; i < 3; ++i)
            directions[set * 3 + i] =
                rotateAbout(rotateAbout(trio[i], tilt, tiltAngle), {0, 0, 1}, Real(set) * 2 * kPi / 3);
    return directions;
}

// The rotation taking +Z to the unit vector `to`, applied to v.
Vec3 turnFromZ(const Vec3& v, const Vec3& to) {
    if (to.z >= Real(0.9999)) return v;
    if (to.z <= Real(-0.9999)) return {-v.x, v.y, -v.z};  // half a turn about Y
    return rotateAbout(v, normalize(cross({0, 0, 1}, to)), std::acos(to.z));
}

void growFlake(Model& flake, const std::array<Vec3, 9>& directions, const Vec3& centre, Real radius,
               const Vec3& direction, int level) {
    addSphere(flake, centre, radius);
    if (level == 0) return;
    const Real childRadius = radius / 3;
    for (const Vec3& d : directions) {
        const Vec3 childDirection = turnFromZ(d, direction);
        growFlake(flake, directions, centre + childDirection * (radius + childRadius), childRadius, childDirection,
                  level - 1);
    }
}

// SPD balls.c: its viewpoint, lights, floor and colours; `level` generations below the
// first sphere give 1 + 9 + ... + 9^level spheres.
Scene sphereflakeScene(int level) {
    Scene scene;
    scene.background = {0.078f, 0.361f, 0.753f};
    scene.camera.origin = {Real(2.1), Real(1.3), Real(1.7)};
    scene.camera.destination = {0, 0, 0};
    scene.camera.up = {0, 0, 1};
    scene.camera.fovDegrees = kSpdFovAt4To3;
    addSpdLights(scene, {Vec3{4, 3, 2}, Vec3{1, -4, 4}, Vec3{-3, 1, 5}});
    const auto floor = addMaterial(scene, {"floor", {1.0f, 0.75f, 0.33f}, {0.2f, 0.8f}});
    const auto mirror = addMaterial(scene, {"flake", {1.0f, 0.9f, 0.7f}, {0.0f, 0.5f, 0.5f, 37.0f, 0.5f}});
    addFloor(scene, 12, Real(-0.5), floor);
    Model flake = namedModel("sphereflake");
    growFlake(flake, flakeDirections(), {0, 0, 0}, Real(0.5), {0, 0, 1}, level);
    place(scene, std::move(flake), mirror);
    return finished(std::move(scene));
}

// ---------------------------------------------------------------------------------------
// tree: Haines's tree (SPD "tree", after Aono and Kunii 1984). Every branch is a cone
// carrying a sphere at its tip and two smaller branches; 11 levels give 4,095 of each. The
// thesis renders triangles and spheres only, so cones and spheres are tessellated: 44
// triangles a branch, which is what 180,182 = 2 + 4,095 x 44 leaves.

constexpr int kConeSides = 6;  // 12 triangles; the sphere takes the other 32

// The side of a truncated cone from a circle of radius r0 around `base` to one of radius
// r1 around `apex`, open at both ends as SPD's cones are.
void addCone(Model& model, const Vec3& base, Real r0, const Vec3& apex, Real r1) {
    const Vec3 axis = normalize(apex - base);
    const Vec3 u = normalize(cross(axis, std::abs(axis.x) < Real(0.9) ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
    const Vec3 v = cross(axis, u);
    auto around = [&](int i) {
        const Real a = Real(i) * 2 * kPi / kConeSides;
        return u * std::cos(a) + v * std::sin(a);
    };
    for (int i = 0; i < kConeSides; ++i)
        addQuad(model, base + around(i) * r0, base + around(i + 1) * r0, apex + around(i + 1) * r1,
                apex + around(i) * r1);
}

// An octahedron with each face split in four and pushed onto the sphere: 32 triangles.
void addGeodesicSphere(Model& model, const Vec3& centre, Real radius) {
    const std::array<Vec3, 6> corner{Vec3{1, 0, 0},  Vec3{0, 1, 0}, Vec3{-1, 0, 0},
                                     Vec3{0, -1, 0}, Vec3{0, 0, 1}, Vec3{0, 0, -1}};
    auto onSphere = [&](const Vec3& p) { return centre + normalize(p) * radius; };
    for (int pole = 4; pole < 6; ++pole)
        for (int i = 0; i < 4; ++i) {
            // Counter-clockwise seen from outside: around the equator, then the pole.
            const Vec3 a = pole == 4 ? corner[i] : corner[(i + 1) % 4];
            const Vec3 b = pole == 4 ? corner[(i + 1) % 4] : corner[i];
            const Vec3 c = corner[pole];
            const Vec3 ab = a + b, bc = b + c, ca = c + a;
            addTriangle(model, onSphere(a), onSphere(ab), onSphere(ca));
            addTriangle(model, onSphere(ab), onSphere(b), onSphere(bc));
            addTriangle(model, onSphere(ca), onSphere(bc), onSphere(c));
            addTriangle(model, onSphere(ab), onSphere(bc), onSphere(ca));
        }
}

struct TreeShape {
    std::array<Transform, 2> child;  // a child branch's frame within its parent's
    Real widthRatio = Real(0.15);    // base radius over length of the trunk
    Real taper = Real(0.67);         // tip radius over base radius, and each child's width over its parent's
};

// SPD tree.c's two growth rules: turn by the branching angle about X and by the divergence
// about Z, shrink by the contraction, and move to the tip of the parent (its local z = 1).
TreeShape treeShape() {
    auto rule = [](Real branchDegrees, Real divergenceDegrees, Real contraction) {
        const Real degree = kPi / 180;
        return Transform::translate({0, 0, 1}) * Transform::scale({contraction, contraction, contraction}) *
               Transform::rotateZ(divergenceDegrees * degree) * Transform::rotateX(branchDegrees * degree);
    };
    return {{rule(40, 90, Real(0.65)), rule(25, 140 + 90, Real(0.70))}};
}

void growTree(Model& tree, const TreeShape& shape, const Transform& frame, Real width, int level) {
    const Vec3 base = frame.point({0, 0, 0}), apex = frame.point({0, 0, 1});
    const Real r0 = width * shape.widthRatio, r1 = r0 * shape.taper;
    addCone(tree, base, r0, apex, r1);
    addGeodesicSphere(tree, apex, r1);
    if (level == 0) return;
    for (const Transform& child : shape.child) growTree(tree, shape, frame * child, width * shape.taper, level - 1);
}

// ---------------------------------------------------------------------------------------
// pyramid5: a Sierpinski square pyramid. A pyramid is replaced by five of half its size,
// four on the corners of its base and one on top; five levels give 5^5 = 3,125 pyramids of
// six triangles (four sides, the base as two), 18,750 in all. Y is up.

void addPyramid(Model& model, const Vec3& baseCentre, Real side, Real height) {
    const Real h = side / 2;
    const Vec3 apex = baseCentre + Vec3{0, height, 0};
    const std::array<Vec3, 4> c{baseCentre + Vec3{-h, 0, -h}, baseCentre + Vec3{-h, 0, h}, baseCentre + Vec3{h, 0, h},
                                baseCentre + Vec3{h, 0, -h}};
    for (int i = 0; i < 4; ++i) addTriangle(model, c[i], c[(i + 1) % 4], apex);
    addQuad(model, c[0], c[3], c[2], c[1]);  // facing down
}

void growPyramid(Model& model, const Vec3& baseCentre, Real side, Real height, int level) {
    if (level == 0) {
        addPyramid(model, baseCentre, side, height);
        return;
    }
    const Real q = side / 4;
    for (const Vec3 offset : {Vec3{-q, 0, -q}, Vec3{-q, 0, q}, Vec3{q, 0, q}, Vec3{q, 0, -q}, Vec3{0, height / 2, 0}})
        growPyramid(model, baseCentre + offset, side / 2, height / 2, level - 1);
}

// ---------------------------------------------------------------------------------------
// ships: the example scene of thesis 3.4.2 (its background, camera, materials, blue
// sphere, light, and its model scaled by 0.025, turned about y by pi and moved by
// (-3, 0, 4.5)), with the model now a fleet of four ships of 251 triangles and 3 spheres.
// A ship is drawn 120 long in its own frame, which kShipSize scales to the model's units;
// 0.025 then makes it 4.5 long in the world. Y is up; the ships point along -z in the
// model, so after the half turn they fly along +z, towards the planet.

constexpr Real kShipSize = 1.5;

// The hull is turned on a lathe: a nose point, ten rings of twelve sides, a flat tail.
struct HullRing {
    Real z, radius;
};
constexpr std::array<HullRing, 10> kHull{
    {{-50, 5}, {-40, 8}, {-28, 10}, {-15, 11}, {0, 11.5}, {15, 11}, {30, 10}, {42, 9}, {52, 8}, {58, 7}}};
constexpr int kHullSides = 12;

// 12 (nose) + 9 x 24 (between rings) + 12 (tail) = 240 triangles.
void addHull(Model& ship, const Transform& frame) {
    auto ring = [&](int r, int i) {
        const Real a = Real(i) * 2 * kPi / kHullSides;
        return frame.point({kHull[r].radius * std::cos(a), kHull[r].radius * std::sin(a), kHull[r].z});
    };
    const Vec3 nose = frame.point({0, 0, -60}), tail = frame.point({0, 0, kHull.back().z});
    for (int i = 0; i < kHullSides; ++i) {
        addTriangle(ship, nose, ring(0, i + 1), ring(0, i));
        for (int r = 0; r + 1 < int(kHull.size()); ++r)
            addQuad(ship, ring(r, i), ring(r, i + 1), ring(r + 1, i + 1), ring(r + 1, i));
        addTriangle(ship, tail, ring(int(kHull.size()) - 1, i), ring(int(kHull.size()) - 1, i + 1));
    }
}

// A swept wing on side `s` (+1 right, -1 left): a thin diamond, 4 triangles, its root
// hidden in the hull. Returns the wing tip, where an engine pod sits.
Vec3 addWing(Model& ship, const Transform& frame, Real s) {
    const Vec3 lead = frame.point({s * 9, 0, -5}), trail = frame.point({s * 9, 0, 35}),
               tip = frame.point({s * 55, -4, 42});
    const Vec3 top = frame.point({s * 9, 3, 15}), bottom = frame.point({s * 9, -3, 15});
    addTriangle(ship, lead, tip, top);
    addTriangle(ship, top, tip, trail);
    addTriangle(ship, lead, bottom, tip);
    addTriangle(ship, bottom, trail, tip);
    return tip;
}

// The tail fin: a tetrahedron whose base lies in the hull, 3 triangles.
void addFin(Model& ship, const Transform& frame) {
    const Vec3 front = frame.point({0, 8, 20}), left = frame.point({-2, 7, 56}), right = frame.point({2, 7, 56});
    const Vec3 tip = frame.point({0, 34, 62});
    addTriangle(ship, front, left, tip);
    addTriangle(ship, front, tip, right);
    addTriangle(ship, left, right, tip);
}

// 251 triangles in `hulls`, a canopy and two engine pods in `parts`.
void addShip(Model& hulls, Model& parts, const Transform& frame) {
    addHull(hulls, frame);
    for (const Real side : {Real(-1), Real(1)}) addSphere(parts, addWing(hulls, frame, side), 5 * frame.maxScale());
    addFin(hulls, frame);
    addSphere(parts, frame.point({0, 8, -25}), 6 * frame.maxScale());
}

}  // namespace

Scene thesisBalls() { return sphereflakeScene(4); }

Scene thesisBalls2() { return sphereflakeScene(6); }

Scene thesisShips() {
    Scene scene;
    scene.background = {0.1f, 0.1f, 0.6f};
    scene.camera.origin = {4, Real(-4.5), -18};
    scene.camera.destination = {1, Real(-0.5), 5};
    scene.camera.fovDegrees = Real(50);
    scene.lights.push_back({{-1, 0, 0}, {0.8f, 0.8f, 0.8f}, Real(0.1)});
    scene.lights.push_back({{6, 8, -10}, {0.5f, 0.5f, 0.5f}, Real(0.1)});
    const auto blue = addMaterial(
        scene, {.name = "blue", .color = {0.7f, 0.7f, 1.0f}, .phong = {.diffuse = 0.4f, .reflection = 0.4f}});
    const auto steel =
        addMaterial(scene, {.name = "red_steel", .color = {1, 0, 0}, .phong = {.diffuse = 0.6f, .specular = 0.3f}});
    scene.looseObjects.add<Sphere>({{0, -1, 12}, Real(1.2)}, blue);
    Model hulls = namedModel("ships"), parts = namedModel("ship_parts");
    for (const Vec3& at : {Vec3{0, 0, 0}, Vec3{-100, -25, 90}, Vec3{100, 15, 90}, Vec3{0, 45, 180}})
        addShip(hulls, parts, Transform::translate(at) * Transform::scale({kShipSize, kShipSize, kShipSize}));
    // Outer element first (docs/scene-format.md): scale, then rotate, then translate.
    const Transform fleet =
        Transform::translate({-3, 0, Real(4.5)}) * Transform::rotateY(kPi) * Transform::scale({0.025, 0.025, 0.025});
    place(scene, std::move(hulls), steel, fleet);
    place(scene, std::move(parts), blue, fleet);
    return finished(std::move(scene));
}

// SPD tree.c at its size factor 11: its viewpoint, seven lights, field and colours.
Scene thesisTree() {
    Scene scene;
    scene.background = {0.078f, 0.361f, 0.753f};
    scene.camera.origin = {Real(4.5), Real(0.4), 2};
    scene.camera.destination = {0, 0, Real(1.5)};
    scene.camera.up = {0, 0, 1};
    scene.camera.fovDegrees = kSpdFovAt4To3;
    addSpdLights(scene, {Vec3{-5, 5, 50}, Vec3{30, -30, 30}, Vec3{-40, -30, 20}, Vec3{10, 30, 40}, Vec3{-30, 40, 10},
                         Vec3{50, 25, 20}, Vec3{-10, -60, 30}});
    const auto field =
        addMaterial(scene, {.name = "field", .color = {0.2f, 0.7f, 0.2f}, .phong = {.ambient = 0, .diffuse = 1}});
    const auto bark =
        addMaterial(scene, {.name = "bark", .color = {0.55f, 0.4f, 0.2f}, .phong = {.ambient = 0, .diffuse = 1}});
    addFloor(scene, 50, 0, field);
    Model tree = namedModel("tree");
    growTree(tree, treeShape(), Transform(), 1, 11);
    place(scene, std::move(tree), bark);
    return finished(std::move(scene));
}

Scene thesisPyramid5() {
    Scene scene;
    scene.background = {0.05f, 0.06f, 0.1f};
    scene.camera.origin = {Real(3.0), Real(2.0), Real(4.0)};
    scene.camera.destination = {0, Real(0.5), 0};
    scene.camera.fovDegrees = Real(45);
    scene.lights.push_back({{5, 6, 1}, {1, 1, 1}});  // from the side, so the two faces in view differ
    const auto stone = addMaterial(
        scene, {.name = "sandstone", .color = {0.9f, 0.75f, 0.5f}, .phong = {.diffuse = 0.8f, .specular = 0.2f}});
    Model pyramid = namedModel("pyramid5");
    growPyramid(pyramid, {0, 0, 0}, 2, 2 / std::sqrt(Real(2)), 5);
    place(scene, std::move(pyramid), stone);
    return finished(std::move(scene));
}

namespace {

struct NamedScene {
    std::string_view name;
    Scene (*make)();
};
// In the order of thesis Table 4.1.
constexpr std::array<NamedScene, 5> kThesisScenes{{{"balls", thesisBalls},
                                                   {"balls2", thesisBalls2},
                                                   {"ships", thesisShips},
                                                   {"tree", thesisTree},
                                                   {"pyramid5", thesisPyramid5}}};

}  // namespace

const std::vector<std::string_view>& thesisSceneNames() {
    static const std::vector<std::string_view> names = [] {
        std::vector<std::string_view> list;
        for (const NamedScene& scene : kThesisScenes) list.push_back(scene.name);
        return list;
    }();
    return names;
}

Scene thesisScene(std::string_view name) {
    for (const NamedScene& scene : kThesisScenes)
        if (scene.name == name) return scene.make();
    std::string known;
    for (const NamedScene& scene : kThesisScenes) known += (known.empty() ? "" : ", ") + std::string(scene.name);
    throw InputError("unknown thesis scene '" + std::string(name) + "' (there are " + known + ")");
}

}  // namespace rt
