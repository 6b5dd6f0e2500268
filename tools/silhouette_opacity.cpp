// strata-silhouette: silhouette opacity measured (Sen, Chemudugunta, Gopi, sections 3-5).
//
// For a transparent sphere (builtin) or any scene with no opaque geometry, renders each technique
// twice, over a white and over a black background, and takes each pixel's opacity as
// 1 - (white - black), averaged over RGB: exact for any technique whose output is linear in the
// background (all of them; the screen-door techniques draw the same samples in both renders, the
// seed being fixed). Pixels are binned by the viewing angle acos|N_z| of the first surface the
// pixel's ray meets (the CPU ray cast's hit triangle, its face normal against the ray), 0 degrees
// face-on to 90 at the rim.
//
// Beside the techniques, two exact columns from the same ray cast, per pixel:
//   alpha: conventional alpha compositing, every crossing of alpha a_i lets (1 - a_i) through:
//          T = prod (1 - a_i). What `abuffer` renders (measured in its own column, a check).
//   shell: the paper's model, a thin shell of absorbing material whose face-on crossing lets
//          (1 - a) through; at angle theta the path through the shell is 1/|N_z| longer, so
//          T = prod (1 - a_i)^(1/|N_z,i|). Object-space sampling at one sample per supersampled
//          pixel converges to this: 1/|N_z| points land per sample, each kept with probability a.
// Writes one CSV row per angle bin (wide: one column per method) and optionally a markdown table.
#include "camera/camera.hpp"
#include "frame/frame_renderer.hpp"
#include "gl/context.hpp"
#include "gl/debug.hpp"
#include "image/image.hpp"
#include "io/atomic_file.hpp"
#include "oit/technique.hpp"
#include "oit/technique_settings.hpp"
#include "reference/raycast.hpp"
#include "render/gpu_scene.hpp"
#include "scene/mesh_builders.hpp"
#include "scene/scene_source.hpp"

#include <CLI/CLI.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

using namespace strata;

namespace {

struct Args {
    std::string scene = "sphere";
    float alpha = 0.3f;
    int size = 256;
    int supersampling = 16;
    int bins = 9;
    std::string modes = "abuffer,crow,screendoor,screendoor-object,screendoor-object-sw";
    std::string csv, markdown;
};

// A unit sphere of `alpha` (black, so the picture shows transmittance) at 3 units down -Z from a
// camera at the origin (fov 50 degrees): it fills about three quarters of the view's height.
Scene sphereScene(float alpha) {
    Scene s;
    s.name = "sphere";
    s.materials.push_back(Material{});
    Material m;
    m.name = "shell";
    m.baseColor = glm::vec3(0.0f);
    m.alpha = alpha;
    m.alphaMode = AlphaMode::Blend;
    Node n;
    n.meshes = {s.addMesh(makeSphere(1.0f, 256, 128))};
    n.materialOverride = s.addMaterial(m);
    n.local = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -3.0f));
    s.addNode(std::move(n));
    s.camera = CameraPose{};
    return s;
}

std::vector<std::string> split(const std::string& text) {
    std::vector<std::string> out;
    std::stringstream in(text);
    for (std::string id; std::getline(in, id, ',');)
        if (!id.empty()) out.push_back(id);
    return out;
}

// What the ray cast says about one pixel.
struct PixelTruth {
    bool hit = false;
    double angleDegrees = 0.0;  // acos |N_z| of the first crossing
    double nz = 0.0;
    double alphaT = 1.0;        // prod (1 - a_i)
    double shellT = 1.0;        // prod (1 - a_i)^(1/|N_z,i|)
    int crossings = 0;
};

std::vector<PixelTruth> castTruth(const GpuScene& gpu, const Camera& camera, int size) {
    const Scene& scene = gpu.scene();
    const auto& objects = gpu.objects();
    std::map<int, const Object*> byId;
    for (const Object& o : objects) byId[o.id] = &o;
    RaycastReference reference(scene, objects);
    std::vector<PixelTruth> truth(std::size_t(size) * size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            PixelSample sample = reference.samplePixel(camera, size, size, x, y);
            if (sample.hasOpaque) throw std::invalid_argument("the scene has opaque geometry at pixel (" + std::to_string(x) + ", " +
                                                              std::to_string(y) + "): opacity needs nothing behind");
            glm::dvec3 origin, direction;
            pixelRay(camera, size, size, x, y, origin, direction);
            direction = glm::normalize(direction);
            PixelTruth& t = truth[std::size_t(y) * size + x];
            for (const SurfaceFragment& f : sample.fragments) {
                const Object& o = *byId.at(f.object);
                const Mesh& mesh = scene.meshes[std::size_t(o.mesh)];
                glm::dvec3 p[3];
                for (int i = 0; i < 3; ++i)
                    p[i] = glm::dvec3(o.world * glm::vec4(mesh.positions[mesh.indices[3 * std::size_t(f.primitive) + i]], 1.0f));
                const double nz = std::abs(glm::dot(glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0])), direction));
                if (t.crossings == 0) {
                    t.hit = true;
                    t.nz = nz;
                    t.angleDegrees = glm::degrees(std::acos(std::min(nz, 1.0)));
                }
                t.alphaT *= 1.0 - f.alpha;
                t.shellT *= std::pow(1.0 - f.alpha, 1.0 / std::max(nz, 1e-6));
                ++t.crossings;
            }
        }
    return truth;
}

struct Bin {
    int pixels = 0;
    double nz = 0.0, crossings = 0.0, alpha = 0.0, shell = 0.0;
    std::vector<double> measured;
};

void run(const Args& a) {
    for (const std::string& out : {a.csv, a.markdown})
        if (!out.empty()) checkWritable(out);
    const std::vector<std::string> modes = split(a.modes);
    for (const std::string& id : modes)
        if (!findTechnique(id)) throw std::invalid_argument("--modes: unknown technique '" + id + "'");

    Scene white = a.scene == "sphere" ? sphereScene(a.alpha) : openScene(a.scene);
    white.background = glm::vec3(1.0f);
    Scene black = white;
    black.background = glm::vec3(0.0f);
    gl::HeadlessContext context;
    GpuScene gpuWhite(std::move(white)), gpuBlack(std::move(black));
    if (!gpuWhite.hasTransparency()) throw std::invalid_argument(a.scene + ": nothing transparent to measure");
    if (!gpuWhite.opaqueObjects().empty())
        throw std::invalid_argument(a.scene + ": has opaque objects; opacity needs nothing but the background behind");
    const Camera camera = defaultCamera(gpuWhite.scene(), gpuWhite.objects());
    // The alpha the CSV names: the sphere's, or the first transparent object's material.
    const double sceneAlpha =
        gpuWhite.scene().materials[std::size_t(gpuWhite.objects()[std::size_t(gpuWhite.transparentObjects().front())].material)].alpha;

    std::fprintf(stderr, "ray casting %dx%d for the viewing angles and the exact columns\n", a.size, a.size);
    const std::vector<PixelTruth> truth = castTruth(gpuWhite, camera, a.size);
    std::vector<Bin> bins(std::size_t(a.bins));
    const double width = 90.0 / a.bins;
    auto binOf = [&](const PixelTruth& t) { return std::min(a.bins - 1, int(t.angleDegrees / width)); };
    for (const PixelTruth& t : truth) {
        if (!t.hit) continue;
        Bin& b = bins[std::size_t(binOf(t))];
        ++b.pixels;
        b.nz += t.nz;
        b.crossings += t.crossings;
        b.alpha += 1.0 - t.alphaT;
        b.shell += 1.0 - t.shellT;
    }

    std::vector<std::string> notes;
    for (const std::string& id : modes) {
        auto technique = createTechnique(id);
        for (const auto& d : findTechnique(id)->settings)
            if (d.name == "supersampling")
                applySettings(*technique, {{"supersampling=" + std::to_string(a.supersampling), "--supersampling"}});
        std::fprintf(stderr, "%s: %s\n", id.c_str(), formatSettings(technique->settingDescriptions(), technique->settings()).c_str());
        FrameRenderer renderer;
        FrameOptions options;
        options.timePasses = false;
        FrameResult onWhite = renderer.render(gpuWhite, camera, {a.size, a.size}, technique.get(), options);
        const Image w = renderer.readOutput();
        renderer.render(gpuBlack, camera, {a.size, a.size}, technique.get(), options);
        const Image k = renderer.readOutput();
        gl::checkGl(id.c_str());
        if (onWhite.stats.overflowed)
            notes.push_back(id + " overflowed (" + std::to_string(onWhite.stats.fragmentsDropped) + " dropped)");
        for (Bin& b : bins) b.measured.push_back(0.0);
        for (int y = 0; y < a.size; ++y)
            for (int x = 0; x < a.size; ++x) {
                const PixelTruth& t = truth[std::size_t(y) * a.size + x];
                if (!t.hit) continue;
                const glm::vec3 through = glm::vec3(w.at(x, y)) - glm::vec3(k.at(x, y));
                bins[std::size_t(binOf(t))].measured.back() += 1.0 - (through.r + through.g + through.b) / 3.0;
            }
    }

    std::ostringstream csv, md;
    csv << "scene,alpha,supersampling,angle_lo,angle_hi,nz_mean,pixels,crossings_mean,exact_alpha,exact_shell";
    md << "| angle (deg) | mean abs(N_z) | pixels | exact alpha | exact shell |";
    for (const std::string& id : modes) {
        csv << "," << id;
        md << " `" << id << "` |";
    }
    csv << "\n";
    md << "\n|---|---:|---:|---:|---:|";
    for (std::size_t i = 0; i < modes.size(); ++i) md << "---:|";
    md << "\n";
    char buffer[128];
    for (int i = 0; i < a.bins; ++i) {
        const Bin& b = bins[std::size_t(i)];
        if (b.pixels == 0) continue;
        const double n = b.pixels;
        csv << (a.scene == "sphere" ? "sphere" : a.scene) << "," << sceneAlpha << "," << a.supersampling << "," << i * width << ","
            << (i + 1) * width << "," << b.nz / n << "," << b.pixels << "," << b.crossings / n << "," << b.alpha / n << ","
            << b.shell / n;
        std::snprintf(buffer, sizeof buffer, "| %.0f-%.0f | %.3f | %d | %.3f | %.3f |", i * width, (i + 1) * width, b.nz / n,
                      b.pixels, b.alpha / n, b.shell / n);
        md << buffer;
        for (double m : b.measured) {
            csv << "," << m / n;
            std::snprintf(buffer, sizeof buffer, " %.3f |", m / n);
            md << buffer;
        }
        csv << "\n";
        md << "\n";
    }
    for (const std::string& note : notes) std::fprintf(stderr, "strata-silhouette: warning: %s\n", note.c_str());
    if (!a.csv.empty()) writeTextFile(a.csv, csv.str());
    if (!a.markdown.empty()) writeTextFile(a.markdown, md.str());
    std::cout << md.str();
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"silhouette opacity: opacity against viewing angle, per technique, measured over white and black"};
    Args a;
    app.add_option("scene", a.scene, "'sphere' (builtin, --alpha), or a scene with no opaque objects")->capture_default_str();
    app.add_option("--alpha", a.alpha, "the sphere's alpha")->check(CLI::Range(0.0, 1.0))->capture_default_str();
    app.add_option("--size", a.size, "image side in pixels")->check(CLI::Range(8, 4096))->capture_default_str();
    app.add_option("--supersampling", a.supersampling, "n of n x n for the techniques that have it")->capture_default_str();
    app.add_option("--bins", a.bins, "angle bins over 0-90 degrees")->check(CLI::Range(1, 90))->capture_default_str();
    app.add_option("--modes", a.modes, "technique ids, comma-separated")->capture_default_str();
    app.add_option("--csv", a.csv, "write the bins as CSV here");
    app.add_option("--markdown", a.markdown, "write the bins as a markdown table here");
    CLI11_PARSE(app, argc, argv);
    try {
        run(a);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "strata-silhouette: %s\n", e.what());
        return 1;
    }
    return 0;
}
