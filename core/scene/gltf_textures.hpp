#pragma once
// glTF textures to the scene's: images decoded while tinygltf loads (GltfImageTable's callback),
// samplers, texCoord sets and KHR_texture_transform read into TextureRefs, and one warning per
// image that could not be decoded, naming the materials that render without it.
// Internal to the glTF loader (gltf_internal.hpp).
#include "scene/gltf_ignored.hpp"
#include "scene/scene.hpp"

#include <tiny_gltf.h>

#include <map>
#include <string>
#include <vector>

namespace strata::detail {

// Every image tinygltf finds (a file beside the glTF, a data URI, a GLB bufferView) is decoded
// here, into a table by glTF image index. The callback always succeeds: a missing, broken,
// oversized or unsupported image becomes a warning naming it and the materials using it, which
// render with their factors; it never fails the whole file.
struct GltfImageTable {
    const tinygltf::Model* model = nullptr;  // being filled by tinygltf: its buffers are loaded before images
    std::vector<TextureImage> images;  // by glTF image index; width 0: not decoded
    std::vector<std::string> errors;   // why not, by glTF image index (empty: never reached)
    std::size_t totalBytes = 0;

    static constexpr std::size_t kMaxTotalBytes = std::size_t(1) << 30;  // decoded, per file

    void ensure(std::size_t index) {
        if (images.size() <= index) {
            images.resize(index + 1);
            errors.resize(index + 1);
        }
    }

    // tinygltf hands an image's bufferView to the callback without checking it against its
    // buffer; a view past the buffer's end must not be read.
    std::string viewProblem(const tinygltf::Image& image) const {
        if (image.bufferView < 0 || !model) return {};
        const std::size_t index = std::size_t(image.bufferView);
        if (index >= model->bufferViews.size()) return "bufferView " + std::to_string(index) + " does not exist";
        const tinygltf::BufferView& view = model->bufferViews[index];
        if (view.buffer < 0 || std::size_t(view.buffer) >= model->buffers.size())
            return "bufferView " + std::to_string(index) + " refers to a buffer that does not exist";
        const std::size_t size = model->buffers[std::size_t(view.buffer)].data.size();
        if (view.byteOffset > size || view.byteLength > size - view.byteOffset)
            return "bufferView " + std::to_string(index) + " exceeds its buffer";
        return {};
    }
};

// tinygltf's LoadImageDataFunction; `user` is the GltfImageTable. Always succeeds.
bool decodeGltfImage(tinygltf::Image* image, const int index, std::string* err, std::string* warn, int width,
                     int height, const unsigned char* bytes, int size, void* user);

class GltfTextures {
public:
    GltfTextures(const tinygltf::Model& model, GltfImageTable& decoded, IgnoredLog& ignored, std::string file)
        : model_(model), decoded_(decoded), ignored_(ignored), file_(std::move(file)) {}

    // The decoded images a material's textures use move to Scene::images (every renderer
    // uploads all of them, so an image no material uses stays out).
    void moveUsedImages(Scene& scene);
    // A textureInfo (index, texCoord, KHR_texture_transform) of a material's `slot`
    // ("baseColorTexture", "normalTexture", ...) to a TextureRef; image -1 where the texture
    // cannot be drawn (warnFailedImages says why). Info is tinygltf's TextureInfo,
    // NormalTextureInfo or OcclusionTextureInfo.
    template <class Info>
    TextureRef textureOf(const Info& info, const char* slot, const std::string& material) {
        return textureOf(info.index, info.texCoord, info.extensions, slot, material);
    }
    // One line per image that could not be decoded but is used, naming why and the materials
    // that render without it (with their factors alone).
    void warnFailedImages(std::vector<std::string>& warnings) const;

private:
    TextureRef textureOf(int index, int texCoord, const tinygltf::ExtensionMap& extensions, const char* slot,
                         const std::string& material);
    std::string imageProblem(std::size_t image) const;

    const tinygltf::Model& model_;
    GltfImageTable& decoded_;
    IgnoredLog& ignored_;
    std::string file_;
    std::vector<int> imageMap_;  // glTF image -> Scene::images, -1 not decoded
    // glTF images that could not be decoded -> the materials that use them, in material order.
    std::map<int, std::vector<std::string>> failedImageUsers_;
};

}  // namespace strata::detail
