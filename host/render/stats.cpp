#include "render/stats.h"

#include <stdexcept>

#include <nlohmann/json.hpp>

namespace vkp {

void Stats::store(const std::string& key, Value value) {
    const auto it = m_index.find(key);
    if (it != m_index.end()) {
        m_entries[it->second].second = std::move(value);
        return;
    }
    m_index.emplace(key, m_entries.size());
    m_entries.emplace_back(key, std::move(value));
}

const Stats::Value& Stats::find(const std::string& key) const {
    const auto it = m_index.find(key);
    if (it == m_index.end()) throw std::out_of_range("stats: no value " + key);
    return m_entries[it->second].second;
}

double Stats::number(const Value& value, const std::string& key) {
    if (const auto* d = std::get_if<double>(&value)) return *d;
    if (const auto* u = std::get_if<uint64_t>(&value)) return double(*u);
    if (const auto* i = std::get_if<int64_t>(&value)) return double(*i);
    if (const auto* b = std::get_if<bool>(&value)) return *b ? 1.0 : 0.0;
    throw std::invalid_argument("stats: " + key + " is not a number");
}

void Stats::add(const std::string& key, uint64_t amount) {
    if (!has(key)) {
        set(key, amount);
        return;
    }
    const Value& old = find(key);
    if (const auto* u = std::get_if<uint64_t>(&old)) set(key, *u + amount);
    else set(key, number(old, key) + double(amount));
}

void Stats::add(const std::string& key, double amount) {
    set(key, getOr<double>(key, 0.0) + amount);
}

void Stats::merge(const Stats& other) {
    for (const auto& [key, value] : other.m_entries) store(key, value);
    m_warnings.insert(m_warnings.end(), other.m_warnings.begin(), other.m_warnings.end());
    m_notes.insert(m_notes.end(), other.m_notes.begin(), other.m_notes.end());
}

nlohmann::json Stats::toJson() const {
    nlohmann::json root = nlohmann::json::object();
    for (const auto& [key, value] : m_entries) {
        nlohmann::json* node = &root;
        size_t begin = 0;
        for (size_t dot = key.find('.'); dot != std::string::npos; dot = key.find('.', begin)) {
            node = &(*node)[key.substr(begin, dot - begin)];
            begin = dot + 1;
        }
        std::visit([&](const auto& v) { (*node)[key.substr(begin)] = v; }, value);
    }
    if (!m_warnings.empty()) root["warnings"] = m_warnings;
    return root;
}

}  // namespace vkp
