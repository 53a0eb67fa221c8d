// Extending a sweep with more values: see plan_extension.h.
#include "sweep/plan_extension.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include <fmt/core.h>

#include "sim/errors.h"
#include "sweep/results_table.h"
#include "sweep/sweep_runner.h"
#include "sweep/table_writer.h"

namespace polyroll::sweep {

namespace fs = std::filesystem;

std::string extension_refusal(const SweepPlan& existing, const SweepPlan& wider) {
    if (existing.base != wider.base) return "its base scene differs from this command's (--scene and fixed flags)";
    if (existing.fields != wider.fields) {
        // Name the difference: the flags only one of the two sweeps.
        auto only_in = [](const SweepPlan& a, const SweepPlan& b) {
            std::string out;
            for (std::size_t i = 0; i < a.fields.size(); ++i)
                if (std::find(b.fields.begin(), b.fields.end(), a.fields[i]) == b.fields.end())
                    out += (out.empty() ? "" : ", ") + a.flags.at(i);
            return out;
        };
        const std::string added = only_in(wider, existing), dropped = only_in(existing, wider);
        std::string diff = added.empty() ? "" : "this command also sweeps " + added;
        if (!dropped.empty()) diff += (diff.empty() ? "" : " and ") + ("it also sweeps " + dropped);
        if (diff.empty()) diff = "its flags come in another order";
        return diff + " (the same flags with more values extend it)";
    }
    std::set<std::string> ids;
    for (const PlannedRun& r : wider.runs) ids.insert(r.id);
    std::size_t missing = 0;
    for (const PlannedRun& r : existing.runs) missing += ids.count(r.id) == 0;
    if (missing > 0)
        return fmt::format("{} of its {} runs are not in this command's grid (a sweep can gain values, not lose them)",
                           missing, existing.runs.size());
    return "";
}

void extend_plan(const fs::path& dir, const SweepPlan& wider) {
    const std::vector<fs::path> tables = table_paths(dir);
    for (const fs::path& p : tables)
        if (p.filename() != "results.csv")
            throw InputError(fmt::format("--out {}: has shard tables ({}); combine them first with 'polyroll sweep "
                                         "--merge {}', then extend", dir.string(), p.filename().string(), dir.string()));
    std::map<std::string, std::size_t> index_of;
    for (const PlannedRun& r : wider.runs) index_of[r.id] = r.index;
    const ResultsTable table(wider);
    {
        // The writer takes the table's lock (a sweep running in this folder refuses the extension)
        // and replaces the table whole when closed.
        TableWriter writer(dir / "results.csv", table.columns(), false);
        std::vector<std::vector<std::string>> rows;
        for (std::vector<std::string> row : writer.existing_rows()) {
            const auto it = index_of.find(row.at(1));
            if (it == index_of.end()) continue;  // not a run of this sweep: it would be ignored anyway
            row.at(0) = std::to_string(it->second);
            rows.push_back(std::move(row));
        }
        writer.replace_rows(std::move(rows));
        writer.close_sorted();
    }
    write_plan(dir, wider);
}

}  // namespace polyroll::sweep
