// A user's program: its own point type in photon's kd-tree, and (CONSUMER_RENDER) a tiny
// photon-mapped render.
#include <photon/photon.hpp>

#include <cstdio>
#include <vector>

struct Star {  // the user's record: position under another name, plus its own data
    float xyz[3];
    int id;
};

template <> struct photon::point_traits<Star> {
    using payload_type = int;
    static photon::Vec3<float> position(const Star& s) noexcept { return {s.xyz[0], s.xyz[1], s.xyz[2]}; }
    static int payload(const Star& s) noexcept { return s.id; }
};

int main() {
    std::vector<Star> stars{{{0, 0, 0}, 7}, {{1, 0, 0}, 8}, {{0, 2, 0}, 9}};
    const photon::KdTree<Star> tree(stars);
    std::vector<photon::Neighbor<float>> buffer;
    const auto nearest = tree.k_nearest({0.9f, 0.1f, 0.0f}, 1, 10.0f, buffer);
    if (nearest.neighbors.size() != 1 || tree.payload(nearest.neighbors[0].index) != 8) return 1;
#if CONSUMER_RENDER

    photon::DefaultScene<float> scene;
    scene.add(photon::Plane<float>({0, 1, 0}, 0), scene.add_material(photon::Material<float>::lambertian(photon::Rgb<float>(0.5f))));
    scene.add_light(photon::PointLight<float>{{0, 1, 0}, photon::Rgb<float>(10)});
    scene.commit();
    photon::RenderSettings settings;
    settings.width = 16;
    settings.height = 12;
    settings.global_photons = 2000;
    const auto camera = photon::PinholeCamera<float>::look_at({0, 1, -2}, {0, 0, 0}, {0, 1, 0}, 60, 4.0f / 3.0f);
    const auto result = photon::render(scene, camera, settings);
    std::printf("consumer: mean radiance %g\n", result.film.mean().x);
    return result.film.all_finite_nonnegative() && result.film.mean().x > 0 ? 0 : 1;
#else
    std::printf("consumer: the kd-tree found the user's point\n");
    return 0;
#endif
}
