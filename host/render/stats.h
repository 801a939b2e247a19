// Named statistics a render emits: the driver (timings, counters, device, scene) and the
// integrator (photon counts, its resolved settings) each set the values they own under dotted
// keys ("photons.globalStored"), and writers walk them (toJson nests the dots) without a field
// list of their own. Warnings and notes for the user travel with them.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace vkp {

class Stats {
public:
    using Value = std::variant<bool, int64_t, uint64_t, double, std::string>;

    // Sets (or replaces) a value; integers are kept as 64-bit, floats as double.
    template <typename T> void set(const std::string& key, const T& value) { store(key, toValue(value)); }
    void set(const std::string& key, const Value& value) { store(key, value); }
    // Sets every value of `other` and appends its warnings and notes.
    void merge(const Stats& other);
    // Adds to a numeric value (0 when absent): counters and seconds summed over passes.
    void add(const std::string& key, uint64_t amount);
    void add(const std::string& key, double amount);

    bool has(const std::string& key) const { return m_index.count(key) > 0; }
    // The value as T (numbers convert between kinds); throws std::out_of_range when absent and
    // std::invalid_argument when a number is asked of a string or the reverse.
    template <typename T> T get(const std::string& key) const;
    // The value as T, or `fallback` when absent.
    template <typename T> T getOr(const std::string& key, T fallback) const {
        return has(key) ? get<T>(key) : fallback;
    }

    // Something the user should know about the result (printed even with --quiet).
    void warn(std::string message) { m_warnings.push_back(std::move(message)); }
    // A line of summary for the user (printed unless --quiet).
    void note(std::string message) { m_notes.push_back(std::move(message)); }
    const std::vector<std::string>& warnings() const { return m_warnings; }
    const std::vector<std::string>& notes() const { return m_notes; }

    // In the order they were first set.
    const std::vector<std::pair<std::string, Value>>& entries() const { return m_entries; }

    // Every value, dotted keys nested as objects ({"photons": {"globalStored": 10}}), and the
    // warnings as "warnings" when there are any.
    nlohmann::json toJson() const;

private:
    template <typename T> static Value toValue(const T& value) {
        if constexpr (std::is_same_v<T, bool>) return value;
        else if constexpr (std::is_integral_v<T> && std::is_signed_v<T>) return int64_t(value);
        else if constexpr (std::is_integral_v<T>) return uint64_t(value);
        else if constexpr (std::is_floating_point_v<T>) return double(value);
        else return std::string(value);
    }
    void store(const std::string& key, Value value);
    const Value& find(const std::string& key) const;
    static double number(const Value& value, const std::string& key);

    std::vector<std::pair<std::string, Value>> m_entries;
    std::map<std::string, size_t> m_index;
    std::vector<std::string> m_warnings;
    std::vector<std::string> m_notes;
};

template <typename T> T Stats::get(const std::string& key) const {
    const Value& value = find(key);
    if constexpr (std::is_same_v<T, std::string>) {
        if (const auto* s = std::get_if<std::string>(&value)) return *s;
        throw std::invalid_argument("stats: " + key + " is not a string");
    } else if constexpr (std::is_same_v<T, bool>) {
        if (const auto* b = std::get_if<bool>(&value)) return *b;
        return number(value, key) != 0.0;
    } else {
        if (const auto* u = std::get_if<uint64_t>(&value)) return static_cast<T>(*u);
        if (const auto* i = std::get_if<int64_t>(&value)) return static_cast<T>(*i);
        return static_cast<T>(number(value, key));
    }
}

}  // namespace vkp
