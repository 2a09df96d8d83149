// A user's program that loads an OBJ mesh (links photon::obj) and traces a ray into it.
#include <photon/io/obj_mesh.hpp>

#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 2) return 2;
    try {
        const auto mesh = photon::load_obj_mesh<float>(argv[1]);
        const auto hit = mesh.intersect({{0, 0, -5}, {0, 0, 1}});
        std::printf("consumer_obj: %zu triangles, hit at t = %g\n", mesh.triangle_count(), hit ? hit->t : -1.0f);
        return hit ? 0 : 1;
    } catch (const photon::ObjError& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
}
