// The web page's scene from its address, and the window's flags of the same names: see page_settings.h.
#include "app/page_settings.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include <fmt/core.h>

#include "app/controls.h"
#include "app/sandbox_presets.h"
#include "sim/errors.h"
#include "sim/message_text.h"
#include "sim/scene/field_text.h"
#include "sim/scene/json_path.h"

namespace polyroll::app {

namespace {

using json = nlohmann::ordered_json;

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

const SceneField* window_field_of_key(const std::string& key) {
    for (const SceneField* f : window_scene_fields())
        if (field_key(*f) == key) return f;
    return nullptr;
}

// A choice the panel offers fewer of than the field has (the model: not the 3D reference) refused as
// the panel would not offer it, in the resolver's words.
void check_offered(const SceneField& f, const json& value, const std::string& said) {
    const ControlRow& row = control_row(f.path);
    if (!row.offered || !value.is_string()) return;
    const std::vector<std::string>& names = row.offered();
    if (std::find(names.begin(), names.end(), value.get<std::string>()) == names.end())
        throw InputError(fmt::format("{} = {} (from {}) is not one the window runs (allowed: {})", f.path,
                                     value.get<std::string>(), said, comma_list(names)));
}

// One scene field, typed as `text`, into the layer; `name` says how it was given for a text that is not
// of the field's type ("sides=six", "--sides six"), `label` for a value the scene refuses ("sides=2",
// "--sides"), as the command line and Python name them. Checked alone over the defaults, so that every
// bad setting of an address is named at once; the combination is checked when applied.
void read_field(const SceneField& f, const std::string& text, const std::string& name, const std::string& label,
                SceneLayer& layer) {
    const json value = field_json_from_text(f, text, name);
    SceneLayer alone{json::object(), layer.origin, {{std::string(f.path), label}}};
    node_at(alone.doc, f.path) = value;
    resolve_scene({alone});
    check_offered(f, value, label);  // a name the scene takes, but not one the window runs
    node_at(layer.doc, f.path) = value;
    layer.field_labels.emplace_back(std::string(f.path), label);
}

// The page's frame count: "frames=240".
long read_frames(const std::string& value, const std::string& name) {
    char* end = nullptr;
    const double v = value.empty() ? NAN : std::strtod(value.c_str(), &end);
    const std::string allowed = fmt::format("(allowed: 1 to {})", kMaxPageFrames);
    if (value.empty()) throw InputError(fmt::format("{}: no value {}", name, allowed));
    if (end != value.c_str() + value.size() || !std::isfinite(v) || v != std::floor(v))
        throw InputError(fmt::format("{}: not a whole number {}", name, allowed));
    if (v < 1 || v > static_cast<double>(kMaxPageFrames))
        throw InputError(fmt::format("{}: out of range {}", name, allowed));
    return static_cast<long>(v);
}

bool read_switch(const std::string& key, const std::string& value) {
    if (!value.empty() && value != "1" && value != "0")
        throw InputError(fmt::format("{}={}: unknown (allowed: 1, 0, or no value)", key, value));
    return value != "0";
}

// One setting of the address into p; throws InputError naming it.
void read_setting(const std::string& key, const std::string& value, PageSettings& p) {
    const std::string said = key + "=" + value;
    if (key == "preset") {
        const std::vector<std::string> names = sandbox_preset_names();
        if (std::find(names.begin(), names.end(), value) == names.end())
            throw InputError(fmt::format("{}: unknown (allowed: {})", said, comma_list(names)));
        p.preset = value;
    } else if (const SceneField* f = window_field_of_key(key)) {
        if (value.empty()) throw InputError(fmt::format("{}: no value (allowed: {})", said, field_allowed(*f)));
        read_field(*f, value, said, said, p.scene);
    } else if (key == "frames") {
        p.frames = read_frames(value, said);
    } else if (key == "paused") {
        p.paused = read_switch(key, value);
    } else if (key == "bench") {
        p.bench = read_switch(key, value);
    } else if (key.empty()) {
        // "?=5" or "?&=&": a value with no name before it (a link cut or mistyped).
        throw InputError(fmt::format("={}: no setting name before the '=' (allowed: {})", value, page_query_keys()));
    } else {
        throw InputError(fmt::format("{}: unknown setting in the address (allowed: {})", key, page_query_keys()));
    }
}

}  // namespace

const std::vector<const SceneField*>& window_scene_fields() {
    static const std::vector<const SceneField*> fields = [] {
        std::vector<const SceneField*> out;
        for (const SceneField& f : scene_fields()) {
            const bool has_control = std::any_of(control_rows().begin(), control_rows().end(),
                                                 [&f](const ControlRow& r) { return r.path == f.path; });
            if (!f.flag.empty() && has_control) out.push_back(&f);
        }
        return out;
    }();
    return fields;
}

const json* PageSettings::field(std::string_view path) const { return find_at(scene.doc, path); }

std::string page_query_keys() {
    std::string keys = "preset";
    for (const SceneField* f : window_scene_fields()) keys += ", " + field_key(*f);
    return keys + ", frames, paused, bench";
}

PageSettings parse_page_query(std::string_view query) {
    if (!query.empty() && query.front() == '?') query.remove_prefix(1);
    PageSettings p;
    p.scene.origin = "the page's address";
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
    p.scene.origin = "command line";
    for (const auto& [key, value] : flags) {
        const std::string flag = "--" + key;
        if (key == "preset") {
            const std::vector<std::string> names = sandbox_preset_names();
            if (std::find(names.begin(), names.end(), value) == names.end())
                throw InputError(fmt::format("{} {}: unknown (allowed: {})", flag, value, comma_list(names)));
            p.preset = value;
        } else if (const SceneField* f = window_field_of_key(key)) {
            read_field(*f, value, flag + " " + value, flag, p.scene);
        } else {
            throw std::logic_error(fmt::format("'{}' is not one of the window's scene flags", flag));
        }
    }
    return p;
}

void apply_page_settings(const PageSettings& page, SandboxState& state) {
    if (page.preset) load_preset(state, *page.preset);
    if (!page.scene.field_labels.empty()) {
        // The selected lane's scene with the settings as one more layer, as the command line's flags are
        // over a scene file: a combination the scene refuses is named as given, and each setting's value
        // is taken as resolved (a preset's name before the values over it, in the table's order).
        LaneChoice& lane = state.lanes.at(static_cast<size_t>(state.selected_lane));
        const Scene resolved = resolve_scene({SceneLayer{lane.base, "sandbox preset", {}},
                                              SceneLayer{controls_layer(lane.controls, state.shared), "panel", {}},
                                              page.scene});
        for (const SceneField* f : window_scene_fields())
            if (page.field(f->path) != nullptr)
                set_control(lane.controls, state.shared, f->path, f->access.get(resolved));
    }
    if (page.paused) state.playing = false;
    scenes_for(state);  // a combination out of range (too many grains) is refused here, named
}

}  // namespace polyroll::app
