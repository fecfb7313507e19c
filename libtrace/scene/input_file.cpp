#include "scene/input_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "core/error.h"

namespace rt {

std::uint64_t inputFileSize(const std::string& path) {
    std::error_code ec;
    const std::uint64_t size = std::filesystem::file_size(path, ec);  // fails for a folder, too
    if (ec) throw InputError(path + ": cannot open: " + ec.message());
    return size;
}

std::string readInputFile(const std::string& path) {
    std::string bytes(inputFileSize(path), '\0');
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": cannot open: " + std::strerror(errno));
    in.read(bytes.data(), std::streamsize(bytes.size()));
    if (in.gcount() != std::streamsize(bytes.size())) throw InputError(path + ": read error");
    return bytes;
}

}  // namespace rt
