// Wall-clock time of a piece of work (tree builds, renders), on the steady clock.
#pragma once

#include <chrono>

namespace rt {

class Stopwatch {
public:
    Stopwatch() : start_(std::chrono::steady_clock::now()) {}

    // Seconds since the stopwatch was made.
    double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }

private:
    std::chrono::steady_clock::time_point start_;
};

}  // namespace rt
