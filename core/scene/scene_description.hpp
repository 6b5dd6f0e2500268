#pragma once
// Scene descriptions: a small JSON file that places glTF models with transforms and optional
// material overrides (so untextured, material-less meshes can be made transparent). Format:
//
// { "name": "fandisk-glass",                                   optional, default: file stem
//   "camera": {"position": [x,y,z], "target": [x,y,z],         optional
//              "up": [0,1,0], "fov_y_deg": 45},                up and fov optional
//   "light_direction": [x,y,z],                                optional, towards the light
//   "background": [r,g,b],                                     optional, linear RGB
//   "wireframe": true | {"width": 0.01, "color": [r,g,b],      optional: a translucent wireframe
//                        "alpha": 0.55},                       over every transparent object, in
//                                                              its triangles' planes (wireframe.hpp)
//   "objects": [                                               required, at least one
//     { "model": "../../shared/scenes-data/fandisk.glb",       relative to the JSON file's folder
//       "name": "...",                                         optional
//       "fit": 2.0,                                            optional: centre the model's bounds
//                                                              at the origin and scale its largest
//                                                              extent to this size, before the rest
//       "scale": s or [sx,sy,sz],                              optional
//       "rotate_deg": [x,y,z]  or  "rotate_axis_angle": [ax,ay,az,deg],   optional; Euler angles
//                                                              apply about X, then Y, then Z
//       "translate": [x,y,z],                                  optional
//       "material": { "name": "...", "base_color": [r,g,b], "alpha": 0.5,
//                     "alpha_mode": "OPAQUE"|"MASK"|"BLEND", "alpha_cutoff": 0.5,
//                     "tau": [r,g,b], "albedo": [r,g,b], "double_sided": true } } ] }
//
// An object's transform is translate * rotate * scale * fit. Each object becomes a root node
// whose children are the model's roots; a "material" replaces every material of that model
// (Node::materialOverride) and starts from Material's defaults, except that alpha_mode
// defaults to BLEND when alpha < 1. Unknown keys are errors (they are usually typos).
#include "scene/load_error.hpp"
#include "scene/scene.hpp"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace strata {

// Throws LoadError("<json file>: <what is wrong>"); a model that fails to load gives
// "<json file>: object N: <the loader's message>". The glTF loader's warnings for the models
// (GltfLoadReport::warnings, each naming its model file) are appended to `warnings` when given,
// each line once however many objects place that model.
// The file is read through readBoundedFile (io/bounded_read.hpp): a regular file of at most
// kSceneDescriptionLimit bytes. Every number is checked as the float it becomes, and each
// object's transform (with its fit) must be finite in float: the message names the key.
Scene loadSceneDescription(const std::filesystem::path& jsonFile, std::vector<std::string>* warnings = nullptr);

// The same from text already in memory; `jsonFile` names it and is the folder models are
// resolved against.
Scene parseSceneDescription(std::string_view text, const std::filesystem::path& jsonFile,
                            std::vector<std::string>* warnings = nullptr);

}  // namespace strata
