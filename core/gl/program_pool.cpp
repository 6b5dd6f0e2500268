#include "gl/program_pool.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace strata::gl {
namespace {

// One uniform location's value right after the link, to be set again on a recycled program.
struct UniformValue {
    GLint location = -1;
    GLenum type = 0;
    std::array<std::uint32_t, 32> bits{};  // up to a dmat4: 16 doubles
};

struct Registered {
    const std::string* key = nullptr;  // interned: a key is a whole program's text, tens of kB
    std::vector<UniformValue> initial;
    bool retired = false;
};

struct Pool {
    std::mutex mutex;
    std::unordered_set<std::string> keys;                              // one copy of each text
    std::unordered_map<GLuint, Registered> registered;                 // every live or retired program
    std::unordered_multimap<const std::string*, GLuint> retired;       // a program nobody owns, by key
    // Programs never registered (a failed link, a refused binary, one made by glCreateShaderProgramv):
    // not handed out again, but not deleted either, so their names are not reused.
    std::vector<GLuint> graveyard;
    std::size_t recycled = 0;
};

// Never destroyed: programs held by static objects are let go after main() returns, when a
// function-local static pool could already be gone.
Pool& pool() {
    static Pool* p = new Pool;
    return *p;
}

enum class Kind { Float, Int, Uint, Double, None };

// How a uniform of `type` is read and set: its scalar kind, and its columns and rows (1 for a
// vector's columns).
struct Shape {
    Kind kind = Kind::None;
    int columns = 1, rows = 1;
};

Shape shapeOf(GLenum type) {
    switch (type) {
        case GL_FLOAT: return {Kind::Float, 1, 1};
        case GL_FLOAT_VEC2: return {Kind::Float, 1, 2};
        case GL_FLOAT_VEC3: return {Kind::Float, 1, 3};
        case GL_FLOAT_VEC4: return {Kind::Float, 1, 4};
        case GL_FLOAT_MAT2: return {Kind::Float, 2, 2};
        case GL_FLOAT_MAT3: return {Kind::Float, 3, 3};
        case GL_FLOAT_MAT4: return {Kind::Float, 4, 4};
        case GL_FLOAT_MAT2x3: return {Kind::Float, 2, 3};
        case GL_FLOAT_MAT2x4: return {Kind::Float, 2, 4};
        case GL_FLOAT_MAT3x2: return {Kind::Float, 3, 2};
        case GL_FLOAT_MAT3x4: return {Kind::Float, 3, 4};
        case GL_FLOAT_MAT4x2: return {Kind::Float, 4, 2};
        case GL_FLOAT_MAT4x3: return {Kind::Float, 4, 3};
        case GL_DOUBLE: return {Kind::Double, 1, 1};
        case GL_DOUBLE_VEC2: return {Kind::Double, 1, 2};
        case GL_DOUBLE_VEC3: return {Kind::Double, 1, 3};
        case GL_DOUBLE_VEC4: return {Kind::Double, 1, 4};
        case GL_DOUBLE_MAT2: return {Kind::Double, 2, 2};
        case GL_DOUBLE_MAT3: return {Kind::Double, 3, 3};
        case GL_DOUBLE_MAT4: return {Kind::Double, 4, 4};
        case GL_DOUBLE_MAT2x3: return {Kind::Double, 2, 3};
        case GL_DOUBLE_MAT2x4: return {Kind::Double, 2, 4};
        case GL_DOUBLE_MAT3x2: return {Kind::Double, 3, 2};
        case GL_DOUBLE_MAT3x4: return {Kind::Double, 3, 4};
        case GL_DOUBLE_MAT4x2: return {Kind::Double, 4, 2};
        case GL_DOUBLE_MAT4x3: return {Kind::Double, 4, 3};
        case GL_INT: case GL_BOOL: return {Kind::Int, 1, 1};
        case GL_INT_VEC2: case GL_BOOL_VEC2: return {Kind::Int, 1, 2};
        case GL_INT_VEC3: case GL_BOOL_VEC3: return {Kind::Int, 1, 3};
        case GL_INT_VEC4: case GL_BOOL_VEC4: return {Kind::Int, 1, 4};
        case GL_UNSIGNED_INT: return {Kind::Uint, 1, 1};
        case GL_UNSIGNED_INT_VEC2: return {Kind::Uint, 1, 2};
        case GL_UNSIGNED_INT_VEC3: return {Kind::Uint, 1, 3};
        case GL_UNSIGNED_INT_VEC4: return {Kind::Uint, 1, 4};
        case GL_UNSIGNED_INT_ATOMIC_COUNTER: return {};  // not a settable value
        default: return {Kind::Int, 1, 1};  // what core 4.5 has left: samplers and images, their unit
    }
}

std::vector<UniformValue> readUniforms(GLuint program) {
    std::vector<UniformValue> values;
    GLint count = 0, maxName = 0;
    glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
    glGetProgramiv(program, GL_ACTIVE_UNIFORM_MAX_LENGTH, &maxName);
    std::string name(std::size_t(std::max(maxName, 1)), '\0');
    for (GLint i = 0; i < count; ++i) {
        GLint size = 0;
        GLenum type = 0;
        GLsizei length = 0;
        glGetActiveUniform(program, GLuint(i), GLsizei(name.size()), &length, &size, &type, name.data());
        const Shape shape = shapeOf(type);
        if (shape.kind == Kind::None) continue;
        std::string base(name.data(), std::size_t(length));
        if (base.size() > 3 && base.compare(base.size() - 3, 3, "[0]") == 0) base.resize(base.size() - 3);
        for (GLint e = 0; e < size; ++e) {
            const std::string element = size > 1 ? base + "[" + std::to_string(e) + "]" : base;
            UniformValue v;
            v.location = glGetUniformLocation(program, element.c_str());
            if (v.location < 0) continue;  // a member of a uniform block
            v.type = type;
            switch (shape.kind) {
                case Kind::Float: glGetUniformfv(program, v.location, reinterpret_cast<GLfloat*>(v.bits.data())); break;
                case Kind::Int: glGetUniformiv(program, v.location, reinterpret_cast<GLint*>(v.bits.data())); break;
                case Kind::Uint: glGetUniformuiv(program, v.location, v.bits.data()); break;
                case Kind::Double: glGetUniformdv(program, v.location, reinterpret_cast<GLdouble*>(v.bits.data())); break;
                case Kind::None: break;
            }
            values.push_back(v);
        }
    }
    return values;
}

// glProgramUniform{1..4}{f,i,ui,d}v for a vector of `rows` components, and
// glProgramUniformMatrix{C}x{R}{f,d}v for `columns` x `rows` (2..4 each): tables indexed by
// the shape, so each type's setter follows from shapeOf alone.
template <class Setter, class T>
void setVector(const std::array<Setter, 4>& setters, int rows, GLuint program, GLint at, const T* values) {
    setters[std::size_t(rows - 1)](program, at, 1, values);
}
template <class Setter, class T>
void setMatrix(const std::array<std::array<Setter, 3>, 3>& setters, const Shape& s, GLuint program, GLint at,
               const T* values) {
    setters[std::size_t(s.columns - 2)][std::size_t(s.rows - 2)](program, at, 1, GL_FALSE, values);
}

void restoreUniform(GLuint program, const UniformValue& v) {
    const Shape s = shapeOf(v.type);
    const auto* f = reinterpret_cast<const GLfloat*>(v.bits.data());
    const auto* d = reinterpret_cast<const GLdouble*>(v.bits.data());
    const GLint at = v.location;
    switch (s.kind) {
        case Kind::Float:
            if (s.columns > 1)
                setMatrix<PFNGLPROGRAMUNIFORMMATRIX2FVPROC>(
                    {{{glProgramUniformMatrix2fv, glProgramUniformMatrix2x3fv, glProgramUniformMatrix2x4fv},
                      {glProgramUniformMatrix3x2fv, glProgramUniformMatrix3fv, glProgramUniformMatrix3x4fv},
                      {glProgramUniformMatrix4x2fv, glProgramUniformMatrix4x3fv, glProgramUniformMatrix4fv}}},
                    s, program, at, f);
            else
                setVector<PFNGLPROGRAMUNIFORM1FVPROC>(
                    {glProgramUniform1fv, glProgramUniform2fv, glProgramUniform3fv, glProgramUniform4fv}, s.rows,
                    program, at, f);
            break;
        case Kind::Double:
            if (s.columns > 1)
                setMatrix<PFNGLPROGRAMUNIFORMMATRIX2DVPROC>(
                    {{{glProgramUniformMatrix2dv, glProgramUniformMatrix2x3dv, glProgramUniformMatrix2x4dv},
                      {glProgramUniformMatrix3x2dv, glProgramUniformMatrix3dv, glProgramUniformMatrix3x4dv},
                      {glProgramUniformMatrix4x2dv, glProgramUniformMatrix4x3dv, glProgramUniformMatrix4dv}}},
                    s, program, at, d);
            else
                setVector<PFNGLPROGRAMUNIFORM1DVPROC>(
                    {glProgramUniform1dv, glProgramUniform2dv, glProgramUniform3dv, glProgramUniform4dv}, s.rows,
                    program, at, d);
            break;
        case Kind::Int:
            setVector<PFNGLPROGRAMUNIFORM1IVPROC>(
                {glProgramUniform1iv, glProgramUniform2iv, glProgramUniform3iv, glProgramUniform4iv}, s.rows, program,
                at, reinterpret_cast<const GLint*>(v.bits.data()));
            break;
        case Kind::Uint:
            setVector<PFNGLPROGRAMUNIFORM1UIVPROC>(
                {glProgramUniform1uiv, glProgramUniform2uiv, glProgramUniform3uiv, glProgramUniform4uiv}, s.rows,
                program, at, v.bits.data());
            break;
        case Kind::None: break;
    }
}

}  // namespace

void registerProgram(GLuint program, const std::string& key) {
    std::vector<UniformValue> initial = readUniforms(program);
    Pool& p = pool();
    std::lock_guard lock(p.mutex);
    const std::string* interned = &*p.keys.insert(key).first;
    p.registered[program] = Registered{interned, std::move(initial)};
}

GLuint takeRetiredProgram(const std::string& key) {
    Pool& p = pool();
    std::lock_guard lock(p.mutex);
    auto interned = p.keys.find(key);
    if (interned == p.keys.end()) return 0;
    auto it = p.retired.find(&*interned);
    if (it == p.retired.end()) return 0;
    const GLuint program = it->second;
    p.retired.erase(it);
    Registered& r = p.registered.at(program);
    r.retired = false;
    for (const UniformValue& v : r.initial) restoreUniform(program, v);
    ++p.recycled;
    return program;
}

void retireProgram(GLuint program) {
    Pool& p = pool();
    std::lock_guard lock(p.mutex);
    auto it = p.registered.find(program);
    if (it == p.registered.end()) {
        p.graveyard.push_back(program);
        return;
    }
    if (it->second.retired) return;  // let go twice: still one entry, so never two owners
    it->second.retired = true;
    p.retired.emplace(it->second.key, program);
}

ProgramPoolStats programPoolStats() {
    Pool& p = pool();
    std::lock_guard lock(p.mutex);
    return {p.retired.size(), p.recycled};
}

void releaseProgramPool() {
    Pool& p = pool();
    std::lock_guard lock(p.mutex);
    for (const auto& [key, program] : p.retired) glDeleteProgram(program);
    for (GLuint program : p.graveyard) glDeleteProgram(program);
    p.retired.clear();
    p.graveyard.clear();
    p.registered.clear();
    p.keys.clear();
}

}  // namespace strata::gl
