// SPDX-License-Identifier: MIT
// Mesh files are read in the build step, not by the parser: the description records the file,
// resolved against the scene file that names it, and where its name is written; build() and
// export_pov() read it, with errors at the name and the scene-size bound counting every use.

#include <catch2/catch.hpp>

#include "dsl_test_util.hpp"

#include <filesystem>
#include <string>

using namespace dsl_test;
using Catch::Matchers::Contains;

TEST_CASE("the parser records a mesh file without opening it", "[dsl][mesh][obj]") {
    ScratchDir dir;
    const auto scene =
        dir.write("sub/scene.pov", std::string(stage) + "mesh {\n  obj \"meshes/none.obj\"\n  triangle { 0, x, y }\n}\n");
    const auto desc = dsl::parse_file(scene);  // the file does not exist: no error yet
    REQUIRE(desc.objects.size() == 2);
    const auto& mesh = std::get<dsl::MeshShape>(desc.objects[1].shape);
    REQUIRE(mesh.file);
    CHECK(mesh.file->written == "meshes/none.obj");
    CHECK(mesh.file->path.lexically_normal() == (dir.path() / "sub/meshes/none.obj").lexically_normal());
    CHECK(mesh.file->at.line == 4);
    CHECK(mesh.file->at.column == 7);
    CHECK(mesh.triangles->size() == 1);
    try {
        (void)dsl::build<float>(desc);
        FAIL("built a scene whose mesh file is missing");
    } catch (const dsl::Error& e) {
        CHECK(e.location().line == 4);
        CHECK(e.location().column == 7);
        CHECK_THAT(e.message(), Contains("cannot find the mesh file \"meshes/none.obj\"") ||
                                    Contains("built without OBJ support"));
    }
    CHECK_THROWS_AS(dsl::export_pov(desc), dsl::Error);
}

#if defined(PHOTON_HAS_OBJ) && PHOTON_HAS_OBJ
TEST_CASE("a mesh file is read at build time, with the mesh's own triangles, and bounded for every use",
          "[dsl][mesh][obj]") {
    ScratchDir dir;
    std::filesystem::create_directories(dir.path() / "meshes");
    std::filesystem::copy_file(std::string(PHOTON_TEST_DATA_DIR) + "/tetrahedron.obj", dir.path() / "meshes/tet.obj");
    const auto scene = dir.write("scene.pov", std::string(stage) +
                                                  "#declare M = mesh { obj \"meshes/tet.obj\" triangle { 0, x, y } }\n"
                                                  "object { M }\nobject { M translate 5 * x }\n");
    const auto desc = dsl::parse_file(scene);
    const auto b = dsl::build<double>(desc);
    REQUIRE(b.scene.objects().size() == 2);
    for (const auto& o : b.scene.objects()) CHECK(std::get<photon::TriangleMesh<double>>(o.shape).triangle_count() == 5);

    dsl::BuildOptions small;
    small.max_primitives = 6;  // 4 triangles of the file per use: the second use passes the bound
    try {
        (void)dsl::build<double>(desc, small);
        FAIL("no size error");
    } catch (const dsl::Error& e) {
        CHECK(e.location().line == 3);
        CHECK(e.location().column == 25);
        CHECK(e.message() == "the scene is too large: more than 6 objects and triangles");
    }

    // export-pov writes the file's triangles out (POV-Ray reads no OBJ files), before the mesh's own.
    const std::string text = dsl::export_pov(desc);
    CHECK(text.find("obj") == std::string::npos);
    const auto again = dsl::parse_string(text, "exported.pov");
    REQUIRE(again.objects.size() == 3);  // the light and the two uses of M
    const auto& m = std::get<dsl::MeshShape>(again.objects[1].shape);
    CHECK(m.triangles->size() == 5);
    CHECK_FALSE(m.file);
}
#endif
