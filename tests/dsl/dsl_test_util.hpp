// SPDX-License-Identifier: MIT
#pragma once
// Helpers for the scene-language tests: parse text while collecting warnings, catch the located
// error of bad input, and write scratch files for #include tests.

#include <catch2/catch.hpp>

#include <photon/dsl/dsl.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <unistd.h>

namespace dsl_test {

namespace dsl = photon::dsl;

struct Parsed {
    dsl::SceneDescription desc;
    std::vector<dsl::Diagnostic> warnings;
};

inline dsl::DiagnosticSink collect(std::vector<dsl::Diagnostic>& into) {
    return [&into](const dsl::Diagnostic& d) { into.push_back(d); };
}

inline Parsed parse(const std::string& text, dsl::ParseOptions options = {}) {
    Parsed p;
    options.diagnostics = collect(p.warnings);
    p.desc = dsl::parse_string(text, "test.pov", options);
    return p;
}

/// Messages of the warnings, for Catch's Contains/Equals.
inline std::string all_messages(const std::vector<dsl::Diagnostic>& ds) {
    std::string s;
    for (const auto& d : ds) s += d.message + "\n";
    return s;
}

/// The warnings of `kind`, as "line:column keyword".
inline std::vector<std::string> places(const std::vector<dsl::Diagnostic>& ws, const std::string& kind) {
    std::vector<std::string> out;
    for (const auto& w : ws)
        if (w.kind == kind)
            out.push_back(std::to_string(w.location.line) + ":" + std::to_string(w.location.column) + " " + w.keyword);
    return out;
}

/// The error a bad input raises, as "line:column: message" (empty when it parses and builds).
inline std::string error_of(const std::string& text, dsl::ParseOptions options = {}) {
    try {
        const auto desc = dsl::parse_string(text, "test.pov", options);
        (void)dsl::build<float>(desc);
    } catch (const dsl::Error& e) {
        return std::to_string(e.location().line) + ":" + std::to_string(e.location().column) + ": " + e.message();
    }
    return {};
}

/// A fresh directory for scratch files, removed at the end of the test.
class ScratchDir {
public:
    ScratchDir() {
        static int counter = 0;
        path_ = std::filesystem::temp_directory_path() /
                ("photon-dsl-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
        std::filesystem::create_directories(path_);
    }
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(path_, ec);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;

    std::filesystem::path write(const std::string& name, const std::string& text) const {
        const auto p = path_ / name;
        std::filesystem::create_directories(p.parent_path());
        std::ofstream(p, std::ios::binary) << text;
        return p;
    }
    [[nodiscard]] const std::filesystem::path& path() const noexcept { return path_; }

private:
    std::filesystem::path path_;
};

/// A camera and a light, so that small test scenes build without the "no camera / no light" warnings.
inline const char* const stage =
    "camera { location <0, 0, -5> look_at 0 }\n"
    "light_source { <0, 5, 0>, rgb 1 fade_distance 1 fade_power 2 }\n";

/// A scene built from `stage_text` (default `stage`) followed by `text`, in double, with the
/// warnings of both steps.
struct StagedScene {
    dsl::SceneDescription desc;
    std::vector<dsl::Diagnostic> warnings;
    photon::DefaultScene<double> scene;
};
inline StagedScene build_staged(const std::string& text, const dsl::ParseOptions& options = {},
                                const char* stage_text = stage) {
    StagedScene b;
    dsl::ParseOptions po = options;
    po.diagnostics = collect(b.warnings);
    b.desc = dsl::parse_string(std::string(stage_text) + text, "test.pov", po);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(b.warnings);
    b.scene = std::move(dsl::build<double>(b.desc, bo).scene);
    return b;
}

/// The one object of a scene of one shape.
template <class Shape> const Shape& only(const StagedScene& b) {
    REQUIRE(b.scene.objects().size() == 1);
    const auto* s = std::get_if<Shape>(&b.scene.objects()[0].shape);
    REQUIRE(s != nullptr);
    return *s;
}

/// The first hit of the ray from `from` along `dir`, if any.
inline std::optional<photon::Hit<double>> shoot(const StagedScene& b, photon::Vec3<double> from,
                                                photon::Vec3<double> dir) {
    photon::Ray<double> r;
    r.origin = from;
    r.direction = dir;
    const auto hit = b.scene.intersect(r);
    return hit ? std::optional<photon::Hit<double>>(hit->hit) : std::nullopt;
}

/// The scene built in double from `text`, its warnings collected into `warnings` when given,
/// with the command line's `overrides`.
inline dsl::BuiltScene<double> built(const std::string& text, std::vector<dsl::Diagnostic>* warnings = nullptr,
                                     dsl::SettingsOverrides overrides = {}) {
    std::vector<dsl::Diagnostic> local;
    auto& w = warnings ? *warnings : local;
    dsl::ParseOptions po;
    po.diagnostics = collect(w);
    const auto desc = dsl::parse_string(text, "test.pov", po);
    dsl::BuildOptions bo;
    bo.diagnostics = collect(w);
    bo.overrides = overrides;
    return dsl::build<double>(desc, bo);
}

}  // namespace dsl_test
