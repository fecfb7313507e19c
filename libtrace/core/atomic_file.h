// Writes that either happen completely or not at all: the data goes to a temporary
// file beside the target, which is renamed over it only once everything is written.
// A failed or interrupted write leaves an existing file untouched and no partial file.
// The path "-" means standard output (written directly: a pipe cannot be atomic).
//
// Temporaries are named "folder/.name.rt-tmp-PID-N.ext". A process killed by SIGKILL while
// writing leaves its temporary behind (nothing can remove it then); every later write of the
// same target first removes those whose process PID no longer runs on this machine.
// Test hook: $RT_TEST_WRITE_DELAY_MS holds each finished temporary that many milliseconds
// before the rename, so tests/cli/render_atomic.sh can kill a process in the middle of a write.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace rt {

// Throws rt::InputError "PATH: is a directory" if `path` names a folder (or ends in '/').
void checkNotDirectory(const std::string& path);

// Checks, before any work, that `path` can be written: creates its missing parent folders
// and creates and removes a temporary file there. Throws rt::InputError naming `path` if it is
// a directory or its folder cannot be created or written. "-" (standard output) always passes.
void prepareOutputFile(const std::string& path);

// Calls write(stream) and commits the result to `path`. Throws std::runtime_error
// (naming the file) if the file cannot be written; the temporary is removed.
void writeFileAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

// For writers that need a file name of their own (OpenImageIO): calls write(tempPath)
// with a temporary path in the target's folder that keeps the target's extension,
// then renames it over `path`. The temporary is removed if write throws or returns false.
void commitFileAtomically(const std::string& path, const std::function<bool(const std::string&)>& write);

// For an output that is a folder of files: calls write(tempFolder) with a new, empty
// temporary folder beside `folder`, then puts it in the place of `folder`, whose old
// contents are removed (nothing stale is left from an earlier output). If write throws or
// returns false, the temporary folder is removed and `folder` is untouched. Throws
// std::runtime_error if `folder` exists but is not a folder, or cannot be replaced.
void commitFolderAtomically(const std::string& folder, const std::function<bool(const std::string&)>& write);

}  // namespace rt
