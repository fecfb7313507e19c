// Errors in what a user gave us (a scene, a model, an option) versus failures while
// working. Tools map InputError to exit code 2 and everything else to 1.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace rt {

class InputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// "file:line: message", the shape compilers use, so editors can jump to it.
[[nodiscard]] InputError inputErrorAt(const std::string& file, int line, const std::string& message);
// "file: byte N: message", for binary files.
[[nodiscard]] InputError inputErrorAtByte(const std::string& file, std::uint64_t offset, const std::string& message);

}  // namespace rt
