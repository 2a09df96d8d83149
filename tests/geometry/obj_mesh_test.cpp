// SPDX-License-Identifier: MIT
// OBJ meshes (photon/io/obj_mesh.hpp): the fixture loads into a closed TriangleMesh, polygons are
// fanned, and bad files fail with file:line messages.

#include <catch2/catch.hpp>

#include <photon/io/obj_mesh.hpp>

#include <string>

using namespace photon;

namespace {
const std::string fixture = std::string(PHOTON_TEST_DATA_DIR) + "/tetrahedron.obj";

std::string error_of(const std::string& text) {
    try {
        (void)parse_obj<float>(text, "t.obj");
    } catch (const ObjError& e) {
        return e.what();
    }
    return "no error";
}
}  // namespace

TEMPLATE_TEST_CASE("the tetrahedron fixture loads as a closed, outward-wound mesh", "[obj]", float, double) {
    using S = TestType;
    const ObjTriangles<S> obj = read_obj<S>(fixture);
    REQUIRE(obj.positions.size() == 4);
    REQUIRE(obj.triangles.size() == 4);
    CHECK(obj.triangles[3] == std::array<std::uint32_t, 3>{1, 3, 2});  // f -3 -1 -2: relative indices
    const TriangleMesh<S> mesh = load_obj_mesh<S>(fixture);
    CHECK(mesh.bounds().min == Vec3<S>(-1));
    CHECK(mesh.bounds().max == Vec3<S>(1));
    // From outside along each axis the hit normal faces the ray; from inside every ray hits.
    for (int axis = 0; axis < 3; ++axis) {
        Vec3<S> d(0);
        d[axis] = 1;
        const auto h = mesh.intersect({-S(3) * d, d});
        REQUIRE(h);
        CHECK(glm::dot(h->normal, d) < 0);
        CHECK(mesh.intersect({Vec3<S>(S(0.1), S(-0.05), S(0.02)), d}));
        CHECK(mesh.intersect({Vec3<S>(0), -d}));
    }
}

TEST_CASE("polygons are fanned into triangles", "[obj]") {
    const auto obj = parse_obj<float>("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv -1 0.5 0\nf 1 2 3 4 5\n");
    REQUIRE(obj.triangles.size() == 3);
    CHECK(obj.triangles[0] == std::array<std::uint32_t, 3>{0, 1, 2});
    CHECK(obj.triangles[2] == std::array<std::uint32_t, 3>{0, 3, 4});
    CHECK(parse_obj<double>("# points only\nv 0 0 0\n").triangles.empty());
}

TEST_CASE("bad OBJ input fails with the file and line", "[obj]") {
    CHECK(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 7\n") ==
          "t.obj:5: the face refers to vertex 7, but the file has 3 vertices before it");
    CHECK(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1 -9 3\n") ==
          "t.obj:5: the face refers to vertex -6, but the file has 3 vertices before it");
    CHECK(error_of("v 0 0 0\nv 1 0 0\nf 1 2 # a line\n") == "t.obj:3: a face needs at least 3 vertices, this one has 2");
    CHECK(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 0 2\n") ==  // tinyobjloader's message, our location
          "t.obj:5: Failed parse `f' line (e.g. zero value for face index)");
    CHECK(error_of("v 0 0 0\nv 1 1e40 0\nv 0 1 0\nf 1 2 3\n") == "t.obj:2: vertex 2 is not finite");  // float overflow
    try {
        (void)read_obj<float>("no/such/mesh.obj");
        FAIL("no error");
    } catch (const ObjError& e) {
        CHECK(std::string(e.what()) == "no/such/mesh.obj: cannot open the file: it does not exist");
        CHECK(e.line() == 0);
    }
    CHECK_THROWS_AS(read_obj<float>(PHOTON_TEST_DATA_DIR), ObjError);  // a directory
}
