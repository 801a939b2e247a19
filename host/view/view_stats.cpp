#include "view/view_stats.h"

namespace vkp {

void ViewStats::change(const std::string& kind, Clock::time_point at, uint64_t photonPaths, uint64_t fullPhotonPaths,
                       double prepareSeconds) {
    ViewChange c;
    c.kind = kind;
    c.at = std::chrono::duration<double>(at - m_start).count();
    c.photonPathsTraced = photonPaths;
    c.fullPhotonPaths = fullPhotonPaths;
    c.prepareSeconds = prepareSeconds;
    m_changes.push_back(c);
    m_changeStart.push_back(at);
}

void ViewStats::refresh(uint64_t photonPaths) {
    if (m_changes.empty()) return;
    m_changes.back().refreshPhotonPaths += photonPaths;
    m_changes.back().refreshRounds += 1;
}

void ViewStats::presented(Clock::time_point now) {
    ++m_frames;
    if (!m_firstImage) m_firstImage = std::chrono::duration<double>(now - m_start).count();
    if (!m_changes.empty() && !m_changes.back().secondsToFirstImage)
        m_changes.back().secondsToFirstImage = std::chrono::duration<double>(now - m_changeStart.back()).count();
}

nlohmann::json ViewStats::toJson(Clock::time_point now) const {
    nlohmann::json changes = nlohmann::json::array();
    for (const ViewChange& c : m_changes)
        changes.push_back({{"kind", c.kind},
                           {"at", c.at},
                           {"secondsToFirstImage", c.secondsToFirstImage ? nlohmann::json(*c.secondsToFirstImage)
                                                                         : nlohmann::json(nullptr)},
                           {"photonPathsTraced", c.photonPathsTraced},
                           {"fullPhotonPaths", c.fullPhotonPaths},
                           {"refreshPhotonPaths", c.refreshPhotonPaths},
                           {"refreshRounds", c.refreshRounds},
                           {"prepareSeconds", c.prepareSeconds}});
    return {{"firstImageSeconds", m_firstImage ? nlohmann::json(*m_firstImage) : nlohmann::json(nullptr)},
            {"framesPresented", m_frames},
            {"seconds", std::chrono::duration<double>(now - m_start).count()},
            {"changes", changes}};
}

}  // namespace vkp
