#include "progress.h"

#include <unistd.h>

#include <cstdio>

namespace rt::tool::render {

namespace {
constexpr int kBarWidth = 40;
constexpr auto kRedrawInterval = std::chrono::milliseconds(100);
constexpr auto kLineInterval = std::chrono::seconds(10);

double secondsLeft(double fraction, double elapsed) { return elapsed * (1 - fraction) / fraction; }
}  // namespace

ProgressMode progressMode(ProgressMode requested, bool quiet) {
    if (quiet) return ProgressMode::None;
    if (requested != ProgressMode::Auto) return requested;
    return isatty(STDERR_FILENO) ? ProgressMode::Bar : ProgressMode::Lines;
}

Progress::Progress(ProgressMode mode) : mode_(mode), start_(std::chrono::steady_clock::now()), lastOutput_(start_) {}

Progress::~Progress() {
    if (barDrawn_) std::fputc('\n', stderr);
}

void announce(ProgressMode mode, const std::string& message) {
    if (mode == ProgressMode::None) return;
    std::fprintf(stderr, "rt-render: %s\n", message.c_str());
    std::fflush(stderr);
}

void Progress::update(std::uint64_t done, std::uint64_t total) {
    if (mode_ == ProgressMode::None || total == 0) return;
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double fraction = double(done) / double(total);
    const bool finished = done >= total;
    if (mode_ == ProgressMode::Bar) {
        if (!finished && barDrawn_ && now - lastOutput_ < kRedrawInterval) return;
        drawBar(fraction, elapsed, finished);
    } else {
        const int decile = int(fraction * 10);
        if (decile <= lastDecile_ && now - lastOutput_ < kLineInterval) return;
        lastDecile_ = decile;
        printLine(done, total, elapsed);
    }
    lastOutput_ = now;
}

void Progress::drawBar(double fraction, double elapsed, bool finished) {
    char bar[kBarWidth + 1];
    const int filled = int(fraction * kBarWidth);
    for (int i = 0; i < kBarWidth; ++i) bar[i] = i < filled ? '#' : '.';
    bar[kBarWidth] = '\0';
    if (!finished && fraction > 0)
        std::fprintf(stderr, "\r[%s] %3d%%  %.1f s left ", bar, int(fraction * 100), secondsLeft(fraction, elapsed));
    else
        std::fprintf(stderr, "\r[%s] %3d%%  %.1f s      ", bar, int(fraction * 100), elapsed);
    std::fflush(stderr);
    barDrawn_ = true;
}

void Progress::printLine(std::uint64_t done, std::uint64_t total, double elapsed) {
    const double fraction = double(done) / double(total);
    std::fprintf(stderr, "rt-render: %d%% of %llu samples, %.1f s elapsed, %.3g M samples/s", int(fraction * 100),
                 static_cast<unsigned long long>(total), elapsed, elapsed > 0 ? double(done) / elapsed / 1e6 : 0.0);
    if (done < total) std::fprintf(stderr, ", %.1f s left", secondsLeft(fraction, elapsed));
    std::fputc('\n', stderr);
    std::fflush(stderr);
}

}  // namespace rt::tool::render
