// SPDX-License-Identifier: MIT
#pragma once
// The TrueType fonts of text objects, read in the build step (build.hpp) through FreeType, with
// POV-Ray 3.7's placing of glyphs (source/core/shape/truetype.cpp, ProcessNewTTF): coordinates in
// em units (font units / units per em), baseline at y = 0, the first glyph moved so its left edge
// is at x = 0, each next one at the pen plus the pair's kerning (FreeType reads the same `kern`
// table POV-Ray reads, clamped as POV-Ray clamps it to one em), the pen moving by the advance
// plus kerning, and `offset` added after every glyph. FreeType is needed only here (the target
// photon::fonts defines PHOTON_HAS_FREETYPE); without it a text object is a located error.

#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#if defined(PHOTON_HAS_FREETYPE) && PHOTON_HAS_FREETYPE
#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H
#endif

#include "description.hpp"
#include "diagnostics.hpp"
#include "mesh_files.hpp"

namespace photon::dsl {

/// The contours of a text's glyphs, placed, in em units.
using GlyphContours = std::vector<std::vector<OutlineCurve>>;

/// The code points of UTF-8 text; a byte that starts no valid sequence stands for itself (Latin-1).
[[nodiscard]] inline std::vector<std::uint32_t> code_points(const std::string& text) {
    std::vector<std::uint32_t> out;
    for (std::size_t i = 0; i < text.size();) {
        const auto b = static_cast<unsigned char>(text[i]);
        const int extra = b >= 0xF0 && b < 0xF8 ? 3 : b >= 0xE0 ? 2 : b >= 0xC0 ? 1 : 0;
        std::uint32_t c = extra == 0 ? b : b & (0x3Fu >> extra);
        bool valid = i + std::size_t(extra) < text.size() + (extra == 0 ? 1 : 0);
        for (int k = 1; valid && k <= extra; ++k) {
            const auto n = static_cast<unsigned char>(text[i + std::size_t(k)]);
            valid = (n & 0xC0) == 0x80;
            c = (c << 6) | (n & 0x3F);
        }
        if (!valid || b >= 0xF8 || (b >= 0x80 && b < 0xC0)) c = b, valid = true, out.push_back(c), ++i;
        else out.push_back(c), i += std::size_t(extra) + 1;
    }
    return out;
}

/// Opens each font once, however many texts use it.
class FontFiles {
public:
    FontFiles() = default;
    FontFiles(const FontFiles&) = delete;
    FontFiles& operator=(const FontFiles&) = delete;
    ~FontFiles() {
#if defined(PHOTON_HAS_FREETYPE) && PHOTON_HAS_FREETYPE
        for (auto& [path, face] : faces_) FT_Done_Face(face);
        if (library_) FT_Done_FreeType(library_);
#endif
    }

    /// The outlines of `text`'s glyphs, placed (all at z = 0: POV-Ray moves a glyph by the x and y
    /// of the offsets only, though it adds their z up too). Throws dsl::Error at the font's name in the scene
    /// when the font cannot be read (or photon was built without FreeType).
    [[nodiscard]] GlyphContours set(const TextShape& text);

private:
#if defined(PHOTON_HAS_FREETYPE) && PHOTON_HAS_FREETYPE
    FT_Face face(const FontFile& file);
    FT_Library library_ = nullptr;
    std::map<std::filesystem::path, FT_Face> faces_;
#endif
};

#if defined(PHOTON_HAS_FREETYPE) && PHOTON_HAS_FREETYPE

inline FT_Face FontFiles::face(const FontFile& file) {
    if (const auto it = faces_.find(file.path); it != faces_.end()) return it->second;
    if (!library_ && FT_Init_FreeType(&library_) != 0) throw Error(file.at, "cannot start FreeType to read fonts");
    FT_Face f = nullptr;
    if (FT_New_Face(library_, file.path.string().c_str(), 0, &f) != 0 || !(f->face_flags & FT_FACE_FLAG_SCALABLE))
        throw Error(file.at, "cannot read the font file \"" + file.written + "\" (" + display_path(file.path) +
                                 ") as a TrueType font");
    faces_[file.path] = f;
    return f;
}

inline GlyphContours FontFiles::set(const TextShape& text) {
    FT_Face f = face(text.font);
    const double em = 1.0 / double(f->units_per_EM);
    GlyphContours contours;
    glm::dvec3 pen(0.0);  // POV-Ray's total_offset
    FT_UInt previous = 0;
    bool first = true;
    for (const std::uint32_t c : code_points(text.text)) {
        const FT_UInt glyph = FT_Get_Char_Index(f, c);  // 0, the font's "missing" glyph, as POV-Ray
        if (FT_Load_Glyph(f, glyph, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) != 0)
            throw Error(text.font.at, "cannot read glyph " + std::to_string(glyph) + " of the font \"" + text.font.written + "\"");
        const FT_GlyphSlot g = f->glyph;
        FT_BBox box;
        FT_Outline_Get_CBox(&g->outline, &box);
        const double advance = double(g->metrics.horiAdvance), lsb = double(g->metrics.horiBearingX);
        const double x_min = g->outline.n_points > 0 ? double(box.xMin) : 0.0;
        glm::dvec2 at(pen.x, pen.y);
        if (first) {
            at.x = -x_min * em;
            pen.x = (advance - lsb) * em;
        } else {
            FT_Vector kern{0, 0};
            if (FT_HAS_KERNING(f)) FT_Get_Kerning(f, previous, glyph, FT_KERNING_UNSCALED, &kern);
            const double kx = std::max(double(kern.x), -double(f->units_per_EM));
            at.x = pen.x + (lsb - x_min + kx) * em;
            pen.x += (advance + kx) * em;
        }
        pen += text.offset;
        first = false;
        previous = glyph;
        if (g->outline.n_contours == 0) continue;
        // FreeType's walk of the outline gives its implied on-curve points and closes each contour.
        struct Walk {
            std::vector<std::vector<OutlineCurve>>* out;
            glm::dvec2 shift, current;
            double scale;
            glm::dvec2 point(const FT_Vector* v) const { return shift + scale * glm::dvec2(double(v->x), double(v->y)); }
        } walk{&contours, at, glm::dvec2(0.0), em};
        FT_Outline_Funcs funcs{};
        funcs.move_to = [](const FT_Vector* to, void* user) {
            auto& w = *static_cast<Walk*>(user);
            if (w.out->empty() || !w.out->back().empty()) w.out->emplace_back();
            w.current = w.point(to);
            return 0;
        };
        funcs.line_to = [](const FT_Vector* to, void* user) {
            auto& w = *static_cast<Walk*>(user);
            const glm::dvec2 p = w.point(to);
            if (p != w.current) w.out->back().push_back({{w.current, p, {}, {}}, 1});
            w.current = p;
            return 0;
        };
        funcs.conic_to = [](const FT_Vector* control, const FT_Vector* to, void* user) {
            auto& w = *static_cast<Walk*>(user);
            const glm::dvec2 p = w.point(to);
            w.out->back().push_back({{w.current, w.point(control), p, {}}, 2});
            w.current = p;
            return 0;
        };
        funcs.cubic_to = [](const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
            auto& w = *static_cast<Walk*>(user);
            const glm::dvec2 p = w.point(to);
            w.out->back().push_back({{w.current, w.point(c1), w.point(c2), p}, 3});
            w.current = p;
            return 0;
        };
        if (FT_Outline_Decompose(&g->outline, &funcs, &walk) != 0)
            throw Error(text.font.at, "cannot read the outline of glyph " + std::to_string(glyph) + " of the font \"" +
                                          text.font.written + "\"");
    }
    contours.erase(std::remove_if(contours.begin(), contours.end(), [](const auto& k) { return k.empty(); }),
                   contours.end());
    return contours;
}

#else

inline GlyphContours FontFiles::set(const TextShape& text) {
    throw Error(text.font.at, "photon was built without FreeType, so it cannot read the font \"" + text.font.written +
                                  "\" (install libfreetype-dev and configure again)");
}

#endif

}  // namespace photon::dsl
