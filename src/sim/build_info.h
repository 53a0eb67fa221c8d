// What `--version` prints for both programs: the project's version (CMake's project() version), the
// version of Box2D's package (which the library's own b2_version lags) and the build type.
#pragma once

#include <string>

namespace polyroll {

// "polyroll 0.1.0 (Box2D 2.4.1, build type Release)" for program "polyroll".
std::string version_text(const std::string& program);

}  // namespace polyroll
