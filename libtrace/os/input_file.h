// Opening the files a scene names, with one error shape for all of them:
// rt::InputError "path: cannot open: reason" (a missing file, a folder, no permission).
#pragma once

#include <cstdint>
#include <string>

namespace rt {

// The largest file or standard input that rt reads (--max-input): a larger file is refused before
// it is read, and standard input that never ends (`yes | rt-render -`) ends at the limit instead
// of filling the memory. Generous: a scene of 10 million triangles inline is about 500 MB.
constexpr std::uint64_t kDefaultMaxInputBytes = std::uint64_t(2) << 30;
void setMaxInputBytes(std::uint64_t bytes);
std::uint64_t maxInputBytes();

// The size of the regular file at `path`, in bytes; an rt::InputError beyond maxInputBytes().
std::uint64_t inputFileSize(const std::string& path);

// The whole file at `path`.
std::string readInputFile(const std::string& path);

// All of standard input, up to maxInputBytes() (an rt::InputError beyond).
std::string readStandardInput();

}  // namespace rt
