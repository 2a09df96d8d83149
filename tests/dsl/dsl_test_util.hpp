// SPDX-License-Identifier: MIT
#pragma once
// Helpers for the scene-language tests: parse text while collecting warnings, catch the located
// error of bad input, and write scratch files for #include tests.

#include <photon/dsl/dsl.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
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

}  // namespace dsl_test
