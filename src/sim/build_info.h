// What `--version` prints for both programs: the project's version (CMake's project() version), the
// Box2D the binary links (its b2_version, not the header it was compiled against) and the build type.
#pragma once

#include <string>

namespace polyroll {

// "polyroll 0.1.0 (Box2D 2.4.1, build type Release)" for program "polyroll".
std::string version_text(const std::string& program);

}  // namespace polyroll
