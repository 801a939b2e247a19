#include "view/script_player.h"

#include <algorithm>

namespace vkp {

std::vector<ViewAction> ScriptPlayer::advance(const ScriptState& state,
                                              const std::function<void(const ScriptEvent&)>& screenshot, bool& quit) {
    std::vector<ViewAction> actions;
    while (!finished() && !quit && state.changeShown && actions.empty()) {
        const ScriptEvent& e = m_events[m_next];
        ViewAction a;
        switch (e.command) {
        case ScriptCommand::Samples:
            if (!state.shownSamples || *state.shownSamples < std::min(e.samples, state.targetSamples) || state.refreshDue)
                return actions;
            break;
        case ScriptCommand::Seconds:
            if (!m_waitFrom) m_waitFrom = state.now;
            if (std::chrono::duration<double>(state.now - *m_waitFrom).count() < e.seconds) return actions;
            m_waitFrom.reset();
            break;
        case ScriptCommand::Screenshot:
            if (!state.shownSamples) return actions;  // nothing on screen yet
            screenshot(e);
            break;
        case ScriptCommand::Move:
            a.kind = ViewAction::Kind::MoveNode;
            a.node = e.node;
            a.delta = e.delta;
            actions.push_back(a);
            break;
        case ScriptCommand::Orbit:
            a.kind = ViewAction::Kind::Orbit;
            a.a = e.from;
            actions.push_back(a);
            break;
        case ScriptCommand::Click:
            a.kind = ViewAction::Kind::Select;
            a.a = e.from;
            actions.push_back(a);
            break;
        case ScriptCommand::Drag: actions.push_back(dragAction(e.button, e.from, e.to)); break;
        case ScriptCommand::Key:
            a.kind = ViewAction::Kind::Key;
            a.key = e.key;
            actions.push_back(a);
            break;
        case ScriptCommand::Resize:
            a.kind = ViewAction::Kind::Resize;
            a.a = e.from;
            actions.push_back(a);
            break;
        case ScriptCommand::Quit: quit = true; break;
        }
        ++m_next;
    }
    return actions;
}

}  // namespace vkp
