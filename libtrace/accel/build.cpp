#include "accel/build.h"

#include <stdexcept>

#include "accel/naive.h"

namespace rt {

std::unique_ptr<Accelerator> buildAccelerator(const Primitives& prims, const AccelSettings& settings) {
    switch (settings.kind) {
        case AccelKind::Naive: return std::make_unique<NaiveAccelerator>(prims);
        case AccelKind::Bsp:
        case AccelKind::Kd: break;
    }
    throw std::runtime_error(std::string("the ") + accelKindName(settings.kind) +
                             " tree is not implemented yet; use --accel naive");
}

}  // namespace rt
