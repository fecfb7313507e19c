// A packet's kPacketSize rays on the level's lanes (core/simd.h), shared by the packet traversals
// of the trees (accel/kd_packet.cpp) and of the BVH (accel/bvh_packet.cpp): one value per ray in
// groups of one register, masks of all-ones lanes, and bit i of a LaneBits for ray i. Included
// last by a file compiled once per level (accel/simd_level.h), in an include block of its own:
// what it defines lies in that level's region and namespace.
#pragma once

#include "accel/accelerator.h"

// Last, in a block of its own (clang-format sorts a block): the level's region starts here.
#include "accel/simd_level.h"

namespace rt::RT_LEVEL_NAMESPACE {

// The packet in groups of one register's lanes: SSE2 takes four groups of two doubles or two of
// four floats, AVX2 two of four doubles or one of eight floats, AVX-512 one of eight doubles or
// eight floats.
inline constexpr int kGroups = kPacketSize / kLanes;
static_assert(kGroups * kLanes == kPacketSize);

// Masks are all-ones lanes (core/simd.h); bit i of a LaneBits is ray i.
using LaneBits = unsigned;

struct Lanes {
    RealLanes group[kGroups];
};

inline LaneBits bitsOf(const Lanes& mask) {
    LaneBits bits = 0;
    for (int g = 0; g < kGroups; ++g) bits |= laneBits(mask.group[g]) << (g * kLanes);
    return bits;
}

// A group's lane mask from one bit per lane.
inline RealLanes groupMaskOf(LaneBits bits) {
    alignas(64) Real lanes[kLanes];
    for (int i = 0; i < kLanes; ++i) lanes[i] = (bits >> i) & 1u ? Real(1) : Real(0);
    return notEqual(loadLanes(lanes), broadcast(0));
}

// A lane mask from one bit per ray.
inline Lanes maskOf(LaneBits bits) {
    Lanes mask;
    for (int g = 0; g < kGroups; ++g) mask.group[g] = groupMaskOf((bits >> (g * kLanes)) & ((1u << kLanes) - 1));
    return mask;
}

inline Lanes load(const Real (&values)[kPacketSize]) {
    Lanes l;
    for (int g = 0; g < kGroups; ++g) l.group[g] = loadLanes(values + g * kLanes);
    return l;
}

inline Lanes broadcastLanes(Real value) {
    Lanes l;
    for (int g = 0; g < kGroups; ++g) l.group[g] = broadcast(value);
    return l;
}

inline void store(const Lanes& l, Real (&values)[kPacketSize]) {
    for (int g = 0; g < kGroups; ++g) storeLanes(values + g * kLanes, l.group[g]);
}

// Lane `ray` of `lanes`.
inline Real laneOf(const Lanes& lanes, int ray) {
    alignas(64) Real values[kPacketSize];
    store(lanes, values);
    return values[ray];
}

}  // namespace rt::RT_LEVEL_NAMESPACE
