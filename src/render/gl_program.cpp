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

// Throws with GL's log unless `object`'s `status` (a shader's compile, a program's link) is true, deleting it.
void require(GLuint object, GLenum status, void (*get_iv)(GLuint, GLenum, GLint*),
             void (*get_log)(GLuint, GLsizei, GLsizei*, GLchar*), void (*destroy)(GLuint), const char* what) {
    GLint ok = 0;
    get_iv(object, status, &ok);
    if (ok) return;
    char log[2048] = {};
    get_log(object, sizeof log, nullptr, log);
    destroy(object);
    throw std::runtime_error(std::string(what) + log);
}

GLuint compile(GLenum type, const char* body, const char* shared_prefix) {
    const std::string src = std::string(kGlslVersion) + "\n" + kGlslPreamble + shared_prefix + body;
    const GLuint s = glCreateShader(type);
    const char* text = src.c_str();
    glShaderSource(s, 1, &text, nullptr);
    glCompileShader(s);
    require(s, GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog, glDeleteShader, "GL shader does not compile: ");
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
    require(p, GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog, glDeleteProgram, "GL program does not link: ");
    return p;
}

}  // namespace polyroll::render
