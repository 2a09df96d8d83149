// SPDX-License-Identifier: MIT
// POV-Ray's quadric: the same hits as the analytic sphere, ellipsoid and cylinder it can stand
// for; exact boxes for its bounded solids and infinite ones where the solid is unbounded; the
// same surface for coefficients scaled by 1e30 or 1e-30; grazing rays, rays along an axis
// (no quadratic term), a cone's apex; Crofton's formula (isotropic uniform lines through a ball
// of radius B cross a surface of area A on average A / (2 pi B^2) times) for an infinite cylinder
// and a double cone, counting only crossings inside the ball; and CSG with a box.

#include <catch2/catch.hpp>

#include <photon/geometry/box.hpp>
#include <photon/geometry/csg.hpp>
#include <photon/geometry/cylinder.hpp>
#include <photon/geometry/offset.hpp>
#include <photon/geometry/quadric.hpp>
#include <photon/geometry/sphere.hpp>
#include <photon/geometry/transformed.hpp>
#include <photon/math/rng.hpp>
#include <photon/math/sampling.hpp>
#include <photon/plan/shape_facts.hpp>

#include "geometry/crofton.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace photon;

namespace {

template <class S> double tol() { return std::is_same_v<S, float> ? 2e-4 : 1e-9; }
/// Boxes are padded outward by 1e-9 of their size (rounding must never cut the solid).
template <class S> double box_tol() { return std::is_same_v<S, float> ? 2e-4 : 1e-8; }

template <class S> Quadric<S> quadric(Vec3<S> squares, Vec3<S> mixed, Vec3<S> linear, S constant) {
    return Quadric<S>(QuadricCoefficients<S>{squares, mixed, linear, constant});
}
/// POV-Ray's shapes.inc.
template <class S> Quadric<S> unit_sphere() { return quadric<S>({1, 1, 1}, {0, 0, 0}, {0, 0, 0}, -1); }
template <class S> Quadric<S> cylinder_y() { return quadric<S>({1, 0, 1}, {0, 0, 0}, {0, 0, 0}, -1); }
template <class S> Quadric<S> cone_y() { return quadric<S>({1, -1, 1}, {0, 0, 0}, {0, 0, 0}, 0); }
template <class S> Quadric<S> paraboloid_y() { return quadric<S>({1, 0, 1}, {0, 0, 0}, {0, -1, 0}, 0); }

/// Random rays aimed near `center` from a distance of about `reach`; `a` and `b` agree on hit or
/// miss (except within `grazing` of a tangent, judged by the normal), t and normal.
template <class S, class A, class B>
void same_hits(const A& a, const B& b, const Vec3<S>& center, S reach, int rays, std::uint64_t seed) {
    Pcg32 rng(seed, 1);
    int compared = 0;
    for (int i = 0; i < rays; ++i) {
        const Vec3<S> origin = center + S(3) * reach * uniform_sphere(rng.uniform2<S>());
        const Vec3<S> target = center + reach * uniform_sphere(rng.uniform2<S>()) * rng.uniform<S>();
        const Ray<S> ray{origin, (target - origin) * S(0.5 + rng.uniform<S>())};  // not unit length
        const auto ha = a.intersect(ray), hb = b.intersect(ray);
        const auto grazing = [&](const auto& h) {
            return h && std::abs(glm::dot(h->normal, glm::normalize(ray.direction))) < S(0.01);
        };
        if (grazing(ha) || grazing(hb)) continue;
        REQUIRE(ha.has_value() == hb.has_value());
        if (!ha) continue;
        ++compared;
        CHECK(ha->t == Approx(hb->t).epsilon(tol<S>()).margin(tol<S>() * reach / glm::length(ray.direction)));
        CHECK(glm::dot(ha->normal, hb->normal) > S(1) - S(10) * S(tol<S>()));
        CHECK(std::abs(glm::length(ha->normal) - S(1)) < S(1e-5));
    }
    CHECK(compared > rays / 4);
}

}  // namespace

TEMPLATE_TEST_CASE("quadric: sphere and ellipsoid give the analytic shapes' hits, placed by transformed()",
                   "[geometry][quadric]", float, double) {
    using S = TestType;
    const Vec3<S> c(1, 2, -3);
    // Written out, as POV-Ray's numbers: (x-1)^2 + (y-2)^2 + (z+3)^2 - 0.25 = 0.
    const Quadric<S> written = quadric<S>({1, 1, 1}, {0, 0, 0}, {-2, -4, 6}, S(1 + 4 + 9 - 0.25));
    same_hits<S>(written, Sphere<S>(c, S(0.5)), c, S(0.5), 2000, 1);
    const Quadric<S> placed = unit_sphere<S>().transformed(Affine<S>::scale(Vec3<S>(S(0.5))).then(Affine<S>::translate(c)));
    same_hits<S>(placed, Sphere<S>(c, S(0.5)), c, S(0.5), 2000, 2);
    // An ellipsoid, rotated and moved: the same as a Transformed sphere under the same map.
    const Affine<S> map =
        Affine<S>::scale({2, S(0.5), 1}).then(Affine<S>::rotate_xyz({30, 40, 50})).then(Affine<S>::translate(c));
    same_hits<S>(unit_sphere<S>().transformed(map), Transformed<Sphere<S>>(Sphere<S>(Vec3<S>(S(0)), S(1)), map), c,
                 S(2), 2000, 3);
    // Its box is exact: the extent along axis i of the image of the unit sphere under L is |row i of L|.
    const BBox<S> box = unit_sphere<S>().transformed(map).bounds();
    for (int i = 0; i < 3; ++i) {
        const S reach = glm::length(Vec3<S>(map.linear[0][i], map.linear[1][i], map.linear[2][i]));
        CHECK(box.min[i] == Approx(c[i] - reach).epsilon(box_tol<S>()));
        CHECK(box.max[i] == Approx(c[i] + reach).epsilon(box_tol<S>()));
    }
    CHECK(plan::is_convex_solid(unit_sphere<S>()));
    CHECK(plan::shape_name(unit_sphere<S>()) == "ellipsoid quadric");
    CHECK(unit_sphere<S>().contains(Vec3<S>(S(0.5))));
    CHECK_FALSE(unit_sphere<S>().contains(Vec3<S>(S(0.6))));
}

TEMPLATE_TEST_CASE("quadric: coefficients scaled by 1e30 or 1e-30 are the same surface", "[geometry][quadric]", float,
                   double) {
    using S = TestType;
    for (const S k : {S(1e30), S(1e-30)}) {
        const Quadric<S> scaled = quadric<S>({k, 2 * k, 3 * k}, {k, 0, 0}, {0, 0, k}, -k);
        const Quadric<S> plain = quadric<S>({1, 2, 3}, {1, 0, 0}, {0, 0, 1}, -1);
        same_hits<S>(scaled, plain, Vec3<S>(S(0)), S(1), 1000, 4);
        CHECK(scaled.bounds().is_finite());
        for (int i = 0; i < 3; ++i) CHECK(scaled.bounds().max[i] == Approx(plain.bounds().max[i]).epsilon(box_tol<S>()));
    }
}

TEMPLATE_TEST_CASE("quadric: the infinite cylinder gives a long cylinder's wall hits, its box infinite along y only",
                   "[geometry][quadric]", float, double) {
    using S = TestType;
    const Affine<S> map = Affine<S>::scale({S(0.3), 1, S(0.3)}).then(Affine<S>::translate({1, 0, 2}));
    const Quadric<S> infinite = cylinder_y<S>().transformed(map);
    // The finite cylinder's caps are far beyond the rays' reach (they are aimed within 1 of (1, 0, 2)).
    same_hits<S>(infinite, Cylinder<S>({1, -1e4, 2}, {1, 1e4, 2}, S(0.3)), Vec3<S>(1, 0, 2), S(1), 2000, 5);
    const BBox<S> b = infinite.bounds();
    CHECK(b.min.x == Approx(0.7).epsilon(box_tol<S>()));
    CHECK(b.max.z == Approx(2.3).epsilon(box_tol<S>()));
    CHECK(std::isinf(b.min.y));
    CHECK(std::isinf(b.max.y));
    CHECK_FALSE(plan::is_convex_solid(infinite));
    // Lying along x (rotated), it is infinite along x instead. (The rotation in double: float's
    // cos 90 degrees, -4e-8, would tilt it, and a tilted infinite cylinder is infinite along y.)
    const BBox<S> lying = cylinder_y<S>().transformed(Affine<double>::rotate_xyz({0, 0, 90})).bounds();
    CHECK(std::isinf(lying.max.x));
    CHECK(lying.max.y == Approx(1).epsilon(box_tol<S>()));
    CHECK(lying.max.z == Approx(1).epsilon(box_tol<S>()));
    // Along the axis there is no quadratic term: inside, the ray never meets the wall...
    CHECK_FALSE(cylinder_y<S>().intersect({{S(0.5), -5, 0}, {0, 1, 0}}));
    // ... a paraboloid along its axis is met once (the linear root).
    const auto h = paraboloid_y<S>().intersect({{0, -5, 0}, {0, 1, 0}});
    REQUIRE(h);
    CHECK(h->t == Approx(5).epsilon(tol<S>()));
    CHECK(h->normal.y == Approx(-1).epsilon(tol<S>()));
    CHECK_FALSE(paraboloid_y<S>().intersect({{0, 5, 0}, {0, 1, 0}}));
}

TEMPLATE_TEST_CASE("quadric: unbounded, inverted and empty solids have the right boxes", "[geometry][quadric]", float,
                   double) {
    using S = TestType;
    CHECK_FALSE(cone_y<S>().bounds().is_finite());
    CHECK_FALSE(paraboloid_y<S>().bounds().is_finite());
    CHECK_FALSE(quadric<S>({1, -1, 1}, {0, 0, 0}, {0, 0, 0}, -1).bounds().is_finite());  // hyperboloid
    // The outside of a sphere: its surface is bounded, its solid is not (what CSG needs).
    const Quadric<S> outside = quadric<S>({-1, -1, -1}, {0, 0, 0}, {0, 0, 0}, 1);
    CHECK_FALSE(outside.bounds().is_finite());
    CHECK(outside.contains(Vec3<S>(5, 0, 0)));
    const auto h = outside.intersect({{-5, 0, 0}, {1, 0, 0}});
    REQUIRE(h);
    CHECK(h->t == Approx(4).epsilon(tol<S>()));
    CHECK(h->normal.x == Approx(1).epsilon(tol<S>()));  // out of the solid: into the ball
    // x^2 + y^2 + z^2 + 1 <= 0 holds nowhere: an empty box, and no hit.
    const Quadric<S> empty = quadric<S>({1, 1, 1}, {0, 0, 0}, {0, 0, 0}, 1);
    CHECK(empty.bounds().is_empty());
    CHECK_FALSE(empty.intersect({{-5, 0, 0}, {1, 0, 0}}));
    // A half-space: no quadratic terms at all, the same hit as a plane.
    const Quadric<S> half = quadric<S>({0, 0, 0}, {0, 0, 0}, {0, 2, 0}, -2);
    const auto p = half.intersect({{0, 5, 0}, {0, -1, 0}});
    REQUIRE(p);
    CHECK(p->t == Approx(4).epsilon(tol<S>()));
    CHECK(p->normal.y == Approx(1).epsilon(tol<S>()));
    CHECK_THROWS_AS(quadric<S>({0, 0, 0}, {0, 0, 0}, {0, 0, 0}, 1), std::invalid_argument);
    CHECK_THROWS_AS(quadric<S>({S(NAN), 0, 0}, {0, 0, 0}, {0, 0, 0}, 1), std::invalid_argument);
    CHECK_THROWS_AS(unit_sphere<S>().transformed(Affine<S>::scale({1, 0, 1})), std::invalid_argument);
}

TEMPLATE_TEST_CASE("quadric: grazing rays, a cone's apex, far origins, rays leaving the surface", "[geometry][quadric]",
                   float, double) {
    using S = TestType;
    const Quadric<S> sphere = unit_sphere<S>();
    CHECK(sphere.intersect({{-5, S(1) - S(1e-3), 0}, {1, 0, 0}}));
    CHECK_FALSE(sphere.intersect({{-5, S(1) + S(1e-3), 0}, {1, 0, 0}}));
    // Nearly tangent from far away: the discriminant from the vertex keeps the chord.
    const S y = S(1) - S(1e-4), half_chord = std::sqrt(S(1) - y * y);
    const auto g = sphere.intersect({{S(-1e4), y, 0}, {1, 0, 0}});
    REQUIRE(g);
    CHECK(g->t == Approx(1e4 - half_chord).epsilon(tol<S>()));
    // Through the apex of the double cone along the axis: the surface is touched there.
    const auto apex = cone_y<S>().intersect({{S(0.5), -5, 0}, {0, 1, 0}});
    REQUIRE(apex);
    CHECK(apex->t == Approx(4.5).epsilon(tol<S>()));
    CHECK(std::abs(glm::length(apex->normal) - S(1)) < S(1e-5));
    // A unit sphere 1e4 away seen from the world's origin: hit at the right distance.
    const Vec3<S> far_c(S(1e4), S(-1e4), S(1e4));
    const Quadric<S> far = sphere.transformed(Affine<S>::translate(far_c));
    const auto hf = far.intersect({Vec3<S>(S(0)), glm::normalize(far_c)});
    REQUIRE(hf);
    CHECK(hf->t == Approx(glm::length(far_c) - 1).epsilon(tol<S>() * 1e-3));
    // Rays leaving the surface from the offset origin never find it again; entering, they
    // reach the far side (not the near one again).
    Pcg32 rng(7, 0);
    int self = 0, missed = 0;
    for (const Quadric<S>& shape : {sphere, far, cylinder_y<S>().transformed(Affine<S>::rotate_xyz({20, 0, 70}))}) {
        const BBox<S> box = shape.bounds();
        const Vec3<S> center = box.is_finite() ? box.center() : Vec3<S>(S(0));
        for (int i = 0; i < 500; ++i) {
            const Ray<S> ray{center + S(4) * uniform_sphere(rng.uniform2<S>()), center - S(4) * uniform_sphere(rng.uniform2<S>()) * S(0.2)};
            const auto h = shape.intersect({ray.origin, ray.direction - ray.origin});
            if (!h) continue;
            const Vec3<S> out = h->normal;  // out of the solid, wherever the ray came from
            const S error = intersection_error(h->point, ray.origin);
            const Vec3<S> leave = glm::normalize(out + S(0.3) * uniform_sphere(rng.uniform2<S>()));
            if (glm::dot(leave, out) > S(0.05) && shape.intersect({offset_origin(h->point, out, error), leave})) ++self;
            const Vec3<S> enter = glm::normalize(-out + S(0.3) * uniform_sphere(rng.uniform2<S>()));
            const auto back = shape.intersect({offset_origin(h->point, -out, error), enter});
            if (!back || glm::length(back->point - h->point) < S(8) * error) ++missed;
        }
    }
    CHECK(self == 0);
    CHECK(missed == 0);
}

TEMPLATE_TEST_CASE("quadric: Crofton's formula for an infinite cylinder and a double cone inside a ball",
                   "[geometry][quadric][crofton]", float, double) {
    using S = TestType;
    const S ball = S(1.5);
    // Crossings within the ball only: each walk restarts just past its last crossing.
    const auto count_in_ball = [&](const Quadric<S>& shape) {
        return [&shape, ball](const Ray<S>& ray) {
            long k = 0;
            Ray<S> r = ray;
            for (int guard = 0; guard < 8; ++guard) {
                const auto h = shape.intersect(r);
                if (!h) break;
                if (glm::length(h->point) < ball) ++k;
                const Vec3<S> side = glm::dot(h->normal, ray.direction) > S(0) ? h->normal : -h->normal;
                r.origin = offset_origin(h->point, side, intersection_error(h->point, ray.origin));
            }
            return k;
        };
    };
    const S r = S(0.6);
    const Quadric<S> cylinder = cylinder_y<S>().transformed(Affine<S>::scale({r, 1, r}).then(Affine<S>::rotate_xyz({10, 20, 30})));
    // The cylinder's wall inside the ball: 2 pi r times the chord 2 sqrt(B^2 - r^2).
    const double wall = 2 * pi<double> * double(r) * 2 * std::sqrt(double(ball * ball - r * r));
    auto [mean, se] = testing::mean_crossings<S>(Vec3<S>(S(0)), ball, 40'000, 11, count_in_ball(cylinder));
    CHECK(std::abs(mean - wall / (2 * pi<double> * double(ball * ball))) < 4 * se);
    // Both nappes of x^2 + z^2 = y^2 within the ball (apex at its centre): slant B, radius B / sqrt 2.
    const double nappes = 2 * pi<double> * double(ball) / std::sqrt(2.0) * double(ball);
    std::tie(mean, se) = testing::mean_crossings<S>(Vec3<S>(S(0)), ball, 40'000, 12, count_in_ball(cone_y<S>()));
    CHECK(std::abs(mean - nappes / (2 * pi<double> * double(ball * ball))) < 4 * se);
}

TEMPLATE_TEST_CASE("quadric: in CSG, an infinite cylinder cut by a box is the finite cylinder", "[geometry][quadric][csg]",
                   float, double) {
    using S = TestType;
    using Tree = Csg<S, Quadric<S>, Box<S>>;
    const Tree cut = Tree::intersection({Tree(cylinder_y<S>()), Tree(Box<S>({-2, 0, -2}, {2, 2, 2}))});
    const BBox<S> b = cut.bounds();  // the overlap of the cylinder's slab and the box
    CHECK(b.is_finite());
    CHECK(b.max.x == Approx(1).epsilon(box_tol<S>()));
    CHECK(b.max.y == Approx(2).epsilon(tol<S>()));
    same_hits<S>(cut, Cylinder<S>({0, 0, 0}, {0, 2, 0}, 1), Vec3<S>(0, 1, 0), S(1.5), 2000, 13);
    CHECK(cut.contains({0, 1, S(0.9)}));
    CHECK_FALSE(cut.contains({0, 3, 0}));
    // Inverted: a box with a cylindrical hole along y.
    Tree hole = Tree::intersection({Tree(cylinder_y<S>()).invert(), Tree(Box<S>({-2, 0, -2}, {2, 2, 2}))});
    const auto h = hole.intersect({{0, 5, 0}, {0, -1, 0}});  // down the hole: no hit
    CHECK_FALSE(h);
    const auto w = hole.intersect({{0, 1, 0}, {1, 0, 0}});  // from the hole's axis: its wall, facing in
    REQUIRE(w);
    CHECK(w->t == Approx(1).epsilon(tol<S>()));
    CHECK(w->normal.x == Approx(-1).epsilon(tol<S>()));
}
