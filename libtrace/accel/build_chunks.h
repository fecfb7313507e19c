// Passes over a node's primitives on all the build's threads, for the top levels of a tree,
// where one node holds most of the scene and the other threads would otherwise wait for its
// split. The work is cut into chunks that depend only on the number of items, never on the
// number of threads, and each chunk's result is gathered in chunk order, so the tree is the
// same for any thread count.
#pragma once

#include <algorithm>
#include <cstddef>

#include "core/parallel_errors.h"

namespace rt {

// Below this many primitive references a subtree is built by the thread that reached it, and
// a node's passes over its primitives run on that thread: a task costs microseconds to start,
// and the subtrees around it keep the other threads busy.
constexpr std::size_t kTaskPrimitives = 16384;

// [0, n) in chunks of `size` items (the last may be shorter); one chunk if n <= size.
class Chunks {
public:
    Chunks(std::size_t n, std::size_t size) : n_(n), size_(std::max<std::size_t>(size, 1)) {}

    std::size_t count() const { return n_ == 0 ? 1 : (n_ + size_ - 1) / size_; }
    std::size_t begin(std::size_t chunk) const { return chunk * size_; }
    std::size_t end(std::size_t chunk) const { return std::min(n_, (chunk + 1) * size_); }

private:
    std::size_t n_, size_;
};

// The chunks of a pass over a node of `n` primitives (or over `n` items of such a node when
// `node` says how many primitives it has): one below kTaskPrimitives, else of `size` items.
inline Chunks nodeChunks(std::size_t n, std::size_t size, std::size_t node) {
    return Chunks(n, node < kTaskPrimitives ? n : size);
}
inline Chunks nodeChunks(std::size_t n, std::size_t size = 4096) { return nodeChunks(n, size, n); }

// Calls body(chunk, begin, end) for every chunk, as OpenMP tasks when there are several (on
// the threads of the enclosing parallel region, if any), and returns when all have run. An
// exception thrown by a body is rethrown here, after the other chunks have finished.
template <typename Body>
void forEachChunk(const Chunks& chunks, const Body& body) {
    const std::size_t count = chunks.count();
    if (count == 1) {
        body(std::size_t(0), chunks.begin(0), chunks.end(0));
        return;
    }
    ParallelErrors errors;
#pragma omp taskloop default(shared) grainsize(1)
    for (std::size_t c = 0; c < count; ++c) errors.capture([&] { body(c, chunks.begin(c), chunks.end(c)); });
    errors.rethrowIfAny();
}

}  // namespace rt
