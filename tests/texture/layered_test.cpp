// SPDX-License-Identifier: MIT
// Layered textures (texture/layered.hpp): POV-Ray 3.7's compositing rule against values worked
// out by hand, filter against transmit, several layers, patterned layers and the exact bound.

#include <catch2/catch.hpp>

#include <vector>

#include <photon/material/material.hpp>
#include <photon/texture/layered.hpp>

using namespace photon;

namespace {

template <Scalar S> void check_rgb_near(const Rgb<S>& got, double r, double g, double b) {
    const double tol = std::is_same_v<S, float> ? 1e-5 : 1e-12;
    CHECK_THAT(double(got.x), Catch::WithinAbs(r, tol));
    CHECK_THAT(double(got.y), Catch::WithinAbs(g, tol));
    CHECK_THAT(double(got.z), Catch::WithinAbs(b, tol));
}

template <Scalar S> PigmentLayer<S> uniform_layer(Rgb<S> c, double filter, double transmit, double weight = 1) {
    return PigmentLayer<S>(LayerColor<S>{c, S(filter), S(transmit)}, Rgb<S>(S(weight)));
}

/// A gradient x layer: at x in [0, 1) colour `a` blends to `b` (with their filter and transmit).
template <Scalar S> PigmentLayer<S> gradient_layer(const LayerColor<S>& a, const LayerColor<S>& b, double weight = 1) {
    Pigment<S> pigment(Pattern::of(PatternKind::gradient), ColorMap<S>({{0.0, a.color}, {1.0, b.color}}));
    return PigmentLayer<S>(std::move(pigment), {{a.filter, a.transmit}, {b.filter, b.transmit}}, Rgb<S>(S(weight)));
}

}  // namespace

TEMPLATE_TEST_CASE("a layered pigment composes its layers as POV-Ray 3.7 does", "[texture][layered]", float, double) {
    using S = TestType;
    static_assert(ReflectanceField<LayeredPigment<S>, S>);
    const Vec3<S> p(S(0.3), S(0.1), S(-0.2));
    const PigmentLayer<S> bottom = uniform_layer<S>({0.8, 0.6, 0.4}, 0, 0, 0.5);

    SECTION("one opaque layer is its colour times its weight") {
        check_rgb_near(LayeredPigment<S>({bottom})(p), 0.4, 0.3, 0.2);
    }
    SECTION("filter and transmit on top: own colour * opacity + (filter * colour + transmit) * below") {
        // own (0.2, 0.4, 1) * 0.3; passed 0.5 * (0.2, 0.4, 1) + 0.2 = (0.3, 0.4, 0.7); below (0.4, 0.3, 0.2).
        const LayeredPigment<S> two({bottom, uniform_layer<S>({0.2, 0.4, 1.0}, 0.5, 0.2)});
        check_rgb_near(two(p), 0.06 + 0.12, 0.12 + 0.12, 0.3 + 0.14);
        check_rgb_near(two.passed(p), 0, 0, 0);  // the bottom is opaque
    }
    SECTION("filter tints what shows through by the layer's colour, transmit does not") {
        const LayeredPigment<S> filtered({bottom, uniform_layer<S>({0.0, 0.0, 1.0}, 1, 0)});
        check_rgb_near(filtered(p), 0, 0, 0.2);
        const LayeredPigment<S> transmitted({bottom, uniform_layer<S>({0.0, 0.0, 1.0}, 0, 1)});
        check_rgb_near(transmitted(p), 0.4, 0.3, 0.2);
        const LayeredPigment<S> opaque({bottom, uniform_layer<S>({0.1, 0.2, 0.3}, 0, 0, 0.6)});
        check_rgb_near(opaque(p), 0.06, 0.12, 0.18);
    }
    SECTION("three layers: each shows through the ones above it") {
        // top: (1, 1, 1) transmit 0.5, weight 0.2 -> own 0.1, passes 0.5.
        // middle: (0, 1, 0) filter 0.6, weight 1 -> own (0, 0.4, 0), passes (0, 0.6, 0).
        // bottom: (0.4, 0.3, 0.2) after its weight.
        const LayeredPigment<S> three(
            {bottom, uniform_layer<S>({0.0, 1.0, 0.0}, 0.6, 0), uniform_layer<S>({1.0, 1.0, 1.0}, 0, 0.5, 0.2)});
        check_rgb_near(three(p), 0.1, 0.1 + 0.5 * (0.4 + 0.6 * 0.3), 0.1);
        CHECK(three.layers().size() == 3);
    }
    SECTION("a clear bottom passes what the layers above let through") {
        const LayeredPigment<S> glassy({uniform_layer<S>({1.0, 0.5, 0.5}, 0.5, 0.5), uniform_layer<S>({1.0, 1.0, 1.0}, 0, 0.25)});
        // passed: (0.5 * (1, 0.5, 0.5) + 0.5) * 0.25
        check_rgb_near(glassy.passed(p), 0.25, 0.1875, 0.1875);
        // the bottom's own colour has opacity 0: only the top's 0.75 shows
        check_rgb_near(glassy(p), 0.75, 0.75, 0.75);
    }
}

TEMPLATE_TEST_CASE("a patterned layer blends filter and transmit with its colours", "[texture][layered]", float, double) {
    using S = TestType;
    // Top: gradient x from clear white (transmit 1) to opaque black, over opaque white.
    const LayeredPigment<S> stack({uniform_layer<S>({1.0, 1.0, 1.0}, 0, 0),
                                   gradient_layer<S>({Rgb<S>(S(1)), S(0), S(1)}, {Rgb<S>(S(0)), S(0), S(0)})});
    for (const double x : {0.0, 0.25, 0.5, 0.9}) {
        // colour 1 - x, transmit 1 - x, opacity x: (1 - x) x + (1 - x) * 1
        const double expected = (1 - x) * x + (1 - x);
        check_rgb_near(stack(Vec3<S>(S(x), S(0.5), S(0.5))), expected, expected, expected);
    }
    check_rgb_near(stack.upper_bound(), 1, 1, 1);
}

TEMPLATE_TEST_CASE("a layered pigment's bound is the exact maximum, also between map entries", "[texture][layered]",
                   float, double) {
    using S = TestType;
    // Black below; on top the colour rises 0 -> 1 while the opacity falls 1 -> 0: x (1 - x),
    // largest (0.25) halfway between the entries, where neither entry reaches it.
    const LayeredPigment<S> stack({uniform_layer<S>({0.0, 0.0, 0.0}, 0, 0),
                                   gradient_layer<S>({Rgb<S>(S(0)), S(0), S(0)}, {Rgb<S>(S(1)), S(0), S(1)})});
    check_rgb_near(stack.upper_bound(), 0.25, 0.25, 0.25);
    double largest = 0;
    for (int i = 0; i < 1000; ++i) {
        const Rgb<S> c = stack(Vec3<S>(S(i / 1000.0), S(0), S(0)));
        largest = std::max(largest, double(c.x));
    }
    CHECK(largest <= double(stack.upper_bound().x) + 1e-6);
    CHECK(largest > 0.2499);
    // A material takes it as its diffuse texture, its bound checked for energy conservation.
    const Material<S> m({.diffuse = Rgb<S>(S(1)), .diffuse_texture = AnyReflectanceField<S>(stack)});
    check_rgb_near(m.max_diffuse(), 0.25, 0.25, 0.25);
    check_rgb_near(m.diffuse_at(Vec3<S>(S(0.5), S(0), S(0))), 0.25, 0.25, 0.25);
    // Its ambient light can weigh the layers otherwise (their finishes' ambient, not diffuse).
    const LayeredPigment<S> glow({uniform_layer<S>({0.5, 0.5, 0.5}, 0, 0, 0.2)});
    const Material<S> lit({.diffuse = Rgb<S>(S(1)), .ambient = Rgb<S>(S(2)), .diffuse_texture = AnyReflectanceField<S>(stack),
                           .ambient_texture = AnyReflectanceField<S>(glow)});
    check_rgb_near(lit.ambient_at(Vec3<S>(S(0.5), S(0), S(0))), 0.2, 0.2, 0.2);
    check_rgb_near(lit.diffuse_at(Vec3<S>(S(0.5), S(0), S(0))), 0.25, 0.25, 0.25);
}

TEST_CASE("a layered pigment rejects what POV-Ray's colours cannot mean", "[texture][layered]") {
    CHECK_THROWS_AS(LayeredPigment<double>({}), std::invalid_argument);
    CHECK_THROWS_AS(uniform_layer<double>({1.0, 1.0, 1.0}, 0.7, 0.7), std::invalid_argument);
    CHECK_THROWS_AS(uniform_layer<double>({1.0, 1.0, 1.0}, 0, 0, -1), std::invalid_argument);
    Pigment<double> two(Pattern::of(PatternKind::gradient),
                        ColorMap<double>({{0.0, Rgb<double>(0.0)}, {1.0, Rgb<double>(1.0)}}));
    CHECK_THROWS_AS(PigmentLayer<double>(two, {{0.0, 0.0}}, Rgb<double>(1.0)), std::invalid_argument);
}
