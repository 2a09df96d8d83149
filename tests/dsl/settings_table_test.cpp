// SPDX-License-Identifier: MIT
// The settings table (settings_table.hpp) against everything that reads it: every setting with a
// keyword read by the parser, exported by export-pov and read back; every setting with a flag
// read by `photon render`'s options; bounds reported where the value was given; and the table of
// docs/scene-language.md generated from it (PHOTON_UPDATE_DOCS=1 rewrites the block).

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

#include <photon/dsl/settings_table.hpp>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#if defined(PHOTON_HAS_CLI11) && PHOTON_HAS_CLI11
#include "setting_options.hpp"
#endif

using namespace dsl_test;
using Catch::Matchers::Contains;

namespace {

using dsl::RenderSetting;
using dsl::SettingKind;

/// A value of `s` inside its bounds and different from the library's default.
dsl::SettingValue test_value(const RenderSetting& s) {
    const dsl::SettingValue fallback = s.field.get(photon::RenderSettings{});
    if (s.kind == SettingKind::mode) {
        for (const dsl::RenderModeName& m : dsl::render_mode_names)
            if (m.in_scene && dsl::SettingValue(std::string(m.name)) != fallback) return std::string(m.name);
    }
    if (s.kind == SettingKind::text) return std::string("caustics=off,indirect=on");  // the one text setting, effects
    if (s.kind == SettingKind::integer) {
        std::uint64_t v = std::uint64_t(s.lo) + 2;
        if (dsl::SettingValue(v) == fallback) ++v;
        return v;
    }
    double v = s.lo + 0.375;  // exact in float too
    if (v > s.hi) v = 0.5 * (s.lo + s.hi);
    if (dsl::SettingValue(v) == fallback) v += 0.125;
    return v;
}

/// A scene with every table setting that a file can write set to test_value.
std::string scene_with_every_setting() {
    std::string pov, own;
    std::map<std::string, std::string> blocks;
    for (const RenderSetting& s : dsl::render_settings_table) {
        if (s.keyword.empty()) continue;
        const std::string value = dsl::format_setting_value(test_value(s));
        const std::string item = std::string(s.keyword) + " " + (s.kind == SettingKind::text ? '"' + value + '"' : value);
        if (!s.block.empty())
            blocks[std::string(s.block)] += " " + item;
        else
            (s.povray ? pov : own) += "  " + item + "\n";
    }
    for (const auto& [block, items] : blocks) own += "  " + block + " {" + items + " }\n";
    return std::string(stage) + "sphere { 0, 1 finish { ambient 0 } }\nglobal_settings {\n" + pov +
           "}\n#ifdef (photon_version)\nglobal_settings {\n" + own + "}\n#end\n";
}

}  // namespace

TEST_CASE("the settings table names each setting, keyword and flag once", "[dsl][settings][table]") {
    std::set<std::string> keys, flags, items;
    for (const RenderSetting& s : dsl::render_settings_table) {
        INFO(s.key);
        CHECK(keys.insert(std::string(s.key)).second);
        CHECK((!s.keyword.empty() || !s.flag.empty()));
        CHECK(!s.noun.empty());
        CHECK(!s.help.empty());
        if (!s.flag.empty()) CHECK(flags.insert(std::string(s.flag)).second);
        if (!s.keyword.empty()) CHECK(items.insert(std::string(s.block) + "." + std::string(s.keyword)).second);
        CHECK(s.lo <= s.hi);
        // The library's default is a value of the setting.
        CHECK_FALSE(dsl::setting_value_problem(s, s.field.get(photon::RenderSettings{})));
        CHECK(dsl::find_setting(s.key) == &s);
    }
    // The settings without a flag, and without a keyword, are these by choice: a new setting
    // that lacks one fails here until it is given one or added to the list.
    std::set<std::string> no_flag, no_keyword;
    for (const RenderSetting& s : dsl::render_settings_table) {
        if (s.flag.empty()) no_flag.insert(std::string(s.key));
        if (s.keyword.empty()) no_keyword.insert(std::string(s.key));
    }
    CHECK(no_flag == std::set<std::string>{"global_estimate.flatten", "global_estimate.boundary_probes",
                                           "caustic_estimate.flatten", "caustic_estimate.boundary_probes"});
    CHECK(no_keyword == std::set<std::string>{"threads"});
}

TEST_CASE("every setting a file can write is read, built, exported and read back the same",
          "[dsl][settings][table]") {
    const std::string text = scene_with_every_setting();
    INFO(text);
    std::vector<dsl::Diagnostic> warnings;
    dsl::ParseOptions po;
    po.diagnostics = collect(warnings);
    const auto desc = dsl::parse_string(text, "every.pov", po);
    CHECK(warnings.empty());
    const std::string exported = dsl::export_pov(desc);
    INFO(exported);
    const auto again = dsl::parse_string(exported, "exported.pov");
    const auto built = dsl::build<double>(desc);
    const auto rebuilt = dsl::build<double>(again);
    for (const RenderSetting& s : dsl::render_settings_table) {
        if (s.keyword.empty()) continue;
        INFO(s.key);
        const dsl::SettingValue want = test_value(s);
        REQUIRE(desc.settings.render.count(std::string(s.key)) == 1);
        CHECK(desc.settings.render.at(std::string(s.key)).value == want);
        REQUIRE(again.settings.render.count(std::string(s.key)) == 1);
        CHECK(again.settings.render.at(std::string(s.key)).value == want);
        CHECK(s.field.get(built.settings) == want);
        CHECK(s.field.get(rebuilt.settings) == want);
    }
    CHECK(desc.settings.render.size() == again.settings.render.size());
    // POV-Ray's own item is exported where POV-Ray reads it, photon's inside the guard.
    const auto guard = exported.find("#ifdef (photon_version)\nglobal_settings");
    REQUIRE(guard != std::string::npos);
    CHECK(exported.find("max_trace_level") < guard);
    CHECK(exported.find("samples_per_pixel") > guard);
}

TEST_CASE("a file's setting out of its bounds is an error where it is written, naming the bounds",
          "[dsl][settings][table]") {
    for (const RenderSetting& s : dsl::render_settings_table) {
        if (s.keyword.empty()) continue;
        INFO(s.key);
        std::string bad = s.kind == SettingKind::mode      ? "fast"
                          : s.kind == SettingKind::text    ? "\"fast\""
                          : s.kind == SettingKind::integer ? dsl::format_whole(s.hi + 1)
                          : s.hi != dsl::unbounded         ? dsl::format_number(s.hi + 1)
                                                           : dsl::format_number(s.lo - 1);
        const std::string item = std::string(s.keyword) + " " + bad;
        const std::string setting = s.block.empty() ? item : std::string(s.block) + " { " + item + " }";
        const std::string line = "#ifdef (photon_version) global_settings { " + setting + " } #end\n";
        const std::string message = error_of(line + "sphere { 0, 1 }");
        const auto column = line.find(bad) + 1;
        CHECK_THAT(message, Contains("1:" + std::to_string(column) + ": "));
        if (s.kind == SettingKind::mode)
            CHECK_THAT(message, Contains("`rt`, `pm`, `pm_direct` or `sppm`"));
        else if (s.kind == SettingKind::integer)
            CHECK_THAT(message, Contains("from " + dsl::format_whole(s.lo) + " to " + dsl::format_whole(s.hi)));
        else
            CHECK_THAT(message, Contains("must be"));
    }
}

TEST_CASE("an override out of its bounds names its option and the bounds", "[dsl][settings][table]") {
    const auto desc = dsl::parse_string(std::string(stage) + "sphere { 0, 1 }\n", "test.pov");
    for (const RenderSetting& s : dsl::render_settings_table) {
        INFO(s.key);
        const dsl::SettingValue bad = s.kind == SettingKind::mode || s.kind == SettingKind::text
                                          ? dsl::SettingValue(std::string("fast"))
                                      : s.kind == SettingKind::integer ? dsl::SettingValue(std::uint64_t(s.hi) + 1)
                                      : s.hi != dsl::unbounded         ? dsl::SettingValue(s.hi + 1)
                                                                       : dsl::SettingValue(s.lo - 1);
        dsl::BuildOptions bo;
        bo.overrides[std::string(s.key)] = bad;
        const std::string from(s.flag.empty() ? s.key : s.flag);
        CHECK_THROWS_WITH(dsl::build<float>(desc, bo), Contains(from + ": " + std::string(s.noun) + " must be"));
    }
    dsl::BuildOptions typo;
    typo.overrides["samples_per_pixle"] = 4u;
    CHECK_THROWS_WITH(dsl::build<float>(desc, typo), Contains("no render setting is called `samples_per_pixle`"));
}

#if defined(PHOTON_HAS_CLI11) && PHOTON_HAS_CLI11
TEST_CASE("every setting with a flag is a `photon render` option setting the same field", "[dsl][settings][cli]") {
    photon::cli::SettingOptions options;
    CLI::App app;
    options.add_to(app);
    std::vector<std::string> args;
    for (const RenderSetting& s : dsl::render_settings_table) {
        if (s.flag.empty()) continue;
        args.emplace_back(s.flag);
        args.push_back(dsl::format_setting_value(test_value(s)));
    }
    std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
    app.parse(reversed);
    const dsl::SettingsOverrides o = options.overrides();
    const auto desc = dsl::parse_string(std::string(stage) + "sphere { 0, 1 finish { ambient 0 } }\n", "test.pov");
    dsl::BuildOptions bo;
    bo.overrides = o;
    const auto built = dsl::build<float>(desc, bo);
    for (const RenderSetting& s : dsl::render_settings_table) {
        if (s.flag.empty()) continue;
        INFO(s.flag);
        REQUIRE(o.count(std::string(s.key)) == 1);
        CHECK(o.at(std::string(s.key)) == test_value(s));
        CHECK(s.field.get(built.settings) == test_value(s));
        CHECK(app.get_option(std::string(s.flag))->get_description() == s.help);
    }
    CHECK(o.size() == args.size() / 2);
    // Every mode name is a value of --mode, and pm-direct is pm_direct.
    for (const dsl::RenderModeName& m : dsl::render_mode_names) {
        photon::cli::SettingOptions one;
        CLI::App a;
        one.add_to(a);
        a.parse(std::vector<std::string>{std::string(m.name), "--mode"});
        dsl::BuildOptions b;
        b.overrides = one.overrides();
        CHECK(dsl::build<float>(desc, b).settings.mode == m.mode);
    }
}
#endif

namespace {

std::string escape_bars(std::string_view text) {
    std::string s;
    for (const char c : text) s += c == '|' ? std::string("\\|") : std::string(1, c);
    return s;
}

/// The table of docs/scene-language.md, from the settings table.
std::string docs_table() {
    std::ostringstream o;
    o << "| in the scene file | command line | RenderSettings | library default | `photon render` default | values | what it sets |\n"
      << "|---|---|---|---|---|---|---|\n";
    for (const RenderSetting& s : dsl::render_settings_table) {
        std::string names, scene_names;
        for (const dsl::RenderModeName& m : dsl::render_mode_names) {
            names.append(names.empty() ? "" : "|").append(m.name);
            if (m.in_scene && dsl::render_mode_name(m.mode) == m.name)
                scene_names.append(scene_names.empty() ? "" : "|").append(m.name);
        }
        const std::string arg = s.kind == SettingKind::mode   ? scene_names
                                : s.kind == SettingKind::real ? "X"
                                : s.kind == SettingKind::text ? "SPEC"
                                                              : "N";
        std::string item;
        if (!s.keyword.empty()) {
            const std::string written = s.kind == SettingKind::text ? '"' + arg + '"' : arg;
            item = s.block.empty() ? std::string(s.keyword) + " " + written
                                   : std::string(s.block) + " { " + std::string(s.keyword) + " " + arg + " }";
            item = "`" + escape_bars(item) + "` (" + (s.povray ? "POV-Ray" : "photon") + ")";
        }
        const std::string flag =
            s.flag.empty() ? "" : "`" + escape_bars(std::string(s.flag) + " " + (s.kind == SettingKind::mode ? names : arg)) + "`";
        std::string values;
        if (s.kind == SettingKind::mode)
            values = "a mode name";
        else if (s.kind == SettingKind::text)
            values = "EFFECT=on/off/auto, ...";
        else if (s.kind == SettingKind::integer)
            values = dsl::format_whole(s.lo) + " to " + dsl::format_whole(s.hi);
        else if (s.hi != dsl::unbounded)
            values = dsl::format_number(s.lo) + " to " + dsl::format_number(s.hi);
        else
            values = (s.lo_exclusive ? "> " : ">= ") + dsl::format_number(s.lo);
        o << "| " << item << " | " << flag << " | " << s.key << " | "
          << dsl::format_setting_value(s.field.get(photon::RenderSettings{})) << " | "
          << escape_bars(dsl::program_default_text(s)) << " | " << values << " | "
          << escape_bars(s.help) << " |\n";
    }
    return o.str();
}

}  // namespace

TEST_CASE("the settings table of docs/scene-language.md is the settings table", "[dsl][settings][docs]") {
    const std::string path = std::string(PHOTON_DOCS_DIR) + "/scene-language.md";
    std::ifstream in(path, std::ios::binary);
    REQUIRE(in);
    const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string begin_marker = "<!-- settings-table: begin", end_marker = "<!-- settings-table: end -->";
    const auto begin = doc.find(begin_marker);
    REQUIRE(begin != std::string::npos);
    const auto body = doc.find('\n', begin) + 1;
    const auto end = doc.find(end_marker, body);
    REQUIRE(end != std::string::npos);
    const std::string want = docs_table();
    if (doc.substr(body, end - body) != want && std::getenv("PHOTON_UPDATE_DOCS")) {
        std::ofstream(path, std::ios::binary) << doc.substr(0, body) + want + doc.substr(end);
        WARN("rewrote the settings table of " << path);
        return;
    }
    INFO("run this test with PHOTON_UPDATE_DOCS=1 to write the table into " << path);
    CHECK(doc.substr(body, end - body) == want);
}
