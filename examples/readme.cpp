// SPDX-License-Identifier: MIT
// The README's library example, word for word (tests/readme_example.cmake checks that it is).
#include <photon/photon.hpp>
#include <photon/film/image_io.hpp>  // write_image (OpenImageIO); not in the umbrella header

#include <cstdio>

int main() {
    photon::DefaultScene<float> scene;
    auto white = scene.add_material(photon::Material<float>::lambertian({0.75f, 0.75f, 0.75f}));
    auto glass = scene.add_material(photon::Material<float>::glass(1.5f));
    scene.add(photon::Box<float>({-2, -0.02f, -2}, {2, 0, 2}), white);  // a floor slab
    scene.add(photon::Sphere<float>({0, 0.4f, 0}, 0.4f), glass);
    scene.add_light(photon::SphereLight<float>{.center = {0, 1.5f, 0}, .radius = 0.1f,
                                               .power = photon::Rgb<float>(31.4f)});  // watts per channel
    scene.commit();

    auto camera = photon::Camera<float>::look_at({0, 0.9f, -3.5f}, {0, 0.4f, 0}, {0, 1, 0},
                                                 53.13f, 4.0f / 3.0f);  // horizontal field of view
    photon::RenderSettings settings;  // the library's defaults: pm, 800 x 600, ray depth 4, photon depth 100
    auto result = photon::render(scene, camera, settings);
    photon::write_image("out.png", result.film);  // .exr keeps linear radiance
    std::puts(photon::format_stats(result.stats).c_str());
}
