// SPDX-License-Identifier: MIT
// "Shadow acne and light leaks do not appear", measured: a flat Lambertian plane under a point
// light must show L = rho / pi * I cos(theta) / d^2 at every pixel. Acne (a shadow ray that finds
// the plane it starts on) makes pixels black; a biased shading point makes them too bright or too
// dark; both are caught per pixel, near the origin and with the plane 1000 units away from it.

#include "hard_case_util.hpp"

using namespace photon;

namespace {

constexpr double rho = 0.5, power = 40.0;

/// The plane y = height, the light 1.5 above it, another 1 below it, the camera looking down at
/// it from 2.5 above.
template <class S> struct LitPlane {
    double height;
    Vec3<double> light{0.3, 0, 0.2};
    DefaultScene<S> scene;
    PinholeCamera<S> camera;

    explicit LitPlane(double h)
        : height(h), camera(make_camera<S>(h)) {
        light.y = h + 1.5;
        scene.add(Plane<S>({0, 1, 0}, S(h)), scene.add_material(Material<S>::lambertian(Rgb<S>(S(rho)))));
        scene.add_light(PointLight<S>{Vec3<S>(light), Rgb<S>(S(power))});
        // A light under the plane must not leak through it: its photons land on the same points
        // of the plane, from the other side.
        scene.add_light(PointLight<S>{Vec3<S>(S(-0.2), S(h - 1.0), S(0.1)), Rgb<S>(S(power))});
        scene.commit();
    }

    template <class T> static PinholeCamera<T> make_camera(double h) {
        return PinholeCamera<T>::look_at({T(0), T(h + 2.5), T(-2.5)}, {T(0), T(h), T(0.3)}, {T(0), T(1), T(0)}, T(60),
                                         T(32.0 / 24.0));
    }

    /// Exact radiance at the centre of pixel (x, y), from the camera ray computed in double.
    [[nodiscard]] double expected(unsigned x, unsigned y, unsigned width, unsigned height_px) const {
        const Ray<double> ray = *make_camera<double>(height).ray((x + 0.5) / width, (y + 0.5) / height_px);
        const double t = (height - ray.origin.y) / ray.direction.y;
        const Vec3<double> p = ray.at(t);
        const Vec3<double> to_light = light - p;
        const double d2 = glm::dot(to_light, to_light);
        const double cos_theta = to_light.y / std::sqrt(d2);
        return rho / pi<double> * (power / (4 * pi<double>)) * cos_theta / d2;
    }
};

/// Largest relative error of any pixel against the exact radiance (every channel).
template <class S> double worst_pixel_error(const LitPlane<S>& plane, const Film& film, unsigned& worst_x, unsigned& worst_y) {
    double worst = 0;
    for (unsigned y = 0; y < film.height(); ++y)
        for (unsigned x = 0; x < film.width(); ++x) {
            const double exact = plane.expected(x, y, film.width(), film.height());
            for (int c = 0; c < 3; ++c) {
                const double err = std::abs(double(film.at(x, y)[c]) / exact - 1.0);
                if (err > worst || !std::isfinite(err)) {
                    worst = std::isfinite(err) ? err : 1e30;
                    worst_x = x;
                    worst_y = y;
                }
            }
        }
    return worst;
}

}  // namespace

TEMPLATE_TEST_CASE("a plane under a point light is exact at every pixel in rt and pm, near and far from the origin",
                   "[hard][acne]", float, double) {
    using S = TestType;
    for (const double height : {0.0, 1000.0, -1000.0}) {
        const LitPlane<S> plane(height);
        RenderSettings rt = hard::tiny(RenderMode::rt);
        RenderSettings pm = hard::tiny(RenderMode::pm);            // shadow rays + gathers that find nothing
        RenderSettings pm_map = hard::tiny(RenderMode::pm);        // shadow rays + the global map read directly
        pm_map.final_gather_rays = 0;
        for (const RenderSettings* settings : {&rt, &pm, &pm_map}) {
            const RenderResult r = render(plane.scene, plane.camera, *settings);
            HARD_REQUIRE_VALID(r.film);
            unsigned wx = 0, wy = 0;
            const double worst = worst_pixel_error(plane, r.film, wx, wy);
            INFO("plane at y = " << height << ", mode " << to_string(settings->mode) << ", final gather rays "
                                 << settings->final_gather_rays << ": worst pixel (" << wx << ", " << wy << ") off by "
                                 << worst * 100 << "%");
            CHECK(worst < 0.01);
        }
    }
}
