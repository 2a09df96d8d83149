// SPDX-License-Identifier: MIT
// Patterns, waves, colour maps and pigments against POV-Ray 3.7's own values: pov_reference.pov
// prints each pattern's value at six points through a pigment function (POV-Ray's colours are
// single precision, hence the 2e-6 tolerance); scripts/pov-pattern-reference.sh regenerates
// pov_reference_values.inc from the installed povray. And the Material's texture contract.

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include <photon/material/material.hpp>
#include <photon/texture/pigment.hpp>

using namespace photon;

namespace {

struct Reference {
    const char* name;
    std::array<double, 6> values;
};
const Reference pov_values[] = {
#include "pov_reference_values.inc"
};
const std::array<Vec3<double>, 6> points = {{{0.13, 0.27, 0.41},
                                             {1.7, -0.6, 2.3},
                                             {-3.21, 4.05, -0.77},
                                             {10.5, 0.25, -7.125},
                                             {0.5, 0.5, 0.5},
                                             {-0.35, -1.9, 0.62}}};

template <Scalar S> ColorMap<S> ramp() { return ColorMap<S>({{0.0, Rgb<S>(S(0))}, {1.0, Rgb<S>(S(1))}}); }

Pattern with(PatternKind k, const std::function<void(Pattern&)>& f = {}) {
    Pattern p = Pattern::of(k);
    if (f) f(p);
    return p;
}

/// mandel with `iterations`, the colouring of `f` (its iterations replaced) and `scale`.
template <Scalar S> Pigment<S> mandel_pigment(int iterations, FractalParams f, double scale) {
    f.iterations = iterations;
    return Pigment<S>(with(PatternKind::mandel, [&](Pattern& p) { p.fractal = f; }), ramp<S>(),
                      Affine<double>::scale(Vec3<double>(scale)));
}

/// The pigment each reference line names, as the scene language would build it.
template <Scalar S> Pigment<S> pigment_named(const std::string& name) {
    using K = PatternKind;
    const std::map<std::string, std::function<Pigment<S>()>> table = {
        {"checker", [] { return Pigment<S>::checker(Rgb<S>(S(0)), Rgb<S>(S(1))); }},
        {"gradient x", [] { return Pigment<S>(with(K::gradient), ramp<S>()); }},
        {"gradient <1,2,0.5>",
         [] { return Pigment<S>(with(K::gradient, [](Pattern& p) { p.gradient = {1, 2, 0.5}; }), ramp<S>()); }},
        {"bozo", [] { return Pigment<S>(with(K::bozo), ramp<S>()); }},
        {"spotted", [] { return Pigment<S>(with(K::spotted), ramp<S>()); }},
        {"bozo noise_generator 1",
         [] { return Pigment<S>(with(K::bozo, [](Pattern& p) { p.noise_generator = NoiseGenerator::original; }), ramp<S>()); }},
        {"bozo noise_generator 3",
         [] { return Pigment<S>(with(K::bozo, [](Pattern& p) { p.noise_generator = NoiseGenerator::perlin; }), ramp<S>()); }},
        {"bozo turbulence", [] {
             return Pigment<S>(with(K::bozo,
                                    [](Pattern& p) {
                                        p.turbulence = Vec3<double>(0.3);
                                        p.octaves = {.octaves = 3, .omega = 0.7, .lambda = 2.5};
                                    }),
                               ramp<S>());
         }},
        {"granite", [] { return Pigment<S>(with(K::granite), ramp<S>()); }},
        {"granite noise_generator 1",
         [] { return Pigment<S>(with(K::granite, [](Pattern& p) { p.noise_generator = NoiseGenerator::original; }), ramp<S>()); }},
        {"marble", [] { return Pigment<S>(with(K::marble), ramp<S>()); }},
        {"marble turbulence",
         [] { return Pigment<S>(with(K::marble, [](Pattern& p) { p.turbulence = Vec3<double>(0.5); }), ramp<S>()); }},
        {"wood", [] { return Pigment<S>(with(K::wood), ramp<S>()); }},
        {"wood turbulence",
         [] { return Pigment<S>(with(K::wood, [](Pattern& p) { p.turbulence = {0.1, 0.2, 0}; }), ramp<S>()); }},
        {"agate", [] { return Pigment<S>(with(K::agate), ramp<S>()); }},
        {"agate agate_turb 0.5",
         [] { return Pigment<S>(with(K::agate, [](Pattern& p) { p.agate_turb = 0.5; }), ramp<S>()); }},
        {"onion", [] { return Pigment<S>(with(K::onion), ramp<S>()); }},
        {"leopard", [] { return Pigment<S>(with(K::leopard), ramp<S>()); }},
        {"radial", [] { return Pigment<S>(with(K::radial), ramp<S>()); }},
        {"ripples", [] { return Pigment<S>(with(K::ripples), ramp<S>()); }},
        {"waves", [] { return Pigment<S>(with(K::waves), ramp<S>()); }},
        {"spherical",
         [] { return Pigment<S>(with(K::spherical), ramp<S>(), Affine<double>::scale(Vec3<double>(3))); }},
        {"sine_wave", [] {
             return Pigment<S>(with(K::gradient, [](Pattern& p) { p.gradient = {0, 1, 0}, p.wave.type = WaveType::sine; }), ramp<S>());
         }},
        {"triangle_wave", [] {
             return Pigment<S>(with(K::gradient, [](Pattern& p) { p.gradient = {0, 1, 0}, p.wave.type = WaveType::triangle; }),
                               ramp<S>());
         }},
        {"scallop_wave", [] {
             return Pigment<S>(with(K::gradient, [](Pattern& p) { p.gradient = {0, 1, 0}, p.wave.type = WaveType::scallop; }),
                               ramp<S>());
         }},
        {"cubic_wave", [] {
             return Pigment<S>(with(K::gradient, [](Pattern& p) { p.gradient = {0, 1, 0}, p.wave.type = WaveType::cubic; }),
                               ramp<S>());
         }},
        {"frequency phase", [] {
             return Pigment<S>(with(K::gradient,
                                    [](Pattern& p) {
                                        p.gradient = {0, 1, 0};
                                        p.wave.frequency = 3, p.wave.phase = 0.2;
                                    }),
                               ramp<S>());
         }},
        {"transformed granite", [] {
             const Affine<double> placement = Affine<double>::scale({2, 1, 0.5})
                                                  .then(Affine<double>::rotate_xyz({10, 20, 30}))
                                                  .then(Affine<double>::translate({0.3, -1, 2}));
             return Pigment<S>(with(K::granite), ramp<S>(), placement);
         }},
        {"cells", [] { return Pigment<S>(with(K::cells), ramp<S>()); }},
        {"crackle", [] { return Pigment<S>(with(K::crackle), ramp<S>()); }},
        {"crackle scaled",
         [] { return Pigment<S>(with(K::crackle), ramp<S>(), Affine<double>::scale(Vec3<double>(0.37))); }},
        {"crackle form", [] {
             return Pigment<S>(with(K::crackle, [](Pattern& p) { p.crackle.form = {0.3, 0.6, -0.4}; }), ramp<S>(),
                               Affine<double>::scale(Vec3<double>(0.5)));
         }},
        {"crackle metric 1 offset", [] {
             return Pigment<S>(with(K::crackle,
                                    [](Pattern& p) {
                                        p.crackle.metric = 1;
                                        p.crackle.offset = 0.2;
                                    }),
                               ramp<S>(), Affine<double>::scale(Vec3<double>(0.5)));
         }},
        {"crackle metric 3", [] {
             return Pigment<S>(with(K::crackle,
                                    [](Pattern& p) {
                                        p.crackle.metric = 3;
                                        p.crackle.form = {1, 0, 0};
                                    }),
                               ramp<S>());
         }},
        {"crackle solid", [] {
             return Pigment<S>(with(K::crackle, [](Pattern& p) { p.crackle.solid = true; }), ramp<S>(),
                               Affine<double>::scale(Vec3<double>(0.3)));
         }},
        {"bumps", [] { return Pigment<S>(with(K::bumps), ramp<S>()); }},
        {"dents", [] { return Pigment<S>(with(K::dents), ramp<S>(), Affine<double>::scale(Vec3<double>(0.4))); }},
        {"wrinkles", [] { return Pigment<S>(with(K::wrinkles), ramp<S>()); }},
        {"wrinkles noise_generator 1", [] {
             return Pigment<S>(with(K::wrinkles, [](Pattern& p) { p.noise_generator = NoiseGenerator::original; }),
                               ramp<S>(), Affine<double>::scale(Vec3<double>(0.3)));
         }},
        {"wrinkles noise_generator 3", [] {
             return Pigment<S>(with(K::wrinkles, [](Pattern& p) { p.noise_generator = NoiseGenerator::perlin; }), ramp<S>());
         }},
        {"mandel", [] { return mandel_pigment<S>(50, {}, 3); }},
        {"mandel frequency", [] {
             return Pigment<S>(with(K::mandel, [](Pattern& q) {
                                   q.fractal.iterations = 25;
                                   q.wave.frequency = 3;
                               }),
                               ramp<S>(), Affine<double>::scale(Vec3<double>(3)));
         }},
        {"mandel interior 1", [] { return mandel_pigment<S>(30, {.interior_type = 1, .interior_factor = 2}, 3); }},
        {"mandel exterior 6", [] {
             return mandel_pigment<S>(40, {.interior_type = 4, .exterior_type = 6, .interior_factor = 1, .exterior_factor = 0.2}, 3);
         }},
        {"mandel exterior 7", [] {
             return mandel_pigment<S>(40, {.interior_type = 6, .exterior_type = 7, .interior_factor = 0.5, .exterior_factor = 3}, 2);
         }},
        {"spiral1", [] { return Pigment<S>(with(K::spiral1, [](Pattern& p) { p.spiral_arms = 5; }), ramp<S>()); }},
        {"spiral1 ramp", [] {
             return Pigment<S>(with(K::spiral1, [](Pattern& p) {
                                   p.spiral_arms = 3;
                                   p.wave.type = WaveType::ramp;
                                   p.wave.frequency = 0.5;
                               }),
                               ramp<S>());
         }},
        {"spiral2", [] { return Pigment<S>(with(K::spiral2, [](Pattern& p) { p.spiral_arms = 4; }), ramp<S>()); }},
        {"quilted", [] { return Pigment<S>(with(K::quilted), ramp<S>()); }},
        {"quilted controls", [] {
             return Pigment<S>(with(K::quilted, [](Pattern& p) {
                                   p.quilt_control0 = 0.3;
                                   p.quilt_control1 = 0.8;
                               }),
                               ramp<S>(), Affine<double>::scale(Vec3<double>(0.7)));
         }},
        {"color_map", [] {
             return Pigment<S>(with(K::gradient), ColorMap<S>({{0.2, Rgb<S>(S(0.1))},
                                                               {0.5, Rgb<S>(S(0.9))},
                                                               {0.5, Rgb<S>(S(0.3))},
                                                               {0.8, Rgb<S>(S(0.6))}}));
         }},
    };
    return table.at(name)();
}

}  // namespace

TEMPLATE_TEST_CASE("every pattern matches POV-Ray 3.7's value at six points", "[texture]", float, double) {
    using S = TestType;
    // POV-Ray's colours are floats; a float pigment adds its own rounding of the point and colour.
    const double tolerance = std::is_same_v<S, double> ? 2e-6 : 2e-4;
    for (const Reference& ref : pov_values) {
        const Pigment<S> pigment = pigment_named<S>(ref.name);
        for (std::size_t i = 0; i < points.size(); ++i) {
            INFO(ref.name << " at point " << i);
            const Rgb<S> c = pigment(Vec3<S>(points[i]));
            CHECK_THAT(double(c.x), Catch::WithinAbs(ref.values[i], tolerance));
            CHECK(c.x == c.y);
        }
    }
}

TEST_CASE("hexagon picks POV-Ray 3.7's colour on a grid over all four quadrants", "[texture]") {
    struct HexagonSample {
        double x, z;
        int colour;
    };
    const HexagonSample pov_hexagon[] = {
#include "pov_hexagon_values.inc"
    };
    int seen[3] = {0, 0, 0};
    for (const HexagonSample& h : pov_hexagon) {
        INFO("x " << h.x << ", z " << h.z);
        CHECK(pattern_detail::hexagon_colour(h.x, h.z) == h.colour);
        ++seen[h.colour];
    }
    CHECK((seen[0] > 100 && seen[1] > 100 && seen[2] > 100));  // the grid crosses every colour often
    // Through the scene language's path: the three listed colours at 0, 1/2 and 1 of the map.
    const Pigment<double> pigment(Pattern::of(PatternKind::hexagon),
                                  ColorMap<double>({{0.0, Rgb<double>(0.1)}, {0.5, Rgb<double>(0.4)}, {1.0, Rgb<double>(0.9)}}));
    const double listed[3] = {0.1, 0.4, 0.9};
    for (const HexagonSample& h : pov_hexagon) CHECK(pigment(Vec3<double>(h.x, 7.0, h.z)).x == listed[h.colour]);
}

TEST_CASE("noise stays in [0, 1] and is continuous across lattice cells", "[texture]") {
    for (auto g : {NoiseGenerator::original, NoiseGenerator::range_corrected, NoiseGenerator::perlin}) {
        double lo = 1, hi = 0;
        for (int i = 0; i < 20000; ++i) {
            const Vec3<double> p(i * 0.0173 - 150, std::sin(i * 0.7) * 40, i * -0.0311);
            const double n = pov_noise(p, g);
            lo = std::min(lo, n), hi = std::max(hi, n);
            REQUIRE(n >= 0.0);
            REQUIRE(n <= 1.0);
            // Continuity: a step of 1e-7 across anything moves the value by far less than its range.
            CHECK(std::abs(pov_noise(p + Vec3<double>(1e-7), g) - n) < 1e-4);
        }
        CHECK(hi - lo > 0.5);  // and it does vary
    }
    // Across an integer lattice plane (x = 3) from both sides.
    CHECK(std::abs(pov_noise({3 - 1e-9, 0.4, 0.7}) - pov_noise({3 + 1e-9, 0.4, 0.7})) < 1e-6);
    CHECK(std::abs(pov_noise({-3 - 1e-9, 0.4, 0.7}) - pov_noise({-3 + 1e-9, 0.4, 0.7})) < 1e-6);
}

TEST_CASE("a colour map searches and blends as POV-Ray's", "[texture]") {
    const ColorMap<double> map({{0.25, Rgb<double>(1, 0, 0)}, {0.75, Rgb<double>(0, 0, 1)}});
    CHECK(map(0.0) == Rgb<double>(1, 0, 0));  // below the first entry: the first colour
    CHECK(map(1.0) == Rgb<double>(0, 0, 1));  // above the last: the last
    CHECK(map(0.5) == Rgb<double>(0.5, 0, 0.5));
    CHECK(map.upper_bound() == Rgb<double>(1, 0, 1));
    CHECK_THROWS_AS(ColorMap<double>(std::vector<ColorMap<double>::Entry>{}), std::invalid_argument);
    CHECK_THROWS_AS(ColorMap<double>({{0.0, Rgb<double>(-0.1, 0, 0)}}), std::invalid_argument);
    CHECK_THROWS_AS(ColorMap<double>({{NAN, Rgb<double>(0.1)}}), std::invalid_argument);
}

namespace {
/// A user's own texture: stripes along x.
struct Stripes {
    Rgb<float> operator()(const Vec3<float>& p) const { return std::fmod(std::abs(p.x), 2.0f) < 1.0f ? a : b; }
    Rgb<float> upper_bound() const { return glm::max(a, b); }
    Rgb<float> a, b;
};
static_assert(ReflectanceField<Stripes, float>);
static_assert(ReflectanceField<Pigment<double>, double>);
static_assert(!ReflectanceField<int, float>);
}  // namespace

TEST_CASE("a material reads its texture at the hit point and checks energy with its upper bound", "[texture]") {
    const auto m = Material<float>::lambertian(Stripes{Rgb<float>(0.8f, 0.1f, 0.1f), Rgb<float>(0.1f, 0.1f, 0.6f)});
    CHECK(m.is_textured());
    CHECK(m.has_diffuse());
    CHECK(m.diffuse_at({0.5f, 0, 0}) == Rgb<float>(0.8f, 0.1f, 0.1f));
    CHECK(m.diffuse_at({1.5f, 0, 0}) == Rgb<float>(0.1f, 0.1f, 0.6f));
    CHECK(m.scattering({1.5f, 0, 0}, 1.0f, true).diffuse == Rgb<float>(0.1f, 0.1f, 0.6f));
    CHECK(m.max_diffuse() == Rgb<float>(0.8f, 0.1f, 0.6f));
    // The factor scales the texture (the scene language's finish `diffuse`).
    const Material<float> half({.diffuse = Rgb<float>(0.5f), .diffuse_texture = AnyReflectanceField<float>(Stripes{Rgb<float>(1), Rgb<float>(0)})});
    CHECK(half.diffuse_at({0.5f, 0, 0}) == Rgb<float>(0.5f));
    CHECK(half.diffuse_at({1.5f, 0, 0}) == Rgb<float>(0));
    // A texture whose brightest colour plus the mirror exceeds 1 is refused; its average would pass.
    CHECK_THROWS_AS(Material<float>({.diffuse = Rgb<float>(1), .specular = Rgb<float>(0.3f),
                                     .diffuse_texture = AnyReflectanceField<float>(Stripes{Rgb<float>(0.9f), Rgb<float>(0.1f)})}),
                    std::invalid_argument);
    CHECK_NOTHROW(Material<float>({.diffuse = Rgb<float>(1), .specular = Rgb<float>(0.1f),
                                   .diffuse_texture = AnyReflectanceField<float>(Stripes{Rgb<float>(0.9f), Rgb<float>(0.1f)})}));
    // An untextured material is unchanged.
    const auto plain = Material<float>::lambertian(Rgb<float>(0.3f));
    CHECK_FALSE(plain.is_textured());
    CHECK(plain.diffuse_at({7, 8, 9}) == Rgb<float>(0.3f));
}
