// Plays an event script (view/event_script.h) against the view's state, one command after the
// other: a command runs once the one before it has finished (a change once its first image has
// been presented, `samples` once the image holds them and no refresh round is left, `seconds`
// once the time has passed). Changes come back as the ViewActions a mouse or key would make;
// screenshots go through a callback. No window or device: tests drive it with made-up states.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "util/stopwatch.h"
#include "view/event_script.h"
#include "view/view_input.h"

namespace vkp {

// What the view shows now, as far as a script waits for it.
struct ScriptState {
    bool changeShown = true;                // the last change's first image has been presented
    std::optional<uint32_t> shownSamples;   // samples per pixel of the image on screen (none yet)
    uint32_t targetSamples = 1;             // --spp: accumulation stops there
    bool refreshDue = false;                // photon groups still stale after a move
    Clock::time_point now = Clock::now();
};

class ScriptPlayer {
public:
    explicit ScriptPlayer(std::vector<ScriptEvent> events) : m_events(std::move(events)) {}

    // Runs the commands that can run in `state`, stopping after the first that makes a change
    // (its actions are returned: they must be applied and shown before the script goes on) or at
    // the first that waits. `screenshot(event)` writes the image on screen; `quit` is set by quit.
    std::vector<ViewAction> advance(const ScriptState& state, const std::function<void(const ScriptEvent&)>& screenshot,
                                    bool& quit);
    bool finished() const { return m_next >= m_events.size(); }
    // Whether the command waited on is `seconds` (the loop must not sleep past it).
    bool waitingForTime() const { return !finished() && m_events[m_next].command == ScriptCommand::Seconds; }

private:
    std::vector<ScriptEvent> m_events;
    size_t m_next = 0;
    std::optional<Clock::time_point> m_waitFrom;  // `seconds`: when its wait began
};

}  // namespace vkp
