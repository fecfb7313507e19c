#include "os/input_file.h"

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "core/error.h"

namespace rt {
namespace {

std::atomic<std::uint64_t> maxInput{kDefaultMaxInputBytes};

InputError tooLarge(const std::string& name) {
    return InputError(name + ": larger than the input limit of " + std::to_string(maxInputBytes() >> 20) +
                      " MiB (--max-input)");
}

}  // namespace

void setMaxInputBytes(std::uint64_t bytes) { maxInput = bytes; }
std::uint64_t maxInputBytes() { return maxInput; }

std::uint64_t inputFileSize(const std::string& path) {
    std::error_code ec;
    const std::uint64_t size = std::filesystem::file_size(path, ec);  // fails for a folder, too
    if (ec) throw InputError(path + ": cannot open: " + ec.message());
    if (size > maxInputBytes()) throw tooLarge(path);
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

std::string readStandardInput() {
    std::string bytes;
    char block[1 << 16];
    while (std::cin.read(block, sizeof block) || std::cin.gcount() > 0) {
        if (bytes.size() + std::uint64_t(std::cin.gcount()) > maxInputBytes()) throw tooLarge("<stdin>");
        bytes.append(block, std::size_t(std::cin.gcount()));
    }
    if (std::cin.bad()) throw InputError("<stdin>: read error");
    return bytes;
}

}  // namespace rt
