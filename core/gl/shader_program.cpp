#include "gl/shader_program.hpp"

#include "gl/debug.hpp"
#include "gl/program_pool.hpp"

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <mutex>
#include <set>
#include <sstream>
#include <unordered_map>

namespace strata::gl {
namespace fs = std::filesystem;

fs::path shaderRoot() {
    if (const char* env = std::getenv("STRATA_SHADER_DIR"); env && *env) return env;
    return STRATA_SHADER_DIR;
}

namespace {

std::string readFile(const fs::path& file, const std::string& includedFrom) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw ShaderError(file.string() + ": cannot open shader file" + includedFrom);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Preprocessor {
    fs::path root;
    PreprocessedSource out;
    std::set<std::string> including;  // guards against include cycles
    // Where #extension lines go: right after #version, before the defines and any prelude. GLSL
    // allows them only before the first non-preprocessor token, so one in a scene shader or an
    // include (after the scene prelude's declarations) is moved there, unconditionally: one
    // inside an #if is moved out of it, so use `enable`, which an absent extension only warns
    // about, and test the extension's own macro. npos: no #version yet.
    std::size_t extensionAt = std::string::npos;

    int fileIndex(const std::string& name) {
        out.files.push_back(name);
        return int(out.files.size()) - 1;
    }

    std::string displayName(const fs::path& file) const {
        auto rel = file.lexically_relative(root.parent_path());
        return rel.empty() ? file.string() : rel.string();
    }

    void expand(const fs::path& file, const std::string& from, bool top, const Defines& defines,
                const StageWrap& wrap = {}) {
        std::string canonical = fs::weakly_canonical(file).string();
        if (including.count(canonical)) throw ShaderError(from + ": #include cycle through " + file.string());
        including.insert(canonical);
        std::string text = readFile(file, from.empty() ? "" : " (included from " + from + ")");
        int index = fileIndex(displayName(file));
        std::istringstream lines(text);
        std::string line;
        int lineNumber = 0;
        bool versionSeen = !top;
        static const std::regex includeRe(R"(^\s*#\s*include\s+\"([^\"]+)\"\s*$)");
        static const std::regex extensionRe(R"(^\s*#\s*extension\s[^\n]*$)");  // [^\n]: CRLF files too
        if (!top) out.text += "#line 1 " + std::to_string(index) + "\n";
        while (std::getline(lines, line)) {
            ++lineNumber;
            std::smatch m;
            if (!versionSeen && line.rfind("#version", 0) == 0) {
                versionSeen = true;
                out.text += line + "\n";
                extensionAt = out.text.size();
                for (const auto& [name, value] : defines) out.text += "#define " + name + " " + value + "\n";
                if (!wrap.prelude.empty()) expand(root / wrap.prelude, displayName(file) + " (prelude)", false, {});
                out.text += "#line " + std::to_string(lineNumber + 1) + " " + std::to_string(index) + "\n";
                continue;
            }
            if (extensionAt != std::string::npos && std::regex_match(line, extensionRe)) {
                const std::string hoisted = line + "\n";
                out.text.insert(extensionAt, hoisted);
                extensionAt += hoisted.size();
                out.text += "\n";  // keeps the line numbers that follow
                continue;
            }
            if (std::regex_match(line, m, includeRe)) {
                fs::path target = file.parent_path() / m[1].str();
                if (!fs::exists(target)) target = root / m[1].str();
                if (!fs::exists(target)) target = root / "common" / m[1].str();
                expand(target, displayName(file) + ":" + std::to_string(lineNumber), false, {});
                out.text += "#line " + std::to_string(lineNumber + 1) + " " + std::to_string(index) + "\n";
                continue;
            }
            out.text += line + "\n";
        }
        if (top && !versionSeen) throw ShaderError(displayName(file) + ":1: missing #version line");
        if (top && !wrap.epilogue.empty()) expand(root / wrap.epilogue, displayName(file) + " (epilogue)", false, {});
        including.erase(canonical);
    }
};

GLenum stageOf(const std::string& file) {
    if (file.find(".vert.") != std::string::npos) return GL_VERTEX_SHADER;
    if (file.find(".frag.") != std::string::npos) return GL_FRAGMENT_SHADER;
    if (file.find(".comp.") != std::string::npos) return GL_COMPUTE_SHADER;
    if (file.find(".geom.") != std::string::npos) return GL_GEOMETRY_SHADER;
    throw ShaderError(file + ": cannot tell the shader stage from the name (.vert/.frag/.comp/.geom.glsl)");
}

}  // namespace

PreprocessedSource preprocessShader(const fs::path& file, const Defines& defines, const fs::path& root,
                                    const StageWrap& wrap) {
    Preprocessor p{root, {}, {}};
    p.expand(file, "", true, defines, wrap);
    return std::move(p.out);
}

std::string mapShaderLog(const std::string& log, const std::vector<std::string>& files) {
    static const std::regex mesaRe(R"(^(\d+):(\d+)\(\d+\):\s*(.*)$)");
    static const std::regex nvRe(R"(^(\d+)\((\d+)\)\s*:\s*(.*)$)");
    std::istringstream in(log);
    std::string line, out;
    while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_match(line, m, mesaRe) || std::regex_match(line, m, nvRe)) {
            std::size_t index = std::stoul(m[1].str());
            std::string name = index < files.size() ? files[index] : "source " + m[1].str();
            line = name + ":" + m[2].str() + ": " + m[3].str();
        }
        if (!line.empty()) out += line + "\n";
    }
    return out;
}

namespace {

// Programs already linked in this process, by their exact preprocessed stage texts: a bench
// or a test run builds the same program again for every technique object it makes, and a
// driver that compiles to machine code (NVIDIA) spends tens to hundreds of milliseconds on a
// resolve shader where loading its binary takes about one. Binaries are valid for the driver
// that produced them, so the cache lives no longer than the process. STRATA_PROGRAM_CACHE=0
// turns it off (to time compilation). A driver that offers no binary format (Mesa with its disk
// shader cache turned off) gets no cache: every build compiles, as before.
struct ProgramBinary {
    GLenum format = 0;
    std::vector<char> data;
};
constexpr std::size_t kProgramCacheBytes = std::size_t(256) << 20;

struct ProgramCache {
    std::mutex mutex;
    std::unordered_map<std::string, ProgramBinary> binaries;
    std::size_t bytes = 0;
    ProgramBuildStats stats;
};

ProgramCache& programCache() {
    static ProgramCache cache;
    return cache;
}

// Whether the environment variable `name` is not "0": the switches of what is on by default.
bool notSwitchedOff(const char* name) {
    const char* env = std::getenv(name);
    return !(env && std::string(env) == "0");
}

bool programCacheEnabled() {
    static const bool enabled = notSwitchedOff("STRATA_PROGRAM_CACHE");
    return enabled;
}

// STRATA_PROGRAM_POOL=0: programs are deleted when let go, their names free for reuse (the
// behaviour gl/program_pool.hpp works around).
bool programPoolEnabled() {
    static const bool enabled = notSwitchedOff("STRATA_PROGRAM_POOL");
    return enabled;
}

// The program from a cached binary, or an empty handle where there is none or the driver
// refuses it (a driver may reject its own binary, e.g. after an update: then compile).
Program loadCachedProgram(const std::string& key) {
    if (!programCacheEnabled()) return {};
    ProgramCache& cache = programCache();
    std::lock_guard lock(cache.mutex);
    auto it = cache.binaries.find(key);
    if (it == cache.binaries.end()) return {};
    Program program = Program::create();
    glProgramBinary(program.id(), it->second.format, it->second.data.data(), GLsizei(it->second.data.size()));
    GLint ok = 0;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        cache.bytes -= it->first.size() + it->second.data.size();
        cache.binaries.erase(it);
        ++cache.stats.rejected;
        return {};
    }
    ++cache.stats.loaded;
    return program;
}

void storeProgramBinary(const std::string& key, GLuint program) {
    if (!programCacheEnabled()) return;
    GLint formats = 0, length = 0;
    glGetIntegerv(GL_NUM_PROGRAM_BINARY_FORMATS, &formats);
    if (formats <= 0) return;
    glGetProgramiv(program, GL_PROGRAM_BINARY_LENGTH, &length);
    ProgramCache& cache = programCache();
    std::lock_guard lock(cache.mutex);
    // The cap counts the keys (whole preprocessed texts) as well as the binaries.
    if (length <= 0 || cache.bytes + key.size() + std::size_t(length) > kProgramCacheBytes) return;
    ProgramBinary binary;
    binary.data.resize(std::size_t(length));
    GLsizei written = 0;
    glGetProgramBinary(program, length, &written, &binary.format, binary.data.data());
    if (written <= 0) return;
    binary.data.resize(std::size_t(written));
    cache.bytes += key.size() + binary.data.size();
    cache.binaries.insert_or_assign(key, std::move(binary));
}

}  // namespace

ProgramBuildStats programBuildStats() {
    ProgramCache& cache = programCache();
    std::lock_guard lock(cache.mutex);
    return cache.stats;
}

namespace {

// STRATA_DEBUG_FINISH_BUILDS=1: glFinish after every program build, loaded or compiled. A
// diagnostic for drivers that finish a link asynchronously (docs/gpu-h100.md, group 2: an object
// drawn by a program built inside the frame goes missing on NVIDIA); it costs a stall per build.
void finishIfDebugging() {
    static const bool finish = debugSwitch("STRATA_DEBUG_FINISH_BUILDS");
    if (finish) glFinish();
}

Program buildProgramUnsynchronized(const std::vector<std::string>& stageFiles, const Defines& defines,
                                   const StageWrap& fragmentWrap);

}  // namespace

Program buildProgram(const std::vector<std::string>& stageFiles, const Defines& defines, const StageWrap& fragmentWrap) {
    Program program = buildProgramUnsynchronized(stageFiles, defines, fragmentWrap);
    finishIfDebugging();
    return program;
}

namespace {

Program buildProgramUnsynchronized(const std::vector<std::string>& stageFiles, const Defines& defines,
                                   const StageWrap& fragmentWrap) {
    const auto started = std::chrono::steady_clock::now();
    fs::path root = shaderRoot();
    struct Stage {
        GLenum type;
        PreprocessedSource source;
    };
    std::vector<Stage> stages;
    std::string key;
    for (const auto& name : stageFiles) {
        GLenum type = stageOf(name);
        stages.push_back({type, preprocessShader(root / name, defines, root,
                                                 type == GL_FRAGMENT_SHADER ? fragmentWrap : StageWrap{})});
        key += std::to_string(type) + '\n' + stages.back().source.text + '\0';
    }
    // A retired program of the same text first (gl/program_pool.hpp: why names are not reused).
    if (programPoolEnabled()) {
        if (GLuint recycled = takeRetiredProgram(key)) return Program(recycled);
    }
    if (Program cached = loadCachedProgram(key)) {
        if (programPoolEnabled()) registerProgram(cached.id(), key);
        return cached;
    }

    Program program = Program::create();
    std::vector<Shader> shaders;
    for (const auto& stage : stages) {
        Shader shader(glCreateShader(stage.type));
        const char* text = stage.source.text.c_str();
        glShaderSource(shader.id(), 1, &text, nullptr);
        glCompileShader(shader.id());
        GLint ok = 0;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (!ok) {
            GLint length = 0;
            glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &length);
            std::string log(std::size_t(std::max(length, 1)), '\0');
            glGetShaderInfoLog(shader.id(), length, nullptr, log.data());
            std::string mapped = mapShaderLog(log.c_str(), stage.source.files);
            if (mapped.empty()) mapped = stage.source.files.front() + ": compile failed without a log\n";
            throw ShaderError(mapped.substr(0, mapped.size() - 1));
        }
        glAttachShader(program.id(), shader.id());
        shaders.push_back(std::move(shader));
    }
    if (programCacheEnabled()) glProgramParameteri(program.id(), GL_PROGRAM_BINARY_RETRIEVABLE_HINT, GL_TRUE);
    glLinkProgram(program.id());
    GLint ok = 0;
    glGetProgramiv(program.id(), GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program.id(), GL_INFO_LOG_LENGTH, &length);
        std::string log(std::size_t(std::max(length, 1)), '\0');
        glGetProgramInfoLog(program.id(), length, nullptr, log.data());
        std::string files;
        for (const auto& n : stageFiles) files += (files.empty() ? "" : " + ") + n;
        throw ShaderError(files + ": link failed: " + std::string(log.c_str()));
    }
    for (auto& s : shaders) glDetachShader(program.id(), s.id());
    {
        ProgramCache& cache = programCache();
        std::lock_guard lock(cache.mutex);
        ++cache.stats.compiled;
        cache.stats.compileSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    }
    storeProgramBinary(key, program.id());
    if (programPoolEnabled()) registerProgram(program.id(), key);
    return program;
}

}  // namespace

void deleteProgram(GLuint name) {
    if (programPoolEnabled()) retireProgram(name);
    else glDeleteProgram(name);
}

}  // namespace strata::gl
