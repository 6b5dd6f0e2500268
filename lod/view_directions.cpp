#include "lod/view_directions.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>

namespace strata::lod {

namespace {

// The icosahedron's 12 vertices: cyclic permutations of (0, +-1, +-phi).
std::vector<glm::vec3> icosahedronVertices() {
    const float phi = (1.0f + std::sqrt(5.0f)) * 0.5f;
    std::vector<glm::vec3> v;
    for (float a : {-1.0f, 1.0f})
        for (float b : {-phi, phi}) {
            v.push_back(glm::normalize(glm::vec3(0.0f, a, b)));
            v.push_back(glm::normalize(glm::vec3(a, b, 0.0f)));
            v.push_back(glm::normalize(glm::vec3(b, 0.0f, a)));
        }
    return v;
}

// The dodecahedron's 20 vertices as the directions of the icosahedron's face centres (the two
// solids are dual), so the combined set of 32 is the pentakis dodecahedron's vertices. Faces are
// the vertex triples pairwise one edge (the smallest distance) apart, in index order.
std::vector<glm::vec3> dodecahedronVertices() {
    const auto ico = icosahedronVertices();
    float maxDot = -1.0f;
    for (std::size_t i = 1; i < ico.size(); ++i) maxDot = std::max(maxDot, glm::dot(ico[0], ico[i]));
    auto adjacent = [&](std::size_t a, std::size_t b) { return glm::dot(ico[a], ico[b]) > maxDot - 1e-4f; };
    std::vector<glm::vec3> v;
    for (std::size_t i = 0; i < ico.size(); ++i)
        for (std::size_t j = i + 1; j < ico.size(); ++j)
            for (std::size_t k = j + 1; k < ico.size(); ++k)
                if (adjacent(i, j) && adjacent(j, k) && adjacent(i, k))
                    v.push_back(glm::normalize(ico[i] + ico[j] + ico[k]));
    return v;
}

}  // namespace

bool isValidViewCount(int count) { return count == 12 || count == 20 || count == 32; }

std::vector<glm::vec3> viewDirections(int count) {
    if (count == 12) return icosahedronVertices();
    if (count == 20) return dodecahedronVertices();
    if (count == 32) {
        auto v = icosahedronVertices();
        auto d = dodecahedronVertices();
        v.insert(v.end(), d.begin(), d.end());
        return v;
    }
    throw std::invalid_argument("impostor view count " + std::to_string(count) + " is not 12, 20 or 32");
}

std::vector<int> nearestViews(const std::vector<glm::vec3>& dirs, const glm::vec3& v, int k) {
    std::vector<int> order(dirs.size());
    std::iota(order.begin(), order.end(), 0);
    std::vector<float> dots(dirs.size());
    for (std::size_t i = 0; i < dirs.size(); ++i) dots[i] = glm::dot(dirs[i], v);
    k = std::clamp(k, 0, int(dirs.size()));
    std::partial_sort(order.begin(), order.begin() + k, order.end(),
                      [&](int a, int b) { return dots[a] != dots[b] ? dots[a] > dots[b] : a < b; });
    order.resize(std::size_t(k));
    return order;
}

float angleToNearestView(const std::vector<glm::vec3>& dirs, const glm::vec3& v) {
    const float len = glm::length(v);
    if (dirs.empty() || !(len > 0.0f)) return 0.0f;
    float best = -1.0f;
    for (const auto& d : dirs) best = std::max(best, glm::dot(d, v / len));
    return std::acos(std::clamp(best, -1.0f, 1.0f));
}

float minPairwiseAngle(const std::vector<glm::vec3>& dirs) {
    float maxDot = -1.0f;
    for (std::size_t i = 0; i < dirs.size(); ++i)
        for (std::size_t j = i + 1; j < dirs.size(); ++j) maxDot = std::max(maxDot, glm::dot(dirs[i], dirs[j]));
    return std::acos(std::clamp(maxDot, -1.0f, 1.0f));
}

std::vector<glm::vec3> fibonacciSphere(int count) {
    std::vector<glm::vec3> out;
    out.reserve(std::size_t(std::max(count, 0)));
    const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < count; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / count;
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double a = golden * i;
        out.emplace_back(float(r * std::cos(a)), float(r * std::sin(a)), float(z));
    }
    return out;
}

float coveringRadius(const std::vector<glm::vec3>& dirs, int samples) {
    float worst = 0.0f;
    for (const auto& s : fibonacciSphere(samples)) worst = std::max(worst, angleToNearestView(dirs, s));
    return worst;
}

std::vector<std::pair<int, int>> adjacentViews(const std::vector<glm::vec3>& dirs, int samples) {
    std::set<std::pair<int, int>> pairs;
    if (dirs.size() < 3) return {};
    for (const auto& s : fibonacciSphere(samples)) {
        const auto n = nearestViews(dirs, s, 3);
        pairs.insert({n[0], n[1]});
        pairs.insert({n[0], n[2]});
    }
    return {pairs.begin(), pairs.end()};
}

}  // namespace strata::lod
