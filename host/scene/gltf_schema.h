// Validates a glTF document against the Khronos glTF 2.0 JSON schema (third_party/gltf-schema,
// embedded at build time) and the schemas of the extensions vkphoton reads, before tinygltf sees
// it: tinygltf skips optional values of the wrong type and casts integers without range checks,
// so a value it would silently drop or wrap is refused here, naming the element.
//
// On top of the schema, in the precision the values are used in:
// - integers must be written as integers (tinygltf ignores 1.0 where it wants an integer) and
//   fit the 32-bit int tinygltf stores them in; byte offsets, lengths and counts of accessors,
//   buffer views and buffers may be up to 2^53;
// - numbers must be finite as 32-bit floats, and minimum/maximum bounds hold after the
//   conversion to float too (a yfov of 1e-50 is 0 as a float);
// - enumerations that the schema leaves open for future values ("anyOf" consts plus a bare type)
//   must be one of the listed values, as glTF-Validator reads them.
#pragma once

#include <string>

#include <nlohmann/json_fwd.hpp>

namespace vkp {

// Throws InputError("ELEMENT: problem") for the first value (in document order) the schema
// refuses, e.g. "accessors[0].byteOffset: -12 is below the minimum 0".
void validateGltfSchema(const nlohmann::json& root);

}  // namespace vkp
