// SPDX-License-Identifier: MIT
#pragma once
// `mesh2`: POV-Ray's indexed triangle mesh, read into photon's mesh (its vertices and faces).
// Normals, uv coordinates and per-face textures are read and left out, with a warning.

#include "degradation.hpp"
#include "parser_class.hpp"

namespace photon::dsl::detail {

// MESH2: mesh2 { vertex_vectors { N, V {, V} } [normal_vectors {..}] [uv_vectors {..}] [texture_list {..}]
//                face_indices { N, <I, J, K> [, T [, T, T]] {, ...} } [normal_indices {..}] [uv_indices {..}]
//                MODIFIERS }
// The block is open; the modifiers and the `}` are read by parse_object.
inline MeshShape Parser::parse_mesh2(const Token& kw, Object& obj) {
    std::vector<Vector3> vertices;
    auto tris = std::make_shared<std::vector<std::array<Vector3, 3>>>();
    // The count is a plain number in practice, often followed by `<` on the next line without a
    // comma (`14 <-1, ...`), which an expression would read as a comparison.
    auto count_of = [&](const Token& block) {
        const std::string what = "the number of entries of `" + block.text + "`";
        const Token n = peek();
        if (n.kind != TokenKind::number) return std::size_t(parse_integer(what, 0, double(options_.max_primitives)));
        next();
        if (!(n.number >= 0 && n.number <= double(options_.max_primitives)) || n.number != std::floor(n.number))
            fail(n.location, what + " must be a whole number from 0 to " + std::to_string(options_.max_primitives) +
                                 ", found " + format_number(n.number));
        return std::size_t(n.number);
    };
    bool faces = false;
    obj.primitives = 0;
    for (;;) {
        const Token t = peek();
        if (t.is_identifier("vertex_vectors")) {
            next();
            const Nest nest(*this, t.location);
            open_block(t);
            const std::size_t n = count_of(t);
            vertices.reserve(n);
            for (std::size_t i = 0; i < n; ++i) {
                optional_comma();
                vertices.push_back(parse_vector("vertex " + std::to_string(i) + " of the mesh2"));
            }
            optional_comma();  // POV-Ray allows one after the last entry, as in its objects/mesh2.pov
            close_block(t, "no more vertices (`vertex_vectors` says " + std::to_string(n) + ")");
        } else if (t.is_identifier("face_indices")) {
            next();
            faces = true;
            const Nest nest(*this, t.location);
            open_block(t);
            const std::size_t n = count_of(t);
            for (std::size_t i = 0; i < n; ++i) {
                optional_comma();
                SourceLocation at;
                const Vector3 f = parse_vector("the vertex indices of face " + std::to_string(i), &at);
                std::array<Vector3, 3> tri;
                for (int k = 0; k < 3; ++k) {
                    const double index = f[k];
                    if (!(index >= 0 && index < double(vertices.size())) || index != std::floor(index))
                        fail(at, "vertex index " + format_number(index) + " of face " + std::to_string(i) +
                                     " is not one of the " + std::to_string(vertices.size()) +
                                     " vertices given before in `vertex_vectors`");
                    tri[std::size_t(k)] = vertices[std::size_t(index)];
                }
                tris->push_back(tri);
                // Texture indices into texture_list: one, or one per corner.
                while (accept_symbol(",")) {
                    if (peek().kind != TokenKind::number) break;
                    parse_float("a texture index of face " + std::to_string(i));
                }
                add_primitives(obj, 1, at);
            }
            optional_comma();
            close_block(t, "no more faces (`face_indices` says " + std::to_string(n) + ")");
        } else if (t.is_identifier("texture_list")) {
            next();
            const Nest nest(*this, t.location);
            open_block(t);
            const std::size_t n = count_of(t);
            for (std::size_t i = 0; i < n; ++i) {
                optional_comma();
                const Token tk = next();
                if (!tk.is_identifier("texture")) fail_expected("`texture` in `texture_list`", tk);
                parse_texture(tk, default_texture_);
            }
            optional_comma();
            close_block(t, "no more textures (`texture_list` says " + std::to_string(n) + ")");
            degrade(t.location, degraded::approximated_texture, "texture_list",
                    "`texture_list` is ignored: photon gives the mesh2 one texture");
        } else if (t.kind == TokenKind::identifier &&
                   one_of(t.text, {"normal_vectors", "uv_vectors", "normal_indices", "uv_indices"})) {
            next();
            const Nest nest(*this, t.location);
            skip_block(t);
            if (t.text == "normal_vectors")
                degrade(t.location, degraded::ignored_effect, t.text,
                        "`normal_vectors` are ignored: photon shades triangles flat");
        } else {
            break;
        }
    }
    if (!faces) fail_expected("`face_indices` in `mesh2`", peek());
    obj.primitives = tris->size();
    if (tris->empty()) fail(kw.location, "the `mesh2` has no faces");
    return MeshShape{std::move(tris), {}};
}

}  // namespace photon::dsl::detail
