// SPDX-License-Identifier: MIT
#pragma once
// The furnace case shared by the analytic tests of every mode (tests/transport/analytic_test.cpp,
// tests/render/sppm_test.cpp).

#include <photon/photon.hpp>

namespace photon::testing {

/// A closed diffuse sphere of radius R and albedo rho, a point light of power Phi at its centre,
/// and a camera inside looking at the wall. Its wall radiance is rho Phi / (4 pi^2 R^2 (1 - rho)):
/// direct light rho Phi / (4 pi^2 R^2) times the geometric series of interreflections.
struct FurnaceSphere {
    static constexpr double R = 1.5, rho = 0.5, Phi = 20.0;
    DefaultScene<double> scene;
    PinholeCamera<double> camera = PinholeCamera<double>::look_at({0, 0.2, -0.3}, {0.3, 0.4, 1}, {0, 1, 0}, 70, 1.0);
    FurnaceSphere() {
        scene.add(Sphere<double>({0, 0, 0}, R), scene.add_material(Material<double>::lambertian(Rgb<double>(rho))));
        scene.add_light(PointLight<double>{{0, 0, 0}, Rgb<double>(Phi)});
        scene.commit();
    }
    static double radiance() { return rho * Phi / (4 * pi<double> * pi<double> * R * R * (1 - rho)); }
    static double direct() { return rho * Phi / (4 * pi<double> * pi<double> * R * R); }
};

}  // namespace photon::testing
