// The host and the shaders read the same headers (shaders/**/*.h, common/host_device.h); these
// tests check that both compilers make the same thing of them: struct offsets, field types and
// strides against GLSL std430, binding points against what the linked programs report, and
// compute group sizes against the host's dispatch arithmetic. A header edited for one side only
// (an #ifdef __cplusplus, a literal binding in a shader) fails here, not as a wrong image.
#include "gl_test_support.hpp"

#include "common/bindings.h"
#include "common/object_records.h"
#include "debug/error_map.h"
#include "lod/lod_bindings.h"
#include "gl/shader_program.hpp"
#include "render/scene_program.hpp"
#include "oit/abuffer_node.h"
#include "oit/approximate/approximate_bindings.h"
#include "oit/buffers/buffer_bindings.h"
#include "oit/coplanarity_bindings.h"
#include "oit/buffers/prefix_sum.hpp"
#include "oit/peeling/layer_bindings.h"
#include "oit/peeling/peel_bindings.h"
#include "oit/screendoor/screendoor_bindings.h"
#include "oit/volume/volume_bindings.h"

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include <unistd.h>

using namespace strata;
namespace fs = std::filesystem;

namespace {

// A compute program from source text whose #includes resolve in the real shader tree.
gl::Program buildCompute(const std::string& source) {
    const fs::path dir = fs::temp_directory_path() / ("strata-probe-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "probe.comp.glsl") << source;
    const gl::PreprocessedSource pre = gl::preprocessShader(dir / "probe.comp.glsl", {}, gl::shaderRoot());
    fs::remove_all(dir);
    const char* text = pre.text.c_str();
    gl::Program program(glCreateShaderProgramv(GL_COMPUTE_SHADER, 1, &text));
    GLint ok = 0, length = 0;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &length);
    std::string log(std::size_t(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program.id(), length, nullptr, log.data());
    INFO(gl::mapShaderLog(log.c_str(), pre.files));
    REQUIRE(ok);
    return program;
}

std::string resourceName(GLuint program, GLenum interface, GLuint index) {
    GLint length = 0;
    const GLenum prop = GL_NAME_LENGTH;
    glGetProgramResourceiv(program, interface, index, 1, &prop, 1, nullptr, &length);
    std::string name(std::size_t(std::max(length, 1)), '\0');
    glGetProgramResourceName(program, interface, index, length, nullptr, name.data());
    return name.c_str();
}

template <std::size_t N>
std::array<GLint, N> resourceProps(GLuint program, GLenum interface, GLuint index, const std::array<GLenum, N>& props) {
    std::array<GLint, N> values{};
    glGetProgramResourceiv(program, interface, index, GLsizei(N), props.data(), GLsizei(N), nullptr, values.data());
    return values;
}

// ---- struct layouts ----

// The GLSL type a C++ field of a shared struct must be; anything else does not compile.
template <class T>
constexpr GLenum glslType() {
    if constexpr (std::is_same_v<T, gpu::uint>) return GL_UNSIGNED_INT;
    else if constexpr (std::is_same_v<T, int>) return GL_INT;
    else {
        static_assert(std::is_same_v<T, float>, "shared structs hold uint, int and float only");
        return GL_FLOAT;
    }
}

struct Field {
    std::string name;
    std::size_t offset;
    GLenum type;
};
#define FIELD(S, m) Field{#m, offsetof(S, m), glslType<decltype(S::m)>()}

struct Member {
    GLint offset, type, stride;
};

// The members of the struct array in storage block `block`, by field name ("nodes[0].next": next).
std::map<std::string, Member> blockMembers(GLuint program, const std::string& block) {
    const GLuint index = glGetProgramResourceIndex(program, GL_SHADER_STORAGE_BLOCK, block.c_str());
    REQUIRE(index != GL_INVALID_INDEX);
    const GLint count = resourceProps<1>(program, GL_SHADER_STORAGE_BLOCK, index, {GL_NUM_ACTIVE_VARIABLES})[0];
    std::vector<GLint> variables(std::size_t(std::max(count, 0)));
    const GLenum prop = GL_ACTIVE_VARIABLES;
    glGetProgramResourceiv(program, GL_SHADER_STORAGE_BLOCK, index, 1, &prop, count, nullptr, variables.data());
    std::map<std::string, Member> members;
    for (GLint v : variables) {
        const std::string name = resourceName(program, GL_BUFFER_VARIABLE, GLuint(v));
        const auto p = resourceProps<3>(program, GL_BUFFER_VARIABLE, GLuint(v),
                                        {GL_OFFSET, GL_TYPE, GL_TOP_LEVEL_ARRAY_STRIDE});
        members[name.substr(name.rfind('.') + 1)] = {p[0], p[1], p[2]};
    }
    return members;
}

template <class S>
void checkLayout(GLuint program, const std::string& block, const std::vector<Field>& fields) {
    const auto members = blockMembers(program, block);
    REQUIRE(!members.empty());
    {
        INFO(block, " array stride");
        CHECK(members.begin()->second.stride == GLint(sizeof(S)));
    }
    std::set<std::string> listed;
    for (const Field& f : fields) {
        INFO(block, " field ", f.name);
        listed.insert(f.name);
        const auto it = members.find(f.name);
        if (it == members.end()) {
            FAIL_CHECK("the GLSL block has no such field");
            continue;
        }
        CHECK(it->second.offset == GLint(f.offset));
        CHECK(it->second.type == GLint(f.type));
    }
    for (const auto& [name, member] : members) {
        INFO(block, " has field ", name, " that the C++ struct (or this test's list) lacks");
        CHECK(listed.count(name) == 1);
    }
}

// ---- binding points ----

enum class Unit { Texture, Image, Storage, Counters };

std::string unitName(Unit u) {
    switch (u) {
    case Unit::Texture: return "texture unit";
    case Unit::Image: return "image unit";
    case Unit::Storage: return "SSBO binding";
    case Unit::Counters: return "atomic counter binding";
    }
    return "?";
}

struct Binding {
    Unit unit;
    GLuint point;
};

bool isSampler(GLint type) {
    switch (type) {
    case GL_SAMPLER_2D: case GL_SAMPLER_2D_ARRAY: case GL_SAMPLER_3D: case GL_SAMPLER_CUBE:
    case GL_SAMPLER_2D_SHADOW: case GL_SAMPLER_2D_MULTISAMPLE: case GL_SAMPLER_2D_MULTISAMPLE_ARRAY:
    case GL_SAMPLER_BUFFER: case GL_INT_SAMPLER_BUFFER: case GL_UNSIGNED_INT_SAMPLER_BUFFER:
    case GL_INT_SAMPLER_2D: case GL_INT_SAMPLER_2D_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_2D: case GL_UNSIGNED_INT_SAMPLER_2D_ARRAY:
        return true;
    default: return false;
    }
}

bool isImage(GLint type) {
    switch (type) {
    case GL_IMAGE_2D: case GL_IMAGE_2D_ARRAY: case GL_IMAGE_3D: case GL_IMAGE_BUFFER:
    case GL_INT_IMAGE_2D: case GL_INT_IMAGE_2D_ARRAY:
    case GL_UNSIGNED_INT_IMAGE_2D: case GL_UNSIGNED_INT_IMAGE_2D_ARRAY: case GL_UNSIGNED_INT_IMAGE_BUFFER:
        return true;
    default: return false;
    }
}

// Every texture, image, storage block and atomic counter the linked program uses, by name.
std::map<std::string, Binding> reportedBindings(GLuint program) {
    std::map<std::string, Binding> out;
    GLint uniforms = 0;
    glGetProgramInterfaceiv(program, GL_UNIFORM, GL_ACTIVE_RESOURCES, &uniforms);
    for (GLuint i = 0; i < GLuint(uniforms); ++i) {
        const auto p = resourceProps<3>(program, GL_UNIFORM, i, {GL_TYPE, GL_LOCATION, GL_ATOMIC_COUNTER_BUFFER_INDEX});
        const std::string name = resourceName(program, GL_UNIFORM, i);
        if (p[0] == GL_UNSIGNED_INT_ATOMIC_COUNTER) {
            const GLint point = resourceProps<1>(program, GL_ATOMIC_COUNTER_BUFFER, GLuint(p[2]), {GL_BUFFER_BINDING})[0];
            out[name] = {Unit::Counters, GLuint(point)};
        } else if (isSampler(p[0]) || isImage(p[0])) {
            GLint unit = -1;
            glGetUniformiv(program, p[1], &unit);
            out[name] = {isSampler(p[0]) ? Unit::Texture : Unit::Image, GLuint(unit)};
        }
    }
    GLint blocks = 0;
    glGetProgramInterfaceiv(program, GL_SHADER_STORAGE_BLOCK, GL_ACTIVE_RESOURCES, &blocks);
    for (GLuint i = 0; i < GLuint(blocks); ++i) {
        const GLint point = resourceProps<1>(program, GL_SHADER_STORAGE_BLOCK, i, {GL_BUFFER_BINDING})[0];
        out[resourceName(program, GL_SHADER_STORAGE_BLOCK, i)] = {Unit::Storage, GLuint(point)};
    }
    return out;
}

struct ProgramCase {
    std::vector<std::string> stages;
    gl::Defines defines;
    std::map<std::string, Binding> expected;  // what the host binds for this program
};

Binding tex(gpu::uint point) { return {Unit::Texture, point}; }
Binding image(gpu::uint point) { return {Unit::Image, point}; }
Binding ssbo(gpu::uint point) { return {Unit::Storage, point}; }
const Binding kCounters{Unit::Counters, gpu::BIND_COUNTERS};

// Each program core/ builds, with the points its C++ binds before drawing with it.
std::vector<ProgramCase> programCases() {
    using namespace gpu;
    const std::string scene = "common/scene.vert.glsl", full = "common/fullscreen.vert.glsl";
    const std::map<std::string, Binding> tail = {{"uTailAccum", tex(BIND_TAIL_ACCUM)},
                                                 {"uTailReveal", tex(BIND_TAIL_REVEAL)}};
    auto with = [](std::map<std::string, Binding> a, const std::map<std::string, Binding>& b) {
        a.insert(b.begin(), b.end());
        return a;
    };
    const std::map<std::string, Binding> lists = {{"uHeads", image(BIND_HEADS)}, {"FragmentNodes", ssbo(BIND_NODES)}};
    const std::map<std::string, Binding> listResolve = with(lists, {{"uOpaqueColor", tex(BIND_OPAQUE_COLOR)}});
    const std::map<std::string, Binding> volumeResolve =
        with(listResolve, {{"uOpaqueDepth", tex(BIND_OPAQUE_DEPTH)},
                           {"uVolumeMedia", tex(BIND_VOLUME_MEDIA)},
                           {"VolumeStats", ssbo(BIND_VOLUME_STATS)}});
    const std::map<std::string, Binding> texelResolve = {{"uHeads", image(BIND_HEADS)},
                                                         {"uNodeTexels", tex(BIND_NODE_TEXELS)},
                                                         {"uOpaqueColor", tex(BIND_OPAQUE_COLOR)}};
    const std::map<std::string, Binding> texelVolumeResolve =
        with(texelResolve, {{"uOpaqueDepth", tex(BIND_OPAQUE_DEPTH)},
                            {"uVolumeMedia", tex(BIND_VOLUME_MEDIA)},
                            {"VolumeStats", ssbo(BIND_VOLUME_STATS)}});
    const std::map<std::string, Binding> arrayResolve = with(tail, {{"uOpaqueColor", tex(BIND_OPAQUE_COLOR)},
                                                                    {"FragmentEntries", ssbo(BIND_ENTRIES)}});
    const std::map<std::string, Binding> bucket = {{"uRange", tex(BIND_PEEL_PREVIOUS)},
                                                   {"uOpaqueDepth", tex(BIND_OPAQUE_DEPTH)}};
    const std::map<std::string, Binding> coplanarResolve = {
        {"uState", tex(BIND_COPLANAR_STATE)},         {"uCount", tex(BIND_COPLANAR_COUNT)},
        {"uMinColor", tex(BIND_COPLANAR_MIN_COLOR)},  {"uMaxColor", tex(BIND_COPLANAR_MAX_COLOR)},
        {"uLayer", tex(BIND_COPLANAR_LAYER)},         {"uAccum", tex(BIND_COPLANAR_ACCUM)}};
    // The first resolve of an iteration tallies pixels with two or more and with one, and
    // resolves only the latter: no id-max fragment or open id range to read.
    std::map<std::string, Binding> coplanarResolveFirst =
        with(coplanarResolve, {{"uCoplanarPixels", kCounters}, {"uSinglePixels", kCounters}});
    coplanarResolveFirst.erase("uMaxColor");
    coplanarResolveFirst.erase("uState");
    const GLuint back = BIND_COPLANAR_BACK_OFFSET;
    const std::map<std::string, Binding> coplanarDualResolve = {
        {"uFrontState", tex(BIND_COPLANAR_STATE)},        {"uBackState", tex(BIND_COPLANAR_STATE + back)},
        {"uFrontCount", tex(BIND_COPLANAR_COUNT)},        {"uBackCount", tex(BIND_COPLANAR_COUNT + back)},
        {"uFrontMin", tex(BIND_COPLANAR_MIN_COLOR)},      {"uBackMin", tex(BIND_COPLANAR_MIN_COLOR + back)},
        {"uFrontMax", tex(BIND_COPLANAR_MAX_COLOR)},      {"uBackMax", tex(BIND_COPLANAR_MAX_COLOR + back)},
        {"uFrontLayer", tex(BIND_COPLANAR_LAYER)},        {"uBackLayer", tex(BIND_COPLANAR_LAYER + back)},
        {"uFrontAccum", tex(BIND_COPLANAR_ACCUM)},        {"uBackAccum", tex(BIND_COPLANAR_ACCUM + back)}};
    // The STRATA_RGB_TRANSMITTANCE builds' second texels (coplanar_layer.glsl), per side.
    auto coplanarRgb = [](const std::string& prefix, GLuint offset) {
        return std::map<std::string, Binding>{{prefix + "MinOpacity", tex(BIND_COPLANAR_MIN_OPACITY + offset)},
                                              {prefix + "MaxOpacity", tex(BIND_COPLANAR_MAX_OPACITY + offset)},
                                              {prefix + "LayerPasses", tex(BIND_COPLANAR_LAYER_PASSES + offset)},
                                              {prefix + "AccumPasses", tex(BIND_COPLANAR_ACCUM_PASSES + offset)}};
    };
    std::map<std::string, Binding> dualResolveFront, dualResolveBack;
    for (const auto& [name, binding] : coplanarDualResolve) {
        const bool front = name.rfind("uFront", 0) == 0;
        // Each side's draw reads its own side, and the other side's count (the discard rule);
        // the back draw also the front state (the bound of what is left).
        if (front || name == "uBackCount") dualResolveFront.emplace(name, binding);
        if (!front || name == "uFrontCount" || name == "uFrontState") dualResolveBack.emplace(name, binding);
    }
    // The builds for an iteration where no side holds two or more read no id-max fragment and no
    // state (the RGB back draw still reads the front state, for the bound).
    auto onePerSide = [](std::map<std::string, Binding> b, bool keepFrontState = false) {
        for (const char* name : {"uFrontMax", "uBackMax", "uFrontMaxOpacity", "uBackMaxOpacity", "uBackState"})
            b.erase(name);
        if (!keepFrontState) b.erase("uFrontState");
        return b;
    };
    const std::map<std::string, Binding> layerAccum = {{"uAccum", tex(BIND_PEEL_ACCUM)},
                                                       {"uAccumPasses", tex(BIND_PEEL_ACCUM_FILTER)}};
    const std::map<std::string, Binding> layerBackAccum = {{"uBackAccum", tex(BIND_PEEL_BACK_ACCUM)},
                                                           {"uBackAccumPasses", tex(BIND_PEEL_BACK_ACCUM_FILTER)}};
    const std::map<std::string, Binding> layerPeel = {{"uOpaqueDepth", tex(BIND_OPAQUE_DEPTH)},
                                                      {"uPreviousLayer", tex(BIND_PEEL_PREVIOUS)},
                                                      {"uLayer", tex(BIND_PEEL_LAYER)},
                                                      {"uAnchor", tex(BIND_ANCHOR)}};
    const std::map<std::string, Binding> anchor = {{"uAnchor", tex(BIND_ANCHOR)}};
    // dual's blend: the layers and the next range, and the pass's counts (dual_peeling.cpp).
    const std::map<std::string, Binding> dualBlend = {
        {"uFront", tex(BIND_PEEL_LAYER)},  {"uBack", tex(BIND_PEEL_BACK)},     {"uNextRange", tex(BIND_PEEL_PREVIOUS)},
        {"uFrontLayers", kCounters},       {"uBackLayers", kCounters},         {"uInteriorLeft", kCounters}};
    const std::map<std::string, Binding> layerListCounters = {{"uFrontCount", kCounters}, {"uBackCount", kCounters}};
    const std::map<std::string, Binding> layerCounters = {{"uStored", kCounters}, {"uOverflowed", kCounters}};
    const std::map<std::string, Binding> fabLayer = {{"uCounts", image(BIND_PIXEL_COUNTS)},
                                                     {"FragmentEntries", ssbo(BIND_ENTRIES)}};
    const std::map<std::string, Binding> kbLayer = {{"FragmentEntries", ssbo(BIND_ENTRIES)}};
    return {
        // frame (core/render)
        {{scene, "common/opaque.frag.glsl"}, {}, {}},
        {{scene, "common/count_fragments.frag.glsl"}, {}, {{"uFragmentCount", kCounters}}},
        {{full, "frame/deflect.frag.glsl"}, {}, {{"uSource", tex(BIND_SOURCE)}, {"uOutside", kCounters}}},
        {{full, "frame/deflect.frag.glsl"}, {{"REPLICATE", ""}}, {{"uSource", tex(BIND_SOURCE)}}},
        {{full, "frame/present.frag.glsl"}, {}, {{"uLinearColor", tex(BIND_SOURCE)}}},
        {{scene, "oit/blend.frag.glsl"}, {}, {}},
        // screen-door family
        {{scene, "oit/screendoor/crow.frag.glsl"}, {}, {}},
        {{full, "oit/screendoor/supersample_fill.frag.glsl"}, {},
         {{"uOpaqueColor", tex(BIND_OPAQUE_COLOR)}, {"uOpaqueDepth", tex(BIND_OPAQUE_DEPTH)}}},
        {{full, "oit/screendoor/box_average.frag.glsl"}, {}, {{"uSource", tex(BIND_DOWNSAMPLE_SOURCE)}}},
        {{scene, "oit/screendoor/screendoor_image.frag.glsl"}, {}, {{"uAlphaMasks", tex(BIND_ALPHA_MASKS)}}},
        {{scene, "oit/screendoor/object_mask.geom.glsl", "oit/screendoor/screendoor_object.frag.glsl"}, {},
         {{"uAlphaMasks", tex(BIND_ALPHA_MASKS)}}},
        {{"oit/screendoor/point_samples.comp.glsl"}, {},
         {{"MeshVertices", ssbo(BIND_MESH_VERTICES)}, {"MeshIndices", ssbo(BIND_MESH_INDICES)},
          {"Points", ssbo(BIND_POINTS)}, {"uPointsWanted", kCounters}, {"uTrianglesBounded", kCounters},
          {"MeshAttributes", ssbo(BIND_MESH_ATTRIBUTES)}, {"uBaseColorTexture", tex(BIND_BASE_COLOR_TEXTURE)}}},
        {{"oit/screendoor/points.vert.glsl", "oit/screendoor/points.frag.glsl"}, {},
         {{"Points", ssbo(BIND_POINTS)}, {"ObjectColors", ssbo(BIND_OBJECT_COLORS)}}},
        // abuffer
        {{scene, "oit/abuffer_store.frag.glsl"}, {}, with(lists, {{"uNodeCount", kCounters}})},
        {{full, "oit/abuffer_resolve.frag.glsl"}, {}, listResolve},
        {{"oit/abuffer_resolve.comp.glsl"}, {}, with(listResolve, {{"uOutput", image(BIND_RESOLVE_OUTPUT)}})},
        // abuffer's own resolves read the pool through its buffer texture (oit/node_fetch.glsl).
        {{full, "oit/abuffer_resolve.frag.glsl"}, {{"NODE_TEXELS", ""}}, texelResolve},
        {{"oit/abuffer_resolve.comp.glsl"}, {{"NODE_TEXELS", ""}},
         with(texelResolve, {{"uOutput", image(BIND_RESOLVE_OUTPUT)}})},
        // approximate
        {{scene, "oit/approximate/floor.frag.glsl"}, {}, {}},
        {{scene, "oit/approximate/wboit_accumulate.frag.glsl"}, {}, {}},
        {{full, "oit/approximate/accumulation_composite.frag.glsl"}, {{"WEIGHTED_AVERAGE", ""}},
         {{"uOpaqueColor", tex(BIND_OPAQUE_COLOR)}, {"uAccum", tex(BIND_ACCUM)}, {"uTransmittance", tex(BIND_TRANSMITTANCE)}}},
        {{scene, "oit/approximate/stochastic_depth.frag.glsl"}, {}, {{"uSampleDepths", image(BIND_SAMPLE_DEPTHS)}}},
        {{scene, "oit/approximate/stochastic_accumulate.frag.glsl"}, {}, {{"uSampleDepths", image(BIND_SAMPLE_DEPTHS)}}},
        {{full, "oit/approximate/accumulation_composite.frag.glsl"}, {{"ALPHA_CORRECTED", ""}},
         {{"uOpaqueColor", tex(BIND_OPAQUE_COLOR)}, {"uAccum", tex(BIND_ACCUM)}, {"uTransmittance", tex(BIND_TRANSMITTANCE)}}},
        // peeling
        // A counting pass with no bindings (a query counts), then the first layer's program, with
        // no previous layer, and the later layers' (which reads the previous layer's depth).
        {{scene, "oit/peeling/f2b_count.frag.glsl"}, {}, {}},
        {{scene, "oit/peeling/f2b_peel.frag.glsl"}, {{"FIRST_LAYER", ""}},
         {{"uOpaqueDepth", tex(BIND_OPAQUE_DEPTH)}}},
        {{scene, "oit/peeling/f2b_peel.frag.glsl"}, {},
         {{"uOpaqueDepth", tex(BIND_OPAQUE_DEPTH)}, {"uPreviousDepth", tex(BIND_PEEL_PREVIOUS)}}},
        {{scene, "oit/peeling/f2b_peel.frag.glsl"}, {{"DEPTH_ONLY", ""}, {"FIRST_LAYER", ""}},
         {{"uOpaqueDepth", tex(BIND_OPAQUE_DEPTH)}}},
        {{scene, "oit/peeling/f2b_peel.frag.glsl"}, {{"DEPTH_ONLY", ""}},
         {{"uOpaqueDepth", tex(BIND_OPAQUE_DEPTH)}, {"uPreviousDepth", tex(BIND_PEEL_PREVIOUS)}}},
        {{scene, "oit/peeling/f2b2_shade.frag.glsl"}, {}, {}},
        {{full, "oit/peeling/f2b_layer_blend.frag.glsl"}, {},
         {{"uLayerDepth", tex(BIND_PEEL_PREVIOUS)}, {"uLayerColor", tex(BIND_PEEL_LAYER)}}},
        {{full, "oit/peeling/peel_composite.frag.glsl"}, {},
         {{"uOpaqueColor", tex(BIND_OPAQUE_COLOR)}, {"uAccum", tex(BIND_PEEL_ACCUM)}}},
        {{scene, "oit/peeling/dual_init.frag.glsl"}, {}, {}},
        {{scene, "oit/peeling/dual_peel.frag.glsl"}, {}, {{"uMinMax", tex(BIND_PEEL_PREVIOUS)}}},
        {{full, "oit/peeling/dual_blend.frag.glsl"}, {}, dualBlend},
        {{full, "oit/peeling/dual_blend.frag.glsl"}, {{"STRATA_RGB_TRANSMITTANCE", ""}},
         with(dualBlend, {{"uFrontFilter", tex(BIND_PEEL_LAYER_FILTER)}, {"uBackFilter", tex(BIND_PEEL_BACK_FILTER)},
                          {"uFrontAccumFilter", tex(BIND_PEEL_ACCUM_FILTER)}, {"uBackAccum", tex(BIND_PEEL_BACK_ACCUM)}})},
        {{full, "oit/peeling/peel_composite.frag.glsl"}, {{"DUAL", ""}},
         {{"uOpaqueColor", tex(BIND_OPAQUE_COLOR)}, {"uAccum", tex(BIND_PEEL_ACCUM)},
          {"uBackAccum", tex(BIND_PEEL_BACK_ACCUM)}}},
        {{scene, "oit/peeling/bun_range.frag.glsl"}, {}, {}},
        {{"oit/peeling/bounds.vert.glsl", "oit/peeling/bun_range.frag.glsl"}, {}, {}},
        {{scene, "oit/peeling/bun_capture.frag.glsl"}, {{"MAX_TARGETS", "8"}}, with(bucket, {{"uTotal", kCounters}})},
        {{scene, "oit/peeling/bun_color.frag.glsl"}, {{"COLOR_FORMAT", "rgba16f"}},
         with(bucket, {{"uBucketDepths", tex(BIND_PEEL_LAYER)}, {"uColors", image(BIND_BUCKET_COLORS)}})},
        {{full, "oit/peeling/bun_composite.frag.glsl"}, {},
         {{"uOpaqueColor", tex(BIND_OPAQUE_COLOR)}, {"uBucketDepths", tex(BIND_PEEL_LAYER)},
          {"uColors", tex(BIND_PEEL_ACCUM)}, {"uCaptured", kCounters}}},
        {{full, "oit/peeling/bound_reduce.frag.glsl"}, {}, {{"uRemaining", tex(BIND_PEEL_PREVIOUS)}}},
        {{full, "oit/peeling/bound_reduce.frag.glsl"}, {{"NEAR_BOUND_ONLY", ""}}, {{"uRemaining", tex(BIND_PEEL_PREVIOUS)}}},
        {{"oit/peeling/bounds_rect.vert.glsl", "oit/peeling/bounds_query.frag.glsl"}, {},
         {{"uReducedBound", tex(BIND_PEEL_PREVIOUS)}}},
        // coplanarity-aware peeling (f2b-2p, f2b-3p, dual-2p)
        {{scene, "oit/peeling/coplanar_init.frag.glsl"}, {}, {}},
        {{scene, "oit/peeling/coplanar_count.frag.glsl"}, {{"NEXT_ANCHOR", ""}, {"SUM_COLOR", ""}},
         {{"uState", tex(BIND_COPLANAR_STATE)}, {"CoplanarIdBase", ssbo(BIND_COPLANAR_ID_BASE)}}},
        // f2b-3p's: tested against the band's far edge in hardware, the opaque depth in the shader.
        {{scene, "oit/peeling/coplanar_count.frag.glsl"}, {{"BAND_DEPTH", ""}, {"SUM_COLOR", ""}},
         {{"uState", tex(BIND_COPLANAR_STATE)}, {"uOpaqueDepth", tex(BIND_OPAQUE_DEPTH)},
          {"CoplanarIdBase", ssbo(BIND_COPLANAR_ID_BASE)}}},
        {{scene, "oit/peeling/coplanar_count.frag.glsl"},
         {{"BAND_DEPTH", ""}, {"SUM_COLOR", ""}, {"STRATA_RGB_TRANSMITTANCE", ""}},
         {{"uState", tex(BIND_COPLANAR_STATE)}, {"uOpaqueDepth", tex(BIND_OPAQUE_DEPTH)},
          {"CoplanarIdBase", ssbo(BIND_COPLANAR_ID_BASE)}}},
        {{scene, "oit/peeling/coplanar_extract.frag.glsl"}, {},
         {{"uState", tex(BIND_COPLANAR_STATE)}, {"uCount", tex(BIND_COPLANAR_COUNT)},
          {"CoplanarIdBase", ssbo(BIND_COPLANAR_ID_BASE)}}},
        {{scene, "oit/peeling/coplanar_extract.frag.glsl"}, {{"BAND_DEPTH", ""}},
         {{"uState", tex(BIND_COPLANAR_STATE)}, {"uCount", tex(BIND_COPLANAR_COUNT)},
          {"uOpaqueDepth", tex(BIND_OPAQUE_DEPTH)}, {"CoplanarIdBase", ssbo(BIND_COPLANAR_ID_BASE)}}},
        {{full, "oit/peeling/coplanar_band.frag.glsl"}, {}, {{"uState", tex(BIND_COPLANAR_STATE)}}},
        {{scene, "oit/peeling/coplanar_next.frag.glsl"}, {},
         {{"uOpaqueDepth", tex(BIND_OPAQUE_DEPTH)}, {"uState", tex(BIND_COPLANAR_STATE)}}},
        {{full, "oit/peeling/coplanar_resolve.frag.glsl"}, {}, coplanarResolveFirst},
        {{full, "oit/peeling/coplanar_resolve.frag.glsl"}, {{"COPLANAR_PIXELS", ""}}, coplanarResolve},
        {{full, "oit/peeling/coplanar_resolve.frag.glsl"}, {{"NO_OPEN_LAYER", ""}},
         [&] {
             auto b = coplanarResolveFirst;
             b.erase("uLayer");
             return b;
         }()},
        // f2b-3p's builds: the next anchor from its depth pass, the band's far edge written out.
        {{full, "oit/peeling/coplanar_resolve.frag.glsl"}, {{"NEXT_FROM_DEPTH", ""}, {"BAND_OUT", ""}},
         with(coplanarResolveFirst, {{"uNextDepth", tex(BIND_COPLANAR_NEXT_DEPTH)}})},
        {{full, "oit/peeling/coplanar_resolve.frag.glsl"},
         {{"NEXT_FROM_DEPTH", ""}, {"BAND_OUT", ""}, {"COPLANAR_PIXELS", ""}},
         with(coplanarResolve, {{"uNextDepth", tex(BIND_COPLANAR_NEXT_DEPTH)}})},
        {{scene, "oit/peeling/coplanar_dual_count.frag.glsl"}, {},
         {{"uFrontState", tex(BIND_COPLANAR_STATE)}, {"uBackState", tex(BIND_COPLANAR_STATE + BIND_COPLANAR_BACK_OFFSET)},
          {"CoplanarIdBase", ssbo(BIND_COPLANAR_ID_BASE)}}},
        {{scene, "oit/peeling/coplanar_dual_extract.frag.glsl"}, {},
         {{"uFrontState", tex(BIND_COPLANAR_STATE)}, {"uBackState", tex(BIND_COPLANAR_STATE + BIND_COPLANAR_BACK_OFFSET)},
          {"uFrontCount", tex(BIND_COPLANAR_COUNT)}, {"uBackCount", tex(BIND_COPLANAR_COUNT + BIND_COPLANAR_BACK_OFFSET)},
          {"CoplanarIdBase", ssbo(BIND_COPLANAR_ID_BASE)}}},
        {{full, "oit/peeling/coplanar_dual_check.frag.glsl"}, {},
         {{"uFrontCount", tex(BIND_COPLANAR_COUNT)}, {"uBackCount", tex(BIND_COPLANAR_COUNT + BIND_COPLANAR_BACK_OFFSET)},
          {"uCoplanarSides", kCounters}, {"uCountedSides", kCounters}}},
        {{full, "oit/peeling/coplanar_dual_resolve.frag.glsl"}, {}, coplanarDualResolve},
        {{full, "oit/peeling/coplanar_dual_resolve.frag.glsl"}, {{"ONE_PER_SIDE", ""}}, onePerSide(coplanarDualResolve)},
        {{full, "oit/peeling/coplanar_dual_resolve.frag.glsl"}, {{"ONE_PER_SIDE", ""}, {"NO_OPEN_LAYER", ""}},
         [&] {
             auto b = onePerSide(coplanarDualResolve);
             b.erase("uFrontLayer");
             b.erase("uBackLayer");
             return b;
         }()},
        {{full, "oit/peeling/coplanar_resolve.frag.glsl"}, {{"STRATA_RGB_TRANSMITTANCE", ""}},
         [&] {
             auto b = with(coplanarResolveFirst, coplanarRgb("u", 0));
             b.erase("uMaxOpacity");
             return b;
         }()},
        {{full, "oit/peeling/coplanar_resolve.frag.glsl"}, {{"STRATA_RGB_TRANSMITTANCE", ""}, {"COPLANAR_PIXELS", ""}},
         with(coplanarResolve, coplanarRgb("u", 0))},
        {{full, "oit/peeling/coplanar_dual_resolve.frag.glsl"}, {{"STRATA_RGB_TRANSMITTANCE", ""}, {"RESOLVE_FRONT", ""}},
         with(dualResolveFront, coplanarRgb("uFront", 0))},
        {{full, "oit/peeling/coplanar_dual_resolve.frag.glsl"}, {{"STRATA_RGB_TRANSMITTANCE", ""}, {"RESOLVE_BACK", ""}},
         with(dualResolveBack, coplanarRgb("uBack", back))},
        {{full, "oit/peeling/coplanar_dual_resolve.frag.glsl"},
         {{"STRATA_RGB_TRANSMITTANCE", ""}, {"RESOLVE_FRONT", ""}, {"ONE_PER_SIDE", ""}},
         onePerSide(with(dualResolveFront, coplanarRgb("uFront", 0)))},
        {{full, "oit/peeling/coplanar_dual_resolve.frag.glsl"},
         {{"STRATA_RGB_TRANSMITTANCE", ""}, {"RESOLVE_BACK", ""}, {"ONE_PER_SIDE", ""}},
         onePerSide(with(dualResolveBack, coplanarRgb("uBack", back)), true)},
        {{full, "oit/peeling/coplanar_dual_resolve.frag.glsl"},
         {{"STRATA_RGB_TRANSMITTANCE", ""}, {"RESOLVE_BACK", ""}, {"ONE_PER_SIDE", ""}, {"NO_OPEN_LAYER", ""}},
         [&] {
             auto b = onePerSide(with(dualResolveBack, coplanarRgb("uBack", back)), true);
             b.erase("uBackLayer");
             b.erase("uBackLayerPasses");
             return b;
         }()},
        // buffers
        {{scene, "oit/buffers/fab_store.frag.glsl"}, {},
         {{"uCounts", image(BIND_PIXEL_COUNTS)}, {"FragmentEntries", ssbo(BIND_ENTRIES)},
          {"uStored", kCounters}, {"uOverflowed", kCounters}}},
        {{full, "oit/buffers/resolve_array.frag.glsl"}, {{"LAYOUT_FAB", ""}},
         with(arrayResolve, {{"uCounts", image(BIND_PIXEL_COUNTS)}})},
        {{scene, "oit/buffers/kbuffer_store.frag.glsl"}, {},
         {{"DepthKeys", ssbo(BIND_DEPTH_KEYS)}, {"FragmentEntries", ssbo(BIND_ENTRIES)},
          {"uInserted", kCounters}, {"uDropped", kCounters}}},
        {{full, "oit/buffers/resolve_array.frag.glsl"}, {{"LAYOUT_KBUFFER", ""}},
         with(arrayResolve, {{"DepthKeys", ssbo(BIND_DEPTH_KEYS)}})},
        {{scene, "oit/buffers/sbuffer_store.frag.glsl"}, {},
         {{"PixelOffsets", ssbo(BIND_PIXEL_OFFSETS)}, {"FragmentEntries", ssbo(BIND_ENTRIES)}, {"uDropped", kCounters}}},
        {{full, "oit/buffers/resolve_array.frag.glsl"}, {{"LAYOUT_SBUFFER", ""}},
         with(arrayResolve, {{"PixelOffsets", ssbo(BIND_PIXEL_OFFSETS)}})},
        {{scene, "oit/buffers/ll_store.frag.glsl"}, {}, with(lists, {{"uNodeCount", kCounters}})},
        {{full, "oit/abuffer_resolve.frag.glsl"}, {{"LIST_TAIL", ""}}, with(listResolve, tail)},
        // ll's resolve where its pool fits a buffer texture (BoundedBufferFrame::Shaders::nodeTexels)
        {{full, "oit/abuffer_resolve.frag.glsl"}, {{"LIST_TAIL", ""}, {"NODE_TEXELS", ""}}, with(texelResolve, tail)},
        {{"oit/buffers/prefix_scan.comp.glsl"}, {}, {{"Data", ssbo(BIND_SCAN_DATA)}, {"Sums", ssbo(BIND_SCAN_SUMS)}}},
        // volumetric (abuffer-volume, ll-volume): the lists' stores and resolves with VOLUME
        {{scene, "oit/abuffer_store.frag.glsl"}, {{"VOLUME", ""}}, with(lists, {{"uNodeCount", kCounters}})},
        {{scene, "oit/buffers/ll_store.frag.glsl"}, {{"VOLUME", ""}}, with(lists, {{"uNodeCount", kCounters}})},
        {{full, "oit/abuffer_resolve.frag.glsl"}, {{"VOLUME", ""}}, volumeResolve},
        {{full, "oit/abuffer_resolve.frag.glsl"}, {{"LIST_TAIL", ""}, {"VOLUME", ""}}, with(volumeResolve, tail)},
        {{"oit/abuffer_resolve.comp.glsl"}, {{"VOLUME", ""}}, with(volumeResolve, {{"uOutput", image(BIND_RESOLVE_OUTPUT)}})},
        {{full, "oit/abuffer_resolve.frag.glsl"}, {{"NODE_TEXELS", ""}, {"VOLUME", ""}}, texelVolumeResolve},
        {{full, "oit/abuffer_resolve.frag.glsl"}, {{"LIST_TAIL", ""}, {"NODE_TEXELS", ""}, {"VOLUME", ""}},
         with(texelVolumeResolve, tail)},
        {{"oit/buffers/prefix_add.comp.glsl"}, {}, {{"Data", ssbo(BIND_SCAN_DATA)}, {"Sums", ssbo(BIND_SCAN_SUMS)}}},
        // coplanarity-aware peeling with layer storage (f2b-ll, f2b-fab, f2b-kb, dual-ll, dual-fab)
        // and bun-ll; the capture and resolve programs per storage form (layer_storage.glsl)
        {{scene, "oit/peeling/next_layer.frag.glsl"}, {},
         {{"uOpaqueDepth", tex(BIND_OPAQUE_DEPTH)}, {"uTotal", kCounters}}},
        {{scene, "oit/peeling/layer_capture.frag.glsl"}, {{"LAYER_LIST", ""}},
         with(with(lists, layerPeel), {{"uFrontCount", kCounters}})},  // one side: no back counter
        {{scene, "oit/peeling/layer_capture.frag.glsl"}, {{"LAYER_FAB", ""}}, with(with(fabLayer, layerPeel), layerCounters)},
        {{scene, "oit/peeling/layer_capture.frag.glsl"}, {{"LAYER_KB", ""}}, with(with(kbLayer, layerPeel), layerCounters)},
        {{scene, "oit/peeling/layer_peel.frag.glsl"}, {},
         {{"uOpaqueDepth", tex(BIND_OPAQUE_DEPTH)}, {"uLayer", tex(BIND_PEEL_LAYER)}}},
        {{full, "oit/peeling/layer_band.frag.glsl"}, {}, {{"uLayer", tex(BIND_PEEL_LAYER)}}},
        {{scene, "oit/peeling/dual_layer_peel.frag.glsl"}, {{"LAYER_LIST", ""}},
         with(with(lists, layerListCounters), {{"uMinMax", tex(BIND_PEEL_PREVIOUS)}})},
        {{scene, "oit/peeling/dual_layer_peel.frag.glsl"}, {{"LAYER_FAB", ""}},
         with(with(fabLayer, layerCounters), {{"uMinMax", tex(BIND_PEEL_PREVIOUS)}})},
        {{full, "oit/peeling/layer_resolve.frag.glsl"}, {{"LAYER_LIST", ""}, {"ANCHOR", ""}}, with(lists, anchor)},
        {{full, "oit/peeling/layer_resolve.frag.glsl"}, {{"LAYER_FAB", ""}, {"ANCHOR", ""}}, with(fabLayer, anchor)},
        {{full, "oit/peeling/layer_resolve.frag.glsl"}, {{"LAYER_KB", ""}, {"ANCHOR", ""}}, with(kbLayer, anchor)},
        // A layer that stored nothing: the anchors alone, no storage declared or bound.
        {{full, "oit/peeling/layer_resolve.frag.glsl"}, {{"LAYER_LIST", ""}, {"ANCHOR", ""}, {"ANCHORS_ONLY", ""}}, anchor},
        {{full, "oit/peeling/layer_resolve.frag.glsl"}, {{"LAYER_KB", ""}, {"ANCHOR", ""}, {"ANCHORS_ONLY", ""}}, anchor},
        {{full, "oit/peeling/layer_resolve.frag.glsl"}, {{"LAYER_FAB", ""}, {"ANCHOR", ""}, {"ANCHORS_ONLY", ""}}, anchor},
        {{full, "oit/peeling/layer_resolve.frag.glsl"},
         {{"LAYER_LIST", ""}, {"ANCHOR", ""}, {"ANCHORS_ONLY", ""}, {"STRATA_RGB_TRANSMITTANCE", ""}},
         with(anchor, layerAccum)},
        {{full, "oit/peeling/layer_resolve.frag.glsl"},
         {{"LAYER_FAB", ""}, {"ANCHOR", ""}, {"ANCHORS_ONLY", ""}, {"STRATA_RGB_TRANSMITTANCE", ""}},
         with(anchor, layerAccum)},
        {{full, "oit/peeling/layer_resolve.frag.glsl"}, {{"LAYER_LIST", ""}, {"DUAL", ""}}, lists},
        {{full, "oit/peeling/layer_resolve.frag.glsl"}, {{"LAYER_FAB", ""}, {"DUAL", ""}}, fabLayer},
        {{full, "oit/peeling/layer_resolve.frag.glsl"}, {{"LAYER_LIST", ""}, {"ANCHOR", ""}, {"STRATA_RGB_TRANSMITTANCE", ""}},
         with(with(lists, anchor), layerAccum)},
        {{full, "oit/peeling/layer_resolve.frag.glsl"}, {{"LAYER_FAB", ""}, {"DUAL", ""}, {"STRATA_RGB_TRANSMITTANCE", ""}},
         with(with(fabLayer, layerAccum), layerBackAccum)},
        {{scene, "oit/peeling/bun_ll_store.frag.glsl"}, {}, with(with(bucket, lists), {{"uNodeCount", kCounters}})},
        {{full, "oit/peeling/bun_ll_resolve.frag.glsl"}, {{"MAX_BUCKETS", "32"}}, listResolve},
        // coplanarity detector: abuffer's store, then its own resolve
        {{"oit/coplanarity_detect.comp.glsl"}, {},
         with(lists, {{"uLargestLayer", image(BIND_LARGEST_LAYER)}, {"uHeatmap", image(BIND_RESOLVE_OUTPUT)},
                      {"CoplanarityTotals", ssbo(BIND_COPLANARITY_TOTALS)}})},
        // error view (render/error_map)
        {{"debug/error_map.comp.glsl"}, {},
         {{"uImage", tex(BIND_ERROR_IMAGE)}, {"uReference", tex(BIND_ERROR_REFERENCE)},
          {"uFalseColor", image(BIND_RESOLVE_OUTPUT)}, {"ErrorPartials", ssbo(BIND_ERROR_PARTIALS)}}},
        // layered impostors (lod/layered_impostor.cpp): the bake, its peels, the hole-filling id render
        {{"lod/bake.vert.glsl", "lod/bake.frag.glsl"}, {}, {}},
        {{"lod/bake.vert.glsl", "lod/bake.frag.glsl"}, {{"PEEL", ""}}, {{"uPreviousDepth", tex(BIND_BAKE_PREVIOUS_DEPTH)}}},
        {{"lod/slice_id.vert.glsl", "lod/slice_id.frag.glsl"}, {}, {{"uAtlas", tex(BIND_SLICE_ATLAS)}}},
        // lod cost calibration (lod/lod_cost_calibration.cpp)
        {{scene, "lod/calibrate_mesh.frag.glsl"}, {}, {}},
        // stand-in variants (render/scene_program.hpp): the opaque pass's and a list store's
        {{scene, "common/opaque.frag.glsl"}, {{"STRATA_IMPOSTOR", ""}}, {}},
        {{scene, "oit/buffers/ll_store.frag.glsl"}, {{"STRATA_IMPOSTOR", ""}}, with(lists, {{"uNodeCount", kCounters}})},
        {{scene, "oit/screendoor/object_mask.geom.glsl", "oit/screendoor/screendoor_object.frag.glsl"},
         {{"STRATA_IMPOSTOR", ""}}, {{"uAlphaMasks", tex(BIND_ALPHA_MASKS)}}},
    };
}

// "x y z" of a compute program's work group.
std::string workGroupSize(const std::string& stage) {
    gl::Program program = gl::buildProgram({stage});
    std::array<GLint, 3> size{};
    glGetProgramiv(program.id(), GL_COMPUTE_WORK_GROUP_SIZE, size.data());
    return std::to_string(size[0]) + " " + std::to_string(size[1]) + " " + std::to_string(size[2]);
}

}  // namespace

TEST_CASE("shared structs: C++ offsets, field types and sizes equal the GLSL std430 layout") {
    test::glContext();
    // The real storage blocks, every field read so that every member is active.
    gl::Program probe = buildCompute(R"(#version 450 core
#include "oit/abuffer_storage.glsl"
#include "oit/buffers/entry.glsl"
layout(local_size_x = 1) in;
void main() {
    nodes[0] = nodes[1];
    entries[0] = entries[1];
}
)");
    using gpu::FragmentEntry;
    using gpu::FragmentNode;
    checkLayout<FragmentNode>(probe.id(), "FragmentNodes",
                              {FIELD(FragmentNode, next), FIELD(FragmentNode, depth), FIELD(FragmentNode, objectId),
                               FIELD(FragmentNode, primitiveId), FIELD(FragmentNode, colorRG),
                               FIELD(FragmentNode, colorBA)});
    checkLayout<FragmentEntry>(probe.id(), "FragmentEntries",
                               {FIELD(FragmentEntry, depth), FIELD(FragmentEntry, objectId),
                                FIELD(FragmentEntry, primitiveId), FIELD(FragmentEntry, colorRG),
                                FIELD(FragmentEntry, colorBA)});
    gl::Program points = buildCompute(R"(#version 450 core
#include "oit/screendoor/screendoor_bindings.h"
#include "oit/volume/volume_bindings.h"
layout(std430, binding = BIND_POINTS) buffer Points { ScreenDoorPoint points[]; };
layout(local_size_x = 1) in;
void main() {
    points[0] = points[1];
}
)");
    using gpu::ScreenDoorPoint;
    checkLayout<ScreenDoorPoint>(points.id(), "Points",
                                 {FIELD(ScreenDoorPoint, x), FIELD(ScreenDoorPoint, y), FIELD(ScreenDoorPoint, z),
                                  FIELD(ScreenDoorPoint, normal), FIELD(ScreenDoorPoint, object),
                                  FIELD(ScreenDoorPoint, tintRG), FIELD(ScreenDoorPoint, tintB)});
    gl::takeErrors();
}

TEST_CASE("the medium table reads as two RGB32F texels an object: tau, then scatter") {
    test::glContext();
    // The host uploads gpu::VolumeObject as it is; the resolve reads it through an RGB32F
    // buffer texture (oit/volume/volume_list.glsl). Distinct values catch a shifted field.
    const std::vector<gpu::VolumeObject> table = {{0.5f, 1.5f, 2.5f, 0.25f, 0.75f, 1.25f},
                                                  {3.0f, 4.0f, 5.0f, 6.0f, 7.0f, 8.0f}};
    gl::Buffer media = gl::Buffer::create();
    glNamedBufferStorage(media.id(), GLsizeiptr(table.size() * sizeof(gpu::VolumeObject)), table.data(), 0);
    gl::Texture texture = gl::createTexture(GL_TEXTURE_BUFFER);
    glTextureBuffer(texture.id(), GL_RGB32F, media.id());
    gl::Buffer out = gl::Buffer::create();
    glNamedBufferStorage(out.id(), 12 * sizeof(float), nullptr, GL_DYNAMIC_STORAGE_BIT);
    gl::Program read = buildCompute(R"(#version 450 core
#include "oit/volume/volume_bindings.h"
layout(binding = BIND_VOLUME_MEDIA) uniform samplerBuffer uVolumeMedia;
layout(std430, binding = 0) buffer Out { float values[]; };
layout(local_size_x = 1) in;
void main() {
    for (int object = 0; object < 2; ++object)
        for (int c = 0; c < 3; ++c) {
            values[6 * object + c] = texelFetch(uVolumeMedia, 2 * object)[c];
            values[6 * object + 3 + c] = texelFetch(uVolumeMedia, 2 * object + 1)[c];
        }
}
)");
    glBindTextureUnit(gpu::BIND_VOLUME_MEDIA, texture.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, out.id());
    glUseProgram(read.id());
    glDispatchCompute(1, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    float values[12] = {};
    glGetNamedBufferSubData(out.id(), 0, sizeof(values), values);
    for (std::size_t object = 0; object < 2; ++object) {
        const gpu::VolumeObject& v = table[object];
        const float expected[6] = {v.tauR, v.tauG, v.tauB, v.scatterR, v.scatterG, v.scatterB};
        for (std::size_t k = 0; k < 6; ++k) CHECK(values[6 * object + k] == expected[k]);
    }
    CHECK(gl::takeErrors().empty());
}

TEST_CASE("every binding point the host binds is the one the linked program reports") {
    test::glContext();
    for (const ProgramCase& c : programCases()) {
        std::string label;
        for (const auto& s : c.stages) label += (label.empty() ? "" : " + ") + s;
        for (const auto& [name, value] : c.defines) label += " -D" + name;
        INFO(label);
        // A scene program's fragment stage is wrapped (render/scene_program.hpp); its stand-in
        // variant (STRATA_IMPOSTOR) also samples the impostor atlas, which GpuScene::draw binds.
        const bool sceneProgram = c.stages.front() == "common/scene.vert.glsl";
        gl::Program program =
            gl::buildProgram(c.stages, c.defines, sceneProgram ? sceneFragmentWrap() : gl::StageWrap{});
        auto expected = c.expected;
        if (sceneProgram && c.defines.count("STRATA_IMPOSTOR")) {
            expected.emplace("uImpostorAtlas", tex(gpu::BIND_IMPOSTOR_ATLAS));
            expected.emplace("uImpostorAlbedoAtlas", tex(gpu::BIND_IMPOSTOR_ALBEDO));
        }
        const auto reported = reportedBindings(program.id());
        for (const auto& [name, want] : expected) {
            INFO(name, ": the host binds ", unitName(want.unit), " ", want.point);
            const auto it = reported.find(name);
            if (it == reported.end()) {
                FAIL_CHECK("the program does not use it");
                continue;
            }
            CHECK(unitName(it->second.unit) == unitName(want.unit));
            CHECK(it->second.point == want.point);
        }
        for (const auto& [name, got] : reported) {
            INFO(name, " at ", unitName(got.unit), " ", got.point, " is used by the program but not bound by the host");
            CHECK(expected.count(name) == 1);
        }
    }
    gl::takeErrors();
}

TEST_CASE("compute group sizes equal the host's dispatch arithmetic") {
    test::glContext();
    const std::string resolve = std::to_string(gpu::RESOLVE_GROUP_SIZE);
    CHECK(workGroupSize("oit/abuffer_resolve.comp.glsl") == resolve + " " + resolve + " 1");
    CHECK(workGroupSize("oit/coplanarity_detect.comp.glsl") == resolve + " " + resolve + " 1");
    const std::string error = std::to_string(gpu::ERROR_GROUP_SIZE);
    CHECK(workGroupSize("debug/error_map.comp.glsl") == error + " " + error + " 1");
    // Each scan invocation takes two elements: the host's block is twice the group.
    const std::string scan = std::to_string(buffers::PrefixSum::kBlock / 2) + " 1 1";
    CHECK(workGroupSize("oit/buffers/prefix_scan.comp.glsl") == scan);
    CHECK(workGroupSize("oit/buffers/prefix_add.comp.glsl") == scan);
    gl::takeErrors();
}
