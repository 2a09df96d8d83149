// SPDX-License-Identifier: MIT
// Hard cases for the intersectors: grazing rays; rays that start on, just inside and just
// outside a surface (the rays every bounce spawns), at scales 1e-4 to 1e5 and far from the
// origin; hits never behind the ray's origin; degenerate triangles never hit and never NaN.

#include "hard_case_util.hpp"

#include <photon/math/frame.hpp>

#include <functional>
#include <limits>

using namespace photon;

namespace {

/// Where a family of rays is aimed: a shape of size `size` around `center`.
template <class S> struct Placement {
    S size;
    Vec3<S> center;
};

/// The scales and offsets every shape is tried at: unit size at the origin, tiny, huge, and a
/// unit shape 1000 units away (rounding then grows with the position, not with the shape).
template <class S> std::vector<Placement<S>> placements() {
    return {{S(1), Vec3<S>(S(0))}, {S(1e-4), Vec3<S>(S(0))}, {S(1e5), Vec3<S>(S(0))},
            {S(1), Vec3<S>(S(1000), S(-1000), S(1000))}};
}

struct RayFailures {
    int hits = 0;            ///< rays that found the surface (the trials that count)
    int not_finite = 0;      ///< NaN/Inf in t, point or normal, or a normal not of unit length
    int behind = 0;          ///< t <= 0: a hit behind the ray's origin
    int self_hits = 0;       ///< a ray leaving the surface found it again
    int missed_far_side = 0; ///< a ray entering a closed shape did not reach its far side
};

template <class S> bool valid_hit(const Hit<S>& h) {
    return std::isfinite(h.t) && is_finite(h.point) && is_finite(h.normal) &&
           std::abs(glm::length(h.normal) - S(1)) < S(1e-3);
}

template <class S> Vec3<S> in_hemisphere(const Vec3<S>& n, Pcg32& rng, S min_cos) {
    for (;;) {
        const Vec3<S> local = cosine_hemisphere(rng.uniform2<S>());
        if (local.z > min_cos) return Frame<S>::from_normal(n).to_world(local);
    }
}

/// Shoots rays at `shape` from around it; from every hit spawns a ray leaving the surface from
/// the offset origin (it must not find the surface again: shapes here are convex) and, for closed
/// shapes, one entering it (it must reach the far side, not re-hit the near one).
template <class Shape, class S = scalar_of<Shape>>
RayFailures surface_rays(const Shape& shape, const Placement<S>& at, bool closed, Pcg32& rng, int trials) {
    RayFailures f;
    for (int i = 0; i < trials; ++i) {
        const Vec3<S> origin = at.center + S(3) * at.size * uniform_sphere(rng.uniform2<S>());
        const Vec3<S> target = at.center + S(0.7) * at.size * uniform_sphere(rng.uniform2<S>()) * rng.uniform<S>();
        const Ray<S> ray{origin, glm::normalize(target - origin)};
        const auto hit = shape.intersect(ray);
        if (!hit) continue;
        ++f.hits;
        if (!valid_hit(*hit)) { ++f.not_finite; continue; }
        if (!(hit->t > S(0))) ++f.behind;
        const Facing<S> side = facing(hit->normal, ray.direction);
        const S error = intersection_error(hit->point, ray.origin);
        const Ray<S> leaving{offset_origin(hit->point, side.normal, error), in_hemisphere(side.normal, rng, S(0))};
        if (const auto again = shape.intersect(leaving)) {
            ++f.self_hits;
            if (!(again->t > S(0))) ++f.behind;
        }
        if (occluded(shape, leaving)) ++f.self_hits;
        if (!closed) continue;
        const Ray<S> entering{offset_origin(hit->point, -side.normal, error), in_hemisphere(-side.normal, rng, S(0.2))};
        const auto far = shape.intersect(entering);
        if (!far || !valid_hit(*far)) { ++f.missed_far_side; continue; }
        if (!(far->t > S(0))) ++f.behind;
        // Re-hitting the near face lands within a few errors of the start, facing the same way.
        const bool near_face = glm::length(far->point - hit->point) < S(4) * error &&
                               glm::dot(far->normal, hit->normal) > S(0.5);
        if (near_face) ++f.missed_far_side;
    }
    return f;
}

template <class S> void check(const RayFailures& f, int trials, const char* name, const Placement<S>& at) {
    INFO(name << " of size " << at.size << " at <" << at.center.x << ", " << at.center.y << ", " << at.center.z
              << ">: " << f.hits << " hits of " << trials);
    CHECK(f.hits > trials / 10);
    CHECK(f.not_finite == 0);
    CHECK(f.behind == 0);
    CHECK(f.self_hits == 0);
    CHECK(f.missed_far_side == 0);
}

}  // namespace

TEMPLATE_TEST_CASE("rays leaving and entering every primitive, at every scale, never re-hit the surface", "[hard][geometry]",
                   float, double) {
    using S = TestType;
    constexpr int trials = 4000;
    Pcg32 rng(2024, 1), quadric_rng(2024, 2);
    for (const Placement<S>& at : placements<S>()) {
        const S r = at.size;
        const Vec3<S>& c = at.center;
        check(surface_rays(Sphere<S>(c, r), at, true, rng, trials), trials, "sphere", at);
        check(surface_rays(Plane<S>(glm::normalize(Vec3<S>(1, 2, 3)), glm::dot(c, glm::normalize(Vec3<S>(1, 2, 3)))),
                           at, false, rng, trials),
              trials, "plane", at);
        check(surface_rays(Box<S>(c - Vec3<S>(r, S(0.5) * r, S(0.8) * r), c + Vec3<S>(S(0.6) * r, r, S(0.7) * r)), at,
                           true, rng, trials),
              trials, "box", at);
        check(surface_rays(Triangle<S>(c + Vec3<S>(-r, -r, S(0.1) * r), c + Vec3<S>(r, -S(0.5) * r, -S(0.2) * r),
                                       c + Vec3<S>(0, r, S(0.3) * r)),
                           at, false, rng, trials),
              trials, "triangle", at);
        const Affine<S> place = Affine<S>::scale({r, S(0.4) * r, S(0.7) * r})
                                    .then(Affine<S>::rotate_xyz({30, 45, 60}))
                                    .then(Affine<S>::translate(c));
        check(surface_rays(Transformed<Sphere<S>>(Sphere<S>(Vec3<S>(S(0)), S(1)), place), at, true, rng, trials), trials,
              "ellipsoid", at);
        check(surface_rays(Transformed<Box<S>>(Box<S>(Vec3<S>(S(-1)), Vec3<S>(S(1))), place), at, true, rng, trials),
              trials, "rotated box", at);
        // The same ellipsoid as POV-Ray's quadric, its map folded into its numbers (its own random
        // stream, so that the shapes above keep theirs).
        const Quadric<S> unit(QuadricCoefficients<S>{Vec3<S>(S(1)), Vec3<S>(S(0)), Vec3<S>(S(0)), S(-1)});
        check(surface_rays(unit.transformed(place), at, true, quadric_rng, trials), trials, "quadric ellipsoid", at);
    }
}

TEMPLATE_TEST_CASE("rays starting just inside, on and just outside a surface, tangent or pointing away",
                   "[hard][geometry]", float, double) {
    using S = TestType;
    Pcg32 rng(7, 3);
    for (const Placement<S>& at : placements<S>()) {
        const Sphere<S> sphere(at.center, at.size);
        int behind = 0, not_finite = 0, outside_hits = 0, inside_misses = 0;
        for (int i = 0; i < 2000; ++i) {
            const Vec3<S> n = uniform_sphere(rng.uniform2<S>());
            const Vec3<S> p = at.center + at.size * n;
            const S error = intersection_error(p, p);
            const Vec3<S> tangent = Frame<S>::from_normal(n).to_world({S(1), S(0), S(0)});
            for (const S lift : {S(-8), S(-1), S(0), S(1), S(8)}) {
                const Vec3<S> o = p + lift * error * n;
                for (const Vec3<S>& d : {tangent, n, -n, glm::normalize(tangent + n), glm::normalize(tangent - n)}) {
                    const auto h = sphere.intersect({o, d});
                    if (h) {
                        if (!valid_hit(*h)) ++not_finite;
                        // t > 0 is the contract; the point may round onto the origin but never
                        // lies measurably behind it.
                        if (!(h->t > S(0)) || glm::dot(h->point - o, d) < -error) ++behind;
                    }
                    // Outside and pointing away or along the tangent: the sphere is behind.
                    if (lift > S(1) && glm::dot(d, n) >= S(0) && h) ++outside_hits;
                    // Inside and pointing inward: the far side is ahead, about 2 r cos away.
                    if (lift < S(-1) && glm::dot(d, n) < S(-0.5) &&
                        (!h || !(h->t > S(0.5) * at.size)))
                        ++inside_misses;
                }
            }
        }
        INFO("sphere of radius " << at.size << " at x = " << at.center.x);
        CHECK(not_finite == 0);
        CHECK(behind == 0);
        CHECK(outside_hits == 0);
        CHECK(inside_misses == 0);

        // The same for a box face and a plane, from above and below, at and around the surface.
        const Box<S> box(at.center - Vec3<S>(at.size), at.center + Vec3<S>(at.size));
        const Plane<S> plane({0, 1, 0}, at.center.y + at.size);
        int box_bad = 0, plane_bad = 0;
        for (int i = 0; i < 2000; ++i) {
            const Vec2<S> u = rng.uniform2<S>() * S(1.8) - S(0.9);
            const Vec3<S> p = at.center + at.size * Vec3<S>(u.x, S(1), u.y);
            const S error = intersection_error(p, p);
            const Vec3<S> d = glm::normalize(Vec3<S>(rng.uniform<S>() - S(0.5), S(0.5), rng.uniform<S>() - S(0.5)));
            // Just above, leaving upward: nothing ahead.
            const Ray<S> up{p + S(2) * error * Vec3<S>(0, 1, 0), d};
            if (box.intersect(up)) ++box_bad;
            if (plane.intersect(up)) ++plane_bad;
            // Just below, going down: the box's bottom face 2 sizes away; the plane is behind.
            const Ray<S> down{p - S(2) * error * Vec3<S>(0, 1, 0), -d};
            const auto b = box.intersect(down);
            if (!b || !(b->t > S(0.1) * at.size) || !valid_hit(*b)) ++box_bad;
            if (plane.intersect(down)) ++plane_bad;
            // Parallel to the face, exactly on it: a clean miss or a finite hit ahead.
            const Ray<S> along{p, glm::normalize(Vec3<S>(d.x, 0, d.z))};
            if (const auto h = box.intersect(along); h && (!valid_hit(*h) || !(h->t > S(0)))) ++box_bad;
            if (plane.intersect(along)) ++plane_bad;
        }
        CHECK(box_bad == 0);
        CHECK(plane_bad == 0);
    }
}

TEMPLATE_TEST_CASE("grazing rays on a sphere and a plane: hits are finite, on the surface and ahead", "[hard][geometry]",
                   float, double) {
    using S = TestType;
    constexpr S eps = std::numeric_limits<S>::epsilon();
    Pcg32 rng(99, 5);
    for (const Placement<S>& at : placements<S>()) {
        const Sphere<S> sphere(at.center, at.size);
        int bad = 0, wrong_side = 0;
        for (int i = 0; i < 4000; ++i) {
            // A ray whose closest approach to the centre is r (1 + delta), |delta| < 1e-3.
            const Vec3<S> d = uniform_sphere(rng.uniform2<S>());
            const Frame<S> frame = Frame<S>::from_normal(d);
            const S delta = (rng.uniform<S>() * S(2) - S(1)) * S(1e-3);
            const Vec3<S> side = frame.to_world({S(1), S(0), S(0)});
            const Vec3<S> origin = at.center + at.size * (S(1) + delta) * side - S(5) * at.size * d;
            const auto h = sphere.intersect({origin, d});
            if (h) {
                const S off_surface = std::abs(glm::length(h->point - at.center) - at.size);
                // Near tangency the hit is ill-conditioned along the ray (error ~ sqrt(eps) r), but
                // never off the surface by more than that, never behind, never NaN.
                if (!valid_hit(*h) || !(h->t > S(0)) || off_surface > S(8) * std::sqrt(eps) * (at.size + max_component(glm::abs(at.center))))
                    ++bad;
            }
            // Clear misses and clear hits must be decided right.
            if (delta > S(1e-4) && h) ++wrong_side;
            if (delta < S(-1e-4) && !h) ++wrong_side;
        }
        INFO("sphere of radius " << at.size << " at x = " << at.center.x);
        CHECK(bad == 0);
        CHECK(wrong_side == 0);

        const Plane<S> plane({0, 1, 0}, at.center.y);
        int plane_bad = 0;
        for (const S slope : {S(1e-2), S(1e-4), S(1e-6), S(1e-10), S(1e-20), S(1e-30)}) {
            for (const S height : {S(1), S(1e-3), S(-1)}) {
                const Vec3<S> origin = at.center + Vec3<S>(0, height * at.size, 0);
                const Vec3<S> d = glm::normalize(Vec3<S>(1, height > 0 ? -slope : slope, 0));
                const auto h = plane.intersect({origin, d});
                if (!h) continue;  // a slope whose hit overflows is a clean miss
                const S scale = max_component(glm::abs(h->point)) + max_component(glm::abs(origin));
                if (!valid_hit(*h) || !(h->t > S(0)) || std::abs(h->point.y - at.center.y) > S(4) * eps * scale) ++plane_bad;
            }
        }
        CHECK(plane_bad == 0);
    }
}

namespace {

/// Rays through the vertices, the middle of the edges and random points of the triangle's hull,
/// in random directions and straight along z (which keeps the target's x and y exact however
/// small they are).
template <class S> std::vector<Ray<S>> rays_through(const std::array<Vec3<S>, 3>& v, Pcg32& rng) {
    std::vector<Vec3<S>> targets{v[0], v[1], v[2], (v[0] + v[1]) / S(2), (v[1] + v[2]) / S(2), (v[0] + v[2]) / S(2)};
    for (int i = 0; i < 200; ++i) {
        const Vec2<S> u = rng.uniform2<S>();
        targets.push_back(v[0] + u.x * (v[1] - v[0]) + (S(1) - u.x) * u.y * (v[2] - v[0]));
    }
    std::vector<Ray<S>> rays;
    for (const Vec3<S>& target : targets)
        for (int j = 0; j < 10; ++j) {
            const Vec3<S> d = j < 8 ? uniform_sphere(rng.uniform2<S>()) : Vec3<S>(0, 0, j == 8 ? -1 : 1);
            rays.push_back({target - d, d, S(2)});  // ends past the target, before anything else
        }
    return rays;
}

}  // namespace

TEMPLATE_TEST_CASE("degenerate triangles never hit and never give NaN normals", "[hard][geometry]", float, double) {
    using S = TestType;
    // Zero area (one point), exactly collinear (twice), as a Triangle and inside a mesh.
    const std::vector<std::array<Vec3<S>, 3>> degenerate{
        {Vec3<S>(1, 1, 1), Vec3<S>(1, 1, 1), Vec3<S>(1, 1, 1)},
        {Vec3<S>(0, 0, 0), Vec3<S>(1, 1, 1), Vec3<S>(3, 3, 3)},
        {Vec3<S>(-1, 2, 0), Vec3<S>(1, 2, 0), Vec3<S>(0, 2, 0)},
    };
    Pcg32 rng(5, 5);
    for (std::size_t k = 0; k < degenerate.size(); ++k) {
        const auto& v = degenerate[k];
        INFO("triangle " << k);
        const Triangle<S> tri(v[0], v[1], v[2]);
        CHECK(tri.is_degenerate());
        CHECK(is_finite(tri.normal()));
        // A real triangle beside it, so that the mesh has a BVH with more than one leaf.
        const TriangleMesh<S> mesh({v[0], v[1], v[2], Vec3<S>(5, 5, 5), Vec3<S>(6, 5, 5), Vec3<S>(5, 6, 5)},
                                   {{0, 1, 2}, {3, 4, 5}});
        int hits = 0;
        for (const Ray<S>& ray : rays_through(v, rng)) {
            if (tri.intersect(ray)) ++hits;
            if (mesh.intersect(ray)) ++hits;
            if (mesh.occluded(ray)) ++hits;
        }
        CHECK(hits == 0);
    }
}

TEMPLATE_TEST_CASE("a triangle so small that its normal's squared length underflows still has a unit normal",
                   "[hard][geometry]", float, double) {
    using S = TestType;
    constexpr S tiny = std::is_same_v<S, float> ? S(1e-19) : S(1e-150);
    const std::array<Vec3<S>, 3> v{Vec3<S>(0, 0, 0), Vec3<S>(tiny, 0, 0), Vec3<S>(0, tiny, 0)};
    const Triangle<S> tri(v[0], v[1], v[2]);
    const TriangleMesh<S> mesh({v[0], v[1], v[2]}, {{0, 1, 2}});
    CHECK_FALSE(tri.is_degenerate());
    CHECK(tri.normal().z == S(1));
    Pcg32 rng(6, 6);
    int hits = 0, bad = 0;
    for (const Ray<S>& ray : rays_through(v, rng))
        for (const auto& h : {tri.intersect(ray), mesh.intersect(ray)})
            if (h) {
                ++hits;
                if (!valid_hit(*h) || std::abs(h->normal.z) != S(1)) ++bad;
            }
    CHECK(hits > 0);  // the rays along z hit it
    CHECK(bad == 0);
}
