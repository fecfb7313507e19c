// How much memory a run needed, for the statistics: the peak resident set, which is what a farm's
// scheduler (Slurm's MaxRSS, --mem) measures and limits.
#pragma once

#include <cstdint>

namespace rt {

// The most physical memory this process has held so far, in bytes (getrusage's ru_maxrss).
std::uint64_t peakMemoryBytes();

}  // namespace rt
