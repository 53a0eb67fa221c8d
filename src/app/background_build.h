// Where the sandbox builds a lane (pouring and settling its grains, seconds for thousands): on a
// thread of its own on the desktop (background_build_thread.cpp), so the window keeps answering;
// at once on the page (src/web/background_build_inline.cpp), which has no threads. The build
// picks the file; the lanes (lane_set.cpp) see only a future either way.
#pragma once

#include <functional>
#include <future>
#include <memory>

#include "sim/model_run.h"

namespace polyroll::app {

using LaneBuild = std::function<std::unique_ptr<ModelRun>()>;

// A future of the build's run (or of what it threw).
std::future<std::unique_ptr<ModelRun>> build_in_background(LaneBuild build);

}  // namespace polyroll::app
