#include "animation/frame_sequence.h"

#include <charconv>

#include <fmt/format.h>

#include "util/errors.h"

namespace vkp {
namespace {

bool parseUint(const std::string& text, uint32_t& out) {
    if (text.empty()) return false;
    const char* end = text.data() + text.size();
    const auto [ptr, ec] = std::from_chars(text.data(), end, out);
    return ec == std::errc() && ptr == end;
}

}  // namespace

FrameRange parseFrameRange(const std::string& text) {
    FrameRange range;
    const size_t colon = text.find(':');
    const bool ok = colon == std::string::npos
        ? parseUint(text, range.first) && (range.last = range.first, true)
        : parseUint(text.substr(0, colon), range.first) && parseUint(text.substr(colon + 1), range.last);
    if (!ok) throw InputError(fmt::format("--frames {}: expected FIRST:LAST (non-negative integers) or N", text));
    if (range.last < range.first) throw InputError(fmt::format("--frames {}: LAST is before FIRST", text));
    if (range.last - range.first >= kMaxFrames)
        throw InputError(fmt::format("--frames {}: more than {} frames", text, kMaxFrames));
    return range;
}

double frameTime(uint32_t frame, double fps) { return double(frame) / fps; }

bool hasFramePattern(const std::filesystem::path& pattern) {
    return pattern.filename().string().find('#') != std::string::npos;
}

std::filesystem::path frameOutputPath(const std::filesystem::path& pattern, uint32_t frame) {
    const std::string name = pattern.filename().string();
    std::string out;
    for (size_t i = 0; i < name.size();) {
        if (name[i] != '#') {
            out += name[i++];
            continue;
        }
        size_t run = 0;
        while (i + run < name.size() && name[i + run] == '#') ++run;
        out += fmt::format("{:0{}}", frame, run);
        i += run;
    }
    return pattern.parent_path() / out;
}

}  // namespace vkp
