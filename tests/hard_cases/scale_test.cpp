// SPDX-License-Identifier: MIT
// Scale invariance: the same scene built at 1e-4, 1 and 1e5 units gives the same image. Every
// length (geometry, camera, light positions and radii, estimate radii) is multiplied by s and
// every light's power by s^2, so radiance is unchanged. Nothing in the renderer may depend on an
// absolute length (a fixed epsilon, a fixed search radius).

#include "hard_case_util.hpp"

using namespace photon;

namespace {

/// A floor, a back wall, a diffuse and a glass sphere under a sphere light, all times s.
template <class S> struct ScaledScene {
    DefaultScene<S> scene;
    PinholeCamera<S> camera;

    explicit ScaledScene(S s)
        : camera(PinholeCamera<S>::look_at(s * Vec3<S>(0, 1.2, -3), s * Vec3<S>(0, 0.4, 0), {0, 1, 0}, S(55),
                                           S(32.0 / 24.0))) {
        const auto white = scene.add_material(Material<S>::lambertian(Rgb<S>(S(0.7))));
        const auto red = scene.add_material(Material<S>::lambertian({S(0.7), S(0.2), S(0.2)}));
        const auto glass = scene.add_material(Material<S>::glass(S(1.5)));
        scene.add(Box<S>(s * Vec3<S>(-2, -0.1, -2), s * Vec3<S>(2, 0, 2)), white);
        scene.add(Box<S>(s * Vec3<S>(-2, 0, 1), s * Vec3<S>(2, 2, 1.1)), red);
        scene.add(Sphere<S>(s * Vec3<S>(-0.5, 0.4, 0.2), S(0.4) * s), white);
        scene.add(Sphere<S>(s * Vec3<S>(0.6, 0.35, -0.2), S(0.35) * s), glass);
        scene.add_light(SphereLight<S>{.center = s * Vec3<S>(0.2, 1.8, -0.5), .radius = S(0.1) * s,
                                       .power = Rgb<S>(S(60) * s * s)});
        scene.commit();
    }
};

RenderSettings scaled_settings(RenderMode mode, double s) {
    RenderSettings r = hard::tiny(mode);
    r.global_estimate.max_radius = float(0.25 * s);
    r.caustic_estimate.max_radius = float(0.05 * s);
    return r;
}

}  // namespace

TEMPLATE_TEST_CASE("a scene at 1e-4 and at 1e5 units renders as at 1 unit", "[hard][scale]", float, double) {
    using S = TestType;
    const ScaledScene<S> unit(S(1));
    for (const RenderMode mode : {RenderMode::rt, RenderMode::pm}) {
        const RenderResult reference = render(unit.scene, unit.camera, scaled_settings(mode, 1.0));
        HARD_REQUIRE_VALID(reference.film);
        const std::vector<double> expected = hard::region_means(reference.film, 4, 3);
        for (const double s : {1e-4, 1e5}) {
            const ScaledScene<S> scaled{S(s)};
            const RenderResult r = render(scaled.scene, scaled.camera, scaled_settings(mode, s));
            HARD_REQUIRE_VALID(r.film);
            const std::vector<double> got = hard::region_means(r.film, 4, 3);
            // The same seeds draw the same photons and rays at every scale, so the images differ
            // only where rounding sends a path another way: well under 2% in every region.
            for (std::size_t i = 0; i < got.size(); ++i) {
                INFO("mode " << to_string(mode) << ", scale " << s << ", region " << i << ": " << got[i] << " vs "
                             << expected[i]);
                CHECK(got[i] == Approx(expected[i]).epsilon(0.02).margin(1e-4));
            }
        }
    }
}
