// rt-render's progress on standard error, so that standard output stays for data. Two shapes:
// the thesis's ConsoleProgressBar (3.4.5) for a terminal, "[#########.....]  45%  2.1 s left",
// redrawn at most ten times a second; and lines for logs (a farm's job log, a pipe), one
// every 10 % of the work or every 10 s, whichever comes first:
//   rt-render: 40% of 480000 samples, 3.2 s elapsed, 0.06 M samples/s, 4.8 s left
// The estimate comes from the camera samples traced so far (the work done), not from blocks.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

#include "core/names.h"

namespace rt::tool::render {

enum class ProgressMode {
    None,
    Bar,
    Lines,
    Auto,  // what --progress asks for by default: progressMode() makes it Bar or Lines
};
inline constexpr NamedValues<ProgressMode, 4> kProgressModeNames{{{"auto", ProgressMode::Auto},
                                                                  {"bar", ProgressMode::Bar},
                                                                  {"lines", ProgressMode::Lines},
                                                                  {"none", ProgressMode::None}}};

// The mode to show: auto is the bar on a terminal and lines otherwise; quiet (-q) is none.
ProgressMode progressMode(ProgressMode requested, bool quiet);

// A step such as the tree build's start and end, "rt-render: MESSAGE" printed at once (unless None).
void announce(ProgressMode mode, const std::string& message);

// The render's progress; elapsed time counts from construction.
class Progress {
public:
    explicit Progress(ProgressMode mode);
    ~Progress();  // ends the bar's line if one was drawn

    void update(std::uint64_t samplesDone, std::uint64_t samplesTotal);

private:
    void drawBar(double fraction, double elapsed, bool finished);
    void printLine(std::uint64_t done, std::uint64_t total, double elapsed);

    ProgressMode mode_;
    bool barDrawn_ = false;
    int lastDecile_ = 0;  // lines: the last tenth of the work reported
    std::chrono::steady_clock::time_point start_, lastOutput_;
};

}  // namespace rt::tool::render
