// SPDX-License-Identifier: MIT
// POV-Ray's fog (scene/fog.hpp): its attenuation against the closed forms and, for ground fog,
// against a quadrature of its density written here; and where the integrators apply it (one ray
// at a time, every mode alike): on the camera's segment, on the mirror's segment after it, not
// inside glass, and the fog's colour alone where a ray leaves the scene.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include <cmath>
#include <vector>

using namespace photon;

namespace {

/// Ground fog's density at height y, as POV-Ray's comment in trace.cpp draws it.
double ground_density(double y, double offset, double altitude) {
    const double h = (y - offset) / altitude;
    return h <= 0 ? 1.0 : 1.0 / (1.0 + h * h);
}

/// Integral of the density along the segment, by Simpson's rule on many intervals.
double ground_optical_length(const Vec3<double>& o, const Vec3<double>& d, double length, double offset, double altitude) {
    constexpr int n = 20'000;
    const double h = length / n;
    double sum = 0;
    for (int i = 0; i <= n; ++i) {
        const double w = i == 0 || i == n ? 1 : (i % 2 ? 4 : 2);
        sum += w * ground_density((o + d * (h * i)).y, offset, altitude);
    }
    return sum * h / 3;
}

/// The three integrators' radiance along one camera ray: rt (pm's camera side), the path tracer
/// and sppm's camera path, which must agree wherever no light source is involved.
template <class SceneT> std::vector<Rgb<double>> seen_by_every_mode(const SceneT& scene, const Ray<typename SceneT::scalar_type>& ray) {
    RenderSettings settings;
    settings.mode = RenderMode::rt;
    const PhotonMaps no_maps;
    ShadingContext ctx;
    return {Rgb<double>(RadianceIntegrator<SceneT>(scene, no_maps, settings).radiance(ray, 1, ctx)),
            Rgb<double>(PathTracer<SceneT>(scene, settings).radiance(ray, ctx)),
            Rgb<double>(trace_camera_path(scene, ray, settings, ctx).direct)};
}

}  // namespace

TEMPLATE_TEST_CASE("constant fog fades a segment by exp(-length / distance) into its colour", "[fog]", float, double) {
    using S = TestType;
    Fog<S> fog;
    fog.distance = S(3);
    fog.colour = Rgb<S>(S(0.3), S(0.5), S(0.2));
    const Fog<S> fogs[] = {fog};
    const FogEffect<S> e = fog_along<S>(fogs, Vec3<S>(S(1), S(2), S(3)), Vec3<S>(S(0), S(0), S(1)), S(4.5));
    const double att = std::exp(-4.5 / 3.0);
    for (int c = 0; c < 3; ++c) {
        CHECK(double(e.transmittance[c]) == Approx(att).epsilon(1e-6));
        CHECK(double(e.added[c]) == Approx((1 - att) * double(fog.colour[c])).epsilon(1e-6));
    }
    // Filter tints what shows through by the colour; transmit is the least that shows through.
    Fog<S> tinted = fog;
    tinted.filter = S(0.5);
    tinted.transmit = S(0.4);
    const Fog<S> tinted_fogs[] = {tinted};
    const FogEffect<S> t = fog_along<S>(tinted_fogs, Vec3<S>(S(0)), Vec3<S>(S(0), S(0), S(1)), S(30));
    for (int c = 0; c < 3; ++c) {
        CHECK(double(t.transmittance[c]) == Approx(0.4 * (0.5 + 0.5 * double(fog.colour[c]))).epsilon(1e-6));
        CHECK(double(t.added[c]) == Approx(0.6 * double(fog.colour[c])).epsilon(1e-6));
    }
    // Two fogs: what the nearer adds is not faded by the other (POV-Ray sums their colours).
    Fog<S> second = fog;
    second.distance = S(7);
    second.colour = Rgb<S>(S(1), S(0), S(0));
    const Fog<S> both[] = {fog, second};
    const FogEffect<S> b = fog_along<S>(both, Vec3<S>(S(0)), Vec3<S>(S(1), S(0), S(0)), S(2));
    const double a1 = std::exp(-2.0 / 3.0), a2 = std::exp(-2.0 / 7.0);
    CHECK(double(b.transmittance[1]) == Approx(a1 * a2).epsilon(1e-6));
    CHECK(double(b.added[0]) == Approx((1 - a1) * 0.3 + (1 - a2) * 1.0).epsilon(1e-6));
}

TEMPLATE_TEST_CASE("ground fog's attenuation is its density integrated along the segment", "[fog]", float, double) {
    using S = TestType;
    Fog<S> fog;
    fog.kind = Fog<S>::Kind::ground;
    fog.distance = S(5);
    fog.offset = S(0.5);
    fog.altitude = S(2);
    struct Segment {
        Vec3<double> origin, direction;
        double length;
    };
    const Segment segments[] = {
        {{0, -3, 0}, {1, 0, 0}, 4},                              // below the offset: density 1
        {{0, -2, 0}, glm::normalize(Vec3<double>(1, 1, 0)), 9},  // upwards through the offset
        {{0, 6, 0}, glm::normalize(Vec3<double>(1, -1, 0.3)), 10},  // downwards through it
        {{0, 3, 0}, glm::normalize(Vec3<double>(1, 0.2, 0)), 8},    // above it, rising
        {{0, 3, 0}, {0, 0, 1}, 8},                                  // above it, level
    };
    for (const Segment& s : segments) {
        const Fog<S> fogs[] = {fog};
        const FogEffect<S> e = fog_along<S>(fogs, Vec3<S>(s.origin), Vec3<S>(s.direction), S(s.length));
        const double expected = std::exp(-ground_optical_length(s.origin, s.direction, s.length, 0.5, 2) / 5);
        INFO("from y " << s.origin.y << " along " << s.direction.y);
        CHECK(double(e.transmittance[0]) == Approx(expected).epsilon(S(1) == S(1.0f) ? 1e-4 : 1e-6));
    }
    // Altitude 0 (POV-Ray's default): a layer with a flat top at the offset, density 1 under it.
    Fog<S> layer = fog;
    layer.altitude = S(0);
    const Fog<S> layers[] = {layer};
    const FogEffect<S> half = fog_along<S>(layers, Vec3<S>(S(0), S(-0.5), S(0)), Vec3<S>(S(0), S(1), S(0)), S(2));
    CHECK(double(half.transmittance[0]) == Approx(std::exp(-1.0 / 5)).epsilon(1e-5));  // 1 of its 2 below 0.5
    // A ray that leaves the scene upwards sees the fog above it, a finite amount:
    // altitude (pi/2 - atan(h0)) / sin(elevation) in units of the distance.
    const Vec3<S> up_dir = glm::normalize(Vec3<S>(S(1), S(0.5), S(0)));
    const Fog<S> fogs[] = {fog};
    const FogEffect<S> sky = fog_along<S>(fogs, Vec3<S>(S(0), S(1.5), S(0)), up_dir, fog_unbounded_length<S>);
    const double h0 = (1.5 - 0.5) / 2;
    const double expected = std::exp(-2 * (std::acos(-1.0) / 2 - std::atan(h0)) / double(up_dir.y) / 5);
    CHECK(double(sky.transmittance[0]) == Approx(expected).epsilon(1e-3));
    CHECK(std::isfinite(double(sky.added[0])));
}

TEMPLATE_TEST_CASE("every mode fogs the camera's segment and the mirror's after it, not the inside of glass",
                   "[fog][render]", float, double) {
    using S = TestType;
    const Rgb<S> wall_radiance(S(0.8), S(0.6), S(0.4));
    const Rgb<double> fog_colour(0.3, 0.5, 0.2);
    for (const S scale : {S(1e-3), S(1), S(1e4)}) {
        Fog<S> fog;
        fog.distance = S(4) * scale;
        fog.colour = Rgb<S>(fog_colour);
        const auto expected = [&](double length) {
            const double att = std::exp(-length / double(fog.distance));
            return (1 - att) * fog_colour + att * Rgb<double>(wall_radiance);
        };
        MaterialParams<S> glowing;
        glowing.ambient = wall_radiance;  // seen alike by every mode, whatever lights it
        INFO("scale " << scale);
        {  // Straight at a wall 6 away.
            DefaultScene<S> scene;
            scene.add(Plane<S>({S(0), S(0), S(-1)}, S(-6) * scale), scene.add_material(Material<S>(glowing)));
            scene.add_fog(fog);
            scene.commit();
            for (const Rgb<double>& seen : seen_by_every_mode(scene, Ray<S>{Vec3<S>(S(0)), {S(0), S(0), S(1)}}))
                for (int c = 0; c < 3; ++c) CHECK(seen[c] == Approx(expected(6 * double(scale))[c]).epsilon(1e-4));
        }
        {  // A mirror 2 away turns the ray to the wall 5 beyond: fogged over 7.
            DefaultScene<S> scene;
            scene.add(Plane<S>(glm::normalize(Vec3<S>(S(1), S(0), S(-1))), -std::sqrt(S(2)) * scale),
                      scene.add_material(Material<S>::mirror()));
            scene.add(Plane<S>({S(-1), S(0), S(0)}, S(-5) * scale), scene.add_material(Material<S>(glowing)));
            scene.add_fog(fog);
            scene.commit();
            for (const Rgb<double>& seen : seen_by_every_mode(scene, Ray<S>{Vec3<S>(S(0)), {S(0), S(0), S(1)}}))
                for (int c = 0; c < 3; ++c) CHECK(seen[c] == Approx(expected(7 * double(scale))[c]).epsilon(1e-4));
        }
        {  // From inside a clear ball of radius 2 (ior 1: no bending, no reflection): fogged over 6 - 2.
            DefaultScene<S> scene;
            scene.add(Sphere<S>(Vec3<S>(S(0)), S(2) * scale),
                      scene.add_material(Material<S>({.transmission = Rgb<S>(S(1)), .ior = S(1)})));
            scene.add(Plane<S>({S(0), S(0), S(-1)}, S(-6) * scale), scene.add_material(Material<S>(glowing)));
            scene.add_fog(fog);
            scene.commit();
            for (const Rgb<double>& seen : seen_by_every_mode(scene, Ray<S>{Vec3<S>(S(0)), {S(0), S(0), S(1)}}))
                for (int c = 0; c < 3; ++c) CHECK(seen[c] == Approx(expected(4 * double(scale))[c]).epsilon(1e-4));
        }
        {  // Nothing ahead: the fog's colour alone, in place of the sky. (Planes are n . x = offset.)
            DefaultScene<S> scene;
            scene.add(Plane<S>({S(0), S(0), S(-1)}, S(-6) * scale), scene.add_material(Material<S>(glowing)));
            scene.set_environment(Environment<S>(Rgb<S>(S(5))));
            scene.add_fog(fog);
            scene.commit();
            for (const Rgb<double>& seen : seen_by_every_mode(scene, Ray<S>{Vec3<S>(S(0)), {S(0), S(0), S(-1)}}))
                for (int c = 0; c < 3; ++c) CHECK(seen[c] == Approx(fog_colour[c]).epsilon(1e-5));
        }
    }
}

TEMPLATE_TEST_CASE("a fogged image has no NaN in any mode, at tiny and huge scales, and fog lights nothing",
                   "[fog][render]", float, double) {
    using S = TestType;
    for (const S scale : {S(1e-3), S(1e4)}) {
        DefaultScene<S> scene;
        scene.add(Plane<S>({S(0), S(1), S(0)}, S(0)), scene.add_material(Material<S>::lambertian(Rgb<S>(S(0.6)))));
        scene.add(Sphere<S>(Vec3<S>(0, 0.5, 2) * scale, S(0.5) * scale), scene.add_material(Material<S>::glass(S(1.5))));
        Fog<S> ground;
        ground.kind = Fog<S>::Kind::ground;
        ground.distance = S(3) * scale;
        ground.altitude = S(0.3) * scale;
        ground.colour = Rgb<S>(S(0.7));
        ground.turbulence = FogTurbulence{Vec3<double>(1.0 / double(scale)), TurbulenceParams{}, 0.5};
        scene.add_fog(ground);
        scene.commit();
        const auto camera = PinholeCamera<S>::look_at(Vec3<S>(0, 1, -2) * scale, Vec3<S>(0, 0.3, 2) * scale, {0, 1, 0}, 50,
                                                      S(4.0 / 3.0));
        for (const RenderMode mode : {RenderMode::rt, RenderMode::pm, RenderMode::sppm, RenderMode::reference}) {
            RenderSettings settings;
            settings.mode = mode;
            settings.width = 16;
            settings.height = 12;
            settings.threads = 2;
            settings.samples_per_pixel = 1;
            settings.global_photons = 5'000;
            settings.caustic_photons = 5'000;
            settings.final_gather_rays = 16;
            settings.sppm_passes = 2;
            settings.sppm_photons_per_pass = 5'000;
            const Film film = render(scene, camera, settings).film;
            double sum = 0;
            for (const Rgb<float>& p : film.pixels()) {
                REQUIRE(is_finite(p));
                // No light source and no sky: the fog's colour is all there is to see, and no more
                // than it shows anywhere (it lights nothing, so nothing is seen through it).
                for (int c = 0; c < 3; ++c) REQUIRE(double(p[c]) <= 0.7 + 1e-4);
                sum += double(average(p));
            }
            INFO("scale " << scale << ", mode " << int(mode));
            CHECK(sum > 0.0);
        }
    }
}
