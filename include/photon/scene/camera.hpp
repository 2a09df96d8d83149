// SPDX-License-Identifier: MIT
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "../geometry/ray.hpp"
#include "../math/rng.hpp"
#include "../math/sampling.hpp"
#include "projection.hpp"

namespace photon {

/// POV-Ray's focal blur: a thin lens whose rays through one image position meet at
/// `focal_distance` along it. POV-Ray's lens samples span a disc of radius aperture / 4 (its
/// sample grid covers +-0.5 times half the aperture), and so does photon's.
template <Scalar S> struct FocalBlur {
    S aperture = S(0);        ///< 0: a pinhole
    S focal_distance = S(1);  ///< distance from the location to the sharp points, in units of |direction| scaled rays
};

/// Angles of one pixel's rays: a surface at distance d along a ray sees a pixel about
/// `size + angle * d` wide (the larger side; an estimate for radii, not a bound).
template <Scalar S> struct PixelSpread {
    S angle = S(0);  ///< radians
    S size = S(0);   ///< scene units (orthographic and the cylinders 3 and 4)
};

/// POV-Ray 3.7's camera: any of its projections (projection.hpp) with its conventions: a
/// perspective ray through image position (u, v) in [0,1]^2 (u to the right, v down) has
/// direction `direction + (u - 0.5) right + (0.5 - v) up`. With right = cross(up, direction),
/// +x appears on the right for a camera looking along +z with up +y (POV-Ray's left-handed
/// view: red wall on the left in the Cornell box). Optionally with focal blur.
template <Scalar S> class Camera {
public:
    /// A perspective camera from raw POV-Ray vectors. Throws std::invalid_argument if they
    /// are degenerate.
    Camera(const Vec3<S>& location, const Vec3<S>& direction, const Vec3<S>& right, const Vec3<S>& up)
        : Camera(Projection::perspective, CameraFrame<S>{location, direction, right, up}) {}

    /// Any projection. `blur.aperture` 0 is a pinhole. Throws std::invalid_argument for
    /// degenerate vectors, a negative or non-finite angle, aperture or focal distance.
    Camera(Projection projection, const CameraFrame<S>& frame, const FocalBlur<S>& blur = {})
        : projection_(projection), frame_(frame), blur_(blur) {
        const CameraFrame<S>& f = frame_;
        if (!is_finite(f.location) || !is_finite(f.direction) || !is_finite(f.right) || !is_finite(f.up) ||
            !(glm::length(glm::cross(f.right, f.up)) > S(0)) || !(glm::length(f.direction) > S(0)))
            throw std::invalid_argument("camera: direction, right and up must be finite, non-zero and not parallel");
        if (!(f.angle >= S(0)) || !std::isfinite(f.angle) || !(f.vertical_angle >= S(0)) || !std::isfinite(f.vertical_angle))
            throw std::invalid_argument("camera: angles must be finite and not negative");
        if (!(blur.aperture >= S(0)) || !std::isfinite(blur.aperture) || !(blur.focal_distance > S(0)) ||
            !std::isfinite(blur.focal_distance))
            throw std::invalid_argument("camera: aperture must be >= 0 and focal distance > 0");
        if (has_focal_blur()) {  // POV-Ray's FocalBlurData: the lens's axes
            lens_x_ = glm::normalize(glm::cross(f.up, f.direction));
            lens_y_ = glm::normalize(glm::cross(f.direction, lens_x_));
        }
    }

    /// A perspective camera looking from `location` at `target`, `sky` giving up.
    /// `horizontal_fov_degrees` in (0, 180), `aspect` = image width / height.
    [[nodiscard]] static Camera look_at(const Vec3<S>& location, const Vec3<S>& target, const Vec3<S>& sky,
                                        S horizontal_fov_degrees, S aspect) {
        if (!(horizontal_fov_degrees > S(0) && horizontal_fov_degrees < S(180)))
            throw std::invalid_argument("camera: field of view must be in (0, 180) degrees");
        if (!(aspect > S(0)) || !std::isfinite(aspect)) throw std::invalid_argument("camera: aspect must be positive");
        const Vec3<S> forward = target - location;
        if (!(glm::length(forward) > S(0))) throw std::invalid_argument("camera: look_at equals location");
        const Vec3<S> f = glm::normalize(forward);
        const Vec3<S> side = glm::cross(sky, f);
        if (!(glm::length(side) > S(0))) throw std::invalid_argument("camera: sky is parallel to the view direction");
        const Vec3<S> right = glm::normalize(side) * aspect;
        const Vec3<S> up = glm::normalize(glm::cross(f, right));
        const S focal = S(0.5) * aspect / std::tan(horizontal_fov_degrees * pi<S> / S(360));
        return Camera(location, f * focal, right, up);
    }

    /// The primary ray (unit direction) through image position (u, v), through lens position
    /// `lens` in [0,1]^2 when the camera has focal blur ((0.5, 0.5) is the lens's centre).
    /// Nothing where the projection has none (outside a fisheye's circle, say): renders count
    /// such a sample black, as POV-Ray shows it without alpha.
    [[nodiscard]] std::optional<Ray<S>> ray(S u, S v, const Vec2<S>& lens = Vec2<S>(S(0.5))) const noexcept {
        std::optional<Ray<S>> r = project(projection_, frame_, u, v);
        if (!r) return r;
        if (has_focal_blur()) {  // POV-Ray's JitterCameraRay
            const Vec2<S> disc = S(0.5) * concentric_disc(lens);
            const S half = S(0.5) * blur_.aperture;
            const Vec3<S> deflection = lens_x_ * (half * disc.x) - lens_y_ * (half * disc.y);
            r->origin += deflection;
            r->direction = r->direction * (blur_.focal_distance / glm::length(frame_.direction)) - deflection;
        }
        r->direction = glm::normalize(r->direction);
        return r;
    }

    /// The point every primary ray starts from, if there is one (not for orthographic, the
    /// cylinders 3 and 4, or with focal blur).
    [[nodiscard]] std::optional<Vec3<S>> eye() const noexcept {
        if (!rays_share_origin(projection_) || has_focal_blur()) return std::nullopt;
        return frame_.location;
    }

    /// One pixel's spread in an image of `width` x `height` pixels, at the image centre for
    /// the projections whose pixels differ across the image.
    [[nodiscard]] PixelSpread<S> pixel_spread(unsigned width, unsigned height) const noexcept {
        const S w = S(width), h = S(height);
        const S lr = glm::length(frame_.right), lu = glm::length(frame_.up), ld = glm::length(frame_.direction);
        const S degree = pi<S> / S(180), a = frame_.angle * degree;
        switch (projection_) {
            case Projection::perspective: return {std::max(lr / w, lu / h) / ld, S(0)};
            case Projection::orthographic: return {S(0), std::max(lr / w, lu / h)};
            case Projection::fisheye: return {a * std::max(lr / w, lu / h), S(0)};
            case Projection::omnimax: return {S(2.8) * std::max(S(1) / w, S(1) / h), S(0)};  // d theta / d rad = 1.41 at the centre
            case Projection::panoramic: return {pi<S> * std::max(S(1) / w, S(1) / h), S(0)};
            case Projection::ultra_wide_angle: return {a * std::max(S(1) / w, (lu / lr) / h), S(0)};
            case Projection::cylinder_1: return {std::max(a / w, lu / h), S(0)};
            case Projection::cylinder_2: return {std::max(lr / w, a / h), S(0)};
            case Projection::cylinder_3: return {a / w, lu / h};
            case Projection::cylinder_4: return {a / h, lr / w};
            case Projection::spherical: return {std::max(a / w, frame_.vertical_angle * degree / h), S(0)};
        }
        return {};
    }

    [[nodiscard]] Projection projection() const noexcept { return projection_; }
    [[nodiscard]] const CameraFrame<S>& frame() const noexcept { return frame_; }
    [[nodiscard]] const FocalBlur<S>& focal_blur() const noexcept { return blur_; }
    [[nodiscard]] bool has_focal_blur() const noexcept { return blur_.aperture > S(0); }
    [[nodiscard]] const Vec3<S>& location() const noexcept { return frame_.location; }
    [[nodiscard]] const Vec3<S>& direction() const noexcept { return frame_.direction; }
    [[nodiscard]] const Vec3<S>& right() const noexcept { return frame_.right; }
    [[nodiscard]] const Vec3<S>& up() const noexcept { return frame_.up; }

private:
    Projection projection_;
    CameraFrame<S> frame_;
    FocalBlur<S> blur_;
    Vec3<S> lens_x_{}, lens_y_{};
};

/// The lens position for one camera sample: drawn from `rng` with focal blur, the lens's centre
/// without (a pinhole render draws the same random numbers it always did).
template <Scalar S> [[nodiscard]] Vec2<S> lens_sample(const Camera<S>& camera, Pcg32& rng) noexcept {
    return camera.has_focal_blur() ? rng.uniform2<S>() : Vec2<S>(S(0.5));
}

/// The perspective-only name the library had before it had other projections.
template <Scalar S> using PinholeCamera = Camera<S>;

}  // namespace photon
