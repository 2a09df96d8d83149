// SPDX-License-Identifier: MIT
// Expressions beyond arithmetic: strings and their functions, rand/seed with POV-Ray's generator,
// the animation clock, the float and vector built-ins, inside() and user functions. The
// expected values were printed by POV-Ray 3.7.0 itself (`#debug` of the same expression in a 1x1
// render, `povray +W1 +H1 -D`), unless a comment says otherwise.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

#include <fstream>
#include <iterator>
#include <map>
#include <optional>

using namespace dsl_test;
using Catch::Matchers::Contains;

namespace {

/// The texts of the `#warning` messages the scene prints, one per line.
std::string printed(const std::string& text, dsl::ParseOptions options = {}) {
    const Parsed p = parse(text + "\nsphere { 0, 1 }\n", std::move(options));
    std::string out;
    for (const auto& d : p.warnings)
        if (d.message.rfind("#warning: ", 0) == 0) out += d.message.substr(10) + "\n";
    return out;
}

/// The string expression's value, as `#warning` prints it.
std::string string_of(const std::string& expr, dsl::ParseOptions options = {}) {
    std::string s = printed("#warning " + expr + "\n", std::move(options));
    if (!s.empty()) s.pop_back();
    return s;
}

/// The value of the float expression `expr`, after the declarations in `before`.
double value_of(const std::string& expr, const std::string& before = {}, dsl::ParseOptions options = {}) {
    const Parsed p = parse(before + "\n#declare V_ = " + expr + ";\nsphere { 0, 1 translate V_*x }\n", std::move(options));
    return p.desc.objects.at(0).transform.translation.x;
}

dsl::Vector3 vector_of(const std::string& expr, const std::string& before = {}) {
    const Parsed p = parse(before + "\n#declare V_ = " + expr + ";\nsphere { 0, 1 translate V_ }\n");
    return p.desc.objects.at(0).transform.translation;
}

}  // namespace

TEST_CASE("string literals, declared strings and concat", "[dsl][strings]") {
    CHECK(printed("#declare A = \"Hello\";\n#warning concat(\"[\", A, \"|\", concat(\"a\", \"b\", \"c\"), \"]\")") ==
          "[Hello|abc]\n");
    CHECK(printed("#declare A = concat(\"x\", \"y\");\n#declare B = A;\n#local C = strupr(B);\n#warning C") == "XY\n");
    // A message may be any string expression, as may #error's.
    CHECK(error_of("#error concat(\"stop at \", str(3, 0, 0))\n") == "1:1: #error: stop at 3");
}

TEST_CASE("str and vstr format as POV-Ray's printf does", "[dsl][strings]") {
    CHECK(string_of("str(3.14159, 0, 2)") == "3.14");
    CHECK(string_of("str(3.14159, 8, 3)") == "   3.142");
    CHECK(string_of("str(-2.5, -8, 1)") == "-00002.5");
    CHECK(string_of("str(7, 0, 0)") == "7");
    CHECK(string_of("str(1/3, 0, -1)") == "0.333333");
    CHECK(string_of("str(123456789.123, 0, -2)") == "123456789.123000");
    CHECK(string_of("str(1e300, 0, 2)") == "1e+300");  // %f would pass 255 characters: %g
    CHECK(string_of("str(7, -3, 0)") == "007");
    CHECK(string_of("str(1, 0, 20)") == "1.00000000000000000000");
    CHECK(string_of("str(0.5, 0, 0)") == "0");
    CHECK(string_of("str(1.5, 0, 0)") == "2");
    CHECK(string_of("str(-7.5, 0, 0)") == "-8");
    CHECK(string_of("str(2.5, 0, 0)") == "2");
    CHECK(string_of("vstr(3, <1, 2, 3>, \", \", 0, 1)") == "1.0, 2.0, 3.0");
    CHECK(string_of("vstr(2, <1, 2, 3>, \"/\", 3, 0)") == "  1/  2");
    CHECK(string_of("vstr(5, <1, 2, 3>, \",\", 0, 2)") == "1.00,2.00,3.00,0.00,0.00");
    CHECK(string_of("vstr(4, 7, \" \", 0, 0)") == "7 0 0 0");
}

TEST_CASE("chr, substr, strupr, strlwr, datetime", "[dsl][strings]") {
    CHECK(string_of("concat(chr(65), chr(97))") == "Aa");
    CHECK(string_of("substr(\"abcdef\", 2, 3)") == "bcd");
    CHECK(string_of("concat(\"[\", substr(\"abc\", 1, 0), \"]\")") == "[]");
    CHECK(string_of("substr(\"abc\", 3, 1)") == "c");
    CHECK(string_of("strupr(\"MiXed 1\")") == "MIXED 1");
    CHECK(string_of("strlwr(\"MiXed 1\")") == "mixed 1");
    CHECK(string_of("datetime(0)") == "2000-01-01 00:00:00Z");
    CHECK(string_of("datetime(1.5, \"%Y/%m/%d %H\")") == "2000/01/02 12");
    CHECK(error_of("#declare S = substr(\"abc\", 3, 2);") ==
          "1:28: `substr`: characters 3 to 4 are not in a string of 3");
    CHECK(error_of("#declare S = chr(-1);") == "1:18: `chr` takes a character code from 0 to 65535, found -1");
    CHECK(error_of("#declare S = datetime(0, \"\");") == "1:26: `datetime`: empty format string");
}

TEST_CASE("float functions of strings: strlen, val, asc, strcmp, file_exists", "[dsl][strings]") {
    CHECK(value_of("strlen(\"hello\")") == 5);
    CHECK(value_of("strlen(\"\")") == 0);
    CHECK(value_of("val(\"3.5e2x\")") == 350);
    CHECK(value_of("val(\"abc\")") == 0);
    CHECK(value_of("val(\"  -12\")") == -12);
    CHECK(value_of("val(\"0x10\")") == 16);
    CHECK(value_of("asc(\"A\")") == 65);
    CHECK(value_of("asc(\"\")") == 0);
    // POV-Ray's strcmp is the difference of the first characters that differ.
    CHECK(value_of("strcmp(\"abc\", \"abd\")") == -1);
    CHECK(value_of("strcmp(\"b\", \"a\")") == 1);
    CHECK(value_of("strcmp(\"abc\", \"abc\")") == 0);
    CHECK(value_of("strcmp(\"a\", \"abc\")") == -98);
    CHECK(value_of("strcmp(\"Z\", \"a\")") == -7);
    CHECK(error_of("#declare N = strlen(3);") == "1:21: expected a string as argument 1 of `strlen`, found the number 3");
    CHECK(error_of("#declare N = val(\"1e400\");") == "1:18: `val(\"1e400\")` is not a finite number");

    dsl::ParseOptions sandbox;
    sandbox.read_include = [](const std::string& name) -> std::optional<std::string> {
        if (name == "here.inc") return std::string("#declare Here = 1;\n");
        return std::nullopt;
    };
    CHECK(value_of("file_exists(\"here.inc\") * 10 + file_exists(\"absent.inc\")", {}, sandbox) == 10);
    ScratchDir dir;
    const auto scene = dir.write("scene.pov", "#declare E = file_exists(concat(\"pa\", \"rt.inc\")) + 2 * file_exists(\"no.inc\");\n"
                                              "#include concat(\"pa\", \"rt\", \".inc\")\n"
                                              "sphere { 0, 1 translate <E, Part, 0> }\n");
    dir.write("part.inc", "#declare Part = 5;\n");
    const auto desc = dsl::parse_file(scene);
    CHECK(desc.objects.at(0).transform.translation == dsl::Vector3(1, 5, 0));
}

TEST_CASE("seed and rand give POV-Ray's sequences", "[dsl][rand]") {
    const std::string five = "concat(str(rand(S), 0, 10), \" \", str(rand(S), 0, 10), \" \", str(rand(S), 0, 10), \" \", "
                             "str(rand(S), 0, 10), \" \", str(rand(S), 0, 10))";
    CHECK(printed("#declare S = seed(2026);\n#warning " + five) ==
          "0.9517446486 0.1160864271 0.7385192834 0.9338543580 0.5449317600\n");
    CHECK(printed("#declare S = seed(123);\n#warning " + five).substr(0, 38) == "0.9047729822 0.9951378689 0.5186665930");
    // Seeds are truncated to an int (negative ones wrap; out of range is INT_MIN, as on x86-64).
    auto two = [](const std::string& seed) {
        return printed("#declare S = seed(" + seed + ");\n#warning concat(str(rand(S), 0, 10), \" \", str(rand(S), 0, 10))");
    };
    CHECK(two("0") == "0.0000028743 0.4665636845\n");
    CHECK(two("-5") == "0.8900528701 0.3637761160\n");
    CHECK(two("1.7") == "0.4219928753 0.4871211982\n");
    CHECK(two("4294967296 + 7") == "0.5000028744 0.9665636846\n");
    // Streams are numbered in the order they are made and advance independently.
    CHECK(printed("#declare S = seed(2026);\n#declare Skip = " + five + ";\n#declare T = seed(7);\n"
                  "#warning concat(str(rand(T), 0, 10), \" \", str(rand(S), 0, 10), \" \", str(T, 0, 0), str(S, 0, 0))") ==
          "0.9539328806 0.1225994258 10\n");
    CHECK(error_of("#declare R = rand(0);") ==
          "1:19: `rand` of 0: no such random stream (0 made by `seed` so far; write `#declare S = seed(N);` and "
          "`rand(S)`)");
}

TEST_CASE("the animation clock is POV-Ray's still image by default, or the caller's", "[dsl][clock]") {
    for (const char* id : {"clock", "clock_on", "clock_delta", "initial_clock", "final_clock", "frame_number",
                           "initial_frame", "final_frame"})
        CHECK(value_of(id) == 0);
    dsl::ParseOptions o;
    o.animation = {0.25, 0.05, 0, 1, 6, 1, 21, true};
    CHECK(value_of("clock", {}, o) == 0.25);
    CHECK(value_of("clock_delta", {}, o) == 0.05);
    CHECK(value_of("final_clock", {}, o) == 1);
    CHECK(value_of("frame_number", {}, o) == 6);
    CHECK(value_of("final_frame", {}, o) == 21);
    CHECK(value_of("clock_on", {}, o) == 1);
}

TEST_CASE("float built-ins POV-Ray 3.7 has beyond the basic ones", "[dsl][builtins]") {
    CHECK(value_of("acosh(2)") == Approx(1.3169578969).margin(1e-10));
    CHECK(value_of("asinh(1)") == Approx(0.8813735870).margin(1e-10));
    CHECK(value_of("atanh(0.5)") == Approx(0.5493061443).margin(1e-10));
    CHECK(value_of("bitwise_and(12, 10)") == 8);
    CHECK(value_of("bitwise_or(12, 10)") == 14);
    CHECK(value_of("bitwise_xor(12, 10)") == 6);
    CHECK(value_of("bitwise_and(12.7, 10.2, 15)") == 8);
    CHECK(value_of("bitwise_and(-1, 255)") == 255);
    CHECK(value_of("bitwise_or(3.9e9, 0)") == -2147483648.0);
    CHECK(value_of("bitwise_xor(5.9, 1)") == 4);
    CHECK(value_of("mod(-7, 3)") == -1);
    CHECK(value_of("div(-7, 2)") == -3);
    CHECK(value_of("int(-2.5)") == -2);
    CHECK(value_of("min(3, 1, 2) * 10 + max(3, 1, 2)") == 13);
    CHECK(error_of("#declare A = acosh(0.5);") == "1:14: the result of `acosh` is not a finite number");
    CHECK(error_of("#declare A = asin(2);") == "1:14: the result of `asin` is not a finite number");
    CHECK(error_of("#declare A = mod(1, 0);") == "1:21: division by zero in `mod`");
    CHECK(error_of("#declare A = bitwise_and(1);") == "1:14: `bitwise_and` takes at least 2 arguments, found 1");
}

TEST_CASE("vector built-ins: vaxis_rotate: vturbulence is a clear error", "[dsl][builtins]") {
    const auto a = vector_of("vaxis_rotate(<1, 0, 0>, <0, 0, 1>, 90)");
    CHECK(a.x == Approx(0).margin(1e-12));
    CHECK(a.y == Approx(1));
    CHECK(a.z == Approx(0).margin(1e-12));
    const auto b = vector_of("vaxis_rotate(<1, 2, 3>, <1, 1, 0>, 30)");
    CHECK(b.x == Approx(2.12764747).margin(1e-8));
    CHECK(b.y == Approx(0.87235253).margin(1e-8));
    CHECK(b.z == Approx(2.95162960).margin(1e-8));
    CHECK(error_of("#declare A = vaxis_rotate(x, 0, 30);") == "1:30: `vaxis_rotate` about a zero vector");
    CHECK_THAT(error_of("#declare A = vturbulence(2, 0.5, 6, <1, 2, 3>);"),
               Contains("1:14: `vturbulence` is not supported by photon's scene language"));
}

TEST_CASE("inside of declared objects", "[dsl][builtins]") {
    const std::string objects = "#declare P = plane { y, 1 }\n"
                                "#declare S = sphere { <1,2,3>, 2 scale 2 rotate 30*z }\n"
                                "#declare B = box { <0,0,0>, <1,2,3> rotate 45*y translate x }\n"
                                "#declare U = union { object { S } object { B } }\n";
    // POV-Ray prints 1010111 for these seven.
    CHECK(value_of("inside(P, <0,0.5,0>)*1e6 + inside(P, <0,1.5,0>)*1e5 + inside(S, <2,4,6>)*1e4 + inside(S, 0)*1e3 + "
                   "inside(B, <1.1,1,0.1>)*100 + inside(U, <1.1,1,0.1>)*10 + inside(B, <1,0,0>)",
                   objects) == 1010111);
    CHECK(error_of("#declare N = 3;\n#declare A = inside(N, 0);") ==
          "2:21: expected an object identifier as the first argument of `inside`, found `N`");
}

TEST_CASE("user functions: parameters, built-ins, sum/prod, calls of other functions", "[dsl][functions]") {
    const std::string fns = "#declare F = function(a, b) { a*b + select(a-1, 10, 20, 30) }\n"
                            "#declare G = function { x + 2*y - z/4 + u }\n"
                            "#declare H = function(k) { sum(i, 1, k, i*i) + prod(j, 1, 4, j) }\n"
                            "#declare K = function(a) { F(a, 2) + G(a, 0, 4) + (a > 1)*100 + abs(-a) + min(a, 0.5) + mod(a, 2) }\n"
                            "#declare Cst = 7;\n"
                            "#declare L = function { Cst * x + pi }\n"
                            "#declare Cst = 8;\n"  // the body took the value 7 when it was declared
                            "#declare PF = function { pigment { rgb <0.25, 0.5, 0.75> } }\n"
                            "#declare TF = function { transform { rotate 90*z translate <1,0,0> } }\n"
                            "#declare M = function { PF(x,y,z).green + TF(x,y,z).y }\n";
    CHECK(value_of("F(2, 3)", fns) == 36);
    CHECK(value_of("F(1, 3)", fns) == 23);
    CHECK(value_of("F(0, 3)", fns) == 10);
    CHECK(value_of("G(1, 2, 4)", fns) == 5);  // u is x in a function of x, y, z
    CHECK(value_of("H(3)", fns) == 38);
    CHECK(value_of("K(3)", fns) == 145.5);
    CHECK(value_of("L(2, 0, 0)", fns) == Approx(17.141593).margin(1e-6));
    CHECK(value_of("M(1, 0, 0)", fns) == Approx(1.5));
    const auto moved = vector_of("TF(1, 0, 0)", fns);
    CHECK(moved.x == Approx(1));
    CHECK(moved.y == Approx(1));
    CHECK(moved.z == Approx(0).margin(1e-12));
    // A call is an expression like any other, in a vector or a condition.
    CHECK(value_of("<F(2, 3), 0, 0>.x + (G(1, 1, 0) > 3 ? 1 : 0)", fns) == 37);
}

TEST_CASE("the standard includes' functions read: math.inc and functions.inc", "[dsl][functions]") {
    // The declarations of math.inc's functions, as written there.
    const std::string math = "#declare sind = function (x) {sin(radians(x))}\n"
                             "#declare even = function(x) {select(mod(x, 2), 0, 1, 0)}\n"
                             "#declare clip = function (x, y, z) {min(z, max(x, y))}\n"
                             "#declare f_sphere = function { internal(61) }\n";
    CHECK(value_of("sind(30)", math) == Approx(0.5));
    CHECK(value_of("even(4) * 10 + even(3)", math) == 10);
    CHECK(value_of("clip(5, 0, 2)", math) == 2);
    CHECK(error_of(math + "#declare A = f_sphere(1, 2, 3, 1);") ==
          "5:14: `f_sphere` is POV-Ray's internal function 61 (declared at test.pov:4:21), which photon does not "
          "evaluate");
    CHECK(error_of("#declare P = function { pattern { checker scale 2 } }\n#declare A = P(1, 2, 3);") ==
          "2:14: `P` is a pattern function (declared at test.pov:1:14): photon reads patterns but does not evaluate them");
}

TEST_CASE("user function errors are located", "[dsl][functions]") {
    CHECK(error_of("#declare F = function(a) { 1 / a }\n#declare A = F(0);") ==
          "1:30: division by zero (in the call of `F` at test.pov:2:14)");
    CHECK(error_of("#declare F = function(a, b) { a + b }\n#declare A = F(1);") ==
          "2:14: `F` takes 2 arguments (a, b), found 1");
    CHECK(error_of("#declare F = function(a) { a + q }") ==
          "1:32: undefined identifier `q` in the function body (its parameters: a)");
    CHECK(error_of("#declare F = function(a) { x }") == "1:28: `x` is not a parameter of this function (its parameters: a)");
    CHECK(error_of("#declare F = function(a, a) { a }") == "1:26: parameter `a` is named twice");
    CHECK(error_of("#declare F = function { vlength(x) }") ==
          "1:25: `vlength` cannot be used in a function body: POV-Ray's functions take numbers only");
    CHECK(error_of("#declare F = function { sqrt(x) }\n#declare A = F(-1, 0, 0);") ==
          "1:25: the result of `sqrt` is not a finite number (in the call of `F` at test.pov:2:14)");
    CHECK(error_of("#declare F = function { internal(0) + 1 }") == "1:37: expected an operator or `}` to close `function` (opened at 1:14), found `+`");
    // Bounded: a body as deep as it is long, calls that multiply the work.
    std::string chain = "#declare F = function { 1";
    for (int i = 0; i < 300; ++i) chain += "+1";
    CHECK_THAT(error_of(chain + " }"), Contains("function body too deep"));
    std::string doubling = "#declare F0 = function { x }\n";
    for (int i = 1; i <= 40; ++i)
        doubling += "#declare F" + std::to_string(i) + " = function { F" + std::to_string(i - 1) + "(x,y,z) + F" +
                    std::to_string(i - 1) + "(x,y,z) }\n";
    dsl::ParseOptions small;
    small.max_tokens = 100000;
    CHECK_THAT(error_of(doubling + "#declare A = F25(1, 0, 0);", small), Contains("function evaluation too long"));
    CHECK_THAT(error_of(doubling + "#declare A = F40(1, 0, 0);"), Contains("functions call each other too deeply"));
    CHECK_THAT(error_of("#declare F = function { sum(i, 0, 1e300, i) }\n#declare A = F(0, 0, 0);", small),
               Contains("function evaluation too long"));
}

TEST_CASE("the fuzz seeds of strings and functions read as scenes", "[dsl][functions]") {
    dsl::ParseOptions o;
    o.geometry = dsl::library_object_geometry();  // the functions seed asks min_extent and max_extent
    o.read_include = [](const std::string& name) -> std::optional<std::string> {
        if (name == "colors.inc") return std::string("#declare Red = rgb <1, 0, 0>;\n");
        return std::nullopt;
    };
    for (const char* name : {"strings.pov", "functions.pov"}) {
        INFO(name);
        std::ifstream in(std::string(PHOTON_SCENES_DIR) + "/../../fuzz/seeds/" + name, std::ios::binary);
        const std::string text((std::istreambuf_iterator<char>(in)), {});
        REQUIRE(!text.empty());
        CHECK_NOTHROW(parse(text, o));
    }
    // What the strings seed prints: its #warning, evaluated.
    std::ifstream in(std::string(PHOTON_SCENES_DIR) + "/../../fuzz/seeds/strings.pov", std::ios::binary);
    const Parsed p = parse(std::string((std::istreambuf_iterator<char>(in)), {}), o);
    CHECK_THAT(all_messages(p.warnings), Contains("#warning: N = 448.000000 ell"));
}
