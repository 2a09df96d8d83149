// SPDX-License-Identifier: MIT
#pragma once
// What a scene file says, after POV-Ray's evaluation (#declare, #include, #if, expressions) and
// before any library object exists: camera, lights, objects with their textures, interiors,
// photon options and transforms, and the global settings. Values keep POV-Ray's meaning (a light
// colour is POV-Ray's brightness, a finish is POV-Ray's finish); build.hpp translates them.
// Every part carries the location it was written at, for messages.

#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iterator>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "diagnostics.hpp"

namespace photon::dsl {

using Vector3 = glm::dvec3;

/// POV-Ray colour: red, green, blue, filter (transparency tinted by the colour) and transmit
/// (untinted transparency).
struct Color {
    Vector3 rgb{0.0};
    double filter = 0, transmit = 0;

    friend bool operator==(const Color&, const Color&) = default;
};

/// Affine map x' = linear x + translation (column vectors). POV-Ray's transformations compose
/// in the order written: `a.then(b)` applies a, then b.
struct Transform {
    glm::dmat3 linear{1.0};
    Vector3 translation{0.0};

    [[nodiscard]] static Transform translate(const Vector3& t) {
        Transform r;
        r.translation = t;
        return r;
    }
    [[nodiscard]] static Transform scale(const Vector3& s) {
        Transform r;
        r.linear[0][0] = s.x, r.linear[1][1] = s.y, r.linear[2][2] = s.z;
        return r;
    }
    /// POV-Ray's `rotate <a, b, c>`: about x by a degrees, then y by b, then z by c. Each is the
    /// usual right-handed rotation matrix (rotate <0,90,0> takes +x to -z).
    [[nodiscard]] static Transform rotate(const Vector3& degrees) {
        auto axis = [](int a, double deg) {
            const double r = deg * 3.14159265358979323846 / 180.0, c = std::cos(r), s = std::sin(r);
            Transform t;
            const int i = (a + 1) % 3, j = (a + 2) % 3;  // rotation in the (i, j) plane
            t.linear[i][i] = c, t.linear[i][j] = s;      // column i is the image of axis i
            t.linear[j][i] = -s, t.linear[j][j] = c;
            return t;
        };
        return axis(0, degrees.x).then(axis(1, degrees.y)).then(axis(2, degrees.z));
    }
    /// POV-Ray's `matrix <m00, m01, m02, m10, ..., m32>` (row vectors: p' = p M, last row the
    /// translation).
    [[nodiscard]] static Transform matrix(const std::array<double, 12>& m) {
        Transform r;
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k) r.linear[c][k] = m[std::size_t(3 * c + k)];
        r.translation = {m[9], m[10], m[11]};
        return r;
    }
    /// The 12 numbers of POV-Ray's `matrix` for this transform.
    [[nodiscard]] std::array<double, 12> pov_matrix() const {
        std::array<double, 12> m{};
        for (int c = 0; c < 3; ++c)
            for (int k = 0; k < 3; ++k) m[std::size_t(3 * c + k)] = linear[c][k];
        m[9] = translation.x, m[10] = translation.y, m[11] = translation.z;
        return m;
    }

    [[nodiscard]] Transform then(const Transform& next) const {
        return {next.linear * linear, next.linear * translation + next.translation};
    }
    [[nodiscard]] Transform inverse() const {
        const glm::dmat3 inv = glm::inverse(linear);
        return {inv, -(inv * translation)};
    }
    [[nodiscard]] Vector3 point(const Vector3& p) const { return linear * p + translation; }
    [[nodiscard]] Vector3 vector(const Vector3& v) const { return linear * v; }
    [[nodiscard]] bool is_identity() const { return linear == glm::dmat3(1.0) && translation == Vector3(0.0); }

    friend bool operator==(const Transform&, const Transform&) = default;
};

/// The patterns whose values photon evaluates at each point (the rest are averaged with a warning).
inline constexpr std::string_view evaluated_patterns[] = {"checker", "gradient", "bozo",   "spotted", "granite",   "marble",
                                                     "wood",    "agate",    "onion",  "leopard", "radial",    "ripples",
                                                     "waves",   "spherical", "planar", "boxed",  "cylindrical",
                                                     "hexagon", "cells",  "crackle", "bumps",  "dents",  "wrinkles",
                                                     "mandel",  "spiral1", "spiral2", "quilted"};

/// A pigment's pattern as written, with POV-Ray's defaults; build/pigment.hpp makes it a
/// photon::Pigment (texture/pattern.hpp gives each field's meaning).
struct Pigment;

/// An image file a scene names (image_map, bump_map, height_field): where the parser found it
/// (beside the scene or on the include path) and how its samples are decoded.
struct ImageFile {
    std::filesystem::path path;
    std::string written;  ///< the name as the scene writes it
    std::string type;     ///< the keyword before it: png, jpeg, gif, tga, ppm, pgm, tiff, exr, hdr, sys, iff
    /// `gamma G` (decoding gamma), `gamma srgb` (0), or none: the file's own (io/image_file.hpp).
    std::optional<double> gamma;
    SourceLocation at;  ///< where the name is written
};

/// `image_map { FILE ... }` (and `bump_map { FILE ... }`) as photon evaluates it (texture/image_map.hpp gives each field's meaning).
struct ImageMapDesc {
    ImageFile file;
    int map_type = 0;     ///< 0 planar, 1 spherical, 2 cylindrical, 5 torus
    int interpolate = 0;  ///< 0 none, 2 bilinear, 4 normalized distance
    bool once = false;
    double filter_all = 0, transmit_all = 0;
    bool use_index = false;  ///< bump_map's `use_index`: a palette image's indices are the heights
    /// `filter N, F` and `transmit N, T` of palette entries, as written (photon reads a palette
    /// image as its colours: ignored, with a warning).
    std::vector<std::pair<int, double>> filter_index, transmit_index;
};

struct PigmentPattern {
    std::string name;                ///< one of evaluated_patterns, or image_map
    Vector3 gradient{1, 0, 0};       ///< `gradient V`
    double agate_turb = 1;           ///< `agate_turb`
    Vector3 crackle_form{-1, 1, 0};  ///< crackle's `form`
    double crackle_metric = 2, crackle_offset = 0;
    bool crackle_solid = false;
    int fractal_iterations = 1;      ///< mandel's iteration count
    int interior_type = 0, exterior_type = 1;         ///< mandel's `interior` and `exterior` types
    double interior_factor = 1, exterior_factor = 1;  ///< and their factors
    int spiral_arms = 1;                             ///< the number after spiral1 and spiral2
    double quilt_control0 = 1, quilt_control1 = 1;  ///< quilted's `control0` and `control1`
    Vector3 turbulence{0.0};         ///< `turbulence`
    int octaves = 6;
    double omega = 0.5, lambda = 2;
    int noise_generator = 0;         ///< 0: the scene's (POV-Ray's default, 2)
    std::string wave;                ///< `ramp_wave`, `sine_wave`, ...; empty: the pattern's default
    double frequency = 1, phase = 0, exponent = 1;
    /// The colours the value picks: the color_map as written, POV-Ray's default map, or for
    /// checker its two colours at 0 and 1, for hexagon its three at 0, 1/2 and 1.
    std::vector<std::pair<double, Color>> colors;
    /// A pigment_map's patterned entries, one per colour (null where the entry is a colour); empty
    /// when none is patterned. `colors` then holds each entry's average colour.
    std::vector<std::shared_ptr<const Pigment>> nested;
    /// image_map's image and options (`colors` then holds one entry, the filter and transmit
    /// `all` on mid grey, which stands for the image where one colour must).
    std::shared_ptr<const ImageMapDesc> image;

    friend bool operator==(const PigmentPattern&, const PigmentPattern&) = default;
};

/// The patterns a `normal` tilts by a formula of its own (POV-Ray's normal-only patterns; ripples
/// and waves, also pigments, have a normal formula too); any of evaluated_patterns tilts by its slope.
inline constexpr std::string_view normal_patterns[] = {"bumps", "dents", "ripples", "waves", "wrinkles", "quilted"};

/// `normal { PATTERN [AMOUNT] MODIFIERS }` as photon evaluates it: the pattern with its modifiers
/// (`colors` unused), its bump size and accuracy, and its placement, composed like a pigment's.
struct Normal {
    /// name: one of normal_patterns or evaluated_patterns, or bump_map (its image in `image`)
    std::shared_ptr<const PigmentPattern> pattern;
    double amount = 0.5;                            ///< the number after the pattern, or `bump_size`
    double accuracy = 0.02;                         ///< `accuracy` (a slope's tetrahedron size)
    Transform transform;                            ///< pattern space to the object's parent's space
    SourceLocation at;
};

struct Pigment {
    Color color;  ///< POV-Ray's default pigment is black; a patterned pigment's average colour
    /// The pattern photon evaluates at each point; null for one colour everywhere.
    std::shared_ptr<const PigmentPattern> pattern;
    /// The pigment's transformations, then those of its texture and of the object written after
    /// it (POV-Ray moves a texture with its object): pattern space to the object's parent's space.
    Transform transform;
    SourceLocation at;
};

/// `reflection COLOR` or `reflection { [MIN,] MAX [fresnel on] ... }`.
struct Reflection {
    Vector3 min{0.0}, max{0.0};
    bool variable = false;  ///< a MIN was given (reflectance varies with the angle)
    bool fresnel = false;
    double falloff = 1, exponent = 1, metallic = 0;
    SourceLocation at;
};

/// POV-Ray's finish with its defaults. `written` records the items written, with where.
struct Finish {
    Vector3 ambient{0.1};
    double diffuse = 0.6, diffuse_back = 0;
    bool diffuse_albedo = false;  ///< `diffuse albedo F`: POV-Ray scales direct light by (brilliance + 1) / 2
    double brilliance = 1;
    double specular = 0, roughness = 0.05;
    double phong = 0, phong_size = 40;
    double metallic = 0;
    std::optional<Reflection> reflection;
    bool conserve_energy = false;
    Vector3 emission{0.0};
    std::map<std::string, SourceLocation> written;
    SourceLocation at;
};

/// `media { ... }`: POV-Ray's participating media, made the library's Medium (material/medium.hpp)
/// by build/media.hpp. Values as written; POV-Ray's defaults for method 3.
struct MediaDescription {
    Vector3 absorption{0.0}, emission{0.0}, scattering{0.0};
    int scattering_type = 1;  ///< 1 isotropic, 2 Mie hazy, 3 Mie murky, 4 Rayleigh, 5 Henyey-Greenstein
    double eccentricity = 0, extinction = 1;
    /// Densities that multiply, each a pigment (`density { ... }`, its `density_map` read as a
    /// pigment_map, which POV-Ray accepts there too); placed by their own and the media's
    /// transformations, then the object's.
    std::vector<Pigment> density;
    int method = 3, intervals = 1, samples_min = 10, samples_max = 10, aa_level = 3;
    double jitter = 0, aa_threshold = 0.1, confidence = 0.9, variance = 1.0 / 128, ratio = 0.9;
    bool collect = true;
    std::map<std::string, SourceLocation> written;
    SourceLocation at;
};

struct Interior {
    double ior = 1;
    /// POV-Ray's absorption inside (library: Absorption::pov_fade); fade_distance 0 is clear.
    double fade_distance = 0, fade_power = 0;
    Vector3 fade_color{0.0};
    std::vector<MediaDescription> media;  ///< interior media, in order (they add)
    std::map<std::string, SourceLocation> written;
    SourceLocation at;
};

/// Moves the interior's media densities by `step` after their own transformations.
inline void transform_interior(Interior& in, const Transform& step) {
    for (MediaDescription& m : in.media)
        for (Pigment& d : m.density) d.transform = d.transform.then(step);
}

struct Texture {
    Pigment pigment;
    Finish finish;
    std::optional<Normal> normal;  ///< none: the geometric normal shades
    std::map<std::string, SourceLocation> ignored;  ///< parts photon does not render (normal, ...)
    SourceLocation at;
    /// POV-Ray's layered texture (`texture { A } texture { B }`): the layers on top of this one,
    /// bottom first, each without layers of its own. Where a layer's pigment has filter or
    /// transmit, the layers below show through (build/layers.hpp).
    std::vector<Texture> layers;
};

/// Moves a texture by `step` after its own transformations: its pigment, its normal and its layers.
inline void transform_texture(Texture& t, const Transform& step) {
    t.pigment.transform = t.pigment.transform.then(step);
    if (t.normal) t.normal->transform = t.normal->transform.then(step);
    for (Texture& layer : t.layers) transform_texture(layer, step);
}

/// Puts `top` (and the layers it carries) on top of the layers of `bottom`.
inline void add_layer(Texture& bottom, Texture top) {
    std::vector<Texture> above = std::move(top.layers);
    top.layers.clear();
    bottom.layers.push_back(std::move(top));
    for (Texture& t : above) bottom.layers.push_back(std::move(t));
}

/// An object's `photons { }` block (POV-Ray's photon options).
struct ObjectPhotons {
    bool target = false;
    double spacing_multiplier = 1;
    std::optional<bool> reflection, refraction, collect;
    bool pass_through = false;
    SourceLocation at;
};

struct AreaLight {
    Vector3 axis1{0.0}, axis2{0.0};
    int size1 = 1, size2 = 1;
    std::optional<int> adaptive;  ///< POV-Ray's `adaptive N`; none: every emitter
    bool jitter = false, circular = false, orient = false;
    SourceLocation at;
};

struct Spotlight {
    double radius = 30, falloff = 45, tightness = 0;  ///< half-angles in degrees
    Vector3 point_at{0, 0, 1};
    SourceLocation at;
};

struct Object;

/// A `light_source` as POV-Ray reads it: its colour is POV-Ray's brightness, not watts.
struct LightSource {
    Vector3 position{0.0};
    Color color;
    std::optional<Spotlight> spotlight;
    std::optional<AreaLight> area;
    double fade_distance = 0, fade_power = 0;
    bool shadowless = false, looks_like = false;
    /// The `looks_like` object, as written (placed at the light by the build step).
    std::shared_ptr<const Object> looks_like_object;
    /// POV-Ray's `parallel`: every ray along point_at - position (POV-Ray's default point_at <0,0,1>).
    bool parallel = false;
    Vector3 point_at{0, 0, 1};
    bool media_interaction = true, media_attenuation = false;  ///< POV-Ray's defaults
    /// The light's `photons { }` block: POV-Ray shoots reflected and refracted photons by default.
    bool photon_reflection = true, photon_refraction = true, photon_area_light = false;
    std::map<std::string, SourceLocation> written;
    SourceLocation at;
};

struct Object;

struct SphereShape {
    Vector3 center{0.0};
    double radius = 1;
};
struct BoxShape {
    Vector3 corner1{0.0}, corner2{0.0};
};
/// The surface dot(p, normal / |normal|) = distance.
struct PlaneShape {
    Vector3 normal{0, 1, 0};
    double distance = 0;
};
struct TriangleShape {
    std::array<Vector3, 3> vertices{};
};
/// `cylinder { base, cap, radius [open] }`: radius > 0, base and cap apart.
struct CylinderShape {
    Vector3 base{0.0}, cap{0, 1, 0};
    double radius = 1;
    bool open = false;
};
/// `cone { base, base_radius, cap, cap_radius [open] }`: radii >= 0, one > 0, base and cap apart.
/// POV-Ray reads equal radii (within 1e-10) as a cylinder; so does the build step.
struct ConeShape {
    Vector3 base{0.0};
    double base_radius = 1;
    Vector3 cap{0, 1, 0};
    double cap_radius = 0;
    bool open = false;
};
/// `disc { center, normal, radius [, hole_radius] }`: 0 <= hole_radius < radius, normal not zero.
struct DiscShape {
    Vector3 center{0.0}, normal{0, 1, 0};
    double radius = 1, hole_radius = 0;
};
/// `torus { major, minor }`: around the y axis at the origin, both radii > 0.
struct TorusShape {
    double major = 1, minor = 0.25;
};
/// `quadric { <A, B, C>, <D, E, F>, <G, H, I>, J }`: A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x +
/// H y + I z + J = 0, solid where the left side is <= 0. Some of A to I is not zero.
struct QuadricShape {
    Vector3 squares{1, 1, 1}, mixed{0.0}, linear{0.0};
    double constant = -1;
};
/// `polygon { N, points }`: the points as written (2D ones with z = 0), each loop closed by
/// repeating its first point (the last one may stay open); in one plane, not all on one line.
struct PolygonShape {
    std::shared_ptr<const std::vector<Vector3>> points;
};
/// The loops of a polygon's points, POV-Ray's way: a loop ends at the point that repeats its first
/// (within 1e-10 in every coordinate), the next point starts the next loop; the last loop is
/// closed even when its first point is not repeated.
[[nodiscard]] inline std::vector<std::vector<Vector3>> polygon_loops(const std::vector<Vector3>& points) {
    std::vector<std::vector<Vector3>> loops;
    for (const Vector3& p : points) {
        if (loops.empty() || loops.back().empty()) {
            if (loops.empty()) loops.emplace_back();
            loops.back().push_back(p);
            continue;
        }
        const Vector3 first = loops.back().front();
        if (std::abs(p.x - first.x) < 1e-10 && std::abs(p.y - first.y) < 1e-10 && std::abs(p.z - first.z) < 1e-10)
            loops.emplace_back();  // closed: the next point starts a new loop
        else
            loops.back().push_back(p);
    }
    if (!loops.empty() && loops.back().empty()) loops.pop_back();
    return loops;
}
/// One curve of a prism's outline: a Bezier curve of degree 1 (a line), 2 or 3 by its control
/// points (the first degree + 1 of `control`), in the outline's plane.
struct OutlineCurve {
    std::array<glm::dvec2, 4> control{};
    int degree = 1;
};
/// `prism { ... }` after POV-Ray's reading of its points (parser/prism.hpp): closed contours of
/// curves in the xz plane (a curve's (u, v) is x, z), filled by the even-odd rule, swept along y
/// from height1 to height2 (height1 < height2). Conic: the outline is scaled by the height.
struct PrismShape {
    enum class Sweep : std::uint8_t { linear, conic };
    std::shared_ptr<const std::vector<std::vector<OutlineCurve>>> contours;
    double height1 = 0, height2 = 1;
    Sweep sweep = Sweep::linear;
    bool open = false;
};
/// `quartic { <35> }`, `cubic { <20> }`, `poly { N, <...> }`, `polynomial { N, xyz(i, j, k): c }`:
/// p(x, y, z) = 0 of order 2 to 35, solid where p < 0, coefficients in POV-Ray's order (x's
/// power descending, then y's, then z's: photon::polynomial_term_powers).
struct PolynomialShape {
    std::string keyword = "poly";  ///< as written
    int order = 2;
    std::shared_ptr<const std::vector<double>> coefficients;
    /// A `bounded_by` sphere or box in the polynomial's own coordinates: POV-Ray tests each ray
    /// against it first, and a ray that misses it misses the surface (also outside the bound).
    struct Gate {
        bool sphere = true;
        Vector3 center{0.0};
        double radius = 0;
        Vector3 min{0.0}, max{0.0};
    };
    std::optional<Gate> gate;
};
/// `superellipsoid { <e, n> }`: POV-Ray's, in the cube [-1, 1]^3 (e and n positive).
struct SuperellipsoidShape {
    double e = 0.5, n = 0.5;
};
/// `lathe { ... }` after POV-Ray's reading of its points (parser/revolved.hpp): the profile's
/// curves in the (radius, height) plane, turned around the y axis.
struct LatheShape {
    std::shared_ptr<const std::vector<OutlineCurve>> profile;
};
/// `sor { N, points [open] }`: POV-Ray's points as (radius, height), checked as POV-Ray checks
/// them (at least four, radii not negative, the inner heights rising).
struct SorShape {
    std::shared_ptr<const std::vector<glm::dvec2>> points;
    bool open = false;
};
/// `blob { ... }` (parser/blob.hpp): POV-Ray's components, each with its own transformation,
/// and the threshold the summed field must exceed (build/blob_of.hpp makes the library's Blob).
struct BlobShape {
    struct Component {
        bool cylinder = false;
        Vector3 a{0.0}, b{0.0};  ///< the sphere's centre, or the cylinder's ends
        double radius = 1, strength = 1;
        Transform transform;  ///< the component's own, inside the blob
    };
    std::shared_ptr<const std::vector<Component>> components;
    double threshold = 1;
};
/// A TrueType font named in a text object, found by the parser (beside the scene, then on the
/// include path) and read by the build step (font_files.hpp), as mesh files are.
struct FontFile {
    std::filesystem::path path;  ///< where the parser found it
    std::string written;         ///< the name as the scene writes it
    SourceLocation at;           ///< where the name is written
};
/// `text { ttf "font.ttf" "string" thickness, offset }`: the string's glyphs, each a prism of its
/// outline (em units, baseline at y = 0, the first glyph's left edge at x = 0) from z = 0 to
/// z = thickness, placed by POV-Ray's advance, kerning and `offset` per glyph.
struct TextShape {
    FontFile font;
    std::string text;  ///< UTF-8
    double thickness = 1;
    Vector3 offset{0.0};
};
/// `height_field { FILE [smooth] [water_level F] }`: the image's heights over the unit square
/// (geometry/height_field.hpp), read in the build step.
struct HeightFieldShape {
    ImageFile file;
    bool smooth = false;
    double water_level = 0;
};
/// An OBJ file named in a mesh (`mesh { obj "file.obj" }`). The parser only records it; the build
/// step reads it (mesh_files.hpp), so that reading a scene never opens a mesh file.
struct MeshFile {
    std::filesystem::path path;  ///< resolved against the directory of the scene file that names it
    std::string written;         ///< the name as the scene writes it
    SourceLocation at;           ///< where the name is written
};
struct MeshShape {
    std::shared_ptr<const std::vector<std::array<Vector3, 3>>> triangles;  ///< written in the mesh
    std::optional<MeshFile> file;  ///< an OBJ file whose triangles come before them
};
/// `union`: the children, each with its own modifiers. Children are shared, not copied, when a
/// declared object is used again (`object { Name }`), so repeated use stays cheap.
struct UnionShape {
    std::vector<std::shared_ptr<const Object>> children;
};

/// POV-Ray's CSG: `difference` (the first child minus the others), `intersection` (inside every
/// child) and `merge` (a union without inner surfaces), children shared as in UnionShape. Built
/// as one library Csg object (build/scene_builder.hpp) whose leaves keep their own textures.
struct CsgShape {
    enum class Operation : std::uint8_t { difference, intersection, merge };
    Operation operation = Operation::merge;
    std::vector<std::shared_ptr<const Object>> children;
};

/// An object photon reads but cannot render (a difference, a blob, ...) or that has no surface: kept in the
/// description so that the build skips it and `object { Name }` of a declared one warns again.
struct SkippedShape {
    std::string keyword;  ///< POV-Ray's keyword, `blob`
    std::string why;      ///< why, when not "photon has no such shape yet" (a cylinder of radius 0)
};

using Shape = std::variant<SphereShape, BoxShape, PlaneShape, TriangleShape, MeshShape, UnionShape, LightSource,
                           SkippedShape, CsgShape, CylinderShape, ConeShape, DiscShape, TorusShape, QuadricShape,
                           PolygonShape, PrismShape, TextShape, PolynomialShape, SuperellipsoidShape, LatheShape,
                           SorShape, HeightFieldShape, BlobShape>;

/// One object statement with its modifiers. Modifiers missing here come from the enclosing
/// union (texture, interior, photons) when there is one.
struct Object {
    Shape shape;
    std::optional<Texture> texture;
    std::optional<Interior> interior;
    std::optional<ObjectPhotons> photons;
    bool no_shadow = false;
    /// POV-Ray's `inverse`: inside and outside swap (for CSG, and for refraction: a glass object
    /// inverted is a bubble of air in glass).
    bool inverse = false;
    /// POV-Ray's `hollow`: kept for export. photon's fog and atmospheric media stay out of
    /// transmissive objects whatever it says; a hollow one inside media warns (build).
    std::optional<bool> hollow;
    Transform transform;         ///< applied to the shape (and to every child of a union or CSG)
    std::size_t primitives = 1;  ///< shapes and triangles below this object, for the size bound
    /// Texture for the parts that have none, here or in an enclosing union: the `#default`
    /// texture when this top-level statement ended (POV-Ray's rule).
    std::optional<Texture> default_texture;
    std::map<std::string, SourceLocation> ignored;  ///< modifiers photon does not use (no_image, ...)
    /// POV-Ray's `clipped_by`: only the parts of this object's surface inside every one of these
    /// show. Each is placed in this object's space (its transform holds the inverse of the
    /// object's transformations written before `clipped_by`, so that the object's transform
    /// moves it as POV-Ray moves the clip: by the transformations written after).
    std::vector<std::shared_ptr<const Object>> clipped_by;
    SourceLocation clipped_at;  ///< where `clipped_by` was written
    /// POV-Ray's `bounded_by`, placed as clipped_by (kept for `clipped_by { bounded_by }`).
    std::vector<std::shared_ptr<const Object>> bounded_by;
    /// Where a `bounded_by` was written that photon could not show to hold the whole object:
    /// the builder warns where POV-Ray keeps such a bound (see pov_keeps_bound).
    std::optional<SourceLocation> bound_may_cut;
    SourceLocation at;
};

/// POV-Ray's name of a CSG operation.
[[nodiscard]] inline const char* keyword(CsgShape::Operation op) noexcept {
    constexpr const char* names[] = {"difference", "intersection", "merge"};
    return names[static_cast<int>(op)];
}

/// POV-Ray's keyword for the shape of an object (`sphere`, `union`, `light_source`, ...).
[[nodiscard]] inline const char* keyword(const Shape& s) noexcept {
    constexpr const char* names[] = {"sphere",       "box", "plane", "triangle", "mesh", "union",
                                     "light_source", "",    "",      "cylinder", "cone", "disc", "torus",
                                     "quadric",      "polygon", "prism", "text", "poly", "superellipsoid", "lathe", "sor",
                                     "height_field", "blob"};
    static_assert(std::size(names) == std::variant_size_v<Shape>, "a keyword for every shape");
    if (const auto* skipped = std::get_if<SkippedShape>(&s)) return skipped->keyword.c_str();
    if (const auto* csg = std::get_if<CsgShape>(&s)) return keyword(csg->operation);
    if (const auto* poly = std::get_if<PolynomialShape>(&s)) return poly->keyword.c_str();
    return names[s.index()];
}

/// Whether POV-Ray 3.7 keeps a `bounded_by` on a top-level object of this shape. With its
/// default Remove_Bounds=on, Parser::Link_To_Frame removes the bound ("Unnecessary bounding
/// object removed") from everything but unions, intersections, differences, merges, polynomial
/// surfaces, text and quadrics (those without automatic bounds; photon counts them all as kept).
/// A removed bound changes nothing, in POV-Ray as in photon. Inside a CSG every bound is kept.
[[nodiscard]] inline bool pov_keeps_bound(const Shape& shape) {
    if (const auto* skipped = std::get_if<SkippedShape>(&shape))
        return skipped->keyword == "poly" || skipped->keyword == "cubic" || skipped->keyword == "quartic" ||
               skipped->keyword == "polynomial";
    return std::holds_alternative<UnionShape>(shape) || std::holds_alternative<CsgShape>(shape) ||
           std::holds_alternative<TextShape>(shape) || std::holds_alternative<QuadricShape>(shape) ||
           std::holds_alternative<PolynomialShape>(shape);
}

/// A camera as written; build.hpp resolves it in POV-Ray's order (see resolve_camera).
struct CameraDescription {
    /// POV-Ray's camera type keyword, "cylinder 1" to "cylinder 4" with the cylinder's number.
    std::string type = "perspective";
    Vector3 location{0.0}, direction{0, 0, 1}, up{0, 1, 0}, sky{0, 1, 0};
    std::optional<Vector3> right;  ///< default <image width / image height, 0, 0>
    std::optional<Vector3> look_at;
    std::optional<double> angle;           ///< horizontal field of view in degrees (0: orthographic's bare `angle`)
    std::optional<double> vertical_angle;  ///< spherical's second angle
    std::optional<double> aperture;        ///< focal blur, with blur_samples
    std::optional<Vector3> focal_point;
    std::optional<unsigned> blur_samples;
    Transform transform;
    std::map<std::string, SourceLocation> written;
    SourceLocation at;
};

/// POV-Ray's `global_settings { photons { } }` (its caustic photons).
struct PovPhotons {
    std::optional<std::uint64_t> count;
    std::optional<double> spacing;
    std::optional<unsigned> gather_min, gather_max;
    std::optional<double> radius;
    std::optional<unsigned> max_trace_level;
    std::map<std::string, SourceLocation> ignored;
    SourceLocation at;
};

/// A render setting's value as written: a whole number, a real, or a name (a render mode's).
using SettingValue = std::variant<std::uint64_t, double, std::string>;

/// One render setting of the settings table (settings_table.hpp) as the file writes it.
struct WrittenSetting {
    SettingValue value;
    SourceLocation at;  ///< the setting's keyword
};

struct GlobalSettings {
    std::optional<double> assumed_gamma;
    Vector3 ambient_light{1.0};
    bool radiosity = false;
    std::optional<PovPhotons> photons;
    /// The settings of the settings table (photon's own items, inside `#ifdef (photon_version)`,
    /// and POV-Ray's max_trace_level and adc_bailout), by the RenderSettings field each one sets
    /// ("samples_per_pixel", "global_estimate.k").
    std::map<std::string, WrittenSetting> render;
    std::map<std::string, SourceLocation> written;  ///< every item, photon's own ones included
    SourceLocation at;
};

/// `sky_sphere { pigment {...} ... [emission COLOR] TRANSFORMATIONS }`: the sky seen and lit by,
/// each pigment evaluated at the unit direction moved back by `transform` (as POV-Ray does).
struct SkySphere {
    std::vector<Pigment> pigments;  ///< bottom first, as written (the last is on top)
    Vector3 emission{1.0};          ///< POV-Ray 3.7's multiplier of every pigment's colour
    Transform transform;            ///< the sky_sphere's own transformations, after each pigment's
    SourceLocation at;
};

/// `fog { ... }`: POV-Ray's fog, made the library's Fog (scene/fog.hpp) as written.
struct FogDescription {
    int type = 1;           ///< fog_type: 1 constant, 2 ground
    double distance = 0.0;  ///< 0: POV-Ray ignores the fog
    Color color;
    double altitude = 0.0, offset = 0.0;  ///< fog_alt, fog_offset (ground fog)
    Vector3 up{0.0, 1.0, 0.0};            ///< turned by the fog's rotate, scale and matrix
    std::optional<Vector3> turbulence;    ///< set by `turbulence` (octaves, omega, lambda alone start it at 0)
    int octaves = 6;
    double omega = 0.5, lambda = 2.0, turb_depth = 0.5;
    SourceLocation at;
};

/// A whole scene file, evaluated.
struct SceneDescription {
    std::optional<double> version;  ///< from `#version`
    std::optional<CameraDescription> camera;
    std::optional<Color> background;      ///< `background { COLOR }`, the last one written
    std::optional<SkySphere> sky_sphere;  ///< the last one written
    std::vector<FogDescription> fogs;     ///< every one written, in order (POV-Ray composes them all)
    std::vector<MediaDescription> media;  ///< atmospheric media, every one written, in order
    std::vector<Object> objects;  ///< top-level statements, lights included, in file order
    GlobalSettings settings;
    std::vector<std::shared_ptr<const SourceFile>> files;  ///< the scene file and every include, in reading order
    SourceLocation at;                                     ///< the start of the scene file
};

}  // namespace photon::dsl
