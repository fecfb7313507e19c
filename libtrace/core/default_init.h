// A vector whose items, when it grows, are left uninitialized (default-initialized) instead of
// zeroed: for large buffers that are sized first and then written in full, where zeroing them
// first cost a pass over memory of its own (the KD build's event lists, the trees' leaf data).
#pragma once

#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace rt {

template <typename T>
struct DefaultInitAllocator : std::allocator<T> {
    template <typename U>
    struct rebind {
        using other = DefaultInitAllocator<U>;
    };
    template <typename U>
    void construct(U* p) noexcept {
        ::new (static_cast<void*>(p)) U;
    }
    template <typename U, typename... Args>
    void construct(U* p, Args&&... args) {
        ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
    }
};

template <typename T>
using UninitializedVector = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace rt
