// SPDX-License-Identifier: MIT
#pragma once
// Writes a SceneDescription back as a self-contained POV-Ray 3.7 file (pbrt's
// FormattingParserTarget): every #declare, #include, #if and expression evaluated, every
// transformation folded into one `matrix`, numbers written so that they read back exactly, and
// photon's own settings inside `#ifdef (photon_version) ... #end`, which POV-Ray skips. Reading
// the result again gives the same description (a round trip the tests check).

#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>

#include <photon/version.hpp>

#include "description.hpp"
#include "diagnostics.hpp"
#include "mesh_files.hpp"
#include "settings_table.hpp"
#include "value.hpp"

namespace photon::dsl {

namespace detail {

class PovWriter {
public:
    explicit PovWriter(DiagnosticSink sink)
        : mesh_files_([sink](const SourceLocation& at, const std::string& m) {
              if (sink) sink({Severity::warning, at, m, {}, {}});
          }) {}

    std::string write(const SceneDescription& d) {
        out_ << "// Written by `photon export-pov` (photon " << PHOTON_VERSION_MAJOR << '.' << PHOTON_VERSION_MINOR
             << '.' << PHOTON_VERSION_PATCH << ") from " << d.at.file_name() << ".\n"
             << "// Declarations, includes, conditions and expressions are evaluated; photon's own settings are\n"
             << "// inside #ifdef (photon_version), which POV-Ray skips.\n"
             << "#version 3.7;\n\n";
        settings(d.settings, d.version);
        if (d.camera) camera(*d.camera);
        sky(d);
        fogs(d);
        for (const MediaDescription& m : d.media) media(m, 0), out_ << '\n';
        for (const Object& o : d.objects) object(o, 0);
        return out_.str();
    }

private:
    static std::string num(double v) { return format_number(v); }
    static std::string vec(const Vector3& v) { return "<" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + ">"; }
    /// A POV-Ray string literal of `s`.
    static std::string quoted(const std::string& s) {
        std::string out = "\"";
        for (const char c : s) {
            if (c == '"' || c == '\\') out += '\\';
            out += c;
        }
        return out + '"';
    }
    /// A prism as a bezier_spline one (every curve raised to a cubic: exact for lines and
    /// quadratics), so POV-Ray reads back the outline photon read, whatever its spline type.
    void write_prism(const PrismShape& p) {
        std::vector<glm::dvec2> points;
        for (const auto& contour : *p.contours)
            for (const OutlineCurve& c : contour) {
                const auto cubic = as_cubic(c);
                points.insert(points.end(), cubic.begin(), cubic.end());
            }
        out_ << "prism { bezier_spline " << (p.sweep == PrismShape::Sweep::conic ? "conic_sweep " : "linear_sweep ")
             << num(p.height1) << ", " << num(p.height2) << ", " << points.size();
        for (const glm::dvec2& q : points) out_ << ", <" << num(q.x) << ", " << num(q.y) << ">";
        out_ << (p.open ? " open" : "") << '\n';
    }
    /// A lathe as a bezier_spline one, as the prism: POV-Ray reads back the profile photon read.
    void write_lathe(const LatheShape& l) {
        out_ << "lathe { bezier_spline " << 4 * l.profile->size();
        for (const OutlineCurve& c : *l.profile)
            for (const glm::dvec2& q : as_cubic(c)) out_ << ", <" << num(q.x) << ", " << num(q.y) << ">";
        out_ << '\n';
    }
    /// A curve's control points raised to a cubic's (exact for lines and quadratics).
    static std::array<glm::dvec2, 4> as_cubic(const OutlineCurve& c) {
        const auto& q = c.control;
        if (c.degree == 1) return {q[0], q[0] + (q[1] - q[0]) / 3.0, q[1] + (q[0] - q[1]) / 3.0, q[1]};
        if (c.degree == 2) return {q[0], q[0] + 2.0 / 3.0 * (q[1] - q[0]), q[2] + 2.0 / 3.0 * (q[1] - q[2]), q[2]};
        return q;
    }
    static std::string on_off(bool b) { return b ? "on" : "off"; }
    void indent(int level) {
        for (int i = 0; i < level; ++i) out_ << "  ";
    }

    void settings(const GlobalSettings& g, std::optional<double> version) {
        out_ << "global_settings {\n";
        if (g.assumed_gamma) out_ << "  assumed_gamma " << num(*g.assumed_gamma) << '\n';
        if (g.written.count("ambient_light")) out_ << "  ambient_light rgb " << vec(g.ambient_light) << '\n';
        table_items(g, true, out_);
        if (g.photons) {
            const PovPhotons& p = *g.photons;
            out_ << "  photons {";
            if (p.count) out_ << " count " << *p.count;
            if (p.spacing) out_ << " spacing " << num(*p.spacing);
            if (p.gather_max) out_ << " gather " << p.gather_min.value_or(20) << ", " << *p.gather_max;
            if (p.radius) out_ << " radius " << num(*p.radius);
            if (p.max_trace_level) out_ << " max_trace_level " << *p.max_trace_level;
            out_ << " }\n";
        }
        // Radiosity in a 3.7 scene switches `ambient` off (POV-Ray's rule, which photon follows):
        // an empty block keeps that in the 3.7 file written here. Its settings photon does not read.
        if (g.radiosity && version.value_or(3.62) >= 3.7 - 1e-9)
            out_ << "  radiosity { }  // the scene's radiosity settings are not reproduced (photon does not read them)\n";
        else if (g.radiosity)
            out_ << "  // the scene's radiosity block is not reproduced: before 3.7 it left `ambient` on, as no radiosity does\n";
        out_ << "}\n";
        std::ostringstream own;
        table_items(g, false, own);
        if (!own.str().empty()) out_ << "#ifdef (photon_version)\nglobal_settings {\n" << own.str() << "}\n#end\n";
        out_ << '\n';
    }

    /// The settings table's items the file wrote, POV-Ray's own ones or photon's, in the table's
    /// order; the items of a block (global_estimate { count 50 radius 0.5 }) together.
    static void table_items(const GlobalSettings& g, bool povray, std::ostream& out) {
        std::string_view done_block;
        for (const RenderSetting& s : render_settings_table) {
            if (s.povray != povray || s.keyword.empty() || (!s.block.empty() && s.block == done_block)) continue;
            if (s.block.empty()) {
                if (const auto it = g.render.find(std::string(s.key)); it != g.render.end()) {
                    const std::string value = format_setting_value(it->second.value);
                    out << "  " << s.keyword << ' ' << (s.kind == SettingKind::text ? '"' + value + '"' : value) << '\n';
                }
                continue;
            }
            done_block = s.block;
            std::string items;
            for (const RenderSetting& e : render_settings_table)
                if (e.block == s.block)
                    if (const auto it = g.render.find(std::string(e.key)); it != g.render.end())
                        items.append(" ").append(e.keyword).append(" ").append(format_setting_value(it->second.value));
            if (!items.empty()) out << "  " << s.block << " {" << items << " }\n";
        }
    }

    void transform(const Transform& t, int level) {
        if (t.is_identity()) return;
        const auto m = t.pov_matrix();
        indent(level);
        out_ << "matrix <";
        for (std::size_t i = 0; i < 12; ++i) out_ << (i ? ", " : "") << num(m[i]);
        out_ << ">\n";
    }

    void camera(const CameraDescription& c) {
        out_ << "camera {\n  " << c.type << "\n  location " << vec(c.location) << "\n  direction " << vec(c.direction)
             << "\n  up " << vec(c.up) << "\n  sky " << vec(c.sky) << '\n';
        if (c.right) out_ << "  right " << vec(*c.right) << '\n';
        if (c.angle) {
            out_ << "  angle " << num(*c.angle);
            if (c.vertical_angle) out_ << ", " << num(*c.vertical_angle);
            out_ << '\n';
        }
        if (c.aperture) out_ << "  aperture " << num(*c.aperture) << '\n';
        if (c.blur_samples) out_ << "  blur_samples " << *c.blur_samples << '\n';
        if (c.focal_point) out_ << "  focal_point " << vec(*c.focal_point) << '\n';
        if (c.look_at) out_ << "  look_at " << vec(*c.look_at) << '\n';
        transform(c.transform, 1);
        out_ << "}\n\n";
    }

    void light(const LightSource& l, int level) {
        out_ << "light_source {\n";
        indent(level + 1);
        out_ << vec(l.position) << ", rgb " << vec(l.color.rgb) << '\n';
        if (l.spotlight) {
            const Spotlight& s = *l.spotlight;
            indent(level + 1);
            out_ << "spotlight radius " << num(s.radius) << " falloff " << num(s.falloff) << " tightness "
                 << num(s.tightness) << " point_at " << vec(s.point_at) << '\n';
        }
        if (l.parallel) indent(level + 1), out_ << "parallel point_at " << vec(l.point_at) << '\n';
        if (l.area) {
            const AreaLight& a = *l.area;
            indent(level + 1);
            out_ << "area_light " << vec(a.axis1) << ", " << vec(a.axis2) << ", " << a.size1 << ", " << a.size2;
            if (a.adaptive) out_ << " adaptive " << *a.adaptive;
            if (a.jitter) out_ << " jitter";
            if (a.circular) out_ << " circular";
            if (a.orient) out_ << " orient";
            out_ << '\n';
        }
        if (l.fade_distance != 0 || l.fade_power != 0) {
            indent(level + 1);
            out_ << "fade_distance " << num(l.fade_distance) << " fade_power " << num(l.fade_power) << '\n';
        }
        if (l.shadowless) indent(level + 1), out_ << "shadowless\n";
        if (!l.media_interaction) indent(level + 1), out_ << "media_interaction off\n";
        if (l.media_attenuation) indent(level + 1), out_ << "media_attenuation on\n";
        if (l.looks_like_object) {
            indent(level + 1), out_ << "looks_like {\n";
            object(*l.looks_like_object, level + 2);
            indent(level + 1), out_ << "}\n";
        }
        indent(level + 1);
        out_ << "photons { reflection " << on_off(l.photon_reflection) << " refraction " << on_off(l.photon_refraction)
             << (l.photon_area_light ? " area_light" : "") << " }\n";
    }

    [[nodiscard]] static std::string rgbft(const Color& c) {
        return "rgbft <" + num(c.rgb.x) + ", " + num(c.rgb.y) + ", " + num(c.rgb.z) + ", " + num(c.filter) + ", " +
               num(c.transmit) + ">";
    }

    /// The background colour and the sky_sphere: its pigments with their transformations,
    /// then its emission and its own transformation.
    void sky(const SceneDescription& d) {
        if (d.background) out_ << "background { " << rgbft(*d.background) << " }\n\n";
        if (!d.sky_sphere) return;
        out_ << "sky_sphere {\n";
        for (const Pigment& p : d.sky_sphere->pigments) {
            indent(1);
            if (p.pattern)
                pigment_pattern(*p.pattern, p.transform);
            else
                out_ << "pigment { " << rgbft(p.color) << " }\n";
        }
        if (d.sky_sphere->emission != Vector3(1.0)) indent(1), out_ << "emission rgb " << vec(d.sky_sphere->emission) << '\n';
        if (!d.sky_sphere->transform.is_identity()) indent(1), placement_matrix(d.sky_sphere->transform), out_ << '\n';
        out_ << "}\n\n";
    }

    /// Every fog, as read (its transformations already turned `up`).
    void fogs(const SceneDescription& d) {
        for (const FogDescription& f : d.fogs) {
            out_ << "fog {\n";
            indent(1), out_ << "fog_type " << f.type << " distance " << num(f.distance) << ' ' << rgbft(f.color) << '\n';
            if (f.type == 2)
                indent(1), out_ << "fog_offset " << num(f.offset) << " fog_alt " << num(f.altitude) << " up " << vec(f.up) << '\n';
            if (f.turbulence)
                indent(1), out_ << "turbulence " << vec(*f.turbulence) << " octaves " << f.octaves << " omega " << num(f.omega)
                                << " lambda " << num(f.lambda) << " turb_depth " << num(f.turb_depth) << '\n';
            out_ << "}\n\n";
        }
    }

    /// MEDIA as read: its coefficients, sampling and densities, placed in the world (written
    /// after the object's transformations, which POV-Ray then does not apply to them).
    void media(const MediaDescription& m, int level) {
        indent(level), out_ << "media {\n";
        indent(level + 1), out_ << "method " << m.method << " intervals " << m.intervals << " samples " << m.samples_min
                                << ", " << m.samples_max << " jitter " << num(m.jitter) << " aa_threshold "
                                << num(m.aa_threshold) << " aa_level " << m.aa_level << '\n';
        indent(level + 1), out_ << "confidence " << num(m.confidence) << " variance " << num(m.variance) << " ratio "
                                << num(m.ratio) << (m.collect ? "" : " collect off") << '\n';
        if (m.absorption != Vector3(0.0)) indent(level + 1), out_ << "absorption rgb " << vec(m.absorption) << '\n';
        if (m.emission != Vector3(0.0)) indent(level + 1), out_ << "emission rgb " << vec(m.emission) << '\n';
        if (m.scattering != Vector3(0.0)) {
            indent(level + 1), out_ << "scattering { " << m.scattering_type << ", rgb " << vec(m.scattering);
            if (m.scattering_type == 5) out_ << " eccentricity " << num(m.eccentricity);
            out_ << " extinction " << num(m.extinction) << " }\n";
        }
        for (const Pigment& d : m.density) {
            indent(level + 1), out_ << "density { ";
            if (d.pattern) {
                pigment_body(*d.pattern, d.transform);
                out_ << " }\n";
            } else {
                out_ << "rgb " << vec(d.color.rgb) << " }\n";
            }
        }
        indent(level), out_ << "}\n";
    }

    /// An evaluated pattern with every modifier that differs from POV-Ray's default, its colours
    /// and its transformation.
    void pigment_pattern(const PigmentPattern& p, const Transform& placement) {
        out_ << "pigment { ";
        pigment_body(p, placement);
        out_ << " }\n";
    }

    /// PIGMENT_BODY: the pattern, its colours or pigment_map, its modifiers and its placement.
    void pigment_body(const PigmentPattern& p, const Transform& placement) {
        if (p.image) {
            image_map(*p.image);
            placement_matrix(placement);
            return;
        }
        out_ << p.name;
        if (p.name == "gradient") out_ << ' ' << vec(p.gradient);
        if (p.name == "mandel") out_ << ' ' << p.fractal_iterations;
        if (p.name == "spiral1" || p.name == "spiral2") out_ << ' ' << p.spiral_arms;
        if (p.name == "checker" || p.name == "hexagon") {  // listed colours
            for (std::size_t i = 0; i < p.colors.size(); ++i) out_ << (i ? ", " : " ") << rgbft(p.colors[i].second);
        } else if (!p.nested.empty()) {  // a pigment_map: its patterned entries in their own space
            out_ << " pigment_map {";
            for (std::size_t i = 0; i < p.colors.size(); ++i) {
                out_ << " [" << num(p.colors[i].first) << ' ';
                if (const auto& n = p.nested[i]) {
                    pigment_body(*n->pattern, n->transform);
                } else {
                    out_ << rgbft(p.colors[i].second);
                }
                out_ << ']';
            }
            out_ << " }";
        } else {
            out_ << " color_map {";
            for (const auto& [v, c] : p.colors) out_ << " [" << num(v) << ' ' << rgbft(c) << ']';
            out_ << " }";
        }
        pattern_modifiers(p);
        placement_matrix(placement);
    }

    /// IMAGE_MAP with the file where the parser found it, its gamma and its options.
    void image_map(const ImageMapDesc& m) {
        out_ << "image_map { " << m.file.type << ' ' << quoted(m.file.path.string());
        if (m.file.gamma) out_ << " gamma " << (*m.file.gamma == 0 ? std::string("srgb") : num(*m.file.gamma));
        if (m.map_type != 0) out_ << " map_type " << m.map_type;
        if (m.interpolate != 0) out_ << " interpolate " << m.interpolate;
        if (m.once) out_ << " once";
        if (m.filter_all != 0) out_ << " filter all " << num(m.filter_all);
        if (m.transmit_all != 0) out_ << " transmit all " << num(m.transmit_all);
        for (const auto& [i, v] : m.filter_index) out_ << " filter " << i << ", " << num(v);
        for (const auto& [i, v] : m.transmit_index) out_ << " transmit " << i << ", " << num(v);
        out_ << " }";
    }

    /// The modifiers of an evaluated pattern that differ from POV-Ray's defaults.
    void pattern_modifiers(const PigmentPattern& p) {
        static const PigmentPattern pov;
        if (p.turbulence != pov.turbulence) out_ << " turbulence " << vec(p.turbulence);
        if (p.octaves != pov.octaves) out_ << " octaves " << p.octaves;
        if (p.omega != pov.omega) out_ << " omega " << num(p.omega);
        if (p.lambda != pov.lambda) out_ << " lambda " << num(p.lambda);
        if (p.agate_turb != pov.agate_turb) out_ << " agate_turb " << num(p.agate_turb);
        if (p.crackle_form != pov.crackle_form) out_ << " form " << vec(p.crackle_form);
        if (p.crackle_metric != pov.crackle_metric) out_ << " metric " << num(p.crackle_metric);
        if (p.crackle_offset != pov.crackle_offset) out_ << " offset " << num(p.crackle_offset);
        if (p.crackle_solid) out_ << " solid";
        if (p.quilt_control0 != pov.quilt_control0) out_ << " control0 " << num(p.quilt_control0);
        if (p.quilt_control1 != pov.quilt_control1) out_ << " control1 " << num(p.quilt_control1);
        if (p.interior_type != pov.interior_type || p.interior_factor != pov.interior_factor)
            out_ << " interior " << p.interior_type << ", " << num(p.interior_factor);
        if (p.exterior_type != pov.exterior_type || p.exterior_factor != pov.exterior_factor)
            out_ << " exterior " << p.exterior_type << ", " << num(p.exterior_factor);
        if (p.noise_generator != pov.noise_generator) out_ << " noise_generator " << p.noise_generator;
        if (p.frequency != pov.frequency) out_ << " frequency " << num(p.frequency);
        if (p.phase != pov.phase) out_ << " phase " << num(p.phase);
        if (!p.wave.empty()) out_ << ' ' << p.wave;
        if (p.wave == "poly_wave") out_ << ' ' << num(p.exponent);
    }

    void placement_matrix(const Transform& placement) {
        if (placement.is_identity()) return;
        const auto m = placement.pov_matrix();
        out_ << " matrix <";
        for (std::size_t i = 0; i < 12; ++i) out_ << (i ? ", " : "") << num(m[i]);
        out_ << '>';
    }

    /// A normal photon evaluates: its pattern, bump size, modifiers, accuracy and transformation.
    void normal(const Normal& n) {
        const PigmentPattern& p = *n.pattern;
        if (p.image) {  // bump_map { FILE OPTIONS bump_size F }
            const ImageMapDesc& m = *p.image;
            out_ << "normal { bump_map { " << m.file.type << ' ' << quoted(m.file.path.string());
            if (m.file.gamma) out_ << " gamma " << (*m.file.gamma == 0 ? std::string("srgb") : num(*m.file.gamma));
            if (m.map_type != 0) out_ << " map_type " << m.map_type;
            if (m.interpolate != 0) out_ << " interpolate " << m.interpolate;
            if (m.once) out_ << " once";
            if (m.use_index) out_ << " use_index";
            out_ << " bump_size " << num(n.amount) << " }";
            placement_matrix(n.transform);
            out_ << " }\n";
            return;
        }
        out_ << "normal { " << p.name;
        if (p.name == "gradient") out_ << ' ' << vec(p.gradient);
        if (p.name == "mandel") out_ << ' ' << p.fractal_iterations;
        if (p.name == "spiral1" || p.name == "spiral2") out_ << ' ' << p.spiral_arms;
        out_ << " bump_size " << num(n.amount);
        pattern_modifiers(p);
        if (n.accuracy != Normal{}.accuracy) out_ << " accuracy " << num(n.accuracy);
        placement_matrix(n.transform);
        out_ << " }\n";
    }

    void texture(const Texture& t, int level) {
        static const Finish pov;  // POV-Ray's built-in defaults
        const Finish& f = t.finish;
        const Color& c = t.pigment.color;
        indent(level);
        out_ << "texture {\n";
        indent(level + 1);
        if (t.pigment.pattern)
            pigment_pattern(*t.pigment.pattern, t.pigment.transform);
        else
            out_ << "pigment { " << rgbft(c) << " }\n";
        if (t.normal && t.normal->pattern) {
            indent(level + 1);
            normal(*t.normal);
        }
        indent(level + 1);
        out_ << "finish {";
        if (f.ambient != pov.ambient) out_ << " ambient rgb " << vec(f.ambient);
        if (f.diffuse != pov.diffuse || f.diffuse_back != pov.diffuse_back) {
            out_ << " diffuse " << num(f.diffuse);
            if (f.diffuse_back != 0) out_ << ", " << num(f.diffuse_back);
        }
        if (f.brilliance != pov.brilliance) out_ << " brilliance " << num(f.brilliance);
        if (f.specular != pov.specular) out_ << " specular " << num(f.specular);
        if (f.roughness != pov.roughness) out_ << " roughness " << num(f.roughness);
        if (f.phong != pov.phong) out_ << " phong " << num(f.phong);
        if (f.phong_size != pov.phong_size) out_ << " phong_size " << num(f.phong_size);
        if (f.metallic != pov.metallic) out_ << " metallic " << num(f.metallic);
        if (f.reflection) {
            const Reflection& r = *f.reflection;
            out_ << " reflection { ";
            if (r.variable) out_ << "rgb " << vec(r.min) << ", ";
            out_ << "rgb " << vec(r.max);
            if (r.fresnel) out_ << " fresnel on";
            if (r.falloff != 1) out_ << " falloff " << num(r.falloff);
            if (r.exponent != 1) out_ << " exponent " << num(r.exponent);
            if (r.metallic != 0) out_ << " metallic " << num(r.metallic);
            out_ << " }";
        }
        if (f.conserve_energy) out_ << " conserve_energy";
        if (f.emission != pov.emission) out_ << " emission rgb " << vec(f.emission);
        out_ << " }\n";
        indent(level);
        out_ << "}\n";
        for (const Texture& layer : t.layers) texture(layer, level);  // POV-Ray's layers, each on the one before
    }

    void modifiers(const Object& o, int level) {
        if (o.texture)
            texture(*o.texture, level);
        else if (o.default_texture)
            texture(*o.default_texture, level);
        if (o.interior) {
            indent(level);
            const Interior& in = *o.interior;
            out_ << "interior { ior " << num(in.ior);
            if (in.fade_distance != 0) out_ << " fade_distance " << num(in.fade_distance);
            if (in.fade_power != 0) out_ << " fade_power " << num(in.fade_power);
            if (in.fade_color != Vector3(0.0)) out_ << " fade_color rgb " << vec(in.fade_color);
            if (in.media.empty()) {
                out_ << " }\n";
            } else {
                out_ << '\n';
                for (const MediaDescription& m : in.media) media(m, level + 1);
                indent(level), out_ << "}\n";
            }
        }
        if (o.photons) {
            const ObjectPhotons& p = *o.photons;
            indent(level);
            out_ << "photons {";
            if (p.target) out_ << " target " << num(p.spacing_multiplier);
            if (p.reflection) out_ << " reflection " << on_off(*p.reflection);
            if (p.refraction) out_ << " refraction " << on_off(*p.refraction);
            if (p.collect) out_ << " collect " << on_off(*p.collect);
            if (p.pass_through) out_ << " pass_through";
            out_ << " }\n";
        }
        if (o.no_shadow) indent(level), out_ << "no_shadow\n";
        if (o.inverse) indent(level), out_ << "inverse\n";
        if (o.hollow) indent(level), out_ << "hollow " << on_off(*o.hollow) << '\n';
        for (const auto& [name, at] : o.ignored) indent(level), out_ << name << '\n';
        // Written after the object's matrix: each in the world, where the object's transform put it.
        for (const auto& [word, list] : {std::pair{"bounded_by", &o.bounded_by}, {"clipped_by", &o.clipped_by}}) {
            if (list->empty()) continue;
            indent(level), out_ << word << " {\n";
            for (const auto& c : *list) {
                Object placed = *c;
                placed.transform = c->transform.then(o.transform);
                object(placed, level + 1);
            }
            indent(level), out_ << "}\n";
        }
    }

    void object(const Object& o, int level) {
        indent(level);
        if (const auto* skipped = std::get_if<SkippedShape>(&o.shape)) {  // photon kept no geometry to write
            out_ << "// a `" << skipped->keyword << "` photon skipped\n";
            return;
        }
        if (const auto* l = std::get_if<LightSource>(&o.shape)) {
            light(*l, level);
        } else if (const auto* s = std::get_if<SphereShape>(&o.shape)) {
            out_ << "sphere { " << vec(s->center) << ", " << num(s->radius) << '\n';
        } else if (const auto* b = std::get_if<BoxShape>(&o.shape)) {
            out_ << "box { " << vec(b->corner1) << ", " << vec(b->corner2) << '\n';
        } else if (const auto* p = std::get_if<PlaneShape>(&o.shape)) {
            out_ << "plane { " << vec(p->normal) << ", " << num(p->distance) << '\n';
        } else if (const auto* c = std::get_if<CylinderShape>(&o.shape)) {
            out_ << "cylinder { " << vec(c->base) << ", " << vec(c->cap) << ", " << num(c->radius)
                 << (c->open ? " open" : "") << '\n';
        } else if (const auto* k = std::get_if<ConeShape>(&o.shape)) {
            out_ << "cone { " << vec(k->base) << ", " << num(k->base_radius) << ", " << vec(k->cap) << ", "
                 << num(k->cap_radius) << (k->open ? " open" : "") << '\n';
        } else if (const auto* d = std::get_if<DiscShape>(&o.shape)) {
            out_ << "disc { " << vec(d->center) << ", " << vec(d->normal) << ", " << num(d->radius);
            if (d->hole_radius != 0) out_ << ", " << num(d->hole_radius);
            out_ << '\n';
        } else if (const auto* r = std::get_if<TorusShape>(&o.shape)) {
            out_ << "torus { " << num(r->major) << ", " << num(r->minor) << '\n';
        } else if (const auto* q = std::get_if<QuadricShape>(&o.shape)) {
            out_ << "quadric { " << vec(q->squares) << ", " << vec(q->mixed) << ", " << vec(q->linear) << ", "
                 << num(q->constant) << '\n';
        } else if (const auto* g = std::get_if<PolygonShape>(&o.shape)) {
            out_ << "polygon { " << g->points->size();
            for (const Vector3& point : *g->points) out_ << ", " << vec(point);
            out_ << '\n';
        } else if (const auto* pr = std::get_if<PrismShape>(&o.shape)) {
            write_prism(*pr);
        } else if (const auto* py = std::get_if<PolynomialShape>(&o.shape)) {
            // As `poly` whatever was written (the same terms in the same order); the gate before
            // the transformations, in the polynomial's own coordinates, as it was read.
            out_ << "poly { " << py->order << ", <";
            for (std::size_t n = 0; n < py->coefficients->size(); ++n) out_ << (n ? ", " : "") << num((*py->coefficients)[n]);
            out_ << ">";
            if (const auto& gate = py->gate)
                out_ << (gate->sphere ? " bounded_by { sphere { " + vec(gate->center) + ", " + num(gate->radius) + " } }"
                                      : " bounded_by { box { " + vec(gate->min) + ", " + vec(gate->max) + " } }");
            out_ << '\n';
        } else if (const auto* se = std::get_if<SuperellipsoidShape>(&o.shape)) {
            out_ << "superellipsoid { <" << num(se->e) << ", " << num(se->n) << ">\n";
        } else if (const auto* la = std::get_if<LatheShape>(&o.shape)) {
            write_lathe(*la);
        } else if (const auto* so = std::get_if<SorShape>(&o.shape)) {
            out_ << "sor { " << so->points->size();
            for (const glm::dvec2& point : *so->points) out_ << ", <" << num(point.x) << ", " << num(point.y) << ">";
            out_ << (so->open ? " open" : "") << '\n';
        } else if (const auto* bl = std::get_if<BlobShape>(&o.shape)) {
            out_ << "blob { threshold " << num(bl->threshold);
            for (const BlobShape::Component& part : *bl->components) {
                out_ << (part.cylinder ? " cylinder { " + vec(part.a) + ", " + vec(part.b) : " sphere { " + vec(part.a)) << ", "
                     << num(part.radius) << ", " << num(part.strength);
                placement_matrix(part.transform);
                out_ << " }";
            }
            out_ << '\n';
        } else if (const auto* hf = std::get_if<HeightFieldShape>(&o.shape)) {
            out_ << "height_field { " << hf->file.type << ' ' << quoted(hf->file.path.string());
            if (hf->file.gamma) out_ << " gamma " << (*hf->file.gamma == 0 ? std::string("srgb") : num(*hf->file.gamma));
            if (hf->smooth) out_ << " smooth";
            if (hf->water_level != 0) out_ << " water_level " << num(hf->water_level);
            out_ << '\n';
        } else if (const auto* x = std::get_if<TextShape>(&o.shape)) {
            out_ << "text { ttf " << quoted(x->font.path.string()) << ' ' << quoted(x->text) << ' ' << num(x->thickness) << ", "
                 << vec(x->offset) << '\n';
        } else if (const auto* t = std::get_if<TriangleShape>(&o.shape)) {
            out_ << "triangle { " << vec(t->vertices[0]) << ", " << vec(t->vertices[1]) << ", " << vec(t->vertices[2])
                 << '\n';
        } else if (const auto* m = std::get_if<MeshShape>(&o.shape)) {
            out_ << "mesh {\n";
            // POV-Ray reads no OBJ files: the file's triangles are written out, before the mesh's own.
            for (const MeshTriangles* part :
                 {m->file ? &mesh_files_.triangles(*m->file) : nullptr, m->triangles.get()}) {
                if (!part) continue;
                for (const auto& tri : *part) {
                    indent(level + 1);
                    out_ << "triangle { " << vec(tri[0]) << ", " << vec(tri[1]) << ", " << vec(tri[2]) << " }\n";
                }
            }
        } else if (const auto* csg = std::get_if<CsgShape>(&o.shape)) {
            out_ << keyword(csg->operation) << " {\n";
            for (const auto& child : csg->children) object(*child, level + 1);
        } else {
            const auto& u = std::get<UnionShape>(o.shape);
            out_ << "union {\n";
            for (const auto& child : u.children) object(*child, level + 1);
        }
        // The transformation first: POV-Ray would move a texture written before it with the object,
        // and the pigment's own transformation already includes the object's written after it.
        transform(o.transform, level + 1);
        if (!std::holds_alternative<LightSource>(o.shape)) modifiers(o, level + 1);
        indent(level);
        out_ << "}\n";
        if (level == 0) out_ << '\n';
    }

    std::ostringstream out_;
    MeshFiles mesh_files_;
};

}  // namespace detail

/// `desc` as a POV-Ray 3.7 scene file that POV-Ray and photon read alike. Reads the mesh files the
/// scene names (throws dsl::Error as build() does); their warnings go to `diagnostics`.
[[nodiscard]] inline std::string export_pov(const SceneDescription& desc, DiagnosticSink diagnostics = {}) {
    return detail::PovWriter(std::move(diagnostics)).write(desc);
}

}  // namespace photon::dsl
