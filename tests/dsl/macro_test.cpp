// SPDX-License-Identifier: MIT
// The language's control flow and data: #macro (parameters by value and by reference, #local
// scope, recursion and its limit), #switch/#case/#range/#break, #for, arrays, and their errors
// with file:line:column.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

#include <filesystem>
#include <variant>

using namespace dsl_test;
using Catch::Matchers::Contains;

namespace {

/// The values of the float expressions `exprs` after `text` has been read: each becomes the x of
/// a sphere's centre, read back from the scene.
std::vector<double> values(const std::string& text, const std::vector<std::string>& exprs,
                           dsl::ParseOptions options = {}) {
    std::string scene = text + "\n";
    for (const auto& e : exprs) scene += "sphere { <" + e + ", 0, 0>, 1 }\n";
    const Parsed p = parse(scene, options);
    std::vector<double> out;
    for (std::size_t i = p.desc.objects.size() - exprs.size(); i < p.desc.objects.size(); ++i)
        out.push_back(std::get<dsl::SphereShape>(p.desc.objects[i].shape).center.x);
    return out;
}

using V = std::vector<double>;

}  // namespace

TEST_CASE("macro parameters: a bare identifier is passed by reference, anything else by value",
          "[dsl][macro]") {
    const std::string macros = R"(
#macro Set(P, V) #declare P = V; #end
#macro SetLocal(P, V) #local P = V; #end
#declare A = 1; #declare B = 1; #declare C = 1; #declare D = 1;
Set(A, 5)          // by reference: A changes
Set((B), 6)        // an expression: by value, B stays
Set(C + 0, 7)
SetLocal(D, 8)     // #local on a reference parameter also writes through (POV-Ray 3.7)
)";
    CHECK(values(macros, {"A", "B", "C", "D"}) == V{5, 1, 1, 8});
    // A by-value parameter is the macro's own: #declare changes it, not a global of that name.
    CHECK(values("#declare P = 1;\n#macro M(P) #declare P = P + 1; #end\nM(10)", {"P"}) == V{1});
    // References pass through calls: the inner macro changes the outermost caller's identifier.
    CHECK(values("#macro Inner(Q) #declare Q = 42; #end\n#macro Outer(R) Inner(R) #end\n"
                 "#declare X = 0;\nOuter(X)",
                 {"X"}) == V{42});
}

TEST_CASE("macros give any tokens: a float, a vector, an object, a material", "[dsl][macro]") {
    const Parsed p = parse(R"(
#macro Twice(X) (2 * X) #end
#macro Where(X) <X, Twice(X), 0> #end
#macro Ball(R) sphere { Where(1), R } #end
#declare M = material { texture { pigment { rgb <1, 0, 0> } } }
#declare B = Ball(0.5);
object { B material { M } }
Ball(Twice(1.5))
)");
    REQUIRE(p.desc.objects.size() == 2);
    const auto& first = std::get<dsl::SphereShape>(p.desc.objects[0].shape);
    CHECK(first.center.y == 2);
    CHECK(first.radius == 0.5);
    REQUIRE(p.desc.objects[0].texture);
    CHECK(p.desc.objects[0].texture->pigment.color.rgb.x == 1);
    CHECK(std::get<dsl::SphereShape>(p.desc.objects[1].shape).radius == 3);
}

TEST_CASE("#local in a macro is the call's own: #declare makes a global", "[dsl][macro]") {
    CHECK(values(R"(
#declare L = 1;
#macro M() #local L = 100; #declare G = L + 1; #end
M()
)",
                 {"L", "G"}) == V{1, 101});
    CHECK(error_of("#macro M() #local Hidden = 1; #end\nM()\nsphere { 0, Hidden }") ==
          "3:13: undefined identifier `Hidden`");
    // Each call has a new scope, so recursion keeps every level's locals apart.
    CHECK(values(R"(
#macro Fact(N) #local R = 1; #if (N > 1) #local R = N * Fact(N - 1); #end R #end
#declare F = Fact(6);
)",
                 {"F"}) == V{720});
}

TEST_CASE("recursion without end is an error, not a stack overflow", "[dsl][macro]") {
    const std::string err = error_of("#macro Loop(N) Loop(N + 1) #end\nLoop(0)\n");
    CHECK_THAT(err, Contains("macro calls nested too deep: more than 256"));
    CHECK_THAT(err, Contains("in macro `Loop` called at test.pov:1:16"));
    dsl::ParseOptions small;
    small.max_macro_depth = 5;
    CHECK_THAT(error_of("#macro Down(N) #if (N > 0) Down(N - 1) #end #end\nDown(10)\nsphere{0,1}", small),
               Contains("more than 5 running inside each other"));
    CHECK(error_of("#macro Down(N) #if (N > 0) Down(N - 1) #end #end\nDown(4)\nsphere{0,1}", small).empty());
    // Recursion inside expressions nests C++ calls: the nesting bound stops it.
    CHECK_THAT(error_of("#macro F(N) (1 + F(N)) #end\n#declare X = F(1);"), Contains("nesting too deep"));
}

TEST_CASE("an error in a macro body says where the macro was called from", "[dsl][macro]") {
    CHECK(error_of("#macro Bad(R) sphere { 0, R } #end\n\nBad(-1)") ==
          "1:27: sphere radius must be positive, found -1 (in macro `Bad` called at test.pov:3:1)");
    CHECK_THAT(error_of("#macro M(A, B) #end\nM(1)"), Contains("2:4: expected `,` and argument 2 (`B`)"));
    CHECK_THAT(error_of("#macro M(A) #end\nM(1, 2)"), Contains("2:4: expected `)` to close the call"));
    CHECK_THAT(error_of("#macro M(A)\nsphere { 0, 1 }\n"), Contains("expected `#end` to close the `#macro`"));
    CHECK_THAT(error_of("#macro M() #if (1) #end\nM()\nsphere{0,1}"),
               Contains("expected `#end` to close the `#macro` opened at 1:1"));
}

TEST_CASE("macros defined in an include are called from the including file", "[dsl][macro]") {
    ScratchDir dir;
    dir.write("lib.inc", "#macro Scale3(V) (3 * V) #end\n#macro Bad() sphere { 0, -1 } #end\n");
    const auto main = dir.write("main.pov", "#include \"lib.inc\"\nsphere { 0, Scale3(2) }\nBad()\n");
    try {
        (void)dsl::parse_file(main);
        FAIL("no error");
    } catch (const dsl::Error& e) {
        CHECK(e.location().line == 2);
        CHECK(e.location().file_name().find("lib.inc") != std::string::npos);
        CHECK_THAT(e.message(), Contains("in macro `Bad` called at"));
        CHECK_THAT(e.message(), Contains("main.pov:3:1"));
    }
}

TEST_CASE("#switch: #case, #range, fall-through until #break, #else", "[dsl][switch]") {
    const std::string sw = R"(
#macro Pick(X)
  #local R = 0;
  #switch (X)
    #case (1)
      #local R = R + 1;
    #case (2)            // 1 falls through into 2
      #local R = R + 10;
      #break
    #range (3, 5)
      #local R = 100;
      #if (X = 4) #break #end   // #break inside an #if leaves the switch
      #local R = R + 1;
    #else
      #local R = R + 1000;   // reached from the #range too, until a #break
  #end
  R
#end
)";
    CHECK(values(sw, {"Pick(1)", "Pick(2)", "Pick(3)", "Pick(4)", "Pick(5.5)"}) == V{11, 10, 1101, 100, 1000});
    CHECK(error_of("#case (1)\nsphere{0,1}") == "1:1: `#case` without a matching `#switch`");
    CHECK_THAT(error_of("#switch (1) #case (1)\nsphere{0,1}"), Contains("expected `#end` to close the `#switch`"));
}

TEST_CASE("#for counts with a step, either way: #break leaves it", "[dsl][for]") {
    CHECK(values("#declare S = 0; #declare N = 0;\n#for (I, 1, 10, 3) #declare S = S + I; #declare N = N + 1; #end",
                 {"S", "N"}) == V{22, 4});
    CHECK(values("#declare S = 0;\n#for (I, 5, 1, -2) #declare S = S * 10 + I; #end", {"S"}) == V{531});
    CHECK(values("#declare S = 0;\n#for (I, 1, 0) #declare S = 1; #end", {"S"}) == V{0});
    CHECK(values("#declare S = 0;\n#for (I, 0, 100) #if (I = 3) #break #end #declare S = S + 1; #end", {"S"}) ==
          V{3});
    CHECK(values("#declare N = 0;\n#for (I, 0, 2) #for (J, 0, 3) #declare N = N + 1; #end #end", {"N"}) == V{12});
    CHECK(error_of("#for (I, 0, 1, 0) #end\nsphere{0,1}") == "1:16: the step of `#for` must not be 0");
    dsl::ParseOptions few;
    few.max_loop_iterations = 50;
    CHECK_THAT(error_of("#for (I, 0, 1000) #end\nsphere{0,1}", few), Contains("`#for` loop ran more than 50 times"));
}

TEST_CASE("arrays: sizes, initialisers, elements of any type, dimensions", "[dsl][array]") {
    const std::string arrays = R"(
#declare A = array[2][3] { {1, 2, 3}, {4, 5, 6} };
#declare A[1][2] = 60;
#declare V = array[2] { <1, 2, 3>, x };
#declare P = array[2];
#declare P[1] = pigment { rgb <0, 1, 0> };
#declare Copy = A;
#declare Copy[0][0] = -1;   // a copy, not an alias
#macro Sum(Arr) #local S = 0; #for (I, 0, dimension_size(Arr, 1) - 1) #local S = S + Arr[I]; #end S #end
#declare L = array[4] {1, 2, 3, 4};
)";
    CHECK(values(arrays, {"A[0][0]", "A[1][2]", "Copy[0][0]", "V[0].y", "dimensions(A)", "dimension_size(A, 2)",
                          "defined(P[0])", "defined(P[1])", "Sum(L)"}) == V{1, 60, -1, 2, 2, 3, 0, 1, 10});
    const Parsed p = parse(arrays + "sphere { 0, 1 pigment { P[1] } }\n#declare O = array[1] { sphere { 0, 2 } }\n"
                                    "object { O[0] }\n#ifdef (P[0]) #error \"unset\" #end\n");
    REQUIRE(p.desc.objects.size() == 2);
    CHECK(p.desc.objects[0].texture->pigment.color.rgb.y == 1);
    CHECK(std::get<dsl::SphereShape>(p.desc.objects[1].shape).radius == 2);
}

TEST_CASE("array errors: bounds, unset elements, types, sizes, with their location", "[dsl][array]") {
    CHECK(error_of("#declare A = array[3];\n#declare B = A[3];") ==
          "2:16: index 3 is out of the bounds of `A` (indices 0 to 2 in dimension 1, declared at 1:10)");
    CHECK(error_of("#declare A = array[3];\n#declare A[1] = 2;\n#declare B = A[0];") ==
          "3:14: the array element `A[0]` is used before it is set (the array is declared at 1:10)");
    CHECK(error_of("#declare A = array[2][2];\n#declare B = A[1];") ==
          "2:14: `A` has 2 dimensions: expected 2 indices, found 1");
    CHECK(error_of("#declare A = array[2] {1, 2, 3};") ==
          "1:30: expected `}` to close the 2 elements of dimension 1 of the array (opened at 1:23), found the number 3");
    CHECK_THAT(error_of("#declare A = array[2] {1, pigment { rgb 1 }};"),
               Contains("cannot store a pigment in an element of an array of a number"));
    CHECK(error_of("#declare A = array mixed[2] {1, pigment { rgb 1 }};\nsphere{0,1}").empty());
    CHECK_THAT(error_of("#declare A = array[0];"), Contains("the size of an array must be a whole number from 1"));
    dsl::ParseOptions small;
    small.max_array_elements = 1000;
    CHECK_THAT(error_of("#declare A = array[100][100];", small), Contains("array too large"));
    CHECK_THAT(error_of("#declare A = array[500]; #declare A[0] = 1; #declare B = A; #declare B[0] = 2;\n"
                        "#declare C = B; #declare C[0] = 3;",
                        small),
               Contains("arrays too large"));
    CHECK(error_of("#declare A = array[2];\n#macro M() #local A[0] = 1; #end\nM()") ==
          "2:19: cannot use `#local` to assign an element of `A`, which is not local here: use `#declare` (in macro "
          "`M` called at test.pov:3:1)");
}

TEST_CASE("#undef removes identifiers and macros: defined() and #ifdef see macros without calling them",
          "[dsl][macro]") {
    CHECK(values("#macro M() 1 #end\n#declare D1 = defined(M);\n#undef M\n#declare D2 = defined(M);\n"
                 "#ifdef (M) #error \"still defined\" #end",
                 {"D1", "D2"}) == V{1, 0});
    CHECK(error_of("#macro M() 1 #end\n#declare M = 2;") ==
          "2:10: cannot #declare `M`: it is a macro (defined at 1:8); `#undef` it first");
}

TEST_CASE("#declare changes the identifier where it is visible, else makes a global: deprecated marks are read",
          "[dsl][macro]") {
    // Inside a macro, #declare of a parameter changes the parameter; of a new name, a global.
    CHECK(values("#macro M(P) #declare P = P * 2; #declare Out = P; #end\nM(21)", {"Out"}) == V{42});
    // #local makes a new identifier in the call's scope even when a global has the name.
    CHECK(values("#declare G = 1;\n#macro M() #local G = 5; #declare Seen = G; #end\nM()", {"G", "Seen"}) ==
          V{1, 5});
    CHECK(values("#declare deprecated once \"use B\" A = 3;\n#declare deprecated \"old\" C = A + 1;", {"A", "C"}) ==
          V{3, 4});
    CHECK(error_of("#declare deprecated A = 3;") ==
          "1:21: expected a message in double quotes after `deprecated`, found `A`");
}

TEST_CASE("#declare of a block photon does not evaluate is read, and used by name", "[dsl][macro]") {
    // Maps are averaged and normals ignored where they are used (parser/patterns.hpp), so their
    // declarations are silent; a map where a pigment belongs is an error naming what it is.
    const Parsed p = parse("#declare Jade_Map =\ncolor_map { [0 rgb 0] [1 rgb 1] }\n#declare Bumps = normal { bumps 0.5 }\n"
                           "#declare Slopes =\nslope_map { [0 <0, 1>] [1 <1, 0>] }\nsphere { 0, 1 }");
    CHECK(p.warnings.empty());
    CHECK(error_of("#declare M = color_map { [0 rgb 0] }\nsphere { 0, 1 pigment { M } }") ==
          "2:25: expected a colour or a pigment identifier, found `M` (a color_map, declared at 1:10)");
}

TEST_CASE("colors.inc's colour macros run (skipped when POV-Ray's includes are not installed)", "[dsl][macro]") {
    const std::filesystem::path includes = "/usr/share/povray-3.7/include";
    if (!std::filesystem::exists(includes / "colors.inc")) {
        WARN("povray-includes is not installed: skipped");
        return;
    }
    dsl::ParseOptions options;
    options.include_paths.push_back(includes);
    // CHSV2RGB uses #switch/#range and #local; CRGB2HSV nested macros and conditional expressions.
    const V got = values("#include \"colors.inc\"\n#declare C = CHSV2RGB(<120, 1, 1>);\n"
                         "#declare H = CRGB2HSV(rgb <0.2, 0.4, 0.8>);",
                         {"C.red", "C.green", "C.blue", "H.x", "H.y", "H.z"}, options);
    const V want{0, 1, 0, 220, 0.75, 0.8};
    REQUIRE(got.size() == want.size());
    for (std::size_t i = 0; i < want.size(); ++i) CHECK(got[i] == Approx(want[i]).margin(1e-12));
}
