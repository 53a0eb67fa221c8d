// Shader programs: see gl_program.h.
#define GL_GLEXT_PROTOTYPES 1
#include "render/gl_program.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <stdexcept>
#include <string>

#include "render/glsl_version.h"

namespace polyroll::render {

namespace {

GLuint compile(GLenum type, const char* body, const char* shared_prefix) {
    const std::string src = std::string(kGlslVersion) + "\n" + kGlslPreamble + shared_prefix + body;
    const GLuint s = glCreateShader(type);
    const char* text = src.c_str();
    glShaderSource(s, 1, &text, nullptr);
    glCompileShader(s);
    GLint ok = 0;
    glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetShaderInfoLog(s, sizeof log, nullptr, log);
        glDeleteShader(s);
        throw std::runtime_error(std::string("GL shader does not compile: ") + log);
    }
    return s;
}

}  // namespace

unsigned link_program(const char* vertex_body, const char* fragment_body, const char* shared_prefix) {
    const GLuint vs = compile(GL_VERTEX_SHADER, vertex_body, shared_prefix);
    const GLuint fs = compile(GL_FRAGMENT_SHADER, fragment_body, shared_prefix);
    const GLuint p = glCreateProgram();
    glAttachShader(p, vs);
    glAttachShader(p, fs);
    glLinkProgram(p);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetProgramInfoLog(p, sizeof log, nullptr, log);
        glDeleteProgram(p);
        throw std::runtime_error(std::string("GL program does not link: ") + log);
    }
    return p;
}

}  // namespace polyroll::render
