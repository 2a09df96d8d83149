// SPDX-License-Identifier: MIT
#pragma once
// From a SceneDescription to the library's objects: DefaultScene<S>, PinholeCamera<S> and
// RenderSettings, reading the mesh files the scene names (mesh_files.hpp). This is where
// POV-Ray's meaning becomes physics: the light-unit rule (a light's colour and fade give its
// radiant intensity), the finish-to-reflectance rule, the camera in POV-Ray's order of
// application. Library constructors that reject a value (std::invalid_argument) are reported as
// dsl::Error at the place the value was written.

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <photon/photon.hpp>

#include "description.hpp"
#include "diagnostics.hpp"
#include "mesh_files.hpp"
#include "physical_ranges.hpp"
#include "settings_table.hpp"
#include "value.hpp"

namespace photon::dsl {

/// Settings given outside the scene file (the command line), by the settings table's key
/// ("samples_per_pixel", "global_estimate.k", settings_table.hpp); each one overrides the file.
using SettingsOverrides = std::map<std::string, SettingValue, std::less<>>;

struct BuildOptions {
    SettingsOverrides overrides;
    DiagnosticSink diagnostics;
    /// Objects and mesh triangles in the scene, the mesh files' triangles counted for every use
    /// (the parser bounds the rest with ParseOptions::max_primitives, the same default).
    std::size_t max_primitives = 10'000'000;
};

template <Scalar S>
struct BuiltScene {
    DefaultScene<S> scene;
    PinholeCamera<S> camera;
    RenderSettings settings;
};

/// Reports a warning once per place and message.
class Warnings {
public:
    explicit Warnings(DiagnosticSink sink) : sink_(std::move(sink)) {}
    void operator()(const SourceLocation& at, const std::string& message, std::string kind = {},
                    std::string keyword = {}) {
        if (!seen_.insert(at.str() + '\x1f' + message).second) return;
        if (sink_) sink_({Severity::warning, at, message, std::move(kind), std::move(keyword)});
    }

private:
    DiagnosticSink sink_;
    std::set<std::string> seen_;
};

/// POV-Ray 3.7's spotlight intensity relative to its axis (Attenuate_Light): cos^tightness in
/// the front hemisphere, times a smooth step from cos(falloff) up to cos(radius) when
/// cos(radius) > 0. A negative or 90-degree radius therefore means "no soft edge", the cosine
/// lobe of `radius -90 falloff 90 tightness 1` in POV-Ray's radiosity Cornell box.
[[nodiscard]] inline double pov_spotlight_profile(double cos_theta, const Spotlight& sp) {
    constexpr double deg = 3.14159265358979323846 / 180.0;
    if (!(cos_theta > 0)) return 0;
    double a = std::pow(cos_theta, sp.tightness);
    const double cos_radius = std::cos(sp.radius * deg), cos_falloff = std::cos(sp.falloff * deg);
    if (cos_radius > 0 && cos_theta < cos_radius) {
        if (cos_theta < cos_falloff) return 0;  // POV-Ray's cubic_spline: 0 below low, 1 from high
        const double t = (cos_theta - cos_falloff) / (cos_radius - cos_falloff);
        a *= (3 - 2 * t) * t * t;
    }
    return a;
}

/// Half-angle in degrees of the sharp cone that carries a POV-Ray spotlight's power at its axial
/// intensity: 1 - cos(half) = the integral of the profile over cos(theta) in [0, 1] (midpoint
/// rule; the profile is smooth but for at most two kinks, so 2^14 points are within 1e-6).
[[nodiscard]] inline double pov_spotlight_cone_half_angle(const Spotlight& sp) {
    constexpr int n = 1 << 14;
    double integral = 0;
    for (int i = 0; i < n; ++i) integral += pov_spotlight_profile((i + 0.5) / n, sp);
    integral /= n;
    return std::acos(std::clamp(1 - integral, -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
}

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

/// Radiant intensity (W/sr per channel) of a POV-Ray light. With `fade_power 2` and
/// `fade_distance D`, POV-Ray's brightness at distance d >> D is colour * 2 D^2 / d^2, which is
/// a point light of intensity I = 2 pi D^2 colour (docs/scene-language.md). Without a fade,
/// POV-Ray's light does not fall off; photon's light does, and matches POV-Ray at distance 1:
/// I = pi colour, with a warning.
[[nodiscard]] inline Vector3 radiant_intensity(const LightSource& l, Warnings* warn = nullptr) {
    constexpr double pi_d = 3.14159265358979323846;
    const auto item = [&](const char* k) {
        const auto it = l.written.find(k);
        return it != l.written.end() ? it->second : l.at;
    };
    const double d = l.fade_distance;
    if (d > 0 && l.fade_power == 2) return 2 * pi_d * d * d * l.color.rgb;
    if (d > 0 && l.fade_power > 0) {
        if (warn)
            (*warn)(item("fade_power"),
                    "fade_power " + format_number(l.fade_power) +
                        ": photon's lights fall off as 1/d^2; the colour is read as for fade_power 2 "
                        "(intensity 2 pi fade_distance^2 colour)");
        return 2 * pi_d * d * d * l.color.rgb;
    }
    if (warn)
        (*warn)(l.at,
                "light_source without `fade_distance` and `fade_power 2`: POV-Ray's light does not fall off with "
                "distance, photon's falls off as 1/d^2; photon reads the colour as the intensity pi * colour W/sr "
                "(POV-Ray's brightness at distance 1). Write `fade_distance D fade_power 2` with colour "
                "I / (2 pi D^2) for an intensity I");
    return pi_d * l.color.rgb;
}

/// POV-Ray's texture and interior as photon's material: diffuse albedo = diffuse * pigment *
/// (1 - filter - transmit); transmission = filter * pigment + transmit; mirror reflectance from
/// `reflection`; `reflection { 0, 1 fresnel on }` with `conserve_energy` makes Fresnel glass;
/// phong and phong_size carry over. Finish items photon does not render are reported to `warn`,
/// as is a surface reflecting more than it receives, which is scaled down to conserve energy
/// (reported at its finish, or at `object` for a default texture, which was written nowhere).
template <Scalar S>
[[nodiscard]] MaterialParams<S> material_params(const Texture& tex, const Interior* interior,
                                                const GlobalSettings& global, Warnings& warn,
                                                const SourceLocation& object = {}) {
    const Finish& f = tex.finish;
    const SourceLocation at = f.at.known() ? f.at : (tex.at.known() ? tex.at : object);
    auto item = [&](const char* k) {
        const auto it = f.written.find(k);
        return it != f.written.end() ? it->second : at;
    };
    const double ior = interior ? interior->ior : 1.0;
    const SourceLocation pigment_at = tex.pigment.at.known() ? tex.pigment.at : at;
    const Clamped<Color> physical = physical_pigment(tex.pigment.color);
    if (!physical.message.empty()) warn(pigment_at, physical.message, "approximated pigment", "pigment");
    const Color& pc = physical.value;
    const double opacity = std::max(0.0, 1.0 - pc.filter - pc.transmit);
    Vector3 diffuse = f.diffuse * pc.rgb * opacity;
    Vector3 transmission = pc.filter * pc.rgb + Vector3(pc.transmit);
    Vector3 specular(0.0);
    bool fresnel = false;
    if (f.reflection) {
        const Reflection& r = *f.reflection;
        if (r.fresnel && transmission != Vector3(0.0)) {
            fresnel = true;
            if (r.min != Vector3(0.0) || r.max != Vector3(1.0))
                warn(r.at,
                     "photon's Fresnel glass reflects F(angle, ior) exactly; the range of `reflection { min, max "
                     "fresnel }` is read as { 0, 1 }");
            if (!f.conserve_energy)
                warn(r.at,
                     "`fresnel on` without `conserve_energy`: POV-Ray adds the reflection on top of the transmitted "
                     "light, photon takes it out of it (as with conserve_energy)");
        } else if (r.fresnel) {
            const double f0 = ((ior - 1) / (ior + 1)) * ((ior - 1) / (ior + 1));
            specular = r.min + (r.max - r.min) * f0;
            warn(r.at, "`fresnel` on an opaque surface: photon's mirror reflects F(0) = " + format_number(f0) +
                           " at every angle (POV-Ray varies it with the angle)");
        } else {
            specular = r.max;
            if (r.variable && r.min != r.max)
                warn(r.at,
                     "`reflection { min, max }` varies with the angle in POV-Ray; photon's mirror reflects the "
                     "maximum at every angle");
            if (f.conserve_energy) transmission *= Vector3(1.0) - specular;
        }
        if (r.falloff != 1 || r.exponent != 1 || r.metallic != 0)
            warn(r.at, "reflection `falloff`, `exponent` and `metallic` are ignored by photon", "approximated finish", "reflection");
    }
    const Vector3 ambient = f.ambient * global.ambient_light;
    if (ambient != Vector3(0.0))
        warn(item("ambient"),
             std::string(f.written.count("ambient") ? "`ambient`" : "POV-Ray's default `ambient 0.1`") +
                 " is ignored: photon has no ambient light. Write `finish { ambient 0 }` or "
                 "`global_settings { ambient_light 0 }`",
             "approximated finish", "ambient");
    if (f.brilliance != 1)
        warn(item("brilliance"), "`brilliance " + format_number(f.brilliance) +
                                     "` is ignored: photon's diffuse reflection is Lambertian (brilliance 1)",
             "approximated finish", "brilliance");
    if (f.specular != 0)
        warn(item("specular"),
             "`specular` (POV-Ray's Blinn highlight) is ignored by photon: use `phong` for a highlight", "approximated finish",
             "specular");
    if (f.emission != Vector3(0.0))
        warn(item("emission"), "`emission` is ignored: only light sources emit light in photon", "approximated finish", "emission");
    if (f.diffuse_back != 0)
        warn(item("diffuse_back"), "the back-side value of `diffuse` is ignored by photon", "approximated finish", "diffuse");
    if (f.metallic != 0) warn(item("metallic"), "`metallic` is ignored by photon", "approximated finish", "metallic");
    for (const char* k : {"irid", "crand"})
        if (f.written.count(k)) warn(item(k), std::string("`") + k + "` is ignored by photon", "approximated finish", k);

    // POV-Ray renders a surface that reflects more than it receives; photon, which conserves
    // energy, scales its reflectances down (keeping their hue) and says so.
    constexpr const char* channel[] = {"red", "green", "blue"};
    int worst = 0;
    for (int c = 1; c < 3; ++c)
        if (diffuse[c] + specular[c] + transmission[c] > diffuse[worst] + specular[worst] + transmission[worst]) worst = c;
    const double sum = diffuse[worst] + specular[worst] + transmission[worst];
    if (sum > 1 + 1e-9) {
        warn(at,
             std::string("the surface reflects more light than it receives: diffuse ") + format_number(diffuse[worst]) +
                 " + reflection " + format_number(specular[worst]) + " + transmission " +
                 format_number(transmission[worst]) + " = " + format_number(sum) + " > 1 in the " + channel[worst] +
                 " channel; photon scales its reflectances by 1/" + format_number(sum) + " to conserve energy",
             "approximated finish", "finish");
        diffuse /= sum, specular /= sum, transmission /= sum;
    }
    MaterialParams<S> p;
    p.diffuse = Rgb<S>(diffuse);
    p.specular = Rgb<S>(specular);
    p.transmission = Rgb<S>(transmission);
    p.ior = S(ior);
    p.fresnel = fresnel;
    const Clamped<double> phong_size = physical_phong_size(f.phong, f.phong_size);
    if (!phong_size.message.empty()) warn(item("phong_size"), phong_size.message, "approximated finish", "phong_size");
    p.phong = S(f.phong);
    p.phong_exponent = S(phong_size.value);
    return p;
}

/// Render settings: the library's defaults, then POV-Ray's photons block, then the file's items of
/// the settings table, then `overrides` (each one setting through the table). Throws dsl::Error if
/// a file's value is out of range, std::invalid_argument naming the option if an override is.
[[nodiscard]] inline RenderSettings render_settings(const SceneDescription& desc, const SettingsOverrides& o,
                                                    Warnings& warn) {
    RenderSettings s;
    const GlobalSettings& g = desc.settings;
    if (g.photons) {
        const PovPhotons& ph = *g.photons;
        if (ph.count)
            s.caustic_photons = std::size_t(*ph.count);
        else if (ph.spacing)
            warn(ph.at,
                 "photons `spacing` has no photon equivalent: photon shoots a number of photons (`count`, or "
                 "`caustic_photons` in photon's own settings)");
        if (ph.gather_max) s.caustic_estimate.k = *ph.gather_max;
        if (ph.radius) s.caustic_estimate.max_radius = float(*ph.radius);
        if (ph.max_trace_level) s.max_photon_depth = *ph.max_trace_level;
    }
    for (const auto& [key, written] : g.render) {
        try {  // checked where written already, unless the description was made by a program
            const RenderSetting* setting = find_setting(key);
            std::string keyword = "`";
            keyword.append(setting ? setting->keyword : key).push_back('`');
            apply_setting(key, written.value, s, keyword);
        } catch (const std::invalid_argument& e) {
            throw Error(written.at, e.what());
        }
    }
    if (!g.render.count("shadow_samples")) {
        // POV-Ray's area_light N1 x N2 grid is its number of shadow rays per light.
        unsigned most = 0;
        std::function<void(const Object&)> visit = [&](const Object& obj) {
            if (const auto* l = std::get_if<LightSource>(&obj.shape); l && l->area)
                most = std::max(most, unsigned(l->area->size1 * l->area->size2));
            if (const auto* u = std::get_if<UnionShape>(&obj.shape))
                for (const auto& c : u->children) visit(*c);
        };
        for (const Object& obj : desc.objects) visit(obj);
        if (most > 1) s.shadow_samples = most;
    }
    for (const auto& [key, value] : o) apply_setting(key, value, s);  // std::invalid_argument names the option
    try {
        validate(s);
    } catch (const std::invalid_argument& e) {
        throw Error(g.at.known() ? g.at : desc.at, e.what());
    }
    return s;
}

namespace detail {

template <Scalar S>
Affine<S> to_affine(const Transform& t) {
    Affine<S> a;
    a.linear = glm::mat<3, 3, S, glm::defaultp>(t.linear);
    a.translation = Vec3<S>(t.translation);
    return a;
}

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

template <Scalar S>
class Builder {
public:
    Builder(const SceneDescription& desc, Warnings& warn, std::size_t max_primitives)
        : desc_(desc), warn_(warn), max_primitives_(max_primitives),
          mesh_files_([&warn](const SourceLocation& at, const std::string& m) { warn(at, m); }) {}

    void add_all(DefaultScene<S>& scene) {
        scene_ = &scene;
        for (const Object& o : desc_.objects) add(o, Inherited{});
        if (scene.objects().empty() && skipped_ > 0)
            warn_(desc_.at,
                  "nothing renders: photon skipped every object of the scene (" + std::to_string(skipped_) +
                      (skipped_ == 1 ? " object" : " objects") + " it has no shape for)",
                  "nothing renders", "");
        if (scene.lights().empty()) warn_(desc_.at, "the scene has no light_source: the image will be black");
    }

    /// Reads every mesh file the scene names, first, so that a missing one is the build's first
    /// message (as when the parser read them).
    void read_files() {
        std::function<void(const Object&)> visit = [&](const Object& o) {
            if (const auto* m = std::get_if<MeshShape>(&o.shape); m && m->file) (void)mesh_files_.triangles(*m->file);
            if (const auto* u = std::get_if<UnionShape>(&o.shape))
                for (const auto& child : u->children) visit(*child);
        };
        for (const Object& o : desc_.objects) visit(o);
    }

    /// Where each object of the scene was written (a mesh or a union's objects share one place).
    [[nodiscard]] const std::vector<SourceLocation>& object_locations() const noexcept { return object_at_; }

private:
    struct Inherited {
        const Texture* texture = nullptr;
        const Interior* interior = nullptr;
        const ObjectPhotons* photons = nullptr;
        bool no_shadow = false;
        Transform transform;
    };

    void add(const Object& o, const Inherited& parent) {
        const Texture* inherited =
            parent.texture ? parent.texture : (o.default_texture ? &*o.default_texture : nullptr);
        Inherited mine{o.texture ? &*o.texture : inherited, o.interior ? &*o.interior : parent.interior,
                       o.photons ? &*o.photons : parent.photons, o.no_shadow || parent.no_shadow,
                       o.transform.then(parent.transform)};
        if (const auto* l = std::get_if<LightSource>(&o.shape)) return add_light(*l, mine.transform, o.at);
        if (const auto* u = std::get_if<UnionShape>(&o.shape)) {
            for (const auto& child : u->children) add(*child, mine);
            return;
        }
        if (std::holds_alternative<SkippedShape>(o.shape)) {  // the parser warned at its place
            ++skipped_;
            return;
        }
        try {
            const MaterialId material = material_for(mine, o);
            ObjectOptions options;
            options.casts_shadow = !mine.no_shadow;
            if (mine.photons) {
                const ObjectPhotons& ph = *mine.photons;
                options.caustic_target = ph.target ? CausticTarget::on : CausticTarget::off;
                if (ph.target && (ph.reflection == false || ph.refraction == false))
                    warn_(ph.at,
                          "photons `reflection off` / `refraction off` are ignored: photon follows every caustic "
                          "photon path of a target");
                if (ph.collect == false && scene_->materials()[material].has_diffuse())
                    warn_(ph.at, "photons `collect off` is ignored: photon stores photons on every diffuse surface");
                if (ph.pass_through) warn_(ph.at, "photons `pass_through` is ignored by photon");
            }
            const Transform& t = mine.transform;
            std::visit([&](const auto& shape) { add_shape(shape, t, material, options); }, o.shape);
            object_at_.resize(scene_->objects().size(), o.at);
        } catch (const std::invalid_argument& e) {
            throw Error(o.at, e.what());
        }
    }

    void add_shape(const SphereShape& s, const Transform& t, MaterialId m, ObjectOptions opt) {
        if (const auto scale = similarity_scale(t.linear))
            scene_->add(Sphere<S>(Vec3<S>(t.point(s.center)), S(s.radius * *scale)), m, opt);
        else
            scene_->add(Transformed<Sphere<S>>(Sphere<S>(Vec3<S>(s.center), S(s.radius)), to_affine<S>(t)), m, opt);
    }
    void add_shape(const BoxShape& b, const Transform& t, MaterialId m, ObjectOptions opt) {
        if (keeps_axes(t.linear))
            scene_->add(Box<S>(Vec3<S>(t.point(b.corner1)), Vec3<S>(t.point(b.corner2))), m, opt);
        else
            scene_->add(Transformed<Box<S>>(Box<S>(Vec3<S>(b.corner1), Vec3<S>(b.corner2)), to_affine<S>(t)), m, opt);
    }
    void add_shape(const PlaneShape& p, const Transform& t, MaterialId m, ObjectOptions opt) {
        const Vector3 n = glm::normalize(p.normal);
        const Vector3 world_n = glm::normalize(glm::transpose(glm::inverse(t.linear)) * n);
        const Vector3 point = t.point(n * p.distance);
        scene_->add(Plane<S>(Vec3<S>(world_n), S(glm::dot(point, world_n))), m, opt);
    }
    void add_shape(const TriangleShape& tri, const Transform& t, MaterialId m, ObjectOptions opt) {
        scene_->add(Triangle<S>(Vec3<S>(t.point(tri.vertices[0])), Vec3<S>(t.point(tri.vertices[1])),
                                Vec3<S>(t.point(tri.vertices[2]))),
                    m, opt);
    }
    void add_shape(const MeshShape& mesh, const Transform& t, MaterialId m, ObjectOptions opt) {
        const MeshTriangles* from_file = mesh.file ? &mesh_files_.triangles(*mesh.file) : nullptr;
        const std::size_t count = mesh.triangles->size() + (from_file ? from_file->size() : 0);
        file_triangles_ += from_file ? from_file->size() : 0;
        if (from_file && file_triangles_ > max_primitives_)
            throw Error(mesh.file->at, "the scene is too large: more than " + std::to_string(max_primitives_) +
                                           " objects and triangles");
        std::vector<Vec3<S>> positions;
        std::vector<typename TriangleMesh<S>::Index> indices;
        positions.reserve(count * 3);
        indices.reserve(count);
        for (const MeshTriangles* part : {from_file, mesh.triangles.get()}) {
            if (!part) continue;
            for (const auto& tri : *part) {
                const auto base = std::uint32_t(positions.size());
                for (const Vector3& v : tri) positions.push_back(Vec3<S>(t.point(v)));
                indices.push_back({base, base + 1, base + 2});
            }
        }
        scene_->add(TriangleMesh<S>(std::move(positions), std::move(indices)), m, opt);
    }
    void add_shape(const UnionShape&, const Transform&, MaterialId, ObjectOptions) {}
    void add_shape(const LightSource&, const Transform&, MaterialId, ObjectOptions) {}
    void add_shape(const SkippedShape&, const Transform&, MaterialId, ObjectOptions) {}

    MaterialId material_for(const Inherited& in, const Object& o) {
        static const Texture pov_default{};
        const Texture& tex = in.texture ? *in.texture : pov_default;
        const MaterialParams<S> p = material_params<S>(tex, in.interior, desc_.settings, warn_, o.at);
        for (const auto& [params, id] : materials_)
            if (same(params, p)) return id;
        const SourceLocation at = tex.finish.at.known() ? tex.finish.at : (tex.at.known() ? tex.at : o.at);
        try {
            const MaterialId id = scene_->add_material(Material<S>(p));
            materials_.emplace_back(p, id);
            return id;
        } catch (const std::invalid_argument& e) {
            throw Error(at, e.what());
        }
    }
    static bool same(const MaterialParams<S>& a, const MaterialParams<S>& b) {
        return a.diffuse == b.diffuse && a.specular == b.specular && a.transmission == b.transmission &&
               a.ior == b.ior && a.fresnel == b.fresnel && a.phong == b.phong && a.phong_exponent == b.phong_exponent;
    }

    void add_light(const LightSource& l, const Transform& t, const SourceLocation& at) {
        constexpr double pi_d = 3.14159265358979323846;
        const auto item = [&](const char* k) {
            const auto it = l.written.find(k);
            return it != l.written.end() ? it->second : l.at;
        };
        const Vector3 position = t.point(l.position);
        const Clamped<Vector3> physical = physical_light(radiant_intensity(l, &warn_), l.color.rgb);
        if (!physical.message.empty()) {
            warn_(l.at, physical.message, "approximated light", "light_source");
            if (physical.value == Vector3(0.0)) return;
        }
        const Vector3 intensity = physical.value;
        try {
            std::optional<Cone<S>> cone;
            if (l.spotlight) {
                const Spotlight& sp = *l.spotlight;
                const Vector3 axis = t.point(sp.point_at) - position;
                if (glm::length(axis) == 0.0)
                    throw Error(item("point_at"), "spotlight point_at equals the light's position");
                // POV-Ray's profile becomes a sharp cone with the same power, exact when the
                // profile is one (radius = falloff, tightness 0, radius within the front hemisphere).
                const bool sharp = sp.radius == sp.falloff && sp.tightness == 0 && sp.radius > 0 && sp.radius <= 90;
                const double half = sharp ? sp.radius : pov_spotlight_cone_half_angle(sp);
                if (!sharp)
                    warn_(sp.at.known() ? sp.at : l.at,
                          "photon's spotlight has a sharp edge: POV-Ray's soft edge (`radius` " +
                              format_number(sp.radius) + ", `falloff` " + format_number(sp.falloff) +
                              ", `tightness` " + format_number(sp.tightness) +
                              ") becomes a cone of half-angle " + format_number(std::round(half * 100) / 100) +
                              " degrees carrying the same power. Write `radius A falloff A tightness 0` for an exact "
                              "cone");
                if (!(half > 0)) {  // POV-Ray renders it, dark: photon leaves it out
                    warn_(item("radius"),
                          "this spotlight emits no light (its `radius`, `falloff` and `tightness` leave no direction "
                          "lit): photon leaves it out",
                          "approximated light", "spotlight");
                    return;
                }
                cone.emplace(Vec3<S>(axis), S(half));
            }
            const S solid_angle = cone ? cone->solid_angle() : S(4) * pi<S>;
            const Rgb<S> power = Rgb<S>(intensity) * solid_angle;
            double radius = 0;
            if (l.area && l.area->size1 * l.area->size2 > 1) {
                const AreaLight& a = *l.area;
                const double l1 = glm::length(t.vector(a.axis1)), l2 = glm::length(t.vector(a.axis2));
                if (a.circular && a.orient && std::abs(l1 - l2) <= 1e-9 * std::max(l1, l2)) {
                    radius = 0.5 * l1;
                } else {
                    radius = a.circular ? 0.5 * std::sqrt(l1 * l2) : std::sqrt(l1 * l2 / pi_d);
                    warn_(a.at,
                          "photon's area lights are spheres: this `area_light` (without `circular orient` and "
                          "equal axes) becomes a sphere light of radius " +
                              format_number(radius) + " (same area)");
                }
            }
            if (radius > 0)
                scene_->add_light(SphereLight<S>{Vec3<S>(position), S(radius), power, cone});
            else
                scene_->add_light(PointLight<S>{Vec3<S>(position), power, cone});
        } catch (const std::invalid_argument& e) {
            throw Error(at, e.what());
        }
        if (l.shadowless) warn_(item("shadowless"), "`shadowless` is ignored: photon's lights always cast shadows");
        if (l.looks_like)
            warn_(item("looks_like"),
                  "`looks_like` is ignored: photon's lights are invisible, as POV-Ray's without it");
        if (!l.photon_reflection || !l.photon_refraction)
            warn_(item("photons"),
                  "light photons `reflection off` / `refraction off` are ignored: photon traces every "
                  "photon path");
    }

    const SceneDescription& desc_;
    Warnings& warn_;
    DefaultScene<S>* scene_ = nullptr;
    std::vector<std::pair<MaterialParams<S>, MaterialId>> materials_;
    std::vector<SourceLocation> object_at_;
    std::size_t max_primitives_;
    std::size_t file_triangles_ = 0;  ///< triangles of mesh files, for every use of them
    MeshFiles mesh_files_;
    std::size_t skipped_ = 0;  ///< objects photon has no shape for
};

}  // namespace detail

/// The library's scene, camera and render settings for `desc`. Throws dsl::Error with the
/// location of the offending value.
template <Scalar S>
[[nodiscard]] BuiltScene<S> build(const SceneDescription& desc, const BuildOptions& options = {}) {
    Warnings warn(options.diagnostics);
    detail::Builder<S> builder(desc, warn, options.max_primitives);
    builder.read_files();
    RenderSettings settings = render_settings(desc, options.overrides, warn);
    CameraDescription cam;
    if (desc.camera)
        cam = *desc.camera;
    else
        warn(desc.at, "no camera: using POV-Ray's default camera at the origin looking along +z");
    const ResolvedCamera rc = resolve_camera(cam, double(settings.width) / double(settings.height), &warn);
    std::optional<PinholeCamera<S>> camera;
    try {
        camera.emplace(Vec3<S>(rc.location), Vec3<S>(rc.direction), Vec3<S>(rc.right), Vec3<S>(rc.up));
    } catch (const std::invalid_argument& e) {
        throw Error(cam.at.known() ? cam.at : desc.at, e.what());
    }
    DefaultScene<S> scene;
    builder.add_all(scene);
    scene.commit();
    // Said here, where the object's place in the file is known, for `check` and `render` alike
    // (render() lists the same objects in RenderStats::warnings for programs using the library).
    if (settings.mode != RenderMode::rt && settings.mode != RenderMode::reference && scene_has_caustics(scene))
        for (std::uint32_t id : unaimed_specular_objects(scene)) warn(builder.object_locations()[id], unaimed_caustics_warning);
    return BuiltScene<S>{std::move(scene), *camera, std::move(settings)};
}

}  // namespace photon::dsl

// With PHOTON_DSL_SEPARATE_COMPILATION (photon::dsl_compiled), build() for the two scalar types is
// compiled once, in dsl/src/build.cpp.
#if defined(PHOTON_DSL_SEPARATE_COMPILATION) && PHOTON_DSL_SEPARATE_COMPILATION
namespace photon::dsl {
extern template BuiltScene<float> build<float>(const SceneDescription&, const BuildOptions&);
extern template BuiltScene<double> build<double>(const SceneDescription&, const BuildOptions&);
}  // namespace photon::dsl
#endif
