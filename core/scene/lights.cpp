#include "scene/lights.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace strata {

static_assert(sizeof(gpu::PunctualLight) == 64, "PunctualLight is four vec4s, as std140 lays out the GLSL struct");

namespace {

gpu::PunctualLight toPunctual(const Light& l, const glm::mat4& world) {
    gpu::PunctualLight p{};
    int type = gpu::kLightDirectional;
    if (l.type == Light::Type::Point) type = gpu::kLightPoint;
    if (l.type == Light::Type::Spot) type = gpu::kLightSpot;
    p.colorType = glm::vec4(l.color * l.intensity, float(type));
    p.positionRange = glm::vec4(glm::vec3(world[3]), l.range);
    glm::vec3 along = glm::vec3(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
    const float len = glm::length(along);
    along = len > 0.0f && std::isfinite(len) ? along / len : glm::vec3(0.0f, 0.0f, -1.0f);
    // The extension's smoothed cone: scale and offset from the two angles, the difference kept
    // from vanishing when they coincide.
    const float cosOuter = std::cos(l.outerConeAngle), cosInner = std::cos(l.innerConeAngle);
    const float scale = 1.0f / std::max(1e-3f, cosInner - cosOuter);
    p.directionCone = glm::vec4(along, scale);
    p.coneOffset = glm::vec4(-cosOuter * scale, 0.0f, 0.0f, 0.0f);
    return p;
}

struct Placer {
    const Scene& scene;
    std::vector<gpu::PunctualLight> lights;
    std::vector<char> onPath;

    void visit(int node, const glm::mat4& parent) {
        if (node < 0 || std::size_t(node) >= scene.nodes.size()) throw std::runtime_error("lights: bad node index");
        if (onPath[std::size_t(node)]) throw std::runtime_error("lights: the node graph has a cycle");
        const Node& n = scene.nodes[std::size_t(node)];
        const glm::mat4 world = parent * n.local;
        if (n.light >= 0) {
            if (std::size_t(n.light) >= scene.lights.size()) throw std::runtime_error("lights: bad light index");
            if (lights.size() >= std::size_t(gpu::kMaxLights))
                throw std::runtime_error("lights: more than " + std::to_string(gpu::kMaxLights) + " placed lights");
            lights.push_back(toPunctual(scene.lights[std::size_t(n.light)], world));
        }
        onPath[std::size_t(node)] = 1;
        for (int child : n.children) visit(child, world);
        onPath[std::size_t(node)] = 0;
    }
};

}  // namespace

gpu::PunctualLight defaultLight(const Scene& scene) {
    // A directional light shining along -lightDirection (position, range and cone unused).
    gpu::PunctualLight p{};
    p.colorType = glm::vec4(glm::vec3(gpu::kDefaultLightIrradiance), float(gpu::kLightDirectional));
    p.directionCone = glm::vec4(-glm::normalize(scene.lightDirection), 1.0f);
    return p;
}

std::vector<gpu::PunctualLight> placeLights(const Scene& scene) {
    if (scene.lights.empty()) return {defaultLight(scene)};
    Placer p{scene, {}, std::vector<char>(scene.nodes.size(), 0)};
    for (int root : scene.roots) p.visit(root, glm::mat4(1.0f));
    return std::move(p.lights);
}

}  // namespace strata
