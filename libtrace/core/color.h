// Linear, scene-referred RGB. Always float: colour needs no double precision,
// and float keeps framebuffers half the size.
#pragma once

#include <algorithm>
#include <cmath>
#include <ostream>

namespace rt {

struct Color {
    float r = 0, g = 0, b = 0;

    constexpr Color() = default;
    constexpr Color(float r_, float g_, float b_) : r(r_), g(g_), b(b_) {}

    constexpr Color& operator+=(const Color& c) {
        r += c.r;
        g += c.g;
        b += c.b;
        return *this;
    }
    constexpr Color& operator*=(float s) {
        r *= s;
        g *= s;
        b *= s;
        return *this;
    }
    constexpr bool operator==(const Color&) const = default;
};

constexpr Color operator+(const Color& a, const Color& b) { return {a.r + b.r, a.g + b.g, a.b + b.b}; }
constexpr Color operator*(const Color& a, const Color& b) { return {a.r * b.r, a.g * b.g, a.b * b.b}; }
constexpr Color operator*(const Color& a, float s) { return {a.r * s, a.g * s, a.b * s}; }
constexpr Color operator*(float s, const Color& a) { return a * s; }

// Rec.709 luminance of a linear colour.
constexpr float luminance(const Color& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

inline bool isFinite(const Color& c) { return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b); }

// The largest colour value rt reads (a light's colour, an emission, a material's factor, glTF's
// and OBJ's colours and intensities) and the largest a camera sample adds to a pixel: 1e15, far
// beyond any radiance a scene means (the sun's is about 1e9 W/sr/m^2), and far enough below
// float's 3.4e38 that the sum of a pixel's 2^20 samples and their squared deviations (the
// variance) stay finite.
// A double, so that a file's "1e15" is within it; as a float it rounds to a little less.
inline constexpr double kMaxColorValue = 1e15;

// Each channel held to +-kMaxColorValue (a NaN stays NaN).
inline Color clampedToMaxColorValue(const Color& c) {
    const auto clamp = [](float v) { return std::clamp(v, -float(kMaxColorValue), float(kMaxColorValue)); };
    return {clamp(c.r), clamp(c.g), clamp(c.b)};
}

inline std::ostream& operator<<(std::ostream& os, const Color& c) {
    return os << '(' << c.r << ", " << c.g << ", " << c.b << ')';
}

}  // namespace rt
