// Merging a sweep folder's tables: see merge.h.
#include "sweep/merge.h"

#include <map>

#include <fmt/core.h>

#include "sim/errors.h"
#include "sweep/results_table.h"
#include "sweep/sweep_runner.h"
#include "sweep/table_writer.h"

namespace polyroll::sweep {

namespace fs = std::filesystem;

MergeReport merge_tables(const SweepPlan& plan, const fs::path& dir) {
    const ResultsTable table(plan);
    const std::size_t status = table.column("status");
    MergeReport report;
    report.runs = plan.runs.size();
    std::map<std::size_t, std::vector<std::string>> rows;
    auto take = [&](const fs::path& origin, const std::vector<std::vector<std::string>>& from) {
        for (const auto& row : from) {
            std::size_t i = 0;
            try {
                i = std::stoull(row.at(0));
            } catch (const std::exception&) {
                throw InputError(fmt::format("{}: index '{}' is not a run index", origin.string(), row.at(0)));
            }
            if (i >= plan.runs.size() || plan.runs[i].id != row.at(1))
                throw InputError(fmt::format("{}: run {} ({}) is not in this folder's plan (a table of another sweep?)",
                                             origin.string(), row.at(0), row.at(1)));
            auto it = rows.find(i);
            if (it == rows.end())
                rows.emplace(i, row);
            else if (it->second.at(status) != "ok" && row.at(status) == "ok")
                it->second = row;
        }
    };
    // The shards' tables are checked before results.csv is touched: a refused merge changes nothing.
    std::vector<std::pair<fs::path, TableFile>> shards;
    for (const fs::path& p : table_paths(dir)) {
        if (p.filename() == "results.csv" && p.parent_path() == dir) continue;
        TableFile t = read_table(p);
        if (t.header.empty()) continue;
        if (t.header != table.columns())
            throw InputError(fmt::format("{}: its columns differ from this plan's table (a table of another sweep?)",
                                         p.string()));
        shards.emplace_back(p, std::move(t));
    }
    for (const auto& [p, t] : shards) take(p, t.rows);  // checks every row's id against the plan
    rows.clear();
    // results.csv through its writer: locked against a sweep appending to it meanwhile. Its rows come
    // first, so a run in several tables keeps the row results.csv had unless a shard has it "ok".
    TableWriter out(dir / "results.csv", table.columns(), false);
    take(dir / "results.csv", out.existing_rows());
    for (auto& [p, t] : shards) take(p, t.rows);
    report.tables = 1 + shards.size();
    std::vector<std::vector<std::string>> merged;
    for (auto& [i, row] : rows) {
        if (row.at(status) == "failed") ++report.failed;
        merged.push_back(std::move(row));
    }
    for (std::size_t i = 0; i < plan.runs.size(); ++i)
        if (!rows.count(i)) report.missing.push_back(i);
    report.rows = merged.size();
    out.replace_rows(std::move(merged));
    out.close_sorted();
    return report;
}

}  // namespace polyroll::sweep
