#include "os/peak_memory.h"

#include <sys/resource.h>

namespace rt {

std::uint64_t peakMemoryBytes() {
    rusage usage{};
    if (getrusage(RUSAGE_SELF, &usage) != 0) return 0;
    return std::uint64_t(usage.ru_maxrss) * 1024;  // Linux counts kibibytes
}

}  // namespace rt
