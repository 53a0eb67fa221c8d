// The 2D cross-section against the 3D reference: see cross_section.h.
#include "sweep/cross_section.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "sim/assets.h"
#include "sweep/scene_matrices.h"
#include "sweep/grid_values.h"

namespace polyroll::sweep {
namespace {

using json = nlohmann::ordered_json;

// The air track, as the experiment rolled its small polygons: a whole-ramp 3D run of the hexagon a
// quarter full costs about 40 CPU-seconds, so the matrix takes about half an hour on two cores.
const json kBase = {{"shell", {{"preset", "hexagon-small"}}}, {"fill", {{"material", "bb"}}}, {"ramp", {{"preset", "air-track"}}}};
const std::vector<std::string> kModels = {"grains", "dem3d"};
const std::vector<unsigned> kSeeds = {1, 2};

struct Run {
    std::string shell, model;
    double fill = 0.0, angle = 0.0;
    unsigned seed = 0;
    bool ok = false;
    std::string behaviour;
    double distance_m = NAN, vt_m_s = NAN, wall_s = NAN, first_kept = NAN;
};

std::string cell(const TableFile& t, const std::vector<std::string>& row, const std::string& name) {
    const auto it = std::find(t.header.begin(), t.header.end(), name);
    return it == t.header.end() ? std::string() : row.at(static_cast<std::size_t>(it - t.header.begin()));
}
double number(const std::string& s) { return s.empty() ? NAN : std::stod(s); }
std::string fixed(double v, int digits) { return std::isfinite(v) ? fmt::format("{:.{}f}", v, digits) : "-"; }

// The first impact's kinetic energy ratio read kKineticDelay_s after the landing (impacts.csv's
// ratio_3ms), NaN without one.
double first_impact_kept(const std::filesystem::path& impacts_csv) {
    std::ifstream in(impacts_csv);
    std::string header, first;
    if (!std::getline(in, header) || !std::getline(in, first)) return NAN;
    std::vector<std::string> names, cells;
    std::string c;
    for (std::istringstream h(header); std::getline(h, c, ',');) names.push_back(c);
    for (std::istringstream r(first); std::getline(r, c, ',');) cells.push_back(c);
    for (std::size_t i = 0; i < names.size() && i < cells.size(); ++i)
        if (names[i] == "ratio_3ms") return number(cells[i]);
    return NAN;
}

int sides_of(const std::string& shell_preset) {
    return assets::preset_values(assets::Kind::polygon, shell_preset).at("sides").get<int>();
}

std::string short_name(const std::string& behaviour) {
    if (behaviour == "stopped_at_first_impact") return "first impact";
    if (behaviour == "rolled_to_end") return "end";
    if (behaviour == "stopped") return "stopped";
    return behaviour;
}

struct Scene2 {
    std::string shell;
    double fill = 0.0;
    bool operator<(const Scene2& o) const { return std::tie(shell, fill) < std::tie(o.shell, o.fill); }
};

// A threshold as the interval between the last angle below it and the first at or above it, with
// its midpoint (NaN where the matrix does not bracket it).
struct Threshold {
    double below = NAN, above = NAN;
    double mid() const { return std::isfinite(below) && std::isfinite(above) ? 0.5 * (below + above) : NAN; }
    std::string text(double lo, double hi) const {
        if (!std::isfinite(above)) return fmt::format("above {:g}", hi);
        if (!std::isfinite(below)) return fmt::format("below {:g}", lo);
        return fmt::format("{:g}-{:g}", below, above);
    }
};

// The first angle from which every seed at every angle at or above it satisfies `holds`.
template <class F>
Threshold threshold(const std::map<double, std::vector<const Run*>>& by_angle, F holds) {
    Threshold t;
    for (auto it = by_angle.rbegin(); it != by_angle.rend(); ++it) {
        const bool all = std::all_of(it->second.begin(), it->second.end(), [&](const Run* r) { return r->ok && holds(*r); });
        if (!all) {
            t.below = it->first;
            break;
        }
        t.above = it->first;
    }
    return t;
}

}  // namespace

SweepPlan cross_section_plan() {
    SweepPlan plan;
    plan.base = kBase;
    plan.fields = {"shell.preset", "fill.ratio", "ramp.angle_deg", "run.model", "run.seed"};
    plan.flags = plan.fields;
    for (const auto& [shell, angles] : scenes::cross_section_shells())
        for (double r : scenes::cross_section_fill_ratios())
            for (double a : angles)
                for (const std::string& model : kModels)
                    for (unsigned seed : kSeeds)
                        add_run(plan, {{"shell.preset", shell}, {"fill.ratio", r}, {"ramp.angle_deg", a},
                                       {"run.model", model}, {"run.seed", seed}});
    return plan;
}

CrossSectionReport analyse_cross_section(const SweepPlan& plan, const TableFile& t, const std::filesystem::path& dir) {
    std::vector<Run> runs;
    for (const auto& row : t.rows) {
        const PlannedRun& pr = plan.runs.at(std::stoull(row.at(0)));
        const json& p = pr.point;
        Run r;
        r.shell = p.at("shell.preset");
        r.fill = p.at("fill.ratio");
        r.angle = p.at("ramp.angle_deg");
        r.model = p.at("run.model");
        r.seed = p.at("run.seed");
        r.ok = cell(t, row, "status") == "ok";
        r.behaviour = r.ok ? cell(t, row, "behaviour") : "failed";
        r.distance_m = number(cell(t, row, "distance_m"));
        r.vt_m_s = number(cell(t, row, "terminal_velocity_m_s"));
        r.wall_s = number(cell(t, row, "wall_time_s"));
        r.first_kept = first_impact_kept(dir / "runs" / pr.id / "impacts.csv");
        runs.push_back(r);
    }

    std::map<Scene2, std::map<std::string, std::map<double, std::vector<const Run*>>>> by;
    for (const Run& r : runs) by[{r.shell, r.fill}][r.model][r.angle].push_back(&r);

    std::string md = "# The 2D cross-section against the 3D reference\n\n";
    md += "Generated by `polyroll tradeoff --dem3d` (src/sweep/cross_section.cpp). The grain model (2D, the "
          "`standard` preset) and the 3D reference (`--model dem3d`: the box and every BB in Yade) on the small "
          "hexagon and octagon, a quarter, three eighths and half full of BBs, on the 2.54 m air track, "
          "seeds 1 and 2, every other parameter as bundled. Behaviours: `first impact` (stopped at the first "
          "impact), `stopped` (after rolling further), `end` (rolled to the end), with the distance in metres. "
          "First-impact threshold: the angle from which no seed stops at its first impact (at every angle above "
          "too); sustained rolling: the angle from which every seed rolls to the end. Each is given as the two "
          "angles of the matrix it lies between. Energy kept at the first impact: the kinetic energy 3 ms after "
          "the landing over the energy just before it, the same rule in both models (the 3D contacts last about "
          "a millisecond). The energy kept and the terminal velocity are means over the runs where both models "
          "give one at the same angle and seed.\n\n";

    md += "## Thresholds, energy at the first impact, terminal velocity and cost\n\n";
    md += "| scene | first-impact threshold 2D (deg) | 3D (deg) | 3D - 2D | sustained rolling 2D (deg) | 3D (deg) | "
          "3D - 2D | energy kept at 1st impact 2D | 3D | Vt 2D (m/s) | Vt 3D (m/s) | wall s/run 2D | 3D |\n"
          "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    struct Sum {
        double n = 0, v = 0;
        void add(double x) {
            if (std::isfinite(x)) {
                n += 1;
                v += x;
            }
        }
        double mean() const { return n > 0 ? v / n : NAN; }
    };
    Sum first_gap, roll_gap, kept_gap, vt_gap, cost_2d, cost_3d;
    int behaviour_same = 0, behaviour_compared = 0;
    for (auto& [scene, models] : by) {
        std::map<std::string, Threshold> first, roll;
        std::map<std::string, Sum> kept, vt, wall;
        double lo = 1e9, hi = -1e9;
        for (auto& [model, by_angle] : models) {
            first[model] = threshold(by_angle, [](const Run& r) { return r.behaviour != "stopped_at_first_impact"; });
            roll[model] = threshold(by_angle, [](const Run& r) { return r.behaviour == "rolled_to_end"; });
            for (auto& [angle, list] : by_angle) {
                lo = std::min(lo, angle);
                hi = std::max(hi, angle);
                for (const Run* r : list) wall[model].add(r->wall_s);
            }
        }
        // The energy kept and the terminal velocity compare run for run (same angle and seed) where
        // both models give one: a mean over each model's own runs would mix different angles.
        for (auto& [angle, list2d] : models["grains"])
            for (const Run* a : list2d)
                for (const Run* b : models["dem3d"][angle]) {
                    if (a->seed != b->seed) continue;
                    if (std::isfinite(a->first_kept) && std::isfinite(b->first_kept)) {
                        kept["grains"].add(a->first_kept);
                        kept["dem3d"].add(b->first_kept);
                    }
                    if (a->behaviour == "rolled_to_end" && b->behaviour == "rolled_to_end") {
                        vt["grains"].add(a->vt_m_s);
                        vt["dem3d"].add(b->vt_m_s);
                    }
                }
        const double fg = first["dem3d"].mid() - first["grains"].mid();
        const double rg = roll["dem3d"].mid() - roll["grains"].mid();
        first_gap.add(fg);
        roll_gap.add(rg);
        kept_gap.add(kept["dem3d"].mean() - kept["grains"].mean());
        if (vt["grains"].n > 0 && vt["dem3d"].n > 0) vt_gap.add(vt["dem3d"].mean() / vt["grains"].mean() - 1.0);
        cost_2d.add(wall["grains"].mean());
        cost_3d.add(wall["dem3d"].mean());
        auto signed_deg = [](double x) { return std::isfinite(x) ? fmt::format("{:+.1f}", x) : std::string("-"); };
        md += fmt::format("| n = {}, r = {:g} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
                          sides_of(scene.shell), scene.fill, first["grains"].text(lo, hi),
                          first["dem3d"].text(lo, hi), signed_deg(fg), roll["grains"].text(lo, hi),
                          roll["dem3d"].text(lo, hi), signed_deg(rg), fixed(kept["grains"].mean(), 2),
                          fixed(kept["dem3d"].mean(), 2), fixed(vt["grains"].mean(), 3), fixed(vt["dem3d"].mean(), 3),
                          fixed(wall["grains"].mean(), 1), fixed(wall["dem3d"].mean(), 1));
        // Behaviour agreement, run by run (same angle and seed).
        for (auto& [angle, list2d] : models["grains"])
            for (const Run* a : list2d)
                for (const Run* b : models["dem3d"][angle])
                    if (a->seed == b->seed && a->ok && b->ok) {
                        ++behaviour_compared;
                        if (a->behaviour == b->behaviour) ++behaviour_same;
                    }
    }

    md += "\n## What the 2D cross-section costs\n\n";
    md += fmt::format(
        "- Same behaviour, run for run (same scene, angle and seed): {} of {}.\n"
        "- First-impact threshold, 3D minus 2D, mean over the scenes where both are bracketed: {} deg; sustained "
        "rolling: {} deg.\n"
        "- Energy kept at the first impact, 3D minus 2D: {}.\n"
        "- Terminal velocity where both roll to the end, 3D over 2D: {}.\n"
        "- Cost: {} s a run in 2D, {} s in 3D ({}x).\n",
        behaviour_same, behaviour_compared,
        std::isfinite(first_gap.mean()) ? fmt::format("{:+.1f}", first_gap.mean()) : "-",
        std::isfinite(roll_gap.mean()) ? fmt::format("{:+.1f}", roll_gap.mean()) : "-",
        std::isfinite(kept_gap.mean()) ? fmt::format("{:+.3f}", kept_gap.mean()) : "-",
        std::isfinite(vt_gap.mean()) ? fmt::format("{:+.1f}%", 100.0 * vt_gap.mean()) : "-", fixed(cost_2d.mean(), 1),
        fixed(cost_3d.mean(), 1),
        cost_2d.mean() > 0 ? fixed(cost_3d.mean() / cost_2d.mean(), 0) : std::string("-"));

    md += "\n## Every run\n\n";
    md += "| scene | angle (deg) | 2D seed 1 | 2D seed 2 | 3D seed 1 | 3D seed 2 |\n| --- | --- | --- | --- | --- | --- |\n";
    std::string csv = "shell,sides,fill_ratio,model,angle_deg,seed,behaviour,distance_m,first_impact_kept\n";
    for (auto& [scene, models] : by) {
        std::set<double> angles;
        for (auto& [model, by_angle] : models)
            for (auto& [angle, list] : by_angle) angles.insert(angle);
        for (double angle : angles) {
            md += fmt::format("| n = {}, r = {:g} | {:g} |", sides_of(scene.shell), scene.fill, angle);
            for (const std::string& model : kModels)
                for (unsigned seed : kSeeds) {
                    std::string text = "-";
                    for (const Run* r : models[model][angle])
                        if (r->seed == seed)
                            text = r->ok ? fmt::format("{} {}", short_name(r->behaviour), fixed(r->distance_m, 2)) : "failed";
                    md += " " + text + " |";
                }
            md += "\n";
        }
    }
    for (const Run& r : runs)
        csv += fmt::format("{},{},{},{},{},{},{},{},{}\n", r.shell, sides_of(r.shell), r.fill, r.model,
                           r.angle, r.seed, r.behaviour, std::isfinite(r.distance_m) ? fmt::format("{}", r.distance_m) : "",
                           std::isfinite(r.first_kept) ? fmt::format("{}", r.first_kept) : "");
    return {md, csv};
}

}  // namespace polyroll::sweep
