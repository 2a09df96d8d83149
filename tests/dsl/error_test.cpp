// SPDX-License-Identifier: MIT
// Bad input: every class of error with its exact message and line:column, the printed form
// (source line and caret), and the bounds that keep any input from crashing or hanging the parser.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

#include <fstream>
#include <iterator>
#include <optional>
#include <random>

using namespace dsl_test;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

TEST_CASE("an error prints file:line:column, the message, the source line and a caret", "[dsl][errors]") {
    try {
        (void)dsl::parse_string("camera { location -3 look_at 0 }\nsphere { <0,0,0>, -1 }\n", "scene.pov");
        FAIL("no error");
    } catch (const dsl::Error& e) {
        CHECK(std::string(e.what()) ==
              "scene.pov:2:19: error: sphere radius must be positive, found -1\n"
              "  sphere { <0,0,0>, -1 }\n"
              "                    ^");
        CHECK(e.location().file_name() == "scene.pov");
    }
    try {  // tabs are kept in the caret line so that it lines up
        (void)dsl::parse_string("\tsphere {\t0, -2 }", "tab.pov");
        FAIL("no error");
    } catch (const dsl::Error& e) {
        CHECK(std::string(e.what()) ==
              "tab.pov:1:14: error: sphere radius must be positive, found -2\n"
              "  \tsphere {\t0, -2 }\n"
              "  \t        \t   ^");
    }
}

TEST_CASE("unknown keywords", "[dsl][errors]") {
    CHECK(error_of("camera { location <0,0,-3> look_at 0 }\nsphre { <0,0,0>, 1 }") ==
          "2:1: expected a statement (camera, light_source, an object, global_settings or a #directive), found `sphre` "
          "(did you mean `sphere`?)");
    CHECK(error_of("sphere { <0,0,0>, 1 pigmnt { rgb 1 } }") ==
          "1:21: expected an object modifier (texture, pigment, finish, interior, photons, translate, rotate, scale, "
          "matrix, no_shadow) or `}` to close `sphere` (opened at 1:1), found `pigmnt` (did you mean `pigment`?)");
    CHECK(error_of("sphere { 0, 1\n  finish { ambiant 0 } }") ==
          "2:12: expected a finish item (ambient, diffuse, brilliance, specular, phong, phong_size, reflection, "
          "conserve_energy, emission) or `}` to close `finish` (opened at 2:3), found `ambiant` (did you mean "
          "`ambient`?)");
    CHECK(error_of("light_source { 0, 1 fade_distanse 1 }") ==
          "1:21: expected a light_source item (spotlight, area_light, fade_distance, fade_power, photons, translate, "
          "...) "
          "or `}` to close `light_source` (opened at 1:1), found `fade_distanse` (did you mean `fade_distance`?)");
    CHECK(error_of("#foo\n") == "1:1: unknown directive `#foo` (did you mean `for`?)");
    CHECK(error_of("#inclde \"x.inc\"\n") == "1:1: unknown directive `#inclde` (did you mean `include`?)");
}

TEST_CASE("missing braces", "[dsl][errors]") {
    CHECK(error_of("sphere { <0,0,0>, 1 pigment { rgb 1 }\n") ==
          "1:38: expected `}` to close `sphere` (opened at 1:1), found end of file");
    CHECK(error_of("sphere { <0,0,0>, 1\n  pigment { rgb 1 \n}") ==
          "3:2: expected `}` to close `sphere` (opened at 1:1), found end of file");
    CHECK(error_of("sphere <0,0,0>, 1 }") == "1:8: expected `{` after `sphere`, found `<`");
    CHECK(error_of("box { 0, 1 } }") ==
          "1:14: expected a statement (camera, light_source, an object, global_settings or a #directive), found `}`");
    CHECK(error_of("sphere { <0, 0, 0, 1 }") == "1:22: expected `,` or `>` in the vector opened at 1:10, found `}`");
    CHECK(error_of("#if (1)\nsphere { 0, 1 }\n") ==
          "2:16: expected `#end` to close the `#if` opened at 1:1, found end of file");
}

TEST_CASE("bad numbers", "[dsl][errors]") {
    CHECK(error_of("sphere { <0,0,0>, 1e }") ==
          "1:19: bad number `1e`: expected digits after the exponent, found a space");
    CHECK(error_of("sphere { <0,0,0>, 1.2.3 }") ==
          "1:19: bad number `1.2.3`: expected an operator, `,` or a space after the number, found `.`");
    CHECK(error_of("sphere { 0, 12abc }") ==
          "1:13: bad number `12abc`: expected an operator, `,` or a space after the number, found `a`");
    CHECK(error_of("sphere { 0, 1e999 }") == "1:13: bad number `1e999`: out of the range of a double");
    CHECK(error_of("sphere { 0, 1 @ }") == "1:15: unexpected character `@`");
    CHECK(error_of("#warning \"open\nsphere { 0, 1 }") ==
          "1:10: unterminated string: expected `\"` before the end of the line, found end of line");
}

TEST_CASE("undefined identifiers", "[dsl][errors]") {
    CHECK(error_of("sphere { <0,0,0>, Radius }") == "1:19: undefined identifier `Radius`");
    CHECK(error_of("#declare Radius = 1;\nsphere { 0, Radus }") ==
          "2:13: undefined identifier `Radus` (did you mean `Radius`?)");
    CHECK(error_of("sphere { 0, 1 texture { Chrome } }") ==
          "1:25: expected `pigment`, `finish` or `normal` or `}` to close "
          "`texture` (opened at 1:15), found `Chrome`");
    CHECK(error_of("object { Thing }") == "1:10: undefined identifier `Thing`");
    CHECK(error_of("#declare A = A + 1;\n") == "1:14: undefined identifier `A`");
}

TEST_CASE("values of the wrong type", "[dsl][errors]") {
    CHECK(error_of("#declare V = <1,2,3>;\nsphere { <0,0,0>, 1 texture { V } }") ==
          "2:31: expected a texture identifier, `pigment` or `finish`, found `V` (a vector, declared at 1:10)");
    CHECK(error_of("#declare T = texture { pigment { rgb 1 } }\nsphere { <0,0,0>, T }") ==
          "2:19: expected the radius of the sphere, found `T` (a texture, declared at 1:10)");
    CHECK(error_of("sphere { 0, <1, 2, 3> }") ==
          "1:13: expected the radius of the sphere (a number), found the vector <1, 2, 3>");
    CHECK(error_of("#declare F = finish { ambient 0 }\nsphere { 0, 1 interior { F } }") ==
          "2:26: expected an interior identifier or `ior`, found `F` (a finish, declared at 1:10)");
    CHECK(error_of("#declare S = sphere { 0, 1 }\nS") ==
          "2:1: expected a statement (camera, light_source, an object, global_settings or a #directive), found `S` "
          "(an object: write `object { S }`)");
    CHECK(error_of("#declare V = <1,2,3>;\nobject { V }") ==
          "2:10: expected an object identifier in `object`, found `V` (a vector)");
    CHECK(error_of("sphere { 0, 1 translate <1, 2, 3, 4, 5> }") ==
          "1:25: expected the translation after `translate` (a vector), found the vector <1, 2, 3, 4, 5>");
}

TEST_CASE("include loops, missing includes and include depth", "[dsl][errors]") {
    ScratchDir dir;
    dir.write("a.inc", "#declare A = 1;\n#include \"b.inc\"\n");
    dir.write("b.inc", "#include \"a.inc\"\n");
    const auto main = dir.write("main.pov", "#include \"a.inc\"\nsphere { 0, 1 }\n");
    try {
        (void)dsl::parse_file(main);
        FAIL("no error");
    } catch (const dsl::Error& e) {
        CHECK(e.location().line == 1);
        CHECK(e.location().column == 10);
        CHECK_THAT(e.location().file_name(), Contains("b.inc"));
        CHECK_THAT(e.message(), StartsWith("include loop: ") && Contains("a.inc includes ") &&
                                    Contains("b.inc includes \"a.inc\" again"));
    }
    const auto self = dir.write("self.pov", "sphere { 0, 1 }\n#include \"self.pov\"\n");
    try {
        (void)dsl::parse_file(self);
        FAIL("no error");
    } catch (const dsl::Error& e) {
        CHECK(e.location().line == 2);
        CHECK_THAT(e.message(), Contains("self.pov includes \"self.pov\" again"));
    }
    const auto missing = dir.write("missing.pov", "sphere { 0, 1 }\n  #include \"nowhere.inc\"\n");
    try {
        (void)dsl::parse_file(missing);
        FAIL("no error");
    } catch (const dsl::Error& e) {
        CHECK(e.location().line == 2);
        CHECK(e.location().column == 12);
        CHECK_THAT(e.message(), StartsWith("cannot find the include file \"nowhere.inc\" (looked in "));
    }
    for (int i = 0; i < 40; ++i)
        dir.write("deep" + std::to_string(i) + ".inc", "#include \"deep" + std::to_string(i + 1) + ".inc\"\n");
    dir.write("deep40.inc", "sphere { 0, 1 }\n");
    const auto deep = dir.write("deep.pov", "#include \"deep0.inc\"\n");
    try {
        (void)dsl::parse_file(deep);
        FAIL("no error");
    } catch (const dsl::Error& e) {
        CHECK(e.message() == "includes nested too deep: more than 32 files open at once");
        CHECK_THAT(e.location().file_name(), Contains("deep30.inc"));
    }
    try {
        (void)dsl::parse_file(dir.path() / "absent.pov");
        FAIL("no error");
    } catch (const dsl::Error& e) {
        CHECK_THAT(std::string(e.what()), Contains("absent.pov: error: cannot open \""));
    }
}

TEST_CASE("unterminated comments and empty files", "[dsl][errors]") {
    CHECK(error_of("sphere { 0, 1 }\n/* open /* nested */\n") ==
          "2:1: unterminated comment: expected `*/` to close the `/*` opened here, found end of file");
    CHECK(error_of("") == "1:1: empty scene file: expected a camera, a light_source or an object, found end of file");
    CHECK(error_of("// nothing\n/* at all */\n") ==
          "1:1: empty scene file: expected a camera, a light_source or an object, found end of file");
    CHECK(error_of("#declare A = 1;\n") ==
          "1:16: nothing to render: expected a light_source or an object, found end of file");
}

TEST_CASE("values out of range", "[dsl][errors]") {
    CHECK(error_of("sphere { <0,0,0>, -1 }") == "1:19: sphere radius must be positive, found -1");
    CHECK(error_of("sphere { <0,0,0>, 0 }") == "1:19: sphere radius must be positive, found 0");
    CHECK(error_of("sphere { <0,0,0>, sqrt(-1) }") == "1:19: the result of `sqrt` is not a finite number");
    CHECK(error_of("sphere { <0,0,0>, 1/0 }") == "1:20: division by zero");
    CHECK(error_of("sphere { <0,0,0>, 1e300*1e300 }") == "1:24: the result of `*` is not a finite number");
    CHECK(error_of("sphere { <0,0,0>, 1 interior { ior 0 } }") == "1:36: ior must be positive, found 0");
    CHECK(error_of("sphere { <0,0,0>, 1 interior { ior -1.5 } }") == "1:36: ior must be positive, found -1.5");
    CHECK(error_of("sphere { 0, 1 finish { diffuse -0.5 } }") == "1:32: `diffuse` must be >= 0, found -0.5");
    CHECK(error_of("sphere { 0, 1 finish { reflection -1 } }") ==
          "1:35: the reflection colour must be >= 0, found the vector <-1, -1, -1>");
    CHECK(error_of("box { 0, 1 scale <1, 0, 1> }") ==
          "1:18: scale by zero would flatten the object: expected non-zero scale factors, found <1, 0, 1>");
    CHECK(error_of("box { 0, 1 matrix <1,0,0, 0,0,0, 0,0,1, 0,0,0> }") ==
          "1:19: the matrix is singular (its 3x3 part has determinant 0)");
    CHECK(error_of("camera { location 0 angle 190 }\nsphere { 0, 1 }") ==
          "1:27: camera `angle` must be below 180 degrees, found 190");
    CHECK(error_of("camera { location 0 look_at 0 }\nsphere { 0, 1 }") == "1:21: camera look_at equals its location");
    CHECK(error_of("light_source { 0, 1 area_light x, z, 0, 3 }") ==
          "1:38: the number of lights along the first axis must be a whole number from 1 to 1024, found 0");
    CHECK(error_of("plane { 0, 1 }") == "1:9: the normal of the plane must not be zero");
    CHECK(error_of("global_settings { max_trace_level 0 }\nsphere { 0, 1 }") ==
          "1:35: `max_trace_level` must be a whole number from 1 to 256, found 0");
    CHECK(error_of("#ifdef (photon_version) global_settings { global_estimate { radius -1 } } #end\nsphere { 0, 1 }") ==
          "1:68: the estimate radius must be >= 0, found -1");
}

TEST_CASE("directives used wrongly", "[dsl][errors]") {
    CHECK(error_of("#declare R = 1\nsphere { 0, R }") == "2:1: expected `;` after the value of `R`, found `sphere`");
    CHECK(error_of("#declare R = 1\n#declare S = 2;\nsphere { 0, R }") ==
          "2:1: expected `;` after the value of `R`, found `#declare`");
    CHECK(error_of("#declare sphere = 1;\n") == "1:10: cannot #declare `sphere`: it is a keyword");
    CHECK(error_of("sphere { 0, 1 }\n#else\n") == "2:1: `#else` without a matching `#if`");
    CHECK(error_of("sphere { 0, 1 }\n#end\n") ==
          "2:1: `#end` without a matching `#if`, `#ifdef`, `#ifndef`, `#while`, `#for`, `#switch` or `#macro`");
    CHECK(error_of("#statistics\n") ==
          "1:1: `#statistics` is not supported by photon's scene language (see docs/scene-language.md)");
    CHECK(error_of("#error \"stop here\"\n") == "1:1: #error: stop here");
    CHECK(error_of("#if 1 sphere { 0, 1 } #end") == "1:5: expected `(` after `#if`, found the number 1");
    CHECK(error_of("#include scene\n") ==
          "1:10: expected a file name in double quotes after `#include`, found `scene`");
}

TEST_CASE("constructs photon reads but cannot render are warnings, errors inside them stay errors",
          "[dsl][errors]") {
    // The warnings themselves: degradation_test.cpp.
    CHECK(error_of("ovus { 1, 0.5 }\nlight_source { 0, 1 }").empty());
    CHECK(error_of("sky_sphere { pigment { rgb 1 } }\nsphere { 0, 1 }").empty());
    CHECK_THAT(error_of("sphere { 0, 1 pigment { checker rgb 1, rgb } }"), Contains("1:44: expected the value of `rgb`, found `}`"));
    CHECK_THAT(error_of("sphere { 0, 1 clipped_by { 1 } }"), Contains("1:28: expected an object or `bounded_by`"));
    CHECK(error_of("sky_sphere { pigment { rgb 1 }") ==
          "1:31: expected `}` to close `sky_sphere` (opened at 1:1), found end of file");
}

TEST_CASE("bounds: nesting, file size, loops, tokens and scene size give errors, not crashes or hangs",
          "[dsl][errors]") {
    const std::string deep = "sphere { 0, " + std::string(300, '(') + "1" + std::string(300, ')') + " }";
    CHECK_THAT(error_of(deep),
               Contains("nesting too deep: more than 128 blocks, objects, parentheses or directives inside each other"));
    std::string unions;
    for (int i = 0; i < 200; ++i) unions += "union { ";
    unions += "sphere { 0, 1 }";
    for (int i = 0; i < 200; ++i) unions += " }";
    CHECK_THAT(error_of(unions), Contains("nesting too deep"));
    CHECK_THAT(error_of("sphere { 0, " + std::string(5000, '-') + "1 }"), Contains("nesting too deep"));

    dsl::ParseOptions small;
    small.max_file_bytes = 100;
    CHECK(error_of("sphere { 0, 1 }" + std::string(200, ' '), small) ==
          "0:0: file too large: 215 bytes, photon reads scene files of at most 100 bytes");

    dsl::ParseOptions loops;
    loops.max_loop_iterations = 1000;
    CHECK(error_of("#declare I = 0;\n#while (I < 10)\n#end\nsphere { 0, 1 }", loops) ==
          "2:1: `#while` loop ran more than 1000 times: is its condition ever false?");

    dsl::ParseOptions tokens;
    tokens.max_tokens = 10'000;
    CHECK_THAT(error_of("#declare I = 0;\n#while (I < 1e9) #declare I = I + 1; #end\n", tokens),
               Contains("the scene is too long: more than 10000 tokens read"));

    // Each declaration doubles the object: 2^40 spheres without the bound, found out at once.
    std::string doubling = "#declare A = sphere { 0, 1 }\n";
    for (int i = 0; i < 40; ++i) doubling += "#declare A = union { object { A } object { A translate x } }\n";
    doubling += "object { A }\n";
    CHECK(error_of(doubling) == "25:35: the scene is too large: more than 10000000 objects and triangles");
}

TEST_CASE("settings bounded by the library are reported where they are written", "[dsl][errors][limits]") {
    const std::string scene = "sphere { 0, 1 }\n#ifdef (photon_version) global_settings { ";
    CHECK(error_of(scene + "samples_per_pixel 4294967295 } #end") ==
          "2:61: `samples_per_pixel` must be a whole number from 1 to 1000000, found 4294967295");
    CHECK(error_of(scene + "shadow_samples 2000000 } #end") ==
          "2:58: `shadow_samples` must be a whole number from 1 to 1000000, found 2000000");
    CHECK(error_of(scene + "max_photon_depth 100000 } #end") ==
          "2:60: `max_photon_depth` must be a whole number from 1 to 10000, found 100000");
    CHECK(error_of(scene + "max_trace_level 257 } #end").empty() == false);
}

TEST_CASE("includes can be served from memory, sandboxed from the file system", "[dsl][errors][limits]") {
    dsl::ParseOptions o;
    o.read_include = [](const std::string& name) -> std::optional<std::string> {
        if (name == "colors.inc") return "#declare Red = rgb <1, 0, 0>;\n";
        if (name == "self.inc") return "#include \"self.inc\"\n";
        if (name == "deep.inc") return "#include \"deeper.inc\"\n";
        if (name == "deeper.inc") return "#include \"deep.inc\"\n";
        if (name == "big.inc") return std::string(200, ' ');
        return std::nullopt;
    };
    const auto q = parse("#include \"colors.inc\"\nsphere { 0, 1 pigment { Red } }\n", o);
    REQUIRE(q.desc.objects.size() == 1);
    CHECK(q.desc.files.size() == 2);
    CHECK(error_of("#include \"self.inc\"\nsphere { 0, 1 }", o) ==
          "1:10: include loop: self.inc includes \"self.inc\" again");
    CHECK_THAT(error_of("#include \"deep.inc\"\nsphere { 0, 1 }", o),
               Contains("include loop: deep.inc includes deeper.inc includes \"deep.inc\" again"));
    // A file of the machine is not found: the reader is the only source.
    CHECK(error_of("#include \"/etc/passwd\"\nsphere { 0, 1 }", o) ==
          "1:10: cannot find the include file \"/etc/passwd\"");
    o.max_file_bytes = 100;
    CHECK(error_of("#include \"big.inc\"\nsphere { 0, 1 }", o) ==
          "1:10: file too large: 200 bytes, photon reads scene files of at most 100 bytes");
}

// Inputs the fuzzer (fuzz/parse_fuzzer.cpp) once crashed on, read with the fuzzer's options.
TEST_CASE("inputs found by the fuzzer end in clear errors", "[dsl][errors][fuzz]") {
    dsl::ParseOptions o;
    o.read_include = [](const std::string&) { return std::nullopt; };
    o.max_tokens = 200'000;
    o.max_loop_iterations = 2'000;
    o.max_primitives = 2'000;
    auto read = [](const char* name) {
        std::ifstream in(std::string(PHOTON_FUZZ_REGRESSIONS_DIR) + "/" + name, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    // The token limit reached inside a #while loop, in global_settings: built with clang 14, the
    // error's location once held a file the parser had already freed (see docs/robustness.md).
    const std::string text = read("token_limit_in_while.pov");
    REQUIRE(text.size() > 100);
    for (const std::uint64_t limit : {100, 200, 1000, 200'000}) {
        o.max_tokens = limit;
        INFO("max_tokens " << limit);
        CHECK_THAT(error_of(text, o), Contains("the scene is too long: more than " + std::to_string(limit)));
    }
    o.max_tokens = 200'000;
    // `#if#end` inside a #while: the #end ran inside the condition of the #if, closed the loop and
    // re-read its condition, one level deeper on the stack per iteration, until the stack overflowed.
    CHECK(error_of(read("directive_in_while_condition.pov"), o) == "4:6: expected `(` after `#if`, found `#end`");
    CHECK(error_of("#declare N = 0;\n#while (N < 3) #if #end\n#end\nsphere { 0, 1 }") ==
          "2:20: expected `(` after `#if`, found `#end`");
    // Directives taking directives as arguments: bounded like any nesting.
    std::string undefs;
    for (int i = 0; i < 5000; ++i) undefs += "#undef ";
    CHECK_THAT(error_of(undefs + "x\nsphere { 0, 1 }"), Contains("nesting too deep: more than 128"));
}

TEST_CASE("warnings go to the diagnostics sink with their locations", "[dsl][errors]") {
    const auto q = parse(
        "smooth_triangle { 0, y, x, y, y, y }\nsphere { 0, 1 normal { facets 0.5 } no_image }\n"
        "#warning \"check this\"\n");
    REQUIRE(q.warnings.size() == 4);
    CHECK(q.warnings[0].message == "`smooth_triangle` normals are ignored: photon shades triangles flat");
    CHECK(q.warnings[1].message ==
          "`normal { facets }` is ignored: photon does not evaluate this pattern (it tilts normals by bumps, "
          "dents, ripples, waves, wrinkles, quilted and the slope of the patterns it evaluates)");
    CHECK(q.warnings[1].location.line == 2);
    CHECK(q.warnings[1].location.column == 24);
    CHECK(q.warnings[2].message == "`no_image` is ignored by photon");
    CHECK(q.warnings[3].message == "#warning: check this");
    CHECK(q.warnings[2].severity == dsl::Severity::warning);
    // The scene's own #warning is a note: it says nothing about what photon renders.
    CHECK(q.warnings[3].severity == dsl::Severity::note);
    CHECK_THAT(dsl::format_diagnostic(q.warnings[3]), StartsWith("test.pov:3:1: note: #warning: check this\n"));
}

TEST_CASE("damaged scene files give a located error or a scene, never anything else", "[dsl][errors]") {
    std::ifstream in(std::string(PHOTON_SCENES_DIR) + "/cornell.pov", std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    REQUIRE(text.size() > 1000);
    auto survives = [](const std::string& t) {
        try {
            const auto desc = dsl::parse_string(t, "damaged.pov");
            dsl::BuildOptions o;
            o.overrides = {{"width", 8u}, {"height", 6u}};
            (void)dsl::build<float>(desc, o);
        } catch (const dsl::Error&) {
        }
    };
    for (std::size_t cut = 0; cut < text.size(); cut += 41) survives(text.substr(0, cut));
    std::mt19937 rng(12345);
    const std::string alphabet = "{}()<>,;=+-*/#\"0123456789.e xyz_abc\n/*";
    for (int round = 0; round < 200; ++round) {
        std::string t = text;
        for (int k = 0; k < 3; ++k) t[rng() % t.size()] = alphabet[rng() % alphabet.size()];
        survives(t);
    }
}

TEST_CASE("a surface that reflects more than it receives is seen as written and passes on less", "[dsl][errors]") {
    const auto built = [](const std::string& global) {
        std::vector<dsl::Diagnostic> w;
        dsl::BuildOptions bo;
        bo.diagnostics = collect(w);
        const auto b = dsl::build<double>(
            dsl::parse_string(global + "camera { location -5 look_at 0 } light_source { 5, rgb 1 }\n"
                              "sphere { <0,0,0>, 1 pigment { rgb 0.8 } finish { ambient 0 diffuse 1 reflection 0.5 } }"),
            bo);
        return std::pair{all_messages(w), b.scene.material_of(0).params()};
    };
    // Without radiosity or photons POV-Ray passes no light on: photon's image is POV-Ray's.
    const auto [quiet, m] = built("");
    CHECK_THAT(quiet, !Contains("reflects more light"));
    CHECK(m.diffuse.x == Approx(0.8 / 1.3));
    CHECK(m.specular.x == Approx(0.5 / 1.3));
    CHECK(m.seen_gain == Approx(1.3));
    // With radiosity POV-Ray passes the excess on too; photon says it does not.
    const auto [warned, mr] = built("global_settings { radiosity { } }\n");
    CHECK_THAT(warned, Contains("diffuse 0.8 + reflection 0.5 + transmission 0 = 1.3 > 1 in the red channel; the "
                                "camera sees it as written, but photon scales the light it passes on by 1/1.3 to "
                                "conserve energy (POV-Ray's radiosity passes all of it on)"));
    CHECK(mr.seen_gain == Approx(1.3));
}
