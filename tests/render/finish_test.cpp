// SPDX-License-Identifier: MIT
// POV-Ray's finish terms (material/highlight.hpp, MaterialParams::ambient): each term against a
// hand computation of POV-Ray 3.7's formula; direct light with all of them against POV-Ray's sum;
// every mode rendering them alike; an ambient radiance that is seen but lights nothing; and a
// surface's seen gain (what the camera sees of a surface reflecting over 1, as POV-Ray renders it).

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include <cmath>
#include <memory>
#include <vector>

using namespace photon;

namespace {

constexpr double finish_pi = 3.14159265358979323846;

/// A plane floor of `floor` material, lit by one sphere light above; the camera looks down at it.
/// A plane cannot light itself, so every mode's image is direct light (plus ambient) alone.
struct LitFloor {
    DefaultScene<double> scene;
    PinholeCamera<double> camera = PinholeCamera<double>::look_at({0, 2, -2.5}, {0, 0, 0.3}, {0, 1, 0}, 60, 4.0 / 3.0);
    explicit LitFloor(const MaterialParams<double>& floor) {
        scene.add(Plane<double>({0, 1, 0}, 0), scene.add_material(Material<double>(floor)));
        scene.add_light(SphereLight<double>{.center = {0.2, 1.2, 0.4}, .radius = 0.15, .power = Rgb<double>(20.0)});
        scene.commit();
    }
};

/// Mean radiance over each cell of a 4 x 3 grid of the image (the highlight sits in some of them).
std::vector<Rgb<double>> finish_cells(const Film& film, unsigned width, unsigned height) {
    std::vector<Rgb<double>> cells(12, Rgb<double>(0.0));
    for (unsigned y = 0; y < height; ++y)
        for (unsigned x = 0; x < width; ++x)
            cells[(y * 3 / height) * 4 + x * 4 / width] += Rgb<double>(film.pixels()[std::size_t(y) * width + x]);
    for (auto& c : cells) c /= double(width * height / 12);
    return cells;
}

MaterialParams<double> shiny_floor() {
    MaterialParams<double> p;
    p.diffuse = Rgb<double>(0.5, 0.4, 0.3);
    p.blinn = 0.8;
    p.blinn_exponent = 30;
    p.phong = 0.3;
    p.phong_exponent = 20;
    p.metallic = 0.6;
    p.highlight_color = Rgb<double>(1.0, 0.6, 0.2);
    p.brilliance = 2.5;
    p.ambient = Rgb<double>(0.02, 0.01, 0.005);
    return p;
}

/// A floor and a wall of material `wall` standing on it, lit by a small sphere light.
std::unique_ptr<DefaultScene<double>> wall_on_floor(const MaterialParams<double>& wall) {
    auto scene = std::make_unique<DefaultScene<double>>();
    scene->add(Plane<double>({0, 1, 0}, 0), scene->add_material(Material<double>::lambertian(Rgb<double>(0.6))));
    scene->add(Box<double>({-1, 0, 1}, {1, 1.5, 1.2}), scene->add_material(Material<double>(wall)));
    scene->add_light(SphereLight<double>{.center = {0.5, 1.8, -0.5}, .radius = 0.1, .power = Rgb<double>(30.0)});
    scene->commit();
    return scene;
}
const PinholeCamera<double> wall_camera =
    PinholeCamera<double>::look_at({0, 1.2, -2}, {0, 0.4, 0.5}, {0, 1, 0}, 60, 4.0 / 3.0);
constexpr unsigned wall_width = 24, wall_height = 18;

/// Per pixel, the object its whole footprint sees (corners and centre agree), -1 where mixed.
std::vector<int> one_object_pixels(const DefaultScene<double>& scene) {
    std::vector<int> seen(std::size_t(wall_width) * wall_height, -1);
    for (unsigned y = 0; y < wall_height; ++y)
        for (unsigned x = 0; x < wall_width; ++x) {
            int object = -2;
            for (const auto& [u, v] : {std::pair{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {1.0, 1.0}, {0.5, 0.5}}) {
                const auto hit = scene.intersect(*wall_camera.ray((x + u) / wall_width, (y + v) / wall_height));
                const int o = hit ? int(hit->object) : -1;
                object = object == -2 || object == o ? o : -3;
            }
            seen[std::size_t(y) * wall_width + x] = object < 0 ? -1 : object;
        }
    return seen;
}

/// Settings that render the wall scene quickly in every mode.
RenderSettings wall_settings() {
    RenderSettings s;
    s.width = wall_width, s.height = wall_height;
    s.samples_per_pixel = 2;
    s.global_photons = 20'000;
    s.caustic_photons = 0;
    s.final_gather_rays = 16;
    s.sppm_passes = 4;
    s.sppm_photons_per_pass = 5'000;
    return s;
}

}  // namespace

TEST_CASE("POV-Ray's highlight terms equal a hand computation of POV-Ray 3.7's formulas", "[finish]") {
    // n = z; light from 45 degrees (wi), viewer at (-0.6, 0, 0.8) (wo).
    const Vec3<double> n{0, 0, 1}, wi = glm::normalize(Vec3<double>{1, 0, 1}), wo{-0.6, 0, 0.8};
    MaterialParams<double> p;
    p.diffuse = Rgb<double>(0.5);
    p.phong = 0.5;
    p.phong_exponent = 40;
    p.blinn = 0.8;
    p.blinn_exponent = 20;  // roughness 0.05
    // phong: the mirrored light direction (-0.7071, 0, 0.7071) . wo = 0.98995; 0.5 * 0.98995^40 / pi.
    // blinn: h = wo + wi = (0.10711, 0, 1.50711), cos(h, n) = 0.99748; 0.8 * 0.99748^20 / pi.
    const Material<double> plain(p);
    CHECK(phong_highlight(plain, n, wo, wi) == Approx(0.10625310875));
    CHECK(blinn_highlight(plain, n, wo, wi) == Approx(0.24213674285));
    CHECK(highlight(plain, Rgb<double>(1.0, 0.5, 0.2), n, wo, wi).y == Approx(0.10625310875 + 0.24213674285));
    // No highlight from behind the viewer's mirror direction, nor with strength 0.
    CHECK(phong_highlight(plain, n, Vec3<double>{-0.8, 0, 0.6}, wi) > 0);
    CHECK(phong_highlight(plain, n, Vec3<double>{0.8, 0, 0.6}, wi) == 0);  // beyond 90 degrees of the mirror direction
    CHECK(blinn_highlight(Material<double>::lambertian(Rgb<double>(0.5)), n, wo, wi) == 0);

    // metallic: F(45 degrees) = 0.014567225 / (0.5 - 1.12)^2 - 0.011612903 = 0.0262831;
    // colour = strength * (1 + m (1 - F) (pigment - 1)), m = 0.5, pigment (1, 0.5, 0.2).
    CHECK(metallic_fresnel(std::cos(finish_pi / 4)) == Approx(0.0262831038));
    CHECK(metallic_fresnel(1.0) == Approx(0.0).margin(1e-6));  // normal incidence: the surface's colour
    CHECK(metallic_fresnel(0.0) == Approx(1.0).margin(1e-6));  // grazing: the light's colour
    p.metallic = 0.5;
    const Rgb<double> tinted = highlight(Material<double>(p), Rgb<double>(1.0, 0.5, 0.2), n, wo, wi);
    CHECK(tinted.x == Approx(0.3483898516));
    CHECK(tinted.y == Approx(0.2635815804));
    CHECK(tinted.z == Approx(0.2126966176));

    // brilliance: POV-Ray's diffuse intensity is cos^brilliance.
    p.brilliance = 2.5;
    CHECK(diffuse_cosine(Material<double>(p), 0.6) == Approx(0.2788548009));
    CHECK(diffuse_cosine(plain, 0.6) == 0.6);
}

TEMPLATE_TEST_CASE("direct light with every finish term is POV-Ray's sum of them", "[finish]", float, double) {
    using S = TestType;
    DefaultScene<S> scene;
    const auto floor = scene.add_material(Material<S>::lambertian(Rgb<S>(S(0.5))));
    scene.add(Plane<S>({0, 1, 0}, 0), floor);
    // Intensity 40 W/sr at (0, 2, 0): at x = (1, 0, 0), E = 40 / 5 = 8 normal to the light, cos = 2 / sqrt(5).
    scene.add_light(PointLight<S>{{0, 2, 0}, Rgb<S>(S(160) * pi<S>)});
    scene.commit();
    MaterialParams<S> p;
    p.diffuse = Rgb<S>(S(0.5), S(0.4), S(0.3));
    p.blinn = S(0.7);
    p.blinn_exponent = S(10);
    p.metallic = S(1);
    p.highlight_color = Rgb<S>(S(1), S(0.5), S(0.25));
    p.brilliance = S(3);
    p.ambient = Rgb<S>(S(0.25));  // not direct light: direct_lighting leaves it to its callers
    const Material<S> m(p);
    const Vec3<S> x{1, 0, 0}, n{0, 1, 0};
    const Vec3<S> wo = glm::normalize(Vec3<S>{-1, 1, 0});
    ShadingContext ctx;
    const Rgb<S> l = direct_lighting(scene, x, Vec3<S>(1, S(1e-4), 0), n, n, wo, m, m.diffuse(), 1, ctx);

    // POV-Ray: colour * (diffuse * pigment * cos^brilliance + specular * cos(h)^(1/roughness) * tint),
    // where photon's irradiance E is pi * colour.
    const double e = 8, cos_i = 2 / std::sqrt(5.0);
    const Vec3<double> wi = glm::normalize(Vec3<double>{-1, 2, 0}), h = glm::normalize(wi + glm::normalize(Vec3<double>{-1, 1, 0}));
    const double blinn = 0.7 * std::pow(h.y, 10.0);
    const double angle = std::acos(cos_i) / (finish_pi / 2);
    const double f = 0.014567225 / ((angle - 1.12) * (angle - 1.12)) - 0.011612903;
    const double pigment[3] = {1, 0.5, 0.25}, albedo[3] = {0.5, 0.4, 0.3};
    for (int c = 0; c < 3; ++c) {
        const double expected = e / finish_pi * (albedo[c] * std::pow(cos_i, 3.0) + blinn * (1 + (1 - f) * (pigment[c] - 1)));
        CHECK(double(l[c]) == Approx(expected).epsilon(1e-5));
    }
}

TEST_CASE("every mode renders POV-Ray's finish terms alike", "[finish][render]") {
    const MaterialParams<double> shiny = shiny_floor();
    MaterialParams<double> plain;
    plain.diffuse = shiny.diffuse;
    constexpr unsigned width = 32, height = 24;
    RenderSettings s;
    s.width = width, s.height = height;
    s.samples_per_pixel = 4;
    s.shadow_samples = 16;
    s.global_photons = 20'000;
    s.caustic_photons = 0;
    s.final_gather_rays = 16;
    s.sppm_passes = 16;
    s.sppm_photons_per_pass = 5'000;
    const auto cells_of = [&](const MaterialParams<double>& floor, RenderMode mode, unsigned spp) {
        const LitFloor scene(floor);
        RenderSettings m = s;
        m.mode = mode;
        m.samples_per_pixel = spp;
        return finish_cells(render(scene.scene, scene.camera, m).film, width, height);
    };
    const auto rt = cells_of(shiny, RenderMode::rt, 4);
    const auto rt_plain = cells_of(plain, RenderMode::rt, 4);
    // The terms change the picture: the highlight brightens some cell by more than half.
    double brightest = 0;
    for (std::size_t i = 0; i < rt.size(); ++i) brightest = std::max(brightest, rt[i].x / rt_plain[i].x);
    CHECK(brightest > 1.5);
    // A black floor with a highlight (POV-Ray's black ball with `phong 1`): the highlight alone.
    MaterialParams<double> black;
    black.phong = 0.8;
    black.phong_exponent = 10;
    black.blinn = 0.5;
    const auto rt_black = cells_of(black, RenderMode::rt, 4);
    double black_max = 0;
    for (const auto& c : rt_black) black_max = std::max(black_max, c.x);
    CHECK(black_max > 0.01);
    for (const auto& [mode, spp] : {std::pair{RenderMode::pm, 4u}, {RenderMode::sppm, 1u}, {RenderMode::reference, 256u}}) {
        for (const MaterialParams<double>* floor : {&shiny, static_cast<const MaterialParams<double>*>(&black)}) {
            const auto other = cells_of(*floor, mode, spp);
            const auto& expected = floor == &shiny ? rt : rt_black;
            for (std::size_t i = 0; i < rt.size(); ++i)
                for (int c = 0; c < 3; ++c) {
                    INFO("mode " << to_string(mode) << (floor == &shiny ? ", shiny" : ", black") << " floor, cell " << i
                                 << ", channel " << c);
                    CHECK(other[i][c] == Approx(expected[i][c]).epsilon(0.04).margin(2e-4));
                }
        }
    }
}

TEST_CASE("an ambient radiance is seen by the camera and lights nothing, in every mode", "[finish][render]") {
    // A floor and a wall standing on it; the wall shows an ambient radiance or not.
    const auto make = [](Rgb<double> ambient) {
        MaterialParams<double> wall;
        wall.diffuse = Rgb<double>(0.5);
        wall.ambient = ambient;
        return wall_on_floor(wall);
    };
    const auto lit = make(Rgb<double>(0.3, 0.2, 0.1)), dark = make(Rgb<double>(0.0));
    const auto& camera = wall_camera;
    const std::vector<int> seen = one_object_pixels(*dark);
    RenderSettings s = wall_settings();
    for (const RenderMode mode : {RenderMode::rt, RenderMode::pm, RenderMode::sppm, RenderMode::reference}) {
        s.mode = mode;
        const Film with = render(*lit, camera, s).film, without = render(*dark, camera, s).film;
        int floor_pixels = 0, wall_pixels = 0;
        for (std::size_t i = 0; i < seen.size(); ++i) {
            INFO("mode " << to_string(mode) << ", pixel " << i);
            if (seen[i] == 0) {  // the floor: the same random numbers, the same light
                ++floor_pixels;
                CHECK(with.pixels()[i] == without.pixels()[i]);
            } else if (seen[i] == 1) {  // the wall: its ambient radiance more
                ++wall_pixels;
                const Rgb<float> d = with.pixels()[i] - without.pixels()[i];
                CHECK(d.x == Approx(0.3).epsilon(1e-4));
                CHECK(d.y == Approx(0.2).epsilon(1e-4));
                CHECK(d.z == Approx(0.1).epsilon(1e-4));
            }
        }
        CHECK(floor_pixels > 50);
        CHECK(wall_pixels > 50);
    }
}

TEST_CASE("a surface seen with a gain shows it to the camera and passes on no more light, in every mode",
          "[finish][render]") {
    // POV-Ray's surfaces that reflect more than they receive (MaterialParams::seen_gain): a wall
    // with diffuse and mirror terms, seen through a gain of 2 or not, on a floor it lights.
    const auto make = [](double gain) {
        MaterialParams<double> wall;
        wall.diffuse = Rgb<double>(0.5, 0.4, 0.3);
        wall.specular = Rgb<double>(0.3);
        wall.seen_gain = gain;
        return wall_on_floor(wall);
    };
    const auto doubled = make(2.0), plain = make(1.0);
    const auto& camera = wall_camera;
    const std::vector<int> seen = one_object_pixels(*plain);
    RenderSettings s = wall_settings();
    for (const RenderMode mode : {RenderMode::rt, RenderMode::pm, RenderMode::sppm, RenderMode::reference}) {
        s.mode = mode;
        const Film with = render(*doubled, camera, s).film, without = render(*plain, camera, s).film;
        int floor_pixels = 0, wall_pixels = 0;
        for (std::size_t i = 0; i < seen.size(); ++i) {
            INFO("mode " << to_string(mode) << ", pixel " << i);
            if (seen[i] == 0) {  // the floor: lit by the wall as before, with the same random numbers
                ++floor_pixels;
                CHECK(with.pixels()[i] == without.pixels()[i]);
            } else if (seen[i] == 1) {  // the wall: all it shows, doubled (the floor in its mirror too)
                ++wall_pixels;
                for (int c = 0; c < 3; ++c) CHECK(with.pixels()[i][c] == Approx(2 * without.pixels()[i][c]).epsilon(1e-4));
                CHECK(without.pixels()[i].x > 0.01f);
            }
        }
        CHECK(floor_pixels > 50);
        CHECK(wall_pixels > 50);
    }
}

TEST_CASE("finish terms out of range are errors", "[finish]") {
    const auto make = [](auto&& set) {
        MaterialParams<double> p;
        p.diffuse = Rgb<double>(0.5);
        set(p);
        return Material<double>(p);
    };
    CHECK_THROWS_WITH(make([](auto& p) { p.metallic = 1.5; }), Catch::Contains("metallic must be in [0, 1], got 1.5"));
    CHECK_THROWS_WITH(make([](auto& p) { p.brilliance = -1; }), Catch::Contains("brilliance must be finite and >= 0"));
    CHECK_THROWS_WITH(make([](auto& p) { p.blinn_exponent = 0; }), Catch::Contains("blinn_exponent > 0"));
    CHECK_THROWS_WITH(make([](auto& p) { p.blinn = -0.1; }), Catch::Contains("blinn must be >= 0"));
    CHECK_THROWS_WITH(make([](auto& p) { p.ambient = Rgb<double>(0.1, -0.1, 0); }),
                      Catch::Contains("ambient radiance must be finite and >= 0"));
    CHECK_NOTHROW(make([](auto& p) { p.brilliance = 0; }));  // POV-Ray's scenes use it: light from any angle alike
}
