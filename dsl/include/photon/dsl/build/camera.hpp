// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's camera statement resolved in POV-Ray's order of application.

#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include <photon/scene/projection.hpp>

#include "../description.hpp"
#include "../diagnostics.hpp"
#include "../value.hpp"
#include "warnings.hpp"

namespace photon::dsl {

/// The camera after POV-Ray's rules, in world space.
struct ResolvedCamera {
    Vector3 location, direction, right, up;
    std::string type = "perspective";  ///< as CameraDescription::type
    double angle = 90;                 ///< what fisheye, ultra_wide_angle, the cylinders and spherical read
    double vertical_angle = 180;       ///< spherical's
    double aperture = 0;               ///< 0 unless both `aperture` and `blur_samples` are given (POV-Ray's rule)
    double focal_distance = 1;
    unsigned blur_samples = 0;
};

/// POV-Ray 3.7's camera (Parser::Parse_Camera): `right` defaults to <aspect, 0, 0>; then for a
/// perspective or orthographic camera `angle` (> 0) sets |direction| = |right| / (2 tan(angle / 2)),
/// the other types read the angle as theirs; then `look_at` turns direction, right and up towards
/// the target keeping their lengths, right = sky x direction (sign kept from the handedness of
/// the given up, direction, right), up = direction x right; then an orthographic camera without
/// `up` and `right`, or with `angle`, scales right and up by |look_at - location| / |direction|
/// (the area a perspective camera sees at the look_at point; look_at defaults to <0, 0, 1>); the
/// focal distance is |focal_point - location|, or the direction's length when angle or look_at
/// set it, else 1; then the transformations apply.
[[nodiscard]] inline ResolvedCamera resolve_camera(const CameraDescription& cam, double aspect, Warnings* warn = nullptr) {
    auto where = [&](const char* item) {
        const auto it = cam.written.find(item);
        return it != cam.written.end() ? it->second : cam.at;
    };
    ResolvedCamera r{cam.location, cam.direction, cam.right.value_or(Vector3(aspect, 0, 0)), cam.up};
    r.type = cam.type;
    const bool framed = cam.type == "perspective" || cam.type == "orthographic";
    double direction_length = 1.0;  // POV-Ray's Direction_Length, the default focal distance
    if (cam.angle && framed && *cam.angle > 0) {
        if (glm::length(r.direction) == 0.0) throw Error(where("direction"), "camera direction must not be zero");
        direction_length = 0.5 * glm::length(r.right) / std::tan(*cam.angle * 3.14159265358979323846 / 360.0);
        r.direction = glm::normalize(r.direction) * direction_length;
    }
    if (cam.type == "spherical") {
        r.angle = cam.angle.value_or(360.0);
        r.vertical_angle = cam.vertical_angle.value_or(cam.angle ? r.angle / 2 : 180.0);
    } else if (cam.angle) {
        r.angle = *cam.angle;
    }
    if (cam.look_at) {
        direction_length = glm::length(r.direction);
        const double dir_len = glm::length(r.direction), up_len = glm::length(r.up), right_len = glm::length(r.right);
        const double handedness = glm::dot(glm::cross(r.up, r.direction), r.right);
        const Vector3 forward = *cam.look_at - r.location;
        if (glm::length(forward) == 0.0) throw Error(where("look_at"), "camera look_at equals its location");
        const Vector3 d = glm::normalize(forward);
        // Looking along the sky (straight down, say), POV-Ray keeps the right vector it had (the
        // given one, else <aspect, 0, 0>) and warns; so does photon, with a note: nothing differs.
        Vector3 right = glm::cross(cam.sky, d);
        const bool kept_right = std::abs(right.x) < 1e-10 && std::abs(right.y) < 1e-10 && std::abs(right.z) < 1e-10;
        if (kept_right) {
            right = r.right;
            if (warn)
                warn->note(where("look_at"), "camera sky <" + format_number(cam.sky.x) + ", " + format_number(cam.sky.y) +
                                                 ", " + format_number(cam.sky.z) +
                                                 "> is parallel to the viewing direction: as in POV-Ray, the camera keeps its "
                                                 "right vector and its up is direction x right; give another `sky` to choose");
        }
        right = glm::normalize(right);
        const Vector3 across = glm::cross(d, right);  // unit unless a kept right is not across the view
        if (glm::length(across) < 1e-10)
            throw Error(where("look_at"), "camera: the viewing direction is parallel to both its sky and its right vector");
        r.up = (kept_right ? across : glm::normalize(across)) * up_len;  // POV-Ray does not normalise it
        r.direction = d * dir_len;
        r.right = right * (handedness > 0 ? right_len : -right_len);
    }
    if (cam.type == "orthographic" && ((!cam.written.count("up") && !cam.written.count("right")) || cam.angle)) {
        const double k1 = glm::length(cam.look_at.value_or(Vector3(0, 0, 1)) - r.location), k2 = glm::length(r.direction);
        if (k1 > 1e-10 && k2 > 1e-10) {
            r.right *= k1 / k2;
            r.up *= k1 / k2;
        }
    }
    r.focal_distance = cam.focal_point ? glm::length(*cam.focal_point - r.location) : direction_length;
    if (r.focal_distance == 0.0) r.focal_distance = 1.0;
    if (cam.aperture && *cam.aperture != 0.0 && cam.blur_samples) {  // POV-Ray's useFocalBlur
        r.aperture = std::abs(*cam.aperture);  // a negative one mirrors POV-Ray's symmetric lens samples
        r.blur_samples = *cam.blur_samples;
    }
    r.location = cam.transform.point(r.location);
    r.direction = cam.transform.vector(r.direction);
    r.right = cam.transform.vector(r.right);
    r.up = cam.transform.vector(r.up);
    return r;
}

/// The library's projection for a CameraDescription::type.
[[nodiscard]] inline Projection camera_projection(const std::string& type) {
    for (Projection p : {Projection::perspective, Projection::orthographic, Projection::fisheye,
                         Projection::ultra_wide_angle, Projection::omnimax, Projection::panoramic, Projection::cylinder_1,
                         Projection::cylinder_2, Projection::cylinder_3, Projection::cylinder_4, Projection::spherical})
        if (to_string(p) == type) return p;
    throw std::invalid_argument("camera: unknown type `" + type + "`");
}

}  // namespace photon::dsl
