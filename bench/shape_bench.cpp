// SPDX-License-Identifier: MIT
// Rays per second of one intersect() call per shape, against the sphere: the same 4096 rays
// (from a sphere of radius 3 around the shape towards points within radius 1 of its centre, so
// most hit), single-threaded, in float and double. `hit_fraction` says how many of them hit.
//
//   build/bench/shape_bench --benchmark_min_time=0.5

#include <benchmark/benchmark.h>

#include <photon/geometry/blob.hpp>
#include <photon/geometry/cylinder.hpp>
#include <photon/geometry/lathe.hpp>
#include <photon/geometry/height_field.hpp>
#include <photon/geometry/polygon.hpp>
#include <photon/geometry/polynomial_surface.hpp>
#include <photon/geometry/prism.hpp>
#include <photon/geometry/quadric.hpp>
#include <photon/geometry/sor.hpp>
#include <photon/geometry/sphere.hpp>
#include <photon/geometry/torus.hpp>
#include <photon/geometry/superellipsoid.hpp>
#include <photon/geometry/triangle.hpp>
#include <photon/geometry/triangle_mesh.hpp>
#include <photon/math/rng.hpp>
#include <photon/math/sampling.hpp>
#include <photon/scene/scene.hpp>

#include <array>
#include <cmath>
#include <map>
#include <vector>

namespace {

using namespace photon;

template <class S> const std::vector<Ray<S>>& rays() {
    static const std::vector<Ray<S>> all = [] {
        Pcg32 rng(42, 0);
        std::vector<Ray<S>> r;
        for (int i = 0; i < 4096; ++i) {
            const Vec3<S> from = S(3) * uniform_sphere(rng.uniform2<S>());
            const Vec3<S> to = uniform_sphere(rng.uniform2<S>()) * rng.uniform<S>();
            r.push_back({from, glm::normalize(to - from)});
        }
        return r;
    }();
    return all;
}

template <class S> QuadricCoefficients<S> coefficients(Vec3<S> squares, S constant) {
    return {squares, Vec3<S>(S(0)), Vec3<S>(S(0)), constant};
}

template <class Shape> void run(benchmark::State& state, const Shape& shape) {
    using S = scalar_of<Shape>;
    const auto& all = rays<S>();
    std::size_t i = 0, hits = 0, tests = 0;
    for (auto _ : state) {
        const auto h = shape.intersect(all[i]);
        benchmark::DoNotOptimize(h);
        hits += h.has_value();
        ++tests;
        i = (i + 1) & (all.size() - 1);
    }
    state.SetItemsProcessed(std::int64_t(tests));
    state.counters["hit_fraction"] = double(hits) / double(std::max<std::size_t>(tests, 1));
}

template <class S> void sphere(benchmark::State& s) { run(s, Sphere<S>(Vec3<S>(S(0)), S(1))); }
template <class S> void quadric_sphere(benchmark::State& s) { run(s, Quadric<S>(coefficients<S>(Vec3<S>(S(1)), S(-1)))); }
template <class S> void quadric_ellipsoid(benchmark::State& s) {
    const auto map = Affine<S>::scale({1, S(0.5), S(0.7)}).then(Affine<S>::rotate_xyz({30, 45, 60}));
    run(s, Quadric<S>(coefficients<S>(Vec3<S>(S(1)), S(-1))).transformed(map));
}
template <class S> void quadric_cylinder(benchmark::State& s) {  // shapes.inc's Cylinder_Y, unbounded
    run(s, Quadric<S>(coefficients<S>({1, 0, 1}, S(-1))));
}
template <class S> void quadric_cone(benchmark::State& s) {  // QCone_Y, unbounded
    run(s, Quadric<S>(coefficients<S>({1, -1, 1}, S(0))));
}
template <class S> void cylinder(benchmark::State& s) { run(s, Cylinder<S>({0, -1, 0}, {0, 1, 0}, S(1))); }
template <class S> void csg_quadric_cylinder(benchmark::State& s) {  // Cylinder_Y cut by a box: the same solid
    using Tree = DefaultCsg<S>;
    run(s, Tree::intersection({Tree(Quadric<S>(coefficients<S>({1, 0, 1}, S(-1)))), Tree(Box<S>({-2, -1, -2}, {2, 1, 2}))}));
}
template <class S> void triangle(benchmark::State& s) { run(s, Triangle<S>({-1, -1, 0}, {1, -1, 0}, {0, 1, 0})); }
template <class S> void polygon_square(benchmark::State& s) {
    run(s, Polygon<S>({{{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}}));
}
template <class S> void polygon_star(benchmark::State& s) {  // one loop of 5 crossing edges
    std::vector<Vec3<S>> loop;
    for (int k = 0; k < 5; ++k) {
        const double a = (90.0 + 144.0 * k) * pi<double> / 180.0;
        loop.push_back(Vec3<S>(S(std::cos(a)), S(std::sin(a)), S(0)));
    }
    run(s, Polygon<S>({loop}));
}

std::vector<OutlineSegment> square_contour(glm::dvec2 centre, double half) {
    const glm::dvec2 p[4] = {centre + glm::dvec2(-half, -half), centre + glm::dvec2(half, -half),
                             centre + glm::dvec2(half, half), centre + glm::dvec2(-half, half)};
    return {OutlineSegment::line(p[0], p[1]), OutlineSegment::line(p[1], p[2]), OutlineSegment::line(p[2], p[3]),
            OutlineSegment::line(p[3], p[0])};
}
template <class S> void prism_square(benchmark::State& s) {  // a box as a linear prism
    run(s, Prism<S>(Outline({square_contour(glm::dvec2(0.0), 1)}), -1, 1));
}
template <class S> void prism_curved(benchmark::State& s) {  // two cubic Beziers and a quadratic, and a square hole
    const glm::dvec2 a(-1, -0.5), b(1, -0.5), c(0, 1);
    run(s, Prism<S>(Outline({{OutlineSegment::cubic(a, {-0.5, -1.5}, {0.5, -1.5}, b), OutlineSegment::cubic(b, {1.4, 0.3}, {0.6, 1.1}, c),
                              OutlineSegment::quadratic(c, {-1.3, 0.9}, a)},
                             square_contour(glm::dvec2(0.0), 0.2)}),
                    -1, 1));
}
template <class S> void prism_conic(benchmark::State& s) {  // a square frustum
    run(s, Prism<S>(Outline({square_contour(glm::dvec2(0.0), 1)}), S(0.2), 1, PrismSweep::conic));
}
template <class S> void prism_text_row(benchmark::State& s) {  // 24 "glyphs" of 2 quadratic contours each, in a row
    std::vector<std::vector<OutlineSegment>> contours;
    for (int k = 0; k < 24; ++k) {
        const glm::dvec2 c(-1.0 + (k + 0.5) / 12.0, 0.0);
        std::vector<OutlineSegment> ring;
        for (int q = 0; q < 8; ++q) {  // an "o": 8 quadratic arcs
            const double a0 = q * pi<double> / 4, a1 = (q + 1) * pi<double> / 4, am = 0.5 * (a0 + a1);
            const double r = 0.035;
            ring.push_back(OutlineSegment::quadratic(c + r * glm::dvec2(std::cos(a0), 1.6 * std::sin(a0)),
                                                     c + r / std::cos(pi<double> / 8) * glm::dvec2(std::cos(am), 1.6 * std::sin(am)),
                                                     c + r * glm::dvec2(std::cos(a1), 1.6 * std::sin(a1))));
        }
        contours.push_back(ring);
        contours.push_back(square_contour(c, 0.012));
    }
    run(s, Prism<S>(Outline(contours), S(-0.1), S(0.1)));
}

/// Polynomials in x, y, z as powers -> coefficient, for the polynomial rows.
using BenchPoly = std::map<std::array<int, 3>, double>;
BenchPoly bench_mul(const BenchPoly& a, const BenchPoly& b) {
    BenchPoly out;
    for (const auto& [ma, ca] : a)
        for (const auto& [mb, cb] : b) out[{ma[0] + mb[0], ma[1] + mb[1], ma[2] + mb[2]}] += ca * cb;
    return out;
}
/// (|q|^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2), shapesq.inc's way of writing a torus.
BenchPoly bench_torus(double major, double minor) {
    const BenchPoly m{{{2, 0, 0}, 1}, {{0, 2, 0}, 1}, {{0, 0, 2}, 1}, {{0, 0, 0}, major * major - minor * minor}};
    BenchPoly p = bench_mul(m, m);
    p[{2, 0, 0}] -= 4 * major * major, p[{0, 0, 2}] -= 4 * major * major;
    return p;
}
template <class S> PolynomialSurface<S> bench_surface(const BenchPoly& p, int order) {
    std::vector<double> c(polynomial_term_count(order), 0.0);
    for (const auto& [m, v] : p) c[polynomial_term_index(order, m[0], m[1], m[2])] = v;
    return PolynomialSurface<S>(order, c);
}
template <class S> void torus(benchmark::State& s) { run(s, Torus<S>(S(0.7), S(0.3))); }
template <class S> void poly_torus(benchmark::State& s) {  // the same torus as a quartic
    run(s, bench_surface<S>(bench_torus(0.7, 0.3), 4));
}
template <class S> void poly_sextic(benchmark::State& s) {  // a sphere in a torus's hole, as one order-6 surface
    const BenchPoly sphere{{{2, 0, 0}, 1}, {{0, 2, 0}, 1}, {{0, 0, 2}, 1}, {{0, 0, 0}, -0.09}};
    run(s, bench_surface<S>(bench_mul(sphere, bench_torus(0.7, 0.3)), 6));
}
template <class S> void superellipsoid_round(benchmark::State& s) { run(s, Superellipsoid<S>(1, 1)); }  // the sphere
template <class S> void superellipsoid_box(benchmark::State& s) { run(s, Superellipsoid<S>(S(0.2), S(0.2))); }
template <class S> void superellipsoid_star(benchmark::State& s) { run(s, Superellipsoid<S>(S(2.5), S(2.5))); }
template <class S> void lathe_cylinder(benchmark::State& s) {  // a closed cylinder of 3 lines
    run(s, Lathe<S>({OutlineSegment::line({0, -1}, {1, -1}), OutlineSegment::line({1, -1}, {1, 1}),
                     OutlineSegment::line({1, 1}, {0, 1})}));
}
template <class S> void lathe_vase(benchmark::State& s) {  // two cubic Beziers
    run(s, Lathe<S>({OutlineSegment::cubic({0, -1}, {0.9, -1}, {1.1, -0.3}, {0.6, 0.1}),
                     OutlineSegment::cubic({0.6, 0.1}, {0.3, 0.4}, {0.3, 0.8}, {0.5, 1})}));
}
template <class S> void sor_vase(benchmark::State& s) {  // 4 cubic segments, closed
    run(s, Sor<S>({{0.2, -1.2}, {0.8, -1}, {1, -0.5}, {0.5, 0}, {0.4, 0.5}, {0.6, 1}, {0.7, 1.2}}));
}
template <class S> void blob_ball(benchmark::State& s) {  // one sphere component: the unit sphere
    using C = typename Blob<S>::Component;
    run(s, Blob<S>({C::sphere(Vec3<S>(0), S(1) / S(std::sqrt(1 - std::sqrt(0.5))), 1)}, S(0.5)));
}
template <class S> void blob_crossed_rods(benchmark::State& s) {  // POV-Ray's blob1a, scaled to radius ~1
    using C = typename Blob<S>::Component;
    run(s, Blob<S>({C::cylinder({-1, 0, 0}, {1, 0, 0}, S(0.57), 2), C::cylinder({0, 0, -1}, {0, 0, 1}, S(0.57), 2),
                    C::sphere({0, S(0.43), 0}, S(0.36), -4)},
                   S(0.5)));
}
template <class S> void blob_ten_balls(benchmark::State& s) {  // ten sphere components in a ring
    using C = typename Blob<S>::Component;
    std::vector<C> balls;
    for (int i = 0; i < 10; ++i) {
        const double a = 2 * 3.14159265358979 * i / 10;
        balls.push_back(C::sphere(Vec3<S>(S(0.7 * std::cos(a)), 0, S(0.7 * std::sin(a))), S(0.45), 1));
    }
    run(s, Blob<S>(std::move(balls), S(0.4)));
}
/// Rolling hills on a 256 x 256 grid, heights in [0, 1].
std::vector<double> hills(unsigned n) {
    std::vector<double> h(std::size_t(n) * n);
    for (unsigned j = 0; j < n; ++j)
        for (unsigned i = 0; i < n; ++i)
            h[std::size_t(j) * n + i] = 0.5 + 0.25 * std::sin(0.09 * i) * std::cos(0.07 * j) + 0.25 * std::sin(0.031 * (i + 2 * j));
    return h;
}
/// The unit square's field placed over [-1, 1]^2, heights from -1 to 1.
template <class S> Affine<S> hills_placement() {
    return Affine<S>::scale({2, 2, 2}).then(Affine<S>::translate({-1, -1, -1}));
}
template <class S> void height_field_256(benchmark::State& s) {
    run(s, Transformed<HeightField<S>>(HeightField<S>(256, 256, hills(256)), hills_placement<S>()));
}
template <class S> void height_field_256_smooth(benchmark::State& s) {
    run(s, Transformed<HeightField<S>>(HeightField<S>(256, 256, hills(256), {.smooth = true}), hills_placement<S>()));
}
template <class S> void height_field_as_mesh(benchmark::State& s) {  // the same 130,050 triangles in a mesh's BVH
    const unsigned n = 256;
    const std::vector<double> h = hills(n);
    std::vector<Vec3<S>> points;
    for (unsigned j = 0; j < n; ++j)
        for (unsigned i = 0; i < n; ++i)
            points.push_back(hills_placement<S>().point(Vec3<S>(S(double(i) / (n - 1)), S(h[std::size_t(j) * n + i]),
                                                                S(double(j) / (n - 1)))));
    std::vector<typename TriangleMesh<S>::Index> tris;
    for (unsigned j = 0; j + 1 < n; ++j)
        for (unsigned i = 0; i + 1 < n; ++i) {
            const auto v = [&](unsigned a, unsigned b) { return std::uint32_t(b * n + a); };
            tris.push_back({v(i, j), v(i + 1, j), v(i, j + 1)});
            tris.push_back({v(i + 1, j + 1), v(i, j + 1), v(i + 1, j)});
        }
    run(s, TriangleMesh<S>(std::move(points), std::move(tris)));
}

}  // namespace

#define PHOTON_SHAPE_BENCH(f) BENCHMARK_TEMPLATE(f, float); BENCHMARK_TEMPLATE(f, double)
PHOTON_SHAPE_BENCH(sphere);
PHOTON_SHAPE_BENCH(quadric_sphere);
PHOTON_SHAPE_BENCH(quadric_ellipsoid);
PHOTON_SHAPE_BENCH(quadric_cylinder);
PHOTON_SHAPE_BENCH(quadric_cone);
PHOTON_SHAPE_BENCH(cylinder);
PHOTON_SHAPE_BENCH(csg_quadric_cylinder);
PHOTON_SHAPE_BENCH(triangle);
PHOTON_SHAPE_BENCH(polygon_square);
PHOTON_SHAPE_BENCH(polygon_star);
PHOTON_SHAPE_BENCH(prism_square);
PHOTON_SHAPE_BENCH(prism_curved);
PHOTON_SHAPE_BENCH(prism_conic);
PHOTON_SHAPE_BENCH(prism_text_row);
PHOTON_SHAPE_BENCH(torus);
PHOTON_SHAPE_BENCH(poly_torus);
PHOTON_SHAPE_BENCH(poly_sextic);
PHOTON_SHAPE_BENCH(superellipsoid_round);
PHOTON_SHAPE_BENCH(superellipsoid_box);
PHOTON_SHAPE_BENCH(superellipsoid_star);
PHOTON_SHAPE_BENCH(lathe_cylinder);
PHOTON_SHAPE_BENCH(lathe_vase);
PHOTON_SHAPE_BENCH(sor_vase);
PHOTON_SHAPE_BENCH(blob_ball);
PHOTON_SHAPE_BENCH(blob_crossed_rods);
PHOTON_SHAPE_BENCH(blob_ten_balls);
PHOTON_SHAPE_BENCH(height_field_256);
PHOTON_SHAPE_BENCH(height_field_256_smooth);
PHOTON_SHAPE_BENCH(height_field_as_mesh);

BENCHMARK_MAIN();
