#include "core/error.h"

namespace rt {

InputError inputErrorAt(const std::string& file, int line, const std::string& message) {
    return InputError(file + ":" + std::to_string(line) + ": " + message);
}

InputError inputErrorAtByte(const std::string& file, std::uint64_t offset, const std::string& message) {
    return InputError(file + ": byte " + std::to_string(offset) + ": " + message);
}

}  // namespace rt
