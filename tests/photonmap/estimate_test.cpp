// SPDX-License-Identifier: MIT
// The radiance estimate's photon selection against brute force: the k nearest in the flattened
// metric, front-facing only, with the k-th left out and setting the radius.

#include <catch2/catch.hpp>

#include <photon/photon.hpp>

#include <algorithm>
#include <vector>

using namespace photon;

namespace {

/// estimate_irradiance's answer computed the slow way: every photon, sorted.
Rgb<float> brute_force_irradiance(std::span<const Photon> photons, const Vec3<float>& x, const Vec3<float>& n,
                                  const EstimateSettings& s) {
    std::vector<std::pair<float, Rgb<float>>> kept;
    for (const Photon& p : photons) {
        const Vec3<float> d = p.position - x;
        const float h = glm::dot(d, n);
        const float flat2 = glm::dot(d, d) + (s.flatten * s.flatten - 1.0f) * h * h;
        if (!(flat2 < s.max_radius * s.max_radius)) continue;
        if (s.reject_backfacing && !(glm::dot(p.packed.incident_direction(), n) < 0.0f)) continue;
        kept.emplace_back(flat2, p.packed.power());
    }
    std::sort(kept.begin(), kept.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    float r2 = s.max_radius * s.max_radius;
    std::size_t used = kept.size();
    if (kept.size() >= s.k) {
        r2 = kept[s.k - 1].first;
        used = s.k - 1;
    }
    Rgb<float> sum(0.0f);
    for (std::size_t i = 0; i < used; ++i) sum += kept[i].second;
    return used == 0 ? Rgb<float>(0.0f) : sum / (pi<float> * r2);
}

}  // namespace

TEST_CASE("the estimate uses exactly the k nearest front-facing photons in the flattened metric", "[estimate]") {
    // Photons on a floor and on a wall meeting it, arriving from both sides of each.
    Pcg32 rng(7, 3);
    std::vector<Photon> photons;
    for (int i = 0; i < 20'000; ++i) {
        const Vec2<float> u = rng.uniform2<float>();
        const bool floor = i % 3 != 0;
        const Vec3<float> at = floor ? Vec3<float>{2 * u.x - 1, 0.002f * rng.uniform<float>(), 2 * u.y - 1}
                                     : Vec3<float>{0.3f, 2 * u.x, 2 * u.y - 1};
        const Vec3<float> normal = floor ? Vec3<float>{0, 1, 0} : Vec3<float>{-1, 0, 0};
        const float side = rng.uniform<float>() < 0.8f ? -1.0f : 1.0f;  // mostly arriving onto the front
        const Vec3<float> incident = glm::normalize(side * normal + 0.5f * (uniform_sphere(rng.uniform2<float>())));
        photons.push_back({at, PackedPhoton(Rgb<float>(0.1f + rng.uniform<float>(), 0.2f, 0.3f), incident, PathKind::indirect)});
    }
    const PhotonMap map(photons);
    EstimateScratch scratch;
    for (const unsigned k : {1u, 2u, 10u, 150u, 1000u, 30'000u})
        for (const float flatten : {1.0f, 4.0f})
            for (const Vec3<float> x : {Vec3<float>{0, 0, 0}, Vec3<float>{0.25f, 0.001f, 0.5f}, Vec3<float>{-0.9f, 0, -0.9f}}) {
                const EstimateSettings s{.k = k, .max_radius = 0.3f, .flatten = flatten};
                const Vec3<float> n{0, 1, 0};
                const Rgb<float> fast = estimate_irradiance(map, x, n, s, scratch);
                const Rgb<float> slow = brute_force_irradiance(photons, x, n, s);
                INFO("k " << k << ", flatten " << flatten << ", x " << x.x << " " << x.z);
                CHECK((k == 1 ? slow.x == 0.0f : slow.x > 0.0f));  // k = 1 leaves out its only photon
                CHECK(fast.x == Approx(slow.x).epsilon(1e-4));
                CHECK(fast.z == Approx(slow.z).epsilon(1e-4));
            }
}
