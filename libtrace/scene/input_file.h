// Opening the files a scene names, with one error shape for all of them:
// rt::InputError "path: cannot open: reason" (a missing file, a folder, no permission).
#pragma once

#include <cstdint>
#include <string>

namespace rt {

// The size of the regular file at `path`, in bytes.
std::uint64_t inputFileSize(const std::string& path);

// The whole file at `path`.
std::string readInputFile(const std::string& path);

}  // namespace rt
