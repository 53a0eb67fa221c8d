// The step a series stays accurate over: see taylor_series.h.
#include "sim/reduced/taylor_series.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace polyroll::models {

namespace {
// Step = this share of the estimated radius of convergence: the first neglected term is then about
// 0.2^21 = 2e-15 of the coefficients' scale (radians), so a whole ramp of a few hundred steps keeps
// its energy to about 1e-13.
constexpr double kStepShare = 0.2;
constexpr int N = kSeriesOrder;
}  // namespace

double accurate_step_s(const Series& angle) {
    double rho = std::numeric_limits<double>::infinity();
    for (const auto& [c, k] : {std::pair{std::fabs(angle[N - 1]), N - 1}, std::pair{std::fabs(angle[N]), N}})
        if (c > 0.0) rho = std::min(rho, std::pow(c, -1.0 / k));
    return kStepShare * rho;
}

}  // namespace polyroll::models
