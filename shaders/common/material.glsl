// A fragment's base colour and alpha as the glTF material defines them: factor x base colour
// texture x COLOR_0 (common/shading_model.h). Which parts exist is decided when the program is
// built, per material (render/scene_program.hpp, SceneProgram::variant): a factor-only material
// is drawn by a build with no texture fetch, no vertex colour and no branch.
//   STRATA_BASE_COLOR_TEXTURE  the material has a base colour texture (sRGB, decoded by the sampler)
//   STRATA_VERTEX_COLOR        the mesh has COLOR_0
//   STRATA_ALPHA_MASK          the material is MASK: common/scene_main.glsl discards below the cutoff
#ifndef STRATA_MATERIAL_GLSL
#define STRATA_MATERIAL_GLSL
#include "bindings.h"
#include "shading_model.h"

uniform vec3 uBaseColor;
uniform float uAlpha;
uniform float uAlphaCutoff;

#if defined(STRATA_BASE_COLOR_TEXTURE) || defined(STRATA_VERTEX_COLOR)
// Written by common/scene.vert.glsl (and passed on by a geometry stage under the same name).
in MaterialVarying {
    vec2 texCoord0;
    vec2 texCoord1;
    vec4 color;
} vMaterial;
#endif

#ifdef STRATA_BASE_COLOR_TEXTURE
layout(binding = BIND_BASE_COLOR_TEXTURE) uniform sampler2D uBaseColorTexture;
uniform mat3 uBaseColorTransform;  // KHR_texture_transform
uniform int uBaseColorTexCoord;    // which TEXCOORD set
#endif

vec4 materialBaseColor() {
    vec4 texel = vec4(1.0);
    vec4 vertexColor = vec4(1.0);
#ifdef STRATA_BASE_COLOR_TEXTURE
    vec2 uv = uBaseColorTexCoord == 0 ? vMaterial.texCoord0 : vMaterial.texCoord1;
    texel = texture(uBaseColorTexture, transformTexCoord(uBaseColorTransform, uv));
#endif
#ifdef STRATA_VERTEX_COLOR
    vertexColor = vMaterial.color;
#endif
    return combineBaseColor(vec4(uBaseColor, uAlpha), texel, vertexColor);
}

#endif
