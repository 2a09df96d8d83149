// SPDX-License-Identifier: MIT
#pragma once
// The part of a gather disc that a shading point can see. Probe rays in the tangent plane find
// the nearest occluder in each of m sectors (a wall standing on the floor). Each hit becomes a
// line in the tangent plane (the occluder's face, from the hit normal); a photon is kept only if
// it lies in front of the lines of its own sector and of the two neighbouring ones, which closes
// the gaps between sectors that run nearly parallel to a wall. The estimate then divides by the
// area of exactly that region, integrated numerically. This removes both the light leak through
// thin walls and the darkening of corners, where part of the disc lies behind the wall.

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "../math/frame.hpp"
#include "../math/vec.hpp"

namespace photon {

class VisibleDisc {
public:
    static constexpr unsigned max_sectors = 32;

    /// A full disc of radius `radius` in the plane with unit normal `n`, split into `sectors`
    /// equal wedges (clamped to [4, max_sectors]).
    VisibleDisc(const Vec3<float>& n, unsigned sectors, float radius) noexcept
        : frame_(Frame<float>::from_normal(n)), sectors_(std::clamp(sectors, 4u, max_sectors)), radius_(radius) {}

    [[nodiscard]] unsigned sectors() const noexcept { return sectors_; }
    /// Unit direction in the tangent plane through the middle of sector s.
    [[nodiscard]] Vec3<float> sector_direction(unsigned s) const noexcept {
        const float a = (float(s) + 0.5f) * sector_angle();
        return frame_.to_world({std::cos(a), std::sin(a), 0.0f});
    }

    /// Records the occluder a probe along sector_direction(s) met at `offset` (hit point minus
    /// the disc centre) with surface normal `normal`.
    void clip(unsigned s, const Vec3<float>& offset, const Vec3<float>& normal) noexcept {
        const Vec2<float> q = in_plane(offset);
        Vec2<float> u = in_plane(normal);
        const float len = glm::length(u);
        const Vec2<float> e{std::cos((float(s) + 0.5f) * sector_angle()), std::sin((float(s) + 0.5f) * sector_angle())};
        // A face nearly parallel to the plane (an overhang's underside) gives no usable line:
        // treat it as a wall across the probe.
        u = len > 0.2f ? u / len : -e;
        if (glm::dot(u, e) > 0.0f) u = -u;  // the side facing the centre
        lines_[s] = {q, u, true};
        clipped_ = true;
    }

    /// Whether a point at in-plane offset `v` from the centre is visible and within the radius.
    [[nodiscard]] bool contains(const Vec3<float>& v) const noexcept {
        const Vec2<float> p = in_plane(v);
        if (glm::dot(p, p) > radius_ * radius_) return false;
        if (!clipped_) return true;  // no probe met a wall: the whole disc (the common case)
        const unsigned s = sector_of(fast_atan2(p.y, p.x));
        for (unsigned k : {s + sectors_ - 1, s, s + 1}) {
            const Line& l = lines_[k % sectors_];
            if (l.valid && glm::dot(p - l.point, l.normal) < 0.0f) return false;
        }
        return true;
    }

    /// Area of the visible region within radius r (<= the disc's radius): the integral of
    /// rho(theta)^2 / 2 over the angle, rho being the distance to the nearest line.
    [[nodiscard]] float area(float r) const noexcept {
        constexpr unsigned steps = 8;  // per sector
        const float dtheta = sector_angle() / float(steps);
        float sum = 0.0f;
        for (unsigned s = 0; s < sectors_; ++s)
            for (unsigned j = 0; j < steps; ++j) {
                const float theta = (float(s) + (float(j) + 0.5f) / float(steps)) * sector_angle();
                sum += squared(reach(s, {std::cos(theta), std::sin(theta)}, r));
            }
        return 0.5f * sum * dtheta;
    }

private:
    struct Line {
        Vec2<float> point{};   ///< on the occluder, relative to the centre
        Vec2<float> normal{};  ///< unit, towards the centre
        bool valid = false;
    };

    [[nodiscard]] float sector_angle() const noexcept { return 2.0f * pi<float> / float(sectors_); }
    [[nodiscard]] Vec2<float> in_plane(const Vec3<float>& v) const noexcept {
        return {glm::dot(v, frame_.tangent), glm::dot(v, frame_.bitangent)};
    }
    [[nodiscard]] unsigned sector_of(float angle) const noexcept {
        float f = angle / sector_angle();
        if (f < 0.0f) f += float(sectors_);
        return std::min(sectors_ - 1, static_cast<unsigned>(f));
    }
    /// Visible distance along unit direction e in sector s, at most r.
    [[nodiscard]] float reach(unsigned s, const Vec2<float>& e, float r) const noexcept {
        float rho = r;
        for (unsigned k : {s + sectors_ - 1, s, s + 1}) {
            const Line& l = lines_[k % sectors_];
            const float toward = glm::dot(e, l.normal);
            if (!l.valid || toward >= 0.0f) continue;  // moving away from (or along) the face
            // Points t e stay in front while t * dot(e, u) >= dot(q, u).
            rho = std::min(rho, std::max(0.0f, glm::dot(l.point, l.normal) / toward));
        }
        return rho;
    }

    /// atan2 within 1e-5 rad, several times cheaper than std::atan2: it is called per photon
    /// and only picks a sector. Odd minimax polynomial for atan on [-1, 1], then octant folding.
    [[nodiscard]] static float fast_atan2(float y, float x) noexcept {
        const float ax = std::abs(x), ay = std::abs(y);
        const float hi = std::max(ax, ay);
        if (hi == 0.0f) return 0.0f;
        const float a = std::min(ax, ay) / hi, a2 = a * a;
        float r = a * (0.99997726f + a2 * (-0.33262347f + a2 * (0.19354346f + a2 * (-0.11643287f + a2 * (0.05265332f + a2 * -0.01172120f)))));
        if (ay > ax) r = 0.5f * pi<float> - r;
        if (x < 0.0f) r = pi<float> - r;
        return y < 0.0f ? -r : r;
    }

    Frame<float> frame_;
    unsigned sectors_;
    float radius_;
    bool clipped_ = false;
    std::array<Line, max_sectors> lines_{};
};

}  // namespace photon
