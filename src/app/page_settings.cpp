// The web page's scene from its address: see page_settings.h.
#include "app/page_settings.h"

#include <algorithm>
#include <charconv>
#include <cerrno>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <system_error>
#include <vector>

#include <fmt/core.h>

#include "app/controls.h"
#include "app/sandbox_presets.h"
#include "sim/assets.h"
#include "sim/errors.h"
#include "sim/message_text.h"
#include "sim/scene/scene_fields.h"

namespace polyroll::app {

namespace {

// As polyroll-sandbox --frames allows (sandbox_main.cpp): 1 to ten million.
constexpr long kMaxPageFrames = 10'000'000;

int hex_digit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

// "%2C" -> ",", "+" -> " "; a '%' not followed by two hex digits stays as it is.
std::string url_decode(std::string_view s) {
    std::string out;
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '+') {
            out += ' ';
        } else if (s[i] == '%' && i + 2 < s.size() && hex_digit(s[i + 1]) >= 0 && hex_digit(s[i + 2]) >= 0) {
            out += static_cast<char>(hex_digit(s[i + 1]) * 16 + hex_digit(s[i + 2]));
            i += 2;
        } else {
            out += s[i];
        }
    }
    return out;
}

// The whole text as a finite number, or nullopt.
std::optional<double> number_from(const std::string& text) {
    if (text.empty()) return std::nullopt;
    errno = 0;
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (end != text.c_str() + text.size() || errno == ERANGE || !std::isfinite(v)) return std::nullopt;
    return v;
}

// The value checked against the scene field's fixed limits, with the field's own allowed text.
double field_number(const std::string& key, const std::string& text, std::string_view path) {
    const SceneField& f = scene_field(path);
    const std::optional<double> v = number_from(text);
    const std::string allowed = field_allowed(f);
    if (text.empty()) throw InputError(fmt::format("{}=: no value (allowed: {})", key, allowed));
    if (!v) throw InputError(fmt::format("{}={}: not a number (allowed: {})", key, text, allowed));
    const bool below = f.min_open ? *v <= f.min : *v < f.min;
    const bool above = f.max_open ? *v >= f.max : *v > f.max;
    if (below || above) throw InputError(fmt::format("{}={}: out of range (allowed: {})", key, text, allowed));
    if (f.type == FieldType::integer && *v != std::floor(*v))
        throw InputError(fmt::format("{}={}: not a whole number (allowed: {})", key, text, allowed));
    return *v;
}

}  // namespace

std::string page_query_keys() { return "preset, sides, fill, material, angle, seed, frames, paused, bench"; }

namespace {

// One setting of the address into p; throws InputError naming it.
void read_setting(const std::string& key, const std::string& value, PageSettings& p) {
    if (key == "preset") {
        const std::vector<std::string> names = sandbox_preset_names();
        if (std::find(names.begin(), names.end(), value) == names.end())
            throw InputError(fmt::format("preset={}: unknown (allowed: {})", value, comma_list(names)));
        p.preset = value;
    } else if (key == "sides") {
        p.sides = static_cast<int>(field_number(key, value, "shell.sides"));
    } else if (key == "fill") {
        p.fill_ratio = field_number(key, value, "fill.ratio");
    } else if (key == "angle") {
        p.angle_deg = field_number(key, value, "ramp.angle_deg");
    } else if (key == "seed") {
        // Digits only, as polyroll run --seed takes them: "-1" or "1e3" would not be this seed.
        std::uint64_t seed = 0;
        const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), seed);
        if (value.empty() || error != std::errc() || end != value.data() + value.size())
            throw InputError(fmt::format("seed={}: not a whole number (allowed: {})", value,
                                         field_allowed(scene_field("run.seed"))));
        p.seed = seed;
    } else if (key == "material") {
        const std::vector<std::string> names = assets::preset_names(assets::Kind::material);
        if (std::find(names.begin(), names.end(), value) == names.end())
            throw InputError(fmt::format("material={}: unknown (allowed: {})", value, comma_list(names)));
        p.material = value;
    } else if (key == "frames") {
        if (value.empty())
            throw InputError(fmt::format("frames=: no value (allowed: 1 to {})", kMaxPageFrames));
        const std::optional<double> v = number_from(value);
        if (!v || *v != std::floor(*v))
            throw InputError(
                fmt::format("frames={}: not a whole number (allowed: 1 to {})", value, kMaxPageFrames));
        if (*v < 1 || *v > static_cast<double>(kMaxPageFrames))
            throw InputError(fmt::format("frames={}: out of range (allowed: 1 to {})", value, kMaxPageFrames));
        p.frames = static_cast<long>(*v);
    } else if (key == "paused") {
        if (!value.empty() && value != "1" && value != "0")
            throw InputError(fmt::format("paused={}: unknown (allowed: 1, 0, or no value)", value));
        p.paused = value != "0";
    } else if (key == "bench") {
        if (!value.empty() && value != "1" && value != "0")
            throw InputError(fmt::format("bench={}: unknown (allowed: 1, 0, or no value)", value));
        p.bench = value != "0";
    } else if (key.empty()) {
        // "?=5" or "?&=&": a value with no name before it (a link cut or mistyped).
        throw InputError(fmt::format("={}: no setting name before the '=' (allowed: {})", value, page_query_keys()));
    } else {
        throw InputError(fmt::format("{}: unknown setting in the address (allowed: {})", key, page_query_keys()));
    }
}

}  // namespace

PageSettings parse_page_query(std::string_view query) {
    if (!query.empty() && query.front() == '?') query.remove_prefix(1);
    PageSettings p;
    std::vector<std::string> seen;      // the keys read so far
    std::vector<std::string> problems;  // every bad setting, so that one look at the page fixes the address
    while (!query.empty()) {
        const size_t amp = query.find('&');
        const std::string_view pair = query.substr(0, amp);
        query = amp == std::string_view::npos ? std::string_view{} : query.substr(amp + 1);
        if (pair.empty()) continue;
        const size_t eq = pair.find('=');
        const std::string key = url_decode(pair.substr(0, eq));
        const std::string value = eq == std::string_view::npos ? std::string{} : url_decode(pair.substr(eq + 1));
        // ?fill=0.5&fill=0.3 would keep one value silently: which one the page shows is a guess, so say so.
        if (std::find(seen.begin(), seen.end(), key) != seen.end()) {
            problems.push_back(
                fmt::format("{}={}: {} is given twice in the address (allowed: each setting once)", key, value, key));
            continue;
        }
        seen.push_back(key);
        try {
            read_setting(key, value, p);
        } catch (const InputError& e) {
            problems.emplace_back(e.what());
        }
    }
    if (!problems.empty()) {
        std::string all;
        for (const std::string& one : problems) all += (all.empty() ? "" : "; ") + one;
        throw InputError(all);
    }
    return p;
}

PageSettings parse_window_flags(const std::vector<std::pair<std::string, std::string>>& flags) {
    PageSettings p;
    for (const auto& [key, value] : flags) {
        // Each flag through the address's own checks, its value percent-encoded so that no '&', '='
        // or '%' in it reads as more of the address.
        std::string encoded;
        for (const char c : value) {
            if (std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_') encoded += c;
            else encoded += fmt::format("%{:02X}", static_cast<unsigned char>(c));
        }
        PageSettings one;
        try {
            one = parse_page_query(key + "=" + encoded);
        } catch (const InputError& e) {
            // "sides=99: out of range ..." -> "--sides 99: out of range ...".
            const std::string said = e.what(), as_page = key + "=" + value;
            const std::string rest = said.rfind(as_page, 0) == 0 ? said.substr(as_page.size()) : ": " + said;
            throw InputError(fmt::format("--{} {}{}", key, value, rest));
        }
        if (one.preset) p.preset = one.preset;
        if (one.sides) p.sides = one.sides;
        if (one.fill_ratio) p.fill_ratio = one.fill_ratio;
        if (one.material) p.material = one.material;
        if (one.angle_deg) p.angle_deg = one.angle_deg;
        if (one.seed) p.seed = one.seed;
    }
    return p;
}

void apply_page_settings(const PageSettings& page, SandboxState& state) {
    if (page.preset) load_preset(state, *page.preset);
    LaneControls& lane = state.lanes.at(static_cast<size_t>(state.selected_lane)).controls;
    if (page.sides) set_control(lane, "shell.sides", *page.sides);
    if (page.fill_ratio) set_control(lane, "fill.ratio", *page.fill_ratio);
    if (page.material) set_control(lane, "fill.material.preset", *page.material);
    if (page.angle_deg) set_control(state.shared, "ramp.angle_deg", *page.angle_deg);
    if (page.seed) set_control(state.shared, "run.seed", *page.seed);
    if (page.paused) state.playing = false;
    scenes_for(state);  // a combination out of range (too many grains) is refused here, named
}

}  // namespace polyroll::app
