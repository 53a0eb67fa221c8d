// `polyroll bench --auto`: `--model auto` against `--model grains` on the empty shells of issue 13
// (n = 6, 8, 10, 18 at 5, 10, 20, 30 degrees): wall time, speed-up, hand-over and how far apart the
// two runs end, with the rigid model alone and one grain run at the reference preset as yardsticks,
// and what the rigid model's rolling needs (faces that would hop, friction). A benchmark prints;
// tests/test_auto_model.cpp asserts.
#pragma once

#include "sim/scene.h"

namespace polyroll::cli {

// `base`: the scene the empty shells are made from (its fill ratio is set to 0, sides and angle vary).
void bench_auto(const Scene& base, int repeats);

}  // namespace polyroll::cli
