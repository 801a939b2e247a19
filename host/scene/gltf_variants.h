// KHR_materials_variants: the file's named material variants (a shoe in three colours) and the
// material each primitive takes in one of them (docs/scene-format.md, "Materials").
#pragma once

#include <string>
#include <vector>

#include <tiny_gltf.h>

namespace vkp {

// The root extension's variant names, in order ("" for a variant without a name). InputError for
// a malformed list.
std::vector<std::string> materialVariantNames(const tinygltf::Model& model);

// The index of `name` among `names`; -1 for "" (no variant chosen). InputError naming --variant and
// the file's variants when it has no such variant.
int materialVariantIndex(const std::vector<std::string>& names, const std::string& name);

// The material `primitive` takes in variant `variant` (its mappings'), else its own material
// (also for variant -1). InputError for malformed mappings (`element` names the primitive).
int variantMaterial(const tinygltf::Primitive& primitive, int variant, size_t variantCount, const std::string& element);

// Every material a primitive's mappings name (for the instancing plan: an emissive variant keeps
// the mesh flattened, where emitters live).
std::vector<int> variantMaterials(const tinygltf::Primitive& primitive);

}  // namespace vkp
