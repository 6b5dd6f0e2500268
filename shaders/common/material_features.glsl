// Which per-vertex material inputs a build needs (render/scene_program.hpp's variants): any
// texture or COLOR_0 brings the MaterialVarying block (common/scene.vert.glsl writes it, a
// geometry stage passes it on, common/material.glsl reads it); a normal texture adds the tangent.
#ifndef STRATA_MATERIAL_FEATURES_GLSL
#define STRATA_MATERIAL_FEATURES_GLSL
#if defined(STRATA_BASE_COLOR_TEXTURE) || defined(STRATA_VERTEX_COLOR) || defined(STRATA_METALLIC_ROUGHNESS_TEXTURE) || defined(STRATA_NORMAL_TEXTURE) || defined(STRATA_OCCLUSION_TEXTURE) || defined(STRATA_EMISSIVE_TEXTURE)
#define STRATA_MATERIAL_VARYING
#endif
#endif
