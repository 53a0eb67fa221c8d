// The first line of every shader, chosen by the build: GLSL 3.30 core on the desktop and for the
// headless frames (OpenGL 3.3 core, OSMesa), GLSL ES 3.00 in the web page (WebGL 2; the web build
// defines POLYROLL_GLSL_ES). The shaders' bodies are one source, written in the common subset
// (explicit float literals, no implicit int-to-float conversions) so both compile them.
#pragma once

namespace polyroll::render {

#ifdef POLYROLL_GLSL_ES
inline constexpr const char* kGlslVersion = "#version 300 es";
// ES has no default float precision in fragment shaders; highp everywhere matches the desktop.
inline constexpr const char* kGlslPreamble = "precision highp float;\n";
#else
inline constexpr const char* kGlslVersion = "#version 330 core";
inline constexpr const char* kGlslPreamble = "";
#endif

}  // namespace polyroll::render
