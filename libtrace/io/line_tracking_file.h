// A read-only file as a std::streambuf that can say which line was read last and show its
// text (lines end with "\n", "\r\n" or, in old Mac files, "\r"), so that a parser which only reports values through
// callbacks (tinyobjloader's streaming API) can still have its errors point at file:line.
//
// The file is read in 64 KiB blocks; when a block is used up, the unfinished line at its end
// is moved to the front of the next one, so the line that was read last is always in
// memory. The buffer grows for a longer line, up to maxLineBytes: longer lines are refused
// (tooLong()), which also bounds what a parser that copies whole lines can be made to allocate.
#pragma once

#include <cstdio>
#include <memory>
#include <streambuf>
#include <string>
#include <string_view>
#include <vector>

namespace rt {

class LineTrackingFile : public std::streambuf {
public:
    // Throws rt::InputError when the file cannot be opened.
    explicit LineTrackingFile(const std::string& path, std::size_t maxLineBytes = std::size_t(1) << 20);

    // The 1-based number of the line that holds the character read last (1 before any read).
    std::size_t lineNumber() const;
    // That line's text, without its line break.
    std::string_view lineText() const;
    // True once a line longer than maxLineBytes was met; reading stops there (end of file).
    bool tooLong() const { return tooLong_; }
    // True once reading failed (an I/O error, or no memory for a longer line); reading stops there.
    bool readFailed() const { return readFailed_; }

protected:
    int_type underflow() override;

private:
    std::size_t lineStart() const;                                 // offset in buffer_ where the line read last begins
    std::size_t bufferLimit() const { return maxLineBytes_ + 2; }  // the longest line and "\r\n"

    std::unique_ptr<std::FILE, int (*)(std::FILE*)> file_;
    std::vector<char> buffer_;
    std::size_t maxLineBytes_;
    std::size_t linesBefore_ = 0;  // line breaks in the blocks already dropped
    bool tooLong_ = false;
    bool readFailed_ = false;
};

}  // namespace rt
