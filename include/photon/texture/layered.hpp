// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's layered texture (`texture { A } texture { B }`: B on top of A) as one reflectance
// field. Each layer's colour carries POV-Ray's filter and transmit, which on a layer mean "let
// the layers below show through". Composed as POV-Ray 3.7's Trace::ComputeLightedTexture does,
// from the top layer down:
//     result  += through * colour * (1 - filter - transmit) * weight
//     through *= filter * colour + transmit          (through starts at 1)
// where `weight` is the layer's own factor (its finish's diffuse for the diffuse reflectance,
// its ambient and emission for the glow). What `through` still holds after the bottom layer is
// what the stack passes to a surface behind it (passed()).

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include "../math/vec.hpp"
#include "image_map.hpp"
#include "layer_color.hpp"
#include "pigment.hpp"

namespace photon {

/// Per channel, the most a layer's colours reach: of colour, of opacity, of colour * opacity (its
/// own share) and of passed(), each on its own (a bound, not one colour).
template <Scalar S> struct LayerEnvelope {
    Rgb<S> color{S(0)}, opacity{S(0)}, tinted{S(0)}, passed{S(0)};
    void include(const LayerEnvelope& e) noexcept {
        color = glm::max(color, e.color), opacity = glm::max(opacity, e.opacity);
        tinted = glm::max(tinted, e.tinted), passed = glm::max(passed, e.passed);
    }
};

/// One layer: a colour everywhere or a pigment whose map entries carry filter and transmit, and
/// the layer's weight (what multiplies its own colour). An entry may itself be a pigment (POV-Ray's
/// pigment_map with patterned entries): another PigmentLayer, evaluated at the same point.
template <Scalar S> class PigmentLayer {
public:
    /// One colour everywhere. Throws std::invalid_argument on a colour or weight that is not
    /// finite and >= 0, or filter and transmit outside [0, 1] in sum.
    PigmentLayer(const LayerColor<S>& color, const Rgb<S>& weight) : entries_{color}, weight_(weight) { check(); }
    /// A pigment whose colour map entry i has the filter and transmit `clear[i]` (blended between
    /// entries as the colours are). Throws std::invalid_argument as above, or when `clear` does
    /// not have one element per map entry.
    PigmentLayer(Pigment<S> pigment, const std::vector<FilterTransmit<S>>& clear, const Rgb<S>& weight)
        : pigment_(std::move(pigment)), weight_(weight) {
        const auto& map = pigment_->colors().entries();
        if (clear.size() != map.size())
            throw std::invalid_argument("layered texture: one filter and transmit is needed per colour map entry");
        for (std::size_t i = 0; i < map.size(); ++i)
            entries_.push_back({map[i].color, clear[i].filter, clear[i].transmit});
        check();
    }

    /// A pigment_map: entry i is `nested[i]` where that is set (its weight unused; placed in the
    /// world by its own pigment, which carries this one's transformations after its own), else
    /// the colour map's entry with `clear[i]`. Throws as above, or when `nested` does not have one
    /// element per map entry.
    PigmentLayer(Pigment<S> pigment, const std::vector<FilterTransmit<S>>& clear,
                 std::vector<std::shared_ptr<const PigmentLayer>> nested, const Rgb<S>& weight)
        : PigmentLayer(std::move(pigment), clear, weight) {
        if (nested.size() != entries_.size())
            throw std::invalid_argument("layered texture: one nested pigment (or none) is needed per map entry");
        if (std::any_of(nested.begin(), nested.end(), [](const auto& n) { return n != nullptr; })) nested_ = std::move(nested);
    }

    /// An image map: its pixels' colours, filter and transmit. Throws std::invalid_argument on a
    /// null image or a weight that is not finite and >= 0.
    PigmentLayer(std::shared_ptr<const ImageMap<S>> image, const Rgb<S>& weight) : weight_(weight), image_(std::move(image)) {
        if (!image_) throw std::invalid_argument("layered texture: the image map is missing");
        check();
    }

    /// The layer's colour, filter and transmit at world point `p`.
    [[nodiscard]] LayerColor<S> operator()(const Vec3<S>& p) const noexcept {
        if (image_) return image_->layer(p);
        if (!pigment_) return entries_.front();
        const auto where = pigment_->colors().locate(pigment_->value(p));
        const LayerColor<S> a = entry(where.prev, p);
        if (where.prev == where.cur) return a;
        return blend(a, entry(where.cur, p), where.fraction);
    }
    [[nodiscard]] bool has_nested() const noexcept { return !nested_.empty(); }
    /// The most this layer's colours reach, per channel (exact at the entries; between two
    /// entries of which one is nested, colour times opacity is bounded by their maxima's product).
    [[nodiscard]] LayerEnvelope<S> envelope() const noexcept {
        if (image_) return image_envelope();
        LayerEnvelope<S> env;
        const auto of = [&](std::size_t i) {
            if (has_nested() && nested_[i]) return nested_[i]->envelope();
            const LayerColor<S>& c = entries_[i];
            const Rgb<S> o(c.opacity());
            return LayerEnvelope<S>{c.color, o, c.color * o, c.passed()};
        };
        for (std::size_t i = 0; i < entries_.size(); ++i) {
            const LayerEnvelope<S> e = of(i);
            env.include(e);
            if (i == 0 || !pigment_) continue;
            const LayerEnvelope<S> before = of(i - 1);
            if (has_nested() && (nested_[i] || nested_[i - 1])) {
                env.tinted = glm::max(env.tinted, glm::max(e.color, before.color) * glm::max(e.opacity, before.opacity));
            } else {  // colour * opacity along the blend is a quadratic: its top, if inside
                for (int ch = 0; ch < 3; ++ch) {
                    const auto g = [&](const LayerColor<S>& c) { return double(c.color[ch]) * double(c.opacity()); };
                    const double g0 = g(entries_[i - 1]), g1 = g(entries_[i]),
                                 gh = g(blend(entries_[i - 1], entries_[i], S(0.5)));
                    const double a = 2 * g0 - 4 * gh + 2 * g1, b = -3 * g0 + 4 * gh - g1;
                    if (a < 0) {
                        const double x = -b / (2 * a);
                        if (x > 0 && x < 1) env.tinted[ch] = std::max(env.tinted[ch], S((a * x + b) * x + g0));
                    }
                }
            }
        }
        return env;
    }
    [[nodiscard]] const Rgb<S>& weight() const noexcept { return weight_; }
    /// The colours the layer blends between (one for a uniform layer).
    [[nodiscard]] const std::vector<LayerColor<S>>& entries() const noexcept { return entries_; }
    [[nodiscard]] bool is_uniform() const noexcept { return !pigment_ && !image_; }
    /// The layer is an image map (entries() is then empty).
    [[nodiscard]] bool is_image() const noexcept { return image_ != nullptr; }

    [[nodiscard]] static LayerColor<S> blend(const LayerColor<S>& a, const LayerColor<S>& b, S fraction) noexcept {
        return {a.color + fraction * (b.color - a.color), a.filter + fraction * (b.filter - a.filter),
                a.transmit + fraction * (b.transmit - a.transmit)};
    }

private:
    void check() const {
        if (!is_finite(weight_) || min_component(weight_) < S(0))
            throw std::invalid_argument("layered texture: a layer's weight must be finite and >= 0");
        for (const LayerColor<S>& e : entries_) {
            if (!is_finite(e.color) || min_component(e.color) < S(0))
                throw std::invalid_argument("layered texture: colours must be finite and >= 0");
            if (!(e.filter >= S(0) && e.transmit >= S(0) && e.filter + e.transmit <= S(1) + S(1e-6)))
                throw std::invalid_argument("layered texture: filter and transmit must be >= 0 and sum to <= 1");
        }
    }

    /// Over the image's pixels (and the clear white outside a `once` image). Interpolation blends
    /// up to four pixels: colour, opacity and passed() stay below their maxima, colour times
    /// opacity below the product of those.
    [[nodiscard]] LayerEnvelope<S> image_envelope() const noexcept {
        LayerEnvelope<S> env;
        const ImageMap<S>& m = *image_;
        const auto add = [&](const LayerColor<S>& c) {
            const Rgb<S> o(c.opacity());
            env.include({c.color, o, c.color * o, c.passed()});
        };
        for (unsigned y = 0; y < m.image().height(); ++y)
            for (unsigned x = 0; x < m.image().width(); ++x) add(m.sample(x + 0.5, y + 0.5));
        if (m.options().once) add({Rgb<S>(S(1)), S(0), S(1)});
        if (m.options().interpolate != ImageInterpolation::none) env.tinted = env.color * env.opacity;
        return env;
    }

    [[nodiscard]] LayerColor<S> entry(std::size_t i, const Vec3<S>& p) const noexcept {
        return has_nested() && nested_[i] ? (*nested_[i])(p) : entries_[i];
    }

    std::optional<Pigment<S>> pigment_;  ///< none: entries_ holds the one colour
    std::vector<LayerColor<S>> entries_;
    std::vector<std::shared_ptr<const PigmentLayer>> nested_;  ///< empty, or one per entry (null: the colour)
    Rgb<S> weight_;
    std::shared_ptr<const ImageMap<S>> image_;  ///< set: the layer is this image map
};

/// Layers composed into one reflectance: a ReflectanceField (reflectance_field.hpp).
template <Scalar S> class LayeredPigment {
public:
    /// `layers` bottom first, as written in the scene. Throws std::invalid_argument when empty.
    explicit LayeredPigment(std::vector<PigmentLayer<S>> layers) : layers_(std::move(layers)) {
        if (layers_.empty()) throw std::invalid_argument("layered texture: at least one layer is needed");
        bound_ = compute_bound();
    }

    /// The composite reflectance at world point `p`.
    [[nodiscard]] Rgb<S> operator()(const Vec3<S>& p) const noexcept {
        Rgb<S> sum(S(0)), through(S(1));
        for (auto layer = layers_.rbegin(); layer != layers_.rend(); ++layer) {
            const LayerColor<S> c = (*layer)(p);
            sum += through * c.color * (c.opacity() * layer->weight());
            through *= c.passed();
            if (max_component(through) <= S(0)) break;  // nothing below shows
        }
        return sum;
    }
    /// What the whole stack lets through at `p` to a surface behind it: the product of every
    /// layer's passed().
    [[nodiscard]] Rgb<S> passed(const Vec3<S>& p) const noexcept {
        Rgb<S> through(S(1));
        for (const PigmentLayer<S>& layer : layers_) through *= layer(p).passed();
        return through;
    }
    /// Per channel, no point is brighter than this (exact for colours the maps reach at their
    /// entries and between them).
    [[nodiscard]] Rgb<S> upper_bound() const noexcept { return bound_; }
    [[nodiscard]] const std::vector<PigmentLayer<S>>& layers() const noexcept { return layers_; }

private:
    /// From the bottom up: B = max over the layer's colours c of c.color * c.opacity() * weight +
    /// c.passed() * B_below. A colour between two map entries is a linear blend, so that
    /// expression is a quadratic in the blend fraction: its maximum over [0, 1] is exact.
    [[nodiscard]] Rgb<S> compute_bound() const noexcept {
        Rgb<S> below(S(0));
        for (const PigmentLayer<S>& layer : layers_) {
            if (layer.has_nested() || layer.is_image()) {  // each term at its own maximum: a bound
                const LayerEnvelope<S> env = layer.envelope();
                below = env.tinted * layer.weight() + env.passed * below;
                continue;
            }
            const auto& e = layer.entries();
            Rgb<S> best(S(0));
            for (int ch = 0; ch < 3; ++ch) {
                auto g = [&](const LayerColor<S>& c) {
                    return double(c.color[ch]) * double(c.opacity()) * double(layer.weight()[ch]) +
                           double(c.passed()[ch]) * double(below[ch]);
                };
                double m = 0;
                for (std::size_t i = 0; i < e.size(); ++i) {
                    m = std::max(m, g(e[i]));
                    if (i == 0 || layer.is_uniform()) continue;
                    const double g0 = g(e[i - 1]), gh = g(PigmentLayer<S>::blend(e[i - 1], e[i], S(0.5))), g1 = g(e[i]);
                    const double a = 2 * g0 - 4 * gh + 2 * g1, b = -3 * g0 + 4 * gh - g1;
                    if (a < 0) {
                        const double x = -b / (2 * a);
                        if (x > 0 && x < 1) m = std::max(m, (a * x + b) * x + g0);
                    }
                }
                best[ch] = S(m);
            }
            below = best;
        }
        return below;
    }

    std::vector<PigmentLayer<S>> layers_;
    Rgb<S> bound_{S(0)};
};

/// How much of the highlights a layered texture shows at a point, as POV-Ray lights each layer:
/// every layer with a highlight adds it dimmed by what the layers above it let through (their
/// passed(), POV-Ray's filCol), not by its own opacity. Exact for a stack whose highlighted
/// layers share one highlight (the material's): the sum over them of the product above. A
/// ReflectanceField (reflectance_field.hpp) that multiplies the material's highlights.
template <Scalar S> class LayeredHighlightWeight {
public:
    /// `layers` bottom first; `highlighted[i]`: layer i has the highlight. Throws
    /// std::invalid_argument when the sizes differ or no layer has one.
    LayeredHighlightWeight(std::vector<PigmentLayer<S>> layers, std::vector<bool> highlighted)
        : layers_(std::move(layers)), highlighted_(std::move(highlighted)) {
        if (layers_.size() != highlighted_.size() || std::find(highlighted_.begin(), highlighted_.end(), true) == highlighted_.end())
            throw std::invalid_argument("layered highlight: one flag per layer, at least one layer with a highlight");
        // What a layer lets through is at most its largest passed() over its colours (a blend
        // of two entries lies between them).
        Rgb<S> through(S(1));
        for (std::size_t i = layers_.size(); i-- > 0;) {
            if (highlighted_[i]) bound_ += through;
            through *= layers_[i].envelope().passed;
        }
    }

    [[nodiscard]] Rgb<S> operator()(const Vec3<S>& p) const noexcept {
        Rgb<S> sum(S(0)), through(S(1));
        for (std::size_t i = layers_.size(); i-- > 0;) {
            if (highlighted_[i]) sum += through;
            through *= layers_[i](p).passed();
            if (max_component(through) <= S(0)) break;
        }
        return sum;
    }
    [[nodiscard]] Rgb<S> upper_bound() const noexcept { return bound_; }

private:
    std::vector<PigmentLayer<S>> layers_;
    std::vector<bool> highlighted_;
    Rgb<S> bound_{S(0)};
};

}  // namespace photon
