// Scoring runs against observations: see scorecard.h.
#include "sweep/scorecard.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include <fmt/core.h>

#include "sweep/results_table.h"

namespace polyroll::sweep {
namespace {

using json = nlohmann::ordered_json;

// A share's count: the least whole number of runs that reaches it (4 of 5 for 0.8). The epsilon keeps
// 0.8 * 5 = 4.000000000000001 from needing 5.
std::size_t needed_count(double share, std::size_t n) {
    return static_cast<std::size_t>(std::ceil(share * static_cast<double>(n) - 1e-9));
}

std::string signed_text(double v, int digits) { return fmt::format("{:+.{}f}", v, digits); }

// "+2.50 deg: 1.50 beyond the tolerance of 1 deg" or "-0.30 deg: within 1 deg".
std::string beyond_text(double diff, double tolerance, const std::string& unit, int digits) {
    const double over = std::abs(diff) - tolerance;
    if (over <= 0)
        return fmt::format("{} {}: within {} {}", signed_text(diff, digits), unit, tolerance, unit);
    return fmt::format("{} {}: {:.{}f} beyond the tolerance of {} {}", signed_text(diff, digits), unit, over, digits,
                       tolerance, unit);
}

// The objective's units (ScoreCheck::miss): a share's shortfall is counted in tenths of the runs, and a
// check with nothing to compare (no band, no runs with a value) counts as this many tolerances off.
constexpr double kShareUnit = 0.1;
constexpr double kNothingToCompare = 10.0;

struct Spread {
    double mean = 0.0, min = 0.0, max = 0.0;
    std::size_t n = 0;
};
Spread spread_of(const std::vector<double>& v) {
    Spread s;
    if (v.empty()) return s;
    s.n = v.size();
    s.min = *std::min_element(v.begin(), v.end());
    s.max = *std::max_element(v.begin(), v.end());
    for (double x : v) s.mean += x;
    s.mean /= static_cast<double>(v.size());
    return s;
}

// "3 stopped_at_first_impact, 1 failed": what the runs that did not show `except` showed instead.
std::string others_text(const std::vector<ScoredRun>& runs, const std::string& except) {
    std::map<std::string, int> counts;
    for (const ScoredRun& r : runs)
        if (!r.ok) ++counts["failed"];
        else if (r.behaviour != except) ++counts[r.behaviour];
    std::string out;
    for (const auto& [b, c] : counts) out += fmt::format("{}{} {}", out.empty() ? "" : ", ", c, b);
    return out;
}

// Per grid point: how many of its seeds showed `behaviour`.
json per_point(const std::vector<ScoredRun>& runs, const std::string& behaviour) {
    std::map<std::string, std::pair<int, int>> counts;  // label -> shown, runs
    std::vector<std::string> order;
    for (const ScoredRun& r : runs) {
        if (!counts.count(r.label)) order.push_back(r.label);
        auto& c = counts[r.label];
        c.second++;
        if (r.ok && r.behaviour == behaviour) c.first++;
    }
    json out = json::array();
    for (const auto& l : order)
        out.push_back(json{{"point", l}, {"runs", counts[l].second}, {"showed", counts[l].first}});
    return out;
}

void score_share(const Observation& ob, const std::vector<ScoredRun>& runs, ObservationScore& s) {
    const bool negative = ob.behaviour.empty();
    const std::string& b = negative ? ob.not_behaviour : ob.behaviour;
    const std::size_t n = runs.size();
    const std::size_t shown = static_cast<std::size_t>(
        std::count_if(runs.begin(), runs.end(), [&](const ScoredRun& r) { return r.ok && r.behaviour == b; }));
    const std::size_t good = negative ? n - shown : shown;  // runs that agree with the experiment
    const std::size_t need = needed_count(ob.behaviour_share, n);
    const json points = per_point(runs, b);
    // One scene: the runs are its seeds. A grid: the point furthest from the experiment shows the spread.
    const std::string unit = points.size() == 1 ? "seeds" : "runs";
    ScoreCheck c;
    c.unit = "share";
    if (negative) {
        c.check = "never " + b;
        c.experiment = ob.behaviour_share >= 1.0 ? fmt::format("no run {}", b)
                                                 : fmt::format("at least {:g}% of runs not {}", 100 * ob.behaviour_share, b);
        c.simulation = fmt::format("{} of {} {} {}", shown, n, unit, b);
    } else {
        c.check = "behaviour share";
        c.experiment = fmt::format("{} in at least {:g}% of runs", b, 100 * ob.behaviour_share);
        c.simulation = fmt::format("{} of {} {} {}", shown, n, unit, b);
        const std::string others = others_text(runs, b);
        if (!others.empty()) c.simulation += " (others: " + others + ")";
    }
    if (points.size() > 1) {
        // The point whose seeds agree least: most showing a forbidden behaviour, fewest showing the one seen.
        auto agreeing = [&](const json& p) {
            const double k = p["showed"].get<double>(), m = p["runs"].get<double>();
            return negative ? (m - k) / m : k / m;
        };
        const json* worst = &points.front();
        for (const json& p : points)
            if (agreeing(p) < agreeing(*worst)) worst = &p;
        if (agreeing(*worst) < 1.0)  // every point agreeing fully has no spread worth a word
            c.simulation += fmt::format("; least agreeing point {}: {} of {} seeds {}",
                                        worst->at("point").get<std::string>(), worst->at("showed").get<int>(),
                                        worst->at("runs").get<int>(), b);
    }
    c.agree = n > 0 && good >= need;
    // The shortfall in tenths of the runs ("one run in ten"): a share has no tolerance of its own.
    c.miss = n > 0 ? std::max(0.0, ob.behaviour_share - static_cast<double>(good) / static_cast<double>(n)) / kShareUnit
                   : kNothingToCompare;
    if (n > 0) c.difference = static_cast<double>(good) / static_cast<double>(n) - ob.behaviour_share;
    if (n == 0)
        c.by = "no runs";
    else if (good >= need)
        c.by = fmt::format("needs {} of {}: {} to spare", need, n, good - need);
    else
        c.by = fmt::format("needs {} of {}: {} short", need, n, need - good);
    s.details["per_point"] = points;
    if (negative) {
        json where = json::array();
        for (const ScoredRun& r : runs)
            if (r.ok && r.behaviour == b) where.push_back(json{{"point", r.label}, {"seed", r.seed}, {"distance_m", r.distance_m}});
        s.details["runs_showing"] = where;
    }
    s.checks.push_back(c);
    if (!ob.terminal_velocity.empty()) {
        std::vector<double> v;
        for (const ScoredRun& r : runs)
            if (r.ok && r.terminal_velocity_m_s) v.push_back(*r.terminal_velocity_m_s);
        const Spread sp = spread_of(v);
        // The paper's words ("reached smoothly") give no number: reported, not scored.
        s.details["terminal_velocity"] = json{{"experiment", ob.terminal_velocity}, {"runs", sp.n},
                                               {"mean_m_s", sp.n ? json(sp.mean) : json()},
                                               {"min_m_s", sp.n ? json(sp.min) : json()},
                                               {"max_m_s", sp.n ? json(sp.max) : json()}};
    }
}

// One angle of a band observation's runs: how many ran and showed the behaviour, their distances.
struct AtAngle {
    std::size_t runs = 0, shown = 0;
    std::vector<double> d_shown, d_all;
    bool most_show() const { return 2 * shown > runs; }
};

std::map<double, AtAngle> runs_by_angle(const Observation& ob, const std::vector<ScoredRun>& runs) {
    std::map<double, AtAngle> at;
    for (const ScoredRun& r : runs) {
        AtAngle& a = at[r.angle_deg];
        a.runs++;
        if (r.ok) a.d_all.push_back(r.distance_m);
        if (r.ok && r.behaviour == ob.behaviour) {
            a.shown++;
            a.d_shown.push_back(r.distance_m);
        }
    }
    return at;
}

json per_angle_json(const std::map<double, AtAngle>& at) {
    json per_angle = json::array();
    for (const auto& [angle, a] : at) {
        const Spread d = spread_of(a.d_all), ds = spread_of(a.d_shown);
        per_angle.push_back(json{{"angle_deg", angle}, {"runs", a.runs}, {"showed", a.shown}, {"in_band", a.most_show()},
                                 {"distance_mean_m", d.n ? json(d.mean) : json()},
                                 {"distance_min_m", d.n ? json(d.min) : json()},
                                 {"distance_max_m", d.n ? json(d.max) : json()},
                                 {"shown_distance_mean_m", ds.n ? json(ds.mean) : json()},
                                 {"shown_distance_min_m", ds.n ? json(ds.min) : json()},
                                 {"shown_distance_max_m", ds.n ? json(ds.max) : json()}});
    }
    return per_angle;
}

// The angles where most seeds show the behaviour, in increasing order.
std::vector<double> band_of(const std::map<double, AtAngle>& at) {
    std::vector<double> band;
    for (const auto& [angle, a] : at)
        if (a.most_show()) band.push_back(angle);
    return band;
}

// The band's first and last angles against the observed range, each within the angle tolerance.
std::pair<ScoreCheck, ScoreCheck> band_end_checks(const Observation& ob, const std::map<double, AtAngle>& at,
                                                  const std::vector<double>& band, ObservationScore& s) {
    const auto [lo, hi] = *ob.angle_range_deg;
    const double tol = ob.angle_tolerance_deg;
    auto seeds_at = [&](double angle) {
        const AtAngle& a = at.at(angle);
        return fmt::format("{} of {} seeds {}", a.shown, a.runs, ob.behaviour);
    };
    ScoreCheck start, end;
    start.check = "band start";
    end.check = "band end";
    start.unit = end.unit = "deg";
    start.experiment = fmt::format("{} from {:g} deg (+/- {:g})", ob.behaviour, lo, tol);
    end.experiment = fmt::format("{} up to {:g} deg (+/- {:g})", ob.behaviour, hi, tol);
    if (band.empty()) {
        const std::string none = fmt::format("at no angle from {:g} to {:g} deg do most seeds show {}",
                                             at.empty() ? 0.0 : at.begin()->first, at.empty() ? 0.0 : at.rbegin()->first,
                                             ob.behaviour);
        start.simulation = end.simulation = none;
        start.by = end.by = "no band";
        // As far off as the simulated angles reach: worse than any band found among them.
        const double span = at.empty() ? 0.0 : at.rbegin()->first - at.begin()->first;
        start.miss = end.miss = std::max(span / tol, kNothingToCompare);
        return {start, end};
    }
    const double b0 = band.front(), b1 = band.back();
    start.simulation = fmt::format("{:g} deg ({})", b0, seeds_at(b0));
    end.simulation = fmt::format("{:g} deg ({})", b1, seeds_at(b1));
    start.difference = b0 - lo;
    end.difference = b1 - hi;
    start.miss = (b0 - lo) / tol;
    end.miss = (b1 - hi) / tol;
    start.agree = std::abs(b0 - lo) <= tol + 1e-9;
    end.agree = std::abs(b1 - hi) <= tol + 1e-9;
    start.by = beyond_text(b0 - lo, tol, "deg", 2);
    end.by = beyond_text(b1 - hi, tol, "deg", 2);
    // Angles inside the band where most seeds did not show it.
    json gaps = json::array();
    for (const auto& [angle, a] : at)
        if (angle > b0 && angle < b1 && !a.most_show()) gaps.push_back(angle);
    s.details["band_deg"] = json{b0, b1};
    s.details["gaps_deg"] = gaps;
    if (!gaps.empty()) end.simulation += fmt::format("; {} angle(s) inside without it", gaps.size());
    return {start, end};
}

// The slope of the distance over the band's angles against the paper's line, within its relative tolerance.
ScoreCheck slope_check(const Observation& ob, const std::map<double, AtAngle>& at, const std::vector<double>& band,
                       ObservationScore& s) {
    const LinearFit& f = *ob.linear_fit;
    ScoreCheck slope;
    slope.check = "D slope";
    slope.unit = "m/deg";
    slope.experiment = fmt::format("{:g} m/deg (+/- {:g}%)", f.slope_m_per_deg, 100 * ob.slope_relative);
    std::vector<std::pair<double, double>> xy;
    double max_spread = 0.0, sq = 0.0;
    if (!band.empty())
        for (const auto& [angle, a] : at)
            if (angle >= band.front() && angle <= band.back()) {
                for (double d : a.d_shown) {
                    xy.emplace_back(angle, d);
                    const double e = d - (f.slope_m_per_deg * angle + f.intercept_m);
                    sq += e * e;
                }
                if (!a.d_shown.empty())
                    max_spread = std::max(max_spread, spread_of(a.d_shown).max - spread_of(a.d_shown).min);
            }
    const std::optional<LineFit> fit = fit_line(xy);
    slope.miss = 1.0 / ob.slope_relative;  // no slope: as far off as a slope of 0
    if (band.empty()) {
        slope.simulation = "no band, no slope";
        slope.by = "no band";
    } else if (!fit) {
        slope.simulation = fmt::format("one angle only ({:g} deg): no slope", band.front());
        slope.by = "one angle only";
    } else {
        const double rel = (fit->slope - f.slope_m_per_deg) / std::abs(f.slope_m_per_deg);
        slope.difference = fit->slope - f.slope_m_per_deg;
        slope.agree = std::abs(rel) <= ob.slope_relative + 1e-9;
        slope.miss = rel / ob.slope_relative;
        slope.simulation = fmt::format("{:.3f} m/deg (R^2 {:.2f}, {} runs; D seed spread up to {:.3f} m at one angle)",
                                       fit->slope, fit->r_squared, xy.size(), max_spread);
        slope.by = fmt::format("{:+.3f} m/deg ({:+.0f}%): {}", fit->slope - f.slope_m_per_deg, 100 * rel,
                               std::abs(rel) <= ob.slope_relative + 1e-9 ? "within" : "beyond");
        slope.by += fmt::format(" {:g}%", 100 * ob.slope_relative);
        s.details["fit"] = json{{"slope_m_per_deg", fit->slope}, {"intercept_m", fit->intercept},
                                {"r_squared", fit->r_squared}, {"runs", xy.size()},
                                {"rms_from_paper_line_m", std::sqrt(sq / static_cast<double>(xy.size()))}};
    }
    return slope;
}

void score_band(const Observation& ob, const std::vector<ScoredRun>& runs, ObservationScore& s) {
    const std::map<double, AtAngle> at = runs_by_angle(ob, runs);
    const std::vector<double> band = band_of(at);
    s.details["per_angle"] = per_angle_json(at);
    const auto [start, end] = band_end_checks(ob, at, band, s);
    std::optional<ScoreCheck> slope;
    if (ob.linear_fit) slope = slope_check(ob, at, band, s);
    s.checks.push_back(start);
    s.checks.push_back(end);
    if (slope) s.checks.push_back(*slope);
}

// A measured number (a lab's own): the mean over the runs that have one, within the tolerance.
ScoreCheck measured_check(const std::string& name, const std::vector<double>& values, double observed,
                          double tolerance, const std::string& unit, std::size_t runs, ObservationScore& s,
                          const std::string& detail_key) {
    ScoreCheck c;
    c.check = name;
    c.unit = unit;
    c.experiment = fmt::format("{:g} {} (+/- {:g})", observed, unit, tolerance);
    const Spread sp = spread_of(values);
    s.details[detail_key] = json{{"runs_with_value", sp.n}, {"mean", sp.n ? json(sp.mean) : json()},
                                 {"min", sp.n ? json(sp.min) : json()}, {"max", sp.n ? json(sp.max) : json()}};
    if (sp.n == 0) {
        c.simulation = fmt::format("no value in {} runs", runs);
        c.by = "nothing to compare";
        c.miss = kNothingToCompare;
        return c;
    }
    c.simulation = fmt::format("{:.4f} {} (mean of {} of {} runs; {:.4f} to {:.4f})", sp.mean, unit, sp.n, runs, sp.min,
                               sp.max);
    c.difference = sp.mean - observed;
    c.agree = std::abs(sp.mean - observed) <= tolerance + 1e-12;
    c.miss = (sp.mean - observed) / tolerance;
    c.by = beyond_text(sp.mean - observed, tolerance, unit, 4);
    return c;
}

void score_measured(const Observation& ob, const std::vector<ScoredRun>& runs, ObservationScore& s) {
    if (ob.distance_m) {
        std::vector<double> v;
        for (const ScoredRun& r : runs)
            if (r.ok) v.push_back(r.distance_m);
        s.checks.push_back(measured_check("distance", v, *ob.distance_m, ob.distance_tolerance_m, "m", runs.size(), s,
                                          "distance_m"));
    }
    if (ob.terminal_velocity_m_s) {
        std::vector<double> v;
        for (const ScoredRun& r : runs)
            if (r.ok && r.terminal_velocity_m_s) v.push_back(*r.terminal_velocity_m_s);
        s.checks.push_back(measured_check("terminal velocity", v, *ob.terminal_velocity_m_s,
                                          ob.terminal_velocity_tolerance_m_s, "m/s", runs.size(), s,
                                          "terminal_velocity_m_s"));
    }
}

// Rounded to 1e-9, so 14 - 15.2 is written -1.2 and not -1.1999999999999993.
double rounded(double v) { return std::round(v * 1e9) / 1e9; }

std::string difference_cell(const ScoreCheck& c) { return c.difference ? number_cell(rounded(*c.difference)) : ""; }

// The observation as numbers, for the figures: the behaviour seen (or never seen), the band, the
// paper's line and the tolerances.
json experiment_of(const Observation& ob) {
    json e = json::object();
    if (!ob.behaviour.empty()) e["behaviour"] = ob.behaviour;
    if (!ob.not_behaviour.empty()) e["not_behaviour"] = ob.not_behaviour;
    if (ob.angle_range_deg) {
        e["angle_range_deg"] = json{ob.angle_range_deg->first, ob.angle_range_deg->second};
        e["angle_tolerance_deg"] = ob.angle_tolerance_deg;
        e["slope_relative"] = ob.slope_relative;
        if (ob.linear_fit)
            e["linear_fit"] = json{{"slope_m_per_deg", ob.linear_fit->slope_m_per_deg},
                                   {"intercept_m", ob.linear_fit->intercept_m}};
    } else {
        e["behaviour_share"] = ob.behaviour_share;
    }
    return e;
}

// Which runs of the results table are this observation's, and where each sits (grid point, angle);
// what each showed is in the table, under its run_id.
json runs_of(const std::vector<ScoredRun>& runs) {
    json out = json::array();
    for (const ScoredRun& r : runs)
        out.push_back(json{{"run_id", r.run_id}, {"point", r.label}, {"row", r.label_without_angle},
                           {"angle_deg", r.angle_deg}, {"seed", r.seed}, {"ramp_length_m", r.ramp_length_m}});
    return out;
}

}  // namespace

std::optional<LineFit> fit_line(const std::vector<std::pair<double, double>>& xy) {
    if (xy.size() < 2) return std::nullopt;
    const double n = static_cast<double>(xy.size());
    double sx = 0, sy = 0;
    for (const auto& [x, y] : xy) {
        sx += x;
        sy += y;
    }
    const double mx = sx / n, my = sy / n;
    double sxx = 0, sxy = 0, syy = 0;
    for (const auto& [x, y] : xy) {
        sxx += (x - mx) * (x - mx);
        sxy += (x - mx) * (y - my);
        syy += (y - my) * (y - my);
    }
    if (sxx <= 1e-12 * std::max(1.0, mx * mx)) return std::nullopt;  // one x only
    LineFit f;
    f.slope = sxy / sxx;
    f.intercept = my - f.slope * mx;
    f.r_squared = syy > 0 ? (sxy * sxy) / (sxx * syy) : 1.0;
    return f;
}

ObservationScore score_observation(const Observation& ob, const std::vector<ScoredRun>& runs) {
    ObservationScore s;
    s.id = ob.id;
    s.source = ob.source;
    const std::size_t failed =
        static_cast<std::size_t>(std::count_if(runs.begin(), runs.end(), [](const ScoredRun& r) { return !r.ok; }));
    s.experiment = experiment_of(ob);
    s.runs = runs_of(runs);
    s.details["runs"] = runs.size();
    s.details["failed_runs"] = failed;
    if (ob.angle_range_deg)
        score_band(ob, runs, s);
    else if (!ob.behaviour.empty() || !ob.not_behaviour.empty())
        score_share(ob, runs, s);
    score_measured(ob, runs, s);
    s.agree = std::all_of(s.checks.begin(), s.checks.end(), [](const ScoreCheck& c) { return c.agree; });
    return s;
}

std::string scorecard_csv(const std::vector<ObservationScore>& scores) {
    std::string out = csv_line({"observation", "check", "experiment", "simulation", "agree", "difference", "unit", "by"});
    for (const ObservationScore& s : scores)
        for (const ScoreCheck& c : s.checks)
            out += csv_line({s.id, c.check, c.experiment, c.simulation, c.agree ? "yes" : "no", difference_cell(c),
                             c.unit, c.by});
    return out;
}

json scorecard_json(const std::vector<ObservationScore>& scores, const json& about) {
    json obs = json::array();
    std::size_t agreeing = 0;
    for (const ObservationScore& s : scores) {
        agreeing += s.agree ? 1 : 0;
        json checks = json::array();
        for (const ScoreCheck& c : s.checks)
            checks.push_back(json{{"check", c.check}, {"experiment", c.experiment}, {"simulation", c.simulation},
                                  {"agree", c.agree}, {"difference", c.difference ? json(rounded(*c.difference)) : json()},
                                  {"unit", c.unit}, {"by", c.by}});
        obs.push_back(json{{"id", s.id}, {"source", s.source}, {"agree", s.agree}, {"experiment", s.experiment},
                           {"checks", checks}, {"details", s.details}, {"runs", s.runs}});
    }
    json doc = {{"format", "polyroll-scorecard-1"}};
    for (const auto& [k, v] : about.items()) doc[k] = v;
    doc["observations_agreeing"] = agreeing;
    doc["observations_total"] = scores.size();
    doc["observations"] = obs;
    return doc;
}

std::string scorecard_text(const std::vector<ObservationScore>& scores) {
    std::string out;
    for (const ObservationScore& s : scores) {
        out += fmt::format("{}  [{}]\n", s.id, s.agree ? "agrees" : "disagrees");
        for (const ScoreCheck& c : s.checks) {
            out += fmt::format("  {:<16} {}\n", c.check, c.agree ? "yes" : "NO");
            out += fmt::format("    experiment  {}\n", c.experiment);
            out += fmt::format("    simulation  {}\n", c.simulation);
            out += fmt::format("    by          {}\n", c.by);
        }
    }
    std::size_t agreeing = 0;
    for (const ObservationScore& s : scores) agreeing += s.agree ? 1 : 0;
    out += fmt::format("{} of {} observations agree\n", agreeing, scores.size());
    return out;
}

}  // namespace polyroll::sweep
