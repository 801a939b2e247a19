#include "view/event_script.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "render/frame.h"
#include "util/errors.h"
#include "util/printable.h"

namespace vkp {
namespace {

std::vector<std::string> splitWords(std::string_view line) {
    std::vector<std::string> words;
    std::istringstream in{std::string(line)};
    for (std::string word; in >> word;) words.push_back(word);
    return words;
}

double number(const std::string& word, const std::string& where, const char* what) {
    double value = 0.0;
    const char* end = word.data() + word.size();
    const auto [ptr, ec] = std::from_chars(word.data(), end, value);
    if (ec != std::errc() || ptr != end || !std::isfinite(value))
        throw InputError(fmt::format("{}: {} '{}' is not a finite number", where, what, printable(word)));
    return value;
}

void expectArgs(const std::vector<std::string>& words, size_t min, size_t max, const std::string& where,
                const char* usage) {
    const size_t args = words.size() - 1;
    if (args < min || args > max)
        throw InputError(fmt::format("{}: '{}' takes {}", where, words[0], usage));
}

}  // namespace

std::vector<ScriptEvent> parseEventScript(std::string_view text, const std::string& source) {
    std::vector<ScriptEvent> events;
    size_t lineNumber = 0;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t end = std::min(text.find('\n', start), text.size());
        std::string_view line = text.substr(start, end - start);
        start = end + 1;
        ++lineNumber;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        const std::vector<std::string> words = splitWords(line);
        if (words.empty() || words[0][0] == '#') {
            if (end == text.size()) break;
            continue;
        }
        ScriptEvent e;
        e.where = fmt::format("{}:{}", source, lineNumber);
        const std::string& command = words[0];
        if (command == "samples") {
            expectArgs(words, 1, 1, e.where, "one count: samples N");
            e.command = ScriptCommand::Samples;
            const double n = number(words[1], e.where, "the sample count");
            if (!(n >= 1.0 && n <= double(1u << 24) && n == std::floor(n)))
                throw InputError(fmt::format("{}: samples {}: a whole number from 1 to {}", e.where, words[1], 1u << 24));
            e.samples = uint32_t(n);
        } else if (command == "seconds") {
            expectArgs(words, 1, 1, e.where, "one duration: seconds S");
            e.command = ScriptCommand::Seconds;
            e.seconds = number(words[1], e.where, "the duration");
            if (!(e.seconds >= 0.0 && e.seconds <= 86400.0))
                throw InputError(fmt::format("{}: seconds {}: from 0 to 86400", e.where, words[1]));
        } else if (command == "screenshot") {
            expectArgs(words, 1, 1, e.where, "one path: screenshot PATH.exr|PATH.png");
            e.command = ScriptCommand::Screenshot;
            e.path = words[1];
            const std::string ext = e.path.extension().string();
            if (ext != ".exr" && ext != ".png")
                throw InputError(fmt::format("{}: screenshot {}: the path must end in .exr or .png", e.where,
                                             printable(words[1])));
        } else if (command == "move") {
            expectArgs(words, 4, 4, e.where, "a node and three numbers: move NODE DX DY DZ");
            e.command = ScriptCommand::Move;
            e.node = words[1];
            for (int k = 0; k < 3; ++k) e.delta[k] = number(words[2 + k], e.where, "the offset");
        } else if (command == "orbit") {
            expectArgs(words, 2, 2, e.where, "two angles in degrees: orbit DX DY");
            e.command = ScriptCommand::Orbit;
            e.from = {float(number(words[1], e.where, "the angle")), float(number(words[2], e.where, "the angle"))};
        } else if (command == "click") {
            expectArgs(words, 2, 2, e.where, "a pixel: click X Y");
            e.command = ScriptCommand::Click;
            e.from = {float(number(words[1], e.where, "x")), float(number(words[2], e.where, "y"))};
        } else if (command == "drag") {
            expectArgs(words, 4, 5, e.where, "two pixels and an optional button: drag X0 Y0 X1 Y1 [left|right|shift]");
            e.command = ScriptCommand::Drag;
            e.from = {float(number(words[1], e.where, "x0")), float(number(words[2], e.where, "y0"))};
            e.to = {float(number(words[3], e.where, "x1")), float(number(words[4], e.where, "y1"))};
            if (words.size() == 6) {
                const auto button = parseDragButton(words[5]);
                if (!button)
                    throw InputError(fmt::format("{}: drag: unknown button '{}' (left, right or shift)", e.where,
                                                 printable(words[5])));
                e.button = *button;
            }
        } else if (command == "key") {
            expectArgs(words, 1, 1, e.where, "one key name: key NAME");
            e.command = ScriptCommand::Key;
            const auto key = parseKeyName(words[1]);
            if (!key)
                throw InputError(fmt::format("{}: key: unknown key '{}' (i, r, s, space, h, q, escape)", e.where,
                                             printable(words[1])));
            e.key = *key;
        } else if (command == "resize") {
            expectArgs(words, 2, 2, e.where, "a width and a height in pixels: resize W H");
            e.command = ScriptCommand::Resize;
            for (int k = 0; k < 2; ++k) {
                const double n = number(words[1 + k], e.where, k == 0 ? "the width" : "the height");
                if (!(n >= 1.0 && n <= double(kMaxImageSide) && n == std::floor(n)))
                    throw InputError(fmt::format("{}: resize: {} must be a whole number from 1 to {}", e.where,
                                                 words[1 + k], kMaxImageSide));
                e.from[k] = float(n);
            }
        } else if (command == "quit") {
            expectArgs(words, 0, 0, e.where, "no arguments");
            e.command = ScriptCommand::Quit;
        } else {
            throw InputError(fmt::format("{}: unknown command '{}' (samples, seconds, screenshot, move, orbit, click, "
                                         "drag, key, resize, quit)",
                                         e.where, printable(command)));
        }
        events.push_back(std::move(e));
        if (end == text.size()) break;
    }
    return events;
}

std::vector<ScriptEvent> readEventScript(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(fmt::format("--events {}: cannot read the file", printable(file.string())));
    std::ostringstream text;
    text << in.rdbuf();
    return parseEventScript(text.str(), file.string());
}

}  // namespace vkp
