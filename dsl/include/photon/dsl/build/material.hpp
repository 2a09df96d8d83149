// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's texture and interior as photon's material: the finish-to-reflectance rule.

#include <algorithm>
#include <optional>
#include <string>

#include <photon/material/material.hpp>

#include "../description.hpp"
#include "../physical_ranges.hpp"
#include "../value.hpp"
#include "pigment.hpp"
#include "warnings.hpp"

namespace photon::dsl {

/// POV-Ray 3.7's interior fade as photon's absorption, exactly (Absorption::pov_fade). Values
/// POV-Ray takes but that make light grow inside (a negative distance or power, a fade colour
/// outside [0, 1]) are reported and brought into range.
template <Scalar S> [[nodiscard]] Absorption<S> interior_absorption(const Interior& in, Warnings& warn) {
    auto at = [&](const char* k) {
        const auto it = in.written.find(k);
        return it != in.written.end() ? it->second : in.at;
    };
    if (in.fade_distance == 0) return {};
    if (in.fade_distance < 0) {
        warn(at("fade_distance"),
             "a negative `fade_distance` makes POV-Ray's glass brighten light inside; photon's glass stays clear",
             "approximated interior", "fade_distance");
        return {};
    }
    double power = in.fade_power;
    if (power < 0) {
        warn(at("fade_power"), "a negative `fade_power` is read as 0 (light loses half at any depth)",
             "approximated interior", "fade_power");
        power = 0;
    }
    const Vector3 color = glm::clamp(in.fade_color, Vector3(0.0), Vector3(1.0));
    if (color != in.fade_color)
        warn(at("fade_color"),
             "`fade_color` rgb " + rgb_text(in.fade_color) + " outside [0, 1] would make light grow inside; photon uses rgb " +
                 rgb_text(color),
             "approximated interior", "fade_color");
    return Absorption<S>::pov_fade(S(in.fade_distance), S(power), Rgb<S>(color));
}

/// The light a finish shows by itself, before the pigment's colour: POV-Ray 3.7's constant term
/// (trace.cpp, ComputeLightedTexture) ambient * ambient_light + emission, with the ambient part
/// only where radiosity is off or the scene is older than 3.7 (no #version reads as 3.62).
[[nodiscard]] inline Vector3 written_glow(const Finish& f, const GlobalSettings& global, std::optional<double> version) {
    const bool ambient_counts = !global.radiosity || version.value_or(3.62) < 3.7 - 1e-9;
    return f.emission + (ambient_counts ? f.ambient * global.ambient_light : Vector3(0.0));
}

/// POV-Ray renders a surface whose reflectances sum over 1 (diffuse 0.9 on a pigment of 1.2).
/// Photon keeps what the camera sees as written (MaterialParams::seen_gain) and scales what the
/// surface passes on by 1 / the largest channel sum, so that light transport converges. The
/// image differs from POV-Ray's only where POV-Ray passes light on too: under radiosity or
/// photons; only then `report` gets the message's tail (`terms(c)` names channel c's terms).
/// Returns the gain (1 when the sum is at most 1).
template <class Report, class Terms>
[[nodiscard]] double conserve_energy(const Vector3& sum, const GlobalSettings& global, Report&& report, Terms&& terms) {
    const int worst = sum.x >= sum.y && sum.x >= sum.z ? 0 : (sum.y >= sum.z ? 1 : 2);
    if (!(sum[worst] > 1 + 1e-9)) return 1;
    constexpr const char* channel[] = {"red", "green", "blue"};
    if (global.radiosity || global.photons.has_value())
        report(terms(worst) + " = " + format_number(sum[worst]) + " > 1 in the " + channel[worst] +
               " channel; the camera sees it as written, but photon scales the light it passes on by 1/" +
               format_number(sum[worst]) + " to conserve energy (POV-Ray's " +
               (global.radiosity ? "radiosity passes" : "photons carry") + " all of it on)");
    return sum[worst];
}

/// POV-Ray's texture and interior as photon's material: diffuse albedo = diffuse * pigment *
/// (1 - filter - transmit) (for a patterned pigment, `diffuse` alone: the pattern's colours,
/// library_pigment, carry the rest); transmission = filter * pigment + transmit, from a patterned
/// pigment's average colour; mirror reflectance from
/// `reflection`; `reflection { 0, 1 fresnel on }` with `conserve_energy` makes Fresnel glass;
/// phong and phong_size carry over, and POV-Ray's specular (blinn), roughness, metallic,
/// brilliance, ambient and emission as POV-Ray 3.7 computes them (`version`: the scene's
/// #version, none for a scene without one). Finish items photon does not render are reported to `warn`,
/// as is a surface reflecting more than it receives where POV-Ray passes that light on
/// (conserve_energy; reported at its finish, or at `object` for a default texture, which was
/// written nowhere).
template <Scalar S>
[[nodiscard]] MaterialParams<S> material_params(const Texture& tex, const Interior* interior,
                                                const GlobalSettings& global, std::optional<double> version,
                                                Warnings& warn, const SourceLocation& object = {}) {
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
    const PigmentPattern* pattern = tex.pigment.pattern.get();
    Vector3 diffuse = pattern ? Vector3(f.diffuse) : f.diffuse * pc.rgb * opacity;
    // The brightest diffuse albedo anywhere, for the energy check.
    const Vector3 diffuse_bound = pattern ? f.diffuse * max_albedo_color(*pattern) : diffuse;
    if (pattern) {
        for (const auto& [v, c] : pattern->colors)
            if (c.filter != pc.filter || c.transmit != pc.transmit) {
                warn(pigment_at,
                     "the pattern's colours differ in filter or transmit: photon's transmission is the same "
                     "everywhere, from their average (filter " + format_number(pc.filter) + ", transmit " +
                         format_number(pc.transmit) + ")",
                     "approximated pigment", "transmit");
                break;
            }
    }
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
    // POV-Ray 3.7's constant term: pigment * opacity * written_glow.
    const Vector3 written = written_glow(f, global, version);
    const Vector3 glow = glm::max(written, Vector3(0.0));
    if (glow != written)
        warn(item(f.written.count("ambient") || !f.written.count("emission") ? "ambient" : "emission"),
             "ambient and emission sum to rgb " + rgb_text(written) +
                 " (POV-Ray subtracts light where negative): photon's surfaces show no negative light and it uses rgb " +
                 rgb_text(glow),
             "approximated finish", "ambient");
    if (global.radiosity && f.emission != Vector3(0.0))
        warn(item("emission"),
             "with radiosity, POV-Ray's `emission` also lights other surfaces; photon shows it on this surface "
             "only (its light comes from light sources)",
             "approximated finish", "emission");
    // Before 3.7 POV-Ray's radiosity sees a written ambient as glow, which lights the surfaces
    // around it (the default 0.1 does too, faintly, and is not warned of).
    else if (global.radiosity && f.written.count("ambient") && written != Vector3(0.0))
        warn(item("ambient"),
             "with radiosity before #version 3.7, POV-Ray's `ambient` also lights other surfaces; photon shows it "
             "on this surface only (its light comes from light sources)",
             "approximated finish", "ambient");
    if (f.brilliance != 1 && (global.radiosity || global.photons))
        warn(item("brilliance"),
             "`brilliance " + format_number(f.brilliance) +
                 "` shapes the direct light the camera sees, as in POV-Ray; the light this surface passes on to "
                 "others, and the photons it receives, stay Lambertian (brilliance 1)",
             "approximated finish", "brilliance");
    if (f.diffuse_albedo && f.brilliance != 1)
        warn(item("diffuse"),
             "`diffuse albedo` with `brilliance " + format_number(f.brilliance) +
                 "`: POV-Ray scales the direct light by (brilliance + 1) / 2 = " + format_number((f.brilliance + 1) / 2) +
                 "; photon keeps `diffuse` as written",
             "approximated finish", "diffuse");
    if (f.diffuse_back != 0)
        warn(item("diffuse_back"), "the back-side value of `diffuse` is ignored by photon", "approximated finish", "diffuse");
    const bool tinted = f.metallic > 0 && (f.phong > 0 || f.specular > 0);
    if (tinted && pattern && (pc.filter != 0 || pc.transmit != 0))
        warn(item("metallic"),
             "`metallic` under a patterned pigment with filter or transmit: photon tints the highlight with the "
             "pattern's colours times their opacity (POV-Ray: the colours alone)",
             "approximated finish", "metallic");
    for (const char* k : {"irid", "crand"})
        if (f.written.count(k)) warn(item(k), std::string("`") + k + "` is ignored by photon", "approximated finish", k);

    const double gain = conserve_energy(diffuse_bound + specular + transmission, global, [&](const std::string& m) {
        warn(at, "the surface reflects more light than it receives: diffuse " +
                     std::string(pattern ? "(the pattern's brightest colour) " : "") + m,
             "approximated finish", "finish");
    }, [&](int c) {
        return format_number(diffuse_bound[c]) + " + reflection " + format_number(specular[c]) + " + transmission " +
               format_number(transmission[c]);
    });
    diffuse /= gain, specular /= gain, transmission /= gain;
    MaterialParams<S> p;
    p.diffuse = Rgb<S>(diffuse);
    p.specular = Rgb<S>(specular);
    p.transmission = Rgb<S>(transmission);
    p.seen_gain = S(gain);
    p.ior = S(ior);
    p.fresnel = fresnel;
    const Clamped<double> phong_size = physical_phong_size(f.phong, f.phong_size);
    if (!phong_size.message.empty()) warn(item("phong_size"), phong_size.message, "approximated finish", "phong_size");
    p.phong = S(f.phong);
    p.phong_exponent = S(phong_size.value);
    p.blinn = S(f.specular);
    p.blinn_exponent = S(1 / f.roughness);
    p.metallic = S(f.metallic);
    p.highlight_color = pattern ? Rgb<S>(S(1)) : Rgb<S>(pc.rgb);  // a pattern's colours come from the texture
    p.brilliance = S(f.brilliance);
    p.ambient = Rgb<S>(pattern ? glow : glow * pc.rgb * opacity);
    if (interior) p.absorption = interior_absorption<S>(*interior, warn);
    return p;
}

}  // namespace photon::dsl
