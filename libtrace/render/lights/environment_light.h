// The sky around a path-traced scene: the background colour as a constant environment, or an
// equirectangular image (rt-render --environment FILE; docs/path-tracing.md) looked up through
// the scene's image textures (render/texture.h: OpenImageIO in rt-render). An image is sampled
// in proportion to its brightness by a piecewise-constant 2-D distribution over a grid of its
// values, each row weighted by sin(theta), the solid angle its cells cover (pbrt-v4's
// PiecewiseConstant2D and ImageInfiniteLight); the path tracer combines those samples with the
// BSDF's by multiple importance sampling, so a small bright sun gives no fireflies.
//
// The image's mapping: +y is up; the top row looks straight up (t = 0), the bottom row straight
// down; the image's centre (s = 0.5) looks along -z, and s grows towards +x. Scene::environment's
// rotation turns the image about +y (counter-clockwise seen from above: 90 degrees brings the
// centre to -x), its intensity scales it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/color.h"
#include "core/vec3.h"
#include "render/texture.h"
#include "scene/scene.h"

namespace rt {

// Makes the image file at `path` the scene's environment (a texture named "environment"),
// unturned and unscaled, in place of any the scene names.
// Throws rt::InputError when it is not a regular file, or lies outside the sandbox (--sandbox).
void setEnvironmentImage(Scene& scene, const std::string& path);

// Texture coordinates of a unit direction in the equirectangular mapping, and back.
std::pair<Real, Real> equirectangularCoordinates(const Vec3& direction);
Vec3 equirectangularDirection(Real s, Real t);

struct EnvironmentSample {
    Vec3 direction;
    Real pdf = 0;  // per unit solid angle
};

class EnvironmentLight {
public:
    // The scene's environment image if it has one, else its background colour everywhere.
    // The context's lookups read the image (none: it is white, as every image texture without them).
    // Without `sampled` only radiance() may be asked (the Whitted tracer's background): the
    // distribution over the image, a million lookups, is not built.
    explicit EnvironmentLight(const ShadingContext& context, bool sampled = true);

    Color radiance(const Vec3& direction) const;
    // The mean luminance over the sphere, for the light's share of next-event samples.
    Real averageLuminance() const { return average_; }
    EnvironmentSample sample(Real u1, Real u2) const;
    Real pdf(const Vec3& direction) const;

private:
    // Where u falls in n running sums (one row, or the marginal over the rows): a position in
    // [0, 1), and the cell it is in.
    static Real sampleRow(const double* cdf, int n, Real u, int& cell);
    Color imageRadiance(Real s, Real t) const;  // at the image's coordinates, times the intensity
    Vec3 toImage(const Vec3& direction) const;  // undoes the rotation
    Vec3 toWorld(const Vec3& direction) const;  // applies it
    int cellOf(Real s, Real t) const;
    Real densityOf(int cell, Real sinTheta) const;  // per solid angle

    const Scene& scene_;
    const ImageTextures* images_;
    std::optional<std::uint32_t> texture_;
    float intensity_ = 1;
    Real cosRotation_ = 1, sinRotation_ = 0;
    Real average_ = 0;
    // the image's distribution: values per cell (luminance times sin(theta)), the running sums
    // of each row (normalised to end at 1) and of the rows' totals
    int width_ = 0, height_ = 0;
    std::vector<double> cells_, rowCdfs_, marginalCdf_;
    double total_ = 0;  // sum of cells_
};

}  // namespace rt
