// Reading observations files and expanding them into one sweep plan: see observations.h.
#include "sweep/observations.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <fmt/core.h>

#include "sim/assets.h"
#include "sim/errors.h"
#include "sim/scene/json_path.h"
#include "sim/message_text.h"
#include "sim/scene/scene_fields.h"
#include "sim/scene/scene_json.h"
#include "sweep/grid_values.h"

namespace polyroll::sweep {
namespace {

using json = nlohmann::ordered_json;

// Observations files are small; the cap keeps a wrong path (a log, /dev/zero) from filling memory.
constexpr std::size_t kMaxObservationFileBytes = 4 << 20;

const std::vector<std::string> kBehaviours = {"stopped_at_first_impact", "stopped", "rolled_to_end"};

// Builds the one-line messages: "FILE: observation 'ID': KEY = VALUE is not allowed (allowed: ...)".
struct Where {
    std::string origin, id;
    [[noreturn]] void fail(const std::string& key, const json& value, const std::string& allowed) const {
        const std::string who = id.empty() ? origin : fmt::format("{}: observation '{}'", origin, id);
        throw InputError(fmt::format("{}: {} = {} is not allowed (allowed: {})", who, key,
                                     printable_line(value.dump()), allowed));
    }
    [[noreturn]] void missing(const std::string& key, const std::string& allowed) const {
        const std::string who = id.empty() ? origin : fmt::format("{}: observation '{}'", origin, id);
        throw InputError(fmt::format("{}: {} is missing (allowed: {})", who, key, allowed));
    }
};

std::string joined(const std::vector<std::string>& names) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

void check_keys(const Where& w, const std::string& prefix, const json& obj, const std::vector<std::string>& allowed) {
    for (const auto& [k, v] : obj.items())
        if (std::find(allowed.begin(), allowed.end(), k) == allowed.end())
            w.fail(prefix + k, v, "the keys " + joined(allowed));
}

bool is_field(const std::string& path) {
    for (const SceneField& f : scene_fields())
        if (f.path == path) return true;
    return false;
}

std::string field_list() {
    std::vector<std::string> paths;
    for (const SceneField& f : scene_fields()) paths.emplace_back(f.path);
    return "scene fields: " + joined(paths);
}

// {"fill": {"ratio": 0.25, "material": "bb"}} -> fill.ratio = 0.25, fill.material.preset = "bb".
void flatten_scene(const Where& w, const json& doc, const std::string& prefix, json& out) {
    for (const auto& [k, v] : doc.items()) {
        const std::string path = prefix.empty() ? k : prefix + "." + k;
        if (v.is_object())
            flatten_scene(w, v, path, out);
        else if (v.is_string() && !is_field(path) && is_field(path + ".preset"))
            out[path + ".preset"] = v;
        else if (is_field(path))
            out[path] = v;
        else
            w.fail("scene." + path, v, field_list());
    }
}

double number_in(const Where& w, const std::string& key, const json& v, double lo, double hi, bool lo_open,
                 const std::string& allowed) {
    if (!v.is_number()) w.fail(key, v, allowed);
    const double x = v.get<double>();
    if (!std::isfinite(x) || x > hi || x < lo || (lo_open && x == lo)) w.fail(key, v, allowed);
    return x;
}

std::string string_of(const Where& w, const std::string& key, const json& v) {
    if (!v.is_string()) w.fail(key, v, "text");
    return v.get<std::string>();
}

std::string behaviour_of(const Where& w, const std::string& key, const json& v) {
    if (!v.is_string() || std::find(kBehaviours.begin(), kBehaviours.end(), v.get<std::string>()) == kBehaviours.end())
        w.fail(key, v, joined(kBehaviours));
    return v.get<std::string>();
}

void read_observed(const Where& w, const json& o, Observation& ob) {
    check_keys(w, "observed.", o, {"behaviour", "not_behaviour", "linear_fit", "terminal_velocity", "distance_m",
                                   "terminal_velocity_m_s"});
    if (o.contains("behaviour")) ob.behaviour = behaviour_of(w, "observed.behaviour", o["behaviour"]);
    if (o.contains("not_behaviour")) ob.not_behaviour = behaviour_of(w, "observed.not_behaviour", o["not_behaviour"]);
    if (o.contains("distance_m"))
        ob.distance_m = number_in(w, "observed.distance_m", o["distance_m"], 0, 1e6, false, "a distance in m, 0 or more");
    if (o.contains("terminal_velocity_m_s"))
        ob.terminal_velocity_m_s = number_in(w, "observed.terminal_velocity_m_s", o["terminal_velocity_m_s"], 0, 1e6,
                                             false, "a speed in m/s, 0 or more");
    const bool measured = ob.distance_m || ob.terminal_velocity_m_s;
    if (!ob.behaviour.empty() && !ob.not_behaviour.empty())
        w.fail("observed", o, "exactly one of 'behaviour' and 'not_behaviour'");
    if (ob.behaviour.empty() && ob.not_behaviour.empty() && !measured)
        w.fail("observed", o, "one of 'behaviour' and 'not_behaviour', or a measured 'distance_m' or "
                              "'terminal_velocity_m_s'");
    if (o.contains("terminal_velocity"))
        ob.terminal_velocity = string_of(w, "observed.terminal_velocity", o["terminal_velocity"]);
    if (o.contains("linear_fit")) {
        const json& f = o["linear_fit"];
        if (!f.is_object()) w.fail("observed.linear_fit", f, "an object with slope_m_per_deg and intercept_m");
        check_keys(w, "observed.linear_fit.", f, {"slope_m_per_deg", "intercept_m", "r_squared", "distance_uncertainty_m"});
        LinearFit fit;
        if (!f.contains("slope_m_per_deg")) w.missing("observed.linear_fit.slope_m_per_deg", "a number in m/deg");
        if (!f.contains("intercept_m")) w.missing("observed.linear_fit.intercept_m", "a number in m");
        fit.slope_m_per_deg = number_in(w, "observed.linear_fit.slope_m_per_deg", f["slope_m_per_deg"], -1e6, 1e6,
                                        false, "a number in m/deg, not 0");
        if (fit.slope_m_per_deg == 0.0) w.fail("observed.linear_fit.slope_m_per_deg", f["slope_m_per_deg"], "a number in m/deg, not 0");
        fit.intercept_m = number_in(w, "observed.linear_fit.intercept_m", f["intercept_m"], -1e6, 1e6, false, "a number in m");
        if (f.contains("r_squared"))
            fit.r_squared = number_in(w, "observed.linear_fit.r_squared", f["r_squared"], 0, 1, false, "from 0 to 1");
        if (f.contains("distance_uncertainty_m"))
            fit.distance_uncertainty_m = number_in(w, "observed.linear_fit.distance_uncertainty_m",
                                                   f["distance_uncertainty_m"], 0, 1e6, false, "0 m or more");
        ob.linear_fit = fit;
    }
}

void read_tolerance(const Where& w, const json& t, Observation& ob) {
    check_keys(w, "tolerance.", t, {"behaviour_share", "angle_range_deg", "slope_relative", "distance_m",
                                    "terminal_velocity_m_s", "reason"});
    const bool shares = !ob.behaviour.empty() || !ob.not_behaviour.empty();
    if (t.contains("behaviour_share")) {
        if (!shares) w.fail("tolerance.behaviour_share", t["behaviour_share"], "only with observed.behaviour or not_behaviour");
        ob.behaviour_share = number_in(w, "tolerance.behaviour_share", t["behaviour_share"], 0, 1, true,
                                       "a share above 0 and at most 1");
    } else if (!ob.angle_range_deg && shares) {
        w.missing("tolerance.behaviour_share", "a share above 0 and at most 1");
    }
    // A measured number needs its tolerance, and a tolerance its number.
    auto measured_tolerance = [&](const char* key, bool observed, const char* unit, double& out) {
        const std::string name = std::string("tolerance.") + key;
        if (!t.contains(key)) {
            if (observed) w.missing(name, fmt::format("{} above 0, how far the simulation's mean may be off", unit));
            return;
        }
        if (!observed) w.fail(name, t[key], fmt::format("only with observed.{}", key));
        out = number_in(w, name, t[key], 0, 1e6, true, fmt::format("{} above 0", unit));
    };
    measured_tolerance("distance_m", ob.distance_m.has_value(), "m", ob.distance_tolerance_m);
    measured_tolerance("terminal_velocity_m_s", ob.terminal_velocity_m_s.has_value(), "m/s",
                       ob.terminal_velocity_tolerance_m_s);
    if (ob.angle_range_deg) {
        if (!t.contains("angle_range_deg")) w.missing("tolerance.angle_range_deg", "degrees above 0");
        // The slope's tolerance scores observed.linear_fit: a band without a line needs none.
        if (!t.contains("slope_relative") && ob.linear_fit)
            w.missing("tolerance.slope_relative", "a share above 0, with observed.linear_fit");
        ob.angle_tolerance_deg = number_in(w, "tolerance.angle_range_deg", t["angle_range_deg"], 0, 90, true,
                                           "degrees above 0, at most 90");
        if (t.contains("slope_relative"))
            ob.slope_relative = number_in(w, "tolerance.slope_relative", t["slope_relative"], 0, 100, true,
                                          "a share above 0");
    } else {
        for (const char* k : {"angle_range_deg", "slope_relative"})
            if (t.contains(k)) w.fail(std::string("tolerance.") + k, t[k], "only with an angle_range_deg observation");
    }
    if (t.contains("reason")) ob.reason = string_of(w, "tolerance.reason", t["reason"]);
}

// "angles_deg": {"from": 9, "to": 17, "step": 0.25} or a list of angles.
std::vector<double> read_angles(const Where& w, const json& a) {
    const std::string allowed = "a list of angles or {\"from\", \"to\", \"step\"} in degrees, from 0 to 89";
    std::vector<double> out;
    if (a.is_array()) {
        for (const json& v : a) out.push_back(number_in(w, "angles_deg", v, 0, 89, false, allowed));
    } else if (a.is_object()) {
        check_keys(w, "angles_deg.", a, {"from", "to", "step"});
        for (const char* k : {"from", "to", "step"})
            if (!a.contains(k)) w.missing(std::string("angles_deg.") + k, allowed);
        const double from = number_in(w, "angles_deg.from", a["from"], 0, 89, false, allowed);
        const double to = number_in(w, "angles_deg.to", a["to"], from, 89, false, "from 'from' to 89 degrees");
        const double step = number_in(w, "angles_deg.step", a["step"], 0, 89, true, "above 0 degrees");
        try {
            out = inclusive_range("angles_deg", from, to, step, 1000);
        } catch (const InputError&) {
            w.fail("angles_deg", a, "at most 1000 angles");
        }
    } else {
        w.fail("angles_deg", a, allowed);
    }
    std::sort(out.begin(), out.end());
    if (out.empty() || std::adjacent_find(out.begin(), out.end()) != out.end())
        w.fail("angles_deg", a, "at least one angle, each once");
    return out;
}

Observation read_observation(const std::string& origin, const json& e, std::size_t n) {
    Where w{origin, ""};
    if (!e.is_object()) w.fail(fmt::format("observations[{}]", n), e, "an object");
    if (!e.contains("id") || !e["id"].is_string() || e["id"].get<std::string>().empty())
        w.fail(fmt::format("observations[{}].id", n), e.value("id", json()), "a short unique name");
    Observation ob;
    ob.id = e["id"].get<std::string>();
    w.id = ob.id;
    check_keys(w, "", e, {"id", "source", "scene", "grid", "angle_range_deg", "angles_deg", "observed", "tolerance", "notes"});
    if (!e.contains("source")) w.missing("source", "where the observation comes from, as text");
    ob.source = string_of(w, "source", e["source"]);
    if (e.contains("notes")) string_of(w, "notes", e["notes"]);
    if (e.contains("scene")) {
        if (!e["scene"].is_object()) w.fail("scene", e["scene"], "a partial scene, as in a scene file");
        flatten_scene(w, e["scene"], "", ob.scene);
    }
    if (e.contains("grid")) {
        const json& g = e["grid"];
        if (!g.is_object()) w.fail("grid", g, "an object of scene field paths and lists of values");
        for (const auto& [path, values] : g.items()) {
            if (!is_field(path)) w.fail("grid." + path, values, field_list());
            if (path == "run.seed") w.fail("grid.run.seed", values, "no seeds in a grid: polyroll validate --seeds N");
            if (!values.is_array() || values.empty()) w.fail("grid." + path, values, "a non-empty list of values");
            std::set<std::string> seen;
            for (const json& v : values)
                if (!seen.insert(v.dump()).second) w.fail("grid." + path, values, "each value once");
            ob.grid.emplace_back(path, std::vector<json>(values.begin(), values.end()));
        }
    }
    if (ob.scene.contains("run.seed")) w.fail("scene.run.seed", ob.scene["run.seed"], "no seed: polyroll validate --seeds N");
    if (!e.contains("observed")) w.missing("observed", "an object: behaviour or not_behaviour, ...");
    if (!e["observed"].is_object()) w.fail("observed", e["observed"], "an object: behaviour or not_behaviour, ...");
    read_observed(w, e["observed"], ob);
    if (e.contains("angle_range_deg")) {
        const json& r = e["angle_range_deg"];
        const std::string allowed = "[from, to] in degrees, from < to, within 0 to 89";
        if (!r.is_array() || r.size() != 2) w.fail("angle_range_deg", r, allowed);
        const double lo = number_in(w, "angle_range_deg", r[0], 0, 89, false, allowed);
        const double hi = number_in(w, "angle_range_deg", r[1], 0, 89, false, allowed);
        if (!(lo < hi)) w.fail("angle_range_deg", r, allowed);
        ob.angle_range_deg = std::make_pair(lo, hi);
        if (ob.behaviour.empty())
            w.fail("observed", e["observed"], "an angle-range observation names the 'behaviour' of its band");
        if (ob.distance_m || ob.terminal_velocity_m_s)
            w.fail("observed", e["observed"], "no measured distance_m or terminal_velocity_m_s with angle_range_deg "
                                              "(D against theta is its linear_fit)");
        if (!e.contains("angles_deg"))
            w.missing("angles_deg", "the angles to simulate, reaching past both ends of angle_range_deg");
        ob.angles_deg = read_angles(w, e["angles_deg"]);
        if (ob.angles_deg.front() > lo || ob.angles_deg.back() < hi)
            w.fail("angles_deg", e["angles_deg"], fmt::format("angles reaching from {} degrees or below to {} or above, "
                                                              "to find the band's ends", lo, hi));
        if (ob.scene.contains("ramp.angle_deg")) w.fail("scene.ramp.angle_deg", ob.scene["ramp.angle_deg"], "no angle: angles_deg gives them");
        for (const auto& [path, values] : ob.grid)
            if (path == "ramp.angle_deg") w.fail("grid.ramp.angle_deg", json(values), "no angle: angles_deg gives them");
    } else {
        if (e.contains("angles_deg")) w.fail("angles_deg", e["angles_deg"], "only with angle_range_deg");
        if (ob.linear_fit) w.fail("observed.linear_fit", e["observed"]["linear_fit"], "only with angle_range_deg");
    }
    if (!e.contains("tolerance")) w.missing("tolerance", "an object: behaviour_share, or angle_range_deg and slope_relative");
    if (!e["tolerance"].is_object()) w.fail("tolerance", e["tolerance"], "an object");
    read_tolerance(w, e["tolerance"], ob);
    return ob;
}

}  // namespace

ObservationFile parse_observations(const json& doc, const std::string& origin) {
    const Where w{origin, ""};
    if (!doc.is_object()) w.fail("the document", doc, "an object with \"observations\"");
    check_keys(w, "", doc, {"about", "format", "observations", "halves"});
    if (!doc.contains("observations")) w.missing("observations", "a list of observations");
    const json& list = doc["observations"];
    if (!list.is_array() || list.empty()) w.fail("observations", list, "a non-empty list of observations");
    ObservationFile file;
    file.origin = origin;
    file.doc = doc;
    std::set<std::string> ids;
    for (std::size_t i = 0; i < list.size(); ++i) {
        Observation ob = read_observation(origin, list[i], i);
        if (!ids.insert(ob.id).second) w.fail(fmt::format("observations[{}].id", i), json(ob.id), "each id once");
        file.observations.push_back(std::move(ob));
    }
    if (doc.contains("halves")) {
        const json& halves = doc["halves"];
        const std::string allowed = "an object of named lists of observation ids, e.g. {\"fit\": [...], \"held_back\": [...]}";
        if (!halves.is_object() || halves.empty()) w.fail("halves", halves, allowed);
        std::set<std::string> placed;
        for (const auto& [name, list] : halves.items()) {
            const std::string key = "halves." + name;
            if (!list.is_array() || list.empty()) w.fail(key, list, "a non-empty list of observation ids");
            std::vector<std::string> half;
            for (const json& id : list) {
                if (!id.is_string() || !ids.count(id.get<std::string>()))
                    w.fail(key, id, "an id of this file's observations");
                if (!placed.insert(id.get<std::string>()).second) w.fail(key, id, "each id in one half at most");
                half.push_back(id.get<std::string>());
            }
            file.halves.emplace_back(name, std::move(half));
        }
    }
    return file;
}

ObservationFile read_observations(const std::string& path) {
    if (path.empty()) {
        // POLYROLL_ASSETS may replace the bundled file: messages name the one read.
        std::error_code ec;
        const std::filesystem::path replaced = assets::directory() / "experiment.json";
        const bool is_replaced = !assets::directory().empty() && std::filesystem::is_regular_file(replaced, ec);
        return parse_observations(assets::file("experiment.json"),
                                  is_replaced ? replaced.string() : "experiment.json (bundled)");
    }
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    const int open_error = errno;
    std::error_code ec;
    if (!in || std::filesystem::is_directory(path, ec))
        throw InputError(fmt::format("--observations {}: {} (allowed: an observations file, JSON)", path,
                                     in ? "is a directory" : open_failure_reason(open_error)));
    std::string text(kMaxObservationFileBytes + 1, '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    text.resize(static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxObservationFileBytes)
        throw InputError(fmt::format("--observations {}: larger than {} bytes (allowed: an observations file, JSON)",
                                     path, kMaxObservationFileBytes));
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::parse_error& e) {
        throw InputError(fmt::format("--observations {}: not valid JSON ({})", path,
                                     printable_line(json_error_text(e.what()))));
    }
    return parse_observations(doc, path);
}

ObservationFile only_observations(const ObservationFile& file, const std::vector<std::string>& ids,
                                  const std::string& flag) {
    std::vector<std::string> known;
    for (const Observation& ob : file.observations) known.push_back(ob.id);
    for (const std::string& id : ids)
        if (std::find(known.begin(), known.end(), id) == known.end())
            throw InputError(fmt::format("{} {}: no observation of {} has this id (allowed: {})", flag,
                                         printable_line(id.empty() ? "''" : id), file.origin, joined(known)));
    ObservationFile out;
    out.origin = file.origin;
    out.doc = file.doc;
    out.doc["observations"] = json::array();
    for (std::size_t i = 0; i < file.observations.size(); ++i) {
        if (std::find(ids.begin(), ids.end(), file.observations[i].id) == ids.end()) continue;
        out.observations.push_back(file.observations[i]);
        out.doc["observations"].push_back(file.doc["observations"][i]);
    }
    // The halves keep the ids kept, so that the cut document (the folder's copy) reads back as it is.
    out.doc.erase("halves");
    for (const auto& [name, half] : file.halves) {
        std::vector<std::string> kept;
        for (const std::string& id : half)
            if (std::find(ids.begin(), ids.end(), id) != ids.end()) kept.push_back(id);
        if (kept.empty()) continue;
        out.doc["halves"][name] = kept;
        out.halves.emplace_back(name, std::move(kept));
    }
    return out;
}

ObservationFile half_of(const ObservationFile& file, const std::string& name) {
    std::vector<std::string> names;
    for (const auto& [n, ids] : file.halves) {
        if (n == name) {
            return only_observations(file, ids, "--half " + name);
        }
        names.push_back(n);
    }
    throw InputError(fmt::format("--half {}: {} {} (allowed: {})", printable_line(name.empty() ? "''" : name),
                                 file.origin, names.empty() ? "names no halves" : "has no half of this name",
                                 names.empty() ? "no --half with this file" : joined(names)));
}

namespace {

using Overrides = std::vector<std::pair<std::string, json>>;

// One run of a validation before the plan numbers it: its fields and where it belongs.
struct ValidationPoint {
    json fields;  // path -> value, without the seed
    RunPlace place;
};

// A field set on the command line that an observation varies itself: the user's value is what is
// refused, by the field they set, not the observation file.
void refuse_overrides_varied_by(const ObservationFile& file, const Observation& ob, const Overrides& overrides) {
    for (const auto& [f, v] : overrides) {
        const bool own_angles = f == "ramp.angle_deg" && ob.angle_range_deg;
        const auto grid = std::find_if(ob.grid.begin(), ob.grid.end(), [&f = f](const auto& g) { return g.first == f; });
        if (grid == ob.grid.end() && !own_angles) continue;
        throw InputError(fmt::format(
            "{} = {} set on the command line: observation '{}' of {} varies it itself ({}) (allowed: a field "
            "none of the observations run varies; --only picks the observations)",
            f, printable_line(v.dump()), ob.id, file.origin,
            own_angles ? "its angles_deg" : "grid " + printable_line(json(grid->second).dump())));
    }
}

// One combination of an observation's grid values, the command line's fields on top.
struct GridPoint {
    json fields;
    std::string label, label_without_angle;
};

// The observation's grid combinations, the first axis varying slowest.
std::vector<GridPoint> grid_points(const Observation& ob, const Overrides& overrides) {
    std::vector<std::size_t> digit(ob.grid.size(), 0);
    std::size_t combos = 1;
    for (const auto& g : ob.grid) combos *= g.second.size();
    std::vector<GridPoint> out;
    for (std::size_t c = 0; c < combos; ++c) {
        GridPoint gp{ob.scene, "", ""};
        for (std::size_t a = 0; a < ob.grid.size(); ++a) {
            gp.fields[ob.grid[a].first] = ob.grid[a].second[digit[a]];
            const std::string part = ob.grid[a].first + "=" + value_text(ob.grid[a].second[digit[a]]);
            gp.label += (gp.label.empty() ? "" : " ") + part;
            if (ob.grid[a].first != "ramp.angle_deg")
                gp.label_without_angle += (gp.label_without_angle.empty() ? "" : " ") + part;
        }
        for (const auto& [f, v] : overrides) gp.fields[f] = v;
        out.push_back(gp);
        for (std::size_t a = ob.grid.size(); a-- > 0;) {
            if (++digit[a] < ob.grid[a].second.size()) break;
            digit[a] = 0;
        }
    }
    return out;
}

// A point resolved as a scene now, so a bad value fails before anything is written.
void check_resolves(const ObservationFile& file, const Observation& ob, const std::string& label, const json& fields,
                    const Overrides& overrides) {
    try {
        SceneLayer layer{json::object(), "the observation", {}};
        for (const auto& [f, v] : overrides) layer.field_labels.emplace_back(f, "the command line");
        for (const auto& [f, v] : fields.items()) node_at(layer.doc, f) = v;
        resolve_scene({layer});
    } catch (const InputError& e) {
        throw InputError(fmt::format("{}: observation '{}'{}: {}", file.origin, ob.id,
                                     label.empty() ? "" : " at " + label, e.what()));
    }
}

// Observation `oi`'s runs: each grid point at each of its angles (if it has a range), each seed.
std::vector<ValidationPoint> observation_points(const ObservationFile& file, std::size_t oi, int seeds,
                                                const Overrides& overrides) {
    const Observation& ob = file.observations[oi];
    refuse_overrides_varied_by(file, ob, overrides);
    const std::vector<double> angles = ob.angle_range_deg ? ob.angles_deg : std::vector<double>{0.0};
    std::vector<ValidationPoint> out;
    for (const GridPoint& gp : grid_points(ob, overrides)) {
        for (double angle : angles) {
            json p = gp.fields;
            if (ob.angle_range_deg) p["ramp.angle_deg"] = angle;
            check_resolves(file, ob, gp.label, p, overrides);
            for (int s = 1; s <= seeds; ++s)
                out.push_back({p, RunPlace{oi, 0, ob.angle_range_deg ? angle : 0.0, static_cast<std::uint64_t>(s),
                                           gp.label, gp.label_without_angle}});
        }
    }
    return out;
}

// One plan over the union of the points' fields (in order of first use, the angle last, then the
// seed), each distinct point one run; each point's place names its run. With `early_exit`, a run
// every observation of which is decided at a face impact (decided_at_impact) ends there: its point
// has run.end_at_impact, a field of its own after the seed.
ValidationPlan plan_of(const ObservationFile& file, std::vector<ValidationPoint>& points, std::vector<std::string> order,
                       bool early_exit) {
    ValidationPlan vp;
    vp.plan.base = json::object();
    std::stable_partition(order.begin(), order.end(), [](const std::string& f) { return f != "ramp.angle_deg"; });
    order.push_back("run.seed");
    const bool set_by_caller = std::find(order.begin(), order.end(), "run.end_at_impact") != order.end();
    std::vector<std::string> keys;
    std::map<std::string, int> end_at;  // a point's text -> the impact every observation of it is decided at, or 0
    for (ValidationPoint& p : points) {
        p.fields["run.seed"] = p.place.seed;
        json ordered = json::object();
        for (const std::string& f : order)
            if (p.fields.contains(f)) ordered[f] = p.fields[f];
        keys.push_back(ordered.dump());
        const int decided = early_exit && !set_by_caller ? decided_at_impact(file.observations[p.place.observation]) : 0;
        const auto [it, first] = end_at.emplace(keys.back(), decided);
        if (!first) it->second = (it->second == 0 || decided == 0) ? 0 : std::max(it->second, decided);
    }
    const bool any_early = std::any_of(end_at.begin(), end_at.end(), [](const auto& e) { return e.second > 0; });
    if (any_early) order.push_back("run.end_at_impact");
    vp.plan.fields = order;
    vp.plan.flags = order;
    std::map<std::string, std::size_t> planned;  // a point's text -> its run
    for (std::size_t i = 0; i < points.size(); ++i) {
        ValidationPoint& p = points[i];
        auto it = planned.find(keys[i]);
        if (it == planned.end()) {
            json ordered = json::object();
            for (const std::string& f : order)
                if (p.fields.contains(f)) ordered[f] = p.fields[f];
            if (const int e = end_at.at(keys[i]); e > 0) ordered["run.end_at_impact"] = e;
            add_run(vp.plan, ordered);
            it = planned.emplace(keys[i], vp.plan.runs.size() - 1).first;
        }
        p.place.run = it->second;
        vp.places.push_back(p.place);
    }
    return vp;
}

}  // namespace

int decided_at_impact(const Observation& ob) {
    // Whether a run stopped at its first impact is known once it lands a second face: from then on it
    // can only stop later, roll to the end or reach the time limit, none of which is that behaviour. An
    // observation that scores nothing else of its runs (no band, no measured number, no terminal
    // velocity to report) has what it needs there.
    const bool first_impact_only =
        ob.behaviour == "stopped_at_first_impact" || (ob.behaviour.empty() && ob.not_behaviour == "stopped_at_first_impact");
    if (!first_impact_only || ob.angle_range_deg || ob.distance_m || ob.terminal_velocity_m_s ||
        !ob.terminal_velocity.empty())
        return 0;
    return 2;
}

ValidationPlan make_validation_plan(const ObservationFile& file, int seeds, const Overrides& overrides,
                                   bool early_exit) {
    // Every observation's points first, with their place; then one plan over the union of their fields.
    std::vector<ValidationPoint> points;
    std::vector<std::string> order;  // fields in order of first use
    for (std::size_t oi = 0; oi < file.observations.size(); ++oi) {
        for (ValidationPoint& p : observation_points(file, oi, seeds, overrides)) {
            for (const auto& [f, v] : p.fields.items())
                if (std::find(order.begin(), order.end(), f) == order.end()) order.push_back(f);
            points.push_back(std::move(p));
        }
    }
    return plan_of(file, points, std::move(order), early_exit);
}

}  // namespace polyroll::sweep
