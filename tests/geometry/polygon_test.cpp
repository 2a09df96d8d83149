// SPDX-License-Identifier: MIT
// POV-Ray's polygon: even-odd filling over several loops (a hole, overlapping loops), its plane
// and normal, hits from far away and at grazing angles, degenerate input, and Crofton's formula
// (isotropic uniform lines through a ball of radius B cross a surface of area A on average
// A / (2 pi B^2) times) for a polygon with a hole.

#include <catch2/catch.hpp>

#include <photon/geometry/polygon.hpp>
#include <photon/plan/shape_facts.hpp>

#include "geometry/crofton.hpp"

#include <cmath>
#include <stdexcept>

using namespace photon;

namespace {

template <class S> double polygon_tol() { return std::is_same_v<S, float> ? 2e-4 : 1e-9; }

/// A square of side 2 in the xz plane at height `y`, with a square hole of side 1 (POV-Ray writes
/// both loops in one list; the library takes them apart).
template <class S> Polygon<S> frame_square(S y) {
    return Polygon<S>({{{-1, y, -1}, {1, y, -1}, {1, y, 1}, {-1, y, 1}},
                       {{S(-0.5), y, S(-0.5)}, {S(0.5), y, S(-0.5)}, {S(0.5), y, S(0.5)}, {S(-0.5), y, S(0.5)}}});
}

}  // namespace

TEMPLATE_TEST_CASE("polygon: even-odd filling, plane and normal", "[geometry][polygon]", float, double) {
    using S = TestType;
    const Polygon<S> p = frame_square<S>(S(0.5));
    auto h = p.intersect({{S(0.75), 3, 0}, {0, -2, 0}});  // on the frame, non-unit direction
    REQUIRE(h);
    CHECK(h->t == Approx(1.25).epsilon(polygon_tol<S>()));
    CHECK(std::abs(h->normal.y) == Approx(1).epsilon(polygon_tol<S>()));
    CHECK(h->point.y == Approx(0.5).epsilon(polygon_tol<S>()));
    CHECK_FALSE(p.intersect({{0, 3, 0}, {0, -1, 0}}));            // through the hole
    CHECK_FALSE(p.intersect({{S(1.5), 3, 0}, {0, -1, 0}}));       // outside
    CHECK_FALSE(p.intersect({{S(0.75), 3, 0}, {1, 0, 0}}));       // parallel
    CHECK_FALSE(p.intersect({{S(0.75), S(0.5), 0}, {1, 0, 0}}));  // in the plane: no area seen
    CHECK(p.intersect({{S(0.75), -3, 0}, {0, 1, 0}}));            // from below too
    // Overlapping loops cancel where they overlap.
    const Polygon<S> two({{{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}}, {{1, 1, 0}, {3, 1, 0}, {3, 3, 0}, {1, 3, 0}}});
    CHECK(two.intersect({{S(0.5), S(0.5), 5}, {0, 0, -1}}));
    CHECK_FALSE(two.intersect({{S(1.5), S(1.5), 5}, {0, 0, -1}}));
    CHECK(two.intersect({{S(2.5), S(2.5), 5}, {0, 0, -1}}));
    // A ray through a vertex's height: the two edges meeting there count once between them.
    const Polygon<S> diamond({{{0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}}});
    CHECK(diamond.intersect({{S(0.5), 0, 5}, {0, 0, -1}}));
    CHECK_FALSE(diamond.intersect({{S(1.5), 0, 5}, {0, 0, -1}}));
    // Tilted, from far away.
    const Polygon<S> tilted({{{0, 0, 0}, {1, 1, 0}, {1, 1, 1}, {0, 0, 1}}});
    h = tilted.intersect({{S(1e4), S(0.5 - 1e4), S(0.5)}, {-1, 1, 0}});
    REQUIRE(h);
    CHECK(h->point.x == Approx(0.25).margin(std::is_same_v<S, float> ? 2e-3 : 1e-9));
    CHECK(std::abs(h->normal.x) == Approx(std::sqrt(0.5)).epsilon(polygon_tol<S>()));
    CHECK(plan::is_flat(tilted));
    CHECK(plan::shape_name(tilted) == "polygon");
    CHECK_THROWS_AS(Polygon<S>({{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}}), std::invalid_argument);               // a line
    CHECK_THROWS_AS(Polygon<S>({{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 1}}}), std::invalid_argument);    // not flat
    CHECK_THROWS_AS(Polygon<S>({{{0, 0, 0}, {1, 0, 0}, {S(INFINITY), 1, 0}}}), std::invalid_argument);
}

TEMPLATE_TEST_CASE("polygon: Crofton's formula gives the area of a square with a hole", "[geometry][polygon][crofton]",
                   float, double) {
    using S = TestType;
    const Polygon<S> p = frame_square<S>(S(0.1));
    const S ball = S(1.6);
    const auto [mean, se] = testing::mean_crossings<S>(
        Vec3<S>(S(0)), ball, 100'000, 21, [&](const Ray<S>& ray) { return long(p.intersect(ray).has_value()); });
    const double area = 4.0 - 1.0;
    CHECK(std::abs(mean - area / (2 * pi<double> * double(ball * ball))) < 4 * se);
}
