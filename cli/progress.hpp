// Render progress on stderr: a bar with an ETA when stderr is a terminal, nothing otherwise
// (the caller then prints one summary line).
#pragma once
#include <chrono>
#include <string>

namespace lumen::cli {

class ProgressBar {
public:
    explicit ProgressBar(bool enabled, std::string label = {});
    // Fraction done in [0,1]; redraws at most ~10 times a second. Not thread-safe: the
    // renderer serialises its progress callbacks.
    void update(double fraction);
    // Clears the bar line.
    void finish();

private:
    bool enabled_;
    std::string label_;
    std::chrono::steady_clock::time_point start_, last_draw_;
    bool drawn_ = false;
};

// "1.5 s", "2 min 03 s"
std::string format_duration(double seconds);

}  // namespace lumen::cli
