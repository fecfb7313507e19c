// What every fuzz target shares: an input is good or an rt::InputError, nothing else.
#pragma once

#include <unistd.h>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.h"

namespace rt::fuzz {

// Runs `read`; an rt::InputError is the expected answer to bad input. Anything else that
// escapes (std::bad_alloc, std::out_of_range, ...) reaches libFuzzer as an abort, a finding.
template <class Read>
int expectInputErrorOnly(Read&& read) {
    try {
        read();
    } catch (const InputError&) {}
    return 0;
}

// The readers of OBJ and glTF files take a path: the input is written to a file of this
// process's own in a private folder (which holds nothing else, so that the file's references
// to other files find nothing unless the input names itself).
inline std::string writeInputFile(const std::uint8_t* data, std::size_t size, const std::string& fileName) {
    static const std::filesystem::path folder = [] {
        std::filesystem::path p = std::filesystem::temp_directory_path() / ("rt-fuzz-" + std::to_string(getpid()));
        std::filesystem::create_directories(p);
        return p;
    }();
    const std::filesystem::path path = folder / fileName;
    std::ofstream(path, std::ios::binary | std::ios::trunc)
        .write(reinterpret_cast<const char*>(data), std::streamsize(size));
    return path.string();
}

}  // namespace rt::fuzz
