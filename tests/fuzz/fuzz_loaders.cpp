// strata_fuzz: a seeded mutation fuzzer for the input readers (glTF, scene descriptions, camera
// paths, head-pose traces). Built in every tree; run under AddressSanitizer + UBSan (the
// build-asan tree) it finds memory errors and undefined behaviour, and with the memory limits
// below any allocation a hostile input could force. CTest runs a bounded number of inputs per
// target (tests/CMakeLists.txt); a long run is the same command with a larger count:
//
//     strata_fuzz TARGET COUNT SEED CORPUS...     TARGET: gltf, scene, path or trace
//     strata_fuzz TARGET --dump INDEX SEED CORPUS...   writes input INDEX to fuzz-input.bin
//
// CORPUS entries are files or folders (searched recursively for the target's extensions); an
// absent one is skipped with a message. Built-in seeds cover each format's keys besides. Every
// input must either load or be refused with the reader's own error type; any other exception,
// a crash, a sanitizer report or an input that runs longer than 20 s stops the run with the
// input's index, which --dump writes out (the mutations are deterministic for a seed).
#include "mutator.hpp"

#include "camera/camera_path.hpp"
#include "scene/gltf_loader.hpp"
#include "scene/load_error.hpp"
#include "scene/scene_description.hpp"
#ifdef STRATA_FUZZ_TRACES
#include "tracking/trace_io.hpp"
#endif

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <typeinfo>
#include <string>
#include <vector>

#include <unistd.h>

// Memory limits under ASan: a single allocation over 256 MiB, or a resident size over 2 GiB,
// ends the run as a failure (allocator_may_return_null=0: no bad_alloc to hide behind). Fuzz
// inputs are at most 2 MiB, so nothing legitimate comes near either. ASAN_OPTIONS adds to these.
extern "C" const char* __asan_default_options() {
    return "max_allocation_size_mb=256:hard_rss_limit_mb=2048:allocator_may_return_null=0:detect_leaks=0";
}

namespace fs = std::filesystem;
using namespace strata;

namespace {

constexpr std::size_t kMaxInput = 2 << 20;
// Seed sizes: a large seed costs its full parse on every input and finds nothing a small one
// does not, so glTF files over 256 KiB are skipped and text files are cut after 16 KiB (at a
// line end, so they stay valid). This keeps an ASan run near a thousand inputs a second.
constexpr std::uintmax_t kMaxBinarySeed = 256 << 10;
constexpr std::size_t kMaxTextSeed = 16 << 10;
constexpr unsigned kHangSeconds = 20;

volatile std::sig_atomic_t gIndex = -1;

extern "C" void onHang(int) {
    char text[96];
    int n = std::snprintf(text, sizeof text, "strata_fuzz: input %d ran longer than %u s (a hang)\n", int(gIndex),
                          kHangSeconds);
    (void)!::write(2, text, std::size_t(n));
    ::_exit(3);
}

struct Seed {
    fs::path file;  // where it came from: a glTF's external buffers are found beside it
    std::string bytes;
};

std::string readAll(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

// A one-triangle glTF with a material: the model built-in scene seeds place, written where
// the scene inputs' relative paths resolve.
std::string triangleGltf() {
    // Three float positions, base64: (0,0,0) (1,0,0) (0,1,0).
    return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0},"material":0}]}],
"materials":[{"pbrMetallicRoughness":{"baseColorFactor":[1,0,0,0.5]},"alphaMode":"BLEND"}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]}],
"bufferViews":[{"buffer":0,"byteLength":36}],
"buffers":[{"byteLength":36,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]})";
}

// A textured triangle: a PNG as a data URI and as a bufferView, a sampler, KHR_texture_transform,
// TEXCOORD_0 and normalized COLOR_0, so mutations reach the image decoder and the texture paths.
std::string texturedGltf() {
    return R"({"asset":{"version":"2.0"},
"extensionsUsed":["KHR_texture_transform"],
"scene":0,
"scenes":[{"nodes":[0]}],
"nodes":[{"mesh":0}],
"meshes":[{"primitives":[{"attributes":{"POSITION":0,"TEXCOORD_0":1,"COLOR_0":2},"material":0}]}],
"materials":[{"pbrMetallicRoughness":{"baseColorTexture":{"index":0,"extensions":{"KHR_texture_transform":{"offset":[0.5,0],"rotation":0.3,"scale":[2,2],"texCoord":0}}}},"alphaMode":"MASK","alphaCutoff":0.5},{"pbrMetallicRoughness":{"baseColorTexture":{"index":1,"texCoord":1}},"alphaMode":"BLEND"}],
"textures":[{"source":0,"sampler":0},{"source":1}],
"samplers":[{"magFilter":9728,"minFilter":9987,"wrapS":33071,"wrapT":33648}],
"images":[{"uri":"data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAIAAAABCAYAAAD0In+KAAAAEUlEQVR4nGPgEpHTODEt5T8ACQoDJgqPAuUAAAAASUVORK5CYII="},{"bufferView":3,"mimeType":"image/png"}],
"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3","min":[0,0,0],"max":[1,1,0]},{"bufferView":1,"componentType":5126,"count":3,"type":"VEC2"},{"bufferView":2,"componentType":5121,"normalized":true,"count":3,"type":"VEC4"}],
"bufferViews":[{"buffer":0,"byteLength":36},{"buffer":0,"byteOffset":36,"byteLength":24},{"buffer":0,"byteOffset":60,"byteLength":12},{"buffer":0,"byteOffset":72,"byteLength":74}],
"buffers":[{"byteLength":146,"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/AAAAAAAAAAAAAIA//wAA/wD/AIAAAP//iVBORw0KGgoAAAANSUhEUgAAAAIAAAABCAYAAAD0In+KAAAAEUlEQVR4nGPgEpHTODEt5T8ACQoDJgqPAuUAAAAASUVORK5CYII="}]})";
}

struct Target {
    bool text;                            // text seeds are cut, binary seeds over the limit skipped
    std::vector<std::string> extensions;  // corpus files this target reads
    std::vector<std::string> builtinSeeds;
    std::vector<std::string> tokens;      // format keys for the dictionary
    // Loads `bytes` named `file`; true when loaded, false when refused with the reader's error.
    std::function<bool(const std::string& bytes, const fs::path& file)> run;
};

Target makeTarget(const std::string& name, const fs::path& scratch) {
    if (name == "gltf") {
        return {false,
                {".gltf", ".glb"},
                {triangleGltf(), texturedGltf()},
                {"\"accessors\"", "\"bufferViews\"", "\"buffers\"", "\"byteOffset\"", "\"byteLength\"", "\"byteStride\"",
                 "\"count\"", "\"componentType\"", "\"sparse\"", "\"indices\"", "\"uri\"", "\"children\"", "\"matrix\"",
                 "\"translation\"", "\"rotation\"", "\"scale\"", "\"mesh\"", "\"nodes\"", "\"mode\"", "\"material\"",
                 "\"alphaCutoff\"", "\"KHR_materials_volume\"", "\"attenuationDistance\"", "\"extensionsRequired\"",
                 "\".\"", "\"/dev/zero\"", "\"data:application/octet-stream;base64,AAAA\"", "5126", "5125", "5123", "5121",
                 "\"images\"", "\"textures\"", "\"samplers\"", "\"source\"", "\"sampler\"", "\"texCoord\"",
                 "\"TEXCOORD_1\"", "\"COLOR_0\"", "\"KHR_texture_transform\"", "\"mimeType\"", "\"image/png\"",
                 "33071", "33648", "9728", "9987"},
                [](const std::string& bytes, const fs::path& file) {
                    try {
                        GltfLoadReport report;
                        loadGltfFromMemory(bytes, file, report);
                        return true;
                    } catch (const LoadError&) {
                        return false;
                    }
                }};
    }
    if (name == "scene") {
        std::ofstream(scratch / "model.gltf") << triangleGltf();
        return {true,
                {".json"},
                {R"({"name":"s","camera":{"position":[0,0,5],"target":[0,0,0],"up":[0,1,0],"fov_y_deg":45},
"light_direction":[0,1,1],"background":[0.1,0.1,0.1],
"objects":[{"model":"model.gltf","name":"a","fit":2,"translate":[1,2,3],"rotate_deg":[10,20,30],"scale":[1,2,3],
"material":{"name":"m","base_color":[1,0,0],"alpha":0.5,"alpha_mode":"BLEND","alpha_cutoff":0.5,"tau":[1,2,3],
"albedo":[0.5,0.5,0.5],"double_sided":true}},{"model":"model.gltf","rotate_axis_angle":[0,1,0,90],"scale":2}]})"},
                {"\"objects\"", "\"model\"", "\"model.gltf\"", "\"fit\"", "\"translate\"", "\"rotate_deg\"",
                 "\"rotate_axis_angle\"", "\"scale\"", "\"material\"", "\"tau\"", "\"camera\"", "\"position\"",
                 "\"target\"", "\"light_direction\"", "\"background\"", "\"fov_y_deg\""},
                [scratch](const std::string& bytes, const fs::path&) {
                    try {
                        parseSceneDescription(bytes, scratch / "scene.json");
                        return true;
                    } catch (const LoadError&) {
                        return false;
                    }
                }};
    }
    if (name == "path") {
        return {true,
                {".path", ".txt"},
                {"# camera path\n0 0 0 5 0 0 0 1\n1 1 0 5 0 0.3826834 0 0.9238795 # turn\n1 2 0 5 0 0 0 1\n"},
                {"0 0 0 0 0 0 0 1\n", "1e-9"},
                [](const std::string& bytes, const fs::path& file) {
                    try {
                        CameraPath::parse(bytes, file.string());
                        return true;
                    } catch (const LoadError&) {
                        return false;
                    }
                }};
    }
#ifdef STRATA_FUZZ_TRACES
    if (name == "trace") {
        // One target for both layouts: the first byte of the input picks the parser.
        return {true,
                {".path", ".csv"},
                {"0 0 0 0 0 0 0 1\n0.5 0 1 0 0 0 0 1\n",
                 "Timestamp,PlaybackTime,UnitQuaternion.x,UnitQuaternion.y,UnitQuaternion.z,UnitQuaternion.w,"
                 "HmdPosition.x,HmdPosition.y,HmdPosition.z\n2016-12-05 10:00:00.000,0,0,0,0,1,0,1.6,0\n"
                 "2016-12-05 10:00:00.016,0.016,0,0.01,0,0.99995,0,1.6,0\n"},
                {"Timestamp", "UnitQuaternion.w", "HmdPosition.x", "2016-12-05 10:00:00.000", "2016-02-30T25:61:61"},
                [](const std::string& bytes, const fs::path& file) {
                    std::istringstream in(bytes);
                    try {
                        if (!bytes.empty() && bytes[0] == 'T') tracking::parseHeadMovementCsv(in, file.string());
                        else tracking::parseAnimationPath(in, file.string());
                        return true;
                    } catch (const TraceError&) {
                        return false;
                    }
                }};
    }
#endif
    std::fprintf(stderr, "strata_fuzz: unknown target '%s' (gltf, scene, path, trace)\n", name.c_str());
    std::exit(2);
}

std::vector<Seed> corpus(const Target& target, const std::vector<std::string>& places) {
    std::vector<Seed> seeds;
    for (const std::string& s : target.builtinSeeds) seeds.push_back({"builtin", s});
    auto wanted = [&](const fs::path& p) {
        std::error_code ec;
        if (!fs::is_regular_file(p, ec) || (!target.text && fs::file_size(p, ec) > kMaxBinarySeed)) return false;
        for (const auto& e : target.extensions)
            if (p.extension() == e) return true;
        return false;
    };
    for (const std::string& place : places) {
        std::error_code ec;
        if (!fs::exists(place, ec)) {
            std::printf("strata_fuzz: corpus %s absent, skipped\n", place.c_str());
            continue;
        }
        std::vector<fs::path> files;
        if (fs::is_directory(place, ec)) {
            for (const auto& e : fs::recursive_directory_iterator(place, ec))
                if (wanted(e.path())) files.push_back(e.path());
        } else if (wanted(place)) {
            files.push_back(place);
        }
        std::sort(files.begin(), files.end());  // the same order, so the same inputs, everywhere
        for (const auto& f : files) {
            std::string bytes = readAll(f);
            if (target.text && bytes.size() > kMaxTextSeed) bytes.resize(bytes.rfind('\n', kMaxTextSeed) + 1);
            seeds.push_back({f, bytes});
        }
    }
    return seeds;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 4) {
        std::fprintf(stderr, "usage: strata_fuzz TARGET COUNT|--dump INDEX SEED [CORPUS...]\n");
        return 2;
    }
    const std::string name = argv[1];
    int arg = 2;
    long long dumpIndex = -1;
    if (std::strcmp(argv[arg], "--dump") == 0) dumpIndex = std::atoll(argv[++arg]);
    const long long count = dumpIndex >= 0 ? dumpIndex + 1 : std::atoll(argv[arg]);
    const std::uint64_t seed = std::strtoull(argv[++arg], nullptr, 10);
    std::vector<std::string> places(argv + arg + 1, argv + argc);

    const fs::path scratch = fs::temp_directory_path() / ("strata-fuzz-" + std::to_string(::getpid()));
    fs::create_directories(scratch);
    const Target target = makeTarget(name, scratch);
    const std::vector<Seed> seeds = corpus(target, places);
    std::vector<std::string> tokens = strata::fuzz::commonTokens();
    tokens.insert(tokens.end(), target.tokens.begin(), target.tokens.end());
    strata::fuzz::Mutator mutator(seed, tokens, kMaxInput);

    std::signal(SIGALRM, onHang);
    long long loaded = 0, refused = 0;
    const auto start = std::chrono::steady_clock::now();
    int status = 0;
    for (long long i = 0; i < count; ++i) {
        const Seed& s = seeds[mutator.below(seeds.size())];
        std::string input = s.bytes;
        // Every 16th input is a seed as it is, so the loaders' accepting paths stay covered.
        if (mutator.below(16) != 0) mutator.mutate(input, seeds[mutator.below(seeds.size())].bytes);
        if (i == dumpIndex) {
            std::ofstream("fuzz-input.bin", std::ios::binary) << input;
            std::printf("strata_fuzz: input %lld (from %s) written to fuzz-input.bin\n", i, s.file.string().c_str());
            break;
        }
        gIndex = std::sig_atomic_t(i);
        ::alarm(kHangSeconds);
        if (i > 0 && i % 100000 == 0)  // progress of long runs
            std::fprintf(stderr, "strata_fuzz %s: %lld inputs, %.0f s\n", name.c_str(), i,
                         std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        try {
            (target.run(input, s.file) ? loaded : refused)++;
        } catch (const std::exception& e) {
            // Not the reader's error type: a bad_alloc, a library's exception let through.
            std::fprintf(stderr, "strata_fuzz: input %lld: unexpected %s: %s\n", i, typeid(e).name(), e.what());
            status = 1;
            break;
        }
    }
    ::alarm(0);
    std::error_code ec;
    fs::remove_all(scratch, ec);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (dumpIndex < 0)
        std::printf("strata_fuzz %s: %lld inputs (seed %llu, %zu corpus files): %lld loaded, %lld refused, %.1f s\n",
                    name.c_str(), loaded + refused, (unsigned long long)seed, seeds.size(), loaded, refused, seconds);
    return status;
}
