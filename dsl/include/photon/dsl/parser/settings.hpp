// SPDX-License-Identifier: MIT
#pragma once
// global_settings: POV-Ray's own items, its photons block, and photon's own settings.

#include "degradation.hpp"
#include "parser_class.hpp"

namespace photon::dsl::detail {

inline void Parser::parse_global_settings(const Token& kw) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    GlobalSettings& g = scene_.settings;
    if (!g.at.known()) g.at = kw.location;
    PhotonSettings& p = g.photon;
    for (;;) {
        const Token t = peek();
        if (t.kind != TokenKind::identifier) break;
        const std::string& w = t.text;
        const bool photon_own = one_of(w, photon_keywords);
        if (!photon_own && !one_of(w, global_keywords)) break;
        next();
        g.written[w] = t.location;
        if (photon_own && !in_photon_guard())
            warn(t.location, "`" + w +
                                 "` is photon's own setting and POV-Ray stops at it: write it inside "
                                 "`#ifdef (photon_version) ... #end`");
        auto count = [&](const std::string& what) { return std::uint64_t(parse_integer(what, 0, 1e12)); };
        // The library's bounds (photon::SettingsLimits), so that they are reported where written.
        auto positive = [&](const std::string& what, double hi) { return unsigned(parse_integer(what, 1, hi)); };
        if (w == "assumed_gamma") {
            SourceLocation at;
            g.assumed_gamma = parse_float("`assumed_gamma`", &at);
            if (*g.assumed_gamma != 1.0)
                warn(at, "assumed_gamma " + format_number(*g.assumed_gamma) +
                             ": photon reads every colour as linear (as with assumed_gamma 1.0)");
        } else if (w == "ambient_light") {
            g.ambient_light = to_color(parse_expression_for("the ambient light colour")).rgb;
        } else if (w == "max_trace_level") {
            g.max_trace_level = unsigned(parse_integer("`max_trace_level`", 1, 256));
        } else if (w == "adc_bailout") {
            g.adc_bailout = parse_nonnegative("`adc_bailout`");
        } else if (w == "radiosity") {
            skip_block(t);
            g.radiosity = true;
        } else if (w == "photons") {
            parse_pov_photons(t);
        } else if (w == "subsurface") {
            skip_block(t);
            degrade(t.location, degraded::ignored_effect, "subsurface",
                    "`subsurface` is ignored: photon has no subsurface light transport");
        } else if (w == "charset" || w == "noise_generator" || w == "number_of_waves" || w == "max_intersections" ||
                   w == "irid_wavelength" || w == "hf_gray_16" || w == "mm_per_unit") {
            if (w == "irid_wavelength")
                parse_color("the wavelengths");
            else if (w == "charset")
                next();
            else if (w == "hf_gray_16")
                parse_optional_bool();
            else
                parse_float("`" + w + "`");
        } else if (w == "width") {
            p.width = unsigned(parse_integer("`width`", 1, 65536));
        } else if (w == "height") {
            p.height = unsigned(parse_integer("`height`", 1, 65536));
        } else if (w == "render_mode") {
            const Token m = next();
            const std::string mode =
                m.kind == TokenKind::string ? m.text : (m.kind == TokenKind::identifier ? m.text : "");
            if (mode != "rt" && mode != "pm" && mode != "pm_direct" && mode != "pm-direct" && mode != "sppm")
                fail_expected("`rt`, `pm`, `pm_direct` or `sppm` after `render_mode`", m);
            p.render_mode = mode == "pm-direct" ? "pm_direct" : mode;
        } else if (w == "global_photons") {
            p.global_photons = count("`global_photons`");
        } else if (w == "caustic_photons") {
            p.caustic_photons = count("`caustic_photons`");
        } else if (w == "global_estimate" || w == "caustic_estimate") {
            parse_estimate(t, w == "global_estimate" ? p.global_estimate : p.caustic_estimate);
        } else if (w == "max_photon_depth") {
            p.max_photon_depth = positive("`max_photon_depth`", 1e4);
        } else if (w == "final_gather") {
            p.final_gather = unsigned(parse_integer("`final_gather`", 0, 1e6));
        } else if (w == "shadow_samples") {
            p.shadow_samples = positive("`shadow_samples`", 1e6);
        } else if (w == "samples_per_pixel") {
            p.samples_per_pixel = positive("`samples_per_pixel`", 1e6);
        } else if (w == "irradiance_stride") {
            p.irradiance_stride = unsigned(parse_integer("`irradiance_stride`", 0, 1e6));
        } else if (w == "irradiance_cache") {
            SourceLocation at;
            const double a = parse_float("`irradiance_cache`", &at);
            if (!(a >= 0 && a <= 1)) fail(at, "`irradiance_cache` error must be from 0 (off) to 1, found " + format_number(a));
            p.irradiance_cache = a;
        } else if (w == "sppm_passes") {
            p.sppm_passes = positive("`sppm_passes`", 1e6);
        } else if (w == "sppm_photons") {
            p.sppm_photons = std::uint64_t(parse_integer("`sppm_photons`", 1, 2147483648.0));
        } else {  // seed
            p.seed = count("`seed`");
        }
    }
    close_block(
        kw,
        "a global setting (assumed_gamma, ambient_light, max_trace_level, adc_bailout, radiosity, photons"
        ", or photon's own: global_photons, caustic_photons, global_estimate, ...)",
        {"assumed_gamma", "ambient_light", "max_trace_level", "adc_bailout", "radiosity", "photons", "width",
         "height", "render_mode", "global_photons", "caustic_photons", "global_estimate", "caustic_estimate",
         "max_photon_depth", "final_gather", "shadow_samples", "samples_per_pixel", "irradiance_stride",
         "irradiance_cache", "sppm_passes", "sppm_photons", "seed"});
}

inline void Parser::parse_estimate(const Token& kw, EstimateDescription& e) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    for (;;) {
        const Token t = peek();
        if (t.is_identifier("count")) {
            next();
            e.count = unsigned(parse_integer("the photons per estimate after `count`", 1, 1e6));
        } else if (t.is_identifier("radius")) {
            next();
            SourceLocation at;
            e.radius = parse_float("the maximum radius after `radius`", &at);
            if (!(*e.radius > 0))
                fail(at, "the estimate radius must be positive, found " + format_number(*e.radius));
        } else if (t.is_identifier("flatten")) {
            next();
            SourceLocation at;
            e.flatten = parse_float("`flatten`", &at);
            if (!(*e.flatten >= 1)) fail(at, "`flatten` must be >= 1, found " + format_number(*e.flatten));
        } else if (t.is_identifier("probes")) {
            next();
            e.probes = unsigned(parse_integer("`probes`", 0, 1024));
        } else {
            break;
        }
    }
    close_block(kw, "`count`, `radius`, `flatten` or `probes`", {"count", "radius", "flatten", "probes"});
}

inline void Parser::parse_pov_photons(const Token& kw) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    PovPhotons ph = scene_.settings.photons.value_or(PovPhotons{});
    ph.at = kw.location;
    for (;;) {
        const Token t = peek();
        if (t.kind != TokenKind::identifier) break;
        const std::string& w = t.text;
        if (w == "count") {
            next();
            ph.count = std::uint64_t(parse_integer("the photon count", 0, 1e12));
        } else if (w == "spacing") {
            next();
            ph.spacing = parse_nonnegative("`spacing`");
        } else if (w == "gather") {
            next();
            ph.gather_min = unsigned(parse_integer("the minimum of `gather`", 0, 1e6));
            optional_comma();
            ph.gather_max = unsigned(parse_integer("the maximum of `gather`", 1, 1e6));
        } else if (w == "max_trace_level") {
            next();
            ph.max_trace_level = unsigned(parse_integer("`max_trace_level`", 1, 256));
        } else if (w == "radius") {
            next();
            double values[4] = {0, 0, 0, 0};
            int n = 0;
            while (n < 4 && starts_expression(peek())) {
                values[n++] = parse_float("the values of `radius`");
                if (!accept_symbol(",")) break;
            }
            if (n > 0 && values[0] > 0) ph.radius = values[0];
        } else if (one_of(w, {"jitter", "autostop", "adc_bailout"})) {
            next();
            parse_float("`" + w + "`");
            ph.ignored[w] = t.location;
        } else if (w == "expand_thresholds") {
            next();
            parse_float("`expand_thresholds`");
            optional_comma();
            parse_float("`expand_thresholds`");
            ph.ignored[w] = t.location;
        } else if (w == "media") {
            next();
            parse_float("`media`");
            while (accept_symbol(",")) parse_float("`media`");
            ph.ignored[w] = t.location;
        } else if (w == "save_file" || w == "load_file") {
            next();
            const Token s = next();
            if (s.kind != TokenKind::string) fail_expected("a file name in double quotes", s);
            warn(t.location, "`" + w + "` is ignored: photon always traces its photons");
        } else {
            break;
        }
    }
    close_block(
        kw, "a photons setting (spacing, count, gather, max_trace_level, radius, autostop, jitter)",
        {"spacing", "count", "gather", "max_trace_level", "radius", "autostop", "jitter", "expand_thresholds"});
    scene_.settings.photons = ph;
}

}  // namespace photon::dsl::detail
