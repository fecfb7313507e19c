// The thesis's ConsoleProgressBar (3.4.5), on standard error so that standard output
// stays for data: "[#########...........]  45%  2.1 s left". Drawn only when standard
// error is a terminal; redrawn at most ten times a second.
#pragma once

#include <chrono>

namespace rt::render_tool {

class ProgressBar {
public:
    // An inactive bar draws nothing (quiet mode, or standard error is not a terminal).
    explicit ProgressBar(bool active);
    ~ProgressBar();  // ends the line if anything was drawn

    void update(int done, int total);

private:
    bool active_;
    bool drawn_ = false;
    std::chrono::steady_clock::time_point start_, lastDraw_;
};

}  // namespace rt::render_tool
