// One field table for every surface (issue: the window's flags and the page's address were hand-copied
// from it). The command line, the window's flags and the page's address take the scene fields by the
// names the table gives (a field's flag; the page's key is the flag without its dashes, Python's keyword
// the same with '_' for '-'), and refuse a bad value in the same words: the type read by the core
// (sim/scene/field_text.h), the range, preset and choice by resolving the scene. Only the way the
// value was given differs: "--sides 2.5" on a command line, "sides=2.5" in an address, as Python says.
#include <catch2/catch.hpp>

#include "test_helpers.h"

#include <filesystem>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "app/controls.h"
#include "app/page_settings.h"
#include "app/sandbox_state.h"
#include "sim/errors.h"
#include "sim/scene/field_text.h"
#include "sim/scene/json_path.h"
#include "sim/scene/scene_fields.h"
#include "sim/scene/scene_json.h"

namespace fs = std::filesystem;
using namespace polyroll;
using namespace polyroll::app;

namespace {

const test::Scratch surfaces_scratch("field-surfaces-");

template <class Parse>
std::string refusal_of(Parse parse) {
    try {
        parse();
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

// What the command line says, without the program's name before it and the pointer to --help after.
std::string cli_refusal(const std::string& flag, const std::string& value, const fs::path& out) {
    const test::CommandResult r = test::run_polyroll(fmt::format("run {} '{}' --out {}", flag, value, out.string()));
    INFO(r.out);
    CHECK(r.exit_code == 2);
    std::string line = r.out.substr(0, r.out.find('\n'));
    const std::string name = "polyroll: ", help = " (see polyroll run --help)";
    if (line.rfind(name, 0) == 0) line.erase(0, name.size());
    if (line.size() >= help.size() && line.compare(line.size() - help.size(), help.size(), help) == 0)
        line.erase(line.size() - help.size());
    return line;
}

// The window's words with the setting named as the page names it: "--sides 2.5: ..." -> "sides=2.5: ...",
// "(from --sides)" -> "(from sides=2)", "--material: ..." -> "material=sand: ...".
std::string as_page_says(std::string text, const std::string& key, const std::string& value) {
    const std::string flag = "--" + key, page = key + "=" + value;
    for (const std::string& said : {flag + " " + value + ":", flag + ":"})
        if (text.rfind(said, 0) == 0) return page + ":" + text.substr(said.size());
    const std::string from = "(from " + flag + ")";
    if (const auto at = text.find(from); at != std::string::npos) text.replace(at, from.size(), "(from " + page + ")");
    return text;
}

// Bad values for a field: one not of its type (numbers) or no name it has (names), one out of its range.
std::vector<std::string> bad_values(const SceneField& f) {
    switch (f.type) {
        case FieldType::integer: return {"2.5", fmt::format("{:g}", f.max + 1)};
        case FieldType::number:
        case FieldType::optional_number: return {"abc", fmt::format("{:g}", f.max + 1)};
        case FieldType::seed: return {"-1", "1e3"};
        case FieldType::preset:
        case FieldType::choice: return {"nonesuch"};
    }
    return {};
}

}  // namespace

TEST_CASE("the window and the page take every scene field with a flag and a panel control, by the flag's name",
          "[app][web][cli]") {
    // Derived from the two tables, not listed here: a field given a flag and a control joins both.
    std::vector<std::string> expected;
    for (const SceneField& f : scene_fields()) {
        bool control = false;
        for (const ControlRow& r : control_rows()) control = control || r.path == f.path;
        if (!f.flag.empty() && control) expected.push_back(field_key(f));
    }
    std::vector<std::string> keys;
    for (const SceneField* f : window_scene_fields()) keys.push_back(field_key(*f));
    CHECK(keys == expected);
    CHECK(keys.size() >= 5);  // n, r, material, theta and the seed at least: what a teacher's link names

    const test::CommandResult help = test::run_polyroll("run --help");
    for (const SceneField* f : window_scene_fields()) {
        const std::string key = field_key(*f);
        INFO(key);
        // The page's keys, the window's flags and the command line's flags are one list.
        CHECK(page_query_keys().find(", " + key + ",") != std::string::npos);
        CHECK(help.out.find("--" + key + " ") != std::string::npos);
        // A value the default scene already has is taken on the page and as a flag, and lands in the
        // selected lane's scene.
        const Scene defaults = resolve_scene({});
        const nlohmann::ordered_json doc = scene_to_json(defaults);
        const nlohmann::ordered_json* value = find_at(doc, f->path);
        REQUIRE(value != nullptr);
        const std::string text = value->is_string() ? value->get<std::string>() : value->dump();
        SandboxState page_state = state_for_preset("default"), flag_state = state_for_preset("default");
        REQUIRE_NOTHROW(apply_page_settings(parse_page_query(key + "=" + text), page_state));
        REQUIRE_NOTHROW(apply_page_settings(parse_window_flags({{key, text}}), flag_state));
        CHECK(f->access.get(scenes_for(page_state).front()) == f->access.get(defaults));
        CHECK(f->access.get(scenes_for(flag_state).front()) == f->access.get(defaults));
    }
}

TEST_CASE("the command line, the window's flags and the page refuse a bad value in the same words",
          "[app][web][cli][bad-input]") {
    const fs::path out = surfaces_scratch("refused");
    for (const SceneField* f : window_scene_fields()) {
        const std::string key = field_key(*f), flag = "--" + key;
        for (const std::string& bad : bad_values(*f)) {
            INFO(flag << " " << bad);
            const std::string cli = cli_refusal(flag, bad, out);
            const std::string window = refusal_of([&] { parse_window_flags({{key, bad}}); });
            const std::string page = refusal_of([&] { parse_page_query(key + "=" + bad); });
            CHECK_FALSE(cli.empty());
            CHECK(window == cli);
            CHECK(page == as_page_says(cli, key, bad));
            CHECK_FALSE(fs::exists(out));
        }
    }
    // Python names a keyword as the page names its key: the same line (tests/python/test_polyroll.py
    // checks run(sides=2) says exactly this).
    CHECK(refusal_of([] { parse_page_query("sides=2"); }) ==
          "shell.sides = 2 (from sides=2) is out of range (allowed: 3 to 64)");
}
