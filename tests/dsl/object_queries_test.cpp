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

TEST_CASE("bounded_by that holds the whole object changes nothing and says nothing, one that cuts it is reported",
          "[dsl][geometry]") {
    dsl::ParseOptions o;
    o.geometry = dsl::library_object_geometry();
    const auto p = parse("sphere { 0, 1 bounded_by { box { -1.01, 1.01 } } }\n"                      // 1: holds it
                         "sphere { 0, 1 translate 5*x bounded_by { sphere { 5*x, 1.8 } } }\n"       // 2: after the move
                         "sphere { 0, 1 bounded_by { sphere { 0, 0.5 } } }\n"                       // 3: cuts it
                         "sphere { 0, 1 bounded_by { torus { 2, 1.5 } } }\n"                        // 4: not convex
                         "sphere { 0, 1 clipped_by { plane { y, 0 } } bounded_by { clipped_by } }\n",  // 5: the clip
                         o);
    INFO(all_messages(p.warnings));
    CHECK(places(p.warnings, "ignored effect") ==
          std::vector<std::string>{"3:15 bounded_by", "4:15 bounded_by", "5:15 clipped_by"});
    CHECK_THAT(all_messages(p.warnings), Contains("which photon could not rule out here"));
    // Without the library's geometry the parser cannot tell, and says so.
    const auto q = parse("sphere { 0, 1 bounded_by { box { -2, 2 } } }\n");
    CHECK(places(q.warnings, "ignored effect") == std::vector<std::string>{"1:15 bounded_by"});
}
