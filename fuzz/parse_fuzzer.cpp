// SPDX-License-Identifier: MIT
// libFuzzer target for the scene language: any byte string is read as a scene (lexer, directives,
// expressions, parser), and what parses is built into library objects and exported back to
// POV-Ray's language. Bad input must end in dsl::Error (or std::invalid_argument from the
// library's constructors, which build() turns into dsl::Error); anything else (a crash, a
// sanitizer report, another exception, a hang) is a finding.
//
// `#include` never touches the file system here: ParseOptions::read_include serves a few fixed
// in-memory files (one of which includes another, one includes itself), so the fuzzer explores
// include depth, loops and scopes without reading arbitrary files of the machine.
//
// The limits are the parser's own, scaled down so that one input runs in milliseconds: a limit
// reached is a clean error, and the defaults are the same code with larger numbers.

#include <photon/dsl/dsl.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>

namespace {

std::optional<std::string> read_include(const std::string& name) {
    if (name == "colors.inc") return "#declare Red = rgb <1, 0, 0>;\n#declare White = rgb 1;\n";
    if (name == "nested.inc") return "#include \"colors.inc\"\n#local Depth = 2;\nsphere { 0, 1 pigment { Red } }\n";
    if (name == "self.inc") return "#include \"self.inc\"\n";
    if (name == "broken.inc") return "sphere { <0, 0, 0> 1 pigment { rgb <1, 2 }\n";
    return std::nullopt;
}

photon::dsl::ParseOptions fuzz_options() {
    photon::dsl::ParseOptions o;
    o.read_include = read_include;
    o.image_width = 64;
    o.image_height = 48;
    o.max_file_bytes = 1 << 16;
    o.max_tokens = 200'000;
    o.max_loop_iterations = 2'000;
    o.max_primitives = 2'000;
    o.max_macro_depth = 64;
    o.max_array_elements = 1 << 16;
    o.max_parse_bytes = std::uint64_t(1) << 24;
    o.max_parse_seconds = 5;  // half the run's -timeout: a slow input is a clean error first
    return o;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    namespace dsl = photon::dsl;
    static const dsl::ParseOptions options = fuzz_options();
    std::string text(reinterpret_cast<const char*>(data), size);
    try {
        const dsl::SceneDescription desc = dsl::parse_string(std::move(text), "fuzz.pov", options);
        (void)dsl::export_pov(desc);
        const dsl::BuiltScene<float> built = dsl::build<float>(desc);
        (void)built;
    } catch (const dsl::Error& e) {
        // Every error must say where: a message and, unless the whole file is at fault, a line.
        if (e.message().empty()) std::abort();
    }
    return 0;
}
