// SPDX-License-Identifier: MIT
// POV-Ray's normal patterns (normal_pattern.hpp) and the shading-normal guards of facing():
// unit results, no tilt at bump size 0, determinism, float and double, an analytic slope, the
// placement's maths, and grazing views that must not give NaN or a normal below the surface.

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include <photon/material/scatter.hpp>
#include <photon/math/rng.hpp>
#include <photon/texture/normal_pattern.hpp>

using namespace photon;

namespace {

const NormalKind all_normal_kinds[] = {NormalKind::bumps,    NormalKind::dents, NormalKind::ripples,
                                       NormalKind::waves,    NormalKind::wrinkles, NormalKind::slope};

NormalPattern normal_of(NormalKind kind, double amount = 0.5) {
    NormalPattern np;
    np.kind = kind;
    np.amount = amount;
    if (kind == NormalKind::slope) np.pattern = Pattern::of(PatternKind::bozo);
    return np;
}

template <Scalar S> Vec3<S> random_unit_normal(Pcg32& rng) {
    for (;;) {
        const Vec3<S> v(rng.uniform<S>() * 2 - 1, rng.uniform<S>() * 2 - 1, rng.uniform<S>() * 2 - 1);
        const S l = glm::length(v);
        if (l > S(0.1) && l <= S(1)) return v / l;
    }
}

}  // namespace

TEMPLATE_TEST_CASE("normal patterns give unit, finite, deterministic normals", "[texture][normal]", float, double) {
    using S = TestType;
    Pcg32 rng(7, 3);
    for (NormalKind kind : all_normal_kinds) {
        NormalPattern np = normal_of(kind, 1.5);
        np.pattern.turbulence = Vec3<double>(0.4);
        const NormalPerturbation<S> bump(np, Affine<double>::scale({0.3, 0.3, 0.3}));
        const NormalPerturbation<S> copy = bump;
        double tilt = 0;
        for (int i = 0; i < 200; ++i) {
            const Vec3<S> p(rng.uniform<S>() * 20 - 10, rng.uniform<S>() * 20 - 10, rng.uniform<S>() * 20 - 10);
            const Vec3<S> n = random_unit_normal<S>(rng);
            const Vec3<S> b = bump(p, n);
            INFO("kind " << int(kind) << " at <" << p.x << ", " << p.y << ", " << p.z << ">");
            REQUIRE(is_finite(b));
            REQUIRE(glm::length(b) == Approx(1.0).margin(1e-5));
            REQUIRE(copy(p, n) == b);  // the same inputs give the same normal, in any copy
            tilt += double(glm::length(b - n));
        }
        INFO("kind " << int(kind));
        CHECK(tilt / 200 > 0.02);  // it does tilt the normal
    }
}

TEMPLATE_TEST_CASE("a bump size of zero leaves the geometric normal", "[texture][normal]", float, double) {
    using S = TestType;
    Pcg32 rng(11, 5);
    for (NormalKind kind : all_normal_kinds) {
        const NormalPerturbation<S> flat(normal_of(kind, 0.0), Affine<double>::rotate_xyz({10, 20, 30}));
        for (int i = 0; i < 50; ++i) {
            const Vec3<S> p(rng.uniform<S>() * 8 - 4, rng.uniform<S>() * 8 - 4, rng.uniform<S>() * 8 - 4);
            const Vec3<S> n = random_unit_normal<S>(rng);
            const Vec3<S> b = flat(p, n);
            CHECK(glm::length(b - n) < S(1e-5));
        }
    }
}

TEST_CASE("the slope of gradient x tilts a floor's normal by POV-Ray's amount", "[texture][normal]") {
    // Four tetrahedron points around q, value x at each: sum v_i (v_i . x) = 4/3 x, times the
    // accuracy and POV-Ray's factor -5 * amount * 0.02 / accuracy: -5 * 0.5 * 0.02 * 4/3 = -1/15.
    NormalPattern np;
    np.kind = NormalKind::slope;
    np.pattern = Pattern::of(PatternKind::gradient);
    const NormalPerturbation<double> slope(np);
    const Vec3<double> b = slope({0.5, 0.0, 0.25}, {0, 1, 0});
    const Vec3<double> expected = glm::normalize(Vec3<double>(-1.0 / 15.0, 1, 0));
    CHECK(b.x == Approx(expected.x).margin(1e-9));
    CHECK(b.y == Approx(expected.y).margin(1e-9));
    CHECK(b.z == Approx(0.0).margin(1e-9));
}

TEST_CASE("quilted adds POV-Ray's quilt offset times the bump size", "[texture][normal]") {
    NormalPattern np;
    np.kind = NormalKind::quilted;
    np.amount = 0.4;
    const NormalPerturbation<double> quilted(np);
    // At a cell's centre the offset is zero; a quarter from it along x, with both controls 1, the
    // cubic is 0.25^3 + 3 0.25 0.75^2 + 3 0.25^2 0.75 = 0.578125, times 1.154700538.
    const Vec3<double> centre = quilted({0.5, 0.5, 0.5}, {0, 1, 0});
    CHECK(centre.y == Approx(1.0));
    const Vec3<double> b = quilted({0.25, 0.5, 0.5}, {0, 1, 0});
    const Vec3<double> expected = glm::normalize(Vec3<double>(-0.25 * 0.578125 * 1.154700538 * 0.4, 1, 0));
    CHECK(b.x == Approx(expected.x).margin(1e-9));
    CHECK(b.y == Approx(expected.y).margin(1e-9));
    CHECK(b.z == Approx(0.0).margin(1e-9));
}

TEST_CASE("a uniformly scaled normal pattern is the same pattern, larger, and as steep", "[texture][normal]") {
    // POV-Ray takes the normal into the pattern's space and back: a uniform scale changes where
    // the bumps are, not how much they tilt.
    for (NormalKind kind : all_normal_kinds) {
        const NormalPerturbation<double> unit(normal_of(kind));
        const NormalPerturbation<double> big(normal_of(kind), Affine<double>::scale({4, 4, 4}));
        const Vec3<double> n = glm::normalize(Vec3<double>(0.2, 1, -0.3));
        for (const Vec3<double>& q : {Vec3<double>(0.3, 0.7, -1.1), Vec3<double>(2.5, -0.25, 3.0)}) {
            const Vec3<double> a = unit(q, n), b = big(4.0 * q, n);
            INFO("kind " << int(kind));
            CHECK(glm::length(a - b) < 1e-9);
        }
    }
}

TEMPLATE_TEST_CASE("guarded shading normals stay above the surface and face the viewer, even grazing",
                   "[texture][normal][hard]", float, double) {
    using S = TestType;
    const Vec3<S> n(0, 0, 1);
    // Tilts of every kind, some past the tangent plane, against views from normal to exactly grazing.
    const std::vector<Vec3<S>> tilts = {glm::normalize(Vec3<S>(1, 0, S(0.2))), glm::normalize(Vec3<S>(-1, 0, S(0.05))),
                                        glm::normalize(Vec3<S>(0, 1, S(-0.3))), Vec3<S>(1, 0, 0), n};
    for (const S cos_wo : {S(1), S(0.3), S(1e-3), S(1e-6), S(1e-9), S(0)}) {
        const Vec3<S> wo = glm::normalize(Vec3<S>(std::sqrt(S(1) - cos_wo * cos_wo), 0, cos_wo));
        const S c = glm::dot(wo, n);
        for (const Vec3<S>& t : tilts) {
            const Vec3<S> g = guard_shading_normal(t, n, wo, c);
            INFO("cos_wo " << cos_wo << ", tilt <" << t.x << ", " << t.y << ", " << t.z << ">");
            REQUIRE(is_finite(g));
            CHECK(glm::length(g) == Approx(1.0).margin(1e-5));
            CHECK(glm::dot(g, n) >= S(0));
            CHECK(glm::dot(g, wo) >= S(0));
            if (glm::dot(t, wo) >= min_shading_cos<S> && glm::dot(t, n) >= S(0)) CHECK(g == t);  // untouched
        }
    }
}

TEMPLATE_TEST_CASE("facing() under a normal field: two normals, and none without one", "[texture][normal]", float,
                   double) {
    using S = TestType;
    const Material<S> plain = Material<S>::lambertian(Rgb<S>(S(0.5)));
    MaterialParams<S> params{.diffuse = Rgb<S>(S(0.5))};
    params.normal_field = AnyNormalField<S>(NormalPerturbation<S>(normal_of(NormalKind::bumps, 1.0)));
    const Material<S> bumpy(params);
    const Vec3<S> n(0, 1, 0);
    Pcg32 rng(3, 9);
    for (int i = 0; i < 100; ++i) {
        const Vec3<S> p(rng.uniform<S>() * 10, 0, rng.uniform<S>() * 10);
        const Vec3<S> dir = glm::normalize(Vec3<S>(rng.uniform<S>() - S(0.5), i % 2 ? S(-1) : S(1), rng.uniform<S>()));
        const Facing<S> a = facing(plain, p, n, dir);
        CHECK(!a.perturbed);
        CHECK(a.shading == a.normal);
        CHECK(shading_ratio(a) == S(1));
        const Facing<S> b = facing(bumpy, p, n, dir);
        CHECK(b.perturbed);
        CHECK(b.normal == a.normal);  // the geometric normal is untouched
        CHECK(glm::dot(b.shading, b.normal) > S(0));
        CHECK(b.shading_cos > S(0));
        CHECK(shading_ratio(b) <= max_shading_ratio<S>);
    }
}

TEST_CASE("a normal pattern rejects a non-finite bump size and a non-positive accuracy", "[texture][normal]") {
    NormalPattern np;
    np.amount = std::nan("");
    CHECK_THROWS_AS(NormalPerturbation<float>(np), std::invalid_argument);
    np.amount = 0.5;
    np.accuracy = 0;
    CHECK_THROWS_AS(NormalPerturbation<float>(np), std::invalid_argument);
}
