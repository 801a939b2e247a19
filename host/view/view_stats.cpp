#include "view/view_stats.h"

namespace vkp {

void ViewStats::change(const std::string& kind, Clock::time_point at, uint64_t photonPaths, uint64_t fullPhotonPaths,
                       double prepareSeconds, bool sceneRebuilt) {
    ViewChange c;
    c.kind = kind;
    c.at = std::chrono::duration<double>(at - m_start).count();
    c.photonPathsTraced = photonPaths;
    c.fullPhotonPaths = fullPhotonPaths;
    c.prepareSeconds = prepareSeconds;
    c.sceneRebuilt = sceneRebuilt;
    m_changes.push_back(c);
    m_changeStart.push_back(at);
}

void ViewStats::prepared(uint64_t photonPaths, uint64_t fullPhotonPaths, double prepareSeconds) {
    if (m_changes.empty()) return;
    m_changes.back().photonPathsTraced = photonPaths;
    m_changes.back().fullPhotonPaths = fullPhotonPaths;
    m_changes.back().prepareSeconds = prepareSeconds;
}

void ViewStats::refresh(uint64_t photonPaths) {
    if (m_changes.empty()) return;
    m_changes.back().refreshPhotonPaths += photonPaths;
    m_changes.back().refreshRounds += 1;
}

void ViewStats::presented(Clock::time_point now, bool preview) {
    ++m_frames;
    const double sinceStart = std::chrono::duration<double>(now - m_start).count();
    if (!m_firstImage) m_firstImage = sinceStart;
    if (!preview && !m_firstIntegratorImage) {
        m_firstIntegratorImage = sinceStart;
        m_firstIntegratorPresent = now;
    }
    if (m_firstIntegratorImage) ++m_integratorFrames;
    m_lastPresent = now;
    if (m_changes.empty()) return;
    const double sinceChange = std::chrono::duration<double>(now - m_changeStart.back()).count();
    if (!m_changes.back().secondsToFirstImage) m_changes.back().secondsToFirstImage = sinceChange;
    if (!preview && !m_changes.back().secondsToIntegratorImage) m_changes.back().secondsToIntegratorImage = sinceChange;
}

std::optional<double> ViewStats::presentedPerSecond() const {
    const double span = std::chrono::duration<double>(m_lastPresent - m_firstIntegratorPresent).count();
    if (m_integratorFrames < 2 || !(span > 0.0)) return std::nullopt;
    return double(m_integratorFrames - 1) / span;
}

nlohmann::json ViewStats::toJson(Clock::time_point now) const {
    const auto orNull = [](const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(nullptr); };
    nlohmann::json changes = nlohmann::json::array();
    for (const ViewChange& c : m_changes)
        changes.push_back({{"kind", c.kind},
                           {"at", c.at},
                           {"secondsToFirstImage", orNull(c.secondsToFirstImage)},
                           {"secondsToIntegratorImage", orNull(c.secondsToIntegratorImage)},
                           {"photonPathsTraced", c.photonPathsTraced},
                           {"fullPhotonPaths", c.fullPhotonPaths},
                           {"refreshPhotonPaths", c.refreshPhotonPaths},
                           {"refreshRounds", c.refreshRounds},
                           {"prepareSeconds", c.prepareSeconds},
                           {"sceneRebuilt", c.sceneRebuilt}});
    return {{"firstImageSeconds", orNull(m_firstImage)},
            {"firstIntegratorImageSeconds", orNull(m_firstIntegratorImage)},
            {"framesPresented", m_frames},
            {"presentedPerSecond", orNull(presentedPerSecond())},
            {"seconds", std::chrono::duration<double>(now - m_start).count()},
            {"changes", changes}};
}

}  // namespace vkp
