// The sweep's results table (results.csv): one row per run, the scene's main parameters, every
// swept field, and what the run measured. Rows are complete lines; a table read back drops a last
// line cut short by a crash. Everything but the last column, wall_time_s, is a function of the
// plan, so tables of the same plan agree byte for byte once wall_time_s is set aside.
#pragma once

#include <cmath>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "sim/run_result.h"
#include "sweep/sweep_plan.h"

namespace polyroll::sweep {

// What became of one run.
struct RunRecord {
    bool ok = false;            // false: invalid point, an error, or the run diverged
    std::optional<RunResult> result;  // absent when the scene could not be built or run
    std::string reason;         // why it failed (the InputError or divergence message)
    double wall_time_s = 0.0;
};

class ResultsTable {
public:
    explicit ResultsTable(const SweepPlan& plan);

    const std::vector<std::string>& columns() const { return columns_; }
    std::string header_line() const;  // with the newline
    std::string row_line(const PlannedRun& run, const RunRecord& record) const;

    // Column position by name; throws std::out_of_range if absent.
    std::size_t column(const std::string& name) const;

private:
    std::vector<std::string> columns_;
    std::vector<std::string> extra_fields_;  // swept fields without a column of their own
};

// A table as read from disk: the header and the complete rows.
struct TableFile {
    std::filesystem::path path;     // where it was read from, for messages
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    bool had_partial_line = false;  // a last line without its newline (dropped)
};

// Where `name` is in a header, if it is there.
std::optional<std::size_t> find_column(const std::vector<std::string>& header, const std::string& name);
// Where `name` is in the table's header; throws InputError naming the file and the column.
std::size_t column_index(const TableFile& t, const std::string& name);

// Reads a results table; an absent file gives an empty table. Throws InputError if the file is
// not a table (no header, a row with the wrong number of cells).
TableFile read_table(const std::filesystem::path& path);

// CSV cells: quoted when they hold a comma, a quote or leading/trailing spaces; newlines become spaces.
std::string csv_cell(const std::string& s);
std::string csv_line(const std::vector<std::string>& cells);  // with the newline
std::vector<std::string> parse_csv_line(const std::string& line);

// Rows sorted by their index column, as text, header first.
std::string table_text(const std::vector<std::string>& header, std::vector<std::vector<std::string>> rows);

// How numbers are written in the table: shortest exact form, so equal doubles give equal text.
std::string number_cell(double v);

// A row's cell by column name; "" where the table has no such column.
std::string cell(const TableFile& t, const std::vector<std::string>& row, const std::string& column);
// A number cell read back; NaN for an empty one (a run that measured nothing there).
double cell_number(const std::string& cell);

// What a row says of its run, as the studies' reports read it.
struct RowOutcome {
    bool ok = false;                    // status "ok"
    std::string behaviour;              // "failed" when the run did not end well
    double distance_m = NAN, vt_m_s = NAN, wall_s = NAN;  // NaN where the row has none
};
RowOutcome row_outcome(const TableFile& t, const std::vector<std::string>& row);

}  // namespace polyroll::sweep
