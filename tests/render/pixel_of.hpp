// SPDX-License-Identifier: MIT
#pragma once
// Which pixel sees a point: the inverse of PinholeCamera::ray, for the render tests that sum an
// analytic flux over the pixels of a floor (sppm_test.cpp, csg_render_test.cpp).

#include <photon/scene/camera.hpp>

#include <cstddef>
#include <optional>

namespace photon::testing {

/// The pixel of a width x height image that sees point p, if any (the camera's basis is orthogonal).
[[nodiscard]] inline std::optional<std::size_t> pixel_of(const PinholeCamera<double>& camera, const Vec3<double>& p,
                                                         unsigned width, unsigned height) {
    const Vec3<double> d = p - camera.location();
    const double c = glm::dot(d, camera.direction()) / glm::dot(camera.direction(), camera.direction());
    const double u = glm::dot(d, camera.right()) / glm::dot(camera.right(), camera.right()) / c + 0.5;
    const double v = 0.5 - glm::dot(d, camera.up()) / glm::dot(camera.up(), camera.up()) / c;
    if (!(c > 0) || !(u >= 0 && u < 1 && v >= 0 && v < 1)) return std::nullopt;
    return std::size_t(v * height) * width + std::size_t(u * width);
}

}  // namespace photon::testing
