#pragma once
// Program objects are recycled, never deleted while the context lives.
//
// Why: on NVIDIA (driver 580, H100 and H200; docs/gpu-h200-session3.md) a program linked under
// the name of one just deleted sometimes renders its first frame wrong (an object missing, a
// surface shaded brighter), and the driver reuses a deleted program's name at once. Keeping
// every program alive made all 936 repeated renders of the diagnostic agree; Mesa never showed it.
// So a program built by gl::buildProgram is, when its owner lets go of it, kept here under its
// source text; the next build of the same text takes it back instead of creating a new name.
// Memory stays bounded by the most programs of one text alive at once, summed over the texts
// (670 retired at the end of the whole GL test suite, of 553 compiled). Shader objects (which
// share the name space) are deleted as before: keeping programs alive alone made the fault go.
//
// A recycled program is handed out as if new: the values its uniforms had right after the link
// (zeros, and the sampler and image units of layout(binding)) are restored, so no owner sees the
// last owner's values.
#include <epoxy/gl.h>

#include <string>

namespace strata::gl {

// Records that `program`, just linked or loaded from `key` (the preprocessed stage texts), may be
// recycled under that key, with its uniforms' values as they are now.
void registerProgram(GLuint program, const std::string& key);

// A retired program built from `key`, its uniforms restored; 0 where there is none.
GLuint takeRetiredProgram(const std::string& key);

// Called by gl::Program's owner when it lets go: a registered program is retired (kept for its
// text), any other (a failed link, a refused binary) is kept too, never handed out, so that no
// program name is freed while the context lives.
void retireProgram(GLuint program);

// How many programs are retired now, and how many builds took one back.
struct ProgramPoolStats {
    std::size_t retired = 0;
    std::size_t recycled = 0;
};
ProgramPoolStats programPoolStats();

// Deletes every retired program and forgets every registration: the context is going away
// (gl::HeadlessContext's destructor, with the context current).
void releaseProgramPool();

}  // namespace strata::gl
