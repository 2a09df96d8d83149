// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray 3.7's camera projections: image position (u, v) to a ray, as its
// TracePixel::CreateCameraRay (source/core/render/tracepixel.cpp) does it.

#include <cmath>
#include <optional>
#include <string_view>

#include "../geometry/ray.hpp"
#include "../math/vec.hpp"

namespace photon {

/// POV-Ray's camera types (mesh_camera and user_defined excepted).
enum class Projection {
    perspective,
    orthographic,
    fisheye,
    ultra_wide_angle,
    omnimax,
    panoramic,
    cylinder_1,  ///< vertical cylinder, rays from the location
    cylinder_2,  ///< horizontal cylinder, rays from the location
    cylinder_3,  ///< vertical cylinder, rays from a vertical line (orthographic along up)
    cylinder_4,  ///< horizontal cylinder, rays from a horizontal line (orthographic along right)
    spherical,
};

[[nodiscard]] constexpr std::string_view to_string(Projection p) noexcept {
    switch (p) {
        case Projection::perspective: return "perspective";
        case Projection::orthographic: return "orthographic";
        case Projection::fisheye: return "fisheye";
        case Projection::ultra_wide_angle: return "ultra_wide_angle";
        case Projection::omnimax: return "omnimax";
        case Projection::panoramic: return "panoramic";
        case Projection::cylinder_1: return "cylinder 1";
        case Projection::cylinder_2: return "cylinder 2";
        case Projection::cylinder_3: return "cylinder 3";
        case Projection::cylinder_4: return "cylinder 4";
        case Projection::spherical: return "spherical";
    }
    return "?";
}

/// The camera's vectors and angles as POV-Ray's parser leaves them (angle already applied to
/// `direction` for perspective and orthographic; fisheye, ultra_wide_angle and the cylinders
/// read `angle` here, spherical reads `angle` and `vertical_angle`).
template <Scalar S> struct CameraFrame {
    Vec3<S> location{}, direction{S(0), S(0), S(1)}, right{S(4) / S(3), S(0), S(0)}, up{S(0), S(1), S(0)};
    S angle = S(90);            ///< degrees; POV-Ray's default
    S vertical_angle = S(180);  ///< spherical only; POV-Ray's default (its horizontal one is 360)
};

namespace detail {

/// Rodrigues' rotation of v about unit axis k by `angle` radians, as POV-Ray's
/// Compute_Axis_Rotation_Transform followed by MTransPoint.
template <Scalar S> [[nodiscard]] Vec3<S> rotate_about(const Vec3<S>& v, const Vec3<S>& k, S angle) noexcept {
    const S c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(k, v) * s + k * (glm::dot(k, v) * (S(1) - c));
}

/// Azimuth of (x, y) in POV-Ray's fisheye and omnimax: asin-based, in (-pi/2, 3pi/2).
template <Scalar S> [[nodiscard]] S pov_azimuth(S x, S y, S rad) noexcept {
    if (rad == S(0)) return S(0);
    return x < S(0) ? pi<S> - std::asin(y / rad) : std::asin(y / rad);
}

}  // namespace detail

/// The ray POV-Ray traces through image position (u, v) in [0,1]^2 (u to the right, v down),
/// with an unnormalised direction as POV-Ray builds it before its final normalisation (focal
/// blur scales that one). Nothing where the projection has no ray (outside a fisheye's or
/// omnimax's circle, below omnimax's 45 degrees): POV-Ray traces nothing there.
template <Scalar S>
[[nodiscard]] std::optional<Ray<S>> project(Projection p, const CameraFrame<S>& f, S u, S v) noexcept {
    constexpr S degree = pi<S> / S(180);
    const S lr = glm::length(f.right), lu = glm::length(f.up);
    // The types POV-Ray normalises its three vectors for (SetupCamera's `normalise`).
    const Vec3<S> rn = f.right / lr, un = f.up / lu, dn = glm::normalize(f.direction);
    const S x0 = u - S(0.5), y0 = S(0.5) - v;  // POV-Ray's x0, y0 for most types
    switch (p) {
        case Projection::perspective:
            return Ray<S>{f.location, f.direction + x0 * f.right + y0 * f.up};
        case Projection::orthographic:
            return Ray<S>{f.location + x0 * f.right + y0 * f.up, f.direction};
        case Projection::fisheye: {
            // The circle fills the image's shorter side: x and y are scaled by |right|, |up|.
            const S x = S(2) * x0 * lr, y = S(2) * y0 * lu;
            const S rad = std::sqrt(x * x + y * y);
            if (rad > S(1)) return std::nullopt;
            const S phi = detail::pov_azimuth(x, y, rad), theta = rad * f.angle * degree / S(2);
            return Ray<S>{f.location, (std::cos(phi) * std::sin(theta)) * rn + (std::sin(phi) * std::sin(theta)) * un +
                                          std::cos(theta) * dn};
        }
        case Projection::omnimax: {
            const S aspect = lr / lu;
            S x = S(2) * x0, y = S(2) * y0;
            if (aspect > S(1)) {
                if (aspect > S(1.283458)) {
                    x *= aspect / S(1.283458);
                    y = (y - S(1)) / S(1.283458) + S(1);
                } else {
                    y = (y - S(1)) / aspect + S(1);
                }
            } else {
                y /= aspect;
            }
            const S rad = std::sqrt(x * x + y * y);
            if (rad > S(1)) return std::nullopt;
            const S phi = detail::pov_azimuth(x, y, rad);
            const S r3 = rad * rad * rad;
            const S theta = S(1.411269) * rad - S(0.09439) * r3 + S(0.25674) * r3 * rad * rad;
            const S cx = std::cos(phi), sx = std::sin(phi), cy = std::cos(theta), sy = std::sin(theta);
            if (sx * sy < std::tan(S(135) * degree) * cy) return std::nullopt;  // 45 degrees below the axis
            return Ray<S>{f.location, (cx * sy) * rn + (sx * sy) * un + cy * dn};
        }
        case Projection::panoramic: {
            const S azimuth = (S(1) - u) * pi<S>, elevation = pi<S> * y0;
            S ty;
            if (std::abs(pi<S> / S(2) - std::abs(elevation)) < S(1e-10))
                ty = elevation > S(0) ? S(2e10) : S(-2e10);  // POV-Ray's BOUND_HUGE
            else
                ty = std::tan(elevation);
            return Ray<S>{f.location, std::cos(azimuth) * f.right + ty * f.up + std::sin(azimuth) * f.direction};
        }
        case Projection::ultra_wide_angle: {
            const S x = x0 * f.angle * degree, y = y0 * f.angle * (lu / lr) * degree;
            return Ray<S>{f.location, std::sin(x) * rn + std::sin(y) * un + (std::cos(x) * std::cos(y)) * dn};
        }
        case Projection::cylinder_1: {
            const S x = x0 * f.angle * degree, y = y0 * lu;
            return Ray<S>{f.location, std::sin(x) * rn + y * un + std::cos(x) * dn};
        }
        case Projection::cylinder_2: {
            const S y = y0 * f.angle * degree, x = x0 * lr;
            return Ray<S>{f.location, x * rn + std::sin(y) * un + std::cos(y) * dn};
        }
        case Projection::cylinder_3: {
            const S x = x0 * f.angle * degree, y = y0 * lu;
            return Ray<S>{f.location + y * un, std::sin(x) * rn + std::cos(x) * dn};
        }
        case Projection::cylinder_4: {
            const S y = y0 * f.angle * degree, x = x0 * lr;
            return Ray<S>{f.location + x * rn, std::sin(y) * un + std::cos(y) * dn};
        }
        case Projection::spherical: {
            // Latitude about right, then longitude about up, on the unnormalised direction.
            const S latitude = y0 * f.vertical_angle * degree, longitude = x0 * f.angle * degree;
            const Vec3<S> tilted = detail::rotate_about(f.direction, rn, -latitude);
            return Ray<S>{f.location, detail::rotate_about(tilted, un, longitude)};
        }
    }
    return std::nullopt;
}

/// Whether every ray of projection `p` starts at the camera's location (all but orthographic
/// and cylinders 3 and 4, without focal blur).
[[nodiscard]] constexpr bool rays_share_origin(Projection p) noexcept {
    return p != Projection::orthographic && p != Projection::cylinder_3 && p != Projection::cylinder_4;
}

}  // namespace photon
