// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's camera statement resolved in POV-Ray's order of application.

#include <cmath>

#include <glm/geometric.hpp>

#include "../description.hpp"
#include "../diagnostics.hpp"
#include "../value.hpp"
#include "warnings.hpp"

namespace photon::dsl {

/// The camera's vectors after POV-Ray's rules, in world space.
struct ResolvedCamera {
    Vector3 location, direction, right, up;
};

/// POV-Ray 3.7's camera: `right` defaults to <aspect, 0, 0>; then `angle` sets |direction| =
/// |right| / (2 tan(angle / 2)); then `look_at` turns direction, right and up towards the
/// target keeping their lengths, right = sky x direction (sign kept from the handedness of the
/// given up, direction, right), up = direction x right; then the transformations apply.
[[nodiscard]] inline ResolvedCamera resolve_camera(const CameraDescription& cam, double aspect, Warnings* warn = nullptr) {
    auto where = [&](const char* item) {
        const auto it = cam.written.find(item);
        return it != cam.written.end() ? it->second : cam.at;
    };
    ResolvedCamera r{cam.location, cam.direction, cam.right.value_or(Vector3(aspect, 0, 0)), cam.up};
    if (cam.angle) {
        if (glm::length(r.direction) == 0.0) throw Error(where("direction"), "camera direction must not be zero");
        const double len = 0.5 * glm::length(r.right) / std::tan(*cam.angle * 3.14159265358979323846 / 360.0);
        r.direction = glm::normalize(r.direction) * len;
    }
    if (cam.look_at) {
        const double dir_len = glm::length(r.direction), up_len = glm::length(r.up), right_len = glm::length(r.right);
        const double handedness = glm::dot(glm::cross(r.up, r.direction), r.right);
        const Vector3 forward = *cam.look_at - r.location;
        if (glm::length(forward) == 0.0) throw Error(where("look_at"), "camera look_at equals its location");
        const Vector3 d = glm::normalize(forward);
        const Vector3 side = glm::cross(cam.sky, d);
        // Looking along the sky (straight down, say): POV-Ray still renders; photon takes the
        // axis least aligned with the view as the sky and says so.
        Vector3 sky_used = cam.sky;
        if (glm::length(side) == 0.0) {
            sky_used = std::abs(d.z) < 0.9 ? Vector3(0, 0, 1) : Vector3(1, 0, 0);
            if (warn)
                (*warn)(where("look_at"),
                        "camera sky (default y) is parallel to the viewing direction: photon uses the sky <" +
                            format_number(sky_used.x) + ", " + format_number(sky_used.y) + ", " +
                            format_number(sky_used.z) + ">; give another `sky` to choose",
                        "approximated camera", "sky");
        }
        const Vector3 right = glm::normalize(glm::cross(sky_used, d));
        r.up = glm::normalize(glm::cross(d, right)) * up_len;
        r.direction = d * dir_len;
        r.right = right * (handedness > 0 ? right_len : -right_len);
    }
    r.location = cam.transform.point(r.location);
    r.direction = cam.transform.vector(r.direction);
    r.right = cam.transform.vector(r.right);
    r.up = cam.transform.vector(r.up);
    return r;
}

}  // namespace photon::dsl
