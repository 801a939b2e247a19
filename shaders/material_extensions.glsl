// GLSL-only: the KHR_materials_* inputs of a material at a surface point (factor x texture), as
// docs/materials.md lists them. Included by scene_access.glsl after sampleTexture.
#ifndef VKP_MATERIAL_EXTENSIONS_GLSL
#define VKP_MATERIAL_EXTENSIONS_GLSL

void materialExtensionsAt(GpuMaterial m, vec4 uv, inout BsdfParams p) {
    p.specular = m.specular;
    p.specularColor = m.specularColor;
    if (m.specularTexture >= 0) p.specular *= sampleTexture(m.specularTexture, uv).a;
    if (m.specularColorTexture >= 0) p.specularColor *= sampleTexture(m.specularColorTexture, uv).rgb;
    p.sheenColor = m.sheenColor;
    p.sheenRoughness = m.sheenRoughness;
    if (m.sheenColorTexture >= 0 && maxComponent(p.sheenColor) > 0.0f)
        p.sheenColor *= sampleTexture(m.sheenColorTexture, uv).rgb;
    if (m.sheenRoughnessTexture >= 0) p.sheenRoughness *= sampleTexture(m.sheenRoughnessTexture, uv).a;
    p.clearcoat = m.clearcoat;
    p.clearcoatRoughness = m.clearcoatRoughness;
    if (m.clearcoatTexture >= 0 && p.clearcoat > 0.0f) p.clearcoat *= sampleTexture(m.clearcoatTexture, uv).r;
    if (m.clearcoatRoughnessTexture >= 0) p.clearcoatRoughness *= sampleTexture(m.clearcoatRoughnessTexture, uv).g;
    p.specular = clamp(p.specular, 0.0f, 1.0f);
    p.clearcoat = clamp(p.clearcoat, 0.0f, 1.0f);
    p.clearcoatRoughness = clamp(p.clearcoatRoughness, 0.0f, 1.0f);
    p.sheenRoughness = clamp(p.sheenRoughness, 0.0f, 1.0f);
    if ((m.flags & kMaterialNoEnergyCompensation) != 0u) p.flags |= kBsdfNoEnergyCompensation;
}

#endif
