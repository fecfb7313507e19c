#include "os/atomic_file.h"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <climits>
#include <cstdint>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <thread>

#include "core/error.h"

namespace rt {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kTemporaryMarker = ".rt-tmp-";

// ".name.rt-tmp-": how every temporary of `target` begins.
std::string temporaryPrefix(const fs::path& target) {
    std::string prefix = ".";  // built by appending: GCC 12 warns falsely (-Wrestrict) on "." + std::string
    prefix += target.stem().string();
    return prefix + std::string(kTemporaryMarker);
}

// "dir/.name.rt-tmp-PID-N.ext": hidden, unique per process, same extension as the target
// (OpenImageIO picks the format from it).
std::string temporaryPathFor(const std::string& path) {
    static std::atomic<int> counter{0};  // unique per call, also across threads
    const fs::path p(path);
    const std::string name =
        temporaryPrefix(p) + std::to_string(getpid()) + "-" + std::to_string(counter++) + p.extension().string();
    return (p.parent_path() / name).string();
}

// The process id in `name` if it is named as temporaryPathFor names temporaries, for any target.
std::optional<pid_t> temporaryOwner(const std::string& name) {
    const std::size_t at = name.rfind(kTemporaryMarker);
    if (!name.starts_with('.') || at == std::string::npos) return std::nullopt;
    const char *digits = name.data() + at + kTemporaryMarker.size(), *end = name.data() + name.size();
    long pid = 0;
    const auto [next, error] = std::from_chars(digits, end, pid);
    if (error != std::errc() || pid <= 0 || pid > std::numeric_limits<pid_t>::max() || next == end || *next != '-')
        return std::nullopt;
    return pid_t(pid);
}

// The process id in `name` if it is a temporary that temporaryPathFor made for `target`.
std::optional<pid_t> temporaryOwner(const std::string& name, const fs::path& target) {
    if (!name.starts_with(temporaryPrefix(target)) || !name.ends_with(target.extension().string())) return std::nullopt;
    return temporaryOwner(name);
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

// When `p`, a file or a folder, or anything directly in it last changed; the far future if it
// cannot be read (it is then not taken for stale).
fs::file_time_type lastChange(const fs::path& p) {
    std::error_code ec;
    fs::file_time_type newest = fs::last_write_time(p, ec);
    if (ec) return fs::file_time_type::max();
    for (fs::directory_iterator it(p, ec), end; !ec && it != end; it.increment(ec))
        newest = std::max(newest, fs::last_write_time(it->path(), ec));
    return newest;
}

// ---- Temporaries removed on SIGINT and SIGTERM -------------------------------------------
// A fixed table the signal handler can read without locks or allocation: each slot holds the
// path of a temporary file or folder this process is writing now.
enum class LiveKind : int { Free, Claimed, File, Folder };  // Claimed: the path is being copied in
static_assert(std::atomic<LiveKind>::is_always_lock_free, "the signal handler reads it");
struct LiveSlot {
    std::atomic<LiveKind> kind{LiveKind::Free};
    char path[PATH_MAX] = {};
};
LiveSlot liveTemporaries[16];

// Registers a temporary for the lifetime of this object. If the table is full or the path too
// long, the temporary is simply not removed on a signal (the next run removes it as stale).
class LiveTemporary {
public:
    LiveTemporary(const std::string& path, LiveKind kind) {
        if (path.size() >= PATH_MAX) return;
        for (LiveSlot& s : liveTemporaries) {
            LiveKind expected = LiveKind::Free;
            if (!s.kind.compare_exchange_strong(expected, LiveKind::Claimed)) continue;
            std::memcpy(s.path, path.c_str(), path.size() + 1);
            s.kind.store(kind);  // published whole: the handler never sees half a path
            slot_ = &s;
            return;
        }
    }
    ~LiveTemporary() {
        if (slot_) slot_->kind.store(LiveKind::Free);
    }
    LiveTemporary(const LiveTemporary&) = delete;
    LiveTemporary& operator=(const LiveTemporary&) = delete;

private:
    LiveSlot* slot_ = nullptr;
};

// Async-signal-safe: only open, getdents64, unlinkat and close. A temporary folder holds
// files only (RAW models and their own temporaries).
void removeFilesInHandler(const char* folder) {
    const int fd = ::open(folder, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    alignas(dirent64) char buffer[4096];
    for (ssize_t n; (n = ::getdents64(fd, buffer, sizeof buffer)) > 0;)
        for (ssize_t at = 0; at < n;) {
            const auto* entry = reinterpret_cast<const dirent64*>(buffer + at);
            ::unlinkat(fd, entry->d_name, 0);  // "." and ".." fail harmlessly
            at += entry->d_reclen;
        }
    ::close(fd);
}

void removeFolderInHandler(const char* folder) {
    // Another pass if removing entries while reading the folder skipped some.
    for (int pass = 0; pass < 3 && ::rmdir(folder) != 0 && errno == ENOTEMPTY; ++pass) removeFilesInHandler(folder);
}

// ---- The work under way, said when a signal ends the process -----------------------------
std::atomic<const char*> workWho{nullptr}, workUnit{nullptr};
std::atomic<std::uint64_t> workDone{0}, workTotal{0};
static_assert(std::atomic<std::uint64_t>::is_always_lock_free, "the signal handler reads it");

// Async-signal-safe: digits by hand, one write(2).
void appendNumber(char*& at, std::uint64_t n) {
    char digits[20];
    int count = 0;
    do digits[count++] = char('0' + n % 10);
    while ((n /= 10) > 0);
    while (count > 0) *at++ = digits[--count];
}

void appendText(char*& at, const char* text) {
    while (*text) *at++ = *text++;
}

void sayWorkInProgress(int signal) {
    const char *who = workWho.load(), *unit = workUnit.load();
    const std::uint64_t total = workTotal.load(), done = std::min(workDone.load(), total);
    if (!who || total == 0) return;
    char line[256];
    char* at = line;
    appendText(at, who);
    appendText(at, signal == SIGINT ? ": stopped by SIGINT at " : ": stopped by SIGTERM at ");
    appendNumber(at, done);
    appendText(at, " of ");
    appendNumber(at, total);
    appendText(at, " ");
    appendText(at, unit);
    appendText(at, " (");
    appendNumber(at, done * 100 / total);
    appendText(at, "%); its output is not written\n");
    [[maybe_unused]] const ssize_t ignored = ::write(STDERR_FILENO, line, std::size_t(at - line));
}

// Installs `action` for SIGINT and SIGTERM. Async-signal-safe (sigaction only). An ignored
// signal stays ignored (nohup, a background job of a script).
void handleInterrupts(const struct sigaction& action) {
    for (int signal : {SIGINT, SIGTERM}) {
        struct sigaction previous {};
        if (sigaction(signal, nullptr, &previous) == 0 && previous.sa_handler != SIG_IGN)
            sigaction(signal, &action, nullptr);
    }
}

// ---- A request to end the work at its next whole step ------------------------------------
std::atomic<int> endRequest{0};
std::atomic<const char*> endWho{nullptr}, endAnnouncement{nullptr};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler writes it");

const char* signalName(int signal) {
    if (signal == SIGINT) return "SIGINT";
    return signal == SIGTERM ? "SIGTERM" : "SIGUSR1";
}

extern "C" void requestEndOfWork(int signal) {
    const int savedErrno = errno;
    int none = 0;
    const bool first = endRequest.compare_exchange_strong(none, signal);
    // An interrupt is honoured once: the next one ends the process as it would have.
    if (signal != SIGUSR1) removeTemporariesOnSignals();
    const char *who = endWho.load(), *announcement = endAnnouncement.load();
    if (first && who && announcement) {
        char line[512];  // the callers' literals are far shorter
        char* at = line;
        appendText(at, who);
        appendText(at, ": ");
        appendText(at, signalName(signal));
        appendText(at, ": ");
        appendText(at, announcement);
        appendText(at, "\n");
        [[maybe_unused]] const ssize_t ignored = ::write(STDERR_FILENO, line, std::size_t(at - line));
    }
    errno = savedErrno;
}

extern "C" void removeLiveTemporariesAndDie(int signal) {
    const int savedErrno = errno;
    sayWorkInProgress(signal);
    for (LiveSlot& s : liveTemporaries) {
        const LiveKind kind = s.kind.load();
        if (kind == LiveKind::File) ::unlink(s.path);
        if (kind == LiveKind::Folder) removeFolderInHandler(s.path);
    }
    errno = savedErrno;
    // SA_RESETHAND restored the default action: the signal, pending until this handler
    // returns, then ends the process as it would have (exit status 128+N in a shell).
    ::raise(signal);
}

// ---- Checked writes --------------------------------------------------------------------

std::runtime_error cannotWrite(const std::string& path, int error) {
    return std::runtime_error(path + ": cannot write" + (error ? std::string(": ") + std::strerror(error) : ""));
}

// Devices, FIFOs and sockets are written in place: renaming a file over them would replace
// /dev/null with a regular file, and a FIFO's reader would get nothing.
bool isSpecialFile(const std::string& path) {
    struct stat st {};
    return path != "-" && ::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode) && !S_ISDIR(st.st_mode);
}

// Calls write(out), flushes and checks every byte went out; throws naming `name` if not.
void writeStream(std::ostream& out, const std::string& name, const std::function<void(std::ostream&)>& write) {
    if (!out) throw cannotWrite(name, errno);
    errno = 0;
    write(out);
    out.flush();
    if (!out) throw cannotWrite(name, errno);
}

// Makes a written temporary durable before it is renamed into place, and checks that it holds
// what was written: some writers (OpenImageIO's PNG) do not report a full disk themselves.
void syncTemporary(const std::string& path, const std::string& temp, std::optional<std::uintmax_t> expectedSize) {
    const int fd = ::open(temp.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) throw cannotWrite(path, errno);
    struct stat st {};
    const bool ok = ::fsync(fd) == 0 && ::fstat(fd, &st) == 0;
    const int error = errno;
    ::close(fd);
    if (!ok) throw cannotWrite(path, error);
    if (expectedSize && std::uintmax_t(st.st_size) != *expectedSize)
        throw std::runtime_error(path + ": cannot write: only " + std::to_string(st.st_size) + " of " +
                                 std::to_string(*expectedSize) + " bytes reached the disk");
}

// Test hook, for tests/cli/render_atomic.sh only: $RT_TEST_WRITE_DELAY_MS keeps the written
// temporary that many milliseconds before it is renamed, so a test can kill a process mid-write.
void testWriteDelay() {
    if (const char* ms = std::getenv("RT_TEST_WRITE_DELAY_MS"))
        std::this_thread::sleep_for(std::chrono::milliseconds(std::atol(ms)));
}

void renameOver(const std::string& from, const std::string& to) {
    if (std::rename(from.c_str(), to.c_str()) != 0) throw cannotWrite(to, errno);
}

// The common path of every file output: write(temp) fills a temporary beside `path` and returns
// its expected size if it knows it; the temporary is synced, checked and renamed over `path`.
// Whatever fails, the temporary is removed and `path` is untouched.
void publishThroughTemporary(const std::string& path,
                             const std::function<std::optional<std::uintmax_t>(const std::string&)>& write) {
    removeStaleTemporaries(path);
    const std::string temp = temporaryPathFor(path);
    const LiveTemporary live(temp, LiveKind::File);
    try {
        syncTemporary(path, temp, write(temp));
        testWriteDelay();
        renameOver(temp, path);
    } catch (...) {
        std::remove(temp.c_str());
        throw;
    }
}

// Puts `temp` in the place of `folder`; afterwards `temp` holds the old contents (or nothing).
// RENAME_EXCHANGE swaps both at once, so `folder` is never missing, even if the process is
// killed; file systems without it get two renames through `aside`.
void exchangeFolders(const fs::path& temp, const fs::path& folder, const fs::path& aside) {
    std::error_code ec;
    if (!fs::exists(folder, ec)) return fs::rename(temp, folder);
    if (::renameat2(AT_FDCWD, temp.c_str(), AT_FDCWD, folder.c_str(), RENAME_EXCHANGE) == 0) return;
    const std::error_code error(errno, std::generic_category());
    if (error != std::errc::invalid_argument && error != std::errc::function_not_supported)
        throw fs::filesystem_error("rename", temp, folder, error);
    fs::rename(folder, aside);
    fs::rename(temp, folder);
    fs::rename(aside, temp);
}

// Undoes exchangeFolders when the file that goes with the folder could not be renamed.
void putTheOldFolderBack(const fs::path& temp, const fs::path& folder) noexcept {
    std::error_code ec;
    try {
        if (fs::exists(temp, ec))
            exchangeFolders(temp, folder, temporaryPathFor(folder.string()));
        else
            fs::rename(folder, temp, ec);    // there was none: remove the new one with the temporary
    } catch (const fs::filesystem_error&) {  // nothing more can be done; the caller reports the first failure
    }
}

}  // namespace

ExclusiveLock::ExclusiveLock(const std::string& path, const std::string& target) {
    std::error_code ec;
    const bool folder = fs::is_directory(path, ec);
    fd_ = folder ? ::open(path.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC)
                 : ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd_ < 0 && errno == EACCES && !folder)  // another user's lock file: locks on a local disk all the same
        fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0 || ::flock(fd_, LOCK_EX) != 0) {
        const int error = errno;
        if (fd_ >= 0) ::close(fd_);
        throw cannotWrite(target, error);
    }
}

ExclusiveLock::~ExclusiveLock() { ::close(fd_); }

struct TemporaryFolder::Registration {
    explicit Registration(const std::string& folder) : live(folder, LiveKind::Folder) {}
    LiveTemporary live;
};

TemporaryFolder::TemporaryFolder(const std::string& path)
    : path_(path), folder_(temporaryPathFor(path)), live_(std::make_unique<Registration>(folder_)) {
    std::error_code ec;
    if (!fs::create_directory(folder_, ec)) throw cannotWrite(path, ec ? ec.value() : EEXIST);
}

TemporaryFolder::~TemporaryFolder() { removeQuietly(folder_); }

std::string TemporaryFolder::file() const { return (fs::path(folder_) / fs::path(path_).filename()).string(); }

void TemporaryFolder::commit() const {
    syncTemporary(path_, file(), std::nullopt);
    testWriteDelay();
    renameOver(file(), path_);
}

void removeStaleTemporariesIn(const std::string& folder, std::chrono::seconds unchangedFor) {
    const fs::file_time_type before = fs::file_time_type::clock::now() - unchangedFor;
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::optional<pid_t> owner = temporaryOwner(it->path().filename().string());
        if (owner && !processRuns(*owner) && lastChange(it->path()) < before) removeQuietly(it->path());
    }
}

void noteWorkInProgress(const char* who, const char* unit, std::uint64_t done, std::uint64_t total) {
    workTotal.store(0);  // nothing is said while the fields change
    workWho.store(who);
    workUnit.store(unit);
    workDone.store(done);
    workTotal.store(total);
}

void removeTemporariesOnSignals() {
    struct sigaction action {};
    action.sa_handler = removeLiveTemporariesAndDie;
    action.sa_flags = SA_RESETHAND;
    sigemptyset(&action.sa_mask);
    handleInterrupts(action);
}

void endWorkOnSignals(bool interrupts, const char* who, const char* announcement) {
    endWho.store(who);
    endAnnouncement.store(announcement);
    struct sigaction action {};
    action.sa_handler = requestEndOfWork;
    sigemptyset(&action.sa_mask);
    sigaction(SIGUSR1, &action, nullptr);
    if (interrupts) handleInterrupts(action);
}

int workEndRequested() { return endRequest.load(); }

void checkNotDirectory(const std::string& path) {
    std::error_code ec;
    if (path != "-" && (fs::is_directory(path, ec) || fs::path(path).filename().empty()))
        throw InputError(path + ": is a directory");
}

void prepareOutputFile(const std::string& path) {
    if (path == "-") return;
    checkNotDirectory(path);
    if (isSpecialFile(path)) {  // written in place: it must be writable itself
        if (::access(path.c_str(), W_OK) != 0) throw InputError(path + ": cannot write: " + std::strerror(errno));
        return;
    }
    std::error_code ec;
    const fs::path folder = fs::path(path).parent_path();
    if (!folder.empty() && !fs::is_directory(folder, ec) && !fs::create_directories(folder, ec) && ec)
        throw InputError(path + ": cannot create the folder " + folder.string() + ": " + ec.message());
    const std::string probe = temporaryPathFor(path);
    const LiveTemporary live(probe, LiveKind::File);
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd < 0) throw InputError(path + ": cannot write: " + std::strerror(errno));
    ::close(fd);
    std::remove(probe.c_str());
}

void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
    if (path == "-") return writeStream(std::cout, "standard output", write);
    if (isSpecialFile(path)) {
        std::ofstream out(path, std::ios::binary);
        return writeStream(out, path, write);
    }
    publishThroughTemporary(path, [&](const std::string& temp) -> std::optional<std::uintmax_t> {
        std::ofstream out(temp, std::ios::binary | std::ios::trunc);
        writeStream(out, path, write);
        const std::streamoff size = out.tellp();
        out.close();
        if (out.fail()) throw cannotWrite(path, errno);
        return std::uintmax_t(size);
    });
}

void commitFileAndFolderAtomically(const std::string& path, const std::string& folder,
                                   const std::function<bool(const std::string&, const std::string&)>& write) {
    removeStaleTemporaries(path);
    removeStaleTemporaries(folder);
    std::error_code ec;
    if (fs::exists(folder, ec) && !fs::is_directory(folder, ec))
        throw std::runtime_error(folder + ": cannot write: it exists and is not a folder");
    const std::string temp = temporaryPathFor(path), tempFolder = temporaryPathFor(folder);
    const LiveTemporary liveFile(temp, LiveKind::File), liveFolder(tempFolder, LiveKind::Folder);
    try {
        if (!fs::create_directories(tempFolder, ec)) throw cannotWrite(folder, ec ? ec.value() : EEXIST);
        if (!write(temp, tempFolder)) throw cannotWrite(path, 0);
        syncTemporary(path, temp, std::nullopt);
        testWriteDelay();
        // Published as one unit: writers of the same scene take turns here, so each one's
        // file is renamed right after its own folder, never beside another run's half.
        const fs::path parent = fs::path(path).parent_path();
        const ExclusiveLock lock(parent.empty() ? "." : parent.string(), path);
        exchangeFolders(tempFolder, folder, temporaryPathFor(folder));
        try {
            renameOver(temp, path);
        } catch (...) {
            putTheOldFolderBack(tempFolder, folder);
            throw;
        }
    } catch (const fs::filesystem_error& e) {
        std::remove(temp.c_str());
        removeQuietly(tempFolder);
        throw cannotWrite(folder, e.code().value());
    } catch (...) {
        std::remove(temp.c_str());
        removeQuietly(tempFolder);
        throw;
    }
    removeQuietly(tempFolder);  // now the old folder
}

}  // namespace rt
