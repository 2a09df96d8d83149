// SPDX-License-Identifier: MIT
#pragma once
// Objects: the shapes, union, CSG (difference, intersection, merge), `object { }`, meshes and the
// object modifiers.

#include "degradation.hpp"
#include "parser_class.hpp"

namespace photon::dsl::detail {

// The object's texture, made from the #default one when it has none yet: a pigment, finish or
// normal written alone goes into it.
inline Texture& Parser::ensure_texture(Object& obj) {
    if (!obj.texture) obj.texture = default_texture_;
    return *obj.texture;
}

// Counts `n` more primitives (objects, triangles) in `obj`, within ParseOptions::max_primitives.
inline void Parser::add_primitives(Object& obj, std::size_t n, const SourceLocation& at) {
    obj.primitives += n;
    if (obj.primitives > options_.max_primitives)
        fail(at,
             "the scene is too large: more than " + std::to_string(options_.max_primitives) + " objects and triangles");
}

// OBJECT: SHAPE { PARAMS MODIFIERS } | union|light_group { ... } | difference|intersection|merge { ... }
//       | object { OBJECT_ID|OBJECT MODIFIERS }
inline Object Parser::parse_object(const Token& kw) {
    const Nest nest(*this, kw.location);
    const std::string& w = kw.text;
    if (w == "light_source") return parse_light(kw);
    if (one_of(w, unsupported_objects)) return parse_skipped_object(kw);
    Object obj;
    obj.at = kw.location;
    open_block(kw);
    if (w == "sphere") {
        SphereShape s;
        s.center = parse_vector("the centre of the sphere");
        optional_comma();
        SourceLocation at;
        s.radius = parse_float("the radius of the sphere", &at);
        if (!(s.radius > 0)) fail(at, "sphere radius must be positive, found " + format_number(s.radius));
        obj.shape = s;
    } else if (w == "box") {
        BoxShape b;
        b.corner1 = parse_vector("the first corner of the box");
        optional_comma();
        b.corner2 = parse_vector("the second corner of the box");
        obj.shape = b;
    } else if (w == "plane") {
        PlaneShape p;
        SourceLocation at;
        p.normal = parse_vector("the normal of the plane", &at);
        if (glm::length(p.normal) == 0.0) fail(at, "the normal of the plane must not be zero");
        optional_comma();
        p.distance = parse_float("the distance of the plane from the origin");
        obj.shape = p;
    } else if (w == "cylinder") {
        parse_cylinder(obj);
    } else if (w == "cone") {
        parse_cone(obj);
    } else if (w == "disc") {
        parse_disc(obj);
    } else if (w == "torus") {
        parse_torus(obj);
    } else if (w == "quadric") {
        parse_quadric(obj);
    } else if (w == "polygon") {
        parse_polygon(obj);
    } else if (w == "prism") {
        parse_prism(obj);
    } else if (w == "text") {
        parse_text(obj);
    } else if (w == "quartic" || w == "cubic" || w == "poly" || w == "polynomial") {
        parse_polynomial(kw, obj);
    } else if (w == "superellipsoid") {
        parse_superellipsoid(obj);
    } else if (w == "lathe") {
        parse_lathe(obj);
    } else if (w == "sor") {
        parse_sor(obj);
    } else if (w == "blob") {
        parse_blob(kw, obj);
    } else if (w == "height_field") {
        parse_height_field(kw, obj);
    } else if (w == "triangle" || w == "smooth_triangle") {
        obj.shape = parse_triangle_corners(kw);
    } else if (w == "mesh") {
        auto tris = std::make_shared<std::vector<std::array<Vector3, 3>>>();
        std::optional<MeshFile> file;
        if (peek().is_identifier("obj")) file = parse_mesh_file(next());
        while (peek().is_identifier("triangle") || peek().is_identifier("smooth_triangle")) {
            const Token tk = next();
            const Nest inner(*this, tk.location);
            open_block(tk);
            tris->push_back(parse_triangle_corners(tk).vertices);
            if (peek().is_identifier("uv_vectors")) {  // uv_vectors UV, UV, UV: for uv_mapping textures
                const Token uv = next();
                for (int i = 0; i < 3; ++i) {
                    if (i > 0) optional_comma();
                    parse_vector("uv vector " + std::to_string(i + 1) + " of the triangle");
                }
                degrade(uv.location, degraded::ignored_effect, "uv_vectors",
                        "`uv_vectors` are ignored: photon has no uv mapping");
            }
            if (peek().is_identifier("texture")) {
                const Token tt = next();
                parse_texture(tt, default_texture_);
                degrade(tt.location, degraded::approximated_texture, "texture",
                        "a triangle's own `texture` in a `mesh` is ignored: photon gives the mesh one texture");
            }
            close_block(tk, "the triangle's corners");
            if (tris->size() > options_.max_primitives)
                fail(tk.location, "the scene is too large: more than " + std::to_string(options_.max_primitives) +
                                      " objects and triangles");
        }
        if (tris->empty() && !file) fail_expected("`triangle` or `obj \"file.obj\"` in `mesh`", peek());
        obj.primitives = std::max<std::size_t>(1, tris->size());  // the file's triangles are counted when built
        obj.shape = MeshShape{std::move(tris), std::move(file)};
    } else if (w == "mesh2") {
        obj.shape = parse_mesh2(kw, obj);
    } else if (w == "difference" || w == "intersection" || w == "merge") {
        obj.shape = parse_csg(kw, obj);
    } else if (w == "union" || w == "light_group") {
        // UNION: union { {OBJECT} MODIFIERS }
        // LIGHT_GROUP: light_group { {light_source | OBJECT | light_group | global_lights [BOOL]} MODIFIERS }
        UnionShape u;
        if (w == "light_group")
            degrade(kw.location, degraded::approximated_light, w,
                    "`light_group` is read as a union: photon does not keep light groups apart, so its lights "
                    "light the whole scene and the scene's lights light its objects");
        obj.primitives = 0;
        for (;;) {
            const Token& t = peek();
            if (w == "light_group" && t.is_identifier("global_lights")) {
                next();
                parse_optional_bool();
                continue;
            }
            if (t.kind != TokenKind::identifier || !is_object_keyword(t.text)) break;
            const Token ck = next();
            u.children.push_back(std::make_shared<const Object>(parse_object(ck)));
            add_primitives(obj, u.children.back()->primitives, ck.location);
        }
        if (u.children.empty())  // POV-Ray warns too ("Should have at least 2 objects in csg")
            warn(kw.location, "`" + w + "` without objects adds nothing to the scene");
        obj.shape = std::move(u);
        while (w == "light_group") {  // global_lights may come among the modifiers too
            parse_modifiers(kw, obj);
            if (!peek().is_identifier("global_lights")) break;
            next();
            parse_optional_bool();
        }
    } else {  // object
        const Token t = peek();
        if (t.kind == TokenKind::identifier && is_object_keyword(t.text)) {  // object { object { ... } } too
            obj = parse_object(next());
        } else {
            const Value* v = t.kind == TokenKind::identifier ? lookup(t.text) : nullptr;
            if (!v) {
                if (t.kind == TokenKind::identifier && !is_reserved(t.text))
                    fail(t.location, "undefined identifier `" + t.text + "`");
                fail_expected("an object identifier in `object`", t);
            }
            if (!std::holds_alternative<Object>(v->data))
                fail(t.location,
                     "expected an object identifier in `object`, found `" + t.text + "` (" + type_name(v->data) + ")");
            next();
            obj = std::get<Object>(v->data);
            if (const auto* skipped = std::get_if<SkippedShape>(&obj.shape))
                degrade(t.location, degraded::skipped_object, skipped->keyword,
                        "`" + t.text + "` is a `" + skipped->keyword + "` (declared at " + position_in(v->at, t.location) +
                            "): skipped, " +
                            (skipped->why.empty() ? "photon has no " + missing_shape(skipped->keyword) + " yet"
                                                  : skipped->why));
        }
        if (std::holds_alternative<LightSource>(obj.shape)) {
            while (try_transform(obj.transform)) {
            }
            close_block(kw, "a transformation", {"translate", "rotate", "scale", "matrix", "transform"});
            return obj;
        }
    }
    parse_modifiers(kw, obj);
    close_block(kw,
                "an object modifier (texture, pigment, finish, interior, photons, translate, rotate, scale, "
                "matrix, no_shadow)",
                modifier_keywords);
    return obj;
}

// CSG: difference|intersection|merge { OBJECT {OBJECT} MODIFIERS }
// Children before the modifiers, as in a union; POV-Ray warns below two, photon too.
inline CsgShape Parser::parse_csg(const Token& kw, Object& obj) {
    CsgShape c;
    const std::string& w = kw.text;
    c.operation = w == "difference"     ? CsgShape::Operation::difference
                  : w == "intersection" ? CsgShape::Operation::intersection
                                        : CsgShape::Operation::merge;
    obj.primitives = 0;
    while (peek().kind == TokenKind::identifier && is_object_keyword(peek().text)) {
        const Token ck = next();
        c.children.push_back(std::make_shared<const Object>(parse_object(ck)));
        add_primitives(obj, c.children.back()->primitives, ck.location);
    }
    if (c.children.empty()) fail_expected("an object in `" + w + "`", peek());
    if (c.children.size() == 1)  // as POV-Ray: "Should have at least 2 objects in csg"
        warn(kw.location, "`" + w + "` with one object is that object alone");
    return c;
}

// MESH_FILE: obj "file.obj"
// Recorded with its path relative to the scene file that names it, resolved and checked against
// the I/O restrictions now; the build step reads it (mesh_files.hpp), so reading a scene never
// opens a mesh file, and a missing one is the build's error.
inline MeshFile Parser::parse_mesh_file(const Token& kw) {
    const Token s = next();
    if (s.kind != TokenKind::string) fail_expected("a file name in double quotes after `" + kw.text + "`", s);
    const std::filesystem::path place = search_places(s.text, false).front();
    if (options_.read_include) return MeshFile{place, s.text, s.location};
    const std::filesystem::path resolved = resolved_path(place);
    if (!access_.permits(resolved, FileAccess::read)) fail(s.location, access_.refusal(s.text, FileAccess::read));
    return MeshFile{resolved, s.text, s.location};
}

// TRIANGLE_CORNERS: V [,] V [,] V after `triangle {`; V [,] N [,] V [,] N [,] V [,] N after
//   `smooth_triangle {` (the normals read and ignored)
inline TriangleShape Parser::parse_triangle_corners(const Token& kw) {
    TriangleShape t;
    const bool smooth = kw.text == "smooth_triangle";
    for (int i = 0; i < 3; ++i) {
        if (i > 0) optional_comma();
        t.vertices[std::size_t(i)] = parse_vector("corner " + std::to_string(i + 1) + " of the triangle");
        if (smooth) {
            optional_comma();
            parse_vector("the normal at corner " + std::to_string(i + 1));
        }
    }
    if (smooth)
        degrade(kw.location, degraded::ignored_effect, kw.text,
                "`smooth_triangle` normals are ignored: photon shades triangles flat");
    return t;
}

// MATERIAL: material { [MATERIAL_IDENT] {texture {..} | interior {..}} }
inline void Parser::parse_material(const Token& kw, Object& obj) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    if (MaterialBlock m; take_identifier(m, "a material identifier")) {
        if (m.texture) obj.texture = m.texture;
        if (m.interior) obj.interior = m.interior;
    }
    bool had_texture = false;
    for (;;) {
        const Token t = peek();
        if (t.is_identifier("texture") && had_texture && obj.texture)  // a layer on top of the first
            add_layer(*obj.texture, parse_texture(next(), default_texture_));
        else if (t.is_identifier("texture"))
            obj.texture = parse_texture(next(), default_texture_), had_texture = true;
        else if (t.is_identifier("interior"))
            obj.interior = parse_interior(next(), obj.interior.value_or(Interior{}));
        else
            break;
    }
    close_block(kw, "`texture` or `interior`", {"texture", "interior"});
}

// MODIFIERS: {TRANSFORMATION | texture {..} | pigment {..} | finish {..} | normal {..} | interior {..}
//   | material {..} | photons {..} | no_shadow | inverse | hollow BOOL | no_image | no_reflection
//   | no_radiosity | double_illuminate | uv_mapping | sturm BOOL | inside_vector V (a mesh's)
//   | interior_texture {..} | bounded_by {..} | clipped_by {..}}
inline void Parser::parse_modifiers(const Token& kw, Object& obj) {
    bool had_texture = false;
    for (;;) {
        const Token t = peek();
        if (t.kind != TokenKind::identifier) return;
        if (Transform step; try_transform(step)) {
            // POV-Ray moves the texture already given with the object, not one given after.
            obj.transform = obj.transform.then(step);
            if (obj.texture) transform_texture(*obj.texture, step);
            if (obj.interior) transform_interior(*obj.interior, step);  // its media's densities, as POV-Ray
            continue;
        }
        const std::string& w = t.text;
        if (w == "texture") {
            if (had_texture && obj.texture) {
                // POV-Ray layers each further texture on top of the first (the bottom one).
                add_layer(*obj.texture, parse_texture(next(), default_texture_));
                continue;
            }
            had_texture = true;
            obj.texture = parse_texture(next(), default_texture_);
        } else if (w == "pigment") {
            Texture& tex = ensure_texture(obj);
            tex.pigment = parse_pigment(next(), tex.pigment);
            tex.at = t.location;
        } else if (w == "finish") {
            Texture& tex = ensure_texture(obj);
            tex.finish = parse_finish(next(), tex.finish);
            if (!tex.at.known()) tex.at = t.location;
        } else if (w == "normal") {
            Texture& tex = ensure_texture(obj);
            tex.normal = parse_normal(next(), tex.normal.value_or(Normal{}));
        } else if (w == "interior") {
            obj.interior = parse_interior(next(), obj.interior.value_or(Interior{}));
        } else if (w == "material") {
            parse_material(next(), obj);
        } else if (w == "photons") {
            obj.photons = parse_object_photons(next());
        } else if (w == "no_shadow") {
            next();
            obj.no_shadow = true;
        } else if (w == "inverse") {
            next();
            obj.inverse = !obj.inverse;
        } else if (w == "hollow") {
            next();
            obj.hollow = parse_optional_bool();
        } else if (one_of(w, {"no_image", "no_reflection", "no_radiosity", "double_illuminate", "uv_mapping"})) {
            next();
            obj.ignored[w] = t.location;
            degrade(t.location, degraded::ignored_effect, w, "`" + w + "` is ignored by photon");
        } else if (w == "sturm") {
            next();
            parse_optional_bool();
        } else if (w == "inside_vector" && std::holds_alternative<MeshShape>(obj.shape)) {
            next();
            parse_vector("the inside vector of the mesh");
        } else if (w == "interior_texture") {
            next();
            parse_texture(t, default_texture_);
            degrade(t.location, degraded::approximated_texture, w,
                    "`interior_texture` is ignored: photon uses one texture for both sides");
        } else if (w == "bounded_by" || w == "clipped_by") {
            parse_bound_or_clip(next(), obj);
        } else if (is_object_keyword(w) &&
                   (std::holds_alternative<UnionShape>(obj.shape) || std::holds_alternative<CsgShape>(obj.shape))) {
            fail(t.location,
                 "objects in `" + kw.text + "` must come before its modifiers: found `" + w + "` after a modifier");
        } else {
            return;
        }
    }
}

// OBJECT_PHOTONS: photons { {target [F] | reflection BOOL | refraction BOOL | collect BOOL
//   | pass_through BOOL | split_union BOOL} }
inline ObjectPhotons Parser::parse_object_photons(const Token& kw) {
    const Nest nest(*this, kw.location);
    open_block(kw);
    ObjectPhotons p;
    p.at = kw.location;
    for (;;) {
        const Token t = peek();
        if (t.is_identifier("target")) {
            next();
            p.target = true;
            if (starts_expression(peek())) p.spacing_multiplier = parse_float("the spacing multiplier of `target`");
        } else if (t.is_identifier("reflection")) {
            next();
            p.reflection = parse_optional_bool();
        } else if (t.is_identifier("refraction")) {
            next();
            p.refraction = parse_optional_bool();
        } else if (t.is_identifier("collect")) {
            next();
            p.collect = parse_optional_bool();
        } else if (t.is_identifier("pass_through")) {
            next();
            p.pass_through = parse_optional_bool();
        } else if (t.is_identifier("split_union")) {
            next();
            parse_optional_bool();
        } else {
            break;
        }
    }
    close_block(kw, "`target`, `reflection`, `refraction`, `collect` or `pass_through`",
                {"target", "reflection", "refraction", "collect", "pass_through", "split_union"});
    return p;
}

}  // namespace photon::dsl::detail
