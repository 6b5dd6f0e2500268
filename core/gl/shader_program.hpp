#pragma once
// GLSL programs from files in shaders/, with `#include "file"` (relative to the including file,
// then to the shader root, then to shaders/common) and `#define` injection after `#version`. A compile or link error
// throws ShaderError whose first line names the file and line, e.g.
//   shaders/oit/abuffer_resolve.frag.glsl:42: error: syntax error ...
#include "gl/objects.hpp"

#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace strata::gl {

struct ShaderError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// `name=value` pairs; an empty value gives a plain `#define NAME`.
using Defines = std::map<std::string, std::string>;

// The shader root: $STRATA_SHADER_DIR if set, else the source tree's shaders/.
std::filesystem::path shaderRoot();

// Result of preprocessing one stage: the text and, for each `#line` source number, its file.
struct PreprocessedSource {
    std::string text;
    std::vector<std::string> files;
};

// Files (relative to the shader root) expanded right after the #version line and the defines,
// and at the very end, of the stage they wrap: scene programs wrap their fragment stage so one
// main() runs before every technique's (render/scene_program.cpp).
struct StageWrap {
    std::string prelude;
    std::string epilogue;
};

PreprocessedSource preprocessShader(const std::filesystem::path& file, const Defines& defines,
                                    const std::filesystem::path& root, const StageWrap& wrap = {});

// Rewrites driver log lines ("0:12(5): error" Mesa, "0(12) : error" NVIDIA) to "file:12: error".
std::string mapShaderLog(const std::string& log, const std::vector<std::string>& files);

// Programs built in this process: compiled from source, loaded from the in-process binary cache
// (buildProgram reuses the binary of a program with the same preprocessed stages), and binaries
// the driver refused. compileSeconds: wall time of the compiled ones, preprocessing included.
struct ProgramBuildStats {
    int compiled = 0;
    int loaded = 0;
    int rejected = 0;
    double compileSeconds = 0.0;
};
ProgramBuildStats programBuildStats();

// Builds a program from stage files (stage from the name: .vert/.frag/.comp/.geom.glsl),
// given relative to the shader root.
// `fragmentWrap` wraps the fragment stage.
Program buildProgram(const std::vector<std::string>& stageFiles, const Defines& defines = {},
                     const StageWrap& fragmentWrap = {});

}  // namespace strata::gl
