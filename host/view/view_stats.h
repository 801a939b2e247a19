// What `vkphoton view --stats-json` reports (docs/viewer.md): when the first image was shown,
// and per change (a move, an orbit, ...) how long until an image showing it was presented, the
// photon paths it traced and what a full retrace of the maps would have traced.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "util/stopwatch.h"

namespace vkp {

struct ViewChange {
    std::string kind;                           // "move", "orbit", "pan", "dolly", "integrator", "restart", "animation"
    double at = 0.0;                            // seconds since the start of the command
    std::optional<double> secondsToFirstImage;  // from the change to the first presented image showing it (a preview counts)
    std::optional<double> secondsToIntegratorImage;  // ... to the first image of the chosen integrator
    uint64_t photonPathsTraced = 0;             // by the change's own photon update, pilots included
    uint64_t fullPhotonPaths = 0;               // what a full retrace of the same maps traces
    uint64_t refreshPhotonPaths = 0;            // traced by the refresh rounds that followed it
    uint32_t refreshRounds = 0;
    double prepareSeconds = 0.0;                // the restart: scene update, photon maps, raster light
    bool sceneRebuilt = false;                  // the change could not move in place (a new GpuScene: full retrace)
};

class ViewStats {
public:
    explicit ViewStats(Clock::time_point start) : m_start(start) {}

    // A change applied at `at` (before its restart), with what the restart traced.
    void change(const std::string& kind, Clock::time_point at, uint64_t photonPaths, uint64_t fullPhotonPaths,
                double prepareSeconds, bool sceneRebuilt = false);
    // The last change's photon counts, known once its integrator was prepared (after a preview).
    void prepared(uint64_t photonPaths, uint64_t fullPhotonPaths, double prepareSeconds);
    // A refresh round after the last change traced `photonPaths`.
    void refresh(uint64_t photonPaths);
    // An image was presented at `now` (`preview`: the path-traced preview, not the integrator's):
    // the first image, and the first of the last change.
    void presented(Clock::time_point now, bool preview);
    // Whether the last change has been shown (true when there was none).
    bool lastChangeShown() const { return m_changes.empty() || m_changes.back().secondsToFirstImage.has_value(); }
    const std::vector<ViewChange>& changes() const { return m_changes; }
    std::optional<double> firstImageSeconds() const { return m_firstImage; }
    std::optional<double> firstIntegratorImageSeconds() const { return m_firstIntegratorImage; }
    uint64_t framesPresented() const { return m_frames; }
    // Images presented per second from the first of the integrator to the last (null before two).
    std::optional<double> presentedPerSecond() const;

    // {"firstImageSeconds", "firstIntegratorImageSeconds", "framesPresented", "presentedPerSecond", "seconds", "changes":
    // [{kind, secondsToFirstImage, secondsToIntegratorImage, photonPathsTraced, fullPhotonPaths,
    // refreshPhotonPaths, refreshRounds, prepareSeconds, at}]}
    nlohmann::json toJson(Clock::time_point now) const;

private:
    Clock::time_point m_start;
    std::optional<double> m_firstImage;
    std::optional<double> m_firstIntegratorImage;
    std::vector<ViewChange> m_changes;
    std::vector<Clock::time_point> m_changeStart;
    uint64_t m_frames = 0;
    uint64_t m_integratorFrames = 0;  // presented since the first image of the integrator
    Clock::time_point m_firstIntegratorPresent{}, m_lastPresent{};
};

}  // namespace vkp
