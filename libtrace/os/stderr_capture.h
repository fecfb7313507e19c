// What the C libraries under OpenImageIO print on standard error themselves while a picture is
// read: libpng's error handler prints "libpng error: IDAT: Read error: hit end of file" before
// OpenImageIO returns the same text as its error, which rt already puts in its one warning line
// (issue 41: one line per error). While a StderrCapture lives, file descriptor 2 goes to a memory
// file; take() gives back the descriptor and what was written, for the caller to fold into its own
// messages and pass the rest on.
#pragma once

#include <string>
#include <vector>

namespace rt {

class StderrCapture {
public:
    StderrCapture();  // no capture when the memory file cannot be made: the text goes to stderr
    StderrCapture(const StderrCapture&) = delete;
    StderrCapture& operator=(const StderrCapture&) = delete;
    ~StderrCapture();  // restores standard error, writing to it what was not taken

    // Restores standard error and returns what was written to it since the capture began.
    std::string take();

private:
    int saved_ = -1;     // the real standard error
    int captured_ = -1;  // the memory file
};

// The lines of `printed` that are not libpng's own error lines ("libpng error: M") whose message M
// is told in one of `told`: those are folded, the rest kept as they were.
std::string withoutToldLibpngErrors(const std::string& printed, const std::vector<std::string>& told);

// Writes `text` to standard error.
void writeToStderr(const std::string& text);

}  // namespace rt
