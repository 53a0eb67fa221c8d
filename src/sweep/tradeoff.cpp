// The speed/accuracy study: see tradeoff.h.
#include "sweep/tradeoff.h"

#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include <fmt/core.h>

#include "sim/assets.h"
#include "sim/message_text.h"
#include "sim/scene/scene_json.h"
#include "sweep/scene_matrices.h"
#include "sim/geometry/shell_properties.h"
#include "sweep/grid_values.h"

namespace polyroll::sweep {
namespace {

using json = nlohmann::ordered_json;

// The scenes' fixed parts: the short wooden ramp keeps the costly reference runs affordable.
const json kWoodenRampScene = {{"shell", {{"preset", "hexagon-small"}}}, {"ramp", {{"preset", "wooden"}}},
                    {"run", {{"time_limit_s", 20}}}};
const std::vector<std::string> kPresets = {"draft", "standard", "precise", "reference"};

// A material preset's grain diameter, as assets/materials.json gives it.
double diameter_m(const std::string& material) {
    return assets::preset_values(assets::Kind::material, material).at("diameter_m").get<double>();
}

// A material preset's grains per disc (null: column discs of the grain's size).
json grains_per_disc(const std::string& material) {
    return assets::preset_values(assets::Kind::material, material).value("grains_per_disc", json());
}

struct Variant {
    std::string model, preset, kind;  // kind: "", "halved", "coarse x1.5", "coarse x2", "seed 2"
    std::string label() const {
        if (model != "grains") return model;
        if (kind == "halved") return "reference, dt/2";
        return kind.empty() ? preset : preset + ", " + kind;
    }
};

// A run of the table: what its row says (RowOutcome), its scene and variant.
struct Row : RowOutcome {
    std::string scene;  // n, r, material, angle
    Variant v;
    double side_m = NAN;
};

std::string percent(double v) { return std::isfinite(v) ? fmt::format("{:.1f}%", 100.0 * v) : "-"; }

}  // namespace

SweepPlan tradeoff_plan() {
    SweepPlan plan;
    plan.base = kWoodenRampScene;
    plan.fields = {"shell.sides",     "fill.ratio",         "fill.material.preset", "ramp.angle_deg",
                   "run.model",       "fidelity.preset",    "fidelity.substeps",    "fill.material.diameter_m",
                   "fill.material.grains_per_disc", "run.seed"};
    plan.flags = plan.fields;
    const std::vector<scenes::TradeoffScene> matrix = scenes::tradeoff_scenes();
    for (const auto& [n, r, material, a] : matrix) {
        const json scene = {{"shell.sides", n}, {"fill.ratio", r}, {"fill.material.preset", material},
                            {"ramp.angle_deg", a}};
        auto with = [&](json extra) {
            json p = scene;
            for (const auto& [k, v] : extra.items()) p[k] = v;
            add_run(plan, p);
        };
        for (const std::string& preset : kPresets)
            with({{"run.model", "grains"}, {"fidelity.preset", preset}, {"run.seed", 1u}});
        // The reference checked for convergence: its engine step halved once more.
        with({{"run.model", "grains"}, {"fidelity.preset", "reference"}, {"fidelity.substeps", 8}, {"run.seed", 1u}});
        // The spread a different grain packing gives, at the standard preset: the noise floor.
        with({{"run.model", "grains"}, {"fidelity.preset", "standard"}, {"run.seed", 2u}});
        if (r > 0.0) {
            // The same fill mass (r x volume x bulk density) in fewer discs k times larger: as the
            // sandbox's budget makes them (with_coarser_grains), a disc standing for k^2 times the
            // grains where the material sizes its discs by grains_per_disc, else grains k times larger.
            const json per_disc = grains_per_disc(material);
            for (double k : {1.5, 2.0}) {
                const json coarser = per_disc.is_number()
                                         ? json{{"fill.material.grains_per_disc", per_disc.get<double>() * k * k}}
                                         : json{{"fill.material.diameter_m", diameter_m(material) * k}};
                json extra = {{"run.model", "grains"}, {"fidelity.preset", "standard"}, {"run.seed", 1u}};
                extra.update(coarser);
                with(extra);
            }
        }
        // The reduced models integrate to rounding error: the fidelity preset does not change them.
        for (const char* model : {"rigid", "segments"})
            with({{"run.model", model}, {"fidelity.preset", "standard"}, {"run.seed", 1u}});
    }
    // --model auto on every scene, after the rest so the earlier runs keep their indices and run ids:
    // its error and cost against the standard preset's.
    for (const auto& [n, r, material, a] : matrix)
        add_run(plan, {{"shell.sides", n}, {"fill.ratio", r}, {"fill.material.preset", material},
                       {"ramp.angle_deg", a}, {"run.model", "auto"}, {"fidelity.preset", "standard"}, {"run.seed", 1u}});
    return plan;
}

namespace {

// Which choice a planned point is: model, preset and what differs from the preset's own run.
Variant variant_of(const json& p) {
    Variant v;
    v.model = p.at("run.model");
    v.preset = p.at("fidelity.preset");
    if (p.contains("fidelity.substeps")) v.kind = "halved";
    if (p.contains("fill.material.diameter_m")) {
        const double k = p.at("fill.material.diameter_m").get<double>() /
                         diameter_m(p.at("fill.material.preset").get<std::string>());
        v.kind = fmt::format("coarse x{:g}", std::round(k * 10) / 10);
    }
    if (p.contains("fill.material.grains_per_disc")) {
        // Discs k times larger stand for k^2 times the grains.
        const double k = std::sqrt(p.at("fill.material.grains_per_disc").get<double>() /
                                   grains_per_disc(p.at("fill.material.preset").get<std::string>()).get<double>());
        v.kind = fmt::format("coarse x{:g}", std::round(k * 10) / 10);
    }
    if (p.at("run.seed") != 1) v.kind = "seed " + p.at("run.seed").dump();
    return v;
}

// The table's rows with their scenes and choices, each with its scene's outer side length.
std::vector<Row> read_rows(const SweepPlan& plan, const TableFile& t) {
    std::vector<Row> rows;
    std::map<std::string, double> side_of_scene;
    for (const auto& r : t.rows) {
        const PlannedRun& run = plan.runs.at(std::stoull(r.at(0)));
        const json& p = run.point;
        Row row;
        row.scene = fmt::format("n = {}, r = {}, {}, {} deg", p.at("shell.sides").dump(), value_text(p.at("fill.ratio")),
                                p.at("fill.ratio") == 0.0 ? "empty" : p.at("fill.material.preset").get<std::string>(),
                                value_text(p.at("ramp.angle_deg")));
        row.v = variant_of(p);
        static_cast<RowOutcome&>(row) = row_outcome(t, r);
        if (!side_of_scene.count(row.scene)) {
            // The outer side length: the floor of the distance error's scale (a first-impact stop
            // moves the lid centre by a fraction of it).
            const Scene s = resolve_scene(run_layers(plan, run));
            const ShellProperties sp = shell_properties(s.shell);
            side_of_scene[row.scene] = 2.0 * sp.outer_circumradius_m * std::sin(M_PI / s.shell.sides);
        }
        row.side_m = side_of_scene[row.scene];
        rows.push_back(row);
    }
    return rows;
}

// Each scene's reference run: grains at the reference preset, seed 1.
std::map<std::string, const Row*> references(const std::vector<Row>& rows) {
    std::map<std::string, const Row*> reference;
    for (const Row& r : rows)
        if (r.v.model == "grains" && r.v.preset == "reference" && r.v.kind.empty()) reference[r.scene] = &r;
    return reference;
}

struct Totals {
    Variant v;
    int runs = 0, compared = 0, wrong = 0, vt_n = 0, failed = 0;
    double wall = 0, d_err = 0, vt_err = 0;
};

// The totals per choice, in order of first appearance.
struct Tally {
    std::vector<std::string> order;
    std::map<std::string, Totals> totals;
};

Tally tally_choices(const std::vector<Row>& rows, const std::map<std::string, const Row*>& reference) {
    Tally out;
    for (const Row& r : rows) {
        const std::string key = r.v.model + "|" + r.v.preset + "|" + r.v.kind;
        if (!out.totals.count(key)) {
            out.order.push_back(key);
            out.totals[key].v = r.v;
        }
        Totals& tt = out.totals[key];
        ++tt.runs;
        tt.wall += r.wall_s;
        if (!r.ok) ++tt.failed;
        const auto ref = reference.find(r.scene);
        if (ref == reference.end() || !ref->second->ok || !r.ok) continue;
        const Row& f = *ref->second;
        ++tt.compared;
        tt.d_err += std::fabs(r.distance_m - f.distance_m) / std::max(f.distance_m, r.side_m);
        if (r.behaviour != f.behaviour) ++tt.wrong;
        if (std::isfinite(r.vt_m_s) && std::isfinite(f.vt_m_s)) {
            ++tt.vt_n;
            tt.vt_err += std::fabs(r.vt_m_s - f.vt_m_s) / f.vt_m_s;
        }
    }
    return out;
}

// The Pareto front over cost and all three errors among the choices a user has: the models, the
// presets below the reference (which is the yardstick, error 0 by definition) and coarser grains.
// The second seed and the halved step are yardsticks too: the noise floor and the reference's own error.
std::vector<bool> pareto_front(const Tally& tally) {
    auto choice = [&](const Variant& v) {
        return v.model != "grains" || (v.preset != "reference" && (v.kind.empty() || v.kind.rfind("coarse", 0) == 0));
    };
    std::vector<std::array<double, 4>> pts;
    for (const auto& k : tally.order) {
        const Totals& tt = tally.totals.at(k);
        const bool ok = tt.compared && choice(tt.v);
        pts.push_back({tt.wall / tt.runs, ok ? tt.d_err / tt.compared : INFINITY,
                       ok && tt.vt_n ? tt.vt_err / tt.vt_n : INFINITY,
                       ok ? static_cast<double>(tt.wrong) / tt.compared : INFINITY});
    }
    auto on_front = [&](std::size_t i) {
        if (!std::isfinite(pts[i][1])) return false;
        for (std::size_t j = 0; j < pts.size(); ++j) {
            if (j == i) continue;
            bool no_worse = true, better = false;
            for (int m = 0; m < 4; ++m) {
                no_worse = no_worse && pts[j][m] <= pts[i][m];
                better = better || pts[j][m] < pts[i][m];
            }
            if (no_worse && better) return false;
        }
        return true;
    };
    std::vector<bool> front;
    for (std::size_t i = 0; i < pts.size(); ++i) front.push_back(on_front(i));
    return front;
}

const char* const kMethod =
    "# Speed against accuracy\n\n"
    "Generated by `polyroll tradeoff` (src/sweep/tradeoff.cpp). Each scene runs with every model and fidelity "
    "preset and is compared with the reference: the grain simulation at the `reference` preset, seed 1. "
    "Distance error: |D - D_ref| / max(D_ref, s) with s the outer side length (a stop at the first impact "
    "moves the lid centre by a fraction of a side); terminal velocity error: |Vt - Vt_ref| / Vt_ref where both "
    "rolled to the end; behaviour: the share of scenes whose behaviour differs from the reference's. Wall "
    "time: mean per run, each run on one core (two runs at a time). Pareto front: no other choice (model, "
    "preset below the reference, coarser grains) is at once cheaper and no less accurate in all three errors.\n\n";

// The error-against-cost table (markdown) and its points for the figure (CSV).
TradeoffReport error_table(const Tally& tally) {
    const std::vector<bool> front = pareto_front(tally);
    std::string md = "## Error against cost, per model and preset\n\n";
    md += "| model | preset | runs | failed | wall time per run (s) | distance error | terminal velocity error | "
          "wrong behaviour | Pareto front |\n| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    std::string csv = "model,variant,label,runs,wall_time_s,distance_error,velocity_error,behaviour_error,pareto\n";
    for (std::size_t i = 0; i < tally.order.size(); ++i) {
        const Totals& tt = tally.totals.at(tally.order[i]);
        const double d = tt.compared ? tt.d_err / tt.compared : NAN;
        const double vt = tt.vt_n ? tt.vt_err / tt.vt_n : NAN;
        const double wrong = tt.compared ? static_cast<double>(tt.wrong) / tt.compared : NAN;
        const std::string label = tt.v.label();
        md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} ({} of {}) | {} |\n", tt.v.model,
                          tt.v.model == "grains" ? label : "-", tt.runs, tt.failed, fmt::format("{:.2g}", tt.wall / tt.runs),
                          percent(d), percent(vt), percent(wrong), tt.wrong, tt.compared, front[i] ? "yes" : "");
        const std::string variant = tt.v.kind.rfind("coarse", 0) == 0 ? "coarse"
                                    : !tt.v.kind.empty()             ? tt.v.kind
                                    : tt.v.preset == "reference" && tt.v.model == "grains" ? "reference"
                                                                                           : "preset";
        csv += fmt::format("{},{},\"{}\",{},{},{},{},{},{}\n", tt.v.model, variant, label, tt.runs, tt.wall / tt.runs,
                           std::isfinite(d) ? fmt::format("{}", d) : "", std::isfinite(vt) ? fmt::format("{}", vt) : "",
                           std::isfinite(wrong) ? fmt::format("{}", wrong) : "", front[i] ? 1 : 0);
    }
    return {md, csv};
}

// The reference against its own time step halved, and the second seed beside them.
std::string convergence_table(const std::vector<Row>& rows, const std::map<std::string, const Row*>& reference) {
    std::string md = "\n## Is the reference converged? (reference against its own time step halved)\n\n";
    md += "| scene | behaviour (ref) | behaviour (dt/2) | D ref (m) | D dt/2 (m) | distance difference | Vt ref (m/s) | "
          "Vt dt/2 (m/s) | seed 2 at standard: behaviour, D (m) |\n"
          "| --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    int agree = 0, scenes = 0;
    for (const auto& [scene, ref] : reference) {
        const Row* half = nullptr;
        const Row* seed2 = nullptr;
        for (const Row& r : rows) {
            if (r.scene != scene) continue;
            if (r.v.kind == "halved") half = &r;
            if (r.v.kind == "seed 2") seed2 = &r;
        }
        if (!half) continue;
        ++scenes;
        const double diff = std::fabs(half->distance_m - ref->distance_m) / std::max(ref->distance_m, ref->side_m);
        if (half->behaviour == ref->behaviour) ++agree;
        md += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", scene, ref->behaviour, half->behaviour,
                          fixed_or_dash(ref->distance_m, 3), fixed_or_dash(half->distance_m, 3), percent(diff), fixed_or_dash(ref->vt_m_s, 3),
                          fixed_or_dash(half->vt_m_s, 3),
                          seed2 ? seed2->behaviour + ", " + fixed_or_dash(seed2->distance_m, 3) : std::string("-"));
    }
    md += fmt::format("\nThe reference and its halved step agree on the behaviour in {} of {} scenes.\n", agree, scenes);
    return md;
}

}  // namespace

TradeoffReport analyse_tradeoff(const SweepPlan& plan, const TableFile& t) {
    const std::vector<Row> rows = read_rows(plan, t);
    const std::map<std::string, const Row*> reference = references(rows);
    TradeoffReport report = error_table(tally_choices(rows, reference));
    report.markdown = kMethod + report.markdown + convergence_table(rows, reference);
    return report;
}

}  // namespace polyroll::sweep
