// SPDX-License-Identifier: MIT
#pragma once
// The round shapes: cylinder, cone, disc and torus, with POV-Ray 3.7's reading of their values.
// A cylinder or cone whose two points coincide, where POV-Ray stops, is skipped with a warning
// (see degenerate()); where POV-Ray renders nothing (a radius of 0, a disc's zero normal or a hole as wide as
// the disc) photon skips the object with a warning; a negative radius that POV-Ray reads as its
// absolute value (it squares it, or mirrors the shape) is read so too, with a warning. A cone with
// a negative radius, which POV-Ray turns into a double cone, is an error.

#include "degradation.hpp"
#include "parser_class.hpp"

namespace photon::dsl::detail {

namespace quadric {
/// POV-Ray's EPSILON: closer points are one point; radii closer than this are equal.
inline constexpr double epsilon = 1e-10;
}  // namespace quadric

/// OPEN: [open] after a cylinder's or cone's values (before its modifiers, as POV-Ray reads it).
inline bool Parser::accept_open() {
    if (!peek().is_identifier("open")) return false;
    next();
    return true;
}

/// A value that must be finite (an overflowing expression is an error, not a shape).
inline double Parser::finite_value(double v, const std::string& what, const SourceLocation& at) {
    if (!std::isfinite(v)) fail(at, what + " must be finite, found " + format_number(v));
    return v;
}

/// `r` read as POV-Ray reads a radius it squares or mirrors: its absolute value, with a warning.
inline double Parser::absolute_radius(double r, const std::string& what, const SourceLocation& at) {
    if (r < 0)
        warn(at, what + " is negative (" + format_number(r) + "): read as " + format_number(-r) +
                     ", as POV-Ray does (write the positive value)");
    return std::abs(r);
}

/// The object becomes a skipped one: POV-Ray renders nothing for it either.
inline void Parser::skip_empty_shape(Object& obj, const std::string& keyword, const std::string& why,
                                     const SourceLocation& at) {
    const std::string reason = "it has no surface (" + why + "), POV-Ray renders nothing for it either";
    degrade(at, degraded::skipped_object, keyword, "`" + keyword + "` is skipped: " + reason);
    obj.shape = SkippedShape{keyword, reason};
}

/// Whether the two points of a cylinder or cone coincide. POV-Ray stops there ("Degenerate
/// cylinder"); photon skips the object with a warning instead, because such points usually come
/// from a trace() that missed an object photon skipped (language/trace.pov), not from the file.
inline bool Parser::degenerate(Object& obj, const std::string& keyword, const Vector3& base, const Vector3& cap,
                               const SourceLocation& at) {
    if (!(glm::length(cap - base) < quadric::epsilon)) return false;
    const std::string point =
        "<" + format_number(base.x) + ", " + format_number(base.y) + ", " + format_number(base.z) + ">";
    const std::string why = "its base and cap points are the same point " + point +
                            "; POV-Ray stops with \"Degenerate cylinder\" here";
    degrade(at, degraded::skipped_object, keyword, "`" + keyword + "` is skipped: " + why);
    obj.shape = SkippedShape{keyword, why};
    return true;
}

// CYLINDER: cylinder { VECTOR [,] VECTOR [,] FLOAT [open] MODIFIERS }
inline void Parser::parse_cylinder(Object& obj) {
    CylinderShape c;
    SourceLocation base_at, cap_at, radius_at;
    c.base = parse_vector("the base point of the cylinder", &base_at);
    optional_comma();
    c.cap = parse_vector("the cap point of the cylinder", &cap_at);
    optional_comma();
    const double r = finite_value(parse_float("the radius of the cylinder", &radius_at), "the radius of the cylinder",
                                  radius_at);
    c.open = accept_open();
    finite_value(glm::length(c.cap - c.base), "the length of the cylinder", cap_at);
    c.radius = absolute_radius(r, "the radius of the cylinder", radius_at);
    obj.shape = c;
    if (degenerate(obj, "cylinder", c.base, c.cap, base_at)) return;
    if (c.radius == 0) skip_empty_shape(obj, "cylinder", "radius 0", radius_at);
}

// CONE: cone { VECTOR [,] FLOAT [,] VECTOR [,] FLOAT [open] MODIFIERS }
inline void Parser::parse_cone(Object& obj) {
    ConeShape c;
    SourceLocation base_at, cap_at, r0_at, r1_at;
    c.base = parse_vector("the base point of the cone", &base_at);
    optional_comma();
    c.base_radius = finite_value(parse_float("the base radius of the cone", &r0_at), "the base radius of the cone", r0_at);
    optional_comma();
    c.cap = parse_vector("the cap point of the cone", &cap_at);
    optional_comma();
    c.cap_radius = finite_value(parse_float("the cap radius of the cone", &r1_at), "the cap radius of the cone", r1_at);
    c.open = accept_open();
    finite_value(glm::length(c.cap - c.base), "the length of the cone", cap_at);
    for (const auto& [r, at] : {std::pair{c.base_radius, r0_at}, std::pair{c.cap_radius, r1_at}})
        if (r < 0)
            fail(at, "a cone's radii must not be negative, found " + format_number(r) +
                         " (POV-Ray would make a double cone of it, which photon does not have)");
    obj.shape = c;
    if (degenerate(obj, "cone", c.base, c.cap, base_at)) return;
    if (c.base_radius == 0 && c.cap_radius == 0) skip_empty_shape(obj, "cone", "both radii 0", r0_at);
}

// DISC: disc { VECTOR [,] VECTOR [,] FLOAT [,] [FLOAT] MODIFIERS }
inline void Parser::parse_disc(Object& obj) {
    DiscShape d;
    SourceLocation normal_at, radius_at, hole_at;
    d.center = parse_vector("the centre of the disc");
    optional_comma();
    d.normal = parse_vector("the normal of the disc", &normal_at);
    optional_comma();
    const double r = finite_value(parse_float("the radius of the disc", &radius_at), "the radius of the disc", radius_at);
    optional_comma();
    double hole = 0;
    if (starts_expression(peek()))
        hole = finite_value(parse_float("the hole radius of the disc", &hole_at), "the hole radius of the disc", hole_at);
    d.radius = absolute_radius(r, "the radius of the disc", radius_at);
    d.hole_radius = absolute_radius(hole, "the hole radius of the disc", hole_at);
    obj.shape = d;
    if (!(glm::length(d.normal) > 0) || !std::isfinite(glm::length(d.normal)))
        skip_empty_shape(obj, "disc", "its normal is zero", normal_at);
    else if (d.radius == 0)
        skip_empty_shape(obj, "disc", "radius 0", radius_at);
    else if (d.hole_radius >= d.radius)
        skip_empty_shape(obj, "disc", "its hole radius " + format_number(d.hole_radius) + " is not below its radius " +
                                          format_number(d.radius),
                         hole_at);
}

// TORUS: torus { FLOAT [,] FLOAT [sturm] MODIFIERS }
// A major radius of 0 is a sphere of the minor radius (the points at that distance from the
// centre), which is what POV-Ray's quartic draws there too.
inline void Parser::parse_torus(Object& obj) {
    TorusShape t;
    SourceLocation major_at, minor_at;
    const double major =
        finite_value(parse_float("the major radius of the torus", &major_at), "the major radius of the torus", major_at);
    optional_comma();
    const double minor =
        finite_value(parse_float("the minor radius of the torus", &minor_at), "the minor radius of the torus", minor_at);
    t.major = absolute_radius(major, "the major radius of the torus", major_at);
    t.minor = absolute_radius(minor, "the minor radius of the torus", minor_at);
    obj.shape = t;
    if (t.minor == 0) skip_empty_shape(obj, "torus", "minor radius 0", minor_at);
}

}  // namespace photon::dsl::detail
