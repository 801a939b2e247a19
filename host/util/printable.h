// Text that echoes input (file names, URIs, flag values, names from a scene) made safe for a
// terminal: control characters (C0, DEL, and C1 as UTF-8) become \xNN, so a scene cannot move
// the cursor, ring the bell or start an escape sequence in the user's terminal.
#pragma once

#include <string>
#include <string_view>

namespace vkp {

inline std::string printable(std::string_view text) {
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        // U+0080..U+009F, the C1 controls (CSI among them), are 0xc2 0x80..0x9f in UTF-8.
        const bool c1 = c == 0xc2 && i + 1 < text.size() && static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
                        static_cast<unsigned char>(text[i + 1]) <= 0x9f;
        if (c < 0x20 || c == 0x7f || c1) {
            const auto byte = c1 ? static_cast<unsigned char>(text[++i]) : c;
            out += "\\x";
            out += kHex[byte >> 4];
            out += kHex[byte & 15];
        } else {
            out += static_cast<char>(c);
        }
    }
    return out;
}

}  // namespace vkp
