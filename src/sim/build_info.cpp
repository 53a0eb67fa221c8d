// See build_info.h. POLYROLL_VERSION and POLYROLL_BUILD_TYPE come from src/CMakeLists.txt.
#include "sim/build_info.h"

#include <box2d/box2d.h>
#include <fmt/core.h>

#ifndef POLYROLL_VERSION
#error "POLYROLL_VERSION must be defined by the build (src/CMakeLists.txt)"
#endif
#ifndef POLYROLL_BOX2D_VERSION
#define POLYROLL_BOX2D_VERSION ""
#endif
#ifndef POLYROLL_BUILD_TYPE
#error "POLYROLL_BUILD_TYPE must be defined by the build (src/CMakeLists.txt)"
#endif

namespace polyroll {

std::string version_text(const std::string& program) {
    // A multi-config generator or a build without CMAKE_BUILD_TYPE leaves the type empty.
    const std::string type = std::string(POLYROLL_BUILD_TYPE).empty() ? "unspecified" : POLYROLL_BUILD_TYPE;
    // Box2D's version as its package states it (CMake's box2d_VERSION, 2.4.1): the library's own
    // b2_version still says 2.4.0 in 2.4.1's sources, so it is only the fallback.
    std::string box2d = POLYROLL_BOX2D_VERSION;
    if (box2d.empty()) box2d = fmt::format("{}.{}.{}", b2_version.major, b2_version.minor, b2_version.revision);
    return fmt::format("{} {} (Box2D {}, build type {})", program, POLYROLL_VERSION, box2d, type);
}

}  // namespace polyroll
