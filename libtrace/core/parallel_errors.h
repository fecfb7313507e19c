// Exceptions must not leave an OpenMP task or the body of a parallel loop: the runtime
// calls std::terminate. Work that may throw there (a std::bad_alloc while building a tree
// over a scene too large for memory) runs through capture(), which keeps the first
// exception and turns the work still to come into no-ops; rethrowIfAny() raises it once
// the parallel region is over, where it can reach the tool's error handling.
#pragma once

#include <atomic>
#include <exception>
#include <mutex>

namespace rt {

class ParallelErrors {
public:
    template <typename Work>
    void capture(Work&& work) noexcept {
        if (failed()) return;
        try {
            work();
        } catch (...) {
            const std::lock_guard<std::mutex> lock(mutex_);
            if (!first_) first_ = std::current_exception();
            failed_.store(true, std::memory_order_relaxed);
        }
    }

    bool failed() const { return failed_.load(std::memory_order_relaxed); }

    // Call only after the parallel work has finished (no task may still be running).
    void rethrowIfAny() const {
        if (first_) std::rethrow_exception(first_);
    }

private:
    std::atomic<bool> failed_{false};
    std::mutex mutex_;
    std::exception_ptr first_;
};

}  // namespace rt
