#include "progress_bar.h"

#include <cstdio>

namespace rt::render_tool {

namespace {
constexpr int kBarWidth = 40;
constexpr auto kRedrawInterval = std::chrono::milliseconds(100);
}  // namespace

ProgressBar::ProgressBar(bool active) : active_(active), start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
    if (drawn_) std::fputc('\n', stderr);
}

void ProgressBar::update(int done, int total) {
    if (!active_ || total <= 0) return;
    const auto now = std::chrono::steady_clock::now();
    if (done < total && drawn_ && now - lastDraw_ < kRedrawInterval) return;
    lastDraw_ = now;
    drawn_ = true;
    const double fraction = double(done) / double(total);
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    char bar[kBarWidth + 1];
    const int filled = int(fraction * kBarWidth);
    for (int i = 0; i < kBarWidth; ++i) bar[i] = i < filled ? '#' : '.';
    bar[kBarWidth] = '\0';
    if (done < total && done > 0)
        std::fprintf(stderr, "\r[%s] %3d%%  %.1f s left ", bar, int(fraction * 100), elapsed * (1 - fraction) / fraction);
    else
        std::fprintf(stderr, "\r[%s] %3d%%  %.1f s      ", bar, int(fraction * 100), elapsed);
    std::fflush(stderr);
}

}  // namespace rt::render_tool
