// SPDX-License-Identifier: MIT
#pragma once
// Light sources (point, spotlight, area_light, their photons block) and the camera.

#include "degradation.hpp"
#include "parser_class.hpp"

namespace photon::dsl::detail {

inline constexpr double radians_per_degree = 3.14159265358979323846 / 180.0;

// LIGHT_SOURCE: light_source { (LIGHT_IDENT | VECTOR [,] COLOR) {LIGHT_ITEM | TRANSFORMATION} }
// LIGHT_ITEM: spotlight | point_at V | radius F | falloff F | tightness F | area_light V [,] V [,] INT [,] INT
//   | adaptive INT | jitter BOOL | circular BOOL | orient BOOL | area_illumination BOOL | fade_distance F
//   | fade_power F | shadowless | looks_like { (OBJECT | OBJECT_IDENT) MODIFIERS } | media_interaction BOOL
//   | media_attenuation BOOL | photons { .. } | parallel | cylinder | projected_through { OBJECT | OBJECT_IDENT }
inline Object Parser::parse_light(const Token& kw) {
    open_block(kw);
    Object obj;
    obj.at = kw.location;
    LightSource light;
    light.at = kw.location;
    bool from_identifier = false;
    if (peek().kind == TokenKind::identifier) {
        if (const Value* v = lookup(peek().text)) {
            if (const auto* o = std::get_if<Object>(&v->data); o && std::holds_alternative<LightSource>(o->shape)) {
                next();
                obj = *o;
                light = std::get<LightSource>(o->shape);
                from_identifier = true;
            }
        }
    }
    if (!from_identifier) {
        light.position = parse_vector("the position of the light");
        optional_comma();
        light.written["color"] = peek().location;
        light.color = parse_color("the colour of the light");
    }
    Spotlight spot = light.spotlight.value_or(Spotlight{});
    bool is_spot = light.spotlight.has_value();
    AreaLight area = light.area.value_or(AreaLight{});
    for (;;) {
        const Token t = peek();
        if (t.kind != TokenKind::identifier) break;
        if (try_transform(obj.transform)) continue;
        const std::string& w = t.text;
        if (!one_of(w, light_keywords)) break;
        next();
        light.written[w] = t.location;
        if (w == "spotlight") {
            is_spot = true;
            spot.at = t.location;
        } else if (w == "point_at") {
            spot.point_at = light.point_at = parse_vector("the point after `point_at`");
        } else if (w == "radius" || w == "falloff") {
            SourceLocation at;
            double a = parse_float("the angle in degrees after `" + w + "`", &at);
            if (light.written.count("cylinder")) continue;  // a distance there, and photon uses a point light
            // POV-Ray keeps only cos(angle), so any angle means the one from 0 to 180 degrees with that
            // cosine: the `radius -90 falloff 90` of POV-Ray's Cornell box is a hemisphere.
            if (!std::isfinite(a)) fail(at, "`" + w + "` must be a finite angle, found " + format_number(a));
            if (!(a >= 0 && a <= 180)) a = std::acos(std::clamp(std::cos(a * radians_per_degree), -1.0, 1.0)) / radians_per_degree;
            (w == "radius" ? spot.radius : spot.falloff) = a;
        } else if (w == "tightness") {
            spot.tightness = parse_nonnegative("`tightness`");
        } else if (w == "area_light") {
            area.at = t.location;
            area.axis1 = parse_vector("the first axis of the area light");
            optional_comma();
            area.axis2 = parse_vector("the second axis of the area light");
            optional_comma();
            area.size1 = int(parse_integer("the number of lights along the first axis", 1, 1024));
            optional_comma();
            area.size2 = int(parse_integer("the number of lights along the second axis", 1, 1024));
            light.area = area;
        } else if (w == "adaptive") {
            area.adaptive = int(parse_integer("`adaptive`", 0, 16));
        } else if (w == "jitter") {
            area.jitter = parse_optional_bool();
        } else if (w == "circular") {
            area.circular = parse_optional_bool();
        } else if (w == "orient") {
            area.orient = parse_optional_bool();
        } else if (w == "area_illumination") {
            parse_optional_bool();
        } else if (w == "fade_distance") {
            SourceLocation at;
            light.fade_distance = parse_float("the distance after `fade_distance`", &at);
            if (!(light.fade_distance >= 0))
                fail(at, "`fade_distance` must be >= 0, found " + format_number(light.fade_distance));
        } else if (w == "fade_power") {
            SourceLocation at;
            light.fade_power = parse_float("the exponent after `fade_power`", &at);
            if (!(light.fade_power >= 0))
                fail(at, "`fade_power` must be >= 0, found " + format_number(light.fade_power));
        } else if (w == "shadowless") {
            light.shadowless = true;
        } else if (w == "looks_like") {
            const Nest nest(*this, t.location);
            open_block(t);
            // looks_like { OBJECT | OBJECT_IDENTIFIER  MODIFIERS }
            const Token ok = next();
            const Value* named = ok.kind == TokenKind::identifier ? lookup(ok.text) : nullptr;
            if (named && std::holds_alternative<Object>(named->data)) {
                Object shape = std::get<Object>(named->data);
                parse_modifiers(t, shape);
                close_block(t, "object modifiers");
                light.looks_like = true;
                light.looks_like_object = std::make_shared<const Object>(std::move(shape));
                continue;
            }
            if (ok.kind != TokenKind::identifier || !is_object_keyword(ok.text))
                fail_expected("an object or an object identifier in `looks_like`", ok);
            Object shape = parse_object(ok);
            parse_modifiers(t, shape);
            close_block(t, "object modifiers");
            light.looks_like = true;
            light.looks_like_object = std::make_shared<const Object>(std::move(shape));
        } else if (w == "media_interaction" || w == "media_attenuation") {
            (w == "media_interaction" ? light.media_interaction : light.media_attenuation) = parse_optional_bool();
        } else if (w == "photons") {
            parse_light_photons(t, light);
        } else if (w == "parallel") {
            light.parallel = true;
        } else if (w == "cylinder") {
            degrade(t.location, degraded::approximated_light, w,
                    "a `" + w + "` light is approximated by a " + (is_spot ? "spotlight" : "point light") +
                        " at the light's position: photon has no " + w + " lights yet");
        } else if (w == "projected_through") {
            const Nest nest(*this, t.location);
            open_block(t);
            const Token o = next();
            const Value* v = o.kind == TokenKind::identifier ? lookup(o.text) : nullptr;
            if (o.kind == TokenKind::identifier && is_object_keyword(o.text))
                parse_object(o);
            else if (!v || !std::holds_alternative<Object>(v->data))
                fail_expected("an object in `projected_through`", o);
            close_block(t, "nothing more");
            degrade(t.location, degraded::ignored_effect, w,
                    "`projected_through` is ignored: the light shines everywhere, not only through the object");
        }
    }
    if (light.written.count("cylinder")) is_spot = false;  // approximated by a point light, as warned
    if (is_spot) light.spotlight = spot;
    if (light.area) {
        light.area->adaptive = area.adaptive, light.area->jitter = area.jitter;
        light.area->circular = area.circular, light.area->orient = area.orient;
    } else if (light.written.count("circular") || light.written.count("orient") || light.written.count("adaptive") ||
               light.written.count("jitter")) {
        warn(kw.location, "`circular`, `orient`, `adaptive` and `jitter` have no effect without `area_light`");
    }
    if (!is_spot && !light.written.count("cylinder") && !light.written.count("parallel"))
        for (const char* k : {"point_at", "radius", "falloff", "tightness"})
            if (light.written.count(k))
                warn(light.written[k], std::string("`") + k + "` has no effect without `spotlight`");
    obj.shape = light;
    close_block(kw, "a light_source item (spotlight, area_light, fade_distance, fade_power, photons, translate, ...)",
                light_keywords);
    return obj;
}

// LIGHT_PHOTONS: photons { {reflection BOOL | refraction BOOL | area_light BOOL} }
inline void Parser::parse_light_photons(const Token& kw, LightSource& light) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    for (;;) {
        const Token t = peek();
        if (t.is_identifier("reflection")) {
            next();
            light.photon_reflection = parse_optional_bool();
        } else if (t.is_identifier("refraction")) {
            next();
            light.photon_refraction = parse_optional_bool();
        } else if (t.is_identifier("area_light")) {
            next();
            light.photon_area_light = parse_optional_bool();
        } else {
            break;
        }
    }
    close_block(kw, "`reflection`, `refraction` or `area_light`", {"reflection", "refraction", "area_light"});
}

// CAMERA: camera { [CAMERA_ID] [TYPE] ITEM* }   TYPE: perspective | orthographic | fisheye | ultra_wide_angle
//   | omnimax | panoramic | spherical | cylinder 1..4 | mesh_camera {..} | user_defined {..}
// ITEM: location V | look_at V | up V | right V | direction V | sky V | angle F [, F] | aperture F
//   | focal_point V | blur_samples F [, F] | confidence F | variance F | normal {..} | TRANSFORM
inline CameraDescription Parser::parse_camera(const Token& kw) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    CameraDescription cam;
    take_identifier(cam, "a camera identifier or a camera item");
    cam.at = kw.location;
    for (;;) {
        const Token t = peek();
        if (t.kind != TokenKind::identifier) break;
        if (try_transform(cam.transform)) continue;
        const std::string& w = t.text;
        if (one_of(w, {"perspective", "orthographic", "fisheye", "ultra_wide_angle", "omnimax", "panoramic",
                       "spherical", "cylinder"})) {
            next();
            cam.written["type"] = t.location;
            cam.type = w;
            if (w == "cylinder")
                cam.type += " " + std::to_string(parse_integer("the type of the cylinder camera (1 to 4)", 1, 4));
            continue;
        }
        if (w == "mesh_camera" || w == "user_defined") {
            next();
            {
                const Nest inner(*this, t.location);
                skip_block(t);
            }
            degrade(t.location, degraded::approximated_camera, w,
                    "the `" + w + "` camera is approximated by a perspective camera with the same location, "
                    "direction, right and up: photon does not have it");
            continue;
        }
        if (w == "normal") {  // POV-Ray's camera ray perturbation
            const Token n = next();
            skip_block(n);
            degrade(n.location, degraded::ignored_effect, "normal",
                    "the camera's `normal` is ignored: photon does not perturb camera rays");
            continue;
        }
        if (!one_of(w, camera_keywords)) break;
        next();
        cam.written[w] = t.location;
        if (w == "location")
            cam.location = parse_vector("the camera location");
        else if (w == "look_at")
            cam.look_at = parse_vector("the point after `look_at`");
        else if (w == "up")
            cam.up = parse_vector("the vector after `up`");
        else if (w == "right")
            cam.right = parse_vector("the vector after `right`");
        else if (w == "direction")
            cam.direction = parse_vector("the vector after `direction`");
        else if (w == "sky")
            cam.sky = parse_vector("the vector after `sky`");
        else if (w == "angle") {
            // An orthographic camera's angle may come without a number (POV-Ray's 0).
            SourceLocation at;
            const bool number = cam.type != "orthographic" || starts_expression(peek());
            const double a = number ? parse_float("the horizontal field of view in degrees after `angle`", &at) : 0.0;
            if (!(a >= 0)) fail(at, "camera `angle` must not be negative, found " + format_number(a));
            if ((cam.type == "perspective" || cam.type == "orthographic") && !(a < 180))
                fail(at, "camera `angle` must be below 180 degrees, found " + format_number(a));
            cam.angle = a;
            if (accept_symbol(",")) {
                SourceLocation v_at;
                const double v = parse_float("the vertical angle of the camera", &v_at);
                if (!(v >= 0)) fail(v_at, "camera vertical angle must not be negative, found " + format_number(v));
                cam.vertical_angle = v;
            }
        } else if (w == "focal_point") {
            cam.focal_point = parse_vector("the focal point");
        } else if (w == "aperture") {
            cam.aperture = parse_float("`aperture`");
        } else if (w == "blur_samples") {
            // blur_samples N, or POV-Ray's adaptive MIN, MAX: photon always takes the most.
            SourceLocation at;
            double n = parse_float("the number of focal blur samples", &at);
            if (accept_symbol(",")) n = parse_float("the most focal blur samples", &at);
            if (!(n >= 1 && n <= 1e6)) fail(at, "`blur_samples` must be between 1 and 1000000, found " + format_number(n));
            cam.blur_samples = unsigned(n);
        } else if (w != "perspective") {
            parse_float("`" + w + "`");  // confidence, variance: POV-Ray's early stop; photon takes every sample
        }
    }
    close_block(kw, "a camera item (location, look_at, up, right, direction, sky, angle, translate, rotate)",
                camera_keywords);
    return cam;
}

}  // namespace photon::dsl::detail
