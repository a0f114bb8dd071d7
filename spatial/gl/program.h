// GLSL programs and GL object lifetimes for the OpenGL backend. Every function here needs the
// context current on the calling thread (CurrentContext, context.h).
#pragma once

#include <epoxy/gl.h>

#include <initializer_list>
#include <string_view>
#include <utility>

namespace lexel::spatial::gl {

struct ShaderSource {
    GLenum stage;             // GL_VERTEX_SHADER, GL_FRAGMENT_SHADER, GL_COMPUTE_SHADER
    std::string_view source;  // GLSL 4.50
};

// Compiles and links the stages into a program. Throws GlUnavailable with the driver's log when a
// stage does not compile or the program does not link.
GLuint BuildProgram(std::initializer_list<ShaderSource> stages);

// Throws GlUnavailable naming `what` when glGetError reports an error (drains the queue).
void CheckGlError(const char* what);

}  // namespace lexel::spatial::gl
