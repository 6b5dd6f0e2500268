#include "scene/gltf_textures.hpp"

#include "io/printable.hpp"
#include "scene/gltf_internal.hpp"
#include "scene/image_decode.hpp"

#include <cmath>

namespace strata::detail {

bool decodeGltfImage(tinygltf::Image* image, const int index, std::string*, std::string*, int, int,
                     const unsigned char* bytes, int size, void* user) {
    auto& table = *static_cast<GltfImageTable*>(user);
    if (!image || index < 0 || size < 0) return true;
    table.ensure(std::size_t(index));
    std::string& error = table.errors[std::size_t(index)];
    TextureImage decoded;
    if (std::string problem = table.viewProblem(*image); !problem.empty()) {
        error = problem;
    } else if (!decodeImage(bytes, std::size_t(size), decoded, error)) {
        // error says why
    } else if (table.totalBytes + decoded.bytes() > GltfImageTable::kMaxTotalBytes) {
        error = "the file's decoded textures would exceed " + std::to_string(GltfImageTable::kMaxTotalBytes >> 20) + " MiB";
    } else {
        table.totalBytes += decoded.bytes();
        // The name the panel and messages show: the glTF name, else the file it came from; data
        // URIs and bufferViews have neither.
        decoded.name = !image->name.empty() ? image->name
                       : !image->uri.empty() ? image->uri
                                             : "image " + std::to_string(index);
        table.images[std::size_t(index)] = std::move(decoded);
    }
    return true;
}

void GltfTextures::moveUsedImages(Scene& scene) {
    decoded_.ensure(model_.images.size());
    std::vector<char> used(model_.images.size(), 0);
    for (const tinygltf::Material& m : model_.materials) {
        for (int texture : {m.pbrMetallicRoughness.baseColorTexture.index, m.pbrMetallicRoughness.metallicRoughnessTexture.index,
                            m.normalTexture.index, m.occlusionTexture.index, m.emissiveTexture.index}) {
            if (texture < 0 || std::size_t(texture) >= model_.textures.size()) continue;  // textureOf says so
            const int source = model_.textures[std::size_t(texture)].source;
            if (source >= 0 && std::size_t(source) < used.size()) used[std::size_t(source)] = 1;
        }
    }
    for (std::size_t i = 0; i < model_.images.size(); ++i) {
        if (used[i] && decoded_.images[i].width > 0) {
            imageMap_.push_back(int(scene.images.size()));
            scene.images.push_back(std::move(decoded_.images[i]));
        } else {
            imageMap_.push_back(-1);
        }
    }
}

// Why glTF image `i` has no decoded copy.
std::string GltfTextures::imageProblem(std::size_t i) const {
    if (!decoded_.errors[i].empty()) return decoded_.errors[i];
    const tinygltf::Image& g = model_.images[i];
    if (!g.uri.empty() && g.uri.rfind("data:", 0) != 0) return "cannot read '" + printable(g.uri, 80) + "'";
    return "has no image data";
}

namespace {

TextureWrap wrapOf(int value, const std::string& what) {
    switch (value) {
    case TINYGLTF_TEXTURE_WRAP_REPEAT: return TextureWrap::Repeat;
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::ClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::MirroredRepeat;
    default: fail(what + ": wrap mode " + str(value) + " is not a glTF wrap mode");
    }
}

TextureFilter filterOf(int value, bool minification, TextureFilter fallback, const std::string& what) {
    if (value < 0) return fallback;  // absent: the implementation's choice (texture.hpp)
    switch (value) {
    case TINYGLTF_TEXTURE_FILTER_NEAREST: return TextureFilter::Nearest;
    case TINYGLTF_TEXTURE_FILTER_LINEAR: return TextureFilter::Linear;
    default: break;
    }
    if (minification) switch (value) {
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST: return TextureFilter::NearestMipmapNearest;
        case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST: return TextureFilter::LinearMipmapNearest;
        case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR: return TextureFilter::NearestMipmapLinear;
        case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR: return TextureFilter::LinearMipmapLinear;
        default: break;
        }
    fail(what + ": " + (minification ? "minFilter " : "magFilter ") + str(value) + " is not a glTF filter");
}

glm::vec2 vec2Of(const tinygltf::Value& ext, const char* key, glm::vec2 fallback, const std::string& what) {
    if (!ext.Has(key)) return fallback;
    const tinygltf::Value& v = ext.Get(key);
    if (!v.IsArray() || v.ArrayLen() != 2 || !v.Get(0).IsNumber() || !v.Get(1).IsNumber())
        fail(what + ": " + key + " must be an array of 2 numbers");
    return {toFloat(v.Get(0).GetNumberAsDouble(), what + ": " + key),
            toFloat(v.Get(1).GetNumberAsDouble(), what + ": " + key)};
}

}  // namespace

TextureRef GltfTextures::textureOf(int index, int texCoord, const tinygltf::ExtensionMap& extensions, const char* slot,
                                   const std::string& material) {
    TextureRef ref;
    if (index < 0) return ref;
    const std::string what = material + " " + slot;
    if (std::size_t(index) >= model_.textures.size()) fail(what + ": texture " + str(index) + " does not exist");
    const tinygltf::Texture& t = model_.textures[std::size_t(index)];
    if (t.sampler >= 0) {
        if (std::size_t(t.sampler) >= model_.samplers.size())
            fail(what + ": sampler " + str(t.sampler) + " does not exist");
        const tinygltf::Sampler& g = model_.samplers[std::size_t(t.sampler)];
        const std::string sw = "sampler " + str(t.sampler);
        ref.sampler.magFilter = filterOf(g.magFilter, false, ref.sampler.magFilter, sw);
        ref.sampler.minFilter = filterOf(g.minFilter, true, ref.sampler.minFilter, sw);
        ref.sampler.wrapS = wrapOf(g.wrapS, sw);
        ref.sampler.wrapT = wrapOf(g.wrapT, sw);
    }
    ref.texCoord = texCoord;
    auto ext = extensions.find("KHR_texture_transform");
    if (ext != extensions.end() && ext->second.IsObject()) {
        const tinygltf::Value& v = ext->second;
        const std::string tw = what + " KHR_texture_transform";
        ref.transform.offset = vec2Of(v, "offset", ref.transform.offset, tw);
        ref.transform.scale = vec2Of(v, "scale", ref.transform.scale, tw);
        ref.transform.rotation = toFloat(number(v, "rotation", 0.0, tw), tw + ": rotation");
        if (v.Has("texCoord")) {
            const double set = number(v, "texCoord", 0.0, tw);
            if (set != std::floor(set)) fail(tw + ": texCoord must be an integer");
            ref.texCoord = set >= 0.0 && set <= 1e6 ? int(set) : -1;  // -1: dropped below
        }
    }
    if (ref.texCoord != 0 && ref.texCoord != 1) {
        ignored_.note("texCoord set",
                     "textures on a TEXCOORD set other than 0 and 1 ignored: only TEXCOORD_0 and TEXCOORD_1 are read",
                     what);
        return TextureRef{};
    }
    if (t.source < 0) {
        ignored_.note("texture without source", "texture without an image source ignored (" + material +
                                                   " renders without it)", what);
        return TextureRef{};
    }
    if (std::size_t(t.source) >= model_.images.size()) fail(what + ": image " + str(t.source) + " does not exist");
    ref.image = imageMap_[std::size_t(t.source)];
    if (ref.image < 0) {
        auto& users = failedImageUsers_[t.source];
        if (users.empty() || users.back() != material) users.push_back(material);
    }
    return ref;
}

// One line per image that could not be decoded but is used, naming why and the materials
// that render without it (with their factors alone):
// "<file>: image 3 ('logo'): <why>; material 1 ('box') renders without it".
void GltfTextures::warnFailedImages(std::vector<std::string>& warnings) const {
    for (const auto& [index, users] : failedImageUsers_) {
        const tinygltf::Image& g = model_.images[std::size_t(index)];
        std::string line = printable(file_, 120) + ": image " + str(index) +
                           (g.name.empty() ? "" : " ('" + printable(g.name, 60) + "')") + ": " +
                           printableMessage(imageProblem(std::size_t(index))) + "; " + users.front();
        if (users.size() == 1) line += " renders without it";
        else line += " and " + str(users.size() - 1) + " more render without it";
        warnings.push_back(line);
    }
}

}  // namespace strata::detail
