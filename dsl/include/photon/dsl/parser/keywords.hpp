// SPDX-License-Identifier: MIT
#pragma once
// The scene language's keyword tables, and the "did you mean" hints drawn from them.

#include <algorithm>
#include <array>
#include <cstddef>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

#include "../settings_table.hpp"

namespace photon::dsl::detail {

/// Edit distance, for "did you mean" hints.
[[nodiscard]] inline std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diag = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
            diag = up;
        }
    }
    return row[b.size()];
}

/// A list of words: a keyword table or a braced list written at the call.
struct Words {
    std::span<const std::string_view> list;
    Words() = default;
    Words(std::initializer_list<std::string_view> l) : list(l.begin(), l.size()) {}
    template <std::size_t N>
    Words(const std::string_view (&a)[N]) : list(a) {}
    template <std::size_t N>
    Words(const std::array<std::string_view, N>& a) : list(a) {}
    Words(const std::vector<std::string_view>& v) : list(v) {}
    [[nodiscard]] auto begin() const noexcept { return list.begin(); }
    [[nodiscard]] auto end() const noexcept { return list.end(); }
    [[nodiscard]] std::size_t size() const noexcept { return list.size(); }
};

/// Whether `w` is one of `list`, searched in order; the tables asked about every token are sets
/// (reserved_words() and the others below).
inline bool one_of(std::string_view w, Words list) { return std::find(list.begin(), list.end(), w) != list.end(); }

/// Keyword tables joined into one hash set, for the questions the interpreter asks of every
/// identifier it reads (is it reserved, does it start an expression): scanning the tables one
/// word at a time showed in the profile of POV-Ray's loop-heavy sample scenes (bench/README.md).
class WordSet {
public:
    WordSet(std::initializer_list<Words> tables) {
        for (const Words& t : tables) words_.insert(t.begin(), t.end());
    }
    [[nodiscard]] bool contains(std::string_view w) const { return words_.count(w) != 0; }

private:
    std::unordered_set<std::string_view> words_;
};

/// " (did you mean `x`?)" for the closest candidate within a small distance, or "".
[[nodiscard]] inline std::string suggest(std::string_view word, Words candidates) {
    std::string_view best;
    std::size_t best_d = std::max<std::size_t>(1, std::min<std::size_t>(2, word.size() / 3)) + 1;
    for (std::string_view c : candidates) {
        const std::size_t d = edit_distance(word, c);
        if (d < best_d) best_d = d, best = c;
    }
    return best.empty() ? std::string() : " (did you mean `" + std::string(best) + "`?)";
}

inline constexpr std::string_view object_keywords[] = {
    "sphere", "box",          "plane",       "triangle",   "smooth_triangle", "mesh",        "mesh2",
    "union",  "merge",        "difference",  "intersection", "object",        "light_source", "light_group",
    "cylinder", "cone",       "disc",        "torus",      "quadric",         "polygon",
    "prism", "text", "quartic", "cubic", "poly", "polynomial", "superellipsoid", "lathe", "sor", "height_field", "blob"};
inline constexpr std::string_view unsupported_objects[] = {
    "isosurface",
    "julia_fractal", "parametric",     "sphere_sweep",
    "bicubic_patch",  "ovus",       "lemon"};
/// Blend maps: declarable, and read in patterned pigments and textures (parser/patterns.hpp).
inline constexpr std::string_view blend_map_keywords[] = {"color_map",  "colour_map", "pigment_map", "texture_map",
                                                          "normal_map", "slope_map",  "density_map"};
inline constexpr std::string_view statement_keywords[] = {
    "camera",          "light_source", "global_settings", "background", "sphere", "box", "plane", "triangle",
    "smooth_triangle", "mesh",         "union",           "merge",      "difference", "intersection", "object",
    "cylinder",        "cone",         "disc",            "torus",      "quadric",    "polygon",
    "prism",           "text",         "quartic",         "cubic",      "poly",       "polynomial",
    "superellipsoid",  "lathe",        "sor",             "height_field", "blob"};
inline constexpr std::string_view color_keywords[] = {"color", "colour", "rgb",  "rgbf",   "rgbt",    "rgbft",
                                                      "red",   "green",  "blue", "filter", "transmit"};
inline constexpr std::string_view constants[] = {
    "pi",         "tau",          "x",           "y",           "z",            "t",             "u",
    "v",          "true",         "yes",         "on",          "false",        "no",            "off",
    "version",    "clock",        "image_width", "image_height", "clock_on",    "clock_delta",   "initial_clock",
    "final_clock", "frame_number", "initial_frame", "final_frame"};
/// Built-ins whose value is a number or a vector (string functions below).
inline constexpr std::string_view functions[] = {
    "abs",         "acos",        "acosh",      "asin",        "asinh",      "atan",        "atanh",
    "atan2",       "bitwise_and", "bitwise_or", "bitwise_xor", "ceil",       "cos",         "cosh",
    "defined",     "degrees",     "div",        "exp",         "floor",      "int",         "ln",
    "log",         "max",         "min",        "mod",         "pow",        "radians",     "select",
    "sin",         "sinh",        "sqrt",       "tan",         "tanh",       "vcross",      "vdot",
    "vlength",     "vnormalize",  "vrotate",    "vaxis_rotate", "vturbulence", "rand",      "seed",
    "strlen",      "val",         "asc",        "strcmp",     "file_exists", "inside"};
/// Built-ins whose value is a string.
inline constexpr std::string_view string_functions[] = {"concat", "str",    "chr",    "substr",
                                                        "strupr", "strlwr", "vstr",   "datetime"};
/// Words that only mean something inside `function { }`.
inline constexpr std::string_view function_words[] = {"function", "internal", "sum", "prod"};
/// Functions that ask an object's geometry (parser/object_queries.hpp).
inline constexpr std::string_view object_query_functions[] = {"trace", "min_extent", "max_extent"};
/// Kinds of `spline { }` (parser/splines.hpp).
inline constexpr std::string_view spline_keywords[] = {"spline", "linear_spline", "quadratic_spline", "cubic_spline",
                                                      "natural_spline"};
/// Arrays' keywords (parser/arrays.hpp); `dimensions` and `dimension_size` are functions.
inline constexpr std::string_view array_keywords[] = {"array", "mixed", "dimensions", "dimension_size"};
/// Blocks `#declare` reads (and skips) without evaluating them, so that the standard includes read on.
/// Declarable blocks photon reads and ignores (their warning comes where they are used). A
/// sky_sphere, a fog, a media and a density are declarable too, and read (parser/sky.hpp,
/// parser/fog.hpp, parser/media.hpp).
inline constexpr std::string_view ignored_declarable_blocks[] = {"rainbow"};
inline constexpr std::string_view modifier_keywords[] = {
    "texture",      "pigment",           "finish",          "normal",   "interior",
    "material",     "photons",           "translate",       "rotate",   "scale",
    "matrix",       "transform",         "no_shadow",       "no_image", "no_reflection",
    "no_radiosity", "double_illuminate", "inverse",         "hollow",   "sturm",
    "bounded_by",   "clipped_by",        "interior_texture"};
inline constexpr std::string_view finish_keywords[] = {
    "ambient",    "diffuse",         "brilliance", "specular", "roughness", "phong", "phong_size",
    "reflection", "conserve_energy", "emission",   "metallic", "irid",      "crand", "reflection_exponent",
    "subsurface"};
inline constexpr std::string_view light_keywords[] = {"spotlight",
                                                      "point_at",
                                                      "radius",
                                                      "falloff",
                                                      "tightness",
                                                      "area_light",
                                                      "adaptive",
                                                      "jitter",
                                                      "circular",
                                                      "orient",
                                                      "area_illumination",
                                                      "fade_distance",
                                                      "fade_power",
                                                      "shadowless",
                                                      "looks_like",
                                                      "photons",
                                                      "media_interaction",
                                                      "media_attenuation",
                                                      "parallel",
                                                      "cylinder",
                                                      "projected_through",
                                                      "translate",
                                                      "rotate",
                                                      "scale",
                                                      "matrix",
                                                      "transform"};
inline constexpr std::string_view camera_keywords[] = {
    "perspective", "location", "look_at",     "up",           "right",      "direction",
    "sky",         "angle",    "translate",   "rotate",       "scale",      "matrix",
    "transform",   "aperture", "focal_point", "blur_samples", "confidence", "variance"};
inline constexpr std::string_view global_keywords[] = {
    "assumed_gamma",   "ambient_light", "max_trace_level", "adc_bailout",     "radiosity",
    "photons",         "charset",       "number_of_waves", "noise_generator", "max_intersections",
    "irid_wavelength", "hf_gray_16",    "mm_per_unit",     "subsurface"};
/// photon's own global_settings items (POV-Ray does not know them), from the settings table.
inline constexpr auto photon_keywords = photon_setting_items();
inline constexpr std::string_view other_keywords[] = {"camera",
                                                      "global_settings",
                                                      "background",
                                                      "pigment",
                                                      "finish",
                                                      "interior",
                                                      "texture",
                                                      "ior",
                                                      "target",
                                                      "collect",
                                                      "pass_through",
                                                      "refraction",
                                                      "fresnel",
                                                      "albedo",
                                                      "count",
                                                      "spacing",
                                                      "gather",
                                                      "autostop",
                                                      "expand_thresholds",
                                                      "inside_vector",
                                                      "sky_sphere",
                                                      "fog",
                                                      "rainbow",
                                                      "media",
                                                      "orthographic",
                                                      "fisheye"};

/// The hot tables as sets (WordSet), each the union of the tables it names; built on first use
/// (a function's static: no order of initialisation between translation units to get wrong).
/// Names the user cannot declare:
inline const WordSet& reserved_words() {
    static const WordSet set{object_keywords,    unsupported_objects,      color_keywords,  constants,
                             functions,          object_query_functions,   spline_keywords, modifier_keywords,
                             finish_keywords,    camera_keywords,          global_keywords, light_keywords,
                             other_keywords,     array_keywords,           string_functions, function_words,
                             blend_map_keywords, ignored_declarable_blocks, {"sky_sphere", "fog", "media", "density"}};
    return set;
}
/// Words that begin a numeric expression by themselves (a declared name may too).
inline const WordSet& expression_words() {
    static const WordSet set{constants, functions, object_query_functions, color_keywords,
                             {"dimensions", "dimension_size"}};
    return set;
}
/// The constants (pi, clock, ...), which an expression reads as values.
inline const WordSet& constant_words() {
    static const WordSet set{constants};
    return set;
}
/// The numeric built-in functions, which an expression reads as calls.
inline const WordSet& builtin_function_words() {
    static const WordSet set{functions};
    return set;
}
/// The words that start a colour (color, rgb, red, ...), which an expression reads as one.
inline const WordSet& color_words() {
    static const WordSet set{color_keywords};
    return set;
}

}  // namespace photon::dsl::detail
