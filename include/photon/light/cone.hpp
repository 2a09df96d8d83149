// SPDX-License-Identifier: MIT
#pragma once

#include <cmath>
#include <stdexcept>

#include "../math/sampling.hpp"
#include "../math/vec.hpp"

namespace photon {

/// Directions within `half_angle` of `axis`: the paper's light "field of view". A light with a
/// cone emits only into it; its power is what leaves through the cone. A sharp cone emits its
/// axial intensity in every direction inside; a soft one (pov_spotlight) scales it by a profile
/// in [0, 1] and its half-angle bounds where the profile is non-zero.
template <Scalar S> class Cone {
public:
    /// Throws std::invalid_argument unless the axis is non-zero and 0 < half_angle <= 180 degrees.
    Cone(const Vec3<S>& axis, S half_angle_degrees) {
        const S len = glm::length(axis);
        if (!(len > S(0)) || !std::isfinite(len))
            throw std::invalid_argument("cone: direction must be non-zero and finite");
        if (!(half_angle_degrees > S(0)) || !(half_angle_degrees <= S(180)))
            throw std::invalid_argument("cone: half-angle must be in (0, 180] degrees");
        axis_ = axis / len;
        half_angle_ = half_angle_degrees;
        // 1 - cos in double from the half-angle itself: in float 1 - cos(0.1 deg) is 4% off and
        // below 0.03 degrees it is 0, which made the intensity power / 0.
        const double theta = double(half_angle_degrees) * pi<double> / 180.0;
        one_minus_cos_ = S(one_minus_cos(theta));
        cos_half_angle_ = S(std::cos(theta));
        frame_ = Frame<S>::from_normal(axis_);
        effective_solid_angle_ = solid_angle();
    }
    /// POV-Ray 3.7's spotlight (Attenuate_Light): intensity cos^tightness in the front hemisphere,
    /// times cubic_spline(cos falloff, cos radius, cos) (3t^2 - 2t^3, 0 below cos falloff) where
    /// cos(radius) > 0 and cos < cos(radius); angles in degrees, as POV-Ray reads them (a radius of
    /// 90 or more means no soft edge). Throws std::invalid_argument on a zero axis, non-finite
    /// angles, a negative tightness, or a profile that lights no direction.
    [[nodiscard]] static Cone pov_spotlight(const Vec3<S>& axis, double radius_degrees, double falloff_degrees,
                                            double tightness) {
        if (!std::isfinite(radius_degrees) || !std::isfinite(falloff_degrees) || !std::isfinite(tightness) ||
            tightness < 0)
            throw std::invalid_argument("spotlight: radius, falloff and tightness must be finite, tightness >= 0");
        const double deg = pi<double> / 180.0;
        // The profile in terms of u = 1 - cos: exact for narrow cones in float.
        const double u_radius = one_minus_cos(radius_degrees * deg), u_falloff = one_minus_cos(falloff_degrees * deg);
        const bool edge = std::cos(radius_degrees * deg) > 0.0;  // POV-Ray's test, bit for bit
        const double u_bound = edge ? std::min(1.0, std::max(u_radius, u_falloff)) : 1.0;
        if (!(u_bound > 0.0)) throw std::invalid_argument("spotlight: its radius and falloff leave no direction lit");
        Cone cone(axis, S(std::acos(1.0 - u_bound) / deg));
        cone.soft_ = true;
        cone.edge_ = edge;
        cone.tightness_ = S(tightness);
        cone.u_radius_ = S(u_radius);
        cone.u_falloff_ = S(u_falloff);
        // Solid angle weighted by the profile: 2 pi times its integral over u. The part inside
        // the radius is (1 - (1 - a)^(n+1)) / (n + 1); the soft edge, a smooth polynomial times
        // a power, by Simpson's rule on 1024 intervals.
        const double n = tightness;
        const double a = edge ? std::min(u_radius, u_bound) : u_bound;
        double integral = (1.0 - std::pow(1.0 - a, n + 1.0)) / (n + 1.0);
        if (edge && u_falloff > u_radius) {
            const double b = u_bound;
            constexpr int m = 1024;
            const double h = (b - a) / m;
            double sum = 0;
            for (int i = 0; i <= m; ++i) sum += (i == 0 || i == m ? 1 : (i % 2 ? 4 : 2)) * profile_of(a + i * h, n, u_radius, u_falloff);
            integral += sum * h / 3.0;
        }
        if (!(integral > 0.0)) throw std::invalid_argument("spotlight: its radius and falloff leave no direction lit");
        cone.effective_solid_angle_ = S(2.0 * pi<double> * integral);
        return cone;
    }
    /// From a full field of view (twice the half-angle), in degrees.
    [[nodiscard]] static Cone from_field_of_view(const Vec3<S>& axis, S fov_degrees) {
        return Cone(axis, fov_degrees / S(2));
    }

    [[nodiscard]] const Vec3<S>& axis() const noexcept { return axis_; }
    [[nodiscard]] S half_angle_degrees() const noexcept { return half_angle_; }
    [[nodiscard]] S cos_half_angle() const noexcept { return cos_half_angle_; }
    [[nodiscard]] S one_minus_cos_half_angle() const noexcept { return one_minus_cos_; }
    /// Solid angle of the cone's directions (what sample() covers).
    [[nodiscard]] S solid_angle() const noexcept { return cone_solid_angle_1mc(one_minus_cos_); }
    /// The integral of profile() over directions: power / axial intensity. solid_angle() when sharp.
    [[nodiscard]] S effective_solid_angle() const noexcept { return effective_solid_angle_; }
    [[nodiscard]] bool is_soft() const noexcept { return soft_; }
    /// Intensity towards unit `dir` relative to the axis: 1 inside a sharp cone, 0 outside any.
    [[nodiscard]] S profile(const Vec3<S>& unit_dir) const noexcept {
        const S u = one_minus_cos_between(unit_dir, axis_);
        if (!(u <= one_minus_cos_)) return S(0);
        if (!soft_) return S(1);
        return S(profile_of(double(u), double(tightness_), double(u_radius_), double(u_falloff_), edge_));
    }
    /// Compared as 1 - cos, which stays exact for directions nearly along a narrow cone's axis.
    [[nodiscard]] bool contains(const Vec3<S>& unit_dir) const noexcept {
        return one_minus_cos_between(unit_dir, axis_) <= one_minus_cos_;
    }
    /// Uniform direction in the cone.
    [[nodiscard]] Vec3<S> sample(Vec2<S> u) const noexcept {
        return frame_.to_world(uniform_cone_1mc(u, one_minus_cos_));
    }

private:
    /// POV-Ray's spotlight profile at u = 1 - cos(theta).
    [[nodiscard]] static double profile_of(double u, double tightness, double u_radius, double u_falloff,
                                           bool edge = true) noexcept {
        if (!(u < 1.0)) return 0.0;  // cos <= 0: POV-Ray lights the front hemisphere only
        double a = tightness == 0.0 ? 1.0 : std::pow(1.0 - u, tightness);
        if (edge && u > u_radius) {
            if (!(u < u_falloff)) return 0.0;  // cubic_spline: 0 below cos(falloff), also at it
            const double t = (u_falloff - u) / (u_falloff - u_radius);
            a *= (3.0 - 2.0 * t) * t * t;
        }
        return a;
    }

    Vec3<S> axis_;
    S half_angle_, cos_half_angle_, one_minus_cos_;
    Frame<S> frame_;
    bool soft_ = false, edge_ = false;
    S tightness_ = S(0), u_radius_ = S(0), u_falloff_ = S(0);
    S effective_solid_angle_ = S(0);
};

}  // namespace photon
