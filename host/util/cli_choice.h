// Command-line helpers shared by every command and integrator that registers options.
#pragma once

#include <cctype>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

namespace vkp {

// A transform for an option whose value is one of `choices` (case-insensitive), with an error
// that lists them ("--integrator: 'nope' is not one of path, photon, guided").
template <typename T> CLI::Validator oneOf(const std::vector<std::pair<std::string, T>>& choices) {
    std::string names;
    for (const auto& [name, value] : choices) names += (names.empty() ? "" : ", ") + name;
    return CLI::Validator(
        [choices, names](std::string& input) -> std::string {
            std::string lower = input;
            for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            for (const auto& [name, value] : choices)
                if (name == lower) {
                    input = std::to_string(static_cast<int>(value));
                    return {};
                }
            return "'" + input + "' is not one of " + names;
        },
        "");
}

// "a|b|c [default]" for an option's help line.
template <typename T> std::string choiceText(const std::vector<std::pair<std::string, T>>& choices, T current) {
    std::string text;
    std::string fallback;
    for (const auto& [name, value] : choices) {
        text += (text.empty() ? "" : "|") + name;
        if (value == current) fallback = name;
    }
    return text + " [" + fallback + "]";
}

}  // namespace vkp
