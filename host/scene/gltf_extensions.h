// The glTF extensions vkphoton knows, and whether it reads or ignores each: one table for the
// loader's extensionsRequired check, `vkphoton info`, and docs/scene-format.md (a test keeps
// the documentation's table equal to this one).
#pragma once

#include <span>
#include <string_view>

namespace vkp {

enum class ExtensionSupport {
    Read,     // the loader reads it (a file may require it)
    Ignored,  // known, not read: the scene renders without it (a file requiring it is refused)
};

struct GltfExtension {
    std::string_view name;
    ExtensionSupport support;
    std::string_view note;  // what is read, or what is lost by ignoring it
};

std::span<const GltfExtension> knownGltfExtensions();
// The table's entry for `name`, or nullptr for an extension vkphoton does not know (ignored).
const GltfExtension* findGltfExtension(std::string_view name);
// True when the loader reads `name`: only those may appear in extensionsRequired.
bool gltfExtensionIsRead(std::string_view name);
std::string_view extensionSupportName(ExtensionSupport support);  // "read" or "ignored"

}  // namespace vkp
