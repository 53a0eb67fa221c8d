// The sandbox's ImGui panels: see sandbox_ui.h.
//
// Index of this file (search for "[SECTION]" to jump between them), as Dear ImGui's demo does:
// - Helpers: colours, tooltips, rows of buttons, the layout report
// - Keyboard shortcuts: the table (keys, labels, tooltips and --help all read it)
// - Widgets: preset combo, slider with its value beside the knob, tooltips and clamp notes
// - Controls bound to the scene-field table: one widget per row of control_rows() (controls.h)
// - Panel parts: headings, preset buttons, the model, sections of rows, budget, view
// - Plots: a card with title, legend, axes, traces and markers
// - Layout: where the panel, the scene and the readouts strip go       (ui_layout)
// - Control panel window: title, transport, presets, lanes, controls   (draw_control_panel)
// - Readouts and plots window: the table, the speed and energy plots   (draw_readouts_and_plots)
// - Status band over the scene                                          (draw_status)
// - Keyboard shortcuts: reading the keys, and the help                 (read_shortcuts, shortcut_help)
#include "app/sandbox_ui.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <GLFW/glfw3.h>
#include <fmt/core.h>
#include <imgui.h>
#include <imgui_internal.h>

#include "app/plot_data.h"
#include "app/readouts.h"
#include "app/sandbox_presets.h"
#include "app/scene_view.h"
#include "app/slider_text.h"
#include "app/text_wrap.h"
#include "render/colour.h"
#include "render/overlay.h"
#include "render/ticks.h"
#include "sim/assets.h"
#include "sim/errors.h"
#include "sim/model_registry.h"
#include "sim/scene/scene_fields.h"
#include "sim/scene/scene_json.h"
#include "sim/scene/scene_names.h"

namespace polyroll::app {

namespace {

// [SECTION] Helpers: colours, tooltips, rows of buttons, the layout report
ImU32 im_colour(render::Rgba c) { return ImGui::ColorConvertFloat4ToU32({c.r, c.g, c.b, c.a}); }
ImVec4 im_vec(render::Rgba c) { return {c.r, c.g, c.b, c.a}; }

// Begins one of the three panels, which tile the window with the scene. They draw no background of
// their own (their borders stay): the frame is cleared to their colour (panel_background(),
// sandbox_main.cpp). A software GL (llvmpipe under Xvfb) pays for every pixel an ImGui rectangle
// covers, textured and blended: about 4 ms a frame for the panels' backgrounds alone, which the
// clear paints for next to nothing.
void begin_panel(const char* name, ImGuiWindowFlags flags) {
    ImGui::PushStyleColor(ImGuiCol_WindowBg, IM_COL32(0, 0, 0, 0));
    ImGui::Begin(name, nullptr, flags);
    ImGui::PopStyleColor();
}

const ImVec4 kErrorColour = im_vec(render::palette::error_text);
const ImVec4 kWarnColour = im_vec(render::palette::warning_text);

// A colour for text on the panels: as given on the projector theme's pale panels; on the dark
// theme mixed halfway to white, so the lane colours, warnings and errors stay readable there too
// (the saturated red of lane 1 on dark grey was barely legible).
ImVec4 on_panel(ImVec4 c, bool high_contrast) {
    if (high_contrast) return c;
    return {0.5f * (c.x + 1.0f), 0.5f * (c.y + 1.0f), 0.5f * (c.z + 1.0f), c.w};
}

// Prose wrapped to the width left, broken only at spaces (app/text_wrap.h): ImGui's own wrapping
// splits a number after its decimal point.
void text_wrapped(const std::string& text, float min_width = 0.0f) {
    // The font's own advance, unrounded (CalcTextSize rounds up to a whole pixel, which pushed
    // words that fit onto the next line).
    const auto measure = [](std::string_view t) {
        return ImGui::GetFont()->CalcTextSizeA(ImGui::GetFontSize(), FLT_MAX, 0.0f, t.data(), t.data() + t.size()).x;
    };
    for (const std::string& line : wrap_at_spaces(text, std::max(ImGui::GetContentRegionAvail().x, min_width), measure))
        ImGui::TextUnformatted(line.c_str());
}

// A tooltip for the last item: what the control is and its unit.
void tip(const std::string& text) {
    if (!ImGui::IsItemHovered()) return;
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 28.0f);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
}

// [SECTION] Keyboard shortcuts: the table
// The keyboard shortcuts, one row each: what the key does, its keys (GLFW's codes; the second 0 for
// none), whether holding it repeats, the key's name in the panel's labels and tooltips and in
// --help, and what it does in --help. read_shortcuts, the panel and shortcut_help all read it.
enum class Key { play, step, reset, run_to_end, follow, colours, screenshot, export_run, slower, faster, reset_view };
struct Shortcut {
    Key key;
    int code, other_code;
    bool repeat;
    const char* name;
    const char* what;
};
constexpr std::array<Shortcut, 11> kShortcuts = {{
    {Key::play, GLFW_KEY_SPACE, 0, false, "Space", "play/pause"},
    {Key::step, GLFW_KEY_RIGHT, GLFW_KEY_PERIOD, true, "Right arrow", "step"},
    {Key::reset, GLFW_KEY_R, 0, false, "R", "reset"},
    {Key::run_to_end, GLFW_KEY_G, GLFW_KEY_END, false, "G", "run to the end"},
    {Key::follow, GLFW_KEY_F, 0, false, "F", "follow"},
    {Key::colours, GLFW_KEY_C, 0, false, "C", "grain colours"},
    {Key::screenshot, GLFW_KEY_S, 0, false, "S", "screenshot"},
    {Key::export_run, GLFW_KEY_E, 0, false, "E", "export the run's files"},
    {Key::slower, GLFW_KEY_LEFT_BRACKET, 0, false, "[", "slower"},
    {Key::faster, GLFW_KEY_RIGHT_BRACKET, 0, false, "]", "faster"},
    {Key::reset_view, GLFW_KEY_HOME, 0, false, "Home", "reset the view"},
}};

// The name of the key doing `key`: "Space".
const char* key_of(Key key) {
    for (const Shortcut& k : kShortcuts)
        if (k.key == key) return k.name;
    return "";
}

// A button's width for its label at the current font.
float button_w(const char* label) {
    return ImGui::CalcTextSize(label, nullptr, true).x + 2.0f * ImGui::GetStyle().FramePadding.x;
}

// Puts the next item of width `next_w` on the same line when it fits there, else starts a new line:
// rows of buttons wrap in a narrow panel or at a large UI scale instead of running off its edge.
void same_line_if_fits(float next_w) {
    const float right = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + next_w;
    if (right <= ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x) ImGui::SameLine();
}

// The current window's visible rectangle and the extent of what was laid out in it, for the layout
// checks. Call before End (or EndChild).
void record_window(UiLayoutReport* report, const char* name) {
    if (!report) return;
    const ImGuiWindow* w = ImGui::GetCurrentWindow();
    report->windows.push_back({name, w->InnerClipRect.Min.x, w->InnerClipRect.Min.y, w->InnerClipRect.Max.x,
                               w->InnerClipRect.Max.y});
    report->contents.push_back({name, w->DC.CursorStartPos.x, w->DC.CursorStartPos.y, w->DC.CursorMaxPos.x,
                                w->DC.CursorMaxPos.y});
}

// [SECTION] Widgets: preset combo, slider with its value beside the knob, tooltips and clamp notes
std::string preset_description(assets::Kind kind, const std::string& name) {
    try {
        return assets::preset_entry(kind, name).value("description", name);
    } catch (const std::exception&) {
        return name;
    }
}

// A combo over a preset kind; true when the choice changed. `shown`, if given, is what the closed
// combo says instead of the name (a polygon whose n is not its preset's).
bool preset_combo(const char* label, assets::Kind kind, std::string& value, const std::string& shown_instead = {}) {
    bool changed = false;
    const std::string shown = !shown_instead.empty() ? shown_instead : value.empty() ? std::string("(custom)") : value;
    if (ImGui::BeginCombo(label, shown.c_str())) {
        for (const std::string& name : assets::preset_names(kind)) {
            if (ImGui::Selectable(name.c_str(), name == value) && name != value) {
                value = name;
                changed = true;
            }
            tip(preset_description(kind, name));
        }
        ImGui::EndCombo();
    }
    return changed;
}

// A slider whose value is written beside its knob, never under it (slider_text.h): ImGui's own
// centred value is drawn transparent, then the value is drawn where the knob leaves room. While
// Ctrl+click typing is active the field is ImGui's, drawn as usual. The label is drawn after the
// frame, as ImGui does; the group makes the tooltip answer to the frame and the label both.
template <class T>
bool knob_slider(const char* label, ImGuiDataType type, T& v, T lo, T hi, const char* format) {
    ImGui::BeginGroup();
    ImGui::PushID(label);
    const ImGuiID id = ImGui::GetID("##slider");
    const bool typing = ImGui::TempInputIsActive(id);
    if (!typing) ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(0, 0, 0, 0));
    const bool changed = ImGui::SliderScalar("##slider", type, &v, &lo, &hi, format);
    if (!typing) ImGui::PopStyleColor();
    if (!typing) {
        const ImVec2 f0 = ImGui::GetItemRectMin(), f1 = ImGui::GetItemRectMax();
        const double span = static_cast<double>(hi) - static_cast<double>(lo);
        const double fraction = span > 0 ? (static_cast<double>(v) - static_cast<double>(lo)) / span : 0.0;
        const int values = type == ImGuiDataType_S32 ? static_cast<int>(hi - lo) + 1 : 0;
        const KnobSpan knob = slider_knob(f0.x, f1.x, fraction, ImGui::GetStyle().GrabMinSize, values);
        char text[64];
        if constexpr (std::is_integral_v<T>) std::snprintf(text, sizeof text, format, v);
        else std::snprintf(text, sizeof text, format, static_cast<double>(v));
        const ImVec2 size = ImGui::CalcTextSize(text);
        const float x = slider_value_x(f0.x, f1.x, knob, size.x, ImGui::GetStyle().FramePadding.x);
        ImDrawList* dl = ImGui::GetWindowDrawList();
        dl->PushClipRect(f0, f1, true);
        dl->AddText({x, 0.5f * (f0.y + f1.y - size.y)}, ImGui::GetColorU32(ImGuiCol_Text), text);
        dl->PopClipRect();
    }
    ImGui::PopID();
    const char* shown_end = ImGui::FindRenderedTextEnd(label);
    if (shown_end != label) {
        ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
        ImGui::TextUnformatted(label, shown_end);
    }
    ImGui::EndGroup();
    return changed;
}

bool slider_double(const char* label, double& v, double lo, double hi, const char* format) {
    return knob_slider(label, ImGuiDataType_Double, v, lo, hi, format);
}

// A field's tooltip: its help and what it allows (sim/scene/scene_fields.cpp), then what the panel adds.
std::string field_tip(const SceneField& f, const std::string& panel_note = "") {
    std::string text = field_help(f);
    if (!text.empty()) text[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
    return text + "." + (panel_note.empty() ? "" : " " + panel_note);
}

// The last value typed (Ctrl+click) outside its field's limits and clamped by the control's setter,
// said right under that control (where the eye is) as the command line would refuse it; cleared by
// the next edit.
std::string last_clamp_note;
std::string last_clamp_field;  // the field path it is about

void note_clamping(const SceneField& f, double typed) {
    last_clamp_note = clamp_note(f.label, typed, f.min, f.max);
    last_clamp_field = std::string(f.path);
}

// The panel's theme, for the notes drawn inside the controls' helpers (set at the panel's start).
bool panel_high_contrast = true;

// The clamp note under the control of field `f`, if it is about that field.
void clamp_note_here(const SceneField& f) {
    if (last_clamp_note.empty() || last_clamp_field != f.path) return;
    ImGui::PushStyleColor(ImGuiCol_Text, on_panel(kWarnColour, panel_high_contrast));
    text_wrapped(last_clamp_note);
    ImGui::PopStyleColor();
}

// [SECTION] Controls bound to the scene-field table: one widget per row of control_rows()
// The panel's controls are controls.h's rows. Each edits a copy of the value and hands an edit to
// set_control, which checks the name or clamps the number: the panel never writes a value the scene
// would refuse. Each is labelled by its field's row (sim/scene/scene_fields.cpp), shows its tooltip and
// returns true when the user changed the value.
struct Edit {
    LaneControls& lane;
    SharedControls& shared;
};

// What the panel adds to the field's tooltip: the row's note, and how to pass the slider's end.
std::string panel_note(const ControlRow& row, const SceneField& f) {
    if (!row.slider_max) return std::string(row.note);
    const std::string unit = f.unit.empty() ? std::string() : " " + std::string(f.unit);
    const std::string more = fmt::format("Ctrl+click to type more than {:g}{}.", *row.slider_max, unit);
    return row.note.empty() ? more : std::string(row.note) + " " + more;
}

// A combo over the field's presets.
bool preset_control(const ControlRow& row, const SceneField& f, Edit e) {
    std::string value = std::get<std::string>(control_value(row, e.lane, e.shared));
    const std::string shown = row.path == "shell.preset" ? polygon_combo_text(value, e.lane.values.shell.sides) : std::string();
    const bool edited = preset_combo(std::string(control_label(row)).c_str(), *f.kind, value, shown);
    if (edited) set_control(e.lane, e.shared, row.path, value);
    tip(field_tip(f, panel_note(row, f)));
    return edited;
}

// A slider over the field's limits, or up to the row's slider_max (Ctrl+click types up to the limit).
bool slider_control(const ControlRow& row, const SceneField& f, Edit e) {
    const std::string label(control_label(row));
    const std::string format(row.format);
    const double hi = row.slider_max.value_or(f.max);
    bool edited = false;
    if (f.type == FieldType::integer) {
        int n = std::get<int>(control_value(row, e.lane, e.shared));
        edited = knob_slider(label.c_str(), ImGuiDataType_S32, n, static_cast<int>(f.min), static_cast<int>(hi),
                             format.c_str());
        if (edited) {
            set_control(e.lane, e.shared, row.path, n);
            note_clamping(f, n);
        }
    } else {
        double v = std::get<double>(control_value(row, e.lane, e.shared));
        edited = slider_double(label.c_str(), v, f.min, hi, format.c_str());
        if (edited) {
            set_control(e.lane, e.shared, row.path, v);
            note_clamping(f, v);
        }
    }
    tip(field_tip(f, panel_note(row, f)));
    clamp_note_here(f);
    return edited;
}

// A seed typed, or stepped by one.
bool seed_control(const ControlRow& row, const SceneField& f, Edit e) {
    std::uint64_t seed = std::get<std::uint64_t>(control_value(row, e.lane, e.shared));
    const std::uint64_t one = 1;
    const bool edited =
        ImGui::InputScalar(std::string(control_label(row)).c_str(), ImGuiDataType_U64, &seed, &one, nullptr, "%llu");
    if (edited) set_control(e.lane, e.shared, row.path, seed);
    tip(field_tip(f, panel_note(row, f)));
    return edited;
}

// A choice as the row's radio buttons, after the label, wrapping when the panel is narrow.
bool radio_control(const ControlRow& row, const SceneField& f, Edit e) {
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted(std::string(control_label(row)).c_str());
    const float radio_extra = ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x;
    const FieldValue current = control_value(row, e.lane, e.shared);
    bool edited = false;
    for (const RadioOption& o : row.radio) {
        const std::string text(o.text);
        const std::optional<FieldValue> value = f.choice_named(o.name);
        same_line_if_fits(radio_extra + ImGui::CalcTextSize(text.c_str()).x);
        if (ImGui::RadioButton(text.c_str(), value == current) && value) {
            set_control(e.lane, e.shared, row.path, *value);
            edited = true;
        }
        tip(std::string(o.tip));
    }
    return edited;
}

// [SECTION] Panel parts: headings, preset buttons, the model, sections of rows, budget, view
void heading(const char* text) {
    ImGui::Spacing();
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    text_wrapped(text);
    ImGui::PopStyleColor();
    ImGui::Separator();
}

// The preset buttons: the demonstrations, named for what they show, first; then the experiment's
// grid (one row per polygon, one button per material, each with its angle); then the rest, as
// assets/sandbox-presets.json lays them out (sandbox_presets.h). Under them, always visible, what the
// loaded preset is: its description, not only on hover.
void preset_buttons(SandboxState& s, UiRequests& req) {
    static std::string error;
    static const PresetPanel panel = [] {
        try {
            return preset_panel();
        } catch (const std::exception& e) {
            error = e.what();
            return PresetPanel{};
        }
    }();
    if (!error.empty()) text_wrapped(error);
    const bool shown = shows_loaded_preset(s);  // no button lit for a scene the preset no longer is
    auto button = [&](const PresetButton& b, const std::string& text, bool first_in_row) {
        if (!first_in_row) same_line_if_fits(button_w(text.c_str()));
        ImGui::PushID(b.preset.c_str());
        const bool current = shown && s.preset == b.preset;
        if (current) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
        if (ImGui::Button(text.c_str())) req.load_preset = b.preset;
        if (current) ImGui::PopStyleColor();
        tip(b.tooltip);
        ImGui::PopID();
    };
    bool first = true;
    for (const PresetButton& b : panel.demos) {
        button(b, b.label, first);
        first = false;
    }
    for (const PresetButton& b : panel.others) {
        button(b, b.label, first);
        first = false;
    }
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    text_wrapped(preset_rows_heading(panel));
    ImGui::PopStyleColor();
    const float label_w = ImGui::GetFontSize() * 7.5f;
    for (const PresetRow& row : panel.rows) {
        ImGui::AlignTextToFramePadding();
        ImGui::TextUnformatted(row.label.c_str());
        bool first_in_row = true;
        for (const PresetButton& b : row.buttons) {
            // The angle on the button: the presets of one polygon differ in it.
            const std::string text = row_button_text(b);
            // The first material button lines up in a column after the polygon names, when it fits.
            if (first_in_row && label_w + button_w(text.c_str()) <= ImGui::GetContentRegionAvail().x) {
                ImGui::SameLine(label_w);
                button(b, text, true);
            } else {
                button(b, text, false);  // after the label, or on a line of its own
            }
            first_in_row = false;
        }
    }
    // What is loaded, in words.
    std::string loaded;
    if (!s.scene_file.empty()) loaded = "Scene file " + s.scene_file;
    else if (!s.preset.empty()) {
        try {
            loaded = fmt::format("{}'{}': {}", shown ? "" : "Changed from ", s.preset,
                                 sandbox_preset(s.preset).description);
        } catch (const std::exception&) {
            loaded = s.preset;
        }
    }
    if (!loaded.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        text_wrapped(loaded);
        ImGui::PopStyleColor();
    }
}

// A combo over an enumeration's names (sim/scene/scene_names.h); true when the choice changed.
bool names_combo(const char* label, const std::vector<std::string>& names, int& index) {
    return ImGui::Combo(
        label, &index,
        [](void* data, int i, const char** out) {
            *out = (*static_cast<const std::vector<std::string>*>(data))[static_cast<size_t>(i)].c_str();
            return true;
        },
        const_cast<std::vector<std::string>*>(&names), static_cast<int>(names.size()));
}

// A choice in a combo: the field's names, or the fewer the row offers (the model: the window's).
bool choice_combo(const ControlRow& row, const SceneField& f, Edit e) {
    const std::vector<std::string>& names = row.offered ? row.offered() : f.choice_names();
    const FieldValue current = control_value(row, e.lane, e.shared);
    int index = static_cast<int>(names.size());  // none lit if the value is not one offered
    for (size_t i = 0; i < names.size(); ++i)
        if (f.choice_named(names[i]) == current) index = static_cast<int>(i);
    bool changed = false;
    if (names_combo(std::string(control_label(row)).c_str(), names, index)) {
        if (const std::optional<FieldValue> value = f.choice_named(names[static_cast<size_t>(index)])) {
            set_control(e.lane, e.shared, row.path, *value);
            changed = true;
        }
    }
    tip(field_tip(f, panel_note(row, f)));
    return changed;
}

// One control, its widget chosen by its field's type: presets in a combo, numbers on a slider, the
// seed typed, a choice as the row's radio buttons or in a combo.
bool draw_control(const ControlRow& row, Edit e) {
    const SceneField& f = scene_field(row.path);
    switch (f.type) {
        case FieldType::preset: return preset_control(row, f, e);
        case FieldType::integer:
        case FieldType::number: return slider_control(row, f, e);
        case FieldType::seed: return seed_control(row, f, e);
        case FieldType::choice: return row.radio.empty() ? choice_combo(row, f, e) : radio_control(row, f, e);
        case FieldType::optional_number: break;  // no control shows one
    }
    return false;
}

// The controls of one section of the panel, in the rows' order (controls.h); a change asks for a
// rebuild. The lane's controls are the selected lane's.
void section_controls(PanelSection section, SandboxState& s, UiRequests& req) {
    const Edit e{s.lanes[static_cast<size_t>(s.selected_lane)].controls, s.shared};
    bool changed = false;
    for (const ControlRow& row : control_rows())
        if (row.section == section) changed |= draw_control(row, e);
    if (changed) req.controls_changed = true;
}

// What the scenes cost here, and the cheaper model the budget offers, one click away and only when
// clicked: the window never changes the model by itself, so a scene runs the same on any computer.
void budget_controls(SandboxState& s, const UiContext& ctx, UiRequests& req) {
    if (!ctx.budget || !ctx.budget_offer) return;
    const BudgetChoice& c = *ctx.budget;
    const BudgetChoice& offer = *ctx.budget_offer;
    const bool warn = c.reduced() || !c.fits;
    if (warn) ImGui::PushStyleColor(ImGuiCol_Text, on_panel(kWarnColour, s.high_contrast));
    text_wrapped(budget_statement(c, offer, budget_figures()));
    if (warn) ImGui::PopStyleColor();
    if (c.reduced()) {
        if (ImGui::Button("Back to the scene as asked")) {
            s.model_level = -1;
            req.model_level_changed = true;
        }
        tip("Step the scene exactly as asked again, however slowly this computer plays it.");
    } else if (offer.reduced()) {
        const std::string label =
            "Use " + level_label(budget_figures().levels.at(static_cast<size_t>(offer.level)));
        if (ImGui::Button(label.c_str())) {
            s.model_level = offer.level;
            req.model_level_changed = true;
        }
        tip("Step this cheaper model instead (grains of the same total mass but larger, or a coarser time step), so "
            "that the run plays at real time here. What it costs in accuracy is above, as the trade study measured "
            "it (docs/tradeoff/tradeoff.md); the run may differ from the scene as asked.");
    }
}

void view_controls(SandboxState& s, const UiContext& ctx, UiRequests& req) {
    const std::string follow = fmt::format("follow the polygon ({})", key_of(Key::follow));
    ImGui::Checkbox(follow.c_str(), &s.follow);
    tip("On: the camera follows the leading polygon, zoomed in. Off: the whole ramp. Drag to pan, scroll to zoom.");
    ImGui::AlignTextToFramePadding();
    ImGui::TextUnformatted("grains by");
    const float radio_extra = ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x;
    same_line_if_fits(radio_extra + ImGui::CalcTextSize("material").x);
    if (ImGui::RadioButton("material", s.colouring == render::GrainColouring::material))
        s.colouring = render::GrainColouring::material;
    tip(fmt::format("Grains coloured by their material ({} toggles).", key_of(Key::colours)));
    same_line_if_fits(radio_extra + ImGui::CalcTextSize("speed").x);
    if (ImGui::RadioButton("speed", s.colouring == render::GrainColouring::speed))
        s.colouring = render::GrainColouring::speed;
    tip(fmt::format("Grains coloured by speed: dark violet at rest to yellow at {:g} m/s and above ({} toggles); the "
                    "legend is over the scene.",
                    kDefaultColourSpeedMax_m_s, key_of(Key::colours)));
    float scale = s.ui_scale;
    if (knob_slider("UI scale", ImGuiDataType_Float, scale, kUiScaleMin, kUiScaleMax, "%.2f\u00D7")) s.ui_scale = scale;
    tip("Size of the panel's text and the scene's labels, for a projector at the back of the room. A window too "
        "small for the scale asked shows the largest that fits it (a unit of scale needs " +
        fmt::format("{:g}x{:g} pixels).", kUiScaleWindowWidthPx, kUiScaleWindowHeightPx));
    if (ctx.ui_scale_shown < s.ui_scale) {
        ImGui::PushStyleColor(ImGuiCol_Text, on_panel(kWarnColour, s.high_contrast));
        text_wrapped(fmt::format("shown at {:.2f}\u00D7: the largest this window size fits", ctx.ui_scale_shown));
        ImGui::PopStyleColor();
    }
    ImGui::Checkbox("projector theme (high contrast)", &s.high_contrast);
    tip("Dark text on pale panels with strong borders; off: ImGui's dark theme.");
    const std::string reset_view = fmt::format("reset view ({})", key_of(Key::reset_view));
    if (ImGui::Button(reset_view.c_str())) req.reset_view = true;
    tip("Undo panning and zooming.");
}

// [SECTION] Plots: a card with title, legend, axes, traces and markers
// A plot drawn with ImGui's draw list: axes with readable ticks, traces, markers, a legend.
struct Trace {
    std::vector<PlotPoint> points;
    ImU32 colour;
    std::string legend;
};
struct Markers {
    std::vector<PlotPoint> points;
    ImU32 colour;
};

// A plot drawn with ImGui's draw list, on a white card in every theme (so its text is always dark):
// the title, then the legend in a row of its own above the data (never over a trace), then the
// axes, with as many ticks as the card's size leaves room for (no numbers running together at a
// large UI scale or in a narrow window).
void draw_plot(const char* title, const char* unit, const PlotRange& r, const std::vector<Trace>& traces,
               const std::vector<Markers>& markers, ImVec2 size) {
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    ImGui::Dummy(size);
    const float fs = ImGui::GetFontSize();
    const ImU32 text = im_colour(render::palette::text);
    const ImU32 grid = im_colour(render::palette::plot_grid);
    const ImU32 axis = im_colour(render::palette::plot_axis);
    const float thick = std::max(2.0f, fs * 0.14f);
    const ImVec2 p1{p0.x + size.x, p0.y + size.y};
    dl->AddRectFilled(p0, p1, im_colour(render::palette::plot_card), 3.0f);
    dl->PushClipRect(p0, p1, true);
    // The title, shortened to what fits.
    std::string heading = fmt::format("{}: {} against time (s)", title, unit);
    if (ImGui::CalcTextSize(heading.c_str()).x > size.x - fs * 0.8f) heading = fmt::format("{} ({})", title, unit);
    dl->AddText({p0.x + fs * 0.4f, p0.y + fs * 0.15f}, text, heading.c_str());
    // The legend: entries left to right, wrapping to a new row when the card is narrow.
    float lx = p0.x + fs * 0.4f, ly = p0.y + fs * 1.35f;
    bool any_legend = false;
    for (const Trace& tr : traces) {
        if (tr.legend.empty()) continue;
        const float w = fs * 1.3f + ImGui::CalcTextSize(tr.legend.c_str()).x;
        if (any_legend && lx + w > p1.x - fs * 0.4f) {
            lx = p0.x + fs * 0.4f;
            ly += fs * 1.15f;
        }
        any_legend = true;
        dl->AddLine({lx, ly + fs * 0.55f}, {lx + fs * 0.9f, ly + fs * 0.55f}, tr.colour, thick);
        dl->AddText({lx + fs * 1.1f, ly}, text, tr.legend.c_str());
        lx += w + fs * 0.8f;
    }
    const float top = any_legend ? ly + fs * 1.35f : p0.y + fs * 1.5f;
    // Plot area inside the labels.
    const ImVec2 a0{p0.x + fs * 3.6f, top};
    const ImVec2 a1{p1.x - fs * 0.9f, p1.y - fs * 1.5f};
    if (a1.x <= a0.x + 10 || a1.y <= a0.y + 10) {
        dl->PopClipRect();
        return;
    }
    // The frames' plot's mapping (render/overlay.h).
    const render::PlotMapping map{a0.x, a1.x, a0.y, a1.y, r.t_max_s, r.y_min, r.y_max};
    auto X = [&](double t) { return map.x(t); };
    auto Y = [&](double v) { return map.y(v); };
    // Ticks: the frames' plot's rules (render/ticks.h), up to five intervals in time and four in
    // value, fewer when a label (about 3.5 em wide, 2 lines tall) would not fit between them.
    const double t_intervals = std::clamp(std::floor((a1.x - a0.x) / (fs * 3.5f)), 1.0f, 5.0f);
    const double y_intervals = std::clamp(std::floor((a1.y - a0.y) / (fs * 2.0f)), 1.0f, 4.0f);
    const render::AxisTicks t_ticks = render::axis_ticks(0.0, r.t_max_s, t_intervals);
    for (int k = 0; k < t_ticks.count; ++k) {
        const double t = t_ticks.at(k);
        dl->AddLine({X(t), a0.y}, {X(t), a1.y}, grid);
        const std::string l = fmt::format("{:g}", std::round(t * 1000.0) / 1000.0);
        const float w = ImGui::CalcTextSize(l.c_str()).x;
        // The last label kept inside the card.
        const float x = std::min(X(t) - w / 2, p1.x - w - fs * 0.2f);
        dl->AddText({x, a1.y + fs * 0.15f}, text, l.c_str());
    }
    const render::AxisTicks y_ticks = render::axis_ticks(r.y_min, r.y_max, y_intervals);
    for (int k = 0; k < y_ticks.count; ++k) {
        const double v = y_ticks.at(k);
        dl->AddLine({a0.x, Y(v)}, {a1.x, Y(v)}, std::fabs(v) < 1e-12 ? axis : grid);
        const double shown = std::fabs(v) < 1e-12 ? 0.0 : std::round(v * 1e4) / 1e4;  // never "-0"
        const std::string l = fmt::format("{:g}", shown);
        dl->AddText({a0.x - ImGui::CalcTextSize(l.c_str()).x - fs * 0.3f, Y(v) - fs / 2}, text, l.c_str());
    }
    dl->AddRect(a0, a1, axis, 0.0f, 0, 1.5f);
    dl->PopClipRect();
    dl->PushClipRect(a0, a1, true);
    for (const Trace& tr : traces) {
        std::vector<ImVec2> pts;
        pts.reserve(tr.points.size());
        for (const PlotPoint& p : tr.points) pts.push_back({X(p.t_s), Y(p.y)});
        if (pts.size() >= 2) dl->AddPolyline(pts.data(), static_cast<int>(pts.size()), tr.colour, 0, thick);
    }
    for (const Markers& m : markers)
        for (const PlotPoint& p : m.points) {
            dl->AddCircleFilled({X(p.t_s), Y(p.y)}, fs * 0.28f, m.colour);
            dl->AddCircle({X(p.t_s), Y(p.y)}, fs * 0.28f, axis, 0, 1.0f);
        }
    dl->PopClipRect();
}

}  // namespace

// [SECTION] Layout: where the panel, the scene and the readouts strip go
float panel_seam_px(float pixel_ratio) {
    // Half the border and the antialiasing pixel, whole; one more for the panels' copy, which counts a
    // window as reaching a pixel beyond its vertices (panel_cache.cpp).
    return std::ceil((0.5f * ImGui::GetStyle().WindowBorderSize + 1.0f) * pixel_ratio) + 1.0f;
}

UiLayout ui_layout(float width, float height, float ui_scale) {
    UiLayout L;
    L.width = width;
    L.height = height;
    L.panel_w = std::min(kPanelWidthPx * ui_scale, 0.5f * width);
    L.plots_h = std::round(kPlotsHeightShare * height);
    return L;
}

// [SECTION] Control panel window: title, transport, presets, lanes, controls, save
namespace {

// The widest label of the panel's controls: every control's frame ends where its label's room begins,
// so no label runs off the panel's edge (ImGui's default, 65% of the width, leaves too little at a
// large UI scale).
float panel_label_width() {
    float w = std::max(ImGui::CalcTextSize("slow motion").x, ImGui::CalcTextSize("UI scale").x);
    for (const ControlRow& row : control_rows())
        if (row.radio.empty()) w = std::max(w, ImGui::CalcTextSize(std::string(control_label(row)).c_str()).x);
    return w;
}

// Play, step, reset, run to the end and slow motion. After the end, the play button says what it
// does then: the run starts again.
void transport_controls(SandboxState& s, const UiContext& ctx, UiRequests& req) {
    const char* play = ctx.run_over ? "\u25B6 Replay" : s.playing ? "\u275A\u275A Pause" : "\u25B6 Play";
    if (ImGui::Button(play)) req.toggle_play = true;
    tip(ctx.run_over ? fmt::format("The run has ended: start it again from release ({}).", key_of(Key::play))
                     : fmt::format("Play or pause the simulation ({}).", key_of(Key::play)));
    same_line_if_fits(button_w("Step"));
    if (ImGui::Button("Step")) req.step = true;
    tip(fmt::format("Advance {:.3f} s of simulated time while paused ({}).", kSingleStepS, key_of(Key::step)));
    same_line_if_fits(button_w("Reset"));
    if (ImGui::Button("Reset")) req.reset = true;
    tip(fmt::format("Rebuild the scene from the controls and start again from release ({}).", key_of(Key::reset)));
    same_line_if_fits(button_w("Run to end"));
    if (ImGui::Button("Run to end")) req.run_to_end = true;
    tip(fmt::format("Compute the rest of the run as fast as possible without drawing it, then show the end ({}).",
                    key_of(Key::run_to_end)));
    std::vector<std::string> slow_labels;
    slow_labels.reserve(std::size(kSlowMotionDivisors));
    for (int d : kSlowMotionDivisors) slow_labels.push_back(d == 1 ? "1\u00D7 (real time)" : fmt::format("1/{}\u00D7", d));
    if (ImGui::BeginCombo("slow motion", slow_labels[static_cast<size_t>(s.slow_index)].c_str())) {
        for (size_t i = 0; i < slow_labels.size(); ++i)
            if (ImGui::Selectable(slow_labels[i].c_str(), static_cast<int>(i) == s.slow_index))
                s.slow_index = static_cast<int>(i);
        ImGui::EndCombo();
    }
    tip(fmt::format("Simulated time runs at this share of real time: 1\u00D7 is real time, 1/16\u00D7 sixteen times "
                    "slower ({} and {} change it).",
                    key_of(Key::slower), key_of(Key::faster)));
}

// One tab per lane, in its colour (the selected one is the lane the controls edit), and the tab adding
// a lane.
void lane_tabs(SandboxState& s, UiRequests& req) {
    if (!ImGui::BeginTabBar("lanes")) return;
    for (size_t i = 0; i < s.lanes.size(); ++i) {
        const std::string name = fmt::format("Lane {}", i + 1);
        ImGui::PushStyleColor(ImGuiCol_Text, on_panel(im_vec(lane_colour(i)), s.high_contrast));
        const bool open = ImGui::BeginTabItem(name.c_str());
        ImGui::PopStyleColor();
        if (open) {
            s.selected_lane = static_cast<int>(i);
            ImGui::EndTabItem();
        }
    }
    if (static_cast<int>(s.lanes.size()) < kMaxLanes) {
        if (ImGui::TabItemButton("+", ImGuiTabItemFlags_Trailing)) {
            if (add_lane(s)) req.controls_changed = true;
        }
        tip("Add a lane: a copy of this one, on its own parallel ramp, started together with the others.");
    }
    ImGui::EndTabBar();
}

void save_controls(UiRequests& req) {
    const std::string screenshot = fmt::format("Screenshot ({})", key_of(Key::screenshot));
    if (ImGui::Button(screenshot.c_str())) req.screenshot = true;
    tip("Save the window as a PNG; where it went is said over the scene.");
    const std::string export_run = fmt::format("Export run ({})", key_of(Key::export_run));
    same_line_if_fits(button_w(export_run.c_str()));
    if (ImGui::Button(export_run.c_str())) req.export_run = true;
    tip("Write the current run's summary.json, trajectory.csv and impacts.csv (the files polyroll run writes), "
        "one folder per lane; where they went is said over the scene.");
}

// Whether a change restarts at once, and a note while changes wait for Reset.
void restart_controls(SandboxState& s) {
    ImGui::Checkbox("restart on change", &s.restart_on_change);
    tip("On: every change rebuilds the scene and starts again (a slider when let go). Off: changes wait for Reset.");
    if (s.changes_pending && !s.restart_on_change) {
        ImGui::PushStyleColor(ImGuiCol_Text, on_panel(kWarnColour, s.high_contrast));
        text_wrapped("controls changed: Reset applies them");
        ImGui::PopStyleColor();
    }
}

}  // namespace

void draw_control_panel(SandboxState& s, const UiContext& ctx, const UiLayout& L, UiRequests& req,
                        UiLayoutReport* report) {
    ImGui::SetNextWindowPos({0, 0});
    ImGui::SetNextWindowSize({L.panel_w, L.height});
    begin_panel("controls",
                ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                    ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                    ImGuiWindowFlags_NoBringToFrontOnFocus);
    panel_high_contrast = s.high_contrast;
    ImGui::PushItemWidth(-(panel_label_width() + ImGui::GetStyle().ItemInnerSpacing.x + 2.0f));
    if (ctx.large_font) ImGui::PushFont(ctx.large_font);
    ImGui::TextUnformatted("polyroll sandbox");
    if (ctx.large_font) ImGui::PopFont();
    transport_controls(s, ctx, req);

    if (ImGui::CollapsingHeader("Presets", ImGuiTreeNodeFlags_DefaultOpen)) preset_buttons(s, req);

    heading(fmt::format("Lanes (up to {} race side by side)", kMaxLanes).c_str());
    lane_tabs(s, req);
    section_controls(PanelSection::lane, s, req);
    if (s.lanes.size() > 1) {
        if (ImGui::Button("remove this lane")) {
            if (remove_lane(s, s.selected_lane)) req.controls_changed = true;
        }
        tip("Take this lane out of the race.");
    }
    heading("Ramp and physics (all lanes)");
    section_controls(PanelSection::ramp, s, req);
    section_controls(PanelSection::physics, s, req);
    budget_controls(s, ctx, req);

    if (ImGui::CollapsingHeader("Advanced")) section_controls(PanelSection::advanced, s, req);
    tip("Grain and ramp friction and restitution.");
    if (ImGui::CollapsingHeader("View")) view_controls(s, ctx, req);
    if (ImGui::CollapsingHeader("Save")) save_controls(req);
    ImGui::Spacing();
    restart_controls(s);
    // Room under the last control, so that scrolled to the bottom it is whole above the window's edge.
    ImGui::Dummy({1.0f, ImGui::GetFrameHeight()});
    ImGui::PopItemWidth();
    record_window(report, "controls");
    ImGui::End();
}

// [SECTION] Readouts and plots window: the table, the speed plot, the energy plot
namespace {

// The readouts table's rows: the label, the lane's entry, what it is (the label's tooltip).
struct ReadoutRow {
    const char* label;
    std::string LaneReadout::*field;
    const char* what;
};
const std::vector<ReadoutRow>& readout_rows() {
    static const std::vector<ReadoutRow> rows = {
        {"polygon", &LaneReadout::polygon, "The number of sides n."},
        {"fill", &LaneReadout::fill, "The fill ratio r and the grains."},
        {"position", &LaneReadout::position, "The lid centre's distance down the ramp from release, m."},
        {"speed", &LaneReadout::speed, "The lid centre's speed along the ramp, m/s (negative rocking back)."},
        {"face impacts", &LaneReadout::impacts, "Faces landed so far."},
        {"behaviour", &LaneReadout::behaviour,
         "What the run did, once known: stopped at its first impact, stopped (after rolling), or rolled to the end."},
        {"distance", &LaneReadout::distance, "Distance rolled, release to stop or end, m (once the run ended)."},
        {"terminal v", &LaneReadout::terminal,
         "Terminal velocity, m/s: the mean speed over the last full turn, for a run that rolled to the end."},
        {"model", &LaneReadout::model,
         "The model computing this lane. auto picks the cheapest the scene requires: rigid for an empty or a "
         "full shell, going on as a free rigid body where it would lift off or slip; grains for a partly "
         "filled one. Hover a lane's entry for its reason."},
    };
    return rows;
}

// Every lane's readouts; a lane the budget made cheaper says so in its model entry.
std::vector<LaneReadout> lane_readouts(const UiContext& ctx) {
    const LaneSet& lanes = *ctx.lanes;
    std::vector<LaneReadout> r;
    for (size_t i = 0; i < lanes.size(); ++i)
        r.push_back(lane_readout(lanes.lane(i).scene(), lanes.lane(i).measured(), lanes.lane(i).time_s(),
                                 lanes.lane(i).model_choice()));
    if (ctx.budget && ctx.budget->reduced())
        for (size_t i = 0; i < lanes.size(); ++i)
            if (lanes.lane(i).grains() > 0)
                r[i].model = budget_model_label(lanes.lane(i).scene(), lanes.lane(i).model_choice(),
                                                budget_figures().levels.at(static_cast<size_t>(ctx.budget->level)));
    return r;
}

// The model entry wraps in its cell no narrower than this text (two lines at most for auto's).
constexpr const char* kModelEntryMinText = "auto: rigid, hops";

// How the readouts strip is shared between the table and the plots.
struct StripLayout {
    float table_w = 0, plot_w = 0, tab_h = 0;
    bool table_tab = false;   // the table in a tab of its own, as wide as the strip
    bool table_fits = false;  // every entry whole on one line
    bool tabbed = false;      // one plot at a time, chosen by tabs
    bool racing = false;      // several lanes
};

// The table as wide as its longest entries (every lane's "stopped at 1st impact" whole), up to
// kReadoutTableMaxShare of the width; past that its cells wrap rather than cut their text, and the
// plot keeps the rest (at a large UI scale it would otherwise shrink to a thumbnail).
StripLayout strip_layout(const std::vector<LaneReadout>& r, ImVec2 avail) {
    const float gap = ImGui::GetStyle().ItemSpacing.x;
    const float fs = ImGui::GetFontSize();
    const float cell_pad = 2.0f * ImGui::GetStyle().CellPadding.x + 2.0f;
    float needed_w = 0;
    for (const ReadoutRow& row : readout_rows()) needed_w = std::max(needed_w, ImGui::CalcTextSize(row.label).x);
    needed_w += cell_pad;
    for (const LaneReadout& lr : r) {
        float w = fs * 2.0f;
        // The model entry wraps in its cell ("auto: rigid, hops from 0.48 s" would set the column's width
        // alone): the table is as wide as the other entries, or as "auto: rigid, hops" (two lines at most).
        for (const ReadoutRow& row : readout_rows())
            if (row.field != &LaneReadout::model) w = std::max(w, ImGui::CalcTextSize((lr.*row.field).c_str()).x);
        w = std::max(w, std::min(ImGui::CalcTextSize(lr.model.c_str()).x, ImGui::CalcTextSize(kModelEntryMinText).x));
        needed_w += w + cell_pad;
    }
    StripLayout S;
    // A table that needs more than its share of the strip wraps its cells there, as long as the plot
    // beside it keeps kMinPlotWidthEm; past that (a large UI scale, a narrow window) it gets a tab of
    // its own, as wide as the strip, beside the plots' tabs: its cells would otherwise wrap letter by
    // letter, or the plot shrink to a thumbnail.
    const float share_w = avail.x * kReadoutTableMaxShare;
    S.table_tab = needed_w > share_w && avail.x - share_w - gap < fs * kMinPlotWidthEm;
    S.table_fits = needed_w <= (S.table_tab ? avail.x : share_w);
    S.table_w = S.table_tab ? avail.x : std::min(needed_w, share_w);
    // One lane: the speed and energy plots side by side. Several: one plot at a time, chosen by tabs,
    // so the readout columns and the plot both stay wide enough to read.
    S.racing = r.size() > 1;
    // Tabs also when two plots side by side would be narrower than kMinPlotWidthEm each (a large UI
    // scale or a small window): one readable plot rather than two slivers.
    S.tabbed = S.table_tab || S.racing || (avail.x - S.table_w - 2 * gap) / 2.0f < fs * kMinPlotWidthEm;
    S.plot_w = S.table_tab  ? avail.x
               : S.tabbed ? avail.x - S.table_w - gap
                          : (avail.x - S.table_w - 2 * gap) / 2.0f;
    S.tab_h = ImGui::GetFrameHeightWithSpacing();
    return S;
}

// Whether the table's rows, padded, would run past `height` (a large UI scale): its rows are then as
// tall as their text, and the strip's window padding halved, so every row stays in view without a
// scroll. The lines counted: a header when racing, every row, and the model entry's second line.
bool readouts_tight(float height, bool racing) {
    const float padded_row_h = ImGui::GetTextLineHeight() + 2.0f * ImGui::GetStyle().CellPadding.y + 1.0f;
    const size_t lines = readout_rows().size() + (racing ? 1 : 0) + 1;
    return static_cast<float>(lines) * padded_row_h > height;
}

// Readouts: one column per lane (the time is the status line's: the lanes started together).
void readout_table(const SandboxState& s, const UiContext& ctx, const std::vector<LaneReadout>& r,
                   const StripLayout& S, float height, UiLayoutReport* report) {
    ImGui::BeginChild("table", {S.table_w, height});
    const bool tight = readouts_tight(height, S.racing);
    if (tight) ImGui::PushStyleVar(ImGuiStyleVar_CellPadding, {ImGui::GetStyle().CellPadding.x, 0.0f});
    const ImGuiTableFlags tf = ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg |
                               (S.table_fits ? ImGuiTableFlags_SizingFixedFit : ImGuiTableFlags_SizingStretchProp);
    if (ImGui::BeginTable("readouts", static_cast<int>(r.size()) + 1, tf)) {
        if (S.racing) {
            ImGui::TableNextRow(ImGuiTableRowFlags_Headers);
            ImGui::TableSetColumnIndex(0);
            ImGui::TextUnformatted("lane");
            for (size_t i = 0; i < r.size(); ++i) {
                ImGui::TableSetColumnIndex(static_cast<int>(i) + 1);
                if (ctx.large_font) ImGui::PushFont(ctx.large_font);
                ImGui::TextColored(on_panel(im_vec(lane_colour(i)), s.high_contrast), "%zu", i + 1);
                if (ctx.large_font) ImGui::PopFont();
            }
        }
        for (const ReadoutRow& row : readout_rows()) {
            ImGui::TableNextRow();
            ImGui::TableSetColumnIndex(0);
            ImGui::TextUnformatted(row.label);
            tip(row.what);
            const bool model = row.field == &LaneReadout::model;
            for (size_t i = 0; i < r.size(); ++i) {
                ImGui::TableSetColumnIndex(static_cast<int>(i) + 1);
                if (S.table_fits && !model) ImGui::TextUnformatted((r[i].*row.field).c_str());
                // The model entry wraps no narrower than "auto: rigid, hops", the width strip_layout
                // gives it (a cell sized to its content would otherwise wrap word by word).
                else text_wrapped(r[i].*row.field, ImGui::CalcTextSize(kModelEntryMinText).x);
                // auto's reason under the pointer, on the lane's model entry.
                if (model && !r[i].model_reason.empty()) tip(r[i].model_reason);
            }
        }
        ImGui::EndTable();
    }
    if (tight) ImGui::PopStyleVar();
    record_window(report, "table");
    ImGui::EndChild();
}

// The lid centre's speed in every lane, each in its lane's colour, face impacts marked.
void speed_plot(const std::vector<const Measurements*>& all, const StripLayout& S, float height,
                UiLayoutReport* report) {
    const size_t max_points = static_cast<size_t>(std::max(50.0f, S.plot_w));
    std::vector<Trace> traces;
    std::vector<Markers> markers;
    for (size_t i = 0; i < all.size(); ++i) {
        traces.push_back({series(*all[i], Series::speed, max_points), im_colour(lane_colour(i)),
                          S.racing ? fmt::format("lane {}", i + 1) : std::string()});
        markers.push_back({impact_markers(*all[i]), im_colour(lane_colour(i))});
    }
    draw_plot("Speed", "m/s", speed_range(all), traces, markers, {S.plot_w, height});
    if (report)
        report->plots.push_back({"speed", ImGui::GetItemRectMin().x, ImGui::GetItemRectMin().y,
                                 ImGui::GetItemRectMax().x, ImGui::GetItemRectMax().y});
    tip("The lid centre's speed along the ramp against time; dots mark face impacts.");
}

// The energies of the selected lane.
void energy_plot(const Measurements& m, size_t lane, const StripLayout& S, float height) {
    const size_t max_points = static_cast<size_t>(std::max(50.0f, S.plot_w));
    const std::vector<Trace> energy = {
        {series(m, Series::kinetic, max_points), im_colour(render::palette::energy_kinetic), "kinetic"},
        {series(m, Series::potential, max_points), im_colour(render::palette::energy_potential), "potential"},
        {series(m, Series::dissipated, max_points), im_colour(render::palette::energy_dissipated), "dissipated"}};
    const std::string title = S.racing ? fmt::format("Energy, lane {}", lane + 1) : std::string("Energy");
    draw_plot(title.c_str(), "J", energy_range(m), energy, {}, {S.plot_w, height});
    tip("Kinetic energy of shell and grains, potential energy relative to release, and the energy dissipated so "
        "far (in impacts and friction), J. With several lanes: the lane selected in the panel.");
}

}  // namespace

void draw_readouts_and_plots(const SandboxState& s, const UiContext& ctx, const UiLayout& L, UiLayoutReport* report) {
    ImGui::SetNextWindowPos({L.panel_w, L.height - L.plots_h});
    ImGui::SetNextWindowSize({L.width - L.panel_w, L.plots_h});
    const ImVec2 padding = ImGui::GetStyle().WindowPadding;
    const bool tight = readouts_tight(L.plots_h - 2.0f * padding.y, ctx.lanes->size() > 1);
    if (tight) ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, {padding.x, 0.5f * padding.y});
    begin_panel("readouts",
                ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                    ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                    ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_NoScrollbar);
    if (tight) ImGui::PopStyleVar();
    const LaneSet& lanes = *ctx.lanes;
    if (!lanes.ready()) {
        ImGui::TextUnformatted(lanes.building() ? "building the scene..." : "no scene");
        record_window(report, "readouts");
        ImGui::End();
        return;
    }
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const std::vector<LaneReadout> r = lane_readouts(ctx);
    const StripLayout S = strip_layout(r, avail);
    std::vector<const Measurements*> all;
    for (size_t i = 0; i < lanes.size(); ++i) all.push_back(&lanes.lane(i).measured());
    const size_t sel = std::min(static_cast<size_t>(std::max(0, s.selected_lane)), lanes.size() - 1);
    if (!S.table_tab) {
        readout_table(s, ctx, r, S, avail.y, report);
        ImGui::SameLine();
    }
    if (!S.tabbed) {
        speed_plot(all, S, avail.y, report);
        ImGui::SameLine();
        energy_plot(*all[sel], sel, S, avail.y);
    } else {
        ImGui::BeginGroup();
        if (ImGui::BeginTabBar("plots")) {
            if (S.table_tab && ImGui::BeginTabItem("readouts")) {
                readout_table(s, ctx, r, S, avail.y - S.tab_h, report);
                ImGui::EndTabItem();
            }
            if (ImGui::BeginTabItem(S.racing ? "speed, all lanes" : "speed")) {
                speed_plot(all, S, avail.y - S.tab_h, report);
                ImGui::EndTabItem();
            }
            const std::string energy_tab =
                S.racing ? fmt::format("energy, lane {}###energy", sel + 1) : "energy###energy";
            if (ImGui::BeginTabItem(energy_tab.c_str())) {
                energy_plot(*all[sel], sel, S, avail.y - S.tab_h);
                ImGui::EndTabItem();
            }
            ImGui::EndTabBar();
        }
        ImGui::EndGroup();
    }
    record_window(report, "readouts");
    ImGui::End();
}

// [SECTION] Status band over the scene

namespace {

// One line of the status band, with its colour; the first is drawn in the large font.
struct StatusLine {
    std::string text;
    std::optional<ImVec4> colour;
};

// What the band says: the run's state and speed, then errors, warnings and the last action's feedback.
std::vector<StatusLine> status_lines(const SandboxState& s, const UiContext& ctx) {
    const LaneSet& lanes = *ctx.lanes;
    const int divisor = kSlowMotionDivisors[static_cast<size_t>(s.slow_index)];
    std::vector<StatusLine> lines;
    if (lanes.building()) {
        lines.push_back({"Building the scene: pouring and settling the grains...", {}});
    } else if (!lanes.ready()) {
        lines.push_back({"No scene", {}});
    } else {
        std::string state;
        if (lanes.trouble()) state = "stopped";
        else if (ctx.running_to_end) state = "running to the end (not drawn)";
        else if (lanes.all_finished())
            state = lanes.size() == 1 ? "run ended: " + behaviour_label(lanes.lane(0).measured().behaviour)
                                      : std::string("run ended");
        else state = s.playing ? "\u25B6 playing" : "\u275A\u275A paused";
        const bool stepping = s.playing && !lanes.all_finished() && !lanes.trouble() && !ctx.running_to_end;
        const std::string speed =
            ctx.capture ? std::string(kCaptureSpeedStatement)
                        : speed_statement(divisor, stepping, ctx.clock->keeping_up(), ctx.clock->realtime_ratio());
        lines.push_back({status_line(lanes.time_s(), state, speed), {}});
    }
    const ImVec4 error = on_panel(kErrorColour, s.high_contrast), warn = on_panel(kWarnColour, s.high_contrast);
    if (!lanes.build_error().empty()) lines.push_back({"The scene could not be built: " + lanes.build_error(), error});
    if (lanes.trouble()) lines.push_back({*lanes.trouble(), error});
    if (!ctx.control_error.empty()) lines.push_back({ctx.control_error, error});
    if (s.changes_pending && !s.restart_on_change)
        lines.push_back({"Controls changed: press Reset (R) to apply them.", warn});
    if (ctx.budget && ctx.budget->reduced() && lanes.ready())
        lines.push_back({budget_status(budget_figures().levels.at(static_cast<size_t>(ctx.budget->level))), warn});
    // What the user just did (a screenshot or an export saved), where the eye is, for a few seconds.
    if (!ctx.feedback.empty() && ImGui::GetTime() < ctx.feedback_until_s) lines.push_back({ctx.feedback, {}});
    return lines;
}

// Racing: the lanes' legend, one entry per lane (none for a single lane).
std::vector<std::string> lane_legend_names(const LaneSet& lanes) {
    std::vector<std::string> names;
    if (lanes.ready() && lanes.size() > 1)
        for (size_t i = 0; i < lanes.size(); ++i)
            names.push_back(fmt::format("{}  {}", i + 1, lane_readout(lanes.lane(i).scene(), lanes.lane(i).measured(), 0).title));
    return names;
}

// The gap between two entries of the lane legend.
float legend_entry_gap() { return ImGui::GetFontSize() * 1.5f; }

// The band's height from its wrapped text, before it is drawn: the scene starts under it. The lane
// legend wraps as a line of text does: entries left to right, a new row when the next would pass the edge.
float status_height(const std::vector<StatusLine>& lines, const std::vector<std::string>& lane_names,
                    bool speed_legend, float wrap, const UiContext& ctx) {
    const ImGuiStyle& style = ImGui::GetStyle();
    float height = 2.0f * style.WindowPadding.y;
    for (size_t i = 0; i < lines.size(); ++i) {
        const bool large = i == 0 && ctx.large_font;
        if (large) ImGui::PushFont(ctx.large_font);
        height += ImGui::CalcTextSize(lines[i].text.c_str(), nullptr, false, wrap).y;
        if (large) ImGui::PopFont();
        if (i > 0) height += style.ItemSpacing.y;
    }
    const float legend_h = ImGui::GetFontSize();
    if (speed_legend) height += style.ItemSpacing.y + legend_h;
    int legend_rows = 0;
    for (float x = wrap + 1.0f; const std::string& name : lane_names) {
        const float w = ImGui::CalcTextSize(name.c_str()).x;
        if (x + w > wrap) {
            ++legend_rows;
            x = 0.0f;
        }
        x += w + legend_entry_gap();
    }
    if (legend_rows > 0) height += legend_rows * (legend_h + style.ItemSpacing.y);
    return std::ceil(height);
}

void draw_status_text(const std::vector<StatusLine>& lines, const UiContext& ctx) {
    for (size_t i = 0; i < lines.size(); ++i) {
        const bool large = i == 0 && ctx.large_font;
        if (large) ImGui::PushFont(ctx.large_font);
        if (lines[i].colour) ImGui::PushStyleColor(ImGuiCol_Text, *lines[i].colour);
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(lines[i].text.c_str());
        ImGui::PopTextWrapPos();
        if (lines[i].colour) ImGui::PopStyleColor();
        if (large) ImGui::PopFont();
    }
}

// Each lane's name in its colour, in rows as status_height counted them.
void draw_lane_legend(const std::vector<std::string>& lane_names, float wrap, bool high_contrast) {
    const float entry_gap = legend_entry_gap();
    float row_x = 0.0f;  // where the legend's current row ends
    for (size_t i = 0; i < lane_names.size(); ++i) {
        const float w = ImGui::CalcTextSize(lane_names[i].c_str()).x;
        if (i > 0 && row_x + entry_gap + w <= wrap) {
            ImGui::SameLine(0.0f, entry_gap);
            row_x += entry_gap + w;
        } else {
            row_x = w;
        }
        ImGui::TextColored(on_panel(im_vec(lane_colour(i)), high_contrast), "%s", lane_names[i].c_str());
    }
}

// The grain colours' legend: a bar from rest to the top of the colour map.
void draw_speed_legend() {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float legend_h = ImGui::GetFontSize();
    const std::string left = "grain speed  0 m/s", right = fmt::format("{:g} m/s and above", kDefaultColourSpeedMax_m_s);
    ImGui::TextUnformatted(left.c_str());
    ImGui::SameLine();
    const float bar_w = std::min(ImGui::GetFontSize() * 10.0f,
                                 std::max(ImGui::GetFontSize() * 2.0f,
                                          ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize(right.c_str()).x -
                                              2.0f * style.ItemSpacing.x));
    const ImVec2 p = ImGui::GetCursorScreenPos();
    ImDrawList* dl = ImGui::GetWindowDrawList();
    constexpr int kSteps = 24;
    for (int k = 0; k < kSteps; ++k) {
        const render::Rgba c = render::speed_colour((k + 0.5) / kSteps);
        dl->AddRectFilled({p.x + bar_w * k / kSteps, p.y + legend_h * 0.15f},
                          {p.x + bar_w * (k + 1) / kSteps + 0.5f, p.y + legend_h * 0.85f}, im_colour(c));
    }
    ImGui::Dummy({bar_w, legend_h});
    ImGui::SameLine();
    ImGui::TextUnformatted(right.c_str());
}

}  // namespace

// The band spans the scene's width; returns its height.
render::Rgba panel_background() {
    const ImVec4 c = ImGui::GetStyle().Colors[ImGuiCol_WindowBg];
    const render::Rgba under = render::palette::background;
    const auto over = [&](float top, float bottom) { return c.w * top + (1.0f - c.w) * bottom; };
    return {over(c.x, under.r), over(c.y, under.g), over(c.z, under.b), 1.0f};
}

float draw_status(const SandboxState& s, const UiContext& ctx, const UiLayout& L, UiLayoutReport* report) {
    const std::vector<StatusLine> lines = status_lines(s, ctx);
    const std::vector<std::string> lane_names = lane_legend_names(*ctx.lanes);
    const bool speed_legend = s.colouring == render::GrainColouring::speed;
    const float x0 = L.panel_w, width = std::max(1.0f, L.width - L.panel_w);
    const float wrap = std::max(1.0f, width - 2.0f * ImGui::GetStyle().WindowPadding.x);
    const float height = status_height(lines, lane_names, speed_legend, wrap, ctx);

    ImGui::SetNextWindowPos({x0, 0});
    ImGui::SetNextWindowSize({width, height});
    begin_panel("status",
                ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                    ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs |
                    ImGuiWindowFlags_NoBringToFrontOnFocus);
    draw_status_text(lines, ctx);
    draw_lane_legend(lane_names, wrap, s.high_contrast);
    if (speed_legend) draw_speed_legend();
    record_window(report, "status");
    ImGui::End();
    return height;
}

// [SECTION] Keyboard shortcuts: reading the keys, and the help
void read_shortcuts(SandboxState& s, UiRequests& req) {
    if (ImGui::GetIO().WantTextInput) return;
    const int last = static_cast<int>(kSlowMotionDivisors.size()) - 1;
    for (const Shortcut& k : kShortcuts) {
        const bool pressed =
            ImGui::IsKeyPressed(k.code, k.repeat) || (k.other_code != 0 && ImGui::IsKeyPressed(k.other_code, k.repeat));
        if (!pressed) continue;
        switch (k.key) {
            case Key::play: req.toggle_play = true; break;
            case Key::step: req.step = true; break;
            case Key::reset: req.reset = true; break;
            case Key::run_to_end: req.run_to_end = true; break;
            case Key::follow: s.follow = !s.follow; break;
            case Key::colours:
                s.colouring = s.colouring == render::GrainColouring::material ? render::GrainColouring::speed
                                                                              : render::GrainColouring::material;
                break;
            case Key::screenshot: req.screenshot = true; break;
            case Key::export_run: req.export_run = true; break;
            case Key::slower: s.slow_index = std::min(last, s.slow_index + 1); break;
            case Key::faster: s.slow_index = std::max(0, s.slow_index - 1); break;
            case Key::reset_view: req.reset_view = true; break;
        }
    }
}

std::string shortcut_help(size_t width) {
    std::string text = "Keys:";
    for (const Shortcut& k : kShortcuts) text += fmt::format(" {} {},", k.name, k.what);
    text.back() = ';';
    text += " drag to pan, scroll to zoom.";
    // Wrapped at spaces into lines of at most `width` characters.
    std::string out;
    size_t line = 0;
    for (size_t start = 0; start < text.size();) {
        size_t end = text.find(' ', start);
        if (end == std::string::npos) end = text.size();
        const std::string word = text.substr(start, end - start);
        if (line > 0 && line + 1 + word.size() > width) {
            out += '\n';
            line = 0;
        } else if (line > 0) {
            out += ' ';
            ++line;
        }
        out += word;
        line += word.size();
        start = end + 1;
    }
    return out;
}

}  // namespace polyroll::app
