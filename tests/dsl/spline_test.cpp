// SPDX-License-Identifier: MIT
// POV-Ray's splines: declared, called in expressions, with POV-Ray 3.7's interpolation rules.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

using namespace dsl_test;
using Catch::Matchers::Contains;

namespace {

dsl::Vector3 centre_of(const std::string& spline, const std::string& call) {
    const auto p = parse("#declare S = spline { " + spline + " }\nsphere { " + call + ", 1 }\n");
    return std::get<dsl::SphereShape>(p.desc.objects.at(0).shape).center;
}

double x_of(const std::string& spline, double t, const std::string& kind = {}) {
    return centre_of(spline, "S(" + std::to_string(t) + (kind.empty() ? "" : ", " + kind) + ")").x;
}

}  // namespace

TEST_CASE("splines interpolate as POV-Ray's, holding the end values", "[dsl][spline]") {
    const std::string pts = "0, <0, 0, 0> 1, <1, 0, 0>, 2, <4, 0, 0>, 3, <9, 0, 0>,";  // x = t^2, optional commas
    CHECK(x_of("linear_spline " + pts, 1.5) == Approx(2.5));
    CHECK(x_of("linear_spline " + pts, -1) == 0);  // no extrapolation
    CHECK(x_of("linear_spline " + pts, 7) == 9);
    // The parabola through three points is exact on t^2.
    CHECK(x_of("quadratic_spline " + pts, 1.5) == Approx(2.25));
    CHECK(x_of("quadratic_spline " + pts, 0.5) == Approx(0.25));
    // Catmull-Rom: tangents (v[i+1] - v[i-1]) / 2 per unit step; the Hermite midpoint of [1, 2] is
    // (v1 + v2) / 2 + (m1 - m2) / 8 = 2.5 + (2 - 4) / 8 = 2.25. Outside [t1, t_{n-2}] it holds.
    CHECK(x_of("cubic_spline " + pts, 1.5) == Approx(2.25));
    CHECK(x_of("cubic_spline " + pts, 0.5) == 1);
    CHECK(x_of("cubic_spline " + pts, 2.5) == 4);
    // Natural cubic (zero curvature at the ends) through 4 points of t^2: curvature at t = 1 and 2
    // from the tridiagonal system 4 m1 + m2 = 6 * 2, m1 + 4 m2 = 6 * 2: m1 = m2 = 2.4; on [1, 2]
    // the midpoint is 2.5 - (1/8) * (m1 + m2) / 2 = 2.2.
    CHECK(x_of("natural_spline " + pts, 1.5) == Approx(2.2));
    // The kind may be given at the call; a repeated parameter replaces its point.
    CHECK(x_of("linear_spline " + pts, 1.5, "quadratic_spline") == Approx(2.25));
    CHECK(x_of("0, <0,0,0> 1, <5,0,0> 1, <1,0,0>", 0.5) == Approx(0.5));
    // Float splines give floats.
    const auto p = parse("#declare F = spline { 0, 1 2, 3 }\nsphere { 0, F(1) }\n");
    CHECK(std::get<dsl::SphereShape>(p.desc.objects.at(0).shape).radius == Approx(2));
}

TEST_CASE("spline errors are located", "[dsl][spline]") {
    CHECK_THROWS_WITH(parse("#declare S = spline { 0, 1 1, <1, 2, 3> }\n"),
                      Contains("1:31: error: expected a number as in the spline's other points"));
    CHECK_THROWS_WITH(parse("#declare S = spline { linear_spline }\n"),
                      Contains("1:37: error: expected a spline point (parameter, value)"));
    CHECK_THROWS_WITH(parse("#declare S = spline { 0, <0,0,0> 1, <1,1,1> }\nsphere { S(0.5, bad), 1 }\n"),
                      Contains("2:17: error: expected `linear_spline`"));
}
