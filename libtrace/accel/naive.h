// The naive list: every ray is tested against every primitive (thesis 3.3.3).
// Slow, obviously right, and the reference every tree must agree with.
#pragma once

#include "accel/accelerator.h"
#include "accel/settings.h"

namespace rt {

class NaiveAccelerator final : public Accelerator {
public:
    // Its triangles are tested with `triangles`.
    explicit NaiveAccelerator(const Primitives& prims, TriangleTest triangles = TriangleTest::MollerTrumbore)
        : prims_(prims), view_(prims.view()), triangles_(triangles) {}

    bool intersect(const Ray& ray, Real tMax, Hit& hit, RayCounters& counters) const override;
    bool occluded(const Ray& ray, Real tMax, RayCounters& counters) const override;
    AccelStats stats() const override;
    void forEachNode(const std::function<void(const TreeNodeInfo&)>& visit) const override;  // one leaf

private:
    const Primitives& prims_;
    PrimitiveView view_;  // of prims_, which must not change while the list is used
    TriangleTest triangles_;
};

}  // namespace rt
