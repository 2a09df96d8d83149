// SPDX-License-Identifier: MIT
// Shadow rays tested against only the objects touching their region give the same answers as a
// full BVH traversal.

#include <catch2/catch.hpp>

#include "../../examples/cornell_box.hpp"

using namespace photon;

namespace {
template <Scalar S> Vec3<S> uniform3(Pcg32& rng) {
    const S x = rng.uniform<S>(), y = rng.uniform<S>();
    return {x, y, rng.uniform<S>()};
}
}  // namespace

TEMPLATE_TEST_CASE("occluders_in finds every object that can block a ray inside the region", "[scene]", float, double) {
    using S = TestType;
    const auto box = cornell::make_cornell_box<S>();
    const auto& scene = box.scene;
    const BBox<S> bounds = scene.bounds();
    Pcg32 rng(5, 1);
    std::vector<std::uint32_t> ids;
    std::size_t blocked = 0, rays = 0, culled = 0;
    for (int trial = 0; trial < 300; ++trial) {
        // A point and a small "light" sphere anywhere in the box, as direct lighting has them.
        const Vec3<S> x = bounds.min + uniform3<S>(rng) * bounds.extent();
        const Vec3<S> light = bounds.min + uniform3<S>(rng) * bounds.extent();
        const S radius = S(0.2) * rng.uniform<S>();
        BBox<S> region = BBox<S>::of_point(x);
        region.extend(BBox<S>{light - radius, light + radius});
        scene.occluders_in(region, ids);
        culled += scene.objects().size() - ids.size();
        for (int i = 0; i < 50; ++i) {
            const Vec3<S> target = light + radius * uniform_sphere(rng.uniform2<S>()) * std::cbrt(rng.uniform<S>());
            const Vec3<S> d = target - x;
            const S length = glm::length(d);
            if (!(length > S(0))) continue;
            const Ray<S> ray{x, d / length, length};
            const bool full = scene.occluded(ray);
            CHECK(scene.occluded_by(ids, ray) == full);
            blocked += full ? 1 : 0;
            ++rays;
        }
    }
    CHECK(blocked > rays / 10);  // the test exercises both answers
    CHECK(blocked < rays);
    CHECK(culled > 0);           // and the culling does something
}

TEMPLATE_TEST_CASE("occluders_in says when a region holds more objects than its limit", "[scene]", float, double) {
    using S = TestType;
    const auto box = cornell::make_cornell_box<S>();
    const auto& scene = box.scene;
    std::vector<std::uint32_t> all;
    REQUIRE(scene.occluders_in(scene.bounds(), all));  // no limit: complete
    REQUIRE(all.size() > 2);
    std::vector<std::uint32_t> ids;
    CHECK(scene.occluders_in(scene.bounds(), ids, all.size()));      // exactly at the limit: complete
    CHECK(ids.size() == all.size());
    CHECK_FALSE(scene.occluders_in(scene.bounds(), ids, all.size() - 1));  // one over: incomplete
    CHECK(ids.size() <= all.size());
}
