#pragma once
// The view directions a layered impostor is baked from (Schaufler section 3.4, Fig. 5): unit
// vectors on a platonic solid, and the queries the draw needs on them (nearest views, the
// angle to the nearest, which views are adjacent for hole filling, section 3.3 / Fig. 6 right).
#include <glm/glm.hpp>

#include <utility>
#include <vector>

namespace strata::lod {

// 12: the icosahedron's vertices (= the dodecahedron's face normals); 20: the dodecahedron's
// vertices (= the icosahedron's face normals); 32: both. Any other count throws
// std::invalid_argument. Unit length; the order is fixed (a view's index names its atlas layers).
std::vector<glm::vec3> viewDirections(int count);
bool isValidViewCount(int count);

// Indices of the `k` directions nearest `v` (v need not be unit length), nearest first (largest
// dot product first; equal dots by index). k is clamped to dirs.size().
std::vector<int> nearestViews(const std::vector<glm::vec3>& dirs, const glm::vec3& v, int k);

// Angle in radians between `v` and the nearest direction.
float angleToNearestView(const std::vector<glm::vec3>& dirs, const glm::vec3& v);

// The smallest angle (radians) between any two directions.
float minPairwiseAngle(const std::vector<glm::vec3>& dirs);

// Estimated covering radius (radians): the largest angle from any of `samples` Fibonacci
// directions to its nearest view. A lower bound that converges from below as samples grow.
float coveringRadius(const std::vector<glm::vec3>& dirs, int samples = 20000);

// `count` near-uniform unit directions on the sphere (Fibonacci lattice).
std::vector<glm::vec3> fibonacciSphere(int count);

// The hole-filling adjacency: ordered pairs (V, Vi), V the nearest view for some direction and
// Vi one of the two others of its 3 nearest, over `samples` Fibonacci directions. Sorted, unique.
std::vector<std::pair<int, int>> adjacentViews(const std::vector<glm::vec3>& dirs, int samples = 4000);

}  // namespace strata::lod
