// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's layered texture as photon's material. POV-Ray lights each layer with its own pigment,
// finish and normal and adds them, each dimmed by what the layers above let through
// (texture/layered.hpp gives the rule). Photon does exactly the part a material's textures can
// hold: the diffuse reflectance (each layer's colour times its finish's `diffuse`) and the glow
// (times its `ambient` and `emission`). The rest comes from single layers, with a warning where
// that differs from POV-Ray:
// - highlights (phong, specular): exact when the layers that have one share it (each adds it,
//   dimmed by the layers above: LayeredHighlightWeight); otherwise the topmost layer's, at full
//   strength; a `metallic` highlight is the topmost layer's, coloured by the layers together;
// - reflection: the topmost layer that reflects (exact when only one does: POV-Ray does not dim
//   a layer's reflection by the layers above it);
// - normal: the topmost layer's that has one (exact when every layer has the same one);
// - brilliance, transmission and the rest of the finish: the bottom layer's.
// Layers under one that is opaque everywhere are dropped, as POV-Ray stops there.

#include <optional>
#include <string>
#include <vector>

#include <photon/material/material.hpp>
#include <photon/texture/layered.hpp>
#include <photon/texture/normal_field.hpp>

#include "../description.hpp"
#include "../image_files.hpp"
#include "../physical_ranges.hpp"
#include "material.hpp"
#include "normal.hpp"
#include "pigment.hpp"
#include "warnings.hpp"

namespace photon::dsl {

namespace layers_detail {

/// The texture's colours: its pattern's map entries, or its one colour.
inline std::vector<Color> written_colors(const Texture& t) {
    if (!t.pigment.pattern) return {t.pigment.color};
    std::vector<Color> out;
    for (const auto& [v, c] : t.pigment.pattern->colors) out.push_back(c);
    return out;
}

inline bool opaque_everywhere(const Texture& t) {
    for (const Color& c : written_colors(t)) {
        const Color p = physical_pigment(c).value;
        if (p.filter != 0 || p.transmit != 0) return false;
    }
    return true;
}

inline bool has_highlight(const Finish& f) { return f.phong > 0 || f.specular > 0; }
inline bool same_highlight(const Finish& a, const Finish& b) {
    return a.phong == b.phong && a.phong_size == b.phong_size && a.specular == b.specular && a.roughness == b.roughness &&
           a.metallic == b.metallic;
}
inline bool reflects(const Finish& f) {
    return f.reflection && (f.reflection->max != Vector3(0.0) || f.reflection->min != Vector3(0.0));
}
inline bool same_normal(const std::optional<Normal>& a, const std::optional<Normal>& b) {
    const bool ha = a && a->pattern, hb = b && b->pattern;
    if (ha != hb) return false;
    if (!ha) return true;
    return (a->pattern == b->pattern || *a->pattern == *b->pattern) && a->amount == b->amount &&
           a->accuracy == b->accuracy && a->transform == b->transform;
}
inline SourceLocation finish_item(const Finish& f, const char* key, const SourceLocation& fallback) {
    const auto it = f.written.find(key);
    if (it != f.written.end()) return it->second;
    return f.at.known() ? f.at : fallback;
}

/// The pattern as the library's PigmentLayer: its colours with filter and transmit (within
/// POV-Ray's physical range, reported to `warn` otherwise), placed in the world by `placement`,
/// and `weight`. A pigment_map's patterned entries nest: each placed by its own transformations,
/// then `placement` (POV-Ray transforms a map's pigments with the pigment that holds them).
template <Scalar S>
PigmentLayer<S> pattern_layer(const PigmentPattern& pattern, const Transform& placement, const Vector3& weight,
                              Warnings& warn, const SourceLocation& at, ImageFiles* images = nullptr) {
    if (pattern.image) return PigmentLayer<S>(image_map<S>(*pattern.image, placement, images), Rgb<S>(weight));
    std::vector<typename ColorMap<S>::Entry> entries;
    std::vector<FilterTransmit<S>> clear;
    for (const auto& [v, written] : pattern.colors) {
        const Clamped<Color> p = physical_pigment(written);
        if (!p.message.empty()) warn(at, p.message, "approximated pigment", "pigment");
        entries.push_back({v, Rgb<S>(p.value.rgb)});
        clear.push_back({S(p.value.filter), S(p.value.transmit)});
    }
    Affine<double> a;
    a.linear = placement.linear;
    a.translation = placement.translation;
    photon::Pigment<S> pigment(library_pattern(pattern), ColorMap<S>(std::move(entries)), a);
    if (pattern.nested.empty()) return PigmentLayer<S>(std::move(pigment), clear, Rgb<S>(weight));
    std::vector<std::shared_ptr<const PigmentLayer<S>>> nested;
    for (const auto& n : pattern.nested)
        nested.push_back(n ? std::make_shared<const PigmentLayer<S>>(pattern_layer<S>(
                                 *n->pattern, n->transform.then(placement), Vector3(1.0), warn, n->at.known() ? n->at : at, images))
                           : nullptr);
    return PigmentLayer<S>(std::move(pigment), clear, std::move(nested), Rgb<S>(weight));
}

/// The layer as the library's PigmentLayer: its pigment (see pattern_layer) placed by its own
/// transformations then `to_world`, and `weight`.
template <Scalar S>
PigmentLayer<S> library_layer(const Texture& t, const Transform& to_world, const Vector3& weight, Warnings& warn,
                              const SourceLocation& at, ImageFiles* images = nullptr) {
    if (!t.pigment.pattern) {
        const Clamped<Color> p = physical_pigment(t.pigment.color);
        if (!p.message.empty()) warn(at, p.message, "approximated pigment", "pigment");
        const Color& c = p.value;
        return PigmentLayer<S>(LayerColor<S>{Rgb<S>(c.rgb), S(c.filter), S(c.transmit)}, Rgb<S>(weight));
    }
    return pattern_layer<S>(*t.pigment.pattern, t.pigment.transform.then(to_world), weight, warn, at, images);
}

}  // namespace layers_detail

/// The material of a layered texture (`tex.layers` not empty); `to_world` maps the space the
/// texture was written in to the world. Sets the diffuse and ambient textures and the normal
/// field; what photon approximates is reported to `warn`. May throw std::invalid_argument.
template <Scalar S>
[[nodiscard]] MaterialParams<S> layered_material_params(const Texture& tex, const Transform& to_world,
                                                        const Interior* interior, const GlobalSettings& global,
                                                        std::optional<double> version, Warnings& warn,
                                                        const SourceLocation& object = {}, ImageFiles* images = nullptr) {
    using namespace layers_detail;
    std::vector<const Texture*> stack{&tex};  // bottom first
    for (const Texture& t : tex.layers) stack.push_back(&t);
    for (std::size_t i = stack.size(); i-- > 1;)
        if (opaque_everywhere(*stack[i])) {  // nothing below shows: POV-Ray stops here
            stack.erase(stack.begin(), stack.begin() + std::ptrdiff_t(i));
            break;
        }
    const std::size_t top = stack.size() - 1;
    auto place = [&](const Texture& t) {
        return t.finish.at.known() ? t.finish.at : (t.at.known() ? t.at : object);
    };
    auto pigment_place = [&](const Texture& t) { return t.pigment.at.known() ? t.pigment.at : place(t); };
    auto topmost = [&](auto&& has) -> std::optional<std::size_t> {
        for (std::size_t i = stack.size(); i-- > 0;)
            if (has(*stack[i])) return i;
        return std::nullopt;
    };

    // The bottom layer with the finish parts taken from other layers.
    Texture composite = *stack.front();
    composite.layers.clear();
    Finish& cf = composite.finish;
    const auto highlight = topmost([](const Texture& t) { return has_highlight(t.finish); });
    if (highlight) {
        const Finish& h = stack[*highlight]->finish;
        cf.phong = h.phong, cf.phong_size = h.phong_size, cf.specular = h.specular, cf.roughness = h.roughness;
        cf.metallic = h.metallic;
        for (const char* k : {"phong", "phong_size", "specular", "roughness", "metallic"}) {
            cf.written.erase(k);
            if (const auto it = h.written.find(k); it != h.written.end()) cf.written[k] = it->second;
        }
    }
    const auto reflecting = topmost([](const Texture& t) { return reflects(t.finish); });
    cf.reflection = reflecting ? stack[*reflecting]->finish.reflection : std::nullopt;

    MaterialParams<S> p = material_params<S>(composite, interior, global, version, warn, object);

    // The exact part: diffuse and glow, each layer weighed by its own finish.
    std::vector<PigmentLayer<S>> diffuse_layers, glow_layers;
    bool glows = false;
    for (const Texture* t : stack) {
        const Vector3 written = written_glow(t->finish, global, version);
        const Vector3 glow = glm::max(written, Vector3(0.0));
        if (glow != written && t != stack.front())  // material_params reports the bottom's
            warn(finish_item(t->finish, "ambient", place(*t)),
                 "ambient and emission sum to rgb " + rgb_text(written) +
                     " (POV-Ray subtracts light where negative): photon's surfaces show no negative light and it "
                     "uses rgb " + rgb_text(glow),
                 "approximated finish", "ambient");
        glows = glows || glow != Vector3(0.0);
        diffuse_layers.push_back(library_layer<S>(*t, to_world, Vector3(t->finish.diffuse), warn, pigment_place(*t), images));
        glow_layers.push_back(library_layer<S>(*t, to_world, glow, warn, pigment_place(*t), images));
    }
    // Highlights: each layer that has one adds it dimmed by the layers above; exact as one
    // weighted highlight when they all share it and none is metallic.
    bool shared_highlight = highlight && stack[*highlight]->finish.metallic == 0;
    std::vector<bool> highlighted;
    for (const Texture* t : stack) {
        highlighted.push_back(has_highlight(t->finish));
        if (highlighted.back()) shared_highlight = shared_highlight && same_highlight(t->finish, stack[*highlight]->finish);
    }
    if (shared_highlight && (stack.size() > 1 || *highlight != top))
        p.highlight_texture = AnyReflectanceField<S>(LayeredHighlightWeight<S>(diffuse_layers, highlighted));
    const LayeredPigment<S> diffuse(std::move(diffuse_layers));
    p.diffuse = Rgb<S>(S(1));
    p.diffuse_texture = AnyReflectanceField<S>(diffuse);
    p.ambient = Rgb<S>(S(glows ? 1 : 0));
    if (glows) p.ambient_texture = AnyReflectanceField<S>(LayeredPigment<S>(std::move(glow_layers)));
    p.highlight_color = Rgb<S>(S(1));  // metallic highlights take the composite's colour

    const Rgb<S> top_diffuse = diffuse.upper_bound();
    const double gain = conserve_energy(
        Vector3(top_diffuse + p.specular + p.transmission), global,
        [&](const std::string& m) {
            warn(place(*stack.front()),
                 "the layered texture reflects more light than it receives: diffuse (the layers' brightest) " + m,
                 "approximated finish", "finish");
        },
        [&](int c) {
            return format_number(double(top_diffuse[c])) + " + reflection " + format_number(double(p.specular[c])) +
                   " + transmission " + format_number(double(p.transmission[c]));
        });
    p.diffuse /= S(gain), p.specular /= S(gain), p.transmission /= S(gain);
    p.seen_gain = S(gain);

    const auto normal = topmost([](const Texture& t) { return t.normal && t.normal->pattern; });
    if (normal) {
        const Normal& n = *stack[*normal]->normal;
        p.normal_field = library_normal_field<S>(n, n.transform.then(to_world), images);
    }

    // What photon approximates.
    if (highlight && !shared_highlight) {
        std::vector<std::size_t> others;
        for (std::size_t i = 0; i < stack.size(); ++i)
            if (i != *highlight && has_highlight(stack[i]->finish)) others.push_back(i);
        const Finish& h = stack[*highlight]->finish;
        const SourceLocation at = finish_item(h, h.phong > 0 ? "phong" : "specular", place(*stack[*highlight]));
        if (*highlight != top)
            warn(at,
                 "layered texture: photon shows this layer's highlight at full strength over the whole surface; "
                 "POV-Ray dims it where the layers above cover it",
                 "approximated texture", "texture");
        for (const std::size_t i : others)
            warn(finish_item(stack[i]->finish, stack[i]->finish.phong > 0 ? "phong" : "specular", place(*stack[i])),
                 "layered texture: photon shows one layer's highlight, the topmost's (at " + at.str() +
                     "), and not this one; POV-Ray adds every layer's",
                 "approximated texture", "texture");
        if (h.metallic > 0)
            warn(finish_item(h, "metallic", place(*stack[*highlight])),
                 "layered texture: the `metallic` highlight takes the colour of the layers together, not of this "
                 "layer's pigment alone as in POV-Ray",
                 "approximated texture", "texture");
    }
    if (reflecting) {
        const Reflection& r = *stack[*reflecting]->finish.reflection;
        for (std::size_t i = 0; i < stack.size(); ++i)
            if (i != *reflecting && reflects(stack[i]->finish))
                warn(stack[i]->finish.reflection->at,
                     "layered texture: photon reflects with one layer's `reflection`, the topmost's (at " + r.at.str() +
                         "), and not this one; POV-Ray adds every layer's",
                     "approximated texture", "texture");
        if (*reflecting != 0 && stack[*reflecting]->finish.conserve_energy)
            warn(r.at,
                 "layered texture: `conserve_energy` on a layer above the bottom: POV-Ray dims the layers below by "
                 "this reflection, photon does not",
                 "approximated texture", "texture");
    }
    if (normal)
        for (std::size_t i = 0; i < stack.size(); ++i)
            if (!same_normal(stack[i]->normal, stack[*normal]->normal)) {
                warn(stack[*normal]->normal->at,
                     "layered texture: photon shades every layer with this layer's `normal`; POV-Ray shades each "
                     "layer with its own (the layer at " + place(*stack[i]).str() +
                         (stack[i]->normal && stack[i]->normal->pattern ? " has another)" : " has none)"),
                     "approximated texture", "texture");
                break;
            }
    const Finish& bottom = stack.front()->finish;
    for (std::size_t i = 1; i < stack.size(); ++i) {
        const Finish& f = stack[i]->finish;
        if (f.brilliance != bottom.brilliance)
            warn(finish_item(f, "brilliance", place(*stack[i])),
                 "layered texture: photon's direct light takes the bottom layer's brilliance (" +
                     format_number(bottom.brilliance) + ") for every layer, not this layer's " +
                     format_number(f.brilliance),
                 "approximated texture", "texture");
        if (f.diffuse_back != 0)
            warn(finish_item(f, "diffuse_back", place(*stack[i])), "the back-side value of `diffuse` is ignored by photon",
                 "approximated finish", "diffuse");
        for (const char* k : {"irid", "crand"})
            if (f.written.count(k))
                warn(finish_item(f, k, place(*stack[i])), std::string("`") + k + "` is ignored by photon",
                     "approximated finish", k);
    }
    if (p.transmission != Rgb<S>(S(0)) && stack.size() > 1)
        warn(pigment_place(*stack.front()),
             "layered texture over a clear bottom layer: photon's transmission is the bottom layer's, the same "
             "everywhere; POV-Ray dims it by what the layers above let through",
             "approximated texture", "texture");
    return p;
}

}  // namespace photon::dsl
