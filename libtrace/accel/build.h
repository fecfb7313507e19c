// Builds the accelerator a user asked for over a set of primitives.
#pragma once

#include <memory>

#include "accel/accelerator.h"
#include "accel/settings.h"

namespace rt {

// The primitives must outlive the returned structure.
std::unique_ptr<Accelerator> buildAccelerator(const Primitives& prims, const AccelSettings& settings);

}  // namespace rt
