// polyroll bench's rendering section: frames per second of headless 1280x720 frames.
#pragma once

#include "sim/scene/scene.h"

namespace polyroll::cli {

void bench_rendering(const Scene& scene, int repeats);

}  // namespace polyroll::cli
