// SPDX-License-Identifier: MIT
#pragma once
// The image files of image_map (and of bump_map and height_field): the file's type keyword and
// name, its `gamma`, and image_map's options, in POV-Ray 3.7's syntax
// (source/parser/parser_materials.cpp, Parse_Image and Parse_Image_Map). The parser finds the
// file, beside the scene or on the include path, and records it; the build step reads it
// (image_files.hpp), so reading a scene never opens an image.

#include <algorithm>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "degradation.hpp"
#include "parser_class.hpp"

namespace photon::dsl::detail {

/// POV-Ray's image file type keywords.
inline constexpr std::string_view image_file_types[] = {"png", "jpeg", "gif", "tga", "ppm", "pgm",
                                                        "tiff", "exr", "hdr", "sys", "iff", "pot"};

// IMAGE_FILE: [TYPE] STRING [gamma (FLOAT | srgb | bt709)] [premultiplied BOOL]
// TYPE one of image_file_types; without one, the name's extension says the type.
inline ImageFile Parser::parse_image_file(const Token& kw) {
    ImageFile f;
    if (peek().kind == TokenKind::identifier && one_of(peek().text, image_file_types)) f.type = next().text;
    const Token name = parse_string_token("an image file name in double quotes");
    f.written = name.text;
    f.at = name.location;
    if (f.type.empty()) {
        std::string ext = std::filesystem::path(name.text).extension().string();
        if (!ext.empty()) ext.erase(0, 1);
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        f.type = ext == "jpg" ? "jpeg" : ext == "tif" ? "tiff" : ext;
        if (!one_of(f.type, image_file_types))
            fail(name.location, "`" + kw.text + "` needs the image's type (png, jpeg, gif, tga, ppm, pgm, tiff, exr, "
                                "hdr) before \"" + name.text + "\"");
    }
    const std::filesystem::path written(name.text);
    if (options_.read_include || f.type == "pot") {  // POV-Ray's Fractint POT files: photon skips them
        f.path = written;  // scenes read from memory name no files photon could open
    } else {
        f.path = find_readable(search_places(written, true), name);
        if (f.path.empty())
            fail(name.location, "cannot find the image file \"" + name.text + "\" (looked beside the scene and on the include path)");
    }
    for (;;) {
        if (peek().is_identifier("gamma")) {
            next();
            if (peek().is_identifier("srgb")) {
                next();
                f.gamma = 0.0;
            } else if (peek().is_identifier("bt709") || peek().is_identifier("bt2020")) {
                // Their curves are close to power 1/0.45 over most of the range.
                const Token curve = next();
                degrade(curve.location, degraded::approximated_pigment, "gamma",
                        "`gamma " + curve.text + "` is decoded as the power law 2.222 (the curve's linear toe near black differs)");
                f.gamma = 1 / 0.45;
            } else {
                SourceLocation at;
                const double g = parse_float("the image's decoding gamma", &at);
                if (!(g > 0)) fail(at, "the image's gamma must be positive, found " + format_number(g));
                f.gamma = g;
            }
        } else if (peek().is_identifier("premultiplied")) {
            const Token t = next();
            if (parse_float("whether the image's colours are premultiplied by alpha") != 0)
                degrade(t.location, degraded::approximated_pigment, "premultiplied",
                        "`premultiplied on` is ignored: photon reads the colours as not premultiplied");
        } else {
            return f;
        }
    }
}

// IMAGE_MAP: image_map { IMAGE_FILE {ATTRIBUTE} }
// ATTRIBUTE: once | interpolate N | map_type N | use_color | use_colour | use_index | repeat UV | offset UV
//          | (filter | transmit | alpha) (all FLOAT | INDEX, FLOAT)
inline std::shared_ptr<const ImageMapDesc> Parser::parse_image_map_block(const Token& kw) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    ImageMapDesc m;
    m.file = parse_image_file(kw);
    for (;;) {
        const Token t = peek();
        if (t.is_identifier("once")) {
            next();
            m.once = true;
        } else if (t.is_identifier("interpolate")) {
            next();
            SourceLocation at;
            const int n = int(std::lround(parse_float("the interpolation type after `interpolate` (2 or 4)", &at)));
            if (n == 3) {  // POV-Ray's bicubic: photon blends bilinearly
                degrade(at, degraded::approximated_pigment, "interpolate",
                        "`interpolate 3` (bicubic) is read as 2 (bilinear): photon has no bicubic image interpolation");
                m.interpolate = 2;
            } else if (n == 2 || n == 4) {
                m.interpolate = n;
            } else {
                fail(at, "`interpolate` must be 2 (bilinear), 3 (bicubic) or 4 (normalized distance), found " + std::to_string(n));
            }
        } else if (t.is_identifier("map_type")) {
            next();
            SourceLocation at;
            const int n = int(std::lround(parse_float("the mapping after `map_type`", &at)));
            if (n == 7)
                fail(at, "`map_type 7` (angular) is not one photon maps: use 0 (planar), 1 (spherical), 2 (cylindrical) "
                         "or 5 (torus)");
            if (n != 0 && n != 1 && n != 2 && n != 5)
                fail(at, "`map_type` must be 0 (planar), 1 (spherical), 2 (cylindrical) or 5 (torus), found " + std::to_string(n));
            m.map_type = n;
        } else if (t.is_identifier("use_color") || t.is_identifier("use_colour")) {
            next();
        } else if (t.is_identifier("use_index")) {
            next();
            degrade(t.location, degraded::approximated_pigment, "use_index",
                    "`use_index` is ignored: photon reads a palette image as its colours");
        } else if (t.is_identifier("repeat") || t.is_identifier("offset")) {
            next();
            parse_expression_for("the value of `" + t.text + "`");
            degrade(t.location, degraded::approximated_pigment, t.text,
                    "image_map's `" + t.text + "` is ignored (POV-Ray 3.7 leaves it undocumented)");
        } else if (t.is_identifier("filter") || t.is_identifier("transmit") || t.is_identifier("alpha")) {
            next();
            const bool transmit = t.text == "transmit";
            if (peek().is_identifier("all")) {
                next();
                SourceLocation at;
                const double v = parse_float("the value of `" + t.text + " all`", &at);
                if (!(v >= 0 && v <= 1)) fail(at, "`" + t.text + " all` must lie in [0, 1], found " + format_number(v));
                (transmit ? m.transmit_all : m.filter_all) = v;
            } else {
                const int index = int(parse_float("the palette index after `" + t.text + "`") + 0.01);
                optional_comma();
                const double v = parse_float("the value of `" + t.text + "` for palette entry " + std::to_string(index));
                (transmit ? m.transmit_index : m.filter_index).push_back({index, v});
                degrade(t.location, degraded::approximated_pigment, t.text,
                        "`" + t.text + " " + std::to_string(index) +
                            ", ...` is ignored: photon reads a palette image as its colours, without its indices");
            }
        } else {
            break;
        }
    }
    if (m.filter_all + m.transmit_all > 1 + 1e-9)
        fail(kw.location, "image_map's `filter all` and `transmit all` add up to more than 1");
    close_block(kw, "an image_map option (once, interpolate, map_type, filter, transmit)");
    return std::make_shared<const ImageMapDesc>(std::move(m));
}

// BUMP_MAP: bump_map { IMAGE_FILE {once | map_type N | interpolate N | bump_size FLOAT | use_color
//                                  | use_colour | use_index | repeat UV | offset UV} }
inline std::shared_ptr<const ImageMapDesc> Parser::parse_bump_map_block(const Token& kw, double& bump_size) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    ImageMapDesc m;
    m.file = parse_image_file(kw);
    for (;;) {
        const Token t = peek();
        if (t.is_identifier("once")) {
            next();
            m.once = true;
        } else if (t.is_identifier("map_type") || t.is_identifier("interpolate")) {
            next();
            SourceLocation at;
            const int n = int(std::lround(parse_float("the value of `" + t.text + "`", &at)));
            if (t.text == "map_type") {
                if (n != 0 && n != 1 && n != 2 && n != 5)
                    fail(at, "`map_type` must be 0 (planar), 1 (spherical), 2 (cylindrical) or 5 (torus), found " +
                                 std::to_string(n));
                m.map_type = n;
            } else {
                if (n != 0 && n != 2 && n != 3 && n != 4)
                    fail(at, "`interpolate` must be 2 (bilinear), 3 (bicubic) or 4 (normalized distance), found " +
                                 std::to_string(n));
                if (n == 3)
                    degrade(at, degraded::approximated_texture, "interpolate",
                            "`interpolate 3` (bicubic) is read as 2 (bilinear): photon has no bicubic image interpolation");
                m.interpolate = n == 3 ? 2 : n;
            }
        } else if (t.is_identifier("bump_size")) {
            next();
            bump_size = parse_float("the bump size after `bump_size`");
        } else if (t.is_identifier("use_color") || t.is_identifier("use_colour") || t.is_identifier("use_index")) {
            next();
            m.use_index = t.text == "use_index";
        } else if (t.is_identifier("repeat") || t.is_identifier("offset")) {
            next();
            parse_expression_for("the value of `" + t.text + "`");
            degrade(t.location, degraded::approximated_texture, t.text,
                    "bump_map's `" + t.text + "` is ignored (POV-Ray 3.7 leaves it undocumented)");
        } else {
            break;
        }
    }
    close_block(kw, "a bump_map option (once, map_type, interpolate, bump_size, use_index)");
    return std::make_shared<const ImageMapDesc>(std::move(m));
}

// HEIGHT_FIELD: height_field { IMAGE_FILE {smooth | water_level FLOAT | hierarchy BOOL} MODIFIERS }
//             | height_field { function W, H { FUNCTION } ... } (skipped)
inline void Parser::parse_height_field(const Token& kw, Object& obj) {
    HeightFieldShape h;
    const bool function = peek().is_identifier("function");
    if (function) {
        // The function form samples a function of x and y on a W x H grid; photon reads height
        // fields from image files only, for now.
        const Token fn = next();
        parse_float("the width of the height field's grid");
        optional_comma();
        parse_float("the depth of the height field's grid");
        const Nest nest(*this, fn.location);
        skip_block(fn);
    } else {
        h.file = parse_image_file(kw);
    }
    for (;;) {
        const Token t = peek();
        if (t.is_identifier("smooth")) {
            next();
            h.smooth = true;
        } else if (t.is_identifier("water_level")) {
            next();
            SourceLocation at;
            h.water_level = parse_float("the water level of the height field", &at);
            if (!std::isfinite(h.water_level)) fail(at, "the water level must be finite");
        } else if (t.is_identifier("hierarchy")) {  // POV-Ray's bounding blocks: photon walks the grid itself
            next();
            parse_float("whether the height field builds a hierarchy");
        } else {
            break;
        }
    }
    if (!function && h.file.type == "pot") {
        degrade(kw.location, degraded::skipped_object, "height_field",
                "`height_field { pot ... }` is skipped: photon does not read Fractint POT files (use png)");
        obj.shape = SkippedShape{"height_field", "photon does not read Fractint POT files"};
        return;
    }
    if (function) {
        degrade(kw.location, degraded::skipped_object, "height_field",
                "`height_field { function ... }` is skipped: photon reads height fields from image files only");
        obj.shape = SkippedShape{"height_field", "photon reads height fields from image files only"};
        return;
    }
    obj.shape = h;
}

}  // namespace photon::dsl::detail
