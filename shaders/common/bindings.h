// Binding points every family may use; the families' own start above them so that one program
// can use both sets (ll uses the A-buffer's node pool and heads). Uniforms go by name.
#ifndef STRATA_COMMON_BINDINGS_H
#define STRATA_COMMON_BINDINGS_H
#include "common/host_device.h"

GPU_NAMESPACE_BEGIN

GPU_CONST uint BIND_COUNTERS = 0u;        // atomic counter buffer a pass reports through
GPU_CONST uint BIND_NODES = 1u;           // SSBO: the A-buffer's node pool (oit/abuffer_node.h)
GPU_CONST uint BIND_HEADS = 0u;           // image unit: per-pixel list heads (r32ui)
GPU_CONST uint BIND_OPAQUE_COLOR = 0u;    // texture unit
GPU_CONST uint BIND_OPAQUE_DEPTH = 1u;    // texture unit
GPU_CONST uint BIND_RESOLVE_OUTPUT = 3u;  // image unit: compute resolves write the output colour
GPU_CONST uint BIND_SOURCE = 0u;          // texture unit: the image a full-screen pass warps or presents
// Texture units of a layered impostor's atlas and its baked albedo (render/stand_in.hpp,
// common/scene_main.glsl); apart from every technique's units (dual-2p's scalar build reaches
// 19, the coplanarity variants' RGB builds use 26 .. 29 and 33 .. 36) so a stand-in draws
// inside any pass.
GPU_CONST uint BIND_IMPOSTOR_ATLAS = 20u;
GPU_CONST uint BIND_IMPOSTOR_ALBEDO = 30u;
// Texture units of a material's textures (common/material.glsl), above them too.
GPU_CONST uint BIND_BASE_COLOR_TEXTURE = 21u;
GPU_CONST uint BIND_METALLIC_ROUGHNESS_TEXTURE = 22u;
GPU_CONST uint BIND_NORMAL_TEXTURE = 23u;
GPU_CONST uint BIND_OCCLUSION_TEXTURE = 24u;
GPU_CONST uint BIND_EMISSIVE_TEXTURE = 25u;
// Uniform block binding of the scene's lights (common/lighting.glsl; GpuScene::setLightUniforms).
GPU_CONST uint BIND_LIGHTS = 0u;

// Vertex attribute locations of the scene vertex stage (common/scene.vert.glsl,
// render/gpu_scene.cpp). 2 is the stand-in's impostor coordinates (render/stand_in.hpp).
GPU_CONST uint ATTRIB_POSITION = 0u;
GPU_CONST uint ATTRIB_NORMAL = 1u;
GPU_CONST uint ATTRIB_TEXCOORD0 = 3u;
GPU_CONST uint ATTRIB_TEXCOORD1 = 4u;
GPU_CONST uint ATTRIB_COLOR = 5u;
GPU_CONST uint ATTRIB_TANGENT = 6u;

// Compute resolves run square groups of this many pixels a side; the host rounds the
// dispatch up to whole groups.
GPU_CONST uint RESOLVE_GROUP_SIZE = 8u;

GPU_NAMESPACE_END

#endif
