#include "scene/gltf_schema.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <regex>
#include <string_view>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "util/errors.h"

namespace vkp::embedded {
extern const std::pair<std::string_view, std::string_view> gltf_schema_files[];  // cmake/EmbedFiles.cmake
}

namespace vkp {
namespace {

using Json = nlohmann::json;

// tinygltf keeps byte offsets, lengths and counts of accessors, buffer views and buffers in
// size_t; every other integer in an int.
constexpr int64_t kMaxWideInteger = int64_t(1) << 53;

// The KHR_lights_punctual schema files have trailing commas ("enum": [...], }), which strict
// JSON parsers refuse; drop a comma followed only by white space and a closing bracket.
std::string withoutTrailingCommas(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    bool inString = false, escaped = false;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (inString) {
            escaped = !escaped && c == '\\';
            if (c == '"' && !escaped) inString = false;
        } else if (c == '"') {
            inString = true;
        } else if (c == ',') {
            size_t next = i + 1;
            while (next < text.size() && std::isspace(static_cast<unsigned char>(text[next]))) ++next;
            if (next < text.size() && (text[next] == '}' || text[next] == ']')) continue;
        }
        out += c;
    }
    return out;
}

class SchemaSet {
public:
    SchemaSet() {
        for (const auto* file = embedded::gltf_schema_files; !file->first.empty(); ++file)
            m_schemas.emplace(std::string(file->first), Json::parse(withoutTrailingCommas(file->second)));
    }
    const Json* find(const std::string& id) const {
        const auto it = m_schemas.find(id);
        return it == m_schemas.end() ? nullptr : &it->second;
    }
    const Json& get(const std::string& id) const {
        if (const Json* schema = find(id)) return *schema;
        throw std::logic_error("glTF schema " + id + " is not embedded");
    }

private:
    std::map<std::string, Json, std::less<>> m_schemas;
};

const SchemaSet& schemas() {
    static const SchemaSet set;
    return set;
}

struct Problem {
    std::string element;
    std::string what;
};
using Result = std::optional<Problem>;

std::string shortText(const Json& value) {
    std::string text = value.dump();
    return text.size() > 40 ? text.substr(0, 37) + "..." : text;
}

std::string numberText(double value) { return fmt::format("{}", value); }

bool isIntegral(const Json& value) { return value.is_number_integer(); }

// A branch of an "anyOf" that only names a type: the schema's way of leaving an enumeration open
// for values a later version may add.
bool isOpenBranch(const Json& branch) {
    if (!branch.is_object()) return false;
    for (const auto& [key, value] : branch.items())
        if (key != "type" && key != "description") return false;
    return true;
}

bool isClosedBranch(const Json& branch) {
    return branch.is_object() && (branch.contains("const") || branch.contains("enum"));
}

std::string describeRequired(const Json& schema) {
    std::string text;
    const Json& keys = schema.at("required");
    for (size_t i = 0; i < keys.size(); ++i)
        text += fmt::format("{}\"{}\"", i == 0 ? "" : i + 1 == keys.size() ? " and " : ", ", keys[i].get<std::string>());
    return text;
}

// Words for a branch of "oneOf"/"not": the forms the glTF schemas use.
std::string describe(const Json& schema) {
    if (!schema.is_object()) return "the schema";
    if (schema.contains("required")) return describeRequired(schema);
    if (schema.contains("anyOf")) {
        std::string text;
        for (const Json& branch : schema.at("anyOf")) text += (text.empty() ? "" : " or ") + describe(branch);
        return text;
    }
    const bool hasMin = schema.contains("minimum"), hasMax = schema.contains("maximum");
    if (hasMin && hasMax && schema.at("minimum") == schema.at("maximum")) return shortText(schema.at("minimum"));
    if (hasMin && hasMax) return fmt::format("in [{}, {}]", shortText(schema.at("minimum")), shortText(schema.at("maximum")));
    if (hasMin) return fmt::format("at least {}", shortText(schema.at("minimum")));
    if (hasMax) return fmt::format("at most {}", shortText(schema.at("maximum")));
    return "the schema";
}

class Validator {
public:
    Result checkAgainst(const Json& value, const std::string& id) {
        const Json& schema = schemas().get(id);
        if (Result r = check(value, schema, id)) return r;
        return checkExtensions(value, id);
    }

private:
    std::string element() const {
        std::string text;
        for (const std::string& part : m_path) text += (text.empty() || part[0] == '[' ? "" : ".") + part;
        return text;
    }
    Problem problem(std::string what) const { return {element(), std::move(what)}; }

    struct Step {
        Step(std::vector<std::string>& path, std::string part) : m_path(path) { m_path.push_back(std::move(part)); }
        ~Step() { m_path.pop_back(); }
        std::vector<std::string>& m_path;
    };

    // The extension objects of `value` whose schema is embedded as "<type>.<extension>.schema.json"
    // (the naming of the Khronos repository): node.KHR_lights_punctual, material.KHR_materials_ior...
    Result checkExtensions(const Json& value, const std::string& id) {
        if (!value.is_object()) return {};
        const auto extensions = value.find("extensions");
        if (extensions == value.end() || !extensions->is_object()) return {};
        const std::string type = id.substr(0, id.find(".schema.json"));
        for (const auto& [name, extension] : extensions->items()) {
            const std::string extensionId = fmt::format("{}.{}.schema.json", type, name);
            if (!schemas().find(extensionId)) continue;
            Step a(m_path, "extensions"), b(m_path, name);
            if (Result r = checkAgainst(extension, extensionId)) return r;
        }
        return {};
    }

    // Integers: as written (tinygltf ignores 2.0 where it reads an int) and within what tinygltf
    // stores them in.
    Result checkInteger(const Json& value) {
        if (!isIntegral(value)) {
            if (value.is_number() && std::isfinite(value.get<double>()) && std::trunc(value.get<double>()) == value.get<double>())
                return problem(fmt::format("{} must be written as an integer (no fraction or exponent)", shortText(value)));
            return problem(fmt::format("{} is not an integer", shortText(value)));
        }
        const bool wide = m_path.size() == 3 &&
            ((m_path[0] == "accessors" && (m_path[2] == "byteOffset" || m_path[2] == "count")) ||
             (m_path[0] == "bufferViews" && (m_path[2] == "byteOffset" || m_path[2] == "byteLength" || m_path[2] == "byteStride")) ||
             (m_path[0] == "buffers" && m_path[2] == "byteLength"));
        const int64_t lowest = wide ? 0 : std::numeric_limits<int32_t>::min();
        const int64_t highest = wide ? kMaxWideInteger : std::numeric_limits<int32_t>::max();
        const bool fits = value.is_number_unsigned() ? value.get<uint64_t>() <= uint64_t(highest)
                                                     : value.get<int64_t>() >= lowest && value.get<int64_t>() <= highest;
        if (!fits) return problem(fmt::format("{} is out of range ({} to {})", shortText(value), lowest, highest));
        return {};
    }

    bool typeMatches(const Json& value, const std::string& type) const {
        if (type == "object") return value.is_object();
        if (type == "array") return value.is_array();
        if (type == "string") return value.is_string();
        if (type == "boolean") return value.is_boolean();
        if (type == "number") return value.is_number();
        if (type == "integer") return value.is_number();  // refined by checkInteger
        if (type == "null") return value.is_null();
        return true;
    }

    Result checkType(const Json& value, const Json& type) {
        std::vector<std::string> types;
        if (type.is_string()) types.push_back(type.get<std::string>());
        else if (type.is_array())
            for (const Json& t : type) types.push_back(t.get<std::string>());
        for (const std::string& t : types) {
            if (!typeMatches(value, t)) continue;
            if (t == "integer") return checkInteger(value);
            return {};
        }
        std::string names;
        for (const std::string& t : types) names += (names.empty() ? "" : " or ") + t;
        const bool vowel = !names.empty() && std::string_view("aeiou").find(names[0]) != std::string_view::npos;
        return problem(fmt::format("{} is not {} {}", shortText(value), vowel ? "an" : "a", names));
    }

    // Bounds hold in double (as written) and in float (as used): 1e-50 > 0, but not as a float.
    Result checkNumber(const Json& value, const Json& schema) {
        const double d = value.get<double>();
        if (!isIntegral(value) && !std::isfinite(static_cast<float>(d)))
            return problem(fmt::format("{} is beyond the range of a 32-bit float (about 3.4e38)", shortText(value)));
        const bool integral = isIntegral(value);
        const auto asUsed = [&](double x) { return integral ? x : double(static_cast<float>(x)); };
        const auto bound = [&](const char* key) -> std::optional<double> {
            const auto it = schema.find(key);
            if (it == schema.end() || !it->is_number()) return std::nullopt;
            return it->get<double>();
        };
        // draft-04 (the KHR_lights_punctual files): "exclusiveMinimum": true makes "minimum" exclusive.
        const auto flag = [&](const char* key) { return schema.contains(key) && schema.at(key).is_boolean() && schema.at(key).get<bool>(); };
        if (const auto min = bound("minimum")) {
            const bool exclusive = flag("exclusiveMinimum");
            for (const double x : {d, asUsed(d)})
                if (exclusive ? !(x > *min) : !(x >= *min))
                    return problem(fmt::format("{} {} {}", shortText(value), exclusive ? "must be greater than" : "is below the minimum",
                                               numberText(*min)));
        }
        if (const auto max = bound("maximum")) {
            const bool exclusive = flag("exclusiveMaximum");
            // Exporters write 1.0000001 for factors bounded by 1: a relative 1e-6 is let through
            // (the loader clamps it with a warning).
            const double slack = integral ? 0.0 : 1e-6 * std::max(1.0, std::abs(*max));
            for (const double x : {d, asUsed(d)})
                if (exclusive ? !(x < *max) : !(x <= *max + slack))
                    return problem(fmt::format("{} {} {}", shortText(value), exclusive ? "must be less than" : "is above the maximum",
                                               numberText(*max)));
        }
        if (const auto min = bound("exclusiveMinimum"))
            for (const double x : {d, asUsed(d)})
                if (!(x > *min))
                    return problem(fmt::format("{} must be greater than {}{}", shortText(value), numberText(*min),
                                               x == d ? "" : " (as a 32-bit float it is not)"));
        if (const auto max = bound("exclusiveMaximum"))
            for (const double x : {d, asUsed(d)})
                if (!(x < *max)) return problem(fmt::format("{} must be less than {}", shortText(value), numberText(*max)));
        if (const auto step = bound("multipleOf"); step && *step > 0.0 && std::fmod(d, *step) != 0.0)
            return problem(fmt::format("{} is not a multiple of {}", shortText(value), numberText(*step)));
        return {};
    }

    Result checkAnyOf(const Json& value, const Json& branches, const std::string& id) {
        size_t closed = 0, open = 0;
        for (const Json& branch : branches) {
            if (isClosedBranch(branch)) ++closed;
            else if (isOpenBranch(branch)) ++open;
        }
        // An enumeration: one of the listed values (animation paths stay open: extensions add some
        // and vkphoton does not read animations).
        const bool enumeration = closed > 0 && closed + open == branches.size() && id != "animation.channel.target.schema.json";
        std::optional<Problem> first;
        for (const Json& branch : branches) {
            if (enumeration && !isClosedBranch(branch)) continue;
            Result r = check(value, branch, id);
            if (!r) return {};
            if (!first) first = r;
        }
        if (!enumeration) return first;
        std::string allowed;
        for (const Json& branch : branches) {
            if (!isClosedBranch(branch)) continue;
            const Json& listed = branch.contains("const") ? Json::array({branch.at("const")}) : branch.at("enum");
            for (const Json& v : listed) {
                allowed += (allowed.empty() ? "" : ", ") + shortText(v);
                if (branch.contains("description") && branch.at("description").is_string() && v.is_number())
                    allowed += " (" + branch.at("description").get<std::string>() + ")";
            }
        }
        return problem(fmt::format("{} is not one of {}", shortText(value), allowed));
    }

    Result checkObject(const Json& value, const Json& schema, const std::string& id) {
        if (const auto it = schema.find("required"); it != schema.end())
            for (const Json& key : *it)
                if (!value.contains(key.get<std::string>())) return problem(fmt::format("\"{}\" is missing", key.get<std::string>()));
        if (const auto it = schema.find("dependencies"); it != schema.end())
            for (const auto& [key, needs] : it->items())
                if (value.contains(key) && needs.is_array())
                    for (const Json& need : needs)
                        if (!value.contains(need.get<std::string>()))
                            return problem(fmt::format("\"{}\" needs \"{}\"", key, need.get<std::string>()));
        if (const auto it = schema.find("minProperties"); it != schema.end() && value.size() < it->get<size_t>())
            return problem(fmt::format("needs at least {} propert{}", it->get<size_t>(), it->get<size_t>() == 1 ? "y" : "ies"));
        const auto properties = schema.find("properties");
        const auto additional = schema.find("additionalProperties");
        for (const auto& [key, member] : value.items()) {
            const Json* sub = nullptr;
            if (properties != schema.end() && properties->contains(key)) sub = &properties->at(key);
            else if (additional != schema.end()) {
                if (additional->is_boolean() && !additional->get<bool>()) return problem(fmt::format("unknown property \"{}\"", key));
                sub = &*additional;
            }
            if (!sub) continue;
            Step step(m_path, key);
            if (Result r = check(member, *sub, id)) return r;
        }
        return {};
    }

    Result checkArray(const Json& value, const Json& schema, const std::string& id) {
        if (const auto it = schema.find("minItems"); it != schema.end() && value.size() < it->get<size_t>())
            return problem(fmt::format("has {} item{}, needs at least {}", value.size(), value.size() == 1 ? "" : "s", it->get<size_t>()));
        if (const auto it = schema.find("maxItems"); it != schema.end() && value.size() > it->get<size_t>())
            return problem(fmt::format("has {} items, at most {} allowed", value.size(), it->get<size_t>()));
        if (const auto it = schema.find("items"); it != schema.end() && it->is_object())
            for (size_t i = 0; i < value.size(); ++i) {
                Step step(m_path, fmt::format("[{}]", i));
                if (Result r = check(value[i], *it, id)) return r;
            }
        if (const auto it = schema.find("uniqueItems"); it != schema.end() && it->get<bool>()) {
            std::vector<const Json*> seen;
            for (size_t i = 0; i < value.size(); ++i) {
                for (const Json* earlier : seen)
                    if (*earlier == value[i]) return problem(fmt::format("{} is listed twice", shortText(value[i])));
                if (seen.size() < 4096) seen.push_back(&value[i]);  // bounded: quadratic otherwise
            }
        }
        return {};
    }

    Result check(const Json& value, const Json& schema, const std::string& id) {
        if (!schema.is_object()) return {};
        if (const auto it = schema.find("$ref"); it != schema.end()) {
            const std::string ref = it->get<std::string>();
            if (Result r = checkAgainst(value, ref.substr(0, ref.find('#')))) return r;
        }
        if (const auto it = schema.find("allOf"); it != schema.end())
            for (const Json& sub : *it)
                if (Result r = check(value, sub, id)) return r;
        if (const auto it = schema.find("type"); it != schema.end())
            if (Result r = checkType(value, *it)) return r;
        if (const auto it = schema.find("const"); it != schema.end() && value != *it)
            return problem(fmt::format("{} is not {}", shortText(value), shortText(*it)));
        if (const auto it = schema.find("enum"); it != schema.end()) {
            bool listed = false;
            for (const Json& v : *it) listed = listed || v == value;
            if (!listed) return problem(fmt::format("{} is not one of {}", shortText(value), shortText(*it)));
        }
        if (const auto it = schema.find("anyOf"); it != schema.end())
            if (Result r = checkAnyOf(value, *it, id)) return r;
        if (const auto it = schema.find("oneOf"); it != schema.end()) {
            size_t matches = 0;
            std::string forms;
            for (const Json& branch : *it) {
                matches += check(value, branch, id) ? 0 : 1;
                forms += (forms.empty() ? "" : ", ") + describe(branch);
            }
            if (matches != 1) {
                const bool objects = value.is_object();
                return problem(objects ? fmt::format("needs exactly one of {}", forms)
                                       : fmt::format("{} must be exactly one of: {}", shortText(value), forms));
            }
        }
        if (const auto it = schema.find("not"); it != schema.end() && !check(value, *it, id))
            return problem(fmt::format("must not have {}", describe(*it)));
        if (value.is_number())
            if (Result r = checkNumber(value, schema)) return r;
        if (value.is_string()) {
            if (const auto it = schema.find("pattern"); it != schema.end()) {
                const std::string& text = value.get_ref<const std::string&>();
                if (text.size() > 256 || !std::regex_search(text, std::regex(it->get<std::string>(), std::regex::ECMAScript)))
                    return problem(fmt::format("{} does not have the form {}", shortText(value), it->get<std::string>()));
            }
        }
        if (value.is_object())
            if (Result r = checkObject(value, schema, id)) return r;
        if (value.is_array())
            if (Result r = checkArray(value, schema, id)) return r;
        return {};
    }

    std::vector<std::string> m_path;
};

}  // namespace

void validateGltfSchema(const nlohmann::json& root) {
    Validator validator;
    if (const Result r = validator.checkAgainst(root, "glTF.schema.json"))
        throw InputError(r->element.empty() ? r->what : r->element + ": " + r->what);
}

}  // namespace vkp
