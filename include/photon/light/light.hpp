// SPDX-License-Identifier: MIT
#pragma once
// Lights as the two passes see them: photon emission (pass 1) and incident light at a shading
// point for shadow rays (pass 2). Point and spherical lights share both: a point light is the
// limit of a sphere light of radius 0. An area light (area_light.hpp) is a grid or a continuum of
// point emitters: photons leave from one of them, shadow rays aim at one of them. A light's
// falloff (falloff.hpp) and its cone's profile (cone.hpp) scale both alike: direct light by g(d)
// and the profile, photons by the profile at emission and by g(d) d^2 at their first hit
// (first_hit_scale), d from the centre, or from its emitter for an area light. A parallel light
// (parallel_light.hpp) is a plane emitting one direction: photons leave its beam disc, shadow
// rays run along the direction back to the plane, and nothing falls off with distance.

#include <cmath>
#include <algorithm>
#include <optional>
#include <utility>
#include <variant>

#include "../geometry/ray.hpp"
#include "../math/frame.hpp"
#include "../math/rng.hpp"
#include "../math/sampling.hpp"
#include "area_light.hpp"
#include "parallel_light.hpp"
#include "point_light.hpp"
#include "sphere_light.hpp"

namespace photon {

template <Scalar S> using Light = std::variant<PointLight<S>, SphereLight<S>, AreaLight<S>, ParallelLight<S>>;

/// How photon directions are drawn: `rejection` as the paper (points in a cube kept when inside
/// the unit ball, and inside the cone if any), `direct` by inverting the distribution. Both are
/// uniform over the emitting directions; `direct` never loops.
enum class EmissionSampler { direct, rejection };

template <Scalar S> [[nodiscard]] Vec3<S> light_center(const Light<S>& light) noexcept {
    return std::visit([](const auto& l) {
        if constexpr (requires { l.center; }) return l.center; else return l.position;
    }, light);
}
/// Radius of the ball around light_center that holds every point light can leave from: a sphere
/// light's radius, the ball around an area light's emitters, 0 for a point light. A parallel
/// light's centre is its position (a point of its plane) and its radius 0: callers that bound
/// where its light comes from must treat it apart (its beam is ParallelLight::beam_*).
template <Scalar S> [[nodiscard]] S light_radius(const Light<S>& light) noexcept {
    return std::visit([](const auto& l) {
        if constexpr (requires { l.radius; }) return l.radius;
        else if constexpr (requires { l.bounding_radius(); }) return l.bounding_radius();
        else return S(0);
    }, light);
}
/// Whether rays can meet the light (a sphere light's surface); point and area lights are points.
template <Scalar S> [[nodiscard]] bool light_has_surface(const Light<S>& light) noexcept {
    return std::holds_alternative<SphereLight<S>>(light);
}
template <Scalar S> [[nodiscard]] const Rgb<S>& light_power(const Light<S>& light) noexcept {
    return std::visit([](const auto& l) -> const Rgb<S>& { return l.power; }, light);
}
/// The light's cone; none for a parallel light (POV-Ray's parallel spotlight has no cone effect).
template <Scalar S> [[nodiscard]] const std::optional<Cone<S>>& light_cone(const Light<S>& light) noexcept {
    static const std::optional<Cone<S>> none{};
    return std::visit([](const auto& l) -> const std::optional<Cone<S>>& {
        if constexpr (requires { l.cone; }) return l.cone; else return none;
    }, light);
}
template <Scalar S> [[nodiscard]] bool is_parallel(const Light<S>& light) noexcept {
    return std::holds_alternative<ParallelLight<S>>(light);
}
/// Whether the light sends any light: power in some channel, or for a parallel light irradiance
/// (its power is 0 when no finite beam covers the scene, yet it lights infinite planes).
template <Scalar S> [[nodiscard]] bool light_is_lit(const Light<S>& light) noexcept {
    if (const auto* p = std::get_if<ParallelLight<S>>(&light)) return max_component(p->irradiance) > S(0);
    return max_component(light_power(light)) > S(0);
}
template <Scalar S> [[nodiscard]] const Falloff<S>& light_falloff(const Light<S>& light) noexcept {
    return std::visit([](const auto& l) -> const Falloff<S>& { return l.falloff; }, light);
}
template <Scalar S> [[nodiscard]] bool light_casts_shadows(const Light<S>& light) noexcept {
    return std::visit([](const auto& l) { return l.casts_shadows; }, light);
}
/// Whether participating media scatter the light (material/medium.hpp).
template <Scalar S> [[nodiscard]] bool light_media_interaction(const Light<S>& light) noexcept {
    return std::visit([](const auto& l) { return l.media_interaction; }, light);
}
/// Whether the scene's atmospheric media dim the light's shadow rays (interior media always do).
template <Scalar S> [[nodiscard]] bool light_media_attenuation(const Light<S>& light) noexcept {
    return std::visit([](const auto& l) { return l.media_attenuation; }, light);
}
template <Scalar S> void validate(const Light<S>& light) {
    std::visit([](const auto& l) { l.validate(); }, light);
}

/// Power over axial intensity: 4 pi, or its cone's solid angle weighted by the cone's profile.
template <Scalar S> [[nodiscard]] S emission_solid_angle(const Light<S>& light) noexcept {
    const auto& cone = light_cone(light);
    return cone ? cone->effective_solid_angle() : S(4) * pi<S>;
}
/// Radiant intensity in W/sr per channel along the cone's axis (a parallel light has none: its
/// power is over its beam, and its irradiance is ParallelLight::irradiance) (in every direction without a
/// cone or inside a sharp one). With a falloff other than 1/d^2, `power` is the power of the
/// physical light of this intensity and profile, what the photons leave with before their first
/// hit rescales them (first_hit_scale).
template <Scalar S> [[nodiscard]] Rgb<S> radiant_intensity(const Light<S>& light) noexcept {
    return light_power(light) / emission_solid_angle(light);
}
/// Intensity towards unit `direction` (leaving the light) relative to the axial one: 1 without a cone.
template <Scalar S> [[nodiscard]] S intensity_profile(const Light<S>& light, const Vec3<S>& direction) noexcept {
    const auto& cone = light_cone(light);
    return cone ? cone->profile(direction) : S(1);
}
/// Factor on the power of a photon drawn uniformly over the light's emitting directions (what
/// sample_emission_direction does) leaving along unit `direction`: the profile over its mean,
/// 1 for a sharp cone or none.
template <Scalar S> [[nodiscard]] S emission_weight(const Light<S>& light, const Vec3<S>& direction) noexcept {
    const auto& cone = light_cone(light);
    if (!cone || !cone->is_soft()) return S(1);
    return cone->profile(direction) * (cone->solid_angle() / cone->effective_solid_angle());
}
/// Factor on the power of a photon from `light` at its first surface hit `p`: g(d) d^2 for the
/// distance d from the light's centre (falloff.hpp), so that the first-hit irradiance follows
/// the light's falloff; exactly 1 for the physical light. Later bounces are physical. An area
/// light's emitters fall off each from itself (POV-Ray's `area_illumination`): d is from the
/// photon's emission point `origin`.
template <Scalar S>
[[nodiscard]] S first_hit_scale(const Light<S>& light, const Vec3<S>& p, const Vec3<S>& origin) noexcept {
    if (const auto* parallel = std::get_if<ParallelLight<S>>(&light))
        return parallel->falloff_factor(parallel->plane_distance(p));
    const Falloff<S>& falloff = light_falloff(light);
    if (falloff.is_physical()) return S(1);
    const Vec3<S> from = std::holds_alternative<AreaLight<S>>(light) ? origin : light_center(light);
    return falloff.relative_to_inverse_square(glm::length(p - from));
}

/// Unit emission direction, uniform over the light's emitting directions (a parallel light's one).
template <Scalar S>
[[nodiscard]] Vec3<S> sample_emission_direction(const Light<S>& light, EmissionSampler sampler, Pcg32& rng) noexcept {
    if (const auto* parallel = std::get_if<ParallelLight<S>>(&light)) return parallel->direction;
    const auto& cone = light_cone(light);
    if (sampler == EmissionSampler::direct) {
        const Vec2<S> u = rng.uniform2<S>();
        return cone ? cone->sample(u) : uniform_sphere(u);
    }
    for (;;) {  // expected 4 pi / solid angle draws with a cone
        const Vec3<S> d = rejection_sphere<S>(rng);
        if (!cone || cone->contains(d)) return d;
    }
}

/// Origin of a photon leaving the light along unit `direction`. For a sphere light, rays of one
/// direction leave a Lambertian sphere uniformly over its silhouette disc, so the origin is a
/// uniform point of that disc lifted onto the sphere's near side. For an area light, one emitter
/// (each carries the same power into every direction). For a parallel light, a uniform point of
/// its beam disc (every photon carries the same share of irradiance * beam area).
template <Scalar S>
[[nodiscard]] Vec3<S> sample_emission_origin(const Light<S>& light, const Vec3<S>& direction, Vec2<S> u) noexcept {
    if (const auto* parallel = std::get_if<ParallelLight<S>>(&light)) {
        const Vec2<S> disc = parallel->beam_radius * concentric_disc(u);
        const Frame<S> frame = Frame<S>::from_normal(parallel->direction);
        return parallel->beam_center + frame.to_world({disc.x, disc.y, S(0)});
    }
    if (const auto* area = std::get_if<AreaLight<S>>(&light)) return area->center + area->emitter_offset(u);
    const S radius = light_radius(light);
    const Vec3<S> center = light_center(light);
    if (radius == S(0)) return center;
    const Vec2<S> disc = concentric_disc(u);
    const Frame<S> frame = Frame<S>::from_normal(direction);
    const S lift = std::sqrt(std::max(S(0), S(1) - disc.x * disc.x - disc.y * disc.y));
    return center + radius * frame.to_world({disc.x, disc.y, lift});
}

/// Light arriving at a shading point from one sample of a light.
template <Scalar S> struct IncidentLight {
    Vec3<S> direction;  ///< unit, from the shading point towards the light
    S distance;         ///< to the sampled point of the light (shadow rays stop short of it)
    Rgb<S> irradiance;  ///< irradiance on a surface facing the light; times cos(theta) for others
};

/// A light as seen from one shading point `x`: what every sample shares (the direction to the
/// centre, the cone the sphere subtends, its frame, the falloff at x's distance from the centre)
/// is computed once, so n x n shadow samples cost one square root each. Sphere lights are sampled
/// uniformly in the solid angle they subtend, so the estimate is exact for an unoccluded light
/// (with its falloff evaluated at the centre's distance, as POV-Ray does for its area lights).
/// An area light's samples are its emitters, each lighting x by its intensity times its falloff
/// at its own distance (POV-Ray's `area_illumination`). A parallel light's one sample runs back
/// along its direction to its plane (as POV-Ray's shadow ray), with its irradiance (faded by
/// the plane distance, if it fades); nothing behind the plane.
template <Scalar S> class IncidentSampler {
public:
    IncidentSampler(const Light<S>& light, const Vec3<S>& x) noexcept : cone_(light_cone(light)) {
        if (const auto* parallel = std::get_if<ParallelLight<S>>(&light)) {
            distance_ = parallel->plane_distance(x);
            visible_ = distance_ > S(0);
            axis_ = -parallel->direction;
            value_ = parallel->irradiance * parallel->falloff_factor(distance_);
            return;
        }
        to_center_ = light_center(light) - x;
        const S d2 = glm::dot(to_center_, to_center_);
        if ((area_ = std::get_if<AreaLight<S>>(&light))) {
            visible_ = true;  // but nothing from an emitter at x itself
            falloff_ = &light_falloff(light);
            value_ = radiant_intensity(light);
            return;
        }
        radius_ = light_radius(light);
        visible_ = d2 > radius_ * radius_;  // false inside the light
        if (!visible_) return;
        const S dist = std::sqrt(d2);
        axis_ = to_center_ / dist;
        const Rgb<S> intensity = radiant_intensity(light);
        const Falloff<S>& falloff = light_falloff(light);
        if (radius_ == S(0)) {
            distance_ = dist;
            value_ = falloff.is_physical() ? intensity / d2 : intensity * falloff.irradiance_per_intensity(dist);
            return;
        }
        relative_ = falloff.relative_to_inverse_square(dist);
        // Cone of directions subtended by the sphere; 1 - cos computed as sin^2 / (1 + cos).
        const S sin2_max = radius_ * radius_ / d2;
        one_minus_cos_ = sin2_max / (S(1) + std::sqrt(std::max(S(0), S(1) - sin2_max)));
        frame_ = Frame<S>::from_normal(axis_);
        solid_angle_ = cone_solid_angle_1mc(one_minus_cos_);
        value_ = intensity / (pi<S> * radius_ * radius_) * solid_angle_ * relative_;
    }

    /// The falloff over the physical one at x (Falloff::relative_to_inverse_square): 1 when physical.
    [[nodiscard]] S falloff_scale() const noexcept { return relative_; }

    /// Whether more than one sample can differ (a sphere or area light).
    [[nodiscard]] bool is_area() const noexcept { return radius_ > S(0) || area_; }
    /// Whether no ray can meet the light (a point or area light): its samples' directions are
    /// deltas, which no other strategy finds.
    [[nodiscard]] bool is_delta() const noexcept { return !(radius_ > S(0)); }

    /// Strata per axis for `samples` shadow rays: 1 x 1 for a point light, n x n with n^2 >=
    /// samples for a sphere, an area light's own N1 x N2 grid (one ray per emitter, or per
    /// jittered cell as POV-Ray) when it has no more cells than `samples`, else n x n.
    [[nodiscard]] std::pair<unsigned, unsigned> strata(unsigned samples) const noexcept {
        if (!is_area()) return {1u, 1u};
        if (area_ && area_->size1 * area_->size2 <= std::max(samples, 1u)) return {area_->size1, area_->size2};
        const unsigned n = strata_per_axis(samples);
        return {n, n};
    }

    /// Density per steradian of sample()'s directions at unit `direction`: 1 / the solid angle
    /// the sphere subtends if the line along `direction` meets the sphere, else 0 (also for a
    /// point light, whose one direction is a delta). Whether the line meets the sphere is
    /// decided by the centre's distance from it, not by comparing cosines, which round to 1 in
    /// float for small far lights. Multiple importance sampling needs it for directions that
    /// another strategy found.
    [[nodiscard]] S pdf(const Vec3<S>& direction) const noexcept {
        if (!visible_ || radius_ == S(0)) return S(0);
        const S b = glm::dot(direction, to_center_);
        if (!(b > S(0))) return S(0);
        const Vec3<S> off = to_center_ - b * direction;
        return glm::dot(off, off) <= radius_ * radius_ ? S(1) / solid_angle_ : S(0);
    }
    /// pdf() of the directions sample() returns (they all meet the sphere): 1 / solid angle.
    [[nodiscard]] S sample_pdf() const noexcept { return radius_ > S(0) && visible_ ? S(1) / solid_angle_ : S(0); }

    /// One sample, with u uniform in [0,1)^2 (stratify it for soft shadows). Nothing when `x`
    /// is outside the cone or inside the light.
    [[nodiscard]] std::optional<IncidentLight<S>> sample(Vec2<S> u) const noexcept {
        if (!visible_) return std::nullopt;
        if (area_) {
            const Vec3<S> to = to_center_ + area_->emitter_offset(u);
            const S d2 = glm::dot(to, to);
            if (!(d2 > S(0))) return std::nullopt;  // x on an emitter
            const S d = std::sqrt(d2);
            const Vec3<S> dir = to / d;
            const S profile = cone_ ? cone_->profile(-dir) : S(1);
            if (!(profile > S(0))) return std::nullopt;
            const S g = falloff_->is_physical() ? S(1) / d2 : falloff_->irradiance_per_intensity(d);
            return IncidentLight<S>{dir, d, value_ * (profile * g)};
        }
        if (radius_ == S(0)) {
            const S profile = cone_ ? cone_->profile(-axis_) : S(1);
            if (!(profile > S(0))) return std::nullopt;
            return IncidentLight<S>{axis_, distance_, value_ * profile};
        }
        const Vec3<S> dir = frame_.to_world(Vec3<S>{uniform_cone_1mc(u, one_minus_cos_)});
        const S profile = cone_ ? cone_->profile(-dir) : S(1);
        if (!(profile > S(0))) return std::nullopt;
        const S b = glm::dot(dir, to_center_);
        const Vec3<S> off = to_center_ - b * dir;
        const S t = b - std::sqrt(std::max(S(0), radius_ * radius_ - glm::dot(off, off)));
        return IncidentLight<S>{dir, t, value_ * profile};
    }

private:
    const std::optional<Cone<S>>& cone_;
    const AreaLight<S>* area_ = nullptr;
    const Falloff<S>* falloff_ = nullptr;  ///< an area light's, applied per emitter
    Vec3<S> to_center_{}, axis_{};
    S radius_ = S(0), distance_ = S(0), one_minus_cos_ = S(0), solid_angle_ = S(0), relative_ = S(1);
    Frame<S> frame_{};
    Rgb<S> value_{};
    bool visible_ = false;
};

/// One sample of `light` seen from `x` (IncidentSampler for a single sample).
template <Scalar S>
[[nodiscard]] std::optional<IncidentLight<S>> sample_incident(const Light<S>& light, const Vec3<S>& x,
                                                              Vec2<S> u) noexcept {
    return IncidentSampler<S>(light, x).sample(u);
}

}  // namespace photon
