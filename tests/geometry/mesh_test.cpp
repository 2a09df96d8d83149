// SPDX-License-Identifier: MIT
// TriangleMesh and its 4-wide BVH: nearest and any hit against brute force over every triangle on
// random rays, no leaks through shared edges and vertices of a closed mesh, and small meshes that
// leave slots of the root node unused.

#include <catch2/catch.hpp>

#include <photon/geometry/triangle.hpp>
#include <photon/geometry/triangle_mesh.hpp>
#include <photon/math/rng.hpp>

#include <cmath>
#include <limits>
#include <vector>

using namespace photon;

namespace {

template <class S> struct MeshData {
    std::vector<Vec3<S>> positions;
    std::vector<typename TriangleMesh<S>::Index> triangles;
};

/// A closed cube sphere of 12 n^2 triangles with bumps: six grids pushed onto the sphere, the
/// radius varying with direction. Vertices on the cube's edges are repeated with bit-identical
/// coordinates, as an OBJ exporter writing per-face vertices would.
template <class S> MeshData<S> bumpy_sphere(int n) {
    MeshData<S> m;
    for (int face = 0; face < 6; ++face) {
        const int axis = face / 2;
        const S sign = face % 2 == 0 ? S(1) : S(-1);
        const auto base = static_cast<std::uint32_t>(m.positions.size());
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) {
                Vec3<S> c;
                c[axis] = sign;
                c[(axis + 1) % 3] = S(2 * i - n) / S(n) * sign;
                c[(axis + 2) % 3] = S(2 * j - n) / S(n);
                const Vec3<S> d = glm::normalize(c);
                m.positions.push_back(d * (S(1) + S(0.2) * std::sin(S(5) * d.x) * std::cos(S(4) * d.y + S(3) * d.z)));
            }
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const std::uint32_t v00 = base + std::uint32_t(j * (n + 1) + i), v10 = v00 + 1;
                const std::uint32_t v01 = v00 + std::uint32_t(n + 1), v11 = v01 + 1;
                m.triangles.push_back({v00, v10, v11});
                m.triangles.push_back({v00, v11, v01});
            }
    }
    return m;
}

/// Nearest t over all triangles with the same watertight test the mesh uses, or +inf.
template <class S> S brute_force(const MeshData<S>& m, const Ray<S>& ray) {
    const detail::WatertightRay<S> prepared(ray);
    S best = std::numeric_limits<S>::infinity();
    for (const auto& t : m.triangles)
        detail::with_shear_axis(prepared, [&](auto kz) {
            const auto hit = detail::intersect_watertight<kz()>(prepared, ray.t_max, m.positions[t[0]],
                                                                m.positions[t[1]], m.positions[t[2]]);
            if (hit && *hit < best) best = *hit;
        });
    return best;
}

template <class S> Vec3<S> random_direction(Pcg32& rng) {
    const S z = S(1) - S(2) * rng.uniform<S>(), phi = S(2) * pi<S> * rng.uniform<S>();
    const S s = std::sqrt(std::max(S(0), S(1) - z * z));
    return {s * std::cos(phi), s * std::sin(phi), z};
}

}  // namespace

TEMPLATE_TEST_CASE("mesh nearest and any hit match brute force over all triangles", "[geometry][mesh]", float, double) {
    using S = TestType;
    const MeshData<S> m = bumpy_sphere<S>(12);  // 1,728 triangles
    // Leaves of one triangle, the default, and leaves of up to 8 in two blocks of four.
    const BvhConfig config = GENERATE(BvhConfig{.max_leaf_size = 1}, BvhConfig{},
                                      BvhConfig{.max_leaf_size = 8, .intersection_cost = 8.0f});
    const TriangleMesh<S> mesh(m.positions, m.triangles, config);
    REQUIRE(mesh.triangle_count() == 1728);
    Pcg32 rng(7, 1);
    int hits = 0;
    for (int r = 0; r < 4000; ++r) {
        // Origins inside and outside the surface, some rays cut short.
        Ray<S> ray{(Vec3<S>(rng.uniform<S>(), rng.uniform<S>(), rng.uniform<S>()) * S(2) - S(1)) * S(1.5),
                   random_direction<S>(rng)};
        if (r % 3 == 0) ray.t_max = S(0.5) + rng.uniform<S>();
        const S expected = brute_force(m, ray);
        const auto h = mesh.intersect(ray);
        INFO("ray " << r);
        if (std::isinf(expected)) {
            CHECK_FALSE(h);
            CHECK_FALSE(mesh.occluded(ray));
        } else {
            REQUIRE(h);
            CHECK(h->t == Approx(expected).epsilon(std::is_same_v<S, float> ? 1e-6 : 1e-14));
            CHECK(mesh.occluded(ray));
            CHECK(glm::length(h->normal) == Approx(1));
            ++hits;
        }
    }
    CHECK(hits > 1000);  // the rays exercise both outcomes
    CHECK(hits < 3900);
}

TEMPLATE_TEST_CASE("no ray from inside a closed mesh escapes through an edge or a vertex", "[geometry][mesh]", float, double) {
    using S = TestType;
    const MeshData<S> m = bumpy_sphere<S>(20);
    const TriangleMesh<S> mesh(m.positions, m.triangles);
    // Aim exactly at every vertex and every edge midpoint, from the centre and from an off-centre
    // point: the rays where Moller-Trumbore's rounding can let a ray through.
    std::size_t escaped = 0, rays = 0;
    for (const Vec3<S> origin : {Vec3<S>(0, 0, 0), Vec3<S>(S(0.1), S(-0.2), S(0.05))})
        for (const auto& t : m.triangles)
            for (int k = 0; k < 3; ++k) {
                const Vec3<S> a = m.positions[t[k]], b = m.positions[t[(k + 1) % 3]];
                for (const Vec3<S> target : {a, (a + b) * S(0.5)}) {
                    ++rays;
                    const Ray<S> ray{origin, target - origin};
                    if (!mesh.intersect(ray)) ++escaped;
                    if (!mesh.occluded(ray)) ++escaped;
                }
            }
    CHECK(rays == 2 * 4800 * 3 * 2);
    CHECK(escaped == 0);
}

TEMPLATE_TEST_CASE("meshes of 1 to 18 triangles fill the root's slots correctly", "[geometry][mesh]", float, double) {
    using S = TestType;
    // Past Bvh::width (8) triangles the root has inner children too, and either half of its slots
    // (two SSE tests of four) may hold the one that is hit.
    for (std::uint32_t count = 1; count <= 18; ++count) {
        MeshData<S> m;
        for (std::uint32_t i = 0; i < count; ++i) {
            const S x = S(3 * i);
            m.positions.insert(m.positions.end(), {{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}});
            m.triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
        }
        const TriangleMesh<S> mesh(m.positions, m.triangles, {.max_leaf_size = 1});
        for (std::uint32_t i = 0; i < count; ++i) {
            const Ray<S> ray{{S(3 * i) + S(0.25), S(0.25), S(-2)}, {0, 0, 1}};
            const auto h = mesh.intersect(ray);
            REQUIRE(h);
            CHECK(h->t == Approx(2));
            CHECK(h->normal.z == Approx(1));
            CHECK_FALSE(mesh.intersect({{S(3 * i) + S(1.5), S(0.25), S(-2)}, {0, 0, 1}}));
        }
    }
    const TriangleMesh<S> empty({}, {});
    CHECK_FALSE(empty.intersect({{0, 0, -1}, {0, 0, 1}}));
    CHECK_FALSE(empty.occluded({{0, 0, -1}, {0, 0, 1}}));
}

TEST_CASE("degenerate and non-finite triangles never hit", "[geometry][mesh]") {
    const std::vector<Vec3<float>> p{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}};
    const TriangleMesh<float> mesh(p, {{0, 1, 2}, {0, 0, 3}});
    CHECK_FALSE(mesh.intersect({{0.5f, 0, -1}, {0, 0, 1}}));
    CHECK_FALSE(mesh.intersect({{0, 0.5f, -1}, {0, 0, 1}}));
    CHECK_THROWS_AS(TriangleMesh<float>({{0, 0, 0}, {1, 0, 0}, {0, NAN, 0}}, {{0, 1, 2}}), std::invalid_argument);
}
