// GLSL-only: the KHR_materials_* inputs of a material at a surface point (factor x texture), as
// docs/materials.md lists them. Included by scene_access.glsl after sampleMaterialTextures, which
// samples the textures (vec4(1) where there is none: factor x 1 is the factor).
#ifndef VKP_MATERIAL_EXTENSIONS_GLSL
#define VKP_MATERIAL_EXTENSIONS_GLSL

void materialExtensionsAt(GpuMaterial m, MaterialTexels texels, inout BsdfParams p) {
    p.specular = m.specular;
    p.specularColor = m.specularColor;
    p.specular *= texels.specular.a;
    p.specularColor *= texels.specularColor.rgb;
    p.sheenColor = m.sheenColor;
    p.sheenRoughness = m.sheenRoughness;
    p.sheenColor *= texels.sheenColor.rgb;
    p.sheenRoughness *= texels.sheenRoughness.a;
    p.clearcoat = m.clearcoat;
    p.clearcoatRoughness = m.clearcoatRoughness;
    p.clearcoat *= texels.clearcoat.r;
    p.clearcoatRoughness *= texels.clearcoatRoughness.g;
    p.specular = clamp(p.specular, 0.0f, 1.0f);
    p.clearcoat = clamp(p.clearcoat, 0.0f, 1.0f);
    p.clearcoatRoughness = clamp(p.clearcoatRoughness, 0.0f, 1.0f);
    p.sheenRoughness = clamp(p.sheenRoughness, 0.0f, 1.0f);
    // KHR_materials_anisotropy: the texture's B scales the strength (its RG direction is the
    // surface's, SurfaceHit.anisotropyDirection, put into the frame by applyAnisotropy).
    p.anisotropy = clamp(m.anisotropy * texels.anisotropy.b, 0.0f, 1.0f);
    // KHR_materials_iridescence: the factor times R; the thickness from minimum to maximum by G,
    // the maximum without a thickness texture.
    p.iridescence = clamp(m.iridescence * texels.iridescence.r, 0.0f, 1.0f);
    p.iridescenceIor = m.iridescenceIor;
    p.iridescenceThickness = m.iridescenceThicknessTexture >= 0
                                 ? mix(m.iridescenceThicknessMin, m.iridescenceThicknessMax, texels.iridescenceThickness.g)
                                 : m.iridescenceThicknessMax;
    if ((m.flags & kMaterialNoEnergyCompensation) != 0u) p.flags |= kBsdfNoEnergyCompensation;
}

#endif
