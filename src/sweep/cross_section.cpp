// The 2D cross-section against the 3D reference: see cross_section.h.
#include "sweep/cross_section.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <fmt/core.h>

#include "sim/assets.h"
#include "sim/message_text.h"
#include "sweep/scene_matrices.h"
#include "sweep/grid_values.h"

namespace polyroll::sweep {
namespace {

using json = nlohmann::ordered_json;

// The air track, as the experiment rolled its small polygons: a whole-ramp 3D run of the hexagon a
// quarter full costs about 40 CPU-seconds, so the matrix takes about half an hour on two cores.
const json kAirTrackScene = {{"shell", {{"preset", "hexagon-small"}}}, {"fill", {{"material", "bb"}}}, {"ramp", {{"preset", "air-track"}}}};
const std::vector<std::string> kModels = {"grains", "dem3d"};
const std::vector<unsigned> kSeeds = {1, 2};

// A run of the matrix: what its row says (RowOutcome), its scene and what its first impact kept.
struct Run : RowOutcome {
    std::string shell, model;
    double fill = 0.0, angle = 0.0;
    unsigned seed = 0;
    double first_kept = NAN;
};

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
        if (names[i] == "ratio_3ms") return cell_number(cells[i]);
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
    plan.base = kAirTrackScene;
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

namespace {

// A mean over the finite values added.
struct Mean {
    double n = 0, sum = 0;
    void add(double x) {
        if (std::isfinite(x)) {
            n += 1;
            sum += x;
        }
    }
    double mean() const { return n > 0 ? sum / n : NAN; }
};

// The runs of one scene (shell and fill), by model and angle.
using ByAngle = std::map<double, std::vector<const Run*>>;
using ByModel = std::map<std::string, ByAngle>;

// One scene's comparison: each model's thresholds, and the energy kept, terminal velocity and cost,
// the first two compared run for run (same angle and seed) where both models give one.
struct SceneComparison {
    Scene2 scene;
    double lo = 1e9, hi = -1e9;  // the matrix's angles for the scene
    std::map<std::string, Threshold> first, roll;
    std::map<std::string, Mean> kept, vt, wall;
    int behaviour_same = 0, behaviour_compared = 0;

    double first_gap() const { return first.at("dem3d").mid() - first.at("grains").mid(); }
    double roll_gap() const { return roll.at("dem3d").mid() - roll.at("grains").mid(); }
};

// The study's summary: 3D minus 2D over the scenes.
struct Summary {
    Mean first_gap, roll_gap, kept_gap, vt_gap, cost_2d, cost_3d;
    int behaviour_same = 0, behaviour_compared = 0;
};

std::vector<Run> read_runs(const SweepPlan& plan, const TableFile& t, const std::filesystem::path& dir) {
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
        static_cast<RowOutcome&>(r) = row_outcome(t, row);
        r.first_kept = first_impact_kept(dir / "runs" / pr.id / "impacts.csv");
        runs.push_back(r);
    }
    return runs;
}

SceneComparison compare_scene(const Scene2& scene, ByModel& models) {
    SceneComparison c;
    c.scene = scene;
    for (const std::string& model : kModels) {
        const ByAngle& by_angle = models[model];
        c.kept[model] = c.vt[model] = c.wall[model] = Mean{};
        c.first[model] = threshold(by_angle, [](const Run& r) { return r.behaviour != "stopped_at_first_impact"; });
        c.roll[model] = threshold(by_angle, [](const Run& r) { return r.behaviour == "rolled_to_end"; });
        for (const auto& [angle, list] : by_angle) {
            c.lo = std::min(c.lo, angle);
            c.hi = std::max(c.hi, angle);
            for (const Run* r : list) c.wall[model].add(r->wall_s);
        }
    }
    // A mean over each model's own runs would mix different angles: pair the runs.
    for (const auto& [angle, list2d] : models["grains"])
        for (const Run* a : list2d)
            for (const Run* b : models["dem3d"][angle]) {
                if (a->seed != b->seed) continue;
                if (std::isfinite(a->first_kept) && std::isfinite(b->first_kept)) {
                    c.kept["grains"].add(a->first_kept);
                    c.kept["dem3d"].add(b->first_kept);
                }
                if (a->behaviour == "rolled_to_end" && b->behaviour == "rolled_to_end") {
                    c.vt["grains"].add(a->vt_m_s);
                    c.vt["dem3d"].add(b->vt_m_s);
                }
                if (a->ok && b->ok) {
                    ++c.behaviour_compared;
                    if (a->behaviour == b->behaviour) ++c.behaviour_same;
                }
            }
    return c;
}

Summary summarise(const std::vector<SceneComparison>& scenes) {
    Summary s;
    for (const SceneComparison& c : scenes) {
        s.first_gap.add(c.first_gap());
        s.roll_gap.add(c.roll_gap());
        s.kept_gap.add(c.kept.at("dem3d").mean() - c.kept.at("grains").mean());
        if (c.vt.at("grains").n > 0 && c.vt.at("dem3d").n > 0)
            s.vt_gap.add(c.vt.at("dem3d").mean() / c.vt.at("grains").mean() - 1.0);
        s.cost_2d.add(c.wall.at("grains").mean());
        s.cost_3d.add(c.wall.at("dem3d").mean());
        s.behaviour_same += c.behaviour_same;
        s.behaviour_compared += c.behaviour_compared;
    }
    return s;
}

// The report's prose and tables: cross-section.md.

std::string intro_text() {
    return "# The 2D cross-section against the 3D reference\n\n"
           "Generated by `polyroll tradeoff --dem3d` (src/sweep/cross_section.cpp). The grain model (2D, the "
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
}

std::string signed_deg(double x) { return std::isfinite(x) ? fmt::format("{:+.1f}", x) : std::string("-"); }

std::string thresholds_table(const std::vector<SceneComparison>& scenes) {
    std::string md = "## Thresholds, energy at the first impact, terminal velocity and cost\n\n";
    md += "| scene | first-impact threshold 2D (deg) | 3D (deg) | 3D - 2D | sustained rolling 2D (deg) | 3D (deg) | "
          "3D - 2D | energy kept at 1st impact 2D | 3D | Vt 2D (m/s) | Vt 3D (m/s) | wall s/run 2D | 3D |\n"
          "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const SceneComparison& c : scenes) {
        auto mean = [](const std::map<std::string, Mean>& m, const char* model) { return m.at(model).mean(); };
        md += fmt::format("| n = {}, r = {:g} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
                          sides_of(c.scene.shell), c.scene.fill, c.first.at("grains").text(c.lo, c.hi),
                          c.first.at("dem3d").text(c.lo, c.hi), signed_deg(c.first_gap()),
                          c.roll.at("grains").text(c.lo, c.hi), c.roll.at("dem3d").text(c.lo, c.hi),
                          signed_deg(c.roll_gap()), fixed_or_dash(mean(c.kept, "grains"), 2), fixed_or_dash(mean(c.kept, "dem3d"), 2),
                          fixed_or_dash(mean(c.vt, "grains"), 3), fixed_or_dash(mean(c.vt, "dem3d"), 3), fixed_or_dash(mean(c.wall, "grains"), 1),
                          fixed_or_dash(mean(c.wall, "dem3d"), 1));
    }
    return md;
}

std::string summary_text(const Summary& s) {
    return "\n## What the 2D cross-section costs\n\n" +
           fmt::format(
               "- Same behaviour, run for run (same scene, angle and seed): {} of {}.\n"
               "- First-impact threshold, 3D minus 2D, mean over the scenes where both are bracketed: {} deg; "
               "sustained rolling: {} deg.\n"
               "- Energy kept at the first impact, 3D minus 2D: {}.\n"
               "- Terminal velocity where both roll to the end, 3D over 2D: {}.\n"
               "- Cost: {} s a run in 2D, {} s in 3D ({}x).\n",
               s.behaviour_same, s.behaviour_compared,
               std::isfinite(s.first_gap.mean()) ? fmt::format("{:+.1f}", s.first_gap.mean()) : "-",
               std::isfinite(s.roll_gap.mean()) ? fmt::format("{:+.1f}", s.roll_gap.mean()) : "-",
               std::isfinite(s.kept_gap.mean()) ? fmt::format("{:+.3f}", s.kept_gap.mean()) : "-",
               std::isfinite(s.vt_gap.mean()) ? fmt::format("{:+.1f}%", 100.0 * s.vt_gap.mean()) : "-",
               fixed_or_dash(s.cost_2d.mean(), 1), fixed_or_dash(s.cost_3d.mean(), 1),
               s.cost_2d.mean() > 0 ? fixed_or_dash(s.cost_3d.mean() / s.cost_2d.mean(), 0) : std::string("-"));
}

std::string every_run_table(std::map<Scene2, ByModel>& by) {
    std::string md = "\n## Every run\n\n";
    md += "| scene | angle (deg) | 2D seed 1 | 2D seed 2 | 3D seed 1 | 3D seed 2 |\n| --- | --- | --- | --- | --- | --- |\n";
    for (auto& [scene, models] : by) {
        std::set<double> angles;
        for (const auto& [model, by_angle] : models)
            for (const auto& [angle, list] : by_angle) angles.insert(angle);
        for (double angle : angles) {
            md += fmt::format("| n = {}, r = {:g} | {:g} |", sides_of(scene.shell), scene.fill, angle);
            for (const std::string& model : kModels)
                for (unsigned seed : kSeeds) {
                    std::string text = "-";
                    for (const Run* r : models[model][angle])
                        if (r->seed == seed)
                            text = r->ok ? fmt::format("{} {}", short_name(r->behaviour), fixed_or_dash(r->distance_m, 2)) : "failed";
                    md += " " + text + " |";
                }
            md += "\n";
        }
    }
    return md;
}

std::string maps_csv(const std::vector<Run>& runs) {
    std::string csv = "shell,sides,fill_ratio,model,angle_deg,seed,behaviour,distance_m,first_impact_kept\n";
    for (const Run& r : runs)
        csv += fmt::format("{},{},{},{},{},{},{},{},{}\n", r.shell, sides_of(r.shell), r.fill, r.model, r.angle, r.seed,
                           r.behaviour, std::isfinite(r.distance_m) ? fmt::format("{}", r.distance_m) : "",
                           std::isfinite(r.first_kept) ? fmt::format("{}", r.first_kept) : "");
    return csv;
}

}  // namespace

CrossSectionReport analyse_cross_section(const SweepPlan& plan, const TableFile& t, const std::filesystem::path& dir) {
    const std::vector<Run> runs = read_runs(plan, t, dir);
    std::map<Scene2, ByModel> by;
    for (const Run& r : runs) by[{r.shell, r.fill}][r.model][r.angle].push_back(&r);
    std::vector<SceneComparison> scenes;
    scenes.reserve(by.size());
    for (auto& [scene, models] : by) scenes.push_back(compare_scene(scene, models));
    const std::string md = intro_text() + thresholds_table(scenes) + summary_text(summarise(scenes)) + every_run_table(by);
    return {md, maps_csv(runs)};
}

}  // namespace polyroll::sweep
