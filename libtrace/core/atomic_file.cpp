#include "core/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <thread>

#include "core/error.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

// ".name.rt-tmp-": how every temporary of `target` begins.
std::string temporaryPrefix(const fs::path& target) {
    std::string prefix = ".";  // built by appending: GCC 12 warns falsely (-Wrestrict) on "." + std::string
    prefix += target.stem().string();
    return prefix + ".rt-tmp-";
}

// "dir/.name.rt-tmp-PID-N.ext": hidden, unique per process, same extension as the target
// (OpenImageIO picks the format from it).
std::string temporaryPathFor(const std::string& path) {
    static std::atomic<int> counter{0};  // unique per call, also across threads
    const fs::path p(path);
    const std::string name = temporaryPrefix(p) + std::to_string(getpid()) + "-" + std::to_string(counter++) +
                             p.extension().string();
    return (p.parent_path() / name).string();
}

// The process id in `name` if it is a temporary that temporaryPathFor made for `target`.
std::optional<pid_t> temporaryOwner(const std::string& name, const fs::path& target) {
    const std::string prefix = temporaryPrefix(target), suffix = target.extension().string();
    if (name.size() <= prefix.size() + suffix.size() || !name.starts_with(prefix) || !name.ends_with(suffix))
        return std::nullopt;
    const std::string id = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());  // "PID-N"
    long pid = 0, n = 0;
    int used = -1;
    if (std::sscanf(id.c_str(), "%ld-%ld%n", &pid, &n, &used) != 2 || used != int(id.size()) || pid <= 0)
        return std::nullopt;
    return pid_t(pid);
}

// Removes a temporary file or folder and everything in it, ignoring errors (it may not exist).
void removeQuietly(const fs::path& p) {
    std::error_code ignored;
    fs::remove_all(p, ignored);
}

bool processRuns(pid_t pid) { return kill(pid, 0) == 0 || errno == EPERM; }

// A process killed while writing (SIGKILL cannot be caught) leaves its temporary behind;
// the next write of the same target removes those whose process no longer runs.
void removeStaleTemporaries(const std::string& path) {
    const fs::path target(path);
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::optional<pid_t> owner = temporaryOwner(it->path().filename().string(), target);
        if (owner && !processRuns(*owner)) removeQuietly(it->path());
    }
}

// Test hook, for tests/cli/render_atomic.sh only: $RT_TEST_WRITE_DELAY_MS keeps the written
// temporary that many milliseconds before it is renamed, so a test can kill a process mid-write.
void testWriteDelay() {
    if (const char* ms = std::getenv("RT_TEST_WRITE_DELAY_MS"))
        std::this_thread::sleep_for(std::chrono::milliseconds(std::atol(ms)));
}

void renameOver(const std::string& from, const std::string& to) {
    if (std::rename(from.c_str(), to.c_str()) != 0) {
        const std::string why = std::strerror(errno);
        std::remove(from.c_str());
        throw std::runtime_error(to + ": cannot write: " + why);
    }
}

}  // namespace

void checkNotDirectory(const std::string& path) {
    std::error_code ec;
    if (path != "-" && (fs::is_directory(path, ec) || fs::path(path).filename().empty()))
        throw InputError(path + ": is a directory");
}

void prepareOutputFile(const std::string& path) {
    if (path == "-") return;
    checkNotDirectory(path);
    std::error_code ec;
    const fs::path folder = fs::path(path).parent_path();
    if (!folder.empty() && !fs::is_directory(folder, ec) && !fs::create_directories(folder, ec) && ec)
        throw InputError(path + ": cannot create the folder " + folder.string() + ": " + ec.message());
    const std::string probe = temporaryPathFor(path);
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0644);
    if (fd < 0) throw InputError(path + ": cannot write: " + std::strerror(errno));
    ::close(fd);
    std::remove(probe.c_str());
}

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
    removeStaleTemporaries(path);
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
    testWriteDelay();
    renameOver(temp, path);
}

void commitFolderAtomically(const std::string& folder, const std::function<bool(const std::string&)>& write) {
    removeStaleTemporaries(folder);
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
