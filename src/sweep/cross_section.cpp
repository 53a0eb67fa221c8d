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
const json kAirTrackScene = {
    {"shell", {{"preset", "hexagon-small"}}}, {"fill", {{"material", "bb"}}}, {"ramp", {{"preset", "air-track"}}}};
const std::vector<unsigned> kSeeds = {1, 2};

// The closure of the third column: pile-bulk, the bundled default since 2026-12-03 (its bulk factor measured from
// the 3D reference's pours on the fitting half of assets/reference-3d.json: docs/studies/pile-bulk.md). The plain
// 2D column is the one-grain-deep pile without a closure (closure.preset none), so the study shows what the
// default closure mends. Both 2D columns name their closure, so that neither changes meaning when the default
// moves; the other candidates (pile-disorder and the rest) are in docs/studies/closure-from-3d.md.
constexpr const char* kClosurePreset = "pile-bulk";

// The bar for the 2D thresholds against the 3D reference's, over the scenes: |3D - 2D| within these.
constexpr double kBarMeanAbsGapDeg = 0.5, kBarWorstAbsGapDeg = 1.0;

// The column a run belongs to: its model, with "+" and its closure preset where its point sets one other than
// none (the maps csv's model, so the figure tells the two 2D columns apart; "grains" is the pile without one).
std::string column_key(const json& point) {
    std::string key = point.at("run.model");
    const std::string closure = point.value("closure.preset", std::string("none"));
    if (closure != "none") key += "+" + closure;
    return key;
}

// A column of the matrix: the fields its runs set besides the scene, angle and seed, and its name in the tables.
struct Column {
    std::string key;  // column_key of its points
    json fields;
    std::string label;
};

Column make_column(const json& fields, const std::string& label) { return {column_key(fields), fields, label}; }

// The two 2D columns, each compared with the 3D reference. The 3D runs set no closure, so they keep the ids they
// had before the closure columns were added (add_run leaves absent fields out of a run's id): a folder of the
// study made before holds them already.
const std::vector<Column>& columns_2d() {
    static const std::vector<Column> c = {
        make_column({{"run.model", "grains"}, {"closure.preset", "none"}}, "2D"),
        make_column({{"run.model", "grains"}, {"closure.preset", kClosurePreset}}, "2D+closure"),
    };
    return c;
}

const Column& reference_column() {
    static const Column c = make_column({{"run.model", "dem3d"}}, "3D");
    return c;
}

// Every column, the 3D reference last (the order of the plan and of the tables).
const std::vector<Column>& all_columns() {
    static const std::vector<Column> c = [] {
        std::vector<Column> all = columns_2d();
        all.push_back(reference_column());
        return all;
    }();
    return c;
}

// A run of the matrix: what its row says (RowOutcome), its scene, column and what its first impact kept.
struct Run : RowOutcome {
    std::string shell, column;  // column: its Column's key
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
        const bool all =
            std::all_of(it->second.begin(), it->second.end(), [&](const Run* r) { return r->ok && holds(*r); });
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
    plan.fields = {"shell.preset", "fill.ratio", "ramp.angle_deg", "run.model", "closure.preset", "run.seed"};
    plan.flags = plan.fields;
    for (const auto& [shell, angles] : scenes::cross_section_shells())
        for (double r : scenes::cross_section_fill_ratios())
            for (double a : angles)
                for (const Column& column : all_columns())
                    for (unsigned seed : kSeeds) {
                        json point = {{"shell.preset", shell}, {"fill.ratio", r}, {"ramp.angle_deg", a},
                                      {"run.seed", seed}};
                        point.update(column.fields);
                        add_run(plan, std::move(point));  // in the plan's field order, whatever the order here
                    }
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

// The runs of one scene (shell and fill), by column key and angle.
using ByAngle = std::map<double, std::vector<const Run*>>;
using ByColumn = std::map<std::string, ByAngle>;

// A 2D column's runs paired with the 3D runs at the same angle and seed (a mean over each column's own runs
// would mix different angles): the energy kept and the terminal velocity over the pairs where both give one,
// and how many pairs behave alike.
struct Pairing {
    Mean kept_2d, kept_3d, vt_2d_m_s, vt_3d_m_s;
    int behaviour_same = 0, behaviour_compared = 0;
};

void add_pair(Pairing& p, const Run& run_2d, const Run& run_3d) {
    if (std::isfinite(run_2d.first_kept) && std::isfinite(run_3d.first_kept)) {
        p.kept_2d.add(run_2d.first_kept);
        p.kept_3d.add(run_3d.first_kept);
    }
    if (run_2d.behaviour == "rolled_to_end" && run_3d.behaviour == "rolled_to_end") {
        p.vt_2d_m_s.add(run_2d.vt_m_s);
        p.vt_3d_m_s.add(run_3d.vt_m_s);
    }
    if (run_2d.ok && run_3d.ok) {
        ++p.behaviour_compared;
        if (run_2d.behaviour == run_3d.behaviour) ++p.behaviour_same;
    }
}

Pairing pair_with_3d(const ByAngle& runs_2d, const ByAngle& runs_3d) {
    Pairing p;
    for (const auto& [angle, list_2d] : runs_2d) {
        const auto at = runs_3d.find(angle);
        if (at == runs_3d.end()) continue;
        for (const Run* run_2d : list_2d)
            for (const Run* run_3d : at->second)
                if (run_2d->seed == run_3d->seed) add_pair(p, *run_2d, *run_3d);
    }
    return p;
}

// One scene's comparison: each column's thresholds and cost, and each 2D column paired with the 3D runs.
struct SceneComparison {
    Scene2 scene;
    double lo = 1e9, hi = -1e9;  // the matrix's angles for the scene
    std::map<std::string, Threshold> first, roll;  // by column key
    std::map<std::string, Mean> wall_s;            // by column key
    std::map<std::string, Pairing> against_3d;     // by 2D column key
};

// 3D minus a 2D column's threshold, between their midpoints (NaN where either is not bracketed).
double gap_deg(const std::map<std::string, Threshold>& threshold_by_column, const std::string& key_2d) {
    return threshold_by_column.at(reference_column().key).mid() - threshold_by_column.at(key_2d).mid();
}

// A threshold's gap, 3D minus a 2D column, over the scenes where both are bracketed: its mean, and the mean and
// the worst of its absolute value (what the bar judges).
struct GapStats {
    Mean gap_deg, abs_gap_deg;
    double worst_abs_gap_deg = NAN;
    void add(double gap) {
        if (!std::isfinite(gap)) return;
        gap_deg.add(gap);
        abs_gap_deg.add(std::fabs(gap));
        worst_abs_gap_deg = std::fmax(worst_abs_gap_deg, std::fabs(gap));  // fmax(NaN, x) is x: the first gap
    }
    bool within_bar() const {
        return abs_gap_deg.n > 0 && abs_gap_deg.mean() <= kBarMeanAbsGapDeg && worst_abs_gap_deg <= kBarWorstAbsGapDeg;
    }
};

// A 2D column against the 3D reference over the scenes (each scene's own mean for the energy, Vt and cost).
struct ColumnSummary {
    GapStats first, roll;
    Mean kept_gap;      // 3D minus 2D
    Mean vt_ratio_gap;  // 3D over 2D minus 1
    Mean cost_s;
    int behaviour_same = 0, behaviour_compared = 0;
};

// The study's summary: each 2D column against the 3D reference.
struct Summary {
    std::map<std::string, ColumnSummary> against_3d;  // by 2D column key
    Mean cost_3d_s;
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
        r.column = column_key(p);
        r.seed = p.at("run.seed");
        static_cast<RowOutcome&>(r) = row_outcome(t, row);
        r.first_kept = first_impact_kept(dir / "runs" / pr.id / "impacts.csv");
        runs.push_back(r);
    }
    return runs;
}

SceneComparison compare_scene(const Scene2& scene, ByColumn& runs) {
    SceneComparison c;
    c.scene = scene;
    for (const Column& column : all_columns()) {
        const ByAngle& by_angle = runs[column.key];
        c.wall_s[column.key] = Mean{};
        c.first[column.key] =
            threshold(by_angle, [](const Run& r) { return r.behaviour != "stopped_at_first_impact"; });
        c.roll[column.key] = threshold(by_angle, [](const Run& r) { return r.behaviour == "rolled_to_end"; });
        for (const auto& [angle, list] : by_angle) {
            c.lo = std::min(c.lo, angle);
            c.hi = std::max(c.hi, angle);
            for (const Run* r : list) c.wall_s[column.key].add(r->wall_s);
        }
    }
    for (const Column& column : columns_2d())
        c.against_3d[column.key] = pair_with_3d(runs[column.key], runs[reference_column().key]);
    return c;
}

void add_scene(ColumnSummary& s, const SceneComparison& c, const std::string& key_2d) {
    const Pairing& p = c.against_3d.at(key_2d);
    s.first.add(gap_deg(c.first, key_2d));
    s.roll.add(gap_deg(c.roll, key_2d));
    s.kept_gap.add(p.kept_3d.mean() - p.kept_2d.mean());
    s.vt_ratio_gap.add(p.vt_3d_m_s.mean() / p.vt_2d_m_s.mean() - 1.0);
    s.cost_s.add(c.wall_s.at(key_2d).mean());
    s.behaviour_same += p.behaviour_same;
    s.behaviour_compared += p.behaviour_compared;
}

Summary summarise(const std::vector<SceneComparison>& scenes) {
    Summary s;
    for (const SceneComparison& c : scenes) {
        for (const Column& column : columns_2d()) add_scene(s.against_3d[column.key], c, column.key);
        s.cost_3d_s.add(c.wall_s.at(reference_column().key).mean());
    }
    return s;
}

// The report's prose and tables: cross-section.md.

// What the closure column's preset does, as assets/closures.json says it.
std::string closure_description() {
    return assets::preset_entry(assets::Kind::closure, kClosurePreset).value("description", std::string());
}

std::string intro_text() {
    return "# The 2D cross-section against the 3D reference\n\n"
           "Generated by `polyroll tradeoff --dem3d` (src/sweep/cross_section.cpp). Three columns on the small "
           "hexagon and octagon, a quarter, three eighths and half full of BBs, on the 2.54 m air track, seeds 1 "
           "and 2, every other parameter as bundled: **2D**, the grain model at the `standard` preset without a "
           "closure (`closure.preset` none: the pile one grain deep); "
           "**2D+closure**, the same with the closure `" + std::string(kClosurePreset) + "` (`closure.preset`, "
           "assets/closures.json: " + closure_description() + "; the bundled default, measured from the 3D "
           "reference's pours, docs/studies/pile-bulk.md; the other candidates: docs/studies/closure-from-3d.md); "
           "**3D**, the reference (`--model dem3d`: the box and every BB in Yade). Behaviours: `first impact` "
           "(stopped at the first impact), `stopped` (after rolling further), `end` (rolled to the end), with the "
           "distance in metres. First-impact threshold: the angle from which no seed stops at its first impact (at "
           "every angle above too); sustained rolling: the angle from which every seed rolls to the end. Each is "
           "given as the two angles of the matrix it lies between, and 3D minus 2D between their midpoints. "
           "Energy kept at the first impact: the kinetic energy 3 ms after the landing over the energy just before "
           "it, the same rule in every column (the 3D contacts last about a millisecond). The energy kept and the "
           "terminal velocity pair each 2D column's runs with the 3D runs at the same angle and seed: `2D / 3D` "
           "are the two means over the pairs where both give one.\n\n";
}

std::string signed_deg(double x) { return std::isfinite(x) ? fmt::format("{:+.1f}", x) : std::string("-"); }

std::string scene_name(const Scene2& scene) {
    return fmt::format("n = {}, r = {:g}", sides_of(scene.shell), scene.fill);
}

// A group of header cells, one a column: the first says what the group holds, the others only their
// column's label (`label_format` makes a label of a column's: "{}", "{} / 3D", "3D - {}").
std::string header_group(const std::string& what, const std::vector<Column>& columns, const char* label_format,
                         const std::string& unit = "") {
    std::string h;
    for (const Column& column : columns) {
        const std::string label = fmt::format(fmt::runtime(label_format), column.label);
        h += " " + (h.empty() ? (what.empty() ? "" : what + " ") + label + unit : label) + " |";
    }
    return h;
}

// A threshold's header cells: its interval in each column, then 3D minus each 2D column.
std::string threshold_header(const std::string& threshold_name) {
    return header_group(threshold_name, all_columns(), "{}", " (deg)") + header_group("", columns_2d(), "3D - {}");
}

std::string threshold_cells(const SceneComparison& c, const std::map<std::string, Threshold>& by_column) {
    std::string cells;
    for (const Column& column : all_columns()) cells += " " + by_column.at(column.key).text(c.lo, c.hi) + " |";
    for (const Column& column : columns_2d()) cells += " " + signed_deg(gap_deg(by_column, column.key)) + " |";
    return cells;
}

std::string table_rule(std::size_t columns) {
    std::string rule = "|";
    for (std::size_t i = 0; i < columns; ++i) rule += " --- |";
    return rule + "\n";
}

std::string thresholds_table(const std::vector<SceneComparison>& scenes) {
    std::string md = "## Thresholds\n\n| scene |";
    md += threshold_header("first impact") + threshold_header("sustained rolling");
    md += "\n" + table_rule(1 + 2 * (all_columns().size() + columns_2d().size()));
    for (const SceneComparison& c : scenes)
        md += "| " + scene_name(c.scene) + " |" + threshold_cells(c, c.first) + threshold_cells(c, c.roll) + "\n";
    return md;
}

// "2D mean / 3D mean" over a 2D column's pairs with the 3D runs.
std::string pair_cell(const Mean& mean_2d, const Mean& mean_3d, int digits) {
    return fixed_or_dash(mean_2d.mean(), digits) + " / " + fixed_or_dash(mean_3d.mean(), digits);
}

// A scene's energy kept and Vt, each 2D column's against 3D, and each column's cost.
std::string energy_row(const SceneComparison& c) {
    std::string md = "| " + scene_name(c.scene) + " |";
    for (const Column& column : columns_2d()) {
        const Pairing& p = c.against_3d.at(column.key);
        md += " " + pair_cell(p.kept_2d, p.kept_3d, 2) + " |";
    }
    for (const Column& column : columns_2d()) {
        const Pairing& p = c.against_3d.at(column.key);
        md += " " + pair_cell(p.vt_2d_m_s, p.vt_3d_m_s, 3) + " |";
    }
    for (const Column& column : all_columns()) md += " " + fixed_or_dash(c.wall_s.at(column.key).mean(), 1) + " |";
    return md + "\n";
}

std::string energy_table(const std::vector<SceneComparison>& scenes) {
    std::string md = "\n## Energy at the first impact, terminal velocity and cost\n\n| scene |";
    md += header_group("energy kept at 1st impact", columns_2d(), "{} / 3D") +
          header_group("Vt", columns_2d(), "{} / 3D", " (m/s)") + header_group("wall s/run", all_columns(), "{}");
    md += "\n" + table_rule(1 + 2 * columns_2d().size() + all_columns().size());
    for (const SceneComparison& c : scenes) md += energy_row(c);
    return md;
}

// "2D <fact>; 2D+closure <fact>": one summary fact for each 2D column.
template <class F>
std::string each_2d(const Summary& s, F fact) {
    std::string text;
    for (const Column& column : columns_2d())
        text += (text.empty() ? "" : "; ") + column.label + " " + fact(s.against_3d.at(column.key));
    return text;
}

std::string number_or_dash(double x, const char* format) {
    return std::isfinite(x) ? fmt::format(fmt::runtime(format), x) : std::string("-");
}

std::string gap_text(const GapStats& g) {
    if (g.gap_deg.n == 0) return "- (no scene bracketed in both)";
    return fmt::format("mean {:+.1f} deg, |gap| mean {:.1f} and worst {:.1f} ({:g} scenes)", g.gap_deg.mean(),
                       g.abs_gap_deg.mean(), g.worst_abs_gap_deg, g.gap_deg.n);
}

std::string first_gap_text(const ColumnSummary& c) { return gap_text(c.first); }
std::string roll_gap_text(const ColumnSummary& c) { return gap_text(c.roll); }
std::string same_behaviour_text(const ColumnSummary& c) {
    return fmt::format("{} of {}", c.behaviour_same, c.behaviour_compared);
}
std::string bar_text(const ColumnSummary& c) { return c.first.within_bar() && c.roll.within_bar() ? "met" : "not met"; }
std::string kept_gap_text(const ColumnSummary& c) { return number_or_dash(c.kept_gap.mean(), "{:+.3f}"); }
std::string vt_gap_text(const ColumnSummary& c) { return number_or_dash(100.0 * c.vt_ratio_gap.mean(), "{:+.1f}%"); }

std::string cost_text(const Summary& s) {
    const double cost_3d_s = s.cost_3d_s.mean();
    return "3D " + fixed_or_dash(cost_3d_s, 1) + " s; " + each_2d(s, [cost_3d_s](const ColumnSummary& c) {
               const double cost_s = c.cost_s.mean();
               return fixed_or_dash(cost_s, 1) + " s (3D " + (cost_s > 0 ? fixed_or_dash(cost_3d_s / cost_s, 0) : "-") +
                      "x)";
           });
}

std::string summary_text(const Summary& s) {
    return "\n## What the 2D cross-section costs\n\n" +
           fmt::format("- Same behaviour as 3D, run for run (same scene, angle and seed): {}.\n"
                       "- First-impact threshold, 3D minus each 2D column over the scenes where both are bracketed: "
                       "{}.\n"
                       "- Sustained rolling, the same: {}.\n"
                       "- Both thresholds within the bar (|gap| within {:g} deg on average and {:g} at worst): {}.\n"
                       "- Energy kept at the first impact, 3D minus the 2D column: {}.\n"
                       "- Terminal velocity where both roll to the end, 3D over the 2D column: {}.\n"
                       "- Cost, wall time a run: {}.\n",
                       each_2d(s, same_behaviour_text), each_2d(s, first_gap_text), each_2d(s, roll_gap_text),
                       kBarMeanAbsGapDeg, kBarWorstAbsGapDeg, each_2d(s, bar_text), each_2d(s, kept_gap_text),
                       each_2d(s, vt_gap_text), cost_text(s));
}

// A run's cell in the every-run table: its behaviour and distance.
std::string run_cell(const std::vector<const Run*>& runs_at_angle, unsigned seed) {
    for (const Run* r : runs_at_angle)
        if (r->seed == seed)
            return r->ok ? fmt::format("{} {}", short_name(r->behaviour), fixed_or_dash(r->distance_m, 2)) : "failed";
    return "-";
}

std::string every_run_table(std::map<Scene2, ByColumn>& by) {
    std::string md = "\n## Every run\n\n| scene | angle (deg) |";
    for (const Column& column : all_columns())
        for (unsigned seed : kSeeds) md += fmt::format(" {} seed {} |", column.label, seed);
    md += "\n" + table_rule(2 + all_columns().size() * kSeeds.size());
    for (auto& [scene, runs] : by) {
        std::set<double> angles;
        for (const auto& [key, by_angle] : runs)
            for (const auto& [angle, list] : by_angle) angles.insert(angle);
        for (double angle : angles) {
            md += fmt::format("| {} | {:g} |", scene_name(scene), angle);
            for (const Column& column : all_columns())
                for (unsigned seed : kSeeds) md += " " + run_cell(runs[column.key][angle], seed) + " |";
            md += "\n";
        }
    }
    return md;
}

std::string maps_csv(const std::vector<Run>& runs) {
    std::string csv = "shell,sides,fill_ratio,model,angle_deg,seed,behaviour,distance_m,first_impact_kept\n";
    for (const Run& r : runs)
        csv += fmt::format("{},{},{},{},{},{},{},{},{}\n", r.shell, sides_of(r.shell), r.fill, r.column, r.angle,
                           r.seed, r.behaviour, std::isfinite(r.distance_m) ? fmt::format("{}", r.distance_m) : "",
                           std::isfinite(r.first_kept) ? fmt::format("{}", r.first_kept) : "");
    return csv;
}

}  // namespace

CrossSectionReport analyse_cross_section(const SweepPlan& plan, const TableFile& t, const std::filesystem::path& dir) {
    const std::vector<Run> runs = read_runs(plan, t, dir);
    std::map<Scene2, ByColumn> by;
    for (const Run& r : runs) by[{r.shell, r.fill}][r.column][r.angle].push_back(&r);
    std::vector<SceneComparison> scenes;
    scenes.reserve(by.size());
    for (auto& [scene, runs_of_scene] : by) scenes.push_back(compare_scene(scene, runs_of_scene));
    const std::string md = intro_text() + thresholds_table(scenes) + energy_table(scenes) +
                           summary_text(summarise(scenes)) + every_run_table(by);
    return {md, maps_csv(runs)};
}

}  // namespace polyroll::sweep
