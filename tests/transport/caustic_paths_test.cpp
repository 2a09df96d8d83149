// SPDX-License-Identifier: MIT
// Every caustic path is carried once: the caustic pass covers the directions it aims into (cones
// around the caustic targets), and the global pass hands its L S+ D photons from all other
// directions to the caustic map. Before that hand-over the light a mirror plane (then never aimed
// at) reflected onto the floor was in neither map (42% dark next to the mirror); an infinite
// mirror plane is now aimed at through the mirror image of the scene's bounded objects, and what
// it reflects past them still comes from the global pass.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

using namespace photon;

namespace {

/// A floor (a box, or an infinite plane: then the mirror's caustics on it reach past the bounded
/// objects), a glass ball on it (a caustic target), a mirror plane standing on it and a small
/// sphere light.
struct MirrorPlaneScene {
    DefaultScene<double> scene;
    std::uint32_t mirror_plane = 0;

    explicit MirrorPlaneScene(bool infinite_floor = false) {
        const MaterialId white = scene.add_material(Material<double>::lambertian(Rgb<double>(0.75)));
        if (infinite_floor) scene.add(Plane<double>({0, 1, 0}, 0), white);
        else scene.add(Box<double>({-3, -0.1, -3}, {3, 0, 3}), white);
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
    // Aimed at the glass ball only (the plane skipped, as the plan skips a hidden target), the
    // plane's caustics all come from the global pass; aimed at both, they come from the caustic
    // pass. Either way the two passes together carry every L S+ D photon once.
    std::vector<bool> skip(s.scene.objects().size(), false);
    skip[s.mirror_plane] = true;
    const bool plane_aimed = GENERATE(false, true);
    const auto aim = caustic_aim(s.scene, plane_aimed ? std::vector<bool>{} : skip);
    REQUIRE(aim.cones.size() == 1);
    REQUIRE(aim.cones[0].size() == (plane_aimed ? 2u : 1u));
    // Every L S+ D photon of a plain global pass: the truth, by brute force.
    const TracedPhotons all = trace_global_photons(s.scene, {.photons = 1'000'000, .max_depth = 100, .seed = 1});
    const double truth = caustic_power(all.photons);
    // The split: aimed caustic photons plus the global pass's photons outside the cones.
    const TracedPhotons aimed = trace_caustic_photons(s.scene, {.photons = 200'000, .max_depth = 100, .seed = 2}, aim);
    const TracedPhotons global = trace_global_photons(
        s.scene, {.photons = 200'000, .max_depth = 100, .store = {.direct = false, .caustic = false, .indirect = true},
                  .collect_unaimed_caustics = true, .seed = 3},
        aim);
    // The caustic pass returns the photons it aimed at the plane apart (read like the global map's).
    const double from_aimed = caustic_power(aimed.photons) + caustic_power(aimed.unaimed_caustics);
    const double from_global = caustic_power(global.unaimed_caustics);
    CHECK(aimed.unaimed_caustics.empty() == !plane_aimed);
    INFO("plane aimed " << plane_aimed << ": truth " << truth << " W, aimed " << from_aimed
                        << " W, unaimed from the global pass " << from_global << " W");
    // The mirror plane sends about a quarter of the light's power onto the floor: the global
    // pass carries it when the plane is not aimed at, the caustic pass when it is (all of it:
    // the floor is bounded, so everything the mirror reflects onto it is in the plane's cone).
    if (plane_aimed) {
        CHECK(from_aimed > 0.98 * truth);
        CHECK(global.unaimed_caustics.empty());
    } else {
        CHECK(from_global > 0.5 * truth);
        CHECK(from_aimed < 0.5 * truth);
    }
    // The noise of each sum is about 1 / sqrt(caustic photons), below 0.5% here; 2% is the margin.
    CHECK(from_aimed + from_global == Approx(truth).epsilon(0.02));
    // With nothing to aim at, every L S+ D photon of the global pass is handed over.
    const TracedPhotons unaimed_all = trace_global_photons(
        s.scene, {.photons = 100'000, .max_depth = 100, .collect_unaimed_caustics = true, .seed = 1});
    CHECK(unaimed_all.unaimed_caustics.size() ==
          std::size_t(std::count_if(unaimed_all.photons.begin(), unaimed_all.photons.end(),
                                    [](const Photon& p) { return p.packed.kind() == PathKind::caustic; })));
}

TEST_CASE("render() keeps the unaimed caustics in a map of their own", "[transport][caustics]") {
    // The floor is infinite: what the mirror plane reflects onto it past the ball's box is not
    // in the plane's cone, and comes from the global pass.
    const MirrorPlaneScene s(true);
    for (const RenderMode mode : {RenderMode::pm, RenderMode::pm_direct}) {
        RenderSettings settings;
        settings.mode = mode;
        settings.width = 16, settings.height = 12, settings.samples_per_pixel = 1;
        settings.global_photons = 20'000, settings.caustic_photons = 20'000, settings.final_gather_rays = 16;
        RenderStats stats;
        const PhotonMaps maps = build_photon_maps(s.scene, settings, stats);
        REQUIRE(maps.caustic);  // the glass ball's
        REQUIRE(maps.unaimed_caustic);
        CHECK(stats.caustic.from_global + stats.caustic.from_mirror_planes == maps.unaimed_caustic->size());
        CHECK(stats.caustic.from_mirror_planes > 0);
        CHECK(stats.caustic.from_global > 0);
        CHECK(stats.caustic.stored > stats.caustic.from_global);
        CHECK(stats.warnings.empty());  // the plane is aimed at
    }
}

TEST_CASE("a mirror plane with no bounded object to aim into is named, and its caustics come from the global pass",
          "[transport][caustics]") {
    DefaultScene<double> scene;
    scene.add(Plane<double>({0, 1, 0}, 0), scene.add_material(Material<double>::lambertian(Rgb<double>(0.75))));
    const auto mirror = scene.add(Plane<double>({-1, 0, 0}, -1.5), scene.add_material(Material<double>::mirror()));
    scene.add_light(SphereLight<double>{.center = {0, 1.5, 0}, .radius = 0.05, .power = Rgb<double>(10.0)});
    scene.commit();
    CHECK_FALSE(is_aimable_target(scene, mirror));
    CHECK(caustic_aim(scene).empty());
    RenderSettings settings;
    settings.width = 16, settings.height = 12, settings.samples_per_pixel = 1;
    settings.global_photons = 20'000, settings.caustic_photons = 20'000, settings.final_gather_rays = 16;
    RenderStats stats;
    const PhotonMaps maps = build_photon_maps(scene, settings, stats);
    CHECK_FALSE(maps.caustic);
    REQUIRE(maps.unaimed_caustic);
    CHECK(stats.caustic.from_global > 0);
    REQUIRE(stats.warnings.size() == 1);
    CHECK(stats.warnings[0].object == mirror);
}
