// SPDX-License-Identifier: MIT
#pragma once
// The paper's Cornell box built in C++ (no scene file): 0.02 m wall slabs around the interior
// [-1.2,1.2] x [0,1.8] x [-1.2,1.2], open at the front, red wall left, blue wall right, a mirror
// sphere at the back left, a glass sphere at the front right, and a 0.1 m spherical light of
// 2.5 W/sr (31.4 W) near the ceiling. Units are metres, power watts, pixels radiance.

#include <photon/photon.hpp>

namespace cornell {

template <photon::Scalar S> struct CornellBox {
    photon::DefaultScene<S> scene;
    photon::PinholeCamera<S> camera;
};

/// The box and the paper's camera for an image of the given aspect (width / height).
template <photon::Scalar S> CornellBox<S> make_cornell_box(S aspect = S(4) / S(3)) {
    using namespace photon;
    DefaultScene<S> scene;
    const auto white = scene.add_material(Material<S>::lambertian({0.75, 0.75, 0.75}));
    const auto red = scene.add_material(Material<S>::lambertian({0.75, 0.25, 0.25}));
    const auto blue = scene.add_material(Material<S>::lambertian({0.25, 0.25, 0.75}));
    const auto mirror = scene.add_material(Material<S>::mirror());
    const auto glass = scene.add_material(Material<S>::glass(S(1.5)));

    scene.add(Box<S>({-1.22, -0.02, -1.2}, {1.22, 0.0, 1.22}), white);  // floor
    scene.add(Box<S>({-1.22, 1.8, -1.2}, {1.22, 1.82, 1.22}), white);   // ceiling
    scene.add(Box<S>({-1.22, -0.02, 1.2}, {1.22, 1.82, 1.22}), white);  // back
    scene.add(Box<S>({-1.22, -0.02, -1.2}, {-1.2, 1.82, 1.22}), red);   // left
    scene.add(Box<S>({1.2, -0.02, -1.2}, {1.22, 1.82, 1.22}), blue);    // right
    scene.add(Sphere<S>({-0.55, 0.4, 0.45}, S(0.4)), mirror);
    scene.add(Sphere<S>({0.55, 0.4, -0.3}, S(0.4)), glass);

    const S intensity = 2.5;  // W/sr per channel
    scene.add_light(SphereLight<S>{.center = {0, 1.5, 0}, .radius = S(0.1), .power = Rgb<S>(4 * pi<S> * intensity)});
    scene.commit();

    // Horizontal field of view 53.13 degrees: the frame just fits inside the open front.
    auto camera = PinholeCamera<S>::look_at({0, 0.9, -3.5}, {0, 0.9, 0}, {0, 1, 0}, S(53.13), aspect);
    return {std::move(scene), camera};
}

}  // namespace cornell
