// Base64 (RFC 4648, with padding) for the data: URIs of the glTF files tests write.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace vkp::test {

inline std::string base64(const std::vector<uint8_t>& bytes) {
    static const char* kTable = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        uint32_t v = bytes[i] << 16;
        if (i + 1 < bytes.size()) v |= bytes[i + 1] << 8;
        if (i + 2 < bytes.size()) v |= bytes[i + 2];
        out += kTable[(v >> 18) & 63];
        out += kTable[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? kTable[(v >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kTable[v & 63] : '=';
    }
    return out;
}

}  // namespace vkp::test
