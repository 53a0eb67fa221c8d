// Sweep plans: see sweep_plan.h.
#include "sweep/sweep_plan.h"

#include <fstream>
#include <set>
#include <sstream>

#include <fmt/core.h>

#include "sim/files/atomic_file.h"
#include "sim/errors.h"
#include "sim/scene/json_path.h"
#include "sim/message_text.h"
#include "sweep/grid_values.h"

namespace polyroll::sweep {
namespace {

using json = nlohmann::ordered_json;

constexpr const char* kPlanFormat = "polyroll-sweep-plan-1";

// FNV-1a, 64 bits, then mixed: small, fixed by its definition, the same on every host.
std::uint64_t fnv1a(const std::string& s) {
    std::uint64_t h = 1469598103934665603ull;
    for (unsigned char c : s) {
        h ^= c;
        h *= 1099511628211ull;
    }
    // splitmix64's finaliser: ids of neighbouring points no longer share most of their digits.
    h ^= h >> 30;
    h *= 0xbf58476d1ce4e5b9ull;
    h ^= h >> 27;
    h *= 0x94d049bb133111ebull;
    h ^= h >> 31;
    return h;
}

void collect_paths(const json& j, const std::string& prefix, std::vector<std::string>& out) {
    for (const auto& [k, v] : j.items()) {
        const std::string path = prefix.empty() ? k : prefix + "." + k;
        if (v.is_object())
            collect_paths(v, path, out);
        else
            out.push_back(path);
    }
}

}  // namespace

std::string run_id(const json& base, const json& point) {
    // The text hashed is canonical: the base's dump and each field=value in the plan's order.
    std::string text = base.dump();
    for (const auto& [field, value] : point.items()) text += "\n" + field + "=" + value.dump();
    return fmt::format("{:016x}", fnv1a(text));
}

void add_run(SweepPlan& plan, json point) {
    for (const auto& [field, value] : point.items())
        if (std::find(plan.fields.begin(), plan.fields.end(), field) == plan.fields.end())
            throw InputError(fmt::format("sweep plan: run field '{}' is not one of the plan's fields", field));
    // Reorder to the plan's field order, so ids do not depend on how the point was built.
    json ordered = json::object();
    for (const std::string& f : plan.fields)
        if (point.contains(f)) ordered[f] = point.at(f);
    PlannedRun run;
    run.index = plan.runs.size();
    run.id = run_id(plan.base, ordered);
    run.point = std::move(ordered);
    plan.runs.push_back(std::move(run));
}

SweepPlan make_grid_plan(const json& base, const std::vector<SweepAxis>& axes) {
    SweepPlan plan;
    plan.base = base;
    std::size_t total = 1;
    for (const SweepAxis& a : axes) {
        if (std::find(plan.fields.begin(), plan.fields.end(), a.field) != plan.fields.end())
            throw InputError(fmt::format("{}: {} is swept twice (allowed: each scene field once)", a.flag, a.field));
        if (a.values.empty()) throw InputError(fmt::format("{}: no values to sweep", a.flag));
        std::set<std::string> seen;
        for (const json& v : a.values)
            if (!seen.insert(v.dump()).second)
                throw InputError(fmt::format("{}: value {} is given twice (allowed: each value once)", a.flag,
                                             value_text(v)));
        plan.fields.push_back(a.field);
        plan.flags.push_back(a.flag);
        total *= a.values.size();
        if (total > 10000000)
            throw InputError(fmt::format("sweep: the grid has more than 10,000,000 runs (allowed: at most that)"));
    }
    std::vector<std::size_t> digit(axes.size(), 0);
    for (std::size_t n = 0; n < total; ++n) {
        json point = json::object();
        for (std::size_t a = 0; a < axes.size(); ++a) point[axes[a].field] = axes[a].values[digit[a]];
        add_run(plan, std::move(point));
        // The last axis varies fastest.
        for (std::size_t a = axes.size(); a-- > 0;) {
            if (++digit[a] < axes[a].values.size()) break;
            digit[a] = 0;
        }
    }
    return plan;
}

std::vector<SceneLayer> run_layers(const SweepPlan& plan, const PlannedRun& run) {
    SceneLayer base{plan.base, "sweep base scene", {}};
    SceneLayer point;
    point.origin = "sweep point";
    point.doc = json::object();
    for (const auto& [field, value] : run.point.items()) {
        // A section given as a preset name ("material": "bb") becomes {"preset": "bb"} to take fields.
        node_at(point.doc, field, PresetSections::open) = value;
        const auto it = std::find(plan.fields.begin(), plan.fields.end(), field);
        const std::size_t i = static_cast<std::size_t>(it - plan.fields.begin());
        point.field_labels.emplace_back(field, i < plan.flags.size() ? plan.flags[i] : field);
    }
    return {base, point};
}

json plan_to_json(const SweepPlan& plan) {
    json runs = json::array();
    for (const PlannedRun& r : plan.runs) runs.push_back(json{{"index", r.index}, {"id", r.id}, {"point", r.point}});
    return json{{"format", kPlanFormat}, {"base", plan.base}, {"fields", plan.fields}, {"flags", plan.flags},
                {"run_count", plan.runs.size()}, {"runs", runs}};
}

SweepPlan plan_from_json(const json& doc, const std::string& origin) {
    try {
        if (!doc.is_object() || doc.value("format", "") != kPlanFormat)
            throw InputError(fmt::format("{}: not a polyroll sweep plan (expected \"format\": \"{}\")", origin,
                                         kPlanFormat));
        SweepPlan plan;
        plan.base = doc.at("base");
        plan.fields = doc.at("fields").get<std::vector<std::string>>();
        plan.flags = doc.at("flags").get<std::vector<std::string>>();
        for (const json& r : doc.at("runs")) add_run(plan, r.at("point"));
        // The ids are recomputed: a hand-edited or truncated plan is caught here, not half-way through.
        const json& runs = doc.at("runs");
        if (runs.size() != doc.at("run_count").get<std::size_t>())
            throw InputError(fmt::format("{}: holds {} runs but says run_count = {}", origin, runs.size(),
                                         doc.at("run_count").dump()));
        for (std::size_t i = 0; i < plan.runs.size(); ++i)
            if (runs[i].at("id") != plan.runs[i].id || runs[i].at("index") != i)
                throw InputError(fmt::format("{}: run {} does not match its parameters (edited by hand?)", origin, i));
        return plan;
    } catch (const json::exception& e) {
        throw InputError(fmt::format("{}: not a valid sweep plan ({})", origin, json_error_text(e.what())));
    }
}

std::filesystem::path plan_path(const std::filesystem::path& dir) { return dir / "plan.json"; }

void write_plan(const std::filesystem::path& dir, const SweepPlan& plan) {
    write_file_atomic(plan_path(dir), plan_to_json(plan).dump(1) + "\n");
}

SweepPlan read_plan(const std::filesystem::path& dir) {
    const std::filesystem::path p = plan_path(dir);
    std::ifstream in(p, std::ios::binary);
    if (!in)
        throw InputError(fmt::format("{}: no sweep plan there (allowed: a folder written by polyroll sweep "
                                     "--plan-only or by a sweep)", dir.string()));
    std::stringstream buf;
    buf << in.rdbuf();
    json doc;
    try {
        doc = json::parse(buf.str());
    } catch (const json::parse_error& e) {
        throw InputError(fmt::format("{}: not valid JSON (a partly copied plan?)", p.string()));
    }
    return plan_from_json(doc, p.string());
}

std::vector<std::size_t> shard_indices(std::size_t run_count, int k, int n) {
    std::vector<std::size_t> out;
    for (std::size_t i = static_cast<std::size_t>(k - 1); i < run_count; i += static_cast<std::size_t>(n))
        out.push_back(i);
    return out;
}

std::pair<int, int> parse_shard(const std::string& text) {
    const auto slash = text.find('/');
    int k = 0, n = 0;
    bool ok = slash != std::string::npos;
    if (ok) {
        try {
            std::size_t used_k = 0, used_n = 0;
            const std::string ks = text.substr(0, slash), ns = text.substr(slash + 1);
            k = std::stoi(ks, &used_k);
            n = std::stoi(ns, &used_n);
            ok = used_k == ks.size() && used_n == ns.size();
        } catch (const std::exception&) {
            ok = false;
        }
    }
    if (!ok || n < 1 || n > 100000 || k < 1 || k > n)
        throw InputError(fmt::format("--shard {} is not allowed (allowed: K/N with 1 <= K <= N <= 100000, e.g. 3/16)",
                                     text));
    return {k, n};
}

void check_scene_field(const std::string& field, const std::string& flag) {
    static const std::vector<std::string> paths = [] {
        std::vector<std::string> out;
        collect_paths(scene_to_json(resolve_scene({})), "", out);
        return out;
    }();
    if (std::find(paths.begin(), paths.end(), field) != paths.end()) return;
    std::string allowed;
    for (const auto& p : paths) allowed += (allowed.empty() ? "" : ", ") + p;
    throw InputError(fmt::format("{}: '{}' is not a scene field (allowed: {})", flag, field, allowed));
}

}  // namespace polyroll::sweep
