// Progress on stderr: a redrawn bar with ETA on a terminal, plain periodic lines otherwise.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>

namespace vkp {

class ProgressReporter {
public:
    explicit ProgressReporter(std::string label, bool quiet = false);
    void update(uint64_t done, uint64_t total, double elapsedSeconds);
    void finish();

private:
    std::string m_label;
    bool m_quiet;
    bool m_terminal;
    bool m_drawn = false;
    std::chrono::steady_clock::time_point m_lastLine;
};

}  // namespace vkp
