// A GL program from the bodies of its two shaders, each given the build's GLSL version line and
// preamble (glsl_version.h) and a shared prefix (functions both stages use).
#pragma once

namespace polyroll::render {

// Needs a current GL context; throws std::runtime_error with GL's log when a shader does not
// compile or the program does not link.
unsigned link_program(const char* vertex_body, const char* fragment_body, const char* shared_prefix = "");

}  // namespace polyroll::render
