// SPDX-License-Identifier: MIT
// Every caustic path is carried once: the caustic pass covers the directions it aims into (cones
// around the caustic targets), and the global pass hands its L S+ D photons from all other
// directions to the caustic map. A mirror plane cannot be aimed at, so before that hand-over the
// light it reflected onto the floor was in neither map (42% dark next to the mirror).

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

using namespace photon;

namespace {

/// A floor, a glass ball on it (a caustic target), a mirror plane standing on it (infinite: never
/// aimed at) and a small sphere light.
struct MirrorPlaneScene {
    DefaultScene<double> scene;
    std::uint32_t mirror_plane = 0;

    MirrorPlaneScene() {
        const MaterialId white = scene.add_material(Material<double>::lambertian(Rgb<double>(0.75)));
        scene.add(Box<double>({-3, -0.1, -3}, {3, 0, 3}), white);
        scene.add(Sphere<double>({0.6, 0.3, 0}, 0.3), scene.add_material(Material<double>::glass(1.5)));
        mirror_plane = scene.add(Plane<double>({-1, 0, 0}, -1.5), scene.add_material(Material<double>::mirror()));
        scene.add_light(SphereLight<double>{.center = {0, 1.5, 0}, .radius = 0.05, .power = Rgb<double>(10.0)});
        scene.commit();
    }
};

double caustic_power(std::span<const Photon> photons) {
    double sum = 0;
    for (const Photon& p : photons)
        if (p.packed.kind() == PathKind::caustic) sum += double(p.packed.power().x);
    return sum;
}

}  // namespace

TEST_CASE("caustic pass + the global pass's unaimed caustics carry all L S+ D light once", "[transport][caustics]") {
    const MirrorPlaneScene s;
    const auto aim = caustic_aim(s.scene);
    REQUIRE_FALSE(aim.empty());  // the glass ball is aimed at, the plane is not
    // Every L S+ D photon of a plain global pass: the truth, by brute force.
    const TracedPhotons all = trace_global_photons(s.scene, {.photons = 1'000'000, .max_depth = 100, .seed = 1});
    const double truth = caustic_power(all.photons);
    // The split: aimed caustic photons plus the global pass's photons outside the cones.
    const TracedPhotons aimed = trace_caustic_photons(s.scene, {.photons = 200'000, .max_depth = 100, .seed = 2}, aim);
    const TracedPhotons global = trace_global_photons(
        s.scene, {.photons = 200'000, .max_depth = 100, .store = {.direct = false, .caustic = false, .indirect = true},
                  .collect_unaimed_caustics = true, .seed = 3},
        aim);
    const double from_aimed = caustic_power(aimed.photons), from_global = caustic_power(global.unaimed_caustics);
    INFO("truth " << truth << " W, aimed " << from_aimed << " W, unaimed from the global pass " << from_global << " W");
    // The mirror plane sends about a quarter of the light's power onto the floor; only the
    // global pass carries it.
    CHECK(from_global > 0.5 * truth);
    CHECK(from_aimed < 0.5 * truth);
    // The noise of each sum is about 1 / sqrt(caustic photons), below 0.5% here; 2% is the margin.
    CHECK(from_aimed + from_global == Approx(truth).epsilon(0.02));
    // With nothing to aim at, every L S+ D photon of the global pass is handed over.
    const TracedPhotons unaimed_all = trace_global_photons(
        s.scene, {.photons = 100'000, .max_depth = 100, .collect_unaimed_caustics = true, .seed = 1});
    CHECK(unaimed_all.unaimed_caustics.size() ==
          std::size_t(std::count_if(unaimed_all.photons.begin(), unaimed_all.photons.end(),
                                    [](const Photon& p) { return p.packed.kind() == PathKind::caustic; })));
}

TEST_CASE("render() keeps the unaimed caustics in a map of their own and names the unaimed mirror", "[transport][caustics]") {
    const MirrorPlaneScene s;
    for (const RenderMode mode : {RenderMode::pm, RenderMode::pm_direct}) {
        RenderSettings settings;
        settings.mode = mode;
        settings.width = 16, settings.height = 12, settings.samples_per_pixel = 1;
        settings.global_photons = 20'000, settings.caustic_photons = 20'000, settings.final_gather_rays = 16;
        RenderStats stats;
        const PhotonMaps maps = build_photon_maps(s.scene, settings, stats);
        REQUIRE(maps.caustic);  // the glass ball's
        REQUIRE(maps.unaimed_caustic);
        CHECK(stats.caustic.from_global == maps.unaimed_caustic->size());
        CHECK(stats.caustic.from_global > 0);
        CHECK(stats.caustic.stored > stats.caustic.from_global);
        REQUIRE(stats.warnings.size() == 1);
        CHECK(stats.warnings[0].object == s.mirror_plane);
    }
}
