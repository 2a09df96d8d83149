// SPDX-License-Identifier: MIT
// Limits instead of crashes: the memory a render plans to use is estimated before anything is
// allocated and checked against a limit, and sample counts and depths are bounded.

#include <catch2/catch.hpp>

#include "../../examples/cornell_box.hpp"

#include <limits>

using namespace photon;

TEST_CASE("the stores-per-photon bound follows Russian roulette", "[render][limits]") {
    CHECK(stores_per_photon(0.0, 10) == Approx(1.0));
    CHECK(stores_per_photon(0.5, 3) == Approx(1.75));
    CHECK(stores_per_photon(1.0, 10) == Approx(10.0));
    CHECK(stores_per_photon(2.0, 10) == Approx(10.0));  // clamped: a photon survives with probability <= 1
}

TEST_CASE("the memory estimate bounds what a Cornell-box render stores", "[render][limits]") {
    const auto box = cornell::make_cornell_box<float>();
    RenderSettings s;
    s.mode = RenderMode::pm;
    s.width = 32;
    s.height = 24;
    s.samples_per_pixel = 1;
    s.shadow_samples = 1;
    s.final_gather_rays = 4;
    s.global_photons = 20'000;
    s.caustic_photons = 20'000;
    const double rho = max_albedo(box.scene);
    CHECK(rho > 0.5);
    CHECK(rho <= 1.0);
    const MemoryEstimate m = estimate_memory(s, rho);
    CHECK(m.film == Approx(32.0 * 24.0 * 24.0));
    const RenderResult r = render(box.scene, box.camera, s);
    const double stored = double(r.stats.global.stored + r.stats.caustic.stored);
    REQUIRE(stored > 0);
    // The maps hold 20 bytes per photon; the estimate covers them and the transient copies.
    CHECK(double(r.stats.global.memory_bytes + r.stats.caustic.memory_bytes) < m.photon_maps);
    CHECK(stored * bytes_per_stored_photon <= m.photon_maps);
    CHECK(estimate_memory(s, 0.0).photon_maps < m.photon_maps);
    s.mode = RenderMode::rt;
    CHECK(estimate_memory(s, rho).photon_maps == 0.0);
}

TEST_CASE("a render larger than its memory limit stops before allocating, with the sizes", "[render][limits]") {
    const auto box = cornell::make_cornell_box<float>();
    RenderSettings s;
    s.width = 65536;
    s.height = 65536;  // 96 GiB of film and image buffer
    s.global_photons = 1'000'000'000'000;
    s.memory_limit = std::uint64_t(1) << 30;
    REQUIRE_THROWS_AS(render(box.scene, box.camera, s), MemoryLimitError);
    REQUIRE_THROWS_WITH(render(box.scene, box.camera, s),
                        Catch::Contains("not enough memory") && Catch::Contains("film 96.0 GiB") &&
                            Catch::Contains("lower the resolution or the photon counts"));
    // Without a limit the system's available memory is the limit; no machine has a petabyte.
    s.memory_limit = 0;
    CHECK_THROWS_AS(render(box.scene, box.camera, s), MemoryLimitError);
}

TEST_CASE("the available memory is read from the system", "[render][limits]") {
    const auto available = available_memory();
    REQUIRE(available.has_value());
    CHECK(*available > 1e6);
}

TEST_CASE("sample counts and depths are bounded", "[render][limits]") {
    RenderSettings s;
    CHECK_NOTHROW(validate(s));
    auto rejects = [](RenderSettings t, const char* what) {
        INFO(what);
        CHECK_THROWS_WITH(validate(t), Catch::Contains(what));
    };
    // 2^32 - 1 samples would round up to a 65536 x 65536 grid, which overflows to 0 samples.
    RenderSettings t = s;
    t.samples_per_pixel = std::numeric_limits<unsigned>::max();
    rejects(t, "samples per pixel must be from 1 to 1000000");
    t = s, t.shadow_samples = SettingsLimits::max_samples + 1;
    rejects(t, "shadow samples");
    t = s, t.final_gather_rays = SettingsLimits::max_samples + 1;
    rejects(t, "final gather rays");
    t = s, t.max_ray_depth = 257;  // a recursion depth: bounded so that it cannot overflow the stack
    rejects(t, "max ray depth must be from 1 to 256");
    t = s, t.max_photon_depth = 0;
    rejects(t, "max photon depth");
    t = s, t.max_ray_depth = 256, t.samples_per_pixel = 1'000'000;
    CHECK_NOTHROW(validate(t));
}
