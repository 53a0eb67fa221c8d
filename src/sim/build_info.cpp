// See build_info.h. POLYROLL_VERSION and POLYROLL_BUILD_TYPE come from src/CMakeLists.txt.
#include "sim/build_info.h"

#include <box2d/box2d.h>
#include <fmt/core.h>

#ifndef POLYROLL_VERSION
#error "POLYROLL_VERSION must be defined by the build (src/CMakeLists.txt)"
#endif
#ifndef POLYROLL_BUILD_TYPE
#error "POLYROLL_BUILD_TYPE must be defined by the build (src/CMakeLists.txt)"
#endif

namespace polyroll {

std::string version_text(const std::string& program) {
    // b2_version as the linked library states it: Box2D 2.4.1's own sources still say 2.4.0.
    // A multi-config generator or a build without CMAKE_BUILD_TYPE leaves the type empty.
    const std::string type = std::string(POLYROLL_BUILD_TYPE).empty() ? "unspecified" : POLYROLL_BUILD_TYPE;
    return fmt::format("{} {} (Box2D {}.{}.{}, build type {})", program, POLYROLL_VERSION, b2_version.major,
                       b2_version.minor, b2_version.revision, type);
}

}  // namespace polyroll
