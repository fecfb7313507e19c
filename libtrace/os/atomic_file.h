// Writes that either happen completely or not at all: the data goes to a temporary
// file beside the target, which is renamed over it only once everything is written, flushed,
// synced to the disk (fsync) and checked for size. A failed or interrupted write (a full disk,
// SIGINT, SIGTERM) leaves an existing file untouched and no partial file.
// The path "-" means standard output, and a target that exists and is not a regular file (a
// device such as /dev/null, a FIFO, a socket) is written in place: renaming over it would
// replace it, and a pipe cannot be atomic. Every write there is checked too.
//
// Temporaries are named "folder/.name.rt-tmp-PID-N.ext". A process killed by SIGKILL while
// writing leaves its temporary behind (nothing can remove it then); every later write of the
// same target first removes those whose process PID no longer runs on this machine.
// SIGINT and SIGTERM remove the temporaries being written when the tool installed
// removeTemporariesOnSignals (tools/common/tool.cpp does).
// Test hook: $RT_TEST_WRITE_DELAY_MS holds each finished temporary that many milliseconds
// before the rename, so tests/cli/render_atomic.sh can kill a process in the middle of a write.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <ostream>
#include <string>

namespace rt {

// Installs handlers for SIGINT and SIGTERM that remove the temporaries this process is
// writing, then end it by the same signal (default action: the exit status stays 128+N).
// A signal the process started with ignored stays ignored.
void removeTemporariesOnSignals();

// The work under way, which those handlers say on standard error before the process ends, so
// that a log shows where a pre-empted or timed-out task stopped:
//   rt-render: stopped by SIGTERM at 1536 of 6144 samples (25%); its output is not written
// `who` and `unit` must be string literals (the handler reads them). total 0: nothing under way.
void noteWorkInProgress(const char* who, const char* unit, std::uint64_t done, std::uint64_t total);

// A request to end the work at its next whole step and keep it (rt-render's SIGUSR1 and
// --on-interrupt write: the path tracer ends after the pass under way and writes it). After
// this call SIGUSR1 makes the request, and, with `interrupts`, so does the first SIGINT or
// SIGTERM, after which removeTemporariesOnSignals's handlers are back: a second one ends the
// process at once, writing nothing, as without the request. The first signal's handler says
// "WHO: SIGNAME: ANNOUNCEMENT" on standard error (`who` and `announcement` string literals).
void endWorkOnSignals(bool interrupts, const char* who, const char* announcement);

// The signal that asked for the end (SIGUSR1, SIGINT or SIGTERM), or 0 if none has.
int workEndRequested();

// Throws rt::InputError "PATH: is a directory" if `path` names a folder (or ends in '/').
void checkNotDirectory(const std::string& path);

// Checks, before any work, that `path` can be written: creates its missing parent folders
// and creates and removes a temporary file there. Throws rt::InputError naming `path` if it is
// a directory or its folder cannot be created or written. "-" (standard output) always passes.
void prepareOutputFile(const std::string& path);

// Calls write(stream) and commits the result to `path`. Throws std::runtime_error
// (naming the file) if the file cannot be written; the temporary is removed.
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

// For a file that names files in a folder beside it (a scene XML and its RAW models):
// calls write(tempPath, tempFolder) with a temporary file and a new, empty temporary folder,
// then publishes both as one unit: under a lock on the target's folder (flock, so concurrent
// writers of the same scene take turns), the temporary folder takes the place of `folder`,
// whose old contents are removed (nothing stale is left), and the file is renamed over `path`.
// If write throws or returns false, or a rename fails, `path` and `folder` are as they were.
// Throws std::runtime_error if `folder` exists but is not a folder, or cannot be replaced.
void commitFileAndFolderAtomically(const std::string& path, const std::string& folder,
                                   const std::function<bool(const std::string&, const std::string&)>& write);

// Holds an exclusive flock on `path` while it lives: a folder, or a lock file (created if
// missing, opened for writing, so that the lock also holds on NFS, where Linux emulates flock
// with a whole-file byte-range lock). Processes taking the same lock take turns. Throws
// std::runtime_error naming `target` (what the lock protects) if the lock cannot be taken.
class ExclusiveLock {
public:
    ExclusiveLock(const std::string& path, const std::string& target);
    ~ExclusiveLock();  // closing releases the lock
    ExclusiveLock(const ExclusiveLock&) = delete;
    ExclusiveLock& operator=(const ExclusiveLock&) = delete;

private:
    int fd_ = -1;
};

// For a file that a library writes by name, making temporaries of its own beside that name
// (OpenImageIO's make_texture does): a new hidden folder beside `path`, named as the temporaries
// above ("folder/.name.rt-tmp-PID-N.ext/"), in which file() is written. commit() syncs that file
// and renames it to `path`. The folder and whatever is in it are removed when this object dies,
// and on SIGINT and SIGTERM (removeTemporariesOnSignals). Throws std::runtime_error naming `path`
// if the folder cannot be made.
class TemporaryFolder {
public:
    explicit TemporaryFolder(const std::string& path);
    ~TemporaryFolder();
    TemporaryFolder(const TemporaryFolder&) = delete;
    TemporaryFolder& operator=(const TemporaryFolder&) = delete;

    // Where the file is to be written: the folder and the target's file name.
    std::string file() const;
    // Makes file() durable (fsync) and renames it to the target; throws naming the target.
    void commit() const;

private:
    struct Registration;  // the folder in the table the signal handlers empty
    std::string path_, folder_;
    std::unique_ptr<Registration> live_;
};

// Removes from `folder` the temporaries (files or folders named as above, for any target) left by
// processes that no longer run on this machine and in which nothing changed for `unchangedFor`:
// for a folder that several machines may share (a cache), where a process id of another machine
// says nothing, and whose targets are not known in advance. Errors are ignored.
void removeStaleTemporariesIn(const std::string& folder, std::chrono::seconds unchangedFor);

}  // namespace rt
