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

// Removes a temporary folder and everything in it, ignoring errors (it may not exist).
void removeQuietly(const std::filesystem::path& p) {
    std::error_code ignored;
    std::filesystem::remove_all(p, ignored);
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

void commitFolderAtomically(const std::string& folder, const std::function<bool(const std::string&)>& write) {
    namespace fs = std::filesystem;
    std::error_code ec;
    const bool exists = fs::exists(folder, ec);
    if (exists && !fs::is_directory(folder, ec))
        throw std::runtime_error(folder + ": cannot write: it exists and is not a folder");
    const fs::path temp = temporaryPathFor(folder), old = temporaryPathFor(folder);
    if (!fs::create_directories(temp, ec))
        throw std::runtime_error(folder + ": cannot write: " + (ec ? ec.message() : "the temporary folder exists"));
    bool ok = false;
    try {
        ok = write(temp.string());
    } catch (...) {
        removeQuietly(temp);
        throw;
    }
    if (!ok) {
        removeQuietly(temp);
        throw std::runtime_error(folder + ": cannot write");
    }
    // Two renames: the old folder out of the way, the new one in. Between them `folder`
    // is briefly missing; a failure of the second puts the old one back.
    if (exists) fs::rename(folder, old, ec);
    if (!ec) fs::rename(temp, folder, ec);
    if (ec) {
        const std::string why = ec.message();
        if (exists) fs::rename(old, folder, ec);
        removeQuietly(temp);
        throw std::runtime_error(folder + ": cannot write: " + why);
    }
    removeQuietly(old);
}

}  // namespace rt
