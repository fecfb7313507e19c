#include "image/exr_header.h"

#include <cstring>

namespace rt {

namespace {

// OpenEXR's file layout ("The OpenEXR File Layout", openexr.com): the magic number, a version
// field with flags, then one header (several for a multi-part file), each a list of attributes
// (name, type name, 32-bit little-endian size, value) ended by an empty name.
constexpr std::uint8_t kMagic[4] = {0x76, 0x2f, 0x31, 0x01};
constexpr std::uint32_t kLongNames = 0x400;  // names of up to 255 bytes instead of 31
constexpr std::uint32_t kMultiPart = 0x1000;

struct HeaderWalk {
    const ByteReader& read;
    std::uint64_t size;
    std::size_t maxName;
    std::uint64_t at = 8;

    // A null-terminated name at `at` (empty at the end of a header); nullopt with `problem` set.
    std::optional<std::string> name(std::string& problem) {
        std::string text;
        for (std::uint8_t c = 0;; text.push_back(char(c))) {
            if (!read(at + text.size(), 1, &c)) {
                problem = "byte " + std::to_string(at) + ": the header ends inside a name";
                return std::nullopt;
            }
            if (c == 0) break;
            if (text.size() == maxName) {
                problem = "byte " + std::to_string(at) + ": a name longer than " + std::to_string(maxName) + " bytes";
                return std::nullopt;
            }
        }
        at += text.size() + 1;
        return text;
    }

    // One attribute whose name was read; false with `problem` set.
    bool attribute(const std::string& attributeName, std::string& problem) {
        const std::uint64_t start = at;
        if (!name(problem)) return false;  // the type's name
        std::uint8_t bytes[4];
        if (!read(at, 4, bytes)) {
            problem = "byte " + std::to_string(at) + ": the header ends inside attribute '" + attributeName + "'";
            return false;
        }
        const std::int32_t declared = std::int32_t(std::uint32_t(bytes[0]) | std::uint32_t(bytes[1]) << 8 |
                                                   std::uint32_t(bytes[2]) << 16 | std::uint32_t(bytes[3]) << 24);
        at += 4;
        if (declared < 0 || std::uint64_t(declared) > size - at) {
            problem = "byte " + std::to_string(start) + ": attribute '" + attributeName + "' declares " +
                      std::to_string(declared) + " bytes, more than the " + std::to_string(size - at) +
                      " left in the file";
            return false;
        }
        at += std::uint64_t(declared);
        return true;
    }

    // One header; false with `problem` set. `empty` says it had no attribute (a multi-part file's end).
    bool header(bool& empty, std::string& problem) {
        empty = true;
        while (true) {
            const std::optional<std::string> attributeName = name(problem);
            if (!attributeName) return false;
            if (attributeName->empty()) return true;
            empty = false;
            if (!attribute(*attributeName, problem)) return false;
        }
    }
};

}  // namespace

std::optional<std::string> exrHeaderProblem(const ByteReader& read, std::uint64_t size) {
    std::uint8_t start[8];
    if (!read(0, 8, start) || std::memcmp(start, kMagic, 4) != 0) return std::nullopt;
    const std::uint32_t flags =
        std::uint32_t(start[5]) << 8 | std::uint32_t(start[6]) << 16 | std::uint32_t(start[7]) << 24;
    HeaderWalk walk{read, size, (flags & kLongNames) ? 255u : 31u};
    std::string problem;
    bool empty = false;
    if (!(flags & kMultiPart)) return walk.header(empty, problem) ? std::nullopt : std::optional(problem);
    do {  // each part's header, then an empty one
        if (!walk.header(empty, problem)) return problem;
    } while (!empty);
    return std::nullopt;
}

}  // namespace rt
