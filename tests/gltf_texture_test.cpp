// glTF textures: images decoded from files, data URIs and GLB buffer views to known texels,
// within their limits; samplers, texCoord sets, KHR_texture_transform and COLOR_0 read; bad
// images are warnings that name the image and its materials; real textured sample models.
#include "gltf_test_builder.hpp"

#include "scene/gltf_loader.hpp"
#include "scene/lights.hpp"
#include "scene/image_decode.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <doctest/doctest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <string>
#include <tuple>

using namespace strata;
using namespace strata::test;

namespace {

std::string loadError(const std::filesystem::path& file) {
    try {
        loadGltf(file);
    } catch (const LoadError& e) {
        return e.what();
    }
    return "(loaded)";
}

// A 2 x 1 RGBA PNG with known texels.
const std::vector<std::uint8_t> kTwoTexels = {10, 20, 30, 40, 200, 150, 100, 255};

std::vector<unsigned char> twoTexelPng() {
    auto png = encodeImage("two-texels.png", 2, 1, 4, OIIO::TypeDesc::UINT8, kTwoTexels.data());
    REQUIRE_FALSE(png.empty());
    return png;
}

void checkTwoTexels(const Scene& s, const std::string& name) {
    REQUIRE(s.images.size() == 1);
    CHECK(s.images[0].name == name);
    CHECK(s.images[0].width == 2);
    CHECK(s.images[0].height == 1);
    CHECK(s.images[0].rgba == kTwoTexels);
    REQUIRE(s.materials.size() == 2);
    CHECK(s.materials[1].baseColorTexture.image == 0);
}

// A triangle with TEXCOORD_0, textured by image 0 through texture 0.
GltfBuilder texturedTriangle() {
    GltfBuilder b;
    int pos = b.positions(kTrianglePositions);
    int uv = b.accessor(b.view(std::vector<float>{0, 0, 1, 0, 0, 1}), kFloat, 3, "VEC2");
    b.doc["textures"] = {{{"source", 0}}};
    b.material({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}, {"alphaMode", "BLEND"}});
    b.meshNode(json::array({{{"attributes", {{"POSITION", pos}, {"TEXCOORD_0", uv}}}, {"material", 0}}}));
    return b;
}

// decodeImage's result, or its error prefixed by "error: ".
std::string decodeError(const std::vector<unsigned char>& bytes) {
    TextureImage image;
    std::string error;
    return decodeImage(bytes.data(), bytes.size(), image, error) ? "(decoded)" : "error: " + error;
}

}  // namespace

TEST_CASE("gltf: a PNG decodes to its texels from a file, a data URI and a GLB bufferView") {
    const std::vector<unsigned char> png = twoTexelPng();
    {
        GltfBuilder b = texturedTriangle();
        b.imageFile("texels.png", png);
        GltfLoadReport report;
        checkTwoTexels(loadGltf(b.writeGltf("image-file"), report), "texels.png");  // named by its file
        CHECK(report.warnings.empty());
    }
    {
        GltfBuilder b = texturedTriangle();
        b.imageDataUri(png);
        GltfLoadReport report;
        checkTwoTexels(loadGltf(b.writeGltf("image-data-uri"), report), "image 0");  // no name, no file
        CHECK(report.warnings.empty());
    }
    {
        GltfBuilder b = texturedTriangle();
        b.imageBufferView(png);
        b.doc["images"][0]["name"] = "texels";
        GltfLoadReport report;
        checkTwoTexels(loadGltf(b.writeGlb("image-glb"), report), "texels");
        CHECK(report.warnings.empty());
    }
}

TEST_CASE("image decoding: grey, grey + alpha, RGB, 16-bit, JPEG and WebP images become RGBA8") {
    auto decoded = [](const std::vector<unsigned char>& bytes) {
        REQUIRE_FALSE(bytes.empty());
        TextureImage image;
        std::string error;
        CHECK_MESSAGE(decodeImage(bytes.data(), bytes.size(), image, error), error);
        return image;
    };
    const std::uint16_t grey16[2] = {0, 65535};
    TextureImage g = decoded(encodeImage("grey16.png", 2, 1, 1, OIIO::TypeDesc::UINT16, grey16));
    CHECK(g.rgba == std::vector<std::uint8_t>{0, 0, 0, 255, 255, 255, 255, 255});  // grey to RGB, alpha 255
    const std::uint8_t greyAlpha[4] = {50, 100, 200, 0};
    CHECK(decoded(encodeImage("grey-alpha.png", 2, 1, 2, OIIO::TypeDesc::UINT8, greyAlpha)).rgba ==
          std::vector<std::uint8_t>{50, 50, 50, 100, 200, 200, 200, 0});  // straight alpha kept
    const std::uint8_t rgb[6] = {255, 0, 0, 0, 0, 255};
    CHECK(decoded(encodeImage("rgb.png", 2, 1, 3, OIIO::TypeDesc::UINT8, rgb)).rgba ==
          std::vector<std::uint8_t>{255, 0, 0, 255, 0, 0, 255, 255});
    // A flat-coloured JPEG comes back within JPEG's rounding.
    std::vector<std::uint8_t> flat(8 * 8 * 3);
    for (std::size_t i = 0; i < flat.size(); i += 3) flat[i] = 200, flat[i + 1] = 100, flat[i + 2] = 50;
    TextureImage j = decoded(encodeImage("flat.jpg", 8, 8, 3, OIIO::TypeDesc::UINT8, flat.data()));
    CHECK(j.width == 8);
    CHECK(j.height == 8);
    for (int c = 0; c < 3; ++c) CHECK(std::abs(int(j.rgba[std::size_t(c)]) - int(flat[std::size_t(c)])) <= 3);
    CHECK(j.rgba[3] == 255);
    // WebP, lossless: its alpha comes back exactly (OpenImageIO 2.4's WebP writer alters colours
    // of its own, so only the size and alpha are stated).
    const std::vector<unsigned char> webp = encodeImage("texels.webp", 2, 1, 4, OIIO::TypeDesc::UINT8, kTwoTexels.data(), "lossless");
    if (webp.empty()) {
        MESSAGE("skipped: this OpenImageIO writes no WebP");
    } else {
        TextureImage w = decoded(webp);
        CHECK(w.width == 2);
        CHECK(w.height == 1);
        CHECK(w.rgba[3] == 40);
        CHECK(w.rgba[7] == 255);
    }
}

TEST_CASE("image decoding: sizes from the header are bounded before any reader allocates") {
    // JPEG: a progressive frame (SOF2) of 65000 x 65000 (libjpeg would allocate its coefficients).
    CHECK(decodeError({0xFF, 0xD8, 0xFF, 0xE0, 0, 4, 0, 0, 0xFF, 0xC2, 0, 11, 8, 0xFD, 0xE8, 0xFD, 0xE8, 1, 1, 0x11, 0,
                       0xFF, 0xD9}) == "error: 65000x65000 is outside 1..16384 a side");
    // WebP: an extended (VP8X) canvas of 16384 x 16384, a gigabyte decoded (OpenImageIO's reader
    // allocates it on open).
    CHECK(decodeError({'R', 'I', 'F', 'F', 30, 0, 0, 0, 'W', 'E', 'B', 'P', 'V', 'P', '8', 'X', 10, 0, 0, 0, 0, 0, 0,
                       0, 0xFF, 0x3F, 0, 0xFF, 0x3F, 0}) == "error: 16384x16384 decodes to more than 256 MiB");
    // PNG: an IHDR of 0 x 4.
    CHECK(decodeError({0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R', 0, 0, 0, 0, 0, 0,
                       0, 4}) == "error: 0x4 is outside 1..16384 a side");
    // A PNG cut after its header: refused by the reader, in one line.
    std::vector<unsigned char> cut = twoTexelPng();
    cut.resize(40);
    const std::string error = decodeError(cut);
    CHECK(error.rfind("error: cannot decode (", 0) == 0);
    CHECK(error.find('\n') == std::string::npos);
    CHECK(decodeError({}) == "error: not a PNG, JPEG or WebP image");
}

TEST_CASE("gltf: an image bufferView past its buffer's end is a warning, never read") {
    // tinygltf hands such a view to the image callback unchecked.
    GltfBuilder b = texturedTriangle();
    b.imageBufferView(twoTexelPng());
    const int view = b.doc["images"][0]["bufferView"];
    b.doc["bufferViews"][std::size_t(view)]["byteLength"] = 1 << 20;
    GltfLoadReport report;
    auto file = b.writeGltf("image-view-past-end");
    Scene s = loadGltf(file, report);
    CHECK(s.images.empty());
    CHECK(report.warnings == std::vector<std::string>{
        file.string() + ": image 0: bufferView " + std::to_string(view) +
        " exceeds its buffer; material 0 renders without it"});
}

TEST_CASE("gltf: a texture on a TEXCOORD set other than 0 and 1 is dropped, and said") {
    const std::vector<unsigned char> png = twoTexelPng();
    for (const auto& [name, info] : std::vector<std::pair<std::string, json>>{
             {"texcoord-2", {{"index", 0}, {"texCoord", 2}}},
             {"transform-texcoord-3",
              {{"index", 0}, {"extensions", {{"KHR_texture_transform", {{"texCoord", 3}}}}}}}}) {
        CAPTURE(name);
        GltfBuilder b = texturedTriangle();
        b.imageDataUri(png);
        b.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = info;
        GltfLoadReport report;
        auto file = b.writeGltf(name);
        Scene s = loadGltf(file, report);
        CHECK(s.materials[1].baseColorTexture.image == -1);
        CHECK(report.warnings == std::vector<std::string>{
            file.string() + ": textures on a TEXCOORD set other than 0 and 1 ignored: only TEXCOORD_0 and "
                            "TEXCOORD_1 are read (material 0 baseColorTexture)"});
    }
}

TEST_CASE("gltf: samplers, texCoord and KHR_texture_transform are read into the texture reference") {
    const std::vector<unsigned char> png = twoTexelPng();
    GltfBuilder b = texturedTriangle();
    b.doc["images"] = {{{"uri", "data:image/png;base64," + test::base64(png)}}};
    b.doc["samplers"] = {{{"magFilter", 9728}, {"minFilter", 9986}, {"wrapS", 33071}, {"wrapT", 33648}}};
    b.doc["textures"][0]["sampler"] = 0;
    b.doc["extensionsUsed"] = {"KHR_texture_transform"};
    b.doc["extensionsRequired"] = {"KHR_texture_transform"};
    b.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"] = {
        {"KHR_texture_transform", {{"offset", {0.5, -0.25}}, {"rotation", 0.75}, {"scale", {2.0, 3.0}}, {"texCoord", 1}}}};
    GltfLoadReport report;
    Scene s = loadGltf(b.writeGltf("transform"), report);
    CHECK(report.warnings.empty());
    const TextureRef& t = s.materials[1].baseColorTexture;
    CHECK(t.sampler.magFilter == TextureFilter::Nearest);
    CHECK(t.sampler.minFilter == TextureFilter::NearestMipmapLinear);
    CHECK(t.sampler.wrapS == TextureWrap::ClampToEdge);
    CHECK(t.sampler.wrapT == TextureWrap::MirroredRepeat);
    CHECK(t.texCoord == 1);
    CHECK(t.transform.offset == glm::vec2(0.5f, -0.25f));
    CHECK(t.transform.rotation == 0.75f);
    CHECK(t.transform.scale == glm::vec2(2.0f, 3.0f));

    // A texture without a sampler, and a sampler that gives only wrapS: the defaults of texture.hpp
    // (glTF's repeat; trilinear minification, bilinear magnification) for the rest.
    b.doc["samplers"].push_back({{"wrapS", 33071}});
    b.doc["textures"].push_back({{"source", 0}});
    b.doc["textures"].push_back({{"source", 0}, {"sampler", 1}});
    b.material({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 1}}}}}});
    b.material({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 2}}}}}});
    Scene d = loadGltf(b.writeGltf("default-samplers"));
    REQUIRE(d.materials.size() == 4);
    CHECK(d.materials[2].baseColorTexture.image == 0);
    CHECK(d.materials[2].baseColorTexture.sampler == Sampler{});
    CHECK(d.materials[2].baseColorTexture.transform.identity());
    CHECK(d.materials[2].baseColorTexture.texCoord == 0);
    Sampler clampS;
    clampS.wrapS = TextureWrap::ClampToEdge;
    CHECK(d.materials[3].baseColorTexture.sampler == clampS);

    // Values that are not glTF's enums refuse the file, naming the sampler.
    for (const auto& [key, value, said] : std::vector<std::tuple<std::string, int, std::string>>{
             {"wrapS", 12345, "sampler 0: wrap mode 12345 is not a glTF wrap mode"},
             {"wrapT", 9728, "sampler 0: wrap mode 9728 is not a glTF wrap mode"},
             {"magFilter", 9987, "sampler 0: magFilter 9987 is not a glTF filter"},  // mipmapped: minification only
             {"minFilter", 33071, "sampler 0: minFilter 33071 is not a glTF filter"}}) {
        CAPTURE(key);
        GltfBuilder bad = b;
        bad.doc["samplers"][0][key] = value;
        CHECK_THROWS_WITH_AS(loadGltf(bad.writeGltf("bad-sampler")), doctest::Contains(said.c_str()), LoadError);
    }
    // KHR_texture_transform numbers are checked as the floats they become.
    GltfBuilder big = b;
    big.doc["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["extensions"]["KHR_texture_transform"]["rotation"] = 1e300;
    CHECK_THROWS_WITH_AS(loadGltf(big.writeGltf("big-rotation")),
                         doctest::Contains("KHR_texture_transform: rotation 1e+300 does not fit a float"), LoadError);
}

TEST_CASE("gltf: COLOR_0 and TEXCOORD_1 are read, normalized integers decoded") {
    GltfBuilder b;
    int pos = b.positions(kTrianglePositions);
    int rgb = b.accessor(b.view(std::vector<std::uint8_t>{255, 0, 51, 0, 0, 255, 102, 0, 0, 0, 255, 0}, 4), kUByte, 3,
                         "VEC3", 0, true);
    int uv1 = b.accessor(b.view(std::vector<std::uint16_t>{0, 65535, 65535, 0, 32768, 32768}), kUShort, 3, "VEC2", 0,
                         true);
    int uv0 = b.accessor(b.view(std::vector<float>(6, 0.25f)), kFloat, 3, "VEC2");
    b.meshNode(json::array(
        {{{"attributes", {{"POSITION", pos}, {"COLOR_0", rgb}, {"TEXCOORD_0", uv0}, {"TEXCOORD_1", uv1}}}}}));
    GltfLoadReport report;
    Scene s = loadGltf(b.writeGltf("colors"), report);
    CHECK(report.warnings.empty());
    REQUIRE(s.meshes.size() == 1);
    const Mesh& m = s.meshes[0];
    REQUIRE(m.colors.size() == 3);
    CHECK(m.colors[0] == glm::vec4(1.0f, 0.0f, 0.2f, 1.0f));  // VEC3: alpha 1
    CHECK(m.colors[1].b == doctest::Approx(102.0f / 255.0f));
    REQUIRE(m.texCoords[1].size() == 3);
    CHECK(m.texCoords[1][0] == glm::vec2(0.0f, 1.0f));
    CHECK(m.texCoords[1][2].x == doctest::Approx(32768.0f / 65535.0f));
    CHECK(m.texCoords[0][1] == glm::vec2(0.25f));
}

TEST_CASE("gltf: extensionsRequired naming an extension Strata does not implement refuses the file") {
    GltfBuilder b;
    int pos = b.positions(kTrianglePositions);
    b.meshNode(json::array({{{"attributes", {{"POSITION", pos}}}}}));
    b.doc["extensionsUsed"] = {"EXT_meshopt_compression"};
    b.doc["extensionsRequired"] = {"EXT_meshopt_compression"};
    auto file = b.writeGltf("required");
    CHECK_THROWS_WITH_AS(loadGltf(file), (file.string() + ": requires extension EXT_meshopt_compression, which Strata "
                                                          "does not implement").c_str(),
                         LoadError);
    b.doc["extensionsUsed"] = {"KHR_texture_transform", "KHR_foo"};
    b.doc["extensionsRequired"] = {"KHR_texture_transform", "KHR_foo"};
    file = b.writeGltf("required-foo");
    CHECK_THROWS_WITH_AS(loadGltf(file), (file.string() + ": requires extension KHR_foo, which Strata does not "
                                                          "implement").c_str(),
                         LoadError);
    // The extensions Strata implements may be required.
    b.doc["extensionsUsed"] = {"KHR_texture_transform", "KHR_materials_volume", "KHR_mesh_quantization"};
    b.doc["extensionsRequired"] = b.doc["extensionsUsed"];
    GltfLoadReport report;
    CHECK(loadGltf(b.writeGltf("required-implemented"), report).meshes.size() == 1);
    CHECK(report.warnings.empty());
}

TEST_CASE("gltf: TEXCOORD and COLOR_0 accessors are checked like NORMAL") {
    GltfBuilder b;
    int pos = b.positions(kTrianglePositions);
    const int uvFloat = b.accessor(b.view(std::vector<float>(6, 0.5f)), kFloat, 3, "VEC2");
    const int uvShort = b.accessor(b.view(std::vector<float>(4, 0.5f)), kFloat, 2, "VEC2");
    const int uvInf = b.accessor(b.view(std::vector<float>{0, 0, std::numeric_limits<float>::infinity(), 0, 0, 0}),
                                 kFloat, 3, "VEC2");
    const int uvUInt = b.accessor(b.view(std::vector<std::uint32_t>(6, 1)), kUInt, 3, "VEC2");
    const int rgbRaw = b.accessor(b.view(std::vector<std::uint8_t>(12, 255)), kUByte, 3, "VEC3");  // not normalized
    const int rgbSigned = b.accessor(b.view(std::vector<std::int8_t>(12, 127)), kByte, 3, "VEC3", 0, true);
    const int rgNaN = b.accessor(b.view(std::vector<float>(12, std::nanf(""))), kFloat, 3, "VEC4");
    const int rg = b.accessor(b.view(std::vector<float>(6, 1.0f)), kFloat, 3, "VEC2");
    for (const auto& [semantic, accessor, said] : std::vector<std::tuple<std::string, int, std::string>>{
             {"TEXCOORD_0", uvShort, "mesh 0 primitive 0: TEXCOORD_0 has 2 elements, POSITION 3"},
             {"TEXCOORD_1", uvInf, "mesh 0 primitive 0: non-finite TEXCOORD_1 value"},
             {"TEXCOORD_0", uvUInt, "TEXCOORD_0 (accessor " + std::to_string(uvUInt) + "): component type UNSIGNED_INT is not allowed"},
             {"COLOR_0", rgbRaw, "COLOR_0 (accessor " + std::to_string(rgbRaw) + "): component type 5121 not normalized"},
             {"COLOR_0", rgbSigned, "COLOR_0 (accessor " + std::to_string(rgbSigned) + "): component type 5120;"},
             {"COLOR_0", rgNaN, "mesh 0 primitive 0: non-finite COLOR_0 value"},
             {"COLOR_0", rg, "COLOR_0 (accessor " + std::to_string(rg) + "): type VEC2, expected VEC3 or VEC4"}}) {
        CAPTURE(semantic);
        CAPTURE(said);
        GltfBuilder g = b;
        json attributes = {{"POSITION", pos}, {semantic, accessor}};
        if (semantic == "TEXCOORD_1") attributes["TEXCOORD_0"] = uvFloat;
        g.meshNode(json::array({{{"attributes", attributes}}}));
        const std::string error = loadError(g.writeGltf("bad-attribute"));
        CHECK(error.find(said) != std::string::npos);
        CHECK(error.find('\n') == std::string::npos);
    }
}

// A mesh without normals is unwelded for flat normals: its texture coordinates and colours, read
// first, go with their vertices.
TEST_CASE("gltf: texture coordinates and colours follow flat normals' unwelding") {
    GltfBuilder b;
    int pos = b.positions(kQuadPositions);
    int uv = b.accessor(b.view(std::vector<float>{0, 0, 1, 0, 1, 1, 0, 1}), kFloat, 4, "VEC2");
    int rgba = b.accessor(b.view(std::vector<float>{1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 1, 0.5f}), kFloat, 4, "VEC4");
    int ind = b.accessor(b.view(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3}), kUShort, 6, "SCALAR");
    b.meshNode(json::array({{{"attributes", {{"POSITION", pos}, {"TEXCOORD_0", uv}, {"COLOR_0", rgba}}}, {"indices", ind}}}));
    Scene s = loadGltf(b.writeGltf("flat-attributes"));
    REQUIRE(s.meshes.size() == 1);
    const Mesh& m = s.meshes[0];
    REQUIRE(m.texCoords[0].size() == m.positions.size());
    REQUIRE(m.colors.size() == m.positions.size());
    for (std::size_t v = 0; v < m.positions.size(); ++v) {
        CAPTURE(v);
        // Position (x, y) of the unit quad is its texture coordinate here.
        CHECK(m.texCoords[0][v] == glm::vec2(m.positions[v].x, m.positions[v].y));
    }
    CHECK(m.colors[m.indices[5]] == glm::vec4(1, 1, 1, 0.5f));  // vertex 3 of the second triangle
}

TEST_CASE("gltf: an image too large or not an image is refused before decoding, with a warning") {
    // A PNG signature and an IHDR claiming 20000 x 4 texels, and no pixel data (a decompression
    // bomb's header).
    std::vector<unsigned char> header = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R',
                                         0, 0, 0x4e, 0x20, 0, 0, 0, 4, 8, 6, 0, 0, 0};
    // The IHDR's CRC and an empty IDAT make it a well-formed header; the decoder reads the size
    // from it itself, before any reader sees the file.
    std::uint32_t crc = 0xffffffffu;
    for (std::size_t i = 12; i < header.size(); ++i) {
        crc ^= header[i];
        for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    crc ^= 0xffffffffu;
    for (int k = 3; k >= 0; --k) header.push_back(std::uint8_t(crc >> (8 * k)));
    // An empty IDAT chunk (its CRC is that of the bytes "IDAT").
    header.insert(header.end(), {0, 0, 0, 0, 'I', 'D', 'A', 'T', 0x35, 0xaf, 0x06, 0x1e});
    for (const auto& [name, bytes, why] :
         std::vector<std::tuple<std::string, std::vector<unsigned char>, std::string>>{
             {"huge", header, "20000x4 is outside 1..16384 a side"},
             {"text", {'h', 'e', 'l', 'l', 'o'}, "not a PNG, JPEG or WebP image"},
             {"ktx2", {0xAB, 'K', 'T', 'X', ' ', '2', '0', 0xBB, '\r', '\n', 0x1A, '\n', 0, 0}, "KTX2"}}) {
        CAPTURE(name);
        GltfBuilder b = texturedTriangle();
        b.doc["images"] = {{{"uri", "data:application/octet-stream;base64," + test::base64(bytes)}}};
        GltfLoadReport report;
        Scene s = loadGltf(b.writeGltf("image-" + name), report);
        CHECK(s.images.empty());
        CHECK_FALSE(s.materials[1].baseColorTexture.present());
        REQUIRE(report.warnings.size() == 1);
        CAPTURE(report.warnings[0]);
        CHECK(report.warnings[0].find("image 0: " + why) != std::string::npos);
        CHECK(report.warnings[0].find("renders without it") != std::string::npos);
    }
}

// Real textured files from assimp's test models (the Khronos sample models' BoxTextured,
// TextureTransformTest and ClearCoatTest): what their textures load as.
TEST_CASE("gltf: textured sample models load their images, samplers and transforms") {
    const std::filesystem::path root = STRATA_ASSIMP_GLTF2_DIR;
    if (!std::filesystem::is_directory(root)) {
        MESSAGE("skipped: " << root << " is absent (Debian package assimp-testmodels)");
        return;
    }
    // BoxTextured: CesiumLogoFlat.png, a 211 x 211 palette PNG, as a file, a data URI and a GLB
    // bufferView; texels read from the file by hand (zlib and the palette). The sampler is
    // magFilter LINEAR, minFilter NEAREST_MIPMAP_LINEAR, and wraps MIRRORED_REPEAT and
    // CLAMP_TO_EDGE in the .gltf with a file, REPEAT in the other two.
    for (const auto& [rel, wrapS, wrapT] : std::vector<std::tuple<std::string, TextureWrap, TextureWrap>>{
             {"BoxTextured-glTF/BoxTextured.gltf", TextureWrap::MirroredRepeat, TextureWrap::ClampToEdge},
             {"BoxTextured-glTF-Embedded/BoxTextured.gltf", TextureWrap::Repeat, TextureWrap::Repeat},
             {"BoxTextured-glTF-Binary/BoxTextured.glb", TextureWrap::Repeat, TextureWrap::Repeat}}) {
        CAPTURE(rel);
        if (!std::filesystem::exists(root / rel)) {
            MESSAGE("skipped: " << rel << " is absent");
            continue;
        }
        GltfLoadReport report;
        Scene s = loadGltf(root / rel, report);
        CHECK(report.warnings.empty());
        REQUIRE(s.materials.size() == 2);
        const TextureRef& t = s.materials[1].baseColorTexture;
        REQUIRE(t.image == 0);
        REQUIRE(s.images.size() == 1);
        const TextureImage& image = s.images[0];
        CHECK(image.width == 211);
        CHECK(image.height == 211);
        REQUIRE(image.rgba.size() == 211u * 211u * 4u);
        auto texel = [&](int x, int y) {
            const std::size_t i = (std::size_t(y) * 211 + std::size_t(x)) * 4;
            return std::vector<std::uint8_t>(image.rgba.begin() + std::ptrdiff_t(i), image.rgba.begin() + std::ptrdiff_t(i + 4));
        };
        CHECK(texel(0, 0) == std::vector<std::uint8_t>{220, 220, 220, 255});
        CHECK(texel(90, 10) == std::vector<std::uint8_t>{108, 173, 223, 255});
        CHECK(texel(70, 100) == std::vector<std::uint8_t>{92, 135, 39, 255});
        CHECK(t.sampler.magFilter == TextureFilter::Linear);
        CHECK(t.sampler.minFilter == TextureFilter::NearestMipmapLinear);
        CHECK(t.sampler.wrapS == wrapS);
        CHECK(t.sampler.wrapT == wrapT);
        CHECK(t.texCoord == 0);
        CHECK(s.meshes[0].texCoords[0].size() == s.meshes[0].positions.size());
    }

    // TextureTransformTest: nine materials over five images, transforms as the file gives them.
    const auto transformFile = root / "textureTransform/TextureTransformTest.gltf";
    if (std::filesystem::exists(transformFile)) {
        GltfLoadReport report;
        Scene s = loadGltf(transformFile, report);
        CHECK(report.warnings.empty());
        REQUIRE(s.images.size() == 5);
        CHECK(s.images[0].name == "UV.png");
        CHECK(s.images[0].width == 256);
        CHECK(s.images[1].name == "Arrow.png");
        CHECK(s.images[1].width == 128);
        REQUIRE(s.materials.size() == 10);
        auto tex = [&](const char* name) {
            for (const Material& m : s.materials)
                if (m.name == name) return m.baseColorTexture;
            FAIL("no material " << name);
            return TextureRef{};
        };
        CHECK(tex("Offset U").transform.offset == glm::vec2(0.5f, 0.0f));
        CHECK(tex("Offset V").transform.offset == glm::vec2(0.0f, 0.5f));
        CHECK(tex("Rotation").transform.rotation == float(0.39269908169872414));
        CHECK(tex("Scale").transform.scale == glm::vec2(1.5f));
        const TextureRef all = tex("All");
        CHECK(all.image == 1);
        CHECK(all.transform.offset == glm::vec2(-0.2f, -0.1f));
        CHECK(all.transform.rotation == 0.3f);
        CHECK(all.transform.scale == glm::vec2(1.5f));
        CHECK(all.sampler.wrapS == TextureWrap::ClampToEdge);
        CHECK(all.sampler.minFilter == TextureFilter::Linear);
        const TextureRef correct = tex("Correct");  // a texture without a sampler
        CHECK(correct.image == 2);
        CHECK(correct.sampler == Sampler{});
        CHECK(correct.transform.identity());
    }

    // ClearCoatTest: six images (PNGs and a JPEG), of which only PartialCoating_Alpha (256 x 256,
    // RGBA) is a base colour texture, of Partial_Coating. Five are material textures (base
    // colour, RoughnessStripes metallic-roughness, two normal maps, ClearCoatLabels emissive);
    // PartialCoating serves KHR_materials_clearcoat alone, which Strata ignores, so the scene
    // holds the five (every image in the scene is uploaded).
    const auto clearCoat = root / "ClearCoat-glTF/ClearCoatTest.gltf";
    if (std::filesystem::exists(clearCoat)) {
        Scene s = loadGltf(clearCoat);
        REQUIRE(s.images.size() == 5);
        int normalMapped = 0;
        for (const Material& m : s.materials) normalMapped += m.normalTexture.present() ? 1 : 0;
        CHECK(normalMapped == 6);  // six materials on the two normal maps
        for (const Mesh& mesh : s.meshes)
            if (s.materials[std::size_t(mesh.material)].normalTexture.present())
                CHECK(mesh.tangents.size() == mesh.positions.size());  // given or derived
        int textured = 0;
        for (const Material& m : s.materials) {
            if (!m.baseColorTexture.present()) continue;
            ++textured;
            CHECK(m.name == "Partial_Coating");
            const TextureImage& image = s.images[std::size_t(m.baseColorTexture.image)];
            CHECK(image.name == "PartialCoating_Alpha");
            CHECK(image.width == 256);
            CHECK(image.height == 256);
        }
        CHECK(textured == 1);
    }
}

TEST_CASE("gltf: a missing or broken image is a warning naming it and its material, which keeps its factor") {
    GltfBuilder b;
    int pos = b.positions(kTrianglePositions);
    b.doc["images"] = {{{"uri", "does-not-exist.png"}, {"name", "bricks"}}, {{"uri", "data:image/png;base64,AAAA"}}};
    b.doc["textures"] = {{{"source", 0}}, {{"source", 1}}};
    b.material({{"name", "wall"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}, {"normalTexture", {{"index", 1}}}});
    b.meshNode(json::array({{{"attributes", {{"POSITION", pos}}}, {"material", 0}}}));
    GltfLoadReport report;
    auto file = b.writeGltf("textures");
    Scene s = loadGltf(file, report);
    CHECK(s.meshes.size() == 1);
    CHECK(s.materials[1].baseColor == glm::vec3(1.0f));  // glTF's default factor
    CHECK(s.materials[1].baseColorTexture.image == -1);
    CHECK(s.images.empty());
    const std::string line = file.string() + ": image 0 ('bricks'): cannot read 'does-not-exist.png'; material 0 "
                                             "('wall') renders without it";
    CHECK(std::count(report.warnings.begin(), report.warnings.end(), line) == 1);

    // Two materials on the broken image: one line still, counting the second.
    b.material({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
    GltfLoadReport twice;
    file = b.writeGltf("textures-twice");
    loadGltf(file, twice);
    const std::string both = file.string() + ": image 0 ('bricks'): cannot read 'does-not-exist.png'; material 0 "
                                             "('wall') and 1 more render without it";
    CHECK(std::count(twice.warnings.begin(), twice.warnings.end(), both) == 1);
}

TEST_CASE("gltf: metallic-roughness, normal, occlusion and emissive read with their factors and extensions") {
    GltfBuilder b;
    int pos = b.positions(kTrianglePositions);
    int normal = b.accessor(b.view(std::vector<float>{0, 0, 1, 0, 0, 1, 0, 0, 1}), kFloat, 3, "VEC3");
    int uv = b.accessor(b.view(std::vector<float>{0, 0, 1, 0, 0, 1}), kFloat, 3, "VEC2");
    b.imageDataUri(twoTexelPng());
    b.doc["textures"] = {{{"source", 0}}};
    b.doc["extensionsUsed"] = {"KHR_materials_emissive_strength", "KHR_materials_unlit"};
    b.material({{"pbrMetallicRoughness",
                 {{"metallicFactor", 0.25}, {"roughnessFactor", 0.75}, {"metallicRoughnessTexture", {{"index", 0}}}}},
                {"normalTexture", {{"index", 0}, {"scale", 0.5}}},
                {"occlusionTexture", {{"index", 0}, {"strength", 0.3}}},
                {"emissiveTexture", {{"index", 0}}},
                {"emissiveFactor", {1.0, 0.5, 0.0}},
                {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}}});
    b.material({{"extensions", {{"KHR_materials_unlit", json::object()}}}});
    b.meshNode(json::array({{{"attributes", {{"POSITION", pos}, {"NORMAL", normal}, {"TEXCOORD_0", uv}}}, {"material", 0}},
                            {{"attributes", {{"POSITION", pos}}}, {"material", 1}}}));
    GltfLoadReport report;
    Scene s = loadGltf(b.writeGltf("pbr"), report);
    CHECK(report.warnings.empty());
    REQUIRE(s.materials.size() == 3);
    const Material& m = s.materials[1];
    CHECK(m.metallic == doctest::Approx(0.25f));
    CHECK(m.roughness == doctest::Approx(0.75f));
    CHECK(m.metallicRoughnessTexture.image == 0);
    CHECK(m.normalTexture.image == 0);
    CHECK(m.normalScale == doctest::Approx(0.5f));
    CHECK(m.occlusionTexture.image == 0);
    CHECK(m.occlusionStrength == doctest::Approx(0.3f));
    CHECK(m.emissiveTexture.image == 0);
    CHECK(m.emissive == glm::vec3(4.0f, 2.0f, 0.0f));
    CHECK_FALSE(m.unlit);
    CHECK(s.images.size() == 1);  // one image, however many slots use it
    // glTF's defaults where the file says nothing: metallic 1, roughness 1, no emission.
    const Material& plain = s.materials[2];
    CHECK(plain.unlit);
    CHECK(plain.metallic == 1.0f);
    CHECK(plain.roughness == 1.0f);
    CHECK(plain.emissive == glm::vec3(0.0f));
    // The normal-mapped primitive got tangents (derived: the file has none), the other none.
    REQUIRE(s.meshes.size() == 2);
    CHECK(s.meshes[0].tangents.size() == 3);
    CHECK(s.meshes[0].tangents[0] == glm::vec4(1.0f, 0.0f, 0.0f, -1.0f));  // u along +x, v along +y: mirrored
    CHECK(s.meshes[1].tangents.empty());
}

TEST_CASE("gltf: out-of-range PBR factors are clamped and said; a bad emissive strength is refused") {
    GltfBuilder b;
    int pos = b.positions(kTrianglePositions);
    b.material({{"pbrMetallicRoughness", {{"metallicFactor", 2.0}}}, {"emissiveFactor", {0.0, -1.0, 0.5}}});
    b.meshNode(json::array({{{"attributes", {{"POSITION", pos}}}, {"material", 0}}}));
    GltfLoadReport report;
    Scene s = loadGltf(b.writeGltf("pbr-clamped"), report);
    CHECK(s.materials[1].metallic == 1.0f);
    CHECK(s.materials[1].emissive == glm::vec3(0.0f, 0.0f, 0.5f));
    CHECK(report.warnings.size() == 2);

    b.doc["materials"][0]["extensions"] = {{"KHR_materials_emissive_strength", {{"emissiveStrength", -1.0}}}};
    CHECK_THROWS_WITH_AS(loadGltf(b.writeGltf("pbr-strength")),
                         doctest::Contains("KHR_materials_emissive_strength: emissiveStrength must be a number in [0, 10000]"),
                         LoadError);
}

TEST_CASE("gltf: KHR_lights_punctual lights are read and placed by their nodes; bad lights are refused") {
    GltfBuilder b;
    int pos = b.positions(kTrianglePositions);
    b.meshNode(json::array({{{"attributes", {{"POSITION", pos}}}}}));
    b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    b.doc["extensions"] = {{"KHR_lights_punctual",
                            {{"lights", {{{"type", "point"}, {"intensity", 20.0}, {"color", {1.0, 0.5, 0.0}}, {"range", 8.0}},
                                         {{"type", "spot"}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.4}}}}}}}}};
    b.doc["nodes"].push_back({{"translation", {0.0, 3.0, 0.0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    b.doc["nodes"].push_back({{"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
    GltfLoadReport report;
    Scene s = loadGltf(b.writeGltf("lights"), report);
    CHECK(report.warnings.empty());
    REQUIRE(s.lights.size() == 2);
    CHECK(s.lights[0].type == Light::Type::Point);
    CHECK(s.lights[0].intensity == 20.0f);
    CHECK(s.lights[0].color == glm::vec3(1.0f, 0.5f, 0.0f));
    CHECK(s.lights[0].range == 8.0f);
    CHECK(s.lights[1].type == Light::Type::Spot);
    CHECK(s.lights[1].outerConeAngle == doctest::Approx(0.4f));
    const std::vector<gpu::PunctualLight> placed = placeLights(s);
    REQUIRE(placed.size() == 2);
    CHECK(placed[0].positionRange == glm::vec4(0.0f, 3.0f, 0.0f, 8.0f));

    b.doc["extensions"]["KHR_lights_punctual"]["lights"][1]["spot"]["innerConeAngle"] = 0.5;
    CHECK_THROWS_WITH_AS(loadGltf(b.writeGltf("lights-cone")),
                         doctest::Contains("light 1: spot cone angles must satisfy 0 <= inner < outer <= pi/2"), LoadError);
    b.doc["extensions"]["KHR_lights_punctual"]["lights"][1]["spot"]["innerConeAngle"] = 0.2;
    b.doc["nodes"][2]["extensions"]["KHR_lights_punctual"]["light"] = 7;
    CHECK_THROWS_WITH_AS(loadGltf(b.writeGltf("lights-index")), doctest::Contains("light 7"), LoadError);
}

TEST_CASE("gltf: KHR_materials_transmission, _ior and _volume's thickness make a transparent coloured filter") {
    GltfBuilder b;
    int pos = b.positions(kTrianglePositions);
    b.doc["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_volume"};
    b.material({{"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.5, 0.2, 1.0}}, {"metallicFactor", 0.0}}},
                {"extensions",
                 {{"KHR_materials_transmission", {{"transmissionFactor", 0.8}}},
                  {"KHR_materials_ior", {{"ior", 1.33}}},
                  {"KHR_materials_volume", {{"thicknessFactor", 0.25}, {"attenuationDistance", 2.0},
                                            {"attenuationColor", {0.5, 1.0, 1.0}}}}}}});
    b.meshNode(json::array({{{"attributes", {{"POSITION", pos}}}, {"material", 0}}}));
    GltfLoadReport report;
    Scene s = loadGltf(b.writeGltf("glass"), report);
    CHECK(report.warnings.empty());
    REQUIRE(s.materials.size() == 2);
    const Material& glass = s.materials[1];
    CHECK(glass.transmission == doctest::Approx(0.8f));
    CHECK(glass.ior == doctest::Approx(1.33f));
    CHECK(glass.thickness == doctest::Approx(0.25f));
    // OPAQUE in the file, transparent to the OIT core: light passes through it.
    CHECK(glass.alphaMode == AlphaMode::Opaque);
    CHECK(glass.transmissive());
    CHECK(glass.isTransparent());
    // tau = -ln(0.5) / 2 in red; through 0.25 of it (unit scale) exp(-tau 0.25) = 0.5^(1/8).
    const glm::vec3 filter = volumeFilterOnEntry(glass, glm::mat4(1.0f));
    CHECK(filter.r == doctest::Approx(std::pow(0.5, 0.125)).epsilon(1e-5));
    CHECK(filter.g == 1.0f);
    // The node's scale lengthens the path: scaled by 2, 0.5^(1/4).
    CHECK(volumeFilterOnEntry(glass, glm::scale(glm::mat4(1.0f), glm::vec3(2.0f))).r ==
          doctest::Approx(std::pow(0.5, 0.25)).epsilon(1e-5));

    b.doc["materials"][0]["extensions"]["KHR_materials_ior"]["ior"] = 0.5;
    CHECK_THROWS_WITH_AS(loadGltf(b.writeGltf("glass-ior")),
                         doctest::Contains("KHR_materials_ior: ior must be 0 or a number in [1, 10]"), LoadError);
}
