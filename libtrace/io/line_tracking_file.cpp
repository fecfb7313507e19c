#include "io/line_tracking_file.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <new>

#include "core/error.h"

namespace rt {

LineTrackingFile::LineTrackingFile(const std::string& path, std::size_t maxLineBytes)
    : file_(std::fopen(path.c_str(), "rb"), &std::fclose),
      buffer_(std::min(maxLineBytes + 2, std::size_t(64) << 10)),
      maxLineBytes_(maxLineBytes) {
    if (!file_) throw InputError(path + ": cannot open: " + std::strerror(errno));
    setg(buffer_.data(), buffer_.data(), buffer_.data());
}

namespace {

// True if the character at p ends a line: "\n", or a "\r" that does not start "\r\n"
// (old Mac files end lines with "\r" alone). A "\r" last before `end` is undecided, and
// counted as no break: the buffer keeps it with the line until the next block says.
bool endsLine(const char* p, const char* end) { return *p == '\n' || (*p == '\r' && p + 1 < end && p[1] != '\n'); }

std::size_t lineBreaks(const char* from, const char* to, const char* end) {
    std::size_t n = 0;
    for (const char* p = from; p < to; ++p) n += endsLine(p, end);
    return n;
}

}  // namespace

std::size_t LineTrackingFile::lineStart() const {
    const char* begin = eback();
    // The last character read belongs to the line; a line break right at gptr()-1 ends it.
    const char* at = gptr() > begin ? gptr() - 1 : begin;
    while (at > begin && !endsLine(at - 1, egptr())) --at;
    return std::size_t(at - begin);
}

std::size_t LineTrackingFile::lineNumber() const {
    return linesBefore_ + lineBreaks(eback(), eback() + lineStart(), egptr()) + 1;
}

std::string_view LineTrackingFile::lineText() const {
    std::string_view text(eback() + lineStart(), std::size_t(gptr() - eback()) - lineStart());
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.remove_suffix(1);
    return text;
}

LineTrackingFile::int_type LineTrackingFile::underflow() {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    if (tooLong_ || readFailed_) return traits_type::eof();
    // Keep the unfinished line (everything after the last line break) for lineText().
    char* begin = eback();
    char* end = egptr();
    char* keep = end;
    while (keep > begin && !endsLine(keep - 1, end)) --keep;
    linesBefore_ += lineBreaks(begin, keep, end);
    const std::size_t kept = std::size_t(end - keep);
    if (kept == buffer_.size()) {
        if (kept >= bufferLimit()) {
            tooLong_ = true;
            return traits_type::eof();
        }
        const std::size_t keepOffset = std::size_t(keep - begin);
        try {
            buffer_.resize(std::min(2 * buffer_.size(), bufferLimit()));
        } catch (const std::bad_alloc&) {  // std::istream would swallow it and end the file here
            readFailed_ = true;
            return traits_type::eof();
        }
        keep = buffer_.data() + keepOffset;
    }
    std::memmove(buffer_.data(), keep, kept);
    const std::size_t got = std::fread(buffer_.data() + kept, 1, buffer_.size() - kept, file_.get());
    if (got == 0 && std::ferror(file_.get())) readFailed_ = true;
    setg(buffer_.data(), buffer_.data() + kept, buffer_.data() + kept + got);
    return got == 0 ? traits_type::eof() : traits_type::to_int_type(*gptr());
}

}  // namespace rt
