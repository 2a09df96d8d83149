// SPDX-License-Identifier: MIT
// HeightField (geometry/height_field.hpp): the grid walk against every triangle of POV-Ray's
// triangulation for random rays (float and double, tiny and huge scales), grazing and vertical
// rays, the water level, smooth normals at the grid points, the inside against the parity of
// upward rays, and POV-Ray's heights of an image.

#include <catch2/catch.hpp>

#include <photon/geometry/height_field.hpp>
#include <photon/geometry/solid.hpp>
#include <photon/geometry/transformed.hpp>
#include <photon/geometry/triangle.hpp>
#include <photon/math/rng.hpp>
#include <photon/math/sampling.hpp>

#include <cmath>
#include <vector>

using namespace photon;

namespace {

template <class S> double hf_tol() { return std::is_same_v<S, float> ? 3e-4 : 1e-9; }

/// A rows x columns grid of heights in [0.1, 0.9] drawn with `seed`.
std::vector<double> hf_random_heights(unsigned columns, unsigned rows, std::uint64_t seed) {
    Pcg32 rng(seed, 3);
    std::vector<double> h(std::size_t(columns) * rows);
    for (double& v : h) v = 0.1 + 0.8 * rng.uniform<double>();
    return h;
}

/// POV-Ray's two triangles per cell, in the unit square, scaled by `scale`.
template <class S>
std::vector<Triangle<S>> hf_triangles(unsigned nx, unsigned nz, const std::vector<double>& h, double scale) {
    std::vector<Triangle<S>> out;
    const auto v = [&](unsigned i, unsigned j) {
        return Vec3<S>(S(scale * i / (nx - 1)), S(scale * h[std::size_t(j) * nx + i]), S(scale * j / (nz - 1)));
    };
    for (unsigned j = 0; j + 1 < nz; ++j)
        for (unsigned i = 0; i + 1 < nx; ++i) {
            out.emplace_back(v(i, j), v(i + 1, j), v(i, j + 1));
            out.emplace_back(v(i + 1, j + 1), v(i, j + 1), v(i + 1, j));
        }
    return out;
}

template <class S> std::optional<Hit<S>> hf_nearest(const std::vector<Triangle<S>>& tris, const Ray<S>& ray) {
    std::optional<Hit<S>> best;
    for (const auto& t : tris)
        if (auto h = t.intersect(ray); h && (!best || h->t < best->t)) best = h;
    return best;
}

}  // namespace

static_assert(Solid<HeightField<float>> && Solid<Transformed<HeightField<double>>>);

TEMPLATE_TEST_CASE("height_field: the grid walk finds what every triangle finds, at several scales",
                   "[geometry][height_field]", float, double) {
    using S = TestType;
    const unsigned nx = 9, nz = 6;
    const std::vector<double> h = hf_random_heights(nx, nz, 11);
    for (const double scale : {1e-4, 1.0, 1e4}) {
        const Transformed<HeightField<S>> field(HeightField<S>(nx, nz, h), Affine<S>::scale(Vec3<S>(S(scale))));
        const auto tris = hf_triangles<S>(nx, nz, h, scale);
        Pcg32 rng(5, 9);
        int hits = 0, agree = 0, total = 0;
        for (int k = 0; k < 3000; ++k) {
            // From a box around the field (often above it, sometimes under it) in a random direction.
            const Vec3<S> o = Vec3<S>(S(-0.5) + S(2) * rng.uniform<S>(), S(-0.3) + S(1.6) * rng.uniform<S>(),
                                      S(-0.5) + S(2) * rng.uniform<S>()) * S(scale);
            const Vec3<S> d = uniform_sphere<S>(rng.uniform2<S>());
            const Ray<S> ray{o, d};
            const auto a = field.intersect(ray), b = hf_nearest(tris, ray);
            ++total;
            if (a.has_value() != b.has_value()) continue;  // counted below: a ray along a shared edge may split
            ++agree;
            if (!a) continue;
            ++hits;
            CHECK(double(a->t) == Approx(double(b->t)).epsilon(hf_tol<S>()).margin(hf_tol<S>() * scale));
            CHECK(std::abs(double(glm::dot(a->normal, b->normal))) == Approx(1).epsilon(hf_tol<S>()));
            CHECK(a->normal.y > S(0));  // up, out of the solid below the surface
        }
        // Float rays that graze a triangle's edge may be found by one and not the other.
        CHECK(agree >= total - (std::is_same_v<S, float> ? 3 : 0));
        CHECK(hits > 300);  // about 400 of the 3000 rays meet the surface
    }
}

TEST_CASE("height_field: vertical, grazing and horizontal rays", "[geometry][height_field]") {
    // A ramp rising along x: heights i / 4 at column i.
    std::vector<double> h;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 5; ++i) h.push_back(0.25 * i);
    const HeightField<double> ramp(5, 3, h);
    // Straight down onto x = 0.6: the ramp's height there is 0.6.
    const auto down = ramp.intersect({{0.6, 2.0, 0.3}, {0, -1, 0}});
    REQUIRE(down);
    CHECK(down->t == Approx(1.4));
    CHECK(down->normal.x == Approx(-1 / std::sqrt(2.0)));
    // Along the ramp's own plane, just above it: no hit; just below it, from outside, a hit at the near edge.
    CHECK_FALSE(ramp.intersect({{-1.0, -1.0 + 1e-6, 0.5}, glm::normalize(Vec3<double>(1, 1, 0))}));
    const auto under = ramp.intersect({{0.5, 0.2, -1.0}, {0, 0, 1}});
    CHECK_FALSE(under);  // horizontal under the surface: the sides and the bottom are no surface (POV-Ray's)
    const auto across = ramp.intersect({{-1.0, 0.5, 0.5}, {1, 0, 0}});
    REQUIRE(across);
    CHECK(across->t == Approx(1.5));
    // A ray parallel to the z axis at a grid line, exactly on a shared edge: found once.
    const auto edge = ramp.intersect({{0.5, 1.0, 0.5}, glm::normalize(Vec3<double>(0, -1, 1e-3))});
    REQUIRE(edge);
    CHECK(edge->point.y == Approx(0.5).margin(1e-9));
}

TEST_CASE("height_field: nothing below the water level is drawn, and below it is inside", "[geometry][height_field]") {
    std::vector<double> h{0.1, 0.8, 0.1, 0.8};  // 2 x 2: low at x = 0, high at x = 1
    const HeightField<double> field(2, 2, h, {.water_level = 0.45});
    CHECK(field.bounds().min.y >= 0.45 - 1e-12);
    CHECK_FALSE(field.intersect({{0.1, 2.0, 0.5}, {0, -1, 0}}));  // the surface there is at 0.17, under water
    const auto high = field.intersect({{0.9, 2.0, 0.5}, {0, -1, 0}});
    REQUIRE(high);
    CHECK(high->point.y == Approx(0.73));
    CHECK(field.contains({0.1, 0.3, 0.5}));   // below the water level
    CHECK(field.contains({0.1, 0.44, 0.5}));
    CHECK_FALSE(field.contains({0.1, 0.5, 0.5}));
    CHECK_FALSE(field.contains({1.2, 0.3, 0.5}));  // off the unit square
}

TEMPLATE_TEST_CASE("height_field: inside is below the surface, as upward rays count it", "[geometry][height_field]", float,
                   double) {
    using S = TestType;
    const HeightField<S> field(7, 7, hf_random_heights(7, 7, 4));
    Pcg32 rng(2, 2);
    int inside = 0;
    for (int k = 0; k < 4000; ++k) {
        const Vec3<S> p(S(0.02) + S(0.96) * rng.uniform<S>(), rng.uniform<S>(), S(0.02) + S(0.96) * rng.uniform<S>());
        const bool up = field.intersect({p, {0, 1, 0}}).has_value();
        CHECK(field.contains(p) == up);
        inside += up;
    }
    CHECK(inside > 1000);
}

TEST_CASE("height_field: smooth normals are POV-Ray's at the grid points and blend between", "[geometry][height_field]") {
    // A ridge along z at column 1 of 3: each grid point's normal averages its triangles.
    std::vector<double> h{0.0, 0.5, 0.0, 0.0, 0.5, 0.0, 0.0, 0.5, 0.0};
    const HeightField<double> flat(3, 3, h), smooth(3, 3, h, {.smooth = true});
    // On the ridge line the smooth normal is straight up (the two slopes cancel).
    const auto top = smooth.intersect({{0.5, 2.0, 0.5 + 1e-7}, {0, -1, 0}});
    REQUIRE(top);
    CHECK(top->normal.x == Approx(0).margin(1e-6));
    CHECK(top->normal.y == Approx(1));
    // Half way down the left slope: half way between the ridge's and the edge's normals.
    const auto mid = smooth.intersect({{0.25, 2.0, 0.5}, {0, -1, 0}});
    const auto face = flat.intersect({{0.25, 2.0, 0.5}, {0, -1, 0}});
    REQUIRE(mid);
    REQUIRE(face);
    CHECK(face->normal.x < mid->normal.x);  // the facet leans more than the blend
    CHECK(mid->normal.x < 0);
}

TEST_CASE("height_field: POV-Ray's heights of an image", "[geometry][height_field]") {
    // 8-bit colour: red is the high byte, green the low one; row 0 is the far edge (z = 1).
    PixelGrid colour(2, 2, {{1.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 1.0f, 0.0f, 1.0f}, {0.5f, 0.5f, 0.0f, 1.0f}, {0, 0, 0, 1}});
    const std::vector<double> h = height_field_heights(colour);
    CHECK(h[2] == Approx(255.0 * 256 / 65536));         // (0, far) : red 255
    CHECK(h[3] == Approx(255.0 / 65536));               // (1, far) : green 255
    CHECK(h[0] == Approx(std::floor((0.5 * 256 + 0.5) * 255) / 65536));
    // Grey and 16 bits: the grey level over 65535 steps.
    PixelGrid grey(2, 1, {{0.5f, 0.5f, 0.5f, 1.0f}, {1.0f, 1.0f, 1.0f, 1.0f}});
    grey.grayscale = true;
    grey.max_value = 65535;
    const std::vector<double> g = height_field_heights(grey);
    CHECK(g[0] == Approx(std::floor(0.5 * 65535) / 65536));
    CHECK(g[1] == Approx(65535.0 / 65536));
}
