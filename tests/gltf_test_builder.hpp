#pragma once
// Writes tiny glTF files for the loader and scene-description tests: a binary buffer plus a
// JSON document built with nlohmann-json, saved as .gltf (+ .bin or a base64 data URI) or .glb.
#include <nlohmann/json.hpp>
#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <unistd.h>

namespace strata::test {

using json = nlohmann::json;

// A fresh folder per process under the system temp dir (tests in one binary share it),
// removed when the process exits.
inline std::filesystem::path tempDir() {
    struct Dir {
        std::filesystem::path path;
        Dir() : path(std::filesystem::temp_directory_path() / ("strata-tests-" + std::to_string(::getpid()))) {
            std::filesystem::create_directories(path);
        }
        ~Dir() {
            std::error_code ec;
            std::filesystem::remove_all(path, ec);
        }
    };
    static Dir dir;
    return dir.path;
}

inline void writeFile(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
}

inline std::string base64(const std::vector<unsigned char>& data) {
    static const char* table = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < data.size(); i += 3) {
        std::uint32_t v = std::uint32_t(data[i]) << 16;
        if (i + 1 < data.size()) v |= std::uint32_t(data[i + 1]) << 8;
        if (i + 2 < data.size()) v |= data[i + 2];
        out += table[(v >> 18) & 63];
        out += table[(v >> 12) & 63];
        out += i + 1 < data.size() ? table[(v >> 6) & 63] : '=';
        out += i + 2 < data.size() ? table[v & 63] : '=';
    }
    return out;
}

enum Component : int { kByte = 5120, kUByte = 5121, kShort = 5122, kUShort = 5123, kInt = 5124, kUInt = 5125, kFloat = 5126 };

struct GltfBuilder {
    std::vector<unsigned char> bin;
    json doc = {{"asset", {{"version", "2.0"}}}};

    // Appends raw values (4-byte aligned) as a bufferView; returns its index.
    template <class T>
    int view(const std::vector<T>& values, int byteStride = 0) {
        while (bin.size() % 4) bin.push_back(0);
        std::size_t offset = bin.size();
        bin.resize(offset + values.size() * sizeof(T));
        if (!values.empty()) std::memcpy(bin.data() + offset, values.data(), values.size() * sizeof(T));
        json v = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(T)}};
        if (byteStride) v["byteStride"] = byteStride;
        doc["bufferViews"].push_back(v);
        return int(doc["bufferViews"].size()) - 1;
    }

    int accessor(int bufferView, int componentType, std::size_t count, const char* type,
                 std::size_t byteOffset = 0, bool normalized = false) {
        json a = {{"componentType", componentType}, {"count", count}, {"type", type}};
        if (bufferView >= 0) a["bufferView"] = bufferView;
        if (byteOffset) a["byteOffset"] = byteOffset;
        if (normalized) a["normalized"] = true;
        doc["accessors"].push_back(a);
        return int(doc["accessors"].size()) - 1;
    }

    int positions(const std::vector<float>& xyz) {
        return accessor(view(xyz), kFloat, xyz.size() / 3, "VEC3");
    }

    // A mesh with the given primitives, one node showing it (a root); returns the node index.
    int meshNode(const json& primitives, const json& nodeExtra = json::object()) {
        doc["meshes"].push_back({{"primitives", primitives}});
        json node = nodeExtra;
        node["mesh"] = doc["meshes"].size() - 1;
        doc["nodes"].push_back(node);
        return int(doc["nodes"].size()) - 1;
    }

    int material(const json& m) {
        doc["materials"].push_back(m);
        return int(doc["materials"].size()) - 1;
    }

    // An image from encoded bytes (PNG, JPEG, ...), each of the three ways glTF holds one;
    // each returns the image index. A data URI inside the JSON:
    int imageDataUri(const std::vector<unsigned char>& encoded, const std::string& mime = "image/png") {
        return image({{"uri", "data:" + mime + ";base64," + base64(encoded)}});
    }
    // A file `name` beside the glTF (in tempDir(), where writeGltf puts it):
    int imageFile(const std::string& name, const std::vector<unsigned char>& encoded) {
        writeFile(tempDir() / name, std::string(encoded.begin(), encoded.end()));
        return image({{"uri", name}});
    }
    // A bufferView of the binary buffer (the GLB way; a .gltf may do it too):
    int imageBufferView(const std::vector<unsigned char>& encoded, const std::string& mime = "image/png") {
        return image({{"bufferView", view(encoded)}, {"mimeType", mime}});
    }
    int image(const json& description) {
        doc["images"].push_back(description);
        return int(doc["images"].size()) - 1;
    }

    // Where writeGltf's buffer points instead of its own .bin, when set (bad-input tests).
    std::string bufferUri;

    // .gltf with the buffer in a .bin beside it (or inline as base64 when embed is true).
    std::filesystem::path writeGltf(const std::string& name, bool embed = false) {
        auto path = tempDir() / (name + ".gltf");
        json d = doc;
        if (!bin.empty()) {
            if (!bufferUri.empty()) {
                d["buffers"] = {{{"byteLength", bin.size()}, {"uri", bufferUri}}};
            } else if (embed) {
                d["buffers"] = {{{"byteLength", bin.size()},
                                 {"uri", "data:application/octet-stream;base64," + base64(bin)}}};
            } else {
                writeFile(tempDir() / (name + ".bin"), std::string(bin.begin(), bin.end()));
                d["buffers"] = {{{"byteLength", bin.size()}, {"uri", name + ".bin"}}};
            }
        }
        writeFile(path, d.dump(1));
        return path;
    }

    std::string glbBytes() const {
        json d = doc;
        std::vector<unsigned char> data = bin;
        while (data.size() % 4) data.push_back(0);
        if (!data.empty()) d["buffers"] = {{{"byteLength", bin.size()}}};
        std::string text = d.dump();
        while (text.size() % 4) text += ' ';
        auto u32 = [](std::string& s, std::uint32_t v) {
            for (int i = 0; i < 4; ++i) s += char((v >> (8 * i)) & 0xFF);
        };
        std::string out = "glTF";
        u32(out, 2);
        u32(out, std::uint32_t(12 + 8 + text.size() + (data.empty() ? 0 : 8 + data.size())));
        u32(out, std::uint32_t(text.size()));
        u32(out, 0x4E4F534Au);  // "JSON"
        out += text;
        if (!data.empty()) {
            u32(out, std::uint32_t(data.size()));
            u32(out, 0x004E4942u);  // "BIN\0"
            out.append(data.begin(), data.end());
        }
        return out;
    }

    std::filesystem::path writeGlb(const std::string& name) {
        auto path = tempDir() / (name + ".glb");
        writeFile(path, glbBytes());
        return path;
    }
};

// `pixels` (8 or 16 bits a channel, straight alpha) encoded by OpenImageIO in the format the
// extension of `name` names, as the file's bytes; empty when this OpenImageIO cannot write it.
inline std::vector<unsigned char> encodeImage(const std::string& name, int width, int height, int channels, OIIO::TypeDesc type,
                                  const void* pixels, const char* compression = nullptr) {
    const std::filesystem::path path = tempDir() / name;
    OIIO::ImageSpec spec(width, height, channels, type);
    spec.attribute("oiio:UnassociatedAlpha", 1);  // the texels are straight alpha, as glTF's
    if (compression) spec.attribute("compression", compression);
    auto out = OIIO::ImageOutput::create(path.string());
    if (!out || !out->open(path.string(), spec) || !out->write_image(type, pixels)) return {};
    out->close();
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A unit quad in z = 0 (4 vertices) with +Z normals: the smallest indexed test mesh.
inline const std::vector<float> kQuadPositions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
inline const std::vector<float> kTrianglePositions = {0, 0, 0, 1, 0, 0, 0, 1, 0};  // non-indexed
inline const std::vector<float> kQuadNormals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};

}  // namespace strata::test
