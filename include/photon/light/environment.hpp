// SPDX-License-Identifier: MIT
#pragma once
// The sky: light from infinitely far away, a radiance L(w) for every direction w (POV-Ray's
// `background` and `sky_sphere`). Camera, mirror and glass rays that leave the scene see it;
// it lights the scene as any light does: by shadow rays to infinity for direct light
// (integrator/environment_lighting.hpp) and by photons for the rest.
//
// Directions are drawn by importance from a table of the radiance over the sphere in the
// cylindrical equal-area map (y = 1 - 2v, phi = 2 pi u: every cell covers the same solid
// angle, 4 pi / cells, so the density per steradian is the cell's probability times
// cells / 4 pi and nothing is singular at the poles). A tenth of the density is uniform, so
// every direction has one: a bright spot between the table's sample points still gets its
// photons and shadow rays, and every estimate stays unbiased (each sample is weighted by
// L / pdf of its own direction). A constant sky is sampled uniformly.
//
// Photons enter through the disc of a ball around the scene's objects (EnvironmentPhoton):
// every ray from the sky that can hit an object crosses such a disc facing its direction.

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "../geometry/bounding_ball.hpp"
#include "../geometry/ray.hpp"
#include "../math/frame.hpp"
#include "../math/sampling.hpp"
#include "../texture/reflectance_field.hpp"

namespace photon {

/// A direction drawn from the sky, with what arrives along it.
template <Scalar S> struct EnvironmentSample {
    Vec3<S> direction;  ///< unit, towards the sky
    Rgb<S> radiance;    ///< arriving along -direction
    S pdf;              ///< per steradian
};

/// A photon from the sky: its first ray and the power it carries, for one photon emitted (divide
/// by the number emitted).
template <Scalar S> struct EnvironmentPhoton {
    Ray<S> ray;
    Rgb<S> power;
};

template <Scalar S> class Environment {
public:
    /// The same radiance from every direction (POV-Ray's background). Throws
    /// std::invalid_argument unless every channel is finite and >= 0.
    explicit Environment(const Rgb<S>& radiance);
    /// Radiance field(w) towards unit direction w: the field evaluated at the point w of the unit
    /// sphere, as POV-Ray evaluates a sky_sphere's pigments (their transformation is the field's
    /// own). `rows` sets the sampling table: rows x 2 rows cells. Throws std::invalid_argument
    /// on an empty field, rows == 0, or a table value that is negative or not finite.
    explicit Environment(AnyReflectanceField<S> field, unsigned rows = 64);

    /// Radiance arriving from unit direction `direction` (towards the sky).
    [[nodiscard]] Rgb<S> radiance(const Vec3<S>& direction) const {
        return field_ ? field_(direction) : constant_;
    }
    [[nodiscard]] bool is_constant() const noexcept { return !field_; }
    /// Whether no direction brings any light (nothing to sample or emit).
    [[nodiscard]] bool is_black() const noexcept { return photon::is_black(bound_); }
    /// Per channel, no direction brings more.
    [[nodiscard]] const Rgb<S>& upper_bound() const noexcept { return bound_; }
    /// Integral of the radiance over the sphere, per channel (W m^-2 per unit area facing it):
    /// exact for a constant sky, from the table's sample points for a field.
    [[nodiscard]] const Rgb<S>& integral() const noexcept { return integral_; }

    /// A direction drawn with density pdf(), from u uniform in [0,1)^2.
    [[nodiscard]] EnvironmentSample<S> sample(Vec2<S> u) const;
    /// Density per steradian of sample()'s directions at unit `direction`.
    [[nodiscard]] S pdf(const Vec3<S>& direction) const noexcept;

    /// A photon entering `ball` from the sky (u_direction, u_disc uniform in [0,1)^2): a sky
    /// direction w drawn by sample(), the origin uniform over the disc of the ball's radius that
    /// faces w, pushed out to the ball's surface along w, travelling along -w; its power
    /// L(w) pi r^2 / pdf(w), so that the mean power is the sky's flux through that disc,
    /// pi r^2 integral().
    [[nodiscard]] EnvironmentPhoton<S> sample_photon(const Ball<S>& ball, Vec2<S> u_direction, Vec2<S> u_disc) const;
    /// The sky's power entering `ball`: pi r^2 integral(), channel-averaged (what photons are
    /// shared by).
    [[nodiscard]] S power_into(const Ball<S>& ball) const noexcept {
        return pi<S> * ball.radius * ball.radius * average(integral_);
    }

    /// Shadow rays towards the sky per shading point (rounded up to n x n strata): a sky seen
    /// through a window needs many, since only the window's share of them can arrive.
    unsigned shadow_samples = 64;

private:
    [[nodiscard]] static Vec3<S> direction_at(S u, S v) noexcept {
        const S y = std::clamp(S(1) - S(2) * v, S(-1), S(1));
        const S s = std::sqrt(std::max(S(0), S(1) - y * y));
        const S phi = S(2) * pi<S> * u;
        return {s * std::cos(phi), y, s * std::sin(phi)};
    }
    void build_table(unsigned rows);

    Rgb<S> constant_{S(0)};
    AnyReflectanceField<S> field_;
    Rgb<S> bound_{S(0)}, integral_{S(0)};
    unsigned rows_ = 0, cols_ = 0;
    std::vector<double> row_cdf_;   ///< rows_ + 1 values, from 0 to 1
    std::vector<double> cell_cdf_;  ///< per row, cols_ + 1 values from 0 to 1
    std::vector<double> cell_p_;    ///< probability of each cell (uniform share included)
};

/// The share of the sampling density that is uniform over the sphere.
inline constexpr double environment_uniform_share = 0.1;

template <Scalar S> Environment<S>::Environment(const Rgb<S>& radiance) : constant_(radiance) {
    if (!photon::is_finite(radiance) || min_component(radiance) < S(0))
        throw std::invalid_argument("environment: the radiance must be finite and >= 0 in every channel");
    bound_ = radiance;
    integral_ = radiance * (S(4) * pi<S>);
}

template <Scalar S>
Environment<S>::Environment(AnyReflectanceField<S> field, unsigned rows) : field_(std::move(field)) {
    if (!field_) throw std::invalid_argument("environment: the radiance field is empty");
    if (rows == 0) throw std::invalid_argument("environment: the sampling table needs at least one row");
    bound_ = field_.upper_bound();
    build_table(rows);
}

template <Scalar S> void Environment<S>::build_table(unsigned rows) {
    rows_ = rows;
    cols_ = 2 * rows;
    const std::size_t cells = std::size_t(rows_) * cols_;
    // Each cell's mean over a 2 x 2 grid of points: a thin bright band between cell centres
    // still shows in the table.
    std::vector<double> value(cells);
    Rgb<double> sum(0.0);
    for (unsigned i = 0; i < rows_; ++i)
        for (unsigned j = 0; j < cols_; ++j) {
            Rgb<double> cell(0.0);
            for (int a = 0; a < 2; ++a)
                for (int b = 0; b < 2; ++b)
                    cell += Rgb<double>(field_(direction_at(S((j + 0.25 + 0.5 * b) / cols_), S((i + 0.25 + 0.5 * a) / rows_))));
            cell *= 0.25;
            if (!photon::is_finite(cell) || min_component(cell) < 0.0)
                throw std::invalid_argument("environment: the radiance must be finite and >= 0 in every direction");
            value[std::size_t(i) * cols_ + j] = average(cell);
            sum += cell;
        }
    integral_ = Rgb<S>(sum * (4.0 * pi<double> / double(cells)));
    double total = 0;
    for (double v : value) total += v;
    cell_p_.resize(cells);
    for (std::size_t c = 0; c < cells; ++c)
        cell_p_[c] = total > 0 ? (1.0 - environment_uniform_share) * value[c] / total + environment_uniform_share / double(cells)
                               : 1.0 / double(cells);
    row_cdf_.assign(rows_ + 1, 0.0);
    cell_cdf_.assign(std::size_t(rows_) * (cols_ + 1), 0.0);
    for (unsigned i = 0; i < rows_; ++i) {
        double row = 0;
        for (unsigned j = 0; j < cols_; ++j) row += cell_p_[std::size_t(i) * cols_ + j];
        row_cdf_[i + 1] = row_cdf_[i] + row;
        double* cdf = &cell_cdf_[std::size_t(i) * (cols_ + 1)];
        for (unsigned j = 0; j < cols_; ++j) cdf[j + 1] = cdf[j] + cell_p_[std::size_t(i) * cols_ + j] / row;
        cdf[cols_] = 1.0;
    }
    row_cdf_[rows_] = 1.0;
}

template <Scalar S> EnvironmentSample<S> Environment<S>::sample(Vec2<S> u) const {
    if (!field_) {
        const Vec3<S> d = uniform_sphere(u);
        return {d, constant_, S(1) / (S(4) * pi<S>)};
    }
    // Inverse CDFs: the row by the marginal, the column within it, the point within the cell.
    const auto pick = [](const double* cdf, unsigned n, double x, double& fraction) {
        const unsigned k = unsigned(std::upper_bound(cdf + 1, cdf + n, x) - (cdf + 1));
        const double width = cdf[k + 1] - cdf[k];
        fraction = width > 0 ? std::clamp((x - cdf[k]) / width, 0.0, 1.0) : 0.5;
        return std::min(k, n - 1);
    };
    double fy = 0, fx = 0;
    const unsigned i = pick(row_cdf_.data(), rows_, double(u.y), fy);
    const unsigned j = pick(&cell_cdf_[std::size_t(i) * (cols_ + 1)], cols_, double(u.x), fx);
    const Vec3<S> d = direction_at(S((j + fx) / cols_), S((i + fy) / rows_));
    const double p = cell_p_[std::size_t(i) * cols_ + j] * double(rows_) * double(cols_) / (4.0 * pi<double>);
    return {d, field_(d), S(p)};
}

template <Scalar S> S Environment<S>::pdf(const Vec3<S>& direction) const noexcept {
    if (!field_) return S(1) / (S(4) * pi<S>);
    const double y = std::clamp(double(direction.y), -1.0, 1.0);
    double phi = std::atan2(double(direction.z), double(direction.x));
    if (phi < 0) phi += 2.0 * pi<double>;
    const unsigned i = std::min(rows_ - 1, unsigned((1.0 - y) * 0.5 * rows_));
    const unsigned j = std::min(cols_ - 1, unsigned(phi / (2.0 * pi<double>) * cols_));
    return S(cell_p_[std::size_t(i) * cols_ + j] * double(rows_) * double(cols_) / (4.0 * pi<double>));
}

template <Scalar S>
EnvironmentPhoton<S> Environment<S>::sample_photon(const Ball<S>& ball, Vec2<S> u_direction, Vec2<S> u_disc) const {
    const EnvironmentSample<S> s = sample(u_direction);
    const Vec2<S> disc = concentric_disc(u_disc);
    const Frame<S> frame = Frame<S>::from_normal(s.direction);
    const Vec3<S> origin = ball.center + ball.radius * frame.to_world({disc.x, disc.y, S(1)});
    const S area = pi<S> * ball.radius * ball.radius;
    return {Ray<S>{origin, -s.direction}, s.pdf > S(0) ? s.radiance * (area / s.pdf) : Rgb<S>(S(0))};
}

}  // namespace photon
