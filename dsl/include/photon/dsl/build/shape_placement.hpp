// SPDX-License-Identifier: MIT
#pragma once
// Each shape of the description placed by its transformation as a library shape: kept as the
// library's own shape where the transformation allows (a sphere under a similarity, a box whose
// axes stay axes, a cylinder, cone or disc under a similarity), wrapped in Transformed otherwise,
// always Transformed for the shapes that lie at the origin (torus, prism, text, polynomial,
// superellipsoid, lathe, sor, height field, blob). Fonts and images are read through the builder's
// caches.

#include <cmath>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <photon/photon.hpp>

#include "../description.hpp"
#include "../font_files.hpp"
#include "../image_files.hpp"
#include "library_shape.hpp"

namespace photon::dsl::detail {

/// Rotation times uniform scale: returns the scale, or nothing.
inline std::optional<double> similarity_scale(const glm::dmat3& m) {
    const glm::dmat3 g = glm::transpose(m) * m;
    const double s2 = g[0][0];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (std::abs(g[i][j] - (i == j ? s2 : 0.0)) > 1e-12 * s2) return std::nullopt;
    return std::sqrt(s2);
}

/// Whether the map keeps boxes axis-aligned (each axis goes to an axis).
inline bool keeps_axes(const glm::dmat3& m) {
    for (int c = 0; c < 3; ++c) {
        const double len = glm::length(m[c]);
        int big = 0;
        for (int k = 0; k < 3; ++k)
            if (std::abs(m[c][k]) > 1e-12 * len) ++big;
        if (big != 1) return false;
    }
    return true;
}

template <Scalar S> class ShapePlacement {
public:
    ShapePlacement(FontFiles& fonts, ImageFiles& images) : font_files_(fonts), images_(images) {}

    /// The sphere placed: itself under a similarity, else Transformed; handed to `f`.
    template <class F> void place(const SphereShape& s, const Transform& t, F&& f) {
        if (const auto scale = similarity_scale(t.linear))
            f(Sphere<S>(Vec3<S>(t.point(s.center)), S(s.radius * *scale)));
        else
            f(Transformed<Sphere<S>>(Sphere<S>(Vec3<S>(s.center), S(s.radius)), to_affine<S>(t)));
    }
    /// The box placed: itself when the map keeps axes, else Transformed; handed to `f`.
    template <class F> void place(const BoxShape& b, const Transform& t, F&& f) {
        if (keeps_axes(t.linear))
            f(Box<S>(Vec3<S>(t.point(b.corner1)), Vec3<S>(t.point(b.corner2))));
        else
            f(Transformed<Box<S>>(Box<S>(Vec3<S>(b.corner1), Vec3<S>(b.corner2)), to_affine<S>(t)));
    }
    /// A cylinder or cone placed: the library's shape under a similarity (its radii scaled), else
    /// a Transformed cone (a cylinder squashed by a shear or non-uniform scale is a cone of equal
    /// radii: one type fewer to dispatch, the same frustum code); handed to `f`.
    template <class F> void place(const CylinderShape& c, const Transform& t, F&& f) {
        place_frustum(c.base, c.radius, c.cap, c.radius, c.open, t, f);
    }
    template <class F> void place(const ConeShape& c, const Transform& t, F&& f) {
        place_frustum(c.base, c.base_radius, c.cap, c.cap_radius, c.open, t, f);
    }
    template <class F>
    void place_frustum(const Vector3& base, double r0, const Vector3& cap, double r1, bool open, const Transform& t, F&& f) {
        if (std::abs(r0 - r1) < 1e-10) r1 = r0;  // POV-Ray's rule: a cone with (nearly) equal radii is a cylinder
        if (const auto scale = similarity_scale(t.linear)) {
            const Vec3<S> b(t.point(base)), c(t.point(cap));
            if (r0 == r1)
                f(Cylinder<S>(b, c, S(r0 * *scale), open));
            else
                f(TruncatedCone<S>(b, S(r0 * *scale), c, S(r1 * *scale), open));
        } else {
            f(Transformed<TruncatedCone<S>>(TruncatedCone<S>(Vec3<S>(base), S(r0), Vec3<S>(cap), S(r1), open),
                                            to_affine<S>(t)));
        }
    }
    /// The torus placed: always Transformed (Torus lies around the y axis at the origin, and the
    /// matrix costs little beside the quartic); of major radius 0, the sphere it is.
    template <class F> void place(const TorusShape& tor, const Transform& t, F&& f) {
        if (tor.major == 0) return place(SphereShape{Vector3(0.0), tor.minor}, t, f);
        f(Transformed<Torus<S>>(Torus<S>(S(tor.major), S(tor.minor)), to_affine<S>(t)));
    }
    /// The prism placed: always Transformed (Prism lies along the y axis, and text is a prism
    /// turned to lie along z). Its outline's curves as the library's segments.
    template <class F> void place(const PrismShape& g, const Transform& t, F&& f) {
        std::vector<std::vector<OutlineSegment>> contours;
        for (const auto& contour : *g.contours) {
            contours.emplace_back();
            for (const OutlineCurve& c : contour) contours.back().push_back({c.control, c.degree});
        }
        const auto sweep = g.sweep == PrismShape::Sweep::conic ? PrismSweep::conic : PrismSweep::linear;
        f(Transformed<Prism<S>>(Prism<S>(Outline(contours), S(g.height1), S(g.height2), sweep, g.open), to_affine<S>(t)));
    }
    /// A polynomial surface placed: always Transformed (its transformation is not folded into its
    /// coefficients), with its bounded_by gate in its own coordinates.
    template <class F> void place(const PolynomialShape& p, const Transform& t, F&& f) {
        PolynomialSurface<S> surface(p.order, *p.coefficients);
        if (const auto& g = p.gate)
            surface = surface.gated({g->sphere ? PolynomialGate::Kind::sphere : PolynomialGate::Kind::box, g->center,
                                     g->radius, g->min, g->max});
        f(Transformed<PolynomialSurface<S>>(std::move(surface), to_affine<S>(t)));
    }
    /// The superellipsoid, lathe and sor placed: always Transformed (each lies at the origin,
    /// around or along the y axis), as the torus.
    template <class F> void place(const SuperellipsoidShape& g, const Transform& t, F&& f) {
        f(Transformed<Superellipsoid<S>>(Superellipsoid<S>(S(g.e), S(g.n)), to_affine<S>(t)));
    }
    template <class F> void place(const LatheShape& g, const Transform& t, F&& f) {
        std::vector<OutlineSegment> profile;
        for (const OutlineCurve& c : *g.profile) profile.push_back({c.control, c.degree});
        f(Transformed<Lathe<S>>(Lathe<S>(profile), to_affine<S>(t)));
    }
    template <class F> void place(const SorShape& g, const Transform& t, F&& f) {
        f(Transformed<Sor<S>>(Sor<S>(*g.points, g.open), to_affine<S>(t)));
    }
    /// A blob placed: always Transformed (its components keep their own transformations).
    template <class F> void place(const BlobShape& g, const Transform& t, F&& f) {
        f(Transformed<Blob<S>>(blob_of<S>(g), to_affine<S>(t)));
    }
    /// Text placed: its glyphs' outlines (font_files.hpp) as one prism, turned to run from z = 0
    /// to z = thickness (y and z swapped: the outline's v is y). One prism for all glyphs fills
    /// by the even-odd rule across them, POV-Ray's union of glyphs only where glyphs do not
    /// overlap. A text with no outline (spaces) places nothing.
    template <class F> void place(const TextShape& text, const Transform& t, F&& f) {
        auto contours = std::make_shared<const GlyphContours>(font_files_.set(text));
        if (contours->empty()) return;
        Transform turn;
        turn.linear = glm::dmat3(1, 0, 0, 0, 0, 1, 0, 1, 0);
        place(PrismShape{contours, std::min(0.0, text.thickness), std::max(0.0, text.thickness), PrismShape::Sweep::linear,
                         false},
              turn.then(t), f);
    }
    /// The height field placed: always Transformed (HeightField lies over the unit square), its
    /// heights read from the image as POV-Ray reads them. Geometry queries without an image
    /// reader (object_geometry.hpp) place nothing.
    template <class F> void place(const HeightFieldShape& g, const Transform& t, F&& f) {
        if (!images_.reads()) return;
        const auto image = images_.grid(g.file, false);
        if (image->width() < 2 || image->height() < 2)
            throw Error(g.file.at, "a height field's image needs at least 2 x 2 pixels");
        f(Transformed<HeightField<S>>(HeightField<S>(image->width(), image->height(), height_field_heights(*image),
                                                     {.smooth = g.smooth, .water_level = g.water_level}),
                                      to_affine<S>(t)));
    }
    /// The quadric placed: its transformation folded into its numbers (in double, also for float);
    /// with no quadratic term, the plane (half-space) it is. Handed to `f`.
    template <class F> void place(const QuadricShape& q, const Transform& t, F&& f) {
        if (q.squares == Vector3(0.0) && q.mixed == Vector3(0.0)) {  // G x + H y + I z + J <= 0
            const double n = glm::length(q.linear);
            return f(place(PlaneShape{q.linear, -q.constant / n}, t));
        }
        const QuadricCoefficients<S> c{Vec3<S>(q.squares), Vec3<S>(q.mixed), Vec3<S>(q.linear), S(q.constant)};
        f(Quadric<S>(c).transformed(to_affine<double>(t)));
    }
    Plane<S> place(const PlaneShape& p, const Transform& t) {
        const Vector3 n = glm::normalize(p.normal);
        const Vector3 world_n = glm::normalize(glm::transpose(glm::inverse(t.linear)) * n);
        const Vector3 point = t.point(n * p.distance);
        return Plane<S>(Vec3<S>(world_n), S(glm::dot(point, world_n)));
    }

private:
    FontFiles& font_files_;
    ImageFiles& images_;
};

}  // namespace photon::dsl::detail
