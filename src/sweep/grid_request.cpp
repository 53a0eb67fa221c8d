// A sweep's grid as asked for, planned and given its folder: see grid_request.h.
#include "sweep/grid_request.h"

#include <algorithm>
#include <cstdint>
#include <system_error>

#include <fmt/core.h>

#include "sim/files/atomic_file.h"
#include "sim/errors.h"
#include "sim/run_cost.h"
#include "sim/scene/scene_json.h"
#include "sweep/grid_values.h"
#include "sweep/plan_extension.h"
#include "sweep/run_cost.h"

namespace polyroll::sweep {

namespace fs = std::filesystem;
using json = nlohmann::ordered_json;

std::vector<const SceneField*> axis_fields() {
    std::vector<const SceneField*> fields;
    for (const SceneField& f : scene_fields())
        if (f.sweep_axis > 0 && !f.flag.empty()) fields.push_back(&f);
    std::stable_sort(fields.begin(), fields.end(),
                     [](const SceneField* a, const SceneField* b) { return a->sweep_axis < b->sweep_axis; });
    return fields;
}

namespace {

// A list of numbers given out of order ("--angle 12,5") runs in ascending order, so the table and the
// figures read in order; the note says so. Lists of names keep the order given.
std::vector<json> ascending(const std::string& flag, const std::string& text, std::vector<json> values,
                            std::vector<std::string>& notes) {
    const bool numbers = std::all_of(values.begin(), values.end(), [](const json& v) { return v.is_number(); });
    const auto less = [](const json& x, const json& y) { return x.get<double>() < y.get<double>(); };
    if (!numbers || std::is_sorted(values.begin(), values.end(), less)) return values;
    std::stable_sort(values.begin(), values.end(), less);
    notes.push_back(fmt::format("{} {} runs in ascending order", flag, text));
    return values;
}

// The number of runs a grid makes, from its axes alone, refused over the bound before any run is built.
void check_grid_size(const GridRequest& r, const std::vector<SweepAxis>& axes) {
    double runs = 1;
    std::string sizes;
    for (const SweepAxis& ax : axes) {
        runs *= static_cast<double>(ax.values.size());
        sizes += fmt::format("{}{} {}", sizes.empty() ? "" : " x ", ax.flag, ax.values.size());
    }
    if (runs <= kRunsWithoutLarge || r.large) return;
    throw InputError(fmt::format("sweep: {:.0f} runs ({}) is more than {:.0f}; allowed: fewer values, or --large to "
                                 "confirm a plan that big",
                                 runs, sizes, kRunsWithoutLarge));
}

}  // namespace

SweepPlan make_request_plan(const GridRequest& r, std::vector<std::string>& notes) {
    resolve_scene({SceneLayer{r.base, r.base_origin, {}}});  // a bad base fails now
    std::vector<SweepAxis> axes;
    for (const SceneField* f : axis_fields()) {
        const std::string name(f->flag);
        const auto it = r.axis_text.find(name);
        if (it == r.axis_text.end()) continue;
        axes.push_back({std::string(f->path), name, ascending(name, it->second, parse_grid_values(name, it->second), notes)});
    }
    for (const auto& entry : r.axis_text) {
        const std::string& name = entry.first;
        if (std::none_of(axes.begin(), axes.end(), [&name](const SweepAxis& a) { return a.flag == name; }))
            throw InputError(fmt::format("{}: not a swept scene flag", name));
    }
    for (const std::string& s : r.sets) {
        const auto eq = s.find('=');
        if (eq == std::string::npos || eq == 0)
            throw InputError(fmt::format("--set '{}' is not FIELD=VALUES (e.g. --set shell.depth_m=0.05,0.062)", s));
        const std::string field = s.substr(0, eq);
        const std::string flag = "--set " + field;
        check_scene_field(field, flag);
        if (field == "run.seed") throw InputError("--set run.seed: use --seed LIST or --seeds N for seeds");
        axes.push_back({field, flag, ascending(flag, s.substr(eq + 1), parse_grid_values(flag, s.substr(eq + 1)), notes)});
    }
    if (!r.seed_list.empty() && r.seeds > 0)
        throw InputError("--seed and --seeds are both given (allowed: one: --seed 1,5,9 or --seeds 3 for 1,2,3)");
    if (r.seeds > 0) {
        std::vector<json> seeds;
        for (int s = 1; s <= r.seeds; ++s) seeds.emplace_back(static_cast<std::uint64_t>(s));
        axes.push_back({"run.seed", "--seeds", seeds});
    } else if (!r.seed_list.empty()) {
        axes.push_back({"run.seed", "--seed", parse_grid_values("--seed", r.seed_list)});
    }
    check_grid_size(r, axes);
    return make_grid_plan(r.base, axes);
}

GridCheck check_grid(const SweepPlan& plan) {
    GridCheck c;
    for (const PlannedRun& run : plan.runs) {
        try {
            c.max_cost_s += max_run_seconds(resolve_scene(run_layers(plan, run)));
        } catch (const InputError& e) {
            if (c.invalid++ == 0) c.first_invalid = e.what();
        }
    }
    return c;
}

void refuse_unrunnable(const SweepPlan& plan, const GridCheck& check, int jobs, bool large) {
    if (check.invalid > 0)
        throw InputError(fmt::format("sweep: {}; {} of {} runs cannot run, so none was started", check.first_invalid,
                                     check.invalid, plan.runs.size()));
    const double hours = check.max_cost_s / std::max(1, jobs) / 3600.0;
    if (hours > kHoursWithoutLarge && !large)
        throw InputError(fmt::format("sweep: {} runs estimated at up to {} with {} job{}, more than {:.0f} h; "
                                     "allowed: fewer values, a shorter --time-limit, or --large to confirm",
                                     plan.runs.size(), duration_text(check.max_cost_s / std::max(1, jobs)), jobs,
                                     jobs == 1 ? "" : "s", kHoursWithoutLarge));
}

void open_sweep_folder(const fs::path& dir, const std::string& flag, SweepPlan& plan, std::vector<std::string>& notes) {
    std::error_code ec;
    if (fs::exists(plan_path(dir), ec)) {
        // Resuming: the folder's plan must be this request's.
        const SweepPlan existing = read_plan(dir);
        if (plan_to_json(existing) == plan_to_json(plan)) return;
        // More values for the same fields extend it: the finished runs are kept (by id).
        const std::string refusal = extension_refusal(existing, plan);
        if (!refusal.empty())
            throw InputError(fmt::format("{} {}: holds a different sweep ({} runs): {}; allowed: a new folder, the "
                                         "same command to resume, or more values to extend it",
                                         flag, dir.string(), existing.runs.size(), refusal));
        extend_plan(dir, plan);
        notes.push_back(fmt::format("extends the sweep in {}: {} runs were planned there, {} now", dir.string(),
                                    existing.runs.size(), plan.runs.size()));
        return;
    }
    prepare_output_dir(dir, false, "allowed: a new or empty folder, or the folder of this same sweep to resume it");
    write_plan(dir, plan);
}

}  // namespace polyroll::sweep
