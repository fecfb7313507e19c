#include "io/polygon.h"

#include <cmath>

namespace rt {
namespace {

struct Point2 {
    double x, y;
};

double cross(const Point2& a, const Point2& b, const Point2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

void appendFan(std::span<const std::uint32_t> order, std::vector<std::uint32_t>& triangles) {
    for (std::size_t i = 1; i + 1 < order.size(); ++i)
        triangles.insert(triangles.end(), {order[0], order[i], order[i + 1]});
}

// The corners projected onto the coordinate plane that drops the largest component of the
// polygon's Newell normal, and the sign of their area there (0 for a polygon with no area).
double project(std::span<const std::array<float, 3>> corners, std::vector<Point2>& flat) {
    double n[3] = {0, 0, 0};
    for (std::size_t i = 0; i < corners.size(); ++i) {
        const auto& a = corners[i];
        const auto& b = corners[(i + 1) % corners.size()];
        for (int k = 0; k < 3; ++k) {
            const int u = (k + 1) % 3, v = (k + 2) % 3;
            n[k] += (double(a[u]) - b[u]) * (double(a[v]) + b[v]);
        }
    }
    int drop = 0;
    for (int k = 1; k < 3; ++k)
        if (std::abs(n[k]) > std::abs(n[drop])) drop = k;
    const int u = (drop + 1) % 3, v = (drop + 2) % 3;
    flat.clear();
    for (const auto& c : corners) flat.push_back({c[u], c[v]});
    return n[drop] > 0 ? 1 : n[drop] < 0 ? -1 : 0;
}

bool isConvex(const std::vector<Point2>& p, double orientation) {
    for (std::size_t i = 0; i < p.size(); ++i)
        if (cross(p[i], p[(i + 1) % p.size()], p[(i + 2) % p.size()]) * orientation < 0) return false;
    return true;
}

// True if p lies inside or on triangle (a, b, c) of the given orientation.
bool inTriangle(const Point2& p, const Point2& a, const Point2& b, const Point2& c, double orientation) {
    return cross(a, b, p) * orientation >= 0 && cross(b, c, p) * orientation >= 0 && cross(c, a, p) * orientation >= 0;
}

// Removes one ear from `order`, appending it; false when no corner is an ear.
bool clipEar(const std::vector<Point2>& p, double orientation, std::vector<std::uint32_t>& order,
             std::vector<std::uint32_t>& triangles) {
    const std::size_t m = order.size();
    for (std::size_t i = 0; i < m; ++i) {
        const std::uint32_t a = order[(i + m - 1) % m], b = order[i], c = order[(i + 1) % m];
        if (cross(p[a], p[b], p[c]) * orientation <= 0) continue;  // reflex or flat corner
        bool empty = true;
        for (std::size_t j = 0; j < m && empty; ++j) {
            const std::uint32_t q = order[j];
            if (q != a && q != b && q != c && inTriangle(p[q], p[a], p[b], p[c], orientation)) empty = false;
        }
        if (!empty) continue;
        triangles.insert(triangles.end(), {a, b, c});
        order.erase(order.begin() + std::ptrdiff_t(i));
        return true;
    }
    return false;
}

}  // namespace

bool triangulatePolygon(std::span<const std::array<float, 3>> corners, std::vector<std::uint32_t>& triangles) {
    std::vector<std::uint32_t> order(corners.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = std::uint32_t(i);
    if (corners.size() == 3) {
        appendFan(order, triangles);
        return true;
    }
    std::vector<Point2> flat;
    const double orientation = project(corners, flat);
    if (orientation == 0 || isConvex(flat, orientation)) {
        appendFan(order, triangles);  // a flat polygon's triangles have no area either way
        return true;
    }
    if (corners.size() > kMaxEarClippedCorners) {
        appendFan(order, triangles);
        return false;
    }
    while (order.size() > 3)
        if (!clipEar(flat, orientation, order, triangles)) {
            appendFan(order, triangles);
            return false;
        }
    appendFan(order, triangles);
    return true;
}

}  // namespace rt
