// `polyroll bench --auto --ensemble K`: see bench_auto.h.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "cli/bench_auto.h"
#include "sim/errors.h"
#include "sim/scene/fidelity_preset.h"
#include "sim/model_registry.h"
#include "sweep/scene_matrices.h"
#include "sim/scene/scene_validate.h"

namespace polyroll::cli {

namespace {

// Terminal velocities of one model over the members; runs that did not reach the end give none.
struct Spread {
    std::vector<double> v_m_s;
    int missing = 0;

    void add(const std::optional<double>& v) {
        if (v) v_m_s.push_back(*v);
        else ++missing;
    }
    double mean() const {
        double sum = 0.0;
        for (double v : v_m_s) sum += v;
        return sum / static_cast<double>(v_m_s.size());
    }
    std::string text() const {
        if (v_m_s.empty()) return "-";
        const auto [lo, hi] = std::minmax_element(v_m_s.begin(), v_m_s.end());
        return fmt::format("{:.3f} [{:.3f}-{:.3f}]{}", mean(), *lo, *hi, missing ? "*" : "");
    }
};

// (mean - ref's mean) / ref's mean, if both have runs that reached the end.
std::optional<double> mean_off(const Spread& a, const Spread& ref) {
    if (a.v_m_s.empty() || ref.v_m_s.empty()) return std::nullopt;
    return (a.mean() - ref.mean()) / ref.mean();
}

std::string percent(const std::optional<double>& x) { return x ? fmt::format("{:+.1f}%", 100.0 * *x) : "-"; }

}  // namespace

void bench_auto_ensemble(const Scene& base, int members) {
    fmt::print("\nthe same shells over {} releases each, tilted {:g} to {:g} degrees past balance (0.001 apart):\n"
               "terminal velocity mean [min-max] in m/s, and how far each mean is from the finest Box2D's\n",
               members, base.release.tilt_deg, base.release.tilt_deg + 0.001 * (members - 1));
    fmt::print("{:>3} {:>5} {:>24} {:>24} {:>24} {:>7} {:>7}  {}\n", "n", "deg", "auto", "grains", "fine", "a-fine",
               "g-fine", "nearer");
    int auto_within = 0, grains_within = 0, auto_nearer = 0, compared = 0;
    constexpr double kWithin = 0.02;  // auto's agreement bound, 2%
    for (const auto& [sides, angle] : scenes::auto_shells()) {
        Spread a, g, f;
        Scene s = scenes::empty_shell(base, sides, angle);
        s.release.tilt_deg = base.release.tilt_deg + 0.001 * (members - 1);
        try {
            validate_scene(s);  // the largest tilt; a --tilt fit for the base shell may not fit this one
        } catch (const InputError& e) {
            fmt::print("{:>3} {:>5g}  skipped: {}\n", sides, angle, e.what());
            continue;
        }
        for (int k = 0; k < members; ++k) {
            s.release.tilt_deg = base.release.tilt_deg + 0.001 * k;
            s.run.model = Model::automatic;
            a.add(run_scene(s).measured.terminal_velocity_m_s);
            s.run.model = Model::grains;
            g.add(run_scene(s).measured.terminal_velocity_m_s);
            f.add(run_scene(at_finest_box2d(s)).measured.terminal_velocity_m_s);
        }
        const std::optional<double> a_off = mean_off(a, f), g_off = mean_off(g, f);
        std::string nearer = "-";
        if (a_off && g_off) {
            const bool auto_is = std::fabs(*a_off) <= std::fabs(*g_off);
            nearer = auto_is ? "auto" : "grains";
            auto_nearer += auto_is ? 1 : 0;
            auto_within += std::fabs(*a_off) <= kWithin ? 1 : 0;
            grains_within += std::fabs(*g_off) <= kWithin ? 1 : 0;
            ++compared;
        }
        fmt::print("{:>3} {:>5g} {:>24} {:>24} {:>24} {:>7} {:>7}  {}\n", sides, angle, a.text(), g.text(), f.text(),
                   percent(a_off), percent(g_off), nearer);
        std::fflush(stdout);
    }
    fmt::print("of the {} that reach the end: auto's mean within 2% of the finest Box2D's in {}, grains' in {};\n"
               "auto's the nearer in {}. grains: --model grains at the scene's fidelity; fine: Box2D at 80,000\n"
               "steps a second; *: some members did not reach the end (no terminal velocity).\n",
               compared, auto_within, grains_within, auto_nearer);
}

}  // namespace polyroll::cli
