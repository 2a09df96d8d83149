// SPDX-License-Identifier: MIT
#pragma once
// The paper's surface model: a Lambertian diffuse part, a perfect mirror part and a perfect
// transmission part, each with its own reflectance per RGB channel. On top, POV-Ray's finish
// terms that only the light-source light seen by the camera (directly or through mirrors and
// glass) shows: Phong and Blinn highlights, metallic tint, brilliance, and a constant ambient
// radiance; none of them carries light further (highlight.hpp says why). Glass splits its transmission into reflection and refraction by the
// Fresnel equations, with total internal reflection. The diffuse reflectance may vary over the
// surface (a texture): it is then evaluated at each hit point, by every pass alike. So may the
// shading normal (a bump pattern, POV-Ray's `normal`): scatter.hpp's facing() tilts it. A
// transmitting surface may absorb inside (coloured glass, absorption.hpp).

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "../math/vec.hpp"
#include "../texture/normal_field.hpp"
#include "../texture/reflectance_field.hpp"
#include "medium.hpp"
#include "absorption.hpp"
#include "fresnel.hpp"

namespace photon {

/// Everything a Material is made of; see Material for the meaning and the checks.
template <Scalar S> struct MaterialParams {
    Rgb<S> diffuse{S(0)};       ///< Lambertian albedo rho_d (BRDF rho_d / pi); with a texture, its factor
    Rgb<S> specular{S(0)};      ///< mirror reflectance rho_s
    Rgb<S> transmission{S(0)};  ///< transmittance rho_t through a refracting interface
    S ior = S(1);               ///< index of refraction inside the surface (outside is 1)
    bool fresnel = false;       ///< split transmission into reflection F and refraction 1 - F
    S phong = S(0);             ///< Phong highlight strength (direct light only, not energy conserving)
    S phong_exponent = S(40);   ///< Phong exponent (POV-Ray's phong_size)
    S blinn = S(0);             ///< Blinn highlight strength, POV-Ray's `specular` (direct light only, like phong)
    S blinn_exponent = S(20);   ///< Blinn exponent: 1 / POV-Ray's `roughness` (default roughness 0.05)
    /// 0 to 1: how far the highlights take the surface's colour instead of the light's (POV-Ray's
    /// `metallic`), less so at grazing light.
    S metallic = S(0);
    /// The surface colour metallic highlights take (POV-Ray's pigment); with a texture, its factor.
    Rgb<S> highlight_color{S(1)};
    /// Direct light's diffuse term is albedo / pi * cos^brilliance (POV-Ray's `brilliance`; 1 is
    /// Lambertian). Photons and gathered light stay Lambertian.
    S brilliance = S(1);
    /// Radiance the surface shows by itself to camera, mirror and glass rays, whatever lights it
    /// (POV-Ray's `ambient` times `ambient_light`, plus `emission`); with a texture, its factor.
    /// It lights nothing: photons, shadow rays and gathers never see it.
    Rgb<S> ambient{S(0)};
    /// Optional texture: the albedo at point p is then diffuse * diffuse_texture(p).
    AnyReflectanceField<S> diffuse_texture{};
    /// Optional texture for the ambient radiance alone: ambient * ambient_texture(p) (without it,
    /// the diffuse texture's). A layered texture's layers weigh their colours by their own
    /// finishes, which differ between the diffuse and the ambient light.
    AnyReflectanceField<S> ambient_texture{};
    /// Optional factor on the highlights at p (a layered texture's: its layers each add theirs,
    /// dimmed by the layers above). Without it, 1.
    AnyReflectanceField<S> highlight_texture{};
    /// Optional bumps: the shading normal at p is normal_field(p, geometric normal).
    AnyNormalField<S> normal_field{};
    /// What light loses per straight segment it travels inside the surface (clear by default).
    Absorption<S> absorption{};
    /// What the camera sees of the surface (its diffuse, mirror and glass terms, directly or
    /// through mirrors and glass) is seen_gain times what it passes on to photons and gathers.
    /// A POV-Ray surface may reflect more than it receives (diffuse 0.9 on a pigment of 1.2):
    /// its reflectances are scaled to a sum <= 1 for light transport, which must converge, and
    /// this gain gives the camera the surface as written. Not physical, so 1 by default.
    S seen_gain = S(1);
    /// Participating media inside the surface (POV-Ray's interior `media`, medium.hpp):
    /// what fills the object, seen along the segments rays run inside it. Empty: none.
    std::vector<Medium<S>> media{};
};

/// How a surface scatters at one hit, after Fresnel: the three reflectances Russian roulette
/// and the ray tracer use, each <= 1 in sum per channel.
template <Scalar S> struct Scattering {
    Rgb<S> diffuse, specular, transmission;
};

/// A validated surface material. Invariants (checked at construction, std::invalid_argument with
/// the offending values otherwise): every reflectance is finite and >= 0; diffuse + specular +
/// transmission <= 1 in every channel (energy conservation; with a texture, diffuse times the
/// texture's upper bound); ior > 0 and finite; phong, blinn >= 0 with exponents > 0; metallic
/// in [0, 1]; brilliance >= 0; ambient and highlight_color finite and >= 0.
template <Scalar S> class Material {
public:
    explicit Material(const MaterialParams<S>& params);

    /// Lambertian surface of the given albedo.
    [[nodiscard]] static Material lambertian(const Rgb<S>& albedo) { return Material({.diffuse = albedo}); }
    /// Lambertian surface whose albedo at p is texture(p) (a Pigment, or a user's ReflectanceField).
    template <ReflectanceField<S> F> [[nodiscard]] static Material lambertian(F texture) {
        return Material({.diffuse = Rgb<S>(S(1)), .diffuse_texture = AnyReflectanceField<S>(std::move(texture))});
    }
    /// Perfect mirror.
    [[nodiscard]] static Material mirror(const Rgb<S>& reflectance = Rgb<S>(S(1))) {
        return Material({.specular = reflectance});
    }
    /// Clear dielectric: Fresnel reflection, refraction with the rest, total internal reflection.
    [[nodiscard]] static Material glass(S ior, const Rgb<S>& transmission = Rgb<S>(S(1))) {
        return Material({.transmission = transmission, .ior = ior, .fresnel = true});
    }

    [[nodiscard]] const MaterialParams<S>& params() const noexcept { return params_; }
    /// The diffuse albedo's constant factor: the albedo itself unless the material is textured.
    [[nodiscard]] const Rgb<S>& diffuse() const noexcept { return params_.diffuse; }
    [[nodiscard]] bool is_textured() const noexcept { return bool(params_.diffuse_texture); }
    /// The diffuse albedo at surface point `p` (one branch for an untextured material).
    [[nodiscard]] Rgb<S> diffuse_at(const Vec3<S>& p) const {
        if (!params_.diffuse_texture) [[likely]]
            return params_.diffuse;
        return params_.diffuse * params_.diffuse_texture(p);
    }
    /// Per channel, the largest diffuse albedo anywhere on the surface.
    [[nodiscard]] Rgb<S> max_diffuse() const noexcept {
        return params_.diffuse_texture ? params_.diffuse * params_.diffuse_texture.upper_bound() : params_.diffuse;
    }
    /// The ambient radiance at surface point `p` (zero for most materials).
    [[nodiscard]] Rgb<S> ambient_at(const Vec3<S>& p) const {
        if (!has_ambient_) [[likely]]
            return Rgb<S>(S(0));
        if (params_.ambient_texture) return params_.ambient * params_.ambient_texture(p);
        return params_.diffuse_texture ? params_.ambient * params_.diffuse_texture(p) : params_.ambient;
    }
    /// The colour metallic highlights take at surface point `p`.
    [[nodiscard]] Rgb<S> highlight_color_at(const Vec3<S>& p) const {
        return params_.diffuse_texture ? params_.highlight_color * params_.diffuse_texture(p) : params_.highlight_color;
    }
    /// What the highlights at surface point `p` are multiplied by (1 without a highlight texture).
    [[nodiscard]] Rgb<S> highlight_weight_at(const Vec3<S>& p) const {
        return params_.highlight_texture ? params_.highlight_texture(p) : Rgb<S>(S(1));
    }
    /// True when direct light shows a highlight (phong or blinn).
    [[nodiscard]] bool has_highlight() const noexcept { return params_.phong > S(0) || params_.blinn > S(0); }
    /// True when direct light's diffuse term is not Lambertian (brilliance other than 1).
    [[nodiscard]] bool has_brilliance() const noexcept { return params_.brilliance != S(1); }
    /// Factor on the diffuse, mirror and glass terms the camera sees (MaterialParams::seen_gain).
    [[nodiscard]] S seen_gain() const noexcept { return params_.seen_gain; }
    /// Whether a normal field tilts this surface's shading normal.
    [[nodiscard]] bool has_normal_field() const noexcept { return bool(params_.normal_field); }
    /// The unit shading normal at `p` for the unit outward geometric normal `n` (n itself
    /// without a normal field), before facing() turns it to a ray's side and guards it.
    [[nodiscard]] Vec3<S> shading_normal(const Vec3<S>& p, const Vec3<S>& n) const {
        if (!params_.normal_field) [[likely]]
            return n;
        return params_.normal_field(p, n);
    }
    [[nodiscard]] S ior() const noexcept { return params_.ior; }
    /// Whether light travelling inside the surface is absorbed.
    [[nodiscard]] bool absorbs() const noexcept { return params_.absorption.absorbs(); }
    [[nodiscard]] bool has_diffuse() const noexcept { return has_diffuse_; }
    /// True when the surface can reflect or refract specularly (it can form caustics).
    [[nodiscard]] bool is_specular() const noexcept {
        return !is_black(params_.specular) || !is_black(params_.transmission);
    }

    /// Reflectances at hit point `p` where the incoming unit direction makes cos_i (> 0) with the
    /// normal facing it, entering the surface when `entering` (else leaving it).
    [[nodiscard]] Scattering<S> scattering(const Vec3<S>& p, S cos_i, bool entering) const {
        Scattering<S> s{diffuse_at(p), params_.specular, params_.transmission};
        if (params_.fresnel && !is_black(params_.transmission)) {
            const S f = entering ? fresnel_dielectric(cos_i, S(1), params_.ior)
                                 : fresnel_dielectric(cos_i, params_.ior, S(1));
            s.specular += params_.transmission * f;
            s.transmission = params_.transmission * (S(1) - f);
        }
        return s;
    }

private:
    MaterialParams<S> params_;
    bool has_diffuse_ = false;  ///< some point of the surface reflects diffusely
    bool has_ambient_ = false;  ///< the surface shows an ambient radiance somewhere
};

template <Scalar S> Material<S>::Material(const MaterialParams<S>& p) : params_(p) {
    auto fail = [](const std::string& what) { throw std::invalid_argument("material: " + what); };
    auto check_rgb = [&](const Rgb<S>& c, const char* name, const char* what = "reflectance") {
        if (!is_finite(c) || min_component(c) < S(0)) {
            std::ostringstream os;
            os << name << ' ' << what << " must be finite and >= 0, got <" << c.x << ", " << c.y << ", " << c.z << ">";
            fail(os.str());
        }
    };
    check_rgb(p.diffuse, "diffuse");
    if (p.diffuse_texture) check_rgb(p.diffuse_texture.upper_bound(), "the diffuse texture's upper bound as");
    check_rgb(p.specular, "specular");
    check_rgb(p.transmission, "transmission");
    const Rgb<S> diffuse = max_diffuse();
    const Rgb<S> sum = diffuse + p.specular + p.transmission;
    constexpr const char* channel[] = {"red", "green", "blue"};
    for (int c = 0; c < 3; ++c) {
        // A little slack for values like 0.7 + 0.3 that round above 1.
        if (sum[c] > S(1) + S(1e-6)) {
            std::ostringstream os;
            os << "diffuse + specular + transmission = " << sum[c] << " > 1 in the " << channel[c]
               << " channel (diffuse " << diffuse[c] << (p.diffuse_texture ? " at the texture's brightest" : "")
               << ", specular " << p.specular[c] << ", transmission "
               << p.transmission[c] << "); a surface cannot reflect more light than it receives";
            fail(os.str());
        }
    }
    has_diffuse_ = !is_black(diffuse);
    if (!(p.ior > S(0)) || !std::isfinite(p.ior)) {
        std::ostringstream os;
        os << "ior must be positive and finite, got " << p.ior;
        fail(os.str());
    }
    if (!(p.phong >= S(0)) || !std::isfinite(p.phong) || !(p.phong_exponent > S(0)) || !std::isfinite(p.phong_exponent))
        fail("phong must be >= 0 and phong_exponent > 0, both finite");
    if (!(p.blinn >= S(0)) || !std::isfinite(p.blinn) || !(p.blinn_exponent > S(0)) || !std::isfinite(p.blinn_exponent))
        fail("blinn must be >= 0 and blinn_exponent > 0, both finite");
    if (!(p.metallic >= S(0) && p.metallic <= S(1))) {
        std::ostringstream os;
        os << "metallic must be in [0, 1], got " << p.metallic;
        fail(os.str());
    }
    if (!(p.brilliance >= S(0)) || !std::isfinite(p.brilliance)) {
        std::ostringstream os;
        os << "brilliance must be finite and >= 0, got " << p.brilliance;
        fail(os.str());
    }
    if (!(p.seen_gain > S(0)) || !std::isfinite(p.seen_gain)) {
        std::ostringstream os;
        os << "seen_gain must be positive and finite, got " << p.seen_gain;
        fail(os.str());
    }
    check_rgb(p.ambient, "ambient", "radiance");
    if (p.ambient_texture) check_rgb(p.ambient_texture.upper_bound(), "the ambient texture's upper bound as", "radiance");
    if (p.highlight_texture) check_rgb(p.highlight_texture.upper_bound(), "the highlight texture's upper bound as", "weight");
    check_rgb(p.highlight_color, "highlight", "colour");
    for (const Medium<S>& m : p.media) m.validate();
    has_ambient_ = !is_black(p.ambient);
}

}  // namespace photon
