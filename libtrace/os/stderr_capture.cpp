#include "os/stderr_capture.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>
#include <sstream>

namespace rt {

StderrCapture::StderrCapture() {
    std::fflush(stderr);
    captured_ = ::memfd_create("rt-stderr", MFD_CLOEXEC);
    if (captured_ < 0) return;
    saved_ = ::fcntl(2, F_DUPFD_CLOEXEC, 0);
    if (saved_ < 0 || ::dup2(captured_, 2) < 0) {
        if (saved_ >= 0) ::close(saved_);
        ::close(captured_);
        saved_ = captured_ = -1;
    }
}

StderrCapture::~StderrCapture() { writeToStderr(take()); }

std::string StderrCapture::take() {
    if (captured_ < 0) return {};
    std::fflush(stderr);
    ::dup2(saved_, 2);
    ::close(saved_);
    std::string text;
    char buffer[4096];
    ssize_t n;
    for (off_t at = 0; (n = ::pread(captured_, buffer, sizeof buffer, at)) > 0; at += n) text.append(buffer, size_t(n));
    ::close(captured_);
    saved_ = captured_ = -1;
    return text;
}

std::string withoutToldLibpngErrors(const std::string& printed, const std::vector<std::string>& told) {
    static const std::string kLibpng = "libpng error: ";
    std::istringstream lines(printed);
    std::string kept, line;
    while (std::getline(lines, line)) {
        const bool folded = line.starts_with(kLibpng) && [&] {
            const std::string message = line.substr(kLibpng.size());
            for (const std::string& t : told)
                if (t.find(message) != std::string::npos) return true;
            return false;
        }();
        if (!folded) kept += line + '\n';
    }
    return kept;
}

void writeToStderr(const std::string& text) {
    for (std::size_t at = 0; at < text.size();) {
        const ssize_t n = ::write(2, text.data() + at, text.size() - at);
        if (n <= 0) return;
        at += std::size_t(n);
    }
}

}  // namespace rt
