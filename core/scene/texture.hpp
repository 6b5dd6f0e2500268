#pragma once
// Textures as the scene holds them: decoded images, glTF samplers, and a material's reference to
// one (which image, which sampler, which TEXCOORD set, KHR_texture_transform). Every renderer
// reads these: GpuScene uploads them, the CPU reference samples them with the same rules
// (scene/texture_sampling.hpp).
#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace strata {

// glTF's sampler enums (the GL values, so the GPU side passes them through).
enum class TextureWrap : std::uint32_t { Repeat = 0x2901, ClampToEdge = 0x812F, MirroredRepeat = 0x8370 };
enum class TextureFilter : std::uint32_t {
    Nearest = 0x2600,
    Linear = 0x2601,
    NearestMipmapNearest = 0x2700,
    LinearMipmapNearest = 0x2701,
    NearestMipmapLinear = 0x2702,
    LinearMipmapLinear = 0x2703,
};

// glTF leaves an absent filter to the implementation; Strata takes trilinear minification and
// bilinear magnification, what the Khronos sample viewer does.
struct Sampler {
    TextureFilter magFilter = TextureFilter::Linear;
    TextureFilter minFilter = TextureFilter::LinearMipmapLinear;
    TextureWrap wrapS = TextureWrap::Repeat;
    TextureWrap wrapT = TextureWrap::Repeat;

    bool operator==(const Sampler&) const = default;
};

// A decoded image: RGBA, 8 bits a channel, rows top to bottom as the file stores them (glTF's
// UV origin is the image's top-left corner, so v = 0 is row 0). Grey and RGB images get
// alpha 255; 16-bit images are rounded to 8 bits. Colour textures hold sRGB-encoded values:
// the sampler decodes them to linear (GL_SRGB8_ALPHA8 on the GPU, srgbToLinear on the CPU).
struct TextureImage {
    std::string name;  // the glTF image's name or URI, for messages and the panel
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  // width * height * 4

    std::size_t bytes() const { return rgba.size(); }
};

// KHR_texture_transform: uv' = T(offset) * R(rotation) * S(scale) * uv, rotation in radians,
// counter-clockwise in UV space (v down the image): R takes (1, 0) to (cos, -sin).
struct TextureTransform {
    glm::vec2 offset{0.0f};
    float rotation = 0.0f;
    glm::vec2 scale{1.0f};

    // The 3x3 matrix of the extension's specification (column major, as GLSL takes it).
    glm::mat3 matrix() const;
    bool identity() const { return offset == glm::vec2(0.0f) && rotation == 0.0f && scale == glm::vec2(1.0f); }
};

// A material's use of a texture. `image` indexes Scene::images; -1 means "no texture" (also
// what a texture whose image could not be decoded becomes: the material renders with its
// factor, and the loader says so).
struct TextureRef {
    int image = -1;
    Sampler sampler;
    int texCoord = 0;  // TEXCOORD_n set, 0 or 1 (KHR_texture_transform may override it)
    TextureTransform transform;

    bool present() const { return image >= 0; }
};

}  // namespace strata
