#include "core/atomic_file.h"

#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace rt {
namespace {

// "dir/.name.rt-tmp-PID-N.ext": hidden, unique per process, same extension as the target
// (OpenImageIO picks the format from it).
std::string temporaryPathFor(const std::string& path) {
    static std::atomic<int> counter{0};  // unique per call, also across threads
    const std::filesystem::path p(path);
    std::string name = ".";  // built by appending: GCC 12 warns falsely (-Wrestrict) on "." + std::string
    name += p.stem().string();
    name += ".rt-tmp-" + std::to_string(getpid()) + "-" + std::to_string(counter++);
    name += p.extension().string();
    return (p.parent_path() / name).string();
}

void renameOver(const std::string& from, const std::string& to) {
    if (std::rename(from.c_str(), to.c_str()) != 0) {
        const std::string why = std::strerror(errno);
        std::remove(from.c_str());
        throw std::runtime_error(to + ": cannot write: " + why);
    }
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
    if (path == "-") {
        write(std::cout);
        std::cout.flush();
        if (!std::cout) throw std::runtime_error("cannot write to standard output");
        return;
    }
    commitFileAtomically(path, [&](const std::string& temp) {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error(path + ": cannot write: " + std::strerror(errno));
        write(out);
        out.flush();
        return bool(out);
    });
}

void commitFileAtomically(const std::string& path, const std::function<bool(const std::string&)>& write) {
    const std::string temp = temporaryPathFor(path);
    bool ok = false;
    try {
        ok = write(temp);
    } catch (...) {
        std::remove(temp.c_str());
        throw;
    }
    if (!ok) {
        std::remove(temp.c_str());
        throw std::runtime_error(path + ": cannot write");
    }
    renameOver(temp, path);
}

}  // namespace rt
