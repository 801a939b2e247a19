#include "app/progress.h"

#include <cstdio>
#include <string>

#include <fmt/format.h>
#include <unistd.h>

namespace vkp {
namespace {

std::string formatDuration(double seconds) {
    const auto s = static_cast<long>(seconds + 0.5);
    if (s >= 3600) return fmt::format("{}h{:02}m", s / 3600, (s / 60) % 60);
    if (s >= 60) return fmt::format("{}m{:02}s", s / 60, s % 60);
    return fmt::format("{}s", s);
}

// Plain (non-terminal) output prints at most one line per interval.
constexpr auto kPlainInterval = std::chrono::seconds(5);

}  // namespace

ProgressReporter::ProgressReporter(std::string label, bool quiet)
    : m_label(std::move(label)), m_quiet(quiet), m_terminal(isatty(STDERR_FILENO) != 0),
      m_lastLine(std::chrono::steady_clock::now()) {}

void ProgressReporter::update(uint64_t done, uint64_t total, double elapsed) {
    if (m_quiet || total == 0) return;
    const double fraction = static_cast<double>(done) / static_cast<double>(total);
    const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    if (m_terminal) {
        constexpr int kWidth = 30;
        const int filled = static_cast<int>(fraction * kWidth);
        fmt::print(stderr, "\r{} [{}{}] {}/{} {:3.0f}%  elapsed {}  ETA {}  ", m_label,
                   std::string(filled, '#'), std::string(kWidth - filled, '-'), done, total,
                   100.0 * fraction, formatDuration(elapsed), formatDuration(eta));
        m_drawn = true;
        return;
    }
    const auto now = std::chrono::steady_clock::now();
    if (now - m_lastLine < kPlainInterval && done < total) return;
    m_lastLine = now;
    fmt::print(stderr, "{}: {}/{} ({:.0f}%), elapsed {}, ETA {}\n", m_label, done, total,
               100.0 * fraction, formatDuration(elapsed), formatDuration(eta));
}

void ProgressReporter::finish() {
    if (m_drawn) fmt::print(stderr, "\n");
    m_drawn = false;
}

}  // namespace vkp
