// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray 3.7's `normal { bump_map { ... } }`: an image's brightness as heights that tilt the
// shading normal (source/core/support/imageutil.cpp, bump_map). At the pixel the point maps to
// (by the image map's mapping, image_map.hpp) and at the pixels one to the left and one to the
// right of the row below it, the heights bump_size * grey (or the palette index with
// `use_index`) make a small triangle; its normal, in a frame built from the surface normal,
// is the tilted normal. A NormalField (normal_field.hpp).

#include <cmath>
#include <memory>
#include <stdexcept>
#include <utility>

#include "../math/transform.hpp"
#include "image_map.hpp"
#include "pixel_grid.hpp"

namespace photon {

template <Scalar S> class ImageBumpMap {
public:
    /// `mapping`'s map_type, interpolate and once as image_map's (its filter and transmit unused);
    /// `placement` maps the image's space to the world; it must be invertible. `use_index`
    /// reads a palette image's indices as the heights (POV-Ray's `use_index`; other images use
    /// their grey). Throws std::invalid_argument on a null image or a bump size that is not finite.
    ImageBumpMap(std::shared_ptr<const PixelGrid> image, ImageMapOptions mapping, double bump_size,
                 bool use_index = false, const Affine<double>& placement = {})
        : heights_(heights_image(std::move(image), use_index), without_clearness(mapping)), amount_(bump_size),
          to_pattern_(placement.inverse()) {
        if (!std::isfinite(amount_)) throw std::invalid_argument("bump_map: the bump size must be finite");
        to_pattern_normal_ = glm::transpose(glm::inverse(to_pattern_.linear));
        to_world_normal_ = glm::transpose(to_pattern_.linear);
    }

    /// The tilted unit normal at world point p whose unit geometric normal is n; n itself where
    /// the image does not reach (outside a `once` image).
    [[nodiscard]] Vec3<S> operator()(const Vec3<S>& p, const Vec3<S>& n) const noexcept {
        const std::optional<ImageTexel> at = heights_.texel(to_pattern_.point(Vec3<double>(p)));
        if (!at) return n;
        const double w = heights_.image().width(), h = heights_.image().height();
        const auto height = [&](double x, double y) {
            const Rgb<double> c = heights_.sample(x, y).color;
            return amount_ * (0.297 * c.x + 0.589 * c.y + 0.114 * c.z);  // POV-Ray 3.7's grey
        };
        const auto wrap = [](double v, double period) { return v < 0.0 ? v + period : v >= period ? v - period : v; };
        double x = at->x, y = at->y;
        const double h1 = height(x, y);
        x = wrap(x - 1.0, w), y = wrap(y + 1.0, h);
        const double h2 = height(x, y);
        x = wrap(x + 2.0, w);
        const double h3 = height(x, y);
        // The triangle (0, h1, 0), (-1, h2, 1), (1, h3, 1) and its normal.
        const Vec3<double> p1(0, h1, 0), p2(-1, h2, 1), p3(1, h3, 1);
        const Vec3<double> bump = glm::normalize(glm::cross(p3 - p2, p1 - p2));
        // POV-Ray's frame: y along the surface normal, x across it and the world's y.
        const Vec3<double> ny = glm::normalize(to_pattern_normal_ * Vec3<double>(n));
        Vec3<double> yp = ny, xp = glm::cross(yp, Vec3<double>(0, 1, 0));
        double length = glm::length(xp);
        if (length < 1e-10) {
            yp = Vec3<double>(0, std::fabs(ny.y - 1.0) < 1e-10 ? 1.0 : -1.0, 0);
            xp = Vec3<double>(1, 0, 0);
            length = 1.0;
        }
        xp /= length;
        const Vec3<double> zp = glm::normalize(glm::cross(xp, yp));
        const Vec3<double> tilted = xp * bump.x + yp * bump.y - zp * bump.z;
        const Vec3<double> world = to_world_normal_ * tilted;
        const double l = glm::length(world);
        if (!(l > 0.0) || !std::isfinite(l)) return n;
        return Vec3<S>(world / l);
    }

    [[nodiscard]] double bump_size() const noexcept { return amount_; }

private:
    static std::shared_ptr<const PixelGrid> heights_image(std::shared_ptr<const PixelGrid> image, bool use_index) {
        if (!image) throw std::invalid_argument("bump_map: the image is missing");
        if (!use_index || image->indices.empty()) return image;
        // The indices as grey levels: the grey of (i, i, i) is i (POV-Ray's weights sum to 1).
        std::vector<PixelGrid::Pixel> px(image->pixels().size());
        for (std::size_t k = 0; k < px.size(); ++k) {
            const float i = float(image->indices[k]);
            px[k] = {i, i, i, 1.0f};
        }
        return std::make_shared<const PixelGrid>(image->width(), image->height(), std::move(px));
    }
    static ImageMapOptions without_clearness(ImageMapOptions m) {
        m.filter_all = m.transmit_all = 0;
        return m;
    }

    ImageMap<double> heights_;  ///< in the image's own space
    double amount_;
    Affine<double> to_pattern_;  ///< world -> image space
    glm::dmat3 to_pattern_normal_{1.0}, to_world_normal_{1.0};
};

}  // namespace photon
