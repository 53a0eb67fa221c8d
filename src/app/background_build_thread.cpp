// Lane builds on threads of their own (the desktop): see background_build.h.
#include "app/background_build.h"

#include <utility>

namespace polyroll::app {

std::future<std::unique_ptr<ModelRun>> build_in_background(LaneBuild build) {
    return std::async(std::launch::async, std::move(build));
}

}  // namespace polyroll::app
