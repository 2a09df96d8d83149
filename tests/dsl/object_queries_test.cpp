// SPDX-License-Identifier: MIT
// trace(), min_extent() and max_extent(): the scene asks the library's geometry while it is read.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

using namespace dsl_test;
using Catch::Matchers::Contains;

namespace {

dsl::Vector3 centre_of(const std::string& text, std::size_t object = 0) {
    dsl::ParseOptions o;
    o.geometry = dsl::library_object_geometry();
    const auto p = parse(text, o);
    return std::get<dsl::SphereShape>(p.desc.objects.at(object).shape).center;
}

bool close_to(const dsl::Vector3& a, const dsl::Vector3& b, double eps = 1e-9) { return glm::length(a - b) <= eps; }

}  // namespace

TEST_CASE("trace() finds the first hit and its normal on a declared object", "[dsl][geometry]") {
    const std::string ball = "#declare Ball = sphere { <0, 0, 0>, 2 translate <1, 0, 0> }\n";
    CHECK(close_to(centre_of(ball + "sphere { trace(Ball, <1, 10, 0>, -y), 0.1 }"), {1, 2, 0}));
    // The normal faces the ray's origin, written to the fourth argument.
    CHECK(close_to(centre_of(ball + "#declare N = <9, 9, 9>;\n#declare P = trace(Ball, <1, 0, 0>, x, N);\n"
                                "sphere { N, 0.1 }"),
               {-1, 0, 0}));
    // A miss gives <0, 0, 0> for the point and for the normal, as in POV-Ray.
    CHECK(close_to(centre_of(ball + "#declare P = trace(Ball, <10, 10, 0>, y, M);\nsphere { P + M + 1, 0.1 }"), {1, 1, 1}));
    // Transforms and unions are the render's: a scaled box in a union.
    CHECK(close_to(centre_of("#declare U = union { box { -1, 1 scale <1, 3, 1> } sphere { <5, 0, 0>, 1 } }\n"
                         "sphere { trace(U, <0, 10, 0>, -y), 0.1 }"),
               {0, 3, 0}));
}

TEST_CASE("min_extent() and max_extent() are the object's bounds", "[dsl][geometry]") {
    const std::string b = "#declare B = box { <-1, -2, -3>, <1, 2, 3> translate <10, 0, 0> }\n";
    CHECK(close_to(centre_of(b + "sphere { min_extent(B), 1 }"), {9, -2, -3}));
    CHECK(close_to(centre_of(b + "sphere { max_extent(B), 1 }"), {11, 2, 3}));
    // A plane is unbounded: POV-Ray's BOUND_HUGE.
    CHECK(centre_of("#declare P = plane { y, 0 }\nsphere { max_extent(P), 1 }").x == 2e10);
}

TEST_CASE("object queries: bad arguments and a missing geometry are located errors", "[dsl][geometry]") {
    dsl::ParseOptions o;
    o.geometry = dsl::library_object_geometry();
    CHECK_THROWS_WITH(parse("#declare A = 1;\nsphere { trace(A, 0, y), 1 }", o),
                      Contains("2:16: error: expected an object identifier as the first argument of `trace`"));
    CHECK_THROWS_WITH(parse("#declare S = sphere { 0, 1 }\nsphere { trace(S, 0, 0), 1 }", o),
                      Contains("2:22: error: the direction of `trace` must not be zero"));
    CHECK_THROWS_WITH(parse("#declare S = sphere { 0, 1 }\nsphere { min_extent(S), 1 }"),
                      Contains("2:10: error: `min_extent` needs the object's geometry"));
}

TEST_CASE("a bounded_by photon cannot show to hold its object is reported where POV-Ray keeps it", "[dsl][geometry]") {
    // POV-Ray 3.7 removes the bounds of single shapes (Remove_Bounds) and keeps those of unions
    // and CSG, of anything inside a CSG and of the objects of a union it keeps whole.
    dsl::ParseOptions o;
    o.geometry = dsl::library_object_geometry();
    const StagedScene b = build_staged(
                             "union { sphere { 0, 1 } sphere { x, 1 } bounded_by { box { <-1.01, -1.01, -1.01>, <2.01, 1.01, 1.01> } } }\n"
                             "union { sphere { 0, 1 } sphere { x, 1 } translate 5*x bounded_by { sphere { <5.5, 0, 0>, 2.1 } } }\n"
                             "union { sphere { 0, 1 } sphere { x, 1 } bounded_by { sphere { 0, 0.5 } } }\n"
                             "union { sphere { 0, 1 } sphere { x, 1 } bounded_by { torus { 2, 1.5 } } }\n"
                             "sphere { 0, 1 bounded_by { sphere { 0, 0.5 } } }\n"
                             "difference { box { -1, 1 } sphere { 0, 1 bounded_by { sphere { 0, 0.5 } } } }\n"
                             "union { sphere { 0, 1 } clipped_by { plane { y, 0 } } bounded_by { clipped_by } }\n"
                             "union { sphere { 0, 1 bounded_by { sphere { 0, 0.5 } } } sphere { 3*x, 1 } bounded_by { box { -5, 5 } } }\n"   // kept: its union is kept whole
                             "union { sphere { 0, 1 bounded_by { sphere { 0, 0.5 } } } sphere { 3*x, 1 } }\n",  // removed: its union is split
        o, "");
    INFO(all_messages(b.warnings));
    CHECK(places(b.warnings, "ignored effect") ==
          std::vector<std::string>{"3:41 bounded_by", "4:41 bounded_by", "6:42 bounded_by", "8:23 bounded_by"});
    CHECK_THAT(all_messages(b.warnings), Contains("which photon could not rule out here"));
    // Without the library's geometry the parser cannot tell, and says so where it matters.
    const StagedScene q = build_staged("sphere { 0, 1 bounded_by { box { -2, 2 } } }\n"
                                       "union { sphere { 0, 1 } sphere { x, 1 } bounded_by { box { -2, 2 } } }\n", {}, "");
    CHECK(places(q.warnings, "ignored effect") == std::vector<std::string>{"2:41 bounded_by"});
}
