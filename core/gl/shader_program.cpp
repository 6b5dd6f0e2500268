#include "gl/shader_program.hpp"

#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

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
        if (!top) out.text += "#line 1 " + std::to_string(index) + "\n";
        while (std::getline(lines, line)) {
            ++lineNumber;
            std::smatch m;
            if (!versionSeen && line.rfind("#version", 0) == 0) {
                versionSeen = true;
                out.text += line + "\n";
                for (const auto& [name, value] : defines) out.text += "#define " + name + " " + value + "\n";
                if (!wrap.prelude.empty()) expand(root / wrap.prelude, displayName(file) + " (prelude)", false, {});
                out.text += "#line " + std::to_string(lineNumber + 1) + " " + std::to_string(index) + "\n";
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

Program buildProgram(const std::vector<std::string>& stageFiles, const Defines& defines, const StageWrap& fragmentWrap) {
    fs::path root = shaderRoot();
    Program program = Program::create();
    std::vector<Shader> shaders;
    for (const auto& name : stageFiles) {
        GLenum stage = stageOf(name);
        PreprocessedSource source =
            preprocessShader(root / name, defines, root, stage == GL_FRAGMENT_SHADER ? fragmentWrap : StageWrap{});
        Shader shader(glCreateShader(stage));
        const char* text = source.text.c_str();
        glShaderSource(shader.id(), 1, &text, nullptr);
        glCompileShader(shader.id());
        GLint ok = 0;
        glGetShaderiv(shader.id(), GL_COMPILE_STATUS, &ok);
        if (!ok) {
            GLint length = 0;
            glGetShaderiv(shader.id(), GL_INFO_LOG_LENGTH, &length);
            std::string log(std::size_t(std::max(length, 1)), '\0');
            glGetShaderInfoLog(shader.id(), length, nullptr, log.data());
            std::string mapped = mapShaderLog(log.c_str(), source.files);
            if (mapped.empty()) mapped = source.files.front() + ": compile failed without a log\n";
            throw ShaderError(mapped.substr(0, mapped.size() - 1));
        }
        glAttachShader(program.id(), shader.id());
        shaders.push_back(std::move(shader));
    }
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
    return program;
}

}  // namespace strata::gl
