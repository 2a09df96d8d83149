// SPDX-License-Identifier: MIT
// POV-Ray's area light (light/area_light.hpp): its emitters where POV-Ray 3.7 puts them, photons
// leaving them uniformly and isotropically, shadow rays that integrate them exactly (a grid's sum
// and the closed form of a continuous rectangle), soft shadows as wide as the geometry says, and
// photons agreeing with shadow rays and the path tracer, in float and double.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include "mode_mean.hpp"

#include <cmath>
#include <optional>
#include <set>
#include <vector>

using namespace photon;

namespace {

constexpr double area_pi = 3.14159265358979323846;

/// Chi-square critical value at significance 1e-4 (Wilson-Hilferty, z = 3.719).
double area_chi2_critical(int dof) {
    const double k = dof, z = 3.719;
    const double t = 1.0 - 2.0 / (9.0 * k) + z * std::sqrt(2.0 / (9.0 * k));
    return k * t * t * t;
}
double area_chi2(const std::vector<int>& count, int n) {
    const double expected = double(n) / double(count.size());
    double x2 = 0;
    for (const int c : count) x2 += (c - expected) * (c - expected) / expected;
    return x2;
}

/// POV-Ray 3.7's offset of grid light (u, v) (Trace::TraceAreaLightSubsetShadowRay, without
/// jitter), written here from its source independently of AreaLight.
Vec3<double> pov_grid_offset(int u, int v, int n1, int n2, Vec3<double> a1, Vec3<double> a2, bool circular) {
    double ju = u, jv = v;
    if (circular) {
        ju = ju / (n1 - 1) - 0.5 + 0.001;
        jv = jv / (n2 - 1) - 0.5 + 0.001;
        double scale = std::abs(ju) > std::abs(jv) ? std::abs(ju) : std::abs(jv);
        scale /= std::sqrt(ju * ju + jv * jv);
        return a1 * (ju * scale) + a2 * (jv * scale);
    }
    const Vec3<double> o1 = n1 > 1 ? a1 * (ju / (n1 - 1) - 0.5) : Vec3<double>(0.0);
    const Vec3<double> o2 = n2 > 1 ? a2 * (jv / (n2 - 1) - 0.5) : Vec3<double>(0.0);
    return o1 + o2;
}

/// Solid angle of the rectangle [0,a] x [0,b] seen from height h above its corner: the integral of
/// h / r^3 over it, so I / A times it is the irradiance from isotropic emitters spread over it.
double corner_solid_angle(double a, double b, double h) { return std::atan(a * b / (h * std::sqrt(h * h + a * a + b * b))); }

/// A floor y = 0 of albedo 0.5 under `light`, and optionally a thin slab over x < 0 at y in [1, 1.01].
template <Scalar S> DefaultScene<S> area_floor_scene(const AreaLight<S>& light, bool slab) {
    DefaultScene<S> scene;
    const auto white = scene.add_material(Material<S>::lambertian(Rgb<S>(S(0.5))));
    scene.add(Plane<S>({0, 1, 0}, 0), white);
    if (slab) scene.add(Box<S>({-20, 1, -20}, {0, 1.01, 20}), white);
    scene.add_light(light);
    scene.commit();
    return scene;
}

/// Irradiance at floor point p from `scene`'s lights by direct_lighting (radiance pi / albedo).
template <Scalar S> double area_direct(const DefaultScene<S>& scene, const Vec3<S>& p, unsigned samples, unsigned repeats) {
    ShadingContext ctx;
    const Vec3<S> n{0, 1, 0};
    const Material<S> m = Material<S>::lambertian(Rgb<S>(S(0.5)));
    double sum = 0;
    for (unsigned i = 0; i < repeats; ++i)
        sum += double(direct_lighting(scene, p, p + Vec3<S>(0, S(1e-4), 0), n, n, n, m, Rgb<S>(S(0.5)), samples, ctx).x);
    return sum / repeats * area_pi / 0.5;
}

}  // namespace

TEMPLATE_TEST_CASE("area light: emitters on POV-Ray's grid, circular too", "[light][area]", float, double) {
    using S = TestType;
    const Vec3<double> a1(1.2, 0, 0.3), a2(0, 0.2, 0.9);
    for (const bool circular : {false, true}) {
        const AreaLight<S> light{.center = {1, 2, 3}, .axis1 = Vec3<S>(a1), .axis2 = Vec3<S>(a2), .size1 = 4, .size2 = 3,
                                 .circular = circular, .power = Rgb<S>(S(1))};
        light.validate();
        for (int v = 0; v < 3; ++v)
            for (int u = 0; u < 4; ++u) {
                // Any u within cell (u, v) picks emitter (u, v).
                for (const double f : {0.01, 0.5, 0.99}) {
                    const Vec3<S> got = light.emitter_offset(Vec2<S>(S((u + f) / 4), S((v + f) / 3)));
                    const Vec3<double> want = pov_grid_offset(u, v, 4, 3, a1, a2, circular);
                    INFO("circular " << circular << " emitter " << u << ", " << v);
                    CHECK(glm::length(Vec3<double>(got) - want) < 1e-6);
                    CHECK(glm::length(Vec3<double>(got)) <= double(light.bounding_radius()) * (1 + 1e-6));
                }
            }
    }
    // Degenerate grids are allowed (a line, a point); sizes of 0 and circular 1-wide grids are not.
    CHECK_NOTHROW(AreaLight<S>{.axis1 = {1, 0, 0}, .size1 = 5, .size2 = 5, .power = Rgb<S>(S(1))}.validate());
    CHECK_THROWS_AS((AreaLight<S>{.size1 = 0, .power = Rgb<S>(S(1))}.validate()), std::invalid_argument);
    CHECK_THROWS_AS((AreaLight<S>{.axis1 = {1, 0, 0}, .axis2 = {0, 0, 1}, .size1 = 1, .size2 = 4, .circular = true,
                                  .power = Rgb<S>(S(1))}.validate()),
                    std::invalid_argument);
    CHECK_THROWS_AS((AreaLight<S>{.axis1 = {S(NAN), 0, 0}, .power = Rgb<S>(S(1))}.validate()), std::invalid_argument);
}

TEMPLATE_TEST_CASE("area light photons: on the grid or uniform over the jittered parallelogram, isotropic", "[light][area][photons]",
                   float, double) {
    using S = TestType;
    const Vec3<double> c(0.5, 3, -1), a1(2, 0, 0), a2(0.5, 0, 1);  // a parallelogram, not a rectangle
    constexpr int n = 60'000;
    // The grid: each of the 3 x 2 emitters equally often.
    {
        const Light<S> light = AreaLight<S>{.center = Vec3<S>(c), .axis1 = Vec3<S>(a1), .axis2 = Vec3<S>(a2), .size1 = 3,
                                            .size2 = 2, .power = Rgb<S>(S(1))};
        Pcg32 rng(7, 1);
        std::vector<int> count(6, 0);
        for (int i = 0; i < n; ++i) {
            const Vec3<S> d = sample_emission_direction(light, EmissionSampler::direct, rng);
            const Vec3<double> o = Vec3<double>(sample_emission_origin(light, d, rng.uniform2<S>())) - c;
            int found = -1;
            for (int k = 0; k < 6; ++k)
                if (glm::length(o - pov_grid_offset(k % 3, k / 3, 3, 2, a1, a2, false)) < 1e-5) found = k;
            REQUIRE(found >= 0);
            ++count[std::size_t(found)];
        }
        CHECK(area_chi2(count, n) < area_chi2_critical(5));
    }
    // Jittered 4 x 3: uniform over the parallelogram of axes A1 4/3 and A2 3/2 (half a cell wider
    // each side), in 8 x 8 cells of its own coordinates; directions uniform in z and azimuth.
    const Light<S> light = AreaLight<S>{.center = Vec3<S>(c), .axis1 = Vec3<S>(a1), .axis2 = Vec3<S>(a2), .size1 = 4,
                                        .size2 = 3, .jitter = true, .power = Rgb<S>(S(1))};
    const Vec3<double> e1 = a1 * (4.0 / 3.0), e2 = a2 * 1.5;
    Pcg32 rng(7, 2);
    std::vector<int> where(64, 0), towards(64, 0);
    for (int i = 0; i < n; ++i) {
        const Vec3<S> d = sample_emission_direction(light, EmissionSampler::direct, rng);
        const Vec3<double> o = Vec3<double>(sample_emission_origin(light, d, rng.uniform2<S>())) - c;
        // o = s e1 + t e2 with e1, e2 in the plane y = 0: solve the 2 x 2 system in x, z.
        const double det = e1.x * e2.z - e1.z * e2.x;
        const double s = (o.x * e2.z - o.z * e2.x) / det, t = (e1.x * o.z - e1.z * o.x) / det;
        REQUIRE(std::abs(o.y) < 1e-5);
        REQUIRE(std::abs(s) <= 0.5 + 1e-5);
        REQUIRE(std::abs(t) <= 0.5 + 1e-5);
        const int si = std::clamp(int((s + 0.5) * 8), 0, 7), ti = std::clamp(int((t + 0.5) * 8), 0, 7);
        ++where[std::size_t(si * 8 + ti)];
        double phi = std::atan2(double(d.y), double(d.x));
        if (phi < 0) phi += 2 * area_pi;
        const int zi = std::clamp(int((double(d.z) + 1) * 4), 0, 7), pi = std::clamp(int(phi / (2 * area_pi) * 8), 0, 7);
        ++towards[std::size_t(zi * 8 + pi)];
    }
    CHECK(area_chi2(where, n) < area_chi2_critical(63));
    CHECK(area_chi2(towards, n) < area_chi2_critical(63));
    // The test can fail: the unjittered parallelogram (A1, A2) would leave the outer cells empty.
    std::vector<int> narrow(64, 0);
    for (int i = 0; i < n; ++i) {
        const double s = rng.uniform<double>() - 0.5, t = rng.uniform<double>() - 0.5;
        const double s2 = s * 3.0 / 4.0, t2 = t * 2.0 / 3.0;  // in units of e1, e2
        ++narrow[std::size_t(std::clamp(int((s2 + 0.5) * 8), 0, 7) * 8 + std::clamp(int((t2 + 0.5) * 8), 0, 7))];
    }
    CHECK(area_chi2(narrow, n) > area_chi2_critical(63));
}

TEMPLATE_TEST_CASE("area light shadow rays: a grid's exact sum, a jittered rectangle's closed form", "[light][area]", float, double) {
    using S = TestType;
    const double I = 2.0;  // W/sr
    const Rgb<S> power(S(4 * area_pi * I));
    // The 3 x 3 grid over a 1 x 0.6 rectangle 0.5 above the floor: sum over the emitters of
    // (I / 9) cos / d^2, one shadow ray per emitter.
    const AreaLight<S> grid{.center = {0, 0.5, 0}, .axis1 = {1, 0, 0}, .axis2 = {0, 0, 0.6}, .size1 = 3, .size2 = 3, .power = power};
    const auto grid_scene = area_floor_scene(grid, false);
    for (const double x : {0.0, 0.3, 1.5}) {
        double want = 0;
        for (int k = 0; k < 9; ++k) {
            const Vec3<double> e = Vec3<double>(0, 0.5, 0) + pov_grid_offset(k % 3, k / 3, 3, 3, {1, 0, 0}, {0, 0, 0.6}, false);
            const Vec3<double> to = e - Vec3<double>(x, 0, 0.1);
            const double d = glm::length(to);
            want += I / 9 * (to.y / d) / (d * d);
        }
        INFO("x = " << x);
        CHECK(area_direct(grid_scene, Vec3<S>(S(x), 0, S(0.1)), 9, 1) == Approx(want).epsilon(1e-4));
        CHECK(area_direct(grid_scene, Vec3<S>(S(x), 0, S(0.1)), 16, 1) == Approx(want).epsilon(1e-4));
    }
    // POV-Ray's light without a fade (constant falloff) with `area_illumination`: each emitter
    // lights by (I / 9) cos, whatever its distance.
    AreaLight<S> constant = grid;
    constant.falloff = Falloff<S>::constant(S(1));
    const auto constant_scene = area_floor_scene(constant, false);
    for (const double x : {0.0, 0.3, 1.5}) {
        double want = 0;
        for (int k = 0; k < 9; ++k) {
            const Vec3<double> e = Vec3<double>(0, 0.5, 0) + pov_grid_offset(k % 3, k / 3, 3, 3, {1, 0, 0}, {0, 0, 0.6}, false);
            const Vec3<double> to = e - Vec3<double>(x, 0, 0.1);
            want += I / 9 * to.y / glm::length(to);
        }
        INFO("constant falloff, x = " << x);
        CHECK(area_direct(constant_scene, Vec3<S>(S(x), 0, S(0.1)), 9, 1) == Approx(want).epsilon(1e-4));
    }
    // Jittered 2 x 5 with axes 1 and 0.6: the continuous rectangle 2 x 0.75 (half a cell wider per
    // side), I / A times its solid angle below its centre; 4000 calls of 10 stratified rays each
    // (0.3% standard deviation, measured).
    const AreaLight<S> jittered{.center = {0, 0.5, 0}, .axis1 = {1, 0, 0}, .axis2 = {0, 0, 0.6}, .size1 = 2, .size2 = 5,
                                .jitter = true, .power = power};
    const double a = 2.0, b = 0.75, h = 0.5;
    const double want = I / (a * b) * 4 * corner_solid_angle(a / 2, b / 2, h);
    const double got = area_direct(area_floor_scene(jittered, false), Vec3<S>(0, 0, 0), 10'000, 4000);
    INFO("jittered: " << got << " want " << want << " (a point light: " << I / (h * h) << ")");
    CHECK(got == Approx(want).epsilon(0.01));
    // Zero axes: every emitter at the centre, a point light's I cos / d^2.
    const AreaLight<S> point{.center = {0, 0.5, 0}, .size1 = 4, .size2 = 4, .jitter = true, .power = power};
    const double d2 = 0.5 * 0.5 + 0.5 * 0.5;
    CHECK(area_direct(area_floor_scene(point, false), Vec3<S>(0.5, 0, 0), 16, 1) == Approx(I * (0.5 / std::sqrt(d2)) / d2).epsilon(1e-4));
}

TEMPLATE_TEST_CASE("area light soft shadow: the penumbra where the geometry puts it", "[light][area][shadow]", float, double) {
    using S = TestType;
    // Light 2 above the floor, a slab over x < 0 at y in [1, 1.01]. An emitter at height 2 and x_e
    // lights floor point x_f unless the segment between them passes x < 0 at y = 1 or 1.01.
    const auto lit = [](double xf, double xe) {
        for (const double y : {1.0, 1.01})
            if (xf + (xe - xf) * y / 2 < 0) return false;
        return true;
    };
    const Rgb<S> power(S(4 * area_pi));  // I = 1
    // The 5 x 2 grid: exactly the unblocked emitters' I / 10 cos / d^2 (its shadow has steps).
    const AreaLight<S> grid{.center = {0, 2, 0}, .axis1 = {1.2, 0, 0}, .axis2 = {0, 0, 0.4}, .size1 = 5, .size2 = 2, .power = power};
    const auto grid_scene = area_floor_scene(grid, true);
    for (const double x : {-0.7, -0.45, -0.2, -0.05, 0.05, 0.2, 0.45, 0.7}) {
        double want = 0;
        for (int k = 0; k < 10; ++k) {
            const Vec3<double> e = Vec3<double>(0, 2, 0) + pov_grid_offset(k % 5, k / 5, 5, 2, {1.2, 0, 0}, {0, 0, 0.4}, false);
            if (!lit(x, e.x)) continue;
            const Vec3<double> to = e - Vec3<double>(x, 0, 0);
            const double d = glm::length(to);
            want += 0.1 * (to.y / d) / (d * d);
        }
        INFO("grid, x = " << x);
        CHECK(area_direct(grid_scene, Vec3<S>(S(x), 0, 0), 10, 1) == Approx(want).epsilon(1e-4).margin(1e-9));
    }
    // Jittered 4 x 1 with A1 = 1.2: emitters over x in [-0.8, 0.8]. Umbra for x_f < -0.8 (the
    // rightmost emitter hidden by the slab's lower face), full light for x_f > 0.8 * 1.01 / 0.99
    // (the leftmost emitter clear of its upper face); in between, partly lit.
    const AreaLight<S> soft{.center = {0, 2, 0}, .axis1 = {1.2, 0, 0}, .size1 = 4, .size2 = 1, .jitter = true, .power = power};
    const auto soft_scene = area_floor_scene(soft, true);
    const auto open_scene = area_floor_scene(soft, false);
    const double umbra = -0.8, full = 0.8 * 1.01 / 0.99;
    REQUIRE(lit(full + 1e-9, -0.8));
    REQUIRE_FALSE(lit(umbra - 1e-9, 0.8));
    CHECK(area_direct(soft_scene, Vec3<S>(S(umbra - 0.02), 0, 0), 64, 4) == 0.0);
    CHECK(area_direct(soft_scene, Vec3<S>(S(umbra + 0.2), 0, 0), 64, 64) > 0.0);  // emitters x_e > 0.6 lit
    const double clear = area_direct(open_scene, Vec3<S>(S(full + 0.02), 0, 0), 64, 4);
    CHECK(area_direct(soft_scene, Vec3<S>(S(full + 0.02), 0, 0), 64, 4) == Approx(clear).epsilon(1e-9));
    const double inside = area_direct(soft_scene, Vec3<S>(S(full - 0.05), 0, 0), 64, 4);
    CHECK(inside < 0.999 * area_direct(open_scene, Vec3<S>(S(full - 0.05), 0, 0), 64, 4));
    // Half way across, about half the light (the emitters left of x_f = 0 are blocked).
    const double middle = area_direct(soft_scene, Vec3<S>(0, 0, 0), 64, 50) / area_direct(open_scene, Vec3<S>(0, 0, 0), 64, 50);
    CHECK(middle > 0.35);
    CHECK(middle < 0.6);
}

TEST_CASE("adaptive area light: corners first, split where their shadows differ, as POV-Ray's", "[light][area][adaptive]") {
    // A 9 x 9 grid whose emitters with i < 4 are hidden (a shadow's edge through the grid); each
    // emitter's light is i + 10 j, so the averages say which emitters were counted and how.
    std::vector<std::optional<GridSample<double>>> grid;
    std::set<std::pair<unsigned, unsigned>> asked;
    auto grid_sample = [&](bool edge) {
        return [&asked, edge](unsigned i, unsigned j) {
            asked.insert({i, j});
            const bool seen = !edge || i >= 4;
            return GridSample<double>{Rgb<double>(seen ? double(i + 10 * j) : 0.0), Rgb<double>(seen ? 1.0 : 0.0)};
        };
    };
    // Wholly seen, level 0: the four corners stand for the grid, POV-Ray's mean of them.
    Rgb<double> light = adaptive_grid_light<double>(9, 9, 0, grid_sample(false), grid);
    CHECK(asked.size() == 4);
    CHECK(light.x == Approx((0 + 8 + 80 + 88) / 4.0));
    // Level 1: one split however alike the corners, 3 x 3 grid points, each quarter's mean counted once.
    asked.clear();
    light = adaptive_grid_light<double>(9, 9, 1, grid_sample(false), grid);
    CHECK(asked.size() == 9);
    // A linear light: every quarter's corner mean is its centre's value, and so is the whole's.
    CHECK(light.x == Approx(4 + 40));
    // The edge: regions straddling i = 4 split down to neighbouring grid points; regions wholly on
    // one side do not. Fewer rays than the grid's 81, more than the corners.
    asked.clear();
    light = adaptive_grid_light<double>(9, 9, 0, grid_sample(true), grid);
    CHECK(asked.size() > 9);
    CHECK(asked.size() < 81);
    for (unsigned j = 0; j < 9; j += 8) {  // along the edges i = 3, 4 meet where the split resolves the edge
        CHECK(asked.count({3, j}) == 1);
        CHECK(asked.count({4, j}) == 1);
    }
    CHECK(light.x > 0.0);
    // A 1 x 1 light is its one emitter; a 1 x N light splits along its one axis only.
    asked.clear();
    CHECK(adaptive_grid_light<double>(1, 1, 3, grid_sample(false), grid).x == 0.0);
    CHECK(asked.size() == 1);
    asked.clear();
    light = adaptive_grid_light<double>(1, 5, 2, grid_sample(false), grid);
    CHECK(asked.size() == 5);
}

TEMPLATE_TEST_CASE("adaptive area light: direct light as the full grid's where nothing casts a shadow, few rays",
                   "[light][area][adaptive]", float, double) {
    using S = TestType;
    const Rgb<S> power(S(4 * area_pi));
    AreaLight<S> light{.center = {0, 2, 0}, .axis1 = {0.2, 0, 0}, .axis2 = {0, 0, 0.2}, .size1 = 10, .size2 = 10, .power = power};
    const auto full_scene = area_floor_scene(light, false);
    light.adaptive = 1;
    const auto adaptive_scene = area_floor_scene(light, false);
    const auto shadowed_scene = area_floor_scene(light, true);
    const Vec3<S> n{0, 1, 0};
    const Material<S> m = Material<S>::lambertian(Rgb<S>(S(0.5)));
    const DirectLightOptions povray{.adaptive_area_lights = true};
    for (const double x : {0.3, 1.5}) {
        const Vec3<S> p(S(x), 0, 0), above(S(x), S(1e-4), 0);
        ShadingContext full_ctx, adaptive_ctx;
        const double full = double(direct_lighting(full_scene, p, above, n, n, n, m, m.diffuse(), 100, full_ctx).x);
        const double adaptive = double(direct_lighting(adaptive_scene, p, above, n, n, n, m, m.diffuse(), 100, adaptive_ctx, povray).x);
        CHECK(full_ctx.rays.shadow == 100);
        // Level 1 and no shadow: the corners of the quarters [0, 4] and [5, 9] on each axis.
        CHECK(adaptive_ctx.rays.shadow == 16);
        CHECK(adaptive == Approx(full).epsilon(0.01));  // a small light: its corners' mean is its mean
        // Options off (the judges): the adaptive light takes every emitter.
        ShadingContext judge_ctx;
        (void)direct_lighting(adaptive_scene, p, above, n, n, n, m, m.diffuse(), 100, judge_ctx);
        CHECK(judge_ctx.rays.shadow == 100);
    }
    // In the slab's penumbra at x = 0.02 the emitters with x < -0.02 (columns 0 to 3) are hidden:
    // the quarter [0, 4] is split where its corners differ. More rays than the 16 of an open view.
    ShadingContext edge_ctx;
    const double edge = double(direct_lighting(shadowed_scene, Vec3<S>(S(0.02), 0, 0), Vec3<S>(S(0.02), S(1e-4), 0), n, n, n, m,
                                               m.diffuse(), 100, edge_ctx, povray).x);
    CHECK(edge_ctx.rays.shadow > 16);
    CHECK(edge > 0.0);
}

TEMPLATE_TEST_CASE("area light photons: first-hit irradiance equals the shadow rays'", "[light][area][photons]", float, double) {
    using S = TestType;
    // Near the floor (0.5 above, 1 wide), where an area light lights very differently from a point
    // light (half as brightly below its centre): grid, jittered and circular lights.
    const Rgb<S> power(S(8));
    for (const AreaLight<S>& light :
         {AreaLight<S>{.center = {0, 0.5, 0}, .axis1 = {1, 0, 0}, .axis2 = {0, 0, 0.8}, .size1 = 3, .size2 = 2, .power = power},
          AreaLight<S>{.center = {0, 0.5, 0}, .axis1 = {1, 0, 0}, .axis2 = {0, 0, 0.8}, .size1 = 3, .size2 = 2, .jitter = true, .power = power},
          AreaLight<S>{.center = {0, 0.5, 0}, .axis1 = {1, 0, 0}, .axis2 = {0, 0, 1}, .size1 = 5, .size2 = 5, .jitter = true,
                       .circular = true, .power = power},
          // POV-Ray's default light, which does not fall off: each emitter's photons rescaled
          // by their own distance at the first hit.
          AreaLight<S>{.center = {0, 0.5, 0}, .axis1 = {1, 0, 0}, .axis2 = {0, 0, 0.8}, .size1 = 3, .size2 = 2, .jitter = true,
                       .power = power, .falloff = Falloff<S>::constant(S(1))}}) {
        const auto scene = area_floor_scene(light, false);
        const PhotonTracingSettings settings{.photons = 600'000, .store = {.direct = true, .caustic = false, .indirect = false}, .seed = 9};
        const PhotonMap map(trace_global_photons(scene, settings).photons);
        // Of 600k photons about 300k land within 1 of the centre (density ~1e5 per unit area):
        // k = 2000 is 2.2% standard deviation in a disc of radius ~0.08.
        const EstimateSettings estimate{.k = 2'000, .max_radius = 0.5f};
        EstimateScratch scratch;
        for (const double x : {0.0, 0.45}) {
            const Vec3<S> p(S(x), S(0), S(0.1));
            const double shadow_rays = area_direct(scene, p, 400, 500);  // 3000 rays or more: 1% noise
            const Rgb<double> e = estimate_irradiance(map, Vec3<double>(p), Vec3<double>{0, 1, 0}, estimate, scratch);
            INFO("jitter " << light.jitter << " circular " << light.circular << " falloff " << int(light.falloff.kind) << " at x = " << x << ": photons " << e.x
                           << ", shadow rays " << shadow_rays);
            CHECK(e.x == Approx(shadow_rays).epsilon(0.08));
        }
    }
}

TEST_CASE("area light: photon mapping, SPPM and the path tracer agree", "[light][area][render]") {
    // A floor, a wall at x = 1 and a box casting a soft shadow under a jittered area light.
    DefaultScene<double> scene;
    const auto white = scene.add_material(Material<double>::lambertian(Rgb<double>(0.6)));
    scene.add(Plane<double>({0, 1, 0}, 0), white);
    scene.add(Plane<double>({-1, 0, 0}, -1), white);
    scene.add(Box<double>({-0.3, 0, -0.3}, {0.1, 0.4, 0.1}), white);
    scene.add_light(AreaLight<double>{.center = {0, 1.2, 0}, .axis1 = {0.8, 0, 0}, .axis2 = {0, 0, 0.8}, .size1 = 4,
                                      .size2 = 4, .jitter = true, .power = Rgb<double>(30)});
    scene.commit();
    const auto camera = PinholeCamera<double>::look_at({-0.8, 1.8, -1.8}, {0.2, 0.2, 0}, {0, 1, 0}, 50, 1.0);
    const auto mean = [&](RenderMode mode, unsigned spp) { return photon_test::mode_mean(scene, camera, mode, spp); };
    const double rt = mean(RenderMode::rt, 4), pm = mean(RenderMode::pm, 4), reference = mean(RenderMode::reference, 48),
                 sppm = mean(RenderMode::sppm, 1);
    INFO("rt " << rt << ", pm " << pm << ", reference " << reference << ", sppm " << sppm);
    CHECK(pm > 1.05 * rt);  // indirect light is there
    CHECK(pm == Approx(reference).epsilon(0.03));
    CHECK(sppm == Approx(reference).epsilon(0.03));
}

TEMPLATE_TEST_CASE("area light hard cases: a point on an emitter, a light in the floor, far and tiny lights", "[light][area][hard]",
                   float, double) {
    using S = TestType;
    const Rgb<S> power(S(10));
    // Floor point exactly on an emitter of a grid lying in the floor: that emitter adds nothing,
    // the others light it edge-on (cos 0): finite and 0.
    const AreaLight<S> in_floor{.center = {0, 0, 0}, .axis1 = {1, 0, 0}, .axis2 = {0, 0, 1}, .size1 = 3, .size2 = 3, .power = power};
    const Light<S> light = in_floor;
    CHECK_FALSE(sample_incident(light, Vec3<S>(0, 0, 0), Vec2<S>(S(0.5))));
    const double on = area_direct(area_floor_scene(in_floor, false), Vec3<S>(0, 0, 0), 9, 1);
    CHECK(on == 0.0);
    // 1e5 away and 1e-4 wide: the grid's light is the point light's I cos / d^2 to 1e-5.
    for (const double far : {1e-3, 1e5}) {
        const AreaLight<S> small{.center = {0, S(far), 0}, .axis1 = {S(1e-4 * far), 0, 0}, .axis2 = {0, 0, S(1e-4 * far)},
                                 .size1 = 4, .size2 = 4, .jitter = true, .power = power};
        const double want = 10 / (4 * area_pi) / (far * far);
        INFO("height " << far);
        CHECK(area_direct(area_floor_scene(small, false), Vec3<S>(0, 0, 0), 16, 2) == Approx(want).epsilon(1e-5));
    }
    // The effects plan and the reference see area lights as lights of their bounding ball.
    CHECK(double(light_radius(light)) == Approx(1.0));  // 0.5 |A1| + 0.5 |A2|
    CHECK_FALSE(light_has_surface(light));
    CHECK_FALSE(intersect_light(light, Ray<S>{{0, 1, 0}, {0, -1, 0}}));
}

TEST_CASE("a sphere light with one shadow ray per point still samples the whole sphere", "[light][shadow]") {
    // Half the sphere hidden behind a slab's edge: one random shadow ray per call, averaged, must
    // match many rays per call (a fixed sample would see all or nothing of it).
    DefaultScene<double> scene;
    const auto white = scene.add_material(Material<double>::lambertian(Rgb<double>(0.5)));
    scene.add(Plane<double>({0, 1, 0}, 0), white);
    scene.add(Box<double>({-20, 1, -20}, {0, 1.01, 20}), white);
    scene.add_light(SphereLight<double>{.center = {0, 2, 0}, .radius = 0.3, .power = Rgb<double>(10)});
    scene.commit();
    const Vec3<double> p{0, 0, 0};
    const double one = area_direct(scene, p, 1, 20'000), many = area_direct(scene, p, 64, 400);
    INFO("1 ray: " << one << ", 64 rays: " << many);
    CHECK(many > 0.0);
    CHECK(one == Approx(many).epsilon(0.03));
}
