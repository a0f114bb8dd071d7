#include "lexel/spatial/gl/program.h"

#include <string>
#include <vector>

#include "lexel/spatial/gl/context.h"

namespace lexel::spatial::gl {

namespace {

std::string ShaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return log.c_str();
}

std::string ProgramLog(GLuint program) {
    GLint length = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<std::size_t>(std::max(length, 1)), '\0');
    glGetProgramInfoLog(program, length, nullptr, log.data());
    return log.c_str();
}

}  // namespace

GLuint BuildProgram(std::initializer_list<ShaderSource> stages) {
    const GLuint program = glCreateProgram();
    std::vector<GLuint> shaders;
    for (const ShaderSource& stage : stages) {
        const GLuint shader = glCreateShader(stage.stage);
        const char* text = stage.source.data();
        const GLint length = static_cast<GLint>(stage.source.size());
        glShaderSource(shader, 1, &text, &length);
        glCompileShader(shader);
        GLint ok = GL_FALSE;
        glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
        if (!ok) {
            const std::string log = ShaderLog(shader);
            glDeleteShader(shader);
            for (GLuint s : shaders) glDeleteShader(s);
            glDeleteProgram(program);
            throw GlUnavailable("GLSL compile failed: " + log);
        }
        glAttachShader(program, shader);
        shaders.push_back(shader);
    }
    glLinkProgram(program);
    for (GLuint s : shaders) glDeleteShader(s);  // flagged; freed with the program
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        const std::string log = ProgramLog(program);
        glDeleteProgram(program);
        throw GlUnavailable("GLSL link failed: " + log);
    }
    return program;
}

void CheckGlError(const char* what) {
    GLenum first = GL_NO_ERROR;
    for (GLenum e = glGetError(); e != GL_NO_ERROR; e = glGetError())
        if (first == GL_NO_ERROR) first = e;
    if (first != GL_NO_ERROR)
        throw GlUnavailable(std::string(what) + ": OpenGL error 0x" + [first] {
            char hex[16];
            std::snprintf(hex, sizeof hex, "%04x", first);
            return std::string(hex);
        }());
}

}  // namespace lexel::spatial::gl
