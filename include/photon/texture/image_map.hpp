// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray 3.7's image_map: an image (a PixelGrid) wrapped around space by one of its mappings,
// read with or without interpolation, as source/core/support/imageutil.cpp (map_pos,
// image_colour_at, Interp) and ColourImagePattern::Evaluate do it. In the image's own space:
//   map_type 0, planar:      the unit square of the x-y plane, x to the right, y up, repeated
//                            (the image's top row at y = 1), along z for ever;
//   map_type 1, spherical:   longitude from +x towards +z over the width, latitude from the
//                            south pole (y = -1) to the north over the height;
//   map_type 2, cylindrical: longitude as above over the width, y from 0 to 1 over the height;
//   map_type 5, torus:       longitude around y over the width, the angle around the tube of
//                            major radius 1 over the height.
// `once` shows the image a single time: elsewhere the colour is white with transmit 1 (clear).
// A pixel's alpha a reads as transmit 1 - a; POV-Ray 3.7's `filter all F` and `transmit all T`
// add F and T to every pixel before interpolation.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

#include "../math/transform.hpp"
#include "../math/vec.hpp"
#include "layer_color.hpp"
#include "pixel_grid.hpp"

namespace photon {

/// POV-Ray's `map_type` numbers.
enum class ImageMapType : std::uint8_t { planar = 0, spherical = 1, cylindrical = 2, torus = 5 };
/// POV-Ray's `interpolate` numbers: none, bilinear, normalized distance.
enum class ImageInterpolation : std::uint8_t { none = 0, bilinear = 2, normalized_distance = 4 };

struct ImageMapOptions {
    ImageMapType map_type = ImageMapType::planar;
    ImageInterpolation interpolate = ImageInterpolation::none;
    bool once = false;
    /// POV-Ray 3.7's `filter all` and `transmit all`, added to every pixel's (its alpha's transmit).
    double filter_all = 0, transmit_all = 0;
};

/// Where a point falls on the image: pixel coordinates, x from the left and y from the top, each
/// in [0, width) and [0, height).
struct ImageTexel {
    double x = 0, y = 0;
};

template <Scalar S> class ImageMap {
public:
    /// `placement` maps the image's own space to the world (the pigment's transformations, then
    /// its object's); it must be invertible. Throws std::invalid_argument on a null or empty image,
    /// or filter_all, transmit_all outside [0, 1].
    ImageMap(std::shared_ptr<const PixelGrid> image, ImageMapOptions options = {}, const Affine<double>& placement = {})
        : image_(std::move(image)), options_(options), to_image_(placement.inverse()) {
        if (!image_ || image_->width() == 0 || image_->height() == 0)
            throw std::invalid_argument("image_map: the image has no pixels");
        if (!(options_.filter_all >= 0 && options_.filter_all <= 1 && options_.transmit_all >= 0 && options_.transmit_all <= 1))
            throw std::invalid_argument("image_map: `filter all` and `transmit all` must lie in [0, 1]");
        for (const PixelGrid::Pixel& p : image_->pixels())
            for (int c = 0; c < 3; ++c) bound_[c] = std::max(bound_[c], S(std::max(0.0f, p[std::size_t(c)])));
        if (options_.once) bound_ = glm::max(bound_, Rgb<S>(S(1)));  // the clear white outside
    }

    /// The colour, filter and transmit at world point `p`.
    [[nodiscard]] LayerColor<S> layer(const Vec3<S>& p) const noexcept {
        const std::optional<ImageTexel> t = texel(to_image_.point(Vec3<double>(p)));
        if (!t) return {Rgb<S>(S(1)), S(0), S(1)};
        return sample(t->x, t->y);
    }
    /// The colour at world point `p` (a ReflectanceField: reflectance_field.hpp).
    [[nodiscard]] Rgb<S> operator()(const Vec3<S>& p) const noexcept { return layer(p).color; }
    /// Per channel, no point is brighter than this (the brightest pixel; white with `once`).
    [[nodiscard]] Rgb<S> upper_bound() const noexcept { return bound_; }

    /// Where the image-space point `q` falls on the image (POV-Ray's map_pos), or none where the
    /// mapping leaves it uncoloured (outside the image with `once`, on an axis the mapping cannot place).
    [[nodiscard]] std::optional<ImageTexel> texel(const Vec3<double>& q) const noexcept;
    /// The colour at pixel coordinates (x, y) as the interpolation reads it (POV-Ray's image_colour_at).
    [[nodiscard]] LayerColor<S> sample(double x, double y) const noexcept;

    [[nodiscard]] const PixelGrid& image() const noexcept { return *image_; }
    [[nodiscard]] const ImageMapOptions& options() const noexcept { return options_; }

private:
    /// The pixel at integer coordinates, wrapped around the image (clamped to its edge with `once`),
    /// with its transmit from alpha and the `all` values added.
    [[nodiscard]] LayerColor<S> pixel(long x, long y) const noexcept;

    std::shared_ptr<const PixelGrid> image_;
    ImageMapOptions options_;
    Affine<double> to_image_;  ///< world -> image space
    Rgb<S> bound_{S(0)};
};

namespace image_map_detail {

inline constexpr double half_turn = 3.14159265358979323846;  // pi

/// POV-Ray's wrap(): v into [0, period).
inline double wrap(double v, double period) noexcept {
    v = std::fmod(v, period);
    if (v < 0) v += period;
    return v >= period ? 0.0 : v;
}

/// The angle of (x, z) from +x towards +z, in [0, 1) of a turn (POV-Ray's acos form).
inline double longitude(double x, double z, double length) noexcept {
    double theta;
    if (z == 0.0) theta = x > 0 ? 0.0 : half_turn;
    else {
        theta = std::acos(std::clamp(x / length, -1.0, 1.0));
        if (z < 0.0) theta = 2 * half_turn - theta;
    }
    return theta / (2 * half_turn);
}

}  // namespace image_map_detail

template <Scalar S> std::optional<ImageTexel> ImageMap<S>::texel(const Vec3<double>& q) const noexcept {
    using image_map_detail::half_turn, image_map_detail::longitude, image_map_detail::wrap;
    constexpr double pi = half_turn;
    const double w = image_->width(), h = image_->height();
    double u = 0, v = 0;
    switch (options_.map_type) {
    case ImageMapType::planar:  // POV-Ray's gradient <1, -1, 0>: x across, y up
        if (options_.once && (q.x < 0.0 || q.x > 1.0 || q.y < 0.0 || q.y > 1.0)) return std::nullopt;
        u = std::fmod(q.x * w, w);
        v = std::fmod(q.y * h, h);
        break;
    case ImageMapType::spherical: {
        const double len = glm::length(q);
        if (len == 0.0) return std::nullopt;
        const Vec3<double> n = q / len;
        const double phi = 0.5 + std::asin(std::clamp(n.y, -1.0, 1.0)) / pi;
        const double around = std::sqrt(n.x * n.x + n.z * n.z);
        u = (around == 0.0 ? 0.0 : longitude(n.x, n.z, around)) * w;
        v = phi * h;
        break;
    }
    case ImageMapType::cylindrical: {
        if (options_.once && (q.y < 0.0 || q.y > 1.0)) return std::nullopt;
        v = std::fmod(q.y * h, h);
        const double around = std::sqrt(q.x * q.x + q.z * q.z);
        if (around == 0.0) return std::nullopt;
        u = longitude(q.x, q.z, around) * w;
        break;
    }
    case ImageMapType::torus: {
        const double around = std::sqrt(q.x * q.x + q.z * q.z);
        if (around == 0.0) return std::nullopt;
        const double theta = -longitude(q.x, q.z, around);
        const double x = around - 1.0;  // major radius 1
        const double tube = std::sqrt(x * x + q.y * q.y);
        double phi = tube == 0.0 ? 0.0 : std::acos(std::clamp(-x / tube, -1.0, 1.0));
        if (q.y > 0.0) phi = 2 * pi - phi;
        u = -theta * w;
        v = phi / (2 * pi) * h;
        break;
    }
    }
    constexpr double epsilon = 1.0e-10;  // POV-Ray's, against a texel edge on a round value
    u += epsilon, v += epsilon;
    if (options_.once && (u >= w || v >= h || u < 0.0 || v < 0.0)) return std::nullopt;
    return ImageTexel{wrap(u, w), wrap(-v, h)};  // rows count from the top
}

template <Scalar S> LayerColor<S> ImageMap<S>::pixel(long x, long y) const noexcept {
    const long w = long(image_->width()), h = long(image_->height());
    if (options_.once) {
        x = std::clamp(x, 0L, w - 1), y = std::clamp(y, 0L, h - 1);
    } else {
        x = ((x % w) + w) % w, y = ((y % h) + h) % h;
    }
    const PixelGrid::Pixel& p = image_->at(unsigned(x), unsigned(y));
    LayerColor<S> c{Rgb<S>(S(p[0]), S(p[1]), S(p[2])), S(options_.filter_all), S(1 - p[3] + options_.transmit_all)};
    // POV-Ray lets filter + transmit pass 1 here; photon keeps a colour's opacity >= 0.
    c.transmit = std::clamp(c.transmit, S(0), S(1) - c.filter);
    return c;
}

template <Scalar S> LayerColor<S> ImageMap<S>::sample(double x, double y) const noexcept {
    if (options_.interpolate == ImageInterpolation::none) return pixel(long(std::floor(x)), long(std::floor(y)));
    // POV-Ray's Interp: the four pixels whose centres surround (x, y).
    x += 0.5, y += 0.5;
    const long ix = long(x), iy = long(y);
    const double p = x - double(ix), q = y - double(iy);
    double f[4];
    if (options_.interpolate == ImageInterpolation::bilinear) {
        f[0] = p * q, f[1] = (1 - p) * q, f[2] = p * (1 - q), f[3] = (1 - p) * (1 - q);
    } else {  // normalized distance: weights 1 / d^2 to each corner, as POV-Ray pairs them
        const auto sq = [](double a, double b) { return a * a + b * b; };
        double wts[4] = {1 / sq(1 - p, 1 - q), 1 / sq(p, 1 - q), 1 / sq(1 - p, q), 1 / sq(p, q)};
        double sum = 0;
        for (double wt : wts) sum += wt;
        for (int i = 0; i < 4; ++i) f[i] = std::isfinite(wts[i]) && std::isfinite(sum) ? wts[i] / sum : 0.0;
        if (!std::isfinite(sum))  // exactly on a pixel centre: that pixel
            for (int i = 0; i < 4; ++i) f[i] = std::isinf(wts[i]) ? 1.0 : 0.0;
    }
    const LayerColor<S> corner[4] = {pixel(ix, iy), pixel(ix - 1, iy), pixel(ix, iy - 1), pixel(ix - 1, iy - 1)};
    Vec3<double> color(0.0);
    double filter = 0, transmit = 0;
    for (int i = 0; i < 4; ++i) {
        color += Vec3<double>(corner[i].color) * f[i];
        filter += double(corner[i].filter) * f[i];
        transmit += double(corner[i].transmit) * f[i];
    }
    return {Rgb<S>(color), S(filter), S(transmit)};
}

}  // namespace photon
