#include "cli/progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lumen::cli {

std::string format_duration(double seconds) {
    char buf[64];
    if (seconds < 60) {
        std::snprintf(buf, sizeof buf, "%.2f s", seconds);
    } else {
        const long s = std::lround(seconds);
        std::snprintf(buf, sizeof buf, "%ld min %02ld s", s / 60, s % 60);
    }
    return buf;
}

ProgressBar::ProgressBar(bool enabled, std::string label)
    : enabled_(enabled), label_(std::move(label)), start_(std::chrono::steady_clock::now()) {}

void ProgressBar::update(double fraction) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (drawn_ && now - last_draw_ < std::chrono::milliseconds(100) && fraction < 1.0) return;
    last_draw_ = now;
    drawn_ = true;
    fraction = std::clamp(fraction, 0.0, 1.0);
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    constexpr int kWidth = 30;
    const int filled = int(fraction * kWidth);
    std::string bar(size_t(filled), '#');
    bar.resize(kWidth, '.');
    std::string eta = "ETA --";
    if (fraction > 0.01) eta = "ETA " + format_duration(elapsed * (1 - fraction) / fraction);
    std::fprintf(stderr, "\r%s [%s] %3d%% %s   ", label_.c_str(), bar.c_str(),
                 int(fraction * 100), eta.c_str());
    std::fflush(stderr);
}

void ProgressBar::finish() {
    if (!enabled_ || !drawn_) return;
    std::fprintf(stderr, "\r\033[K");
    std::fflush(stderr);
}

}  // namespace lumen::cli
