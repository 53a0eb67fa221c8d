// The results table: see results_table.h.
#include "sweep/results_table.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <fmt/core.h>

#include "sim/errors.h"
#include "sim/files/results_io.h"
#include "sim/scene/scene_json.h"
#include "sim/scene/shell_label.h"
#include "sweep/grid_values.h"

namespace polyroll::sweep {
namespace {

// The scene columns every table has (what the figures group by), and the field each shows.
const std::vector<std::pair<std::string, std::string>> kSceneColumns = {
    {"polygon", "shell.preset"},   {"sides", "shell.sides"},         {"material", "fill.material.preset"},
    {"fill_ratio", "fill.ratio"},  {"ramp", "ramp.preset"},          {"angle_deg", "ramp.angle_deg"},
    {"release", "release.pose"},   {"fidelity", "fidelity.preset"},  {"model", "run.model"},
    {"seed", "run.seed"}};

const std::vector<std::string> kResultColumns = {
    "status",       "model_used", "behaviour",  "distance_m",     "terminal_velocity_m_s", "impacts",
    "mean_impact_energy_ratio",   "stop_time_s",    "end_time_s",            "grains",
    "grains_inside", "fill_mass_kg", "max_energy_gain_J", "model_valid",     "reason",
    "wall_time_s"};

std::string scene_value(const Scene& s, const std::string& field) {
    if (field == "shell.preset") return has_presets_sides(s.shell) ? s.shell.preset : "custom";
    if (field == "shell.sides") return std::to_string(s.shell.sides);
    if (field == "fill.material.preset") return s.fill.material.preset;
    if (field == "fill.ratio") return number_cell(s.fill.ratio);
    if (field == "ramp.preset") return s.ramp.preset;
    if (field == "ramp.angle_deg") return number_cell(s.ramp.angle_deg);
    if (field == "release.pose") return to_string(s.release.pose);
    if (field == "fidelity.preset") return s.fidelity.preset;
    if (field == "run.model") return to_string(s.run.model);
    if (field == "run.seed") return std::to_string(s.run.seed);
    return "";
}

}  // namespace

std::string number_cell(double v) { return fmt::format("{}", v); }

std::optional<std::size_t> find_column(const std::vector<std::string>& header, const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) return std::nullopt;
    return static_cast<std::size_t>(it - header.begin());
}

std::size_t column_index(const TableFile& t, const std::string& name) {
    if (const std::optional<std::size_t> c = find_column(t.header, name)) return *c;
    throw InputError(fmt::format("{}: no column {} (allowed: a polyroll results table, which has it)", t.path.string(),
                                 name));
}

std::string cell(const TableFile& t, const std::vector<std::string>& row, const std::string& column) {
    const std::optional<std::size_t> c = find_column(t.header, column);
    return c ? row.at(*c) : std::string();
}

double cell_number(const std::string& cell) { return cell.empty() ? NAN : std::stod(cell); }

RowOutcome row_outcome(const TableFile& t, const std::vector<std::string>& row) {
    RowOutcome o;
    o.ok = cell(t, row, "status") == "ok";
    o.behaviour = o.ok ? cell(t, row, "behaviour") : "failed";
    o.distance_m = cell_number(cell(t, row, "distance_m"));
    o.vt_m_s = cell_number(cell(t, row, "terminal_velocity_m_s"));
    o.wall_s = cell_number(cell(t, row, "wall_time_s"));
    return o;
}

ResultsTable::ResultsTable(const SweepPlan& plan) {
    columns_ = {"index", "run_id"};
    for (const auto& [name, field] : kSceneColumns) columns_.push_back(name);
    for (const std::string& f : plan.fields) {
        const bool has_own = std::any_of(kSceneColumns.begin(), kSceneColumns.end(),
                                         [&](const auto& c) { return c.second == f; });
        if (!has_own) {
            extra_fields_.push_back(f);
            columns_.push_back(f);
        }
    }
    columns_.insert(columns_.end(), kResultColumns.begin(), kResultColumns.end());
}

std::size_t ResultsTable::column(const std::string& name) const {
    const auto it = std::find(columns_.begin(), columns_.end(), name);
    if (it == columns_.end()) throw std::out_of_range("no column " + name);
    return static_cast<std::size_t>(it - columns_.begin());
}

std::string ResultsTable::header_line() const { return csv_line(columns_); }

std::string ResultsTable::row_line(const PlannedRun& run, const RunRecord& rec) const {
    std::vector<std::string> c;
    c.push_back(std::to_string(run.index));
    c.push_back(run.id);
    auto point_value = [&](const std::string& field) {
        return run.point.contains(field) ? value_text(run.point.at(field)) : std::string();
    };
    for (const auto& [name, field] : kSceneColumns)
        c.push_back(rec.result ? scene_value(rec.result->scene, field) : point_value(field));
    // Extra swept fields show the value as planned (the resolved scene holds the same number).
    for (const std::string& f : extra_fields_) c.push_back(point_value(f));
    c.push_back(rec.ok ? "ok" : "failed");
    if (rec.result) {
        const RunResult& r = *rec.result;
        const Measurements& m = r.measured;
        // The model that ran: auto's choice, and the one it handed over to if it did.
        const ModelChoice* choice = r.model_choice ? &*r.model_choice : nullptr;
        std::string used = to_string(choice ? choice->model : r.scene.run.model);
        if (choice && choice->hand_over_time_s && choice->then) used += " then " + to_string(*choice->then);
        c.push_back(used);
        c.push_back(to_string(m.behaviour));
        c.push_back(number_cell(m.distance_m));
        c.push_back(m.terminal_velocity_m_s ? number_cell(*m.terminal_velocity_m_s) : "");
        c.push_back(std::to_string(m.impacts.size()));
        c.push_back(m.impacts.empty() ? "" : number_cell(mean_impact_ratio(m)));
        c.push_back(m.stop_time_s ? number_cell(*m.stop_time_s) : "");
        c.push_back(number_cell(m.end_time_s));
        c.push_back(std::to_string(r.grains));
        c.push_back(std::to_string(m.grains_inside));
        c.push_back(number_cell(r.fill_mass_kg));
        c.push_back(number_cell(m.max_energy_gain_J));
        c.push_back(r.model_valid ? "true" : "false");
    } else {
        for (int i = 0; i < 13; ++i) c.push_back("");  // model_used to model_valid
    }
    c.push_back(rec.reason);
    c.push_back(fmt::format("{:.4f}", rec.wall_time_s));
    return csv_line(c);
}

std::string csv_cell(const std::string& raw) {
    std::string s = raw;
    std::replace(s.begin(), s.end(), '\n', ' ');
    std::replace(s.begin(), s.end(), '\r', ' ');
    const bool quote = s.find_first_of(",\"") != std::string::npos ||
                       (!s.empty() && (s.front() == ' ' || s.back() == ' '));
    if (!quote) return s;
    std::string q = "\"";
    for (char ch : s) {
        if (ch == '"') q += '"';
        q += ch;
    }
    return q + "\"";
}

std::string csv_line(const std::vector<std::string>& cells) {
    std::string line;
    for (std::size_t i = 0; i < cells.size(); ++i) line += (i ? "," : "") + csv_cell(cells[i]);
    return line + "\n";
}

std::vector<std::string> parse_csv_line(const std::string& line) {
    std::vector<std::string> cells(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        const char ch = line[i];
        if (quoted) {
            if (ch == '"' && i + 1 < line.size() && line[i + 1] == '"') {
                cells.back() += '"';
                ++i;
            } else if (ch == '"') {
                quoted = false;
            } else {
                cells.back() += ch;
            }
        } else if (ch == '"') {
            quoted = true;
        } else if (ch == ',') {
            cells.emplace_back();
        } else {
            cells.back() += ch;
        }
    }
    return cells;
}

TableFile read_table(const std::filesystem::path& path) {
    TableFile t;
    t.path = path;
    std::ifstream in(path, std::ios::binary);
    if (!in) return t;
    std::stringstream buf;
    buf << in.rdbuf();
    const std::string text = buf.str();
    std::size_t pos = 0;
    bool first = true;
    while (pos < text.size()) {
        const std::size_t nl = text.find('\n', pos);
        if (nl == std::string::npos) {  // cut short by a crash: the run is not finished
            t.had_partial_line = true;
            break;
        }
        const std::string line = text.substr(pos, nl - pos);
        pos = nl + 1;
        if (first) {
            t.header = parse_csv_line(line);
            first = false;
            continue;
        }
        auto cells = parse_csv_line(line);
        if (cells.size() != t.header.size())
            throw InputError(fmt::format("{}: a row has {} cells, the header {} (allowed: a polyroll results table)",
                                         path.string(), cells.size(), t.header.size()));
        t.rows.push_back(std::move(cells));
    }
    if (t.header.empty() && t.had_partial_line) t.had_partial_line = true;
    return t;
}

std::string table_text(const std::vector<std::string>& header, std::vector<std::vector<std::string>> rows) {
    std::stable_sort(rows.begin(), rows.end(),
                     [](const auto& a, const auto& b) { return std::stoull(a.at(0)) < std::stoull(b.at(0)); });
    std::string out = csv_line(header);
    for (const auto& r : rows) out += csv_line(r);
    return out;
}

}  // namespace polyroll::sweep
