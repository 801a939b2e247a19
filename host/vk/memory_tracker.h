// Device memory a context has allocated (buffers, images, texture arrays): what is held now and
// the most held at once since the last resetPeak(). The stats JSON's `memory.peakBytes` and the
// `photons` command read it: the peak, not a sum of sizes, is what has to fit the device.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>

namespace vkp::vk {

class MemoryTracker {
public:
    void allocated(uint64_t bytes) {
        const uint64_t now = m_current.fetch_add(bytes) + bytes;
        uint64_t peak = m_peak.load();
        while (now > peak && !m_peak.compare_exchange_weak(peak, now)) {}
    }
    void freed(uint64_t bytes) { m_current.fetch_sub(bytes); }
    uint64_t current() const { return m_current.load(); }
    uint64_t peak() const { return m_peak.load(); }
    // The next peak starts from what is held now.
    void resetPeak() { m_peak.store(m_current.load()); }

private:
    std::atomic<uint64_t> m_current{0};
    std::atomic<uint64_t> m_peak{0};
};

}  // namespace vkp::vk
