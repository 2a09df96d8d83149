// SPDX-License-Identifier: MIT
#pragma once
// The mesh files a scene names (`mesh { obj "file.obj" }`), read in the build step (build.hpp,
// and export_pov.hpp, which writes their triangles out) through photon's OBJ reader,
// photon/io/obj_mesh.hpp (it needs photon::obj, i.e. tinyobjloader). The parser only records the
// file and where its name was written, so reading a scene never opens a mesh file; errors point
// at the file name in the scene, as they did when the parser read it.

#include <array>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#if defined(PHOTON_HAS_OBJ) && PHOTON_HAS_OBJ  // set by the CMake target photon::obj
#include <photon/io/obj_mesh.hpp>
#endif

#include "description.hpp"
#include "diagnostics.hpp"

namespace photon::dsl {

using MeshTriangles = std::vector<std::array<Vector3, 3>>;

/// `file`'s path as messages show it: relative to the working directory when it is below it.
[[nodiscard]] inline std::string display_path(const std::filesystem::path& file) {
    std::error_code ec;
    std::string display = file.lexically_normal().string();
    if (const auto rel = std::filesystem::proximate(file, ec); !ec && !rel.empty() && rel.native().rfind("..", 0) != 0)
        display = rel.lexically_normal().string();
    return display;
}

/// Reads each mesh file once, however many objects use it.
class MeshFiles {
public:
    using Warn = std::function<void(const SourceLocation&, const std::string&)>;
    explicit MeshFiles(Warn warn = {}) : warn_(std::move(warn)) {}

    /// The triangles of `file`. Throws dsl::Error at the file's name in the scene when the file
    /// cannot be found or read, or has no faces; its warnings (tinyobjloader's) go to `warn`.
    const MeshTriangles& triangles(const MeshFile& file) {
        auto& slot = read_[file.path];
        if (!slot) slot = std::make_shared<const MeshTriangles>(read(file));
        return *slot;
    }

private:
    [[nodiscard]] MeshTriangles read(const MeshFile& file) const {
#if defined(PHOTON_HAS_OBJ) && PHOTON_HAS_OBJ
        const std::string display = display_path(file.path);
        std::error_code ec;
        if (!std::filesystem::is_regular_file(file.path, ec))
            throw Error(file.at, "cannot find the mesh file \"" + file.written + "\" (looked for " + display + ")");
        ObjTriangles<double> obj;
        try {
            obj = read_obj<double>(std::filesystem::path(display));  // the same file, named as messages show it
        } catch (const ObjError& e) {
            throw Error(file.at, std::string("cannot read the mesh: ") + e.what());
        }
        if (warn_)
            for (const std::string& w : obj.warnings) warn_(file.at, display + ": " + w);
        if (obj.triangles.empty()) throw Error(file.at, "the mesh file " + display + " has no faces");
        MeshTriangles tris;
        tris.reserve(obj.triangles.size());
        for (const auto& t : obj.triangles)
            tris.push_back({obj.positions[t[0]], obj.positions[t[1]], obj.positions[t[2]]});
        return tris;
#else
        throw Error(file.at, "this program was built without OBJ support: `mesh { obj \"" + file.written +
                                 "\" }` needs photon::obj (tinyobjloader)");
#endif
    }

    Warn warn_;
    std::map<std::filesystem::path, std::shared_ptr<const MeshTriangles>> read_;
};

}  // namespace photon::dsl
