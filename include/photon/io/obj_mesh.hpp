// SPDX-License-Identifier: MIT
#pragma once
// Wavefront OBJ meshes into TriangleMesh, read by tinyobjloader. This header is the only part of
// photon that needs tinyobjloader: link the CMake target photon::obj to use it.
//
//   const auto mesh = photon::load_obj_mesh<float>("bunny.obj");   // throws photon::ObjError
//
// Only geometry is read: vertex positions and faces (polygons are fanned into triangles; every
// object and group goes into the one mesh). Normals, texture coordinates and materials are
// ignored, since photon shades triangles flat with one material per mesh.

#include <tiny_obj_loader.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "../geometry/triangle_mesh.hpp"

namespace photon {

/// An OBJ file that cannot be used. what() reads `file:line: message`, or `file: message` when
/// no line applies (a missing file); line() is 0 then.
class ObjError : public std::runtime_error {
public:
    ObjError(const std::string& file, std::size_t line, const std::string& message)
        : std::runtime_error(file + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " + message),
          file_(file), line_(line), message_(message) {}
    [[nodiscard]] const std::string& file() const noexcept { return file_; }
    [[nodiscard]] std::size_t line() const noexcept { return line_; }
    /// The message without the location.
    [[nodiscard]] const std::string& message() const noexcept { return message_; }

private:
    std::string file_;
    std::size_t line_;
    std::string message_;
};

/// The triangles of an OBJ file, indexed as TriangleMesh takes them.
template <Scalar S> struct ObjTriangles {
    std::vector<Vec3<S>> positions;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<std::string> warnings;  ///< tinyobjloader's (a missing .mtl file, say); the mesh is usable
};

/// Parses OBJ text; `name` is used in error messages. Throws ObjError on a malformed statement,
/// a face of fewer than three vertices, a vertex index out of range or a non-finite position.
template <Scalar S> [[nodiscard]] ObjTriangles<S> parse_obj(const std::string& text, const std::string& name = "<string>");

/// Reads an OBJ file (materials are not loaded). Throws ObjError as parse_obj, and when the file
/// cannot be read.
template <Scalar S> [[nodiscard]] ObjTriangles<S> read_obj(const std::filesystem::path& file);

/// read_obj, then the mesh and its BVH.
template <Scalar S>
[[nodiscard]] TriangleMesh<S> load_obj_mesh(const std::filesystem::path& file, BvhConfig config = {}) {
    ObjTriangles<S> obj = read_obj<S>(file);
    return TriangleMesh<S>(std::move(obj.positions), std::move(obj.triangles), config);
}

namespace detail {

/// 1-based line of the `index`-th (0-based) statement with keyword `keyword` ("v", "f"), or 0.
/// tinyobjloader keeps faces and vertices in file order but not their lines, so errors found
/// after parsing count statements to name the line.
inline std::size_t obj_statement_line(const std::string& text, const std::string& keyword, std::size_t index) {
    std::istringstream in(text);
    std::string line;
    for (std::size_t number = 1; std::getline(in, line); ++number) {
        const std::size_t start = line.find_first_not_of(" \t");
        if (start == std::string::npos || line.compare(start, keyword.size(), keyword) != 0) continue;
        const std::size_t after = start + keyword.size();
        if (after < line.size() && line[after] != ' ' && line[after] != '\t') continue;  // "vn", "fo"
        if (index-- == 0) return number;
    }
    return 0;
}

/// tinyobjloader silently drops faces of fewer than three vertices, which would also break
/// obj_statement_line's counting: such a face is an error, found before parsing.
inline void check_face_sizes(const std::string& text, const std::string& name) {
    std::istringstream in(text);
    std::string line;
    for (std::size_t number = 1; std::getline(in, line); ++number) {
        std::istringstream words(line.substr(0, line.find('#')));
        std::string word;
        if (!(words >> word) || word != "f") continue;
        std::size_t corners = 0;
        while (words >> word) ++corners;
        if (corners < 3)
            throw ObjError(name, number, "a face needs at least 3 vertices, this one has " + std::to_string(corners));
    }
}

/// tinyobjloader's messages end in "line N.)" or "line: N": split that off into our location.
[[noreturn]] inline void throw_tinyobj_error(const std::string& name, const std::string& error) {
    std::string message = error.substr(0, error.find('\n'));
    std::size_t line = 0;
    std::smatch m;
    if (std::regex_search(message, m, std::regex(R"(\.?\s*line:?\s*([0-9]+)\.?\)?\s*$)"))) {
        line = std::stoul(m[1].str());
        message = m.prefix().str();
        // "Failed parse `f' line(e.g. zero value for face index" -> "... line (e.g. ...)"
        if (const auto open = message.rfind('('); open != std::string::npos) {
            if (open > 0 && message[open - 1] != ' ') message.insert(open, " ");
            message += ')';
        }
    }
    throw ObjError(name, line, message.empty() ? "tinyobjloader cannot parse the file" : message);
}

template <Scalar S>
ObjTriangles<S> obj_triangles(const tinyobj::ObjReader& reader, const std::string& name, const std::string& text) {
    ObjTriangles<S> out;
    std::istringstream warnings(reader.Warning());
    for (std::string w; std::getline(warnings, w);)
        if (!w.empty()) out.warnings.push_back(w);

    const std::vector<tinyobj::real_t>& v = reader.GetAttrib().vertices;
    const std::size_t vertex_count = v.size() / 3;
    if (vertex_count > std::size_t(std::numeric_limits<std::uint32_t>::max()))
        throw ObjError(name, 0, "more than 2^32 - 1 vertices");
    out.positions.reserve(vertex_count);
    for (std::size_t i = 0; i < vertex_count; ++i) {
        const Vec3<S> p{S(v[3 * i]), S(v[3 * i + 1]), S(v[3 * i + 2])};  // braces: with parentheses clang reads a function declaration
        if (!is_finite(p))
            throw ObjError(name, obj_statement_line(text, "v", i), "vertex " + std::to_string(i + 1) + " is not finite");
        out.positions.push_back(p);
    }

    std::size_t face = 0;  // across all shapes, in file order
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        std::size_t offset = 0;
        for (const unsigned char corners : shape.mesh.num_face_vertices) {
            auto fail = [&](const std::string& message) -> void {
                throw ObjError(name, obj_statement_line(text, "f", face), message);
            };
            if (corners < 3) fail("a face needs at least 3 vertices, this one has " + std::to_string(corners));
            std::array<std::uint32_t, 256> idx{};
            for (unsigned k = 0; k < corners; ++k) {
                const int i = shape.mesh.indices[offset + k].vertex_index;
                if (i < 0 || std::size_t(i) >= vertex_count)
                    fail("the face refers to vertex " + std::to_string(i < 0 ? i : i + 1) + ", but the file has " +
                         std::to_string(vertex_count) + " vertices before it");
                idx[k] = static_cast<std::uint32_t>(i);
            }
            for (unsigned k = 1; k + 1 < corners; ++k) out.triangles.push_back({idx[0], idx[k], idx[k + 1]});
            offset += corners;
            ++face;
        }
    }
    return out;
}

inline tinyobj::ObjReaderConfig obj_geometry_only() {
    tinyobj::ObjReaderConfig config;
    config.triangulate = false;  // fanned here, so that face k is still the k-th `f` line
    config.vertex_color = false;
    return config;
}

}  // namespace detail

template <Scalar S> ObjTriangles<S> parse_obj(const std::string& text, const std::string& name) {
    detail::check_face_sizes(text, name);
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(text, "", detail::obj_geometry_only())) detail::throw_tinyobj_error(name, reader.Error());
    return detail::obj_triangles<S>(reader, name, text);
}

namespace detail {
/// read_obj with `name` standing for the file in messages.
template <Scalar S> ObjTriangles<S> parse_obj_file(const std::filesystem::path& file, const std::string& name) {
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec)) throw ObjError(name, 0, "cannot read the file: it is a directory");
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        const bool exists = std::filesystem::exists(file, ec);
        throw ObjError(name, 0, exists ? "cannot open the file" : "cannot open the file: it does not exist");
    }
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) throw ObjError(name, 0, "cannot read the file");
    // Parsing from memory keeps the text for locating errors and skips the .mtl files, which
    // photon would not use.
    return parse_obj<S>(buffer.str(), name);
}
}  // namespace detail

template <Scalar S> ObjTriangles<S> read_obj(const std::filesystem::path& file) {
    return detail::parse_obj_file<S>(file, file.string());
}

}  // namespace photon
