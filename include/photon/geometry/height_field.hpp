// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray 3.7's height_field (source/core/shape/heightfield.cpp): a grid of heights over the
// unit square of the x-z plane, exactly as POV-Ray triangulates it. Column i of `columns` lies at
// x = i / (columns - 1), row j of `rows` at z = j / (rows - 1); each cell is cut along the
// diagonal from (i + 1, j) to (i, j + 1) into two flat triangles. `smooth` blends the corners'
// normals (POV-Ray's, computed in its grid units) bilinearly across the cell. Below
// `water_level` nothing is drawn. The inside (a Solid) is POV-Ray's: over the unit square,
// under the surface (heights raised to the water level), and everything below the water level.
// Rays walk the grid cell by cell (Amanatides and Woo's DDA, "A Fast Voxel Traversal Algorithm
// for Ray Tracing", 1987) and test a cell's two triangles only where the ray's height range
// meets the cell's.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "../texture/pixel_grid.hpp"
#include "primitive.hpp"

namespace photon {

struct HeightFieldOptions {
    bool smooth = false;       ///< POV-Ray's `smooth`: normals blended from the corners
    double water_level = 0.0;  ///< POV-Ray's `water_level`, in the heights' units (0 to 1)
};

template <Scalar S> class HeightField {
public:
    using scalar_type = S;

    /// `heights`: columns * rows of them, row by row from z = 0, each finite. Throws
    /// std::invalid_argument with fewer than 2 columns or rows, or the wrong number of heights.
    HeightField(unsigned columns, unsigned rows, std::vector<double> heights, HeightFieldOptions options = {});

    [[nodiscard]] unsigned columns() const noexcept { return nx_; }
    [[nodiscard]] unsigned rows() const noexcept { return nz_; }
    /// The height at column i, row j.
    [[nodiscard]] double height(unsigned i, unsigned j) const noexcept { return heights_[std::size_t(j) * nx_ + i]; }
    [[nodiscard]] const HeightFieldOptions& options() const noexcept { return options_; }
    [[nodiscard]] BBox<S> bounds() const noexcept { return bounds_; }

    /// POV-Ray's inside: x and z in [0, 1), below the surface or the water level.
    [[nodiscard]] bool contains(const Vec3<S>& p) const noexcept;
    /// The nearest hit on a triangle of the grid at or above the water level, in double.
    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept;

private:
    [[nodiscard]] double h(long i, long j) const noexcept { return heights_[std::size_t(j) * nx_ + std::size_t(i)]; }
    /// The cell's two triangles against the ray (grid space: x and z in cells, y in height);
    /// the nearest t in (0, t_max) at or above the water level, with its grid-space normal.
    [[nodiscard]] bool hit_cell(long i, long j, const glm::dvec3& o, const glm::dvec3& d, double t_max, double& t,
                                glm::dvec3& normal) const noexcept;
    [[nodiscard]] glm::dvec3 smooth_normal(long i, long j, double fx, double fz) const noexcept;
    void compute_smooth_normals();

    unsigned nx_, nz_;
    std::vector<double> heights_;
    HeightFieldOptions options_;
    std::vector<float> cell_low_, cell_high_;  ///< per cell, the lowest and highest corner
    std::vector<glm::dvec3> normals_;           ///< `smooth`: per grid point, in local space
    double low_ = 0, high_ = 0;                 ///< the drawn heights: [max(min, water), max]
    BBox<S> bounds_;
};

/// POV-Ray 3.7's heights of an image (image_height_at, scaled as its height field scales them:
/// a sample of 65535 is 65535 / 65536): a palette image's index times 256; a grey image's grey level; a colour image of more than
/// 8 bits its grey value (0.297 red + 0.589 green + 0.114 blue); an 8-bit colour image red as
/// the high byte and green as the low one. Row 0 of the image is the far edge (z = 1).
[[nodiscard]] inline std::vector<double> height_field_heights(const PixelGrid& image) {
    const unsigned w = image.width(), hgt = image.height();
    std::vector<double> out(std::size_t(w) * hgt);
    for (unsigned z = 0; z < hgt; ++z)
        for (unsigned x = 0; x < w; ++x) {
            const PixelGrid::Pixel& p = image.at(x, hgt - 1 - z);
            double v;
            if (!image.indices.empty()) v = double(image.indices[std::size_t(hgt - 1 - z) * w + x]) * 256.0;
            else if (image.grayscale) v = double(p[0]) * 65535.0;
            else if (image.max_value != 255) v = (0.297 * p[0] + 0.589 * p[1] + 0.114 * p[2]) * 65535.0;
            else v = (double(p[0]) * 256.0 + double(p[1])) * 255.0;
            out[std::size_t(z) * w + x] = std::floor(std::clamp(v, 0.0, 65535.0) + 1e-6) / 65536.0;
        }
    return out;
}

template <Scalar S>
HeightField<S>::HeightField(unsigned columns, unsigned rows, std::vector<double> heights, HeightFieldOptions options)
    : nx_(columns), nz_(rows), heights_(std::move(heights)), options_(options) {
    if (nx_ < 2 || nz_ < 2) throw std::invalid_argument("height_field: at least 2 x 2 heights are needed");
    if (heights_.size() != std::size_t(nx_) * nz_)
        throw std::invalid_argument("height_field: one height per column and row is needed");
    if (!std::all_of(heights_.begin(), heights_.end(), [](double v) { return std::isfinite(v); }) ||
        !std::isfinite(options_.water_level))
        throw std::invalid_argument("height_field: heights and the water level must be finite");
    const auto [lo, hi] = std::minmax_element(heights_.begin(), heights_.end());
    low_ = std::max(*lo, options_.water_level);
    high_ = std::max(*hi, low_);
    cell_low_.resize(std::size_t(nx_ - 1) * (nz_ - 1));
    cell_high_.resize(cell_low_.size());
    for (unsigned j = 0; j + 1 < nz_; ++j)
        for (unsigned i = 0; i + 1 < nx_; ++i) {
            const double c[4] = {h(i, j), h(i + 1, j), h(i, j + 1), h(i + 1, j + 1)};
            const std::size_t k = std::size_t(j) * (nx_ - 1) + i;
            // Rounded outwards, so that the float box never cuts off a triangle.
            cell_low_[k] = std::nextafter(float(*std::min_element(c, c + 4)), -std::numeric_limits<float>::infinity());
            cell_high_[k] = std::nextafter(float(*std::max_element(c, c + 4)), std::numeric_limits<float>::infinity());
        }
    bounds_ = {Vec3<S>(S(0), S(low_), S(0)), Vec3<S>(S(1), S(high_), S(1))};
    const S pad = S(4) * std::numeric_limits<S>::epsilon() * std::max(S(1), bounds_.magnitude());
    bounds_.min -= pad, bounds_.max += pad;
    if (options_.smooth) compute_smooth_normals();
}

template <Scalar S> void HeightField<S>::compute_smooth_normals() {
    // POV-Ray's smooth_height_field: at each grid point the sum of the unit normals of the four
    // triangles (point, right, up), (point, up, left), (point, left, down), (point, down, right)
    // that exist, in its grid units (x, z in cells, y in 1/65536 of the height range).
    constexpr double units = 65536.0;
    const long xs = long(nx_) - 1, zs = long(nz_) - 1;
    const auto add = [&](long x0, long z0, long x1, long z1, long x2, long z2, glm::dvec3& n) {
        if (std::min({x0, z0, x1, z1, x2, z2}) < 0 || std::max({x0, x1, x2}) > xs || std::max({z0, z1, z2}) > zs) return;
        const glm::dvec3 v0(double(x0), h(x0, z0) * units, double(z0)), v1(double(x1), h(x1, z1) * units, double(z1)),
            v2(double(x2), h(x2, z2) * units, double(z2));
        glm::dvec3 nt = glm::normalize(glm::cross(v2 - v0, v1 - v0));
        if (nt.y < 0) nt = -nt;
        n += nt;
    };
    normals_.resize(heights_.size());
    for (long i = 0; i <= zs; ++i)
        for (long j = 0; j <= xs; ++j) {
            glm::dvec3 n(0.0);
            add(j, i, j + 1, i, j, i + 1, n);
            add(j, i, j, i + 1, j - 1, i, n);
            add(j, i, j - 1, i, j, i - 1, n);
            add(j, i, j, i - 1, j + 1, i, n);
            n = glm::normalize(n);
            // From grid units to the unit square (the inverse transpose of the scaling).
            normals_[std::size_t(i) * nx_ + std::size_t(j)] = glm::normalize(glm::dvec3(n.x * double(xs), n.y * units, n.z * double(zs)));
        }
}

template <Scalar S> glm::dvec3 HeightField<S>::smooth_normal(long i, long j, double fx, double fz) const noexcept {
    const auto n = [&](long x, long z) { return normals_[std::size_t(z) * nx_ + std::size_t(x)]; };
    const double u = 1 - fx, v = 1 - fz;
    return v * (u * n(i, j) + fx * n(i + 1, j)) + fz * (u * n(i, j + 1) + fx * n(i + 1, j + 1));
}

template <Scalar S> bool HeightField<S>::contains(const Vec3<S>& p) const noexcept {
    const double gx = double(p.x) * (nx_ - 1), gz = double(p.z) * (nz_ - 1), y = double(p.y);
    if (!(gx >= 0 && gx < nx_ - 1 && gz >= 0 && gz < nz_ - 1) || y >= high_) return false;
    const double water = options_.water_level;
    if (y < water) return true;
    const long i = std::clamp(long(gx), 0L, long(nx_) - 2), j = std::clamp(long(gz), 0L, long(nz_) - 2);
    const double fx = gx - double(i), fz = gz - double(j);
    const auto hw = [&](long a, long b) { return std::max(h(a, b), water); };
    if (fx + fz < 1.0) {  // below the plane through the cell's three corners
        const double y1 = hw(i, j);
        return y < y1 + (hw(i + 1, j) - y1) * fx + (hw(i, j + 1) - y1) * fz;
    }
    const double y4 = hw(i + 1, j + 1);
    return y < y4 + (hw(i, j + 1) - y4) * (1 - fx) + (hw(i + 1, j) - y4) * (1 - fz);
}

template <Scalar S>
bool HeightField<S>::hit_cell(long i, long j, const glm::dvec3& o, const glm::dvec3& d, double t_max, double& t,
                              glm::dvec3& normal) const noexcept {
    constexpr double edge = 1e-9;  // cells share their edges: a hit on one is not lost between them
    const double y1 = h(i, j), y2 = h(i + 1, j), y3 = h(i, j + 1), y4 = h(i + 1, j + 1);
    bool found = false;
    const auto tri = [&](const glm::dvec3& corner, const glm::dvec3& n, bool lower) {
        const double dn = glm::dot(n, d);
        if (dn == 0.0) return;  // along the triangle's plane: seen edge-on
        const double tt = glm::dot(n, corner - o) / dn;
        if (!(tt > 0.0 && tt < t_max && tt < t) || !(S(tt) > S(0))) return;
        const double s = o.x + tt * d.x - double(i), u = o.z + tt * d.z - double(j);
        const bool inside = lower ? s >= -edge && u >= -edge && s + u <= 1 + edge
                                  : s <= 1 + edge && u <= 1 + edge && s + u >= 1 - edge;
        if (!inside || o.y + tt * d.y < options_.water_level) return;
        t = tt, normal = n, found = true;
    };
    tri({double(i), y1, double(j)}, {y1 - y2, 1.0, y1 - y3}, true);
    tri({double(i + 1), y4, double(j + 1)}, {y3 - y4, 1.0, y2 - y4}, false);
    return found;
}

template <Scalar S> std::optional<Hit<S>> HeightField<S>::intersect(const Ray<S>& ray) const noexcept {
    const double sx = nx_ - 1, sz = nz_ - 1;
    // Grid space: x and z in cells; t is the ray's own parameter.
    const glm::dvec3 o(double(ray.origin.x) * sx, double(ray.origin.y), double(ray.origin.z) * sz);
    const glm::dvec3 d(double(ray.direction.x) * sx, double(ray.direction.y), double(ray.direction.z) * sz);
    const double t_max = std::isfinite(double(ray.t_max)) ? double(ray.t_max) : std::numeric_limits<double>::infinity();
    // The ray's span in the box of the grid.
    double t0 = 0.0, t1 = t_max;
    const double lo[3] = {0.0, low_, 0.0}, hi[3] = {sx, high_, sz};
    for (int a = 0; a < 3; ++a) {
        if (d[a] == 0.0) {
            if (o[a] < lo[a] || o[a] > hi[a]) return std::nullopt;
            continue;
        }
        double ta = (lo[a] - o[a]) / d[a], tb = (hi[a] - o[a]) / d[a];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta), t1 = std::min(t1, tb);
    }
    if (!(t0 <= t1)) return std::nullopt;
    // Amanatides-Woo over the cells the span crosses.
    const glm::dvec3 start = o + t0 * d;
    long i = std::clamp(long(std::floor(start.x)), 0L, long(nx_) - 2);
    long j = std::clamp(long(std::floor(start.z)), 0L, long(nz_) - 2);
    const long step_i = d.x > 0 ? 1 : -1, step_j = d.z > 0 ? 1 : -1;
    const double inf = std::numeric_limits<double>::infinity();
    const double delta_i = d.x != 0.0 ? std::abs(1.0 / d.x) : inf, delta_j = d.z != 0.0 ? std::abs(1.0 / d.z) : inf;
    double next_i = d.x != 0.0 ? (double(i + (d.x > 0 ? 1 : 0)) - o.x) / d.x : inf;
    double next_j = d.z != 0.0 ? (double(j + (d.z > 0 ? 1 : 0)) - o.z) / d.z : inf;
    double enter = t0, t = inf;
    glm::dvec3 normal(0.0);
    for (;;) {
        const double leave = std::min({next_i, next_j, t1});
        const std::size_t k = std::size_t(j) * (nx_ - 1) + std::size_t(i);
        const double ya = o.y + enter * d.y, yb = o.y + leave * d.y;
        const double slack = 1e-9 * std::max(1.0, std::abs(high_));
        if (std::min(ya, yb) <= double(cell_high_[k]) + slack && std::max(ya, yb) >= double(cell_low_[k]) - slack &&
            hit_cell(i, j, o, d, t_max, t, normal))
            break;
        if (leave >= t1) break;
        if (next_i < next_j) {
            i += step_i, enter = next_i, next_i += delta_i;
            if (i < 0 || i > long(nx_) - 2) break;
        } else {
            j += step_j, enter = next_j, next_j += delta_j;
            if (j < 0 || j > long(nz_) - 2) break;
        }
    }
    if (!std::isfinite(t)) return std::nullopt;
    const S ts = S(t);
    if (!(ts < ray.t_max)) return std::nullopt;
    const Vec3<S> p = ray.at(ts);
    glm::dvec3 n;
    if (options_.smooth) {
        const glm::dvec3 g = o + t * d;
        const long ci = std::clamp(long(std::floor(g.x)), 0L, long(nx_) - 2), cj = std::clamp(long(std::floor(g.z)), 0L, long(nz_) - 2);
        n = smooth_normal(ci, cj, std::clamp(g.x - double(ci), 0.0, 1.0), std::clamp(g.z - double(cj), 0.0, 1.0));
    } else {
        n = glm::dvec3(normal.x * sx, normal.y, normal.z * sz);  // the grid's normal in the unit square
    }
    return Hit<S>{ts, p, Vec3<S>(glm::normalize(n))};
}

}  // namespace photon
