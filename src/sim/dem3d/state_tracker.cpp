// Measurements from recorded states: see state_tracker.h. The rules and their reasons are in
// sim/shell_tracker.cpp.
#include "sim/dem3d/state_tracker.h"

#include <sstream>
#include <stdexcept>

#include <fmt/core.h>

#include "sim/geometry/shell_pose.h"

namespace polyroll::dem3d {

std::vector<StateRow> parse_states_csv(const std::string& text) {
    constexpr int kColumns = 12;
    std::istringstream in(text);
    std::string line;
    const std::string header = "time_s,x_m,y_m,angle_rad,vx_m_s,vy_m_s,omega_rad_s,kinetic_J,potential_J,fill_ahead_m,fill_up_m,grains_inside";
    if (!std::getline(in, line) || line != header)
        throw std::runtime_error(fmt::format("states.csv: the first line is not the header '{}'", header));
    std::vector<StateRow> rows;
    int line_no = 1;
    while (std::getline(in, line)) {
        ++line_no;
        if (line.empty()) continue;
        double v[kColumns] = {};
        std::istringstream fields(line);
        std::string cell;
        int k = 0;
        try {
            for (; k < kColumns && std::getline(fields, cell, ','); ++k) {
                size_t used = 0;
                v[k] = std::stod(cell, &used);
                if (used != cell.size()) throw std::invalid_argument(cell);
            }
        } catch (const std::exception&) {
            throw std::runtime_error(fmt::format("states.csv line {}: '{}' is not a number", line_no, cell));
        }
        if (k != kColumns || std::getline(fields, cell, ','))
            throw std::runtime_error(
                fmt::format("states.csv line {}: {} columns where {} are expected", line_no, k, kColumns));
        StateRow r;
        r.time_s = v[0];
        r.shell.pose.centre_m = {v[1], v[2]};
        r.shell.pose.angle_rad = v[3];
        r.shell.velocity_m_s = {v[4], v[5]};
        r.shell.angular_velocity_rad_s = v[6];
        r.kinetic_J = v[7];
        r.potential_J = v[8];
        r.fill_offset_m = {v[9], v[10]};
        r.grains_inside = static_cast<int>(v[11]);
        rows.push_back(r);
    }
    return rows;
}

ObservedState observed_state(const StateRow& r, bool has_fill) {
    ObservedState s;
    s.time_s = r.time_s;
    s.shell = r.shell;
    s.kinetic_J = r.kinetic_J;
    s.potential_J = r.potential_J;
    if (has_fill) s.fill_offset_m = r.fill_offset_m;
    return s;
}

TrajectorySample trajectory_sample(const StateRow& r, const StateRow& release, bool has_fill) {
    return polyroll::trajectory_sample(observed_state(r, has_fill), release.shell.pose);
}

Measurements measure_states(const Scene& scene, const std::vector<StateRow>& rows, const TrackRules& rules) {
    if (rows.empty()) {
        Measurements m;
        m.behaviour = Behaviour::diverged;
        m.divergence = "at t = 0.0000 s: the 3D reference wrote no state";
        return m;
    }
    TrackRules box = rules;
    box.grains_leave_through = "the box through its walls or lids";
    box.remedy = "use a shorter dem3d.contact_time_s";
    const bool has_fill = rules.grains > 0;
    // The script counts the grains in the box at every row: the rule reads the row being measured.
    const StateRow* row = &rows.front();
    ShellTracker tracker(scene, rows.front().shell.pose, box, [&row] { return GrainCheck{row->grains_inside, {}}; });
    for (size_t i = 0; i < rows.size(); ++i) {
        row = &rows[i];
        if (!tracker.observe(static_cast<long>(i), observed_state(*row, has_fill))) return tracker.measurements();
    }
    // The rows ended before any rule ended the run (the script stops on the same rules, so only a run
    // cut short): the time limit at the last row.
    tracker.end_at_last_state();
    return tracker.measurements();
}

}  // namespace polyroll::dem3d
