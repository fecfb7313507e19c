#include "render/lights/environment_light.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "os/sandbox.h"

namespace rt {

namespace {

// The grid the image's distribution is built on (pbrt-v4 takes the image's own pixels; rt looks
// the image up through ImageTextures, which does not tell its size): 0.35 degrees a cell at the
// equator. A spot smaller than that may fall between the lookups; the BSDF's samples still find
// it (multiple importance sampling keeps the estimate unbiased), only with more noise.
constexpr int kGridWidth = 1024, kGridHeight = 512;

Vec3 uniformSphere(Real u1, Real u2) {
    const Real z = 1 - 2 * u1;
    const Real r = std::sqrt(std::max(Real(0), 1 - z * z));
    const Real phi = 2 * kPi * u2;
    return {r * std::cos(phi), r * std::sin(phi), z};
}

// Running sums of values[0, n), normalised to end at 1; equal steps when they sum to 0.
void appendCdf(const double* values, int n, std::vector<double>& cdf) {
    double sum = 0;
    for (int i = 0; i < n; ++i) sum += values[i];
    double running = 0;
    for (int i = 0; i < n; ++i) cdf.push_back(sum > 0 ? (running += values[i]) / sum : double(i + 1) / n);
    cdf.back() = 1;
}

}  // namespace

void setEnvironmentImage(Scene& scene, const std::string& path) {
    requireInsideSandbox(path, path, "--environment");  // rt-farm passes it through from whoever submits
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(path, error);
    if (!std::filesystem::exists(status)) throw InputError(path + ": no such environment image");
    if (!std::filesystem::is_regular_file(status))  // checked by name: no FIFO is opened
        throw InputError(path + ": the environment image is not a regular file");
    scene.textures.push_back({.name = "environment", .file = path, .path = path});
    scene.environment = Environment{.texture = std::uint32_t(scene.textures.size() - 1)};
}

std::pair<Real, Real> equirectangularCoordinates(const Vec3& d) {
    const Real s = Real(0.5) + std::atan2(d.x, -d.z) / (2 * kPi);
    const Real t = std::acos(std::clamp(d.y, Real(-1), Real(1))) / kPi;
    return {s, t};
}

Vec3 equirectangularDirection(Real s, Real t) {
    const Real phi = 2 * kPi * (s - Real(0.5)), theta = kPi * t;
    const Real sinTheta = std::sin(theta);
    return {sinTheta * std::sin(phi), std::cos(theta), -sinTheta * std::cos(phi)};
}

EnvironmentLight::EnvironmentLight(const ShadingContext& context, bool sampled)
    : scene_(context.scene), images_(context.images) {
    const Scene& scene = context.scene;
    if (scene.environment) {
        texture_ = scene.environment->texture;
        intensity_ = scene.environment->intensity;
        const Real angle = Real(scene.environment->rotation) * kPi / 180;
        cosRotation_ = std::cos(angle), sinRotation_ = std::sin(angle);
    }
    if (!texture_) {
        average_ = luminance(scene.background);
        return;
    }
    if (!sampled) return;
    width_ = kGridWidth, height_ = kGridHeight;
    cells_.resize(std::size_t(width_) * std::size_t(height_));
    const auto brightness = [this](Real s, Real t) { return std::max(0.0, double(luminance(imageRadiance(s, t)))); };
    // A cell's value is the brightest of its centre and corners: a sun that covers part of a cell
    // but not its centre would otherwise get next to no samples, and its light a tiny density.
    const auto cornerRow = [&](int y) {
        std::vector<double> row(std::size_t(width_) + 1);
        for (int x = 0; x <= width_; ++x) row[std::size_t(x)] = brightness(Real(x) / width_, Real(y) / height_);
        return row;
    };
    std::vector<double> above = cornerRow(0);
    for (int y = 0; y < height_; ++y) {
        const std::vector<double> below = cornerRow(y + 1);
        const Real t = (Real(y) + Real(0.5)) / Real(height_);
        const double sinTheta = std::sin(double(kPi * t));
        for (int x = 0; x < width_; ++x) {
            const auto i = std::size_t(x);
            const double value = std::max(
                {brightness((Real(x) + Real(0.5)) / Real(width_), t), above[i], above[i + 1], below[i], below[i + 1]});
            total_ += cells_[std::size_t(y) * std::size_t(width_) + i] = value * sinTheta;
        }
        above = below;
    }
    std::vector<double> rowTotals(std::size_t(height_), 0.0);
    for (int y = 0; y < height_; ++y) {
        const double* row = &cells_[std::size_t(y) * std::size_t(width_)];
        for (int x = 0; x < width_; ++x) rowTotals[std::size_t(y)] += row[x];
        appendCdf(row, width_, rowCdfs_);
    }
    appendCdf(rowTotals.data(), height_, marginalCdf_);
    // the integral of luminance over the sphere, du dv = d(omega) / (2 pi^2 sin(theta)), over 4 pi
    // (of the cells' values: a little above the image's own where it has sharp edges)
    average_ = Real(total_ / (double(width_) * double(height_)) * kPi / 2);
}

Color EnvironmentLight::radiance(const Vec3& direction) const {
    if (!texture_) return scene_.background;
    const auto [s, t] = equirectangularCoordinates(toImage(direction));
    return imageRadiance(s, t);
}

Color EnvironmentLight::imageRadiance(Real s, Real t) const {
    const Color c = images_ ? images_->lookup(*texture_, TexCoord{float(s), float(t)}) : Color{1, 1, 1};
    return c * intensity_;
}

// The image turned by the rotation about +y: a world direction turned back by it is the
// image's, and an image direction turned by it the world's.
Vec3 EnvironmentLight::toImage(const Vec3& d) const {
    return {cosRotation_ * d.x - sinRotation_ * d.z, d.y, sinRotation_ * d.x + cosRotation_ * d.z};
}

Vec3 EnvironmentLight::toWorld(const Vec3& d) const {
    return {cosRotation_ * d.x + sinRotation_ * d.z, d.y, -sinRotation_ * d.x + cosRotation_ * d.z};
}

Real EnvironmentLight::sampleRow(const double* cdf, int n, Real u, int& cell) {
    cell = std::min(int(std::upper_bound(cdf, cdf + n, double(u)) - cdf), n - 1);
    const double below = cell == 0 ? 0 : cdf[cell - 1];
    const double width = cdf[cell] - below;
    const double within = width > 0 ? std::clamp((double(u) - below) / width, 0.0, 1.0) : 0.5;
    return Real((double(cell) + within) / double(n));
}

EnvironmentSample EnvironmentLight::sample(Real u1, Real u2) const {
    if (!texture_) return {uniformSphere(u1, u2), 1 / (4 * kPi)};
    if (!(total_ > 0)) return {};
    int row = 0, column = 0;
    const Real t = sampleRow(marginalCdf_.data(), height_, u1, row);
    const Real s = sampleRow(&rowCdfs_[std::size_t(row) * std::size_t(width_)], width_, u2, column);
    return {toWorld(equirectangularDirection(s, t)), densityOf(row * width_ + column, std::sin(kPi * t))};
}

Real EnvironmentLight::densityOf(int cell, Real sinTheta) const {
    if (!(total_ > 0) || !(sinTheta > 0)) return 0;
    // density over the unit square (the cell's value over the mean cell), per solid angle
    const double overSquare = cells_[std::size_t(cell)] * double(width_) * double(height_) / total_;
    return Real(overSquare / (2 * double(kPi) * double(kPi) * double(sinTheta)));
}

int EnvironmentLight::cellOf(Real s, Real t) const {
    const int x = std::clamp(int(s * Real(width_)), 0, width_ - 1);
    const int y = std::clamp(int(t * Real(height_)), 0, height_ - 1);
    return y * width_ + x;
}

Real EnvironmentLight::pdf(const Vec3& direction) const {
    if (!texture_) return 1 / (4 * kPi);
    const auto [s, t] = equirectangularCoordinates(toImage(direction));
    return densityOf(cellOf(s, t), std::sqrt(std::max(Real(0), 1 - direction.y * direction.y)));
}

}  // namespace rt
