// SPDX-License-Identifier: MIT
#pragma once
// The objects of a SceneDescription added to a DefaultScene: unions flattened with their modifiers
// inherited, each shape placed by its transformation (kept as the library's own shape where the
// transformation allows, wrapped in Transformed otherwise), materials shared between equal textures.

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <photon/photon.hpp>

#include "../description.hpp"
#include "../mesh_files.hpp"
#include "lights.hpp"
#include "material.hpp"
#include "warnings.hpp"

namespace photon::dsl::detail {

template <Scalar S>
Affine<S> to_affine(const Transform& t) {
    Affine<S> a;
    a.linear = glm::mat<3, 3, S, glm::defaultp>(t.linear);
    a.translation = Vec3<S>(t.translation);
    return a;
}

/// Rotation times uniform scale: returns the scale, or nothing.
inline std::optional<double> similarity_scale(const glm::dmat3& m) {
    const glm::dmat3 g = glm::transpose(m) * m;
    const double s2 = g[0][0];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (std::abs(g[i][j] - (i == j ? s2 : 0.0)) > 1e-12 * s2) return std::nullopt;
    return std::sqrt(s2);
}

/// Whether the map keeps boxes axis-aligned (each axis goes to an axis).
inline bool keeps_axes(const glm::dmat3& m) {
    for (int c = 0; c < 3; ++c) {
        const double len = glm::length(m[c]);
        int big = 0;
        for (int k = 0; k < 3; ++k)
            if (std::abs(m[c][k]) > 1e-12 * len) ++big;
        if (big != 1) return false;
    }
    return true;
}

template <Scalar S>
class Builder {
public:
    Builder(const SceneDescription& desc, Warnings& warn, std::size_t max_primitives)
        : desc_(desc), warn_(warn), max_primitives_(max_primitives),
          mesh_files_([&warn](const SourceLocation& at, const std::string& m) { warn(at, m); }) {}

    void add_all(DefaultScene<S>& scene) {
        scene_ = &scene;
        for (const Object& o : desc_.objects) add(o, Inherited{});
        if (scene.objects().empty() && skipped_ > 0)
            warn_(desc_.at,
                  "nothing renders: photon skipped every object of the scene (" + std::to_string(skipped_) +
                      (skipped_ == 1 ? " object" : " objects") + " it has no shape for)",
                  "nothing renders", "");
        if (scene.lights().empty()) warn_(desc_.at, "the scene has no light_source: the image will be black");
    }

    /// Reads every mesh file the scene names, first, so that a missing one is the build's first
    /// message (as when the parser read them).
    void read_files() {
        std::function<void(const Object&)> visit = [&](const Object& o) {
            if (const auto* m = std::get_if<MeshShape>(&o.shape); m && m->file) (void)mesh_files_.triangles(*m->file);
            if (const auto* u = std::get_if<UnionShape>(&o.shape))
                for (const auto& child : u->children) visit(*child);
        };
        for (const Object& o : desc_.objects) visit(o);
    }

    /// Where each object of the scene was written (a mesh or a union's objects share one place).
    [[nodiscard]] const std::vector<SourceLocation>& object_locations() const noexcept { return object_at_; }

private:
    struct Inherited {
        const Texture* texture = nullptr;
        const Interior* interior = nullptr;
        const ObjectPhotons* photons = nullptr;
        bool no_shadow = false;
        Transform transform;
    };

    void add(const Object& o, const Inherited& parent) {
        const Texture* inherited =
            parent.texture ? parent.texture : (o.default_texture ? &*o.default_texture : nullptr);
        Inherited mine{o.texture ? &*o.texture : inherited, o.interior ? &*o.interior : parent.interior,
                       o.photons ? &*o.photons : parent.photons, o.no_shadow || parent.no_shadow,
                       o.transform.then(parent.transform)};
        if (const auto* l = std::get_if<LightSource>(&o.shape))
            return add_pov_light(*scene_, *l, mine.transform, o.at, warn_);
        if (const auto* u = std::get_if<UnionShape>(&o.shape)) {
            for (const auto& child : u->children) add(*child, mine);
            return;
        }
        if (std::holds_alternative<SkippedShape>(o.shape)) {  // the parser warned at its place
            ++skipped_;
            return;
        }
        try {
            const MaterialId material = material_for(mine, o);
            ObjectOptions options;
            options.casts_shadow = !mine.no_shadow;
            if (mine.photons) {
                const ObjectPhotons& ph = *mine.photons;
                options.caustic_target = ph.target ? CausticTarget::on : CausticTarget::off;
                if (ph.target && (ph.reflection == false || ph.refraction == false))
                    warn_(ph.at,
                          "photons `reflection off` / `refraction off` are ignored: photon follows every caustic "
                          "photon path of a target");
                if (ph.collect == false && scene_->materials()[material].has_diffuse())
                    warn_(ph.at, "photons `collect off` is ignored: photon stores photons on every diffuse surface");
                if (ph.pass_through) warn_(ph.at, "photons `pass_through` is ignored by photon");
            }
            const Transform& t = mine.transform;
            std::visit([&](const auto& shape) { add_shape(shape, t, material, options); }, o.shape);
            object_at_.resize(scene_->objects().size(), o.at);
        } catch (const std::invalid_argument& e) {
            throw Error(o.at, e.what());
        }
    }

    void add_shape(const SphereShape& s, const Transform& t, MaterialId m, ObjectOptions opt) {
        if (const auto scale = similarity_scale(t.linear))
            scene_->add(Sphere<S>(Vec3<S>(t.point(s.center)), S(s.radius * *scale)), m, opt);
        else
            scene_->add(Transformed<Sphere<S>>(Sphere<S>(Vec3<S>(s.center), S(s.radius)), to_affine<S>(t)), m, opt);
    }
    void add_shape(const BoxShape& b, const Transform& t, MaterialId m, ObjectOptions opt) {
        if (keeps_axes(t.linear))
            scene_->add(Box<S>(Vec3<S>(t.point(b.corner1)), Vec3<S>(t.point(b.corner2))), m, opt);
        else
            scene_->add(Transformed<Box<S>>(Box<S>(Vec3<S>(b.corner1), Vec3<S>(b.corner2)), to_affine<S>(t)), m, opt);
    }
    void add_shape(const PlaneShape& p, const Transform& t, MaterialId m, ObjectOptions opt) {
        const Vector3 n = glm::normalize(p.normal);
        const Vector3 world_n = glm::normalize(glm::transpose(glm::inverse(t.linear)) * n);
        const Vector3 point = t.point(n * p.distance);
        scene_->add(Plane<S>(Vec3<S>(world_n), S(glm::dot(point, world_n))), m, opt);
    }
    void add_shape(const TriangleShape& tri, const Transform& t, MaterialId m, ObjectOptions opt) {
        scene_->add(Triangle<S>(Vec3<S>(t.point(tri.vertices[0])), Vec3<S>(t.point(tri.vertices[1])),
                                Vec3<S>(t.point(tri.vertices[2]))),
                    m, opt);
    }
    void add_shape(const MeshShape& mesh, const Transform& t, MaterialId m, ObjectOptions opt) {
        const MeshTriangles* from_file = mesh.file ? &mesh_files_.triangles(*mesh.file) : nullptr;
        const std::size_t count = mesh.triangles->size() + (from_file ? from_file->size() : 0);
        file_triangles_ += from_file ? from_file->size() : 0;
        if (from_file && file_triangles_ > max_primitives_)
            throw Error(mesh.file->at, "the scene is too large: more than " + std::to_string(max_primitives_) +
                                           " objects and triangles");
        std::vector<Vec3<S>> positions;
        std::vector<typename TriangleMesh<S>::Index> indices;
        positions.reserve(count * 3);
        indices.reserve(count);
        for (const MeshTriangles* part : {from_file, mesh.triangles.get()}) {
            if (!part) continue;
            for (const auto& tri : *part) {
                const auto base = std::uint32_t(positions.size());
                for (const Vector3& v : tri) positions.push_back(Vec3<S>(t.point(v)));
                indices.push_back({base, base + 1, base + 2});
            }
        }
        scene_->add(TriangleMesh<S>(std::move(positions), std::move(indices)), m, opt);
    }
    // A cylinder, cone or disc under a similarity is the library's shape itself (its radii scaled);
    // under a shear or non-uniform scale, a Transformed cone or disc. A torus is always Transformed.
    void add_shape(const CylinderShape& c, const Transform& t, MaterialId m, ObjectOptions opt) {
        add_frustum(c.base, c.radius, c.cap, c.radius, c.open, t, m, opt);
    }
    void add_shape(const ConeShape& c, const Transform& t, MaterialId m, ObjectOptions opt) {
        add_frustum(c.base, c.base_radius, c.cap, c.cap_radius, c.open, t, m, opt);
    }
    void add_frustum(const Vector3& base, double r0, const Vector3& cap, double r1, bool open, const Transform& t,
                     MaterialId m, ObjectOptions opt) {
        if (std::abs(r0 - r1) < 1e-10) r1 = r0;  // POV-Ray's rule: a cone with (nearly) equal radii is a cylinder
        if (const auto scale = similarity_scale(t.linear)) {
            const Vec3<S> b(t.point(base)), c(t.point(cap));
            if (r0 == r1)
                scene_->add(Cylinder<S>(b, c, S(r0 * *scale), open), m, opt);
            else
                scene_->add(TruncatedCone<S>(b, S(r0 * *scale), c, S(r1 * *scale), open), m, opt);
        } else {
            scene_->add(Transformed<TruncatedCone<S>>(
                            TruncatedCone<S>(Vec3<S>(base), S(r0), Vec3<S>(cap), S(r1), open), to_affine<S>(t)),
                        m, opt);
        }
    }
    void add_shape(const DiscShape& d, const Transform& t, MaterialId m, ObjectOptions opt) {
        if (const auto scale = similarity_scale(t.linear)) {
            const Vector3 normal = glm::transpose(glm::inverse(t.linear)) * d.normal;
            scene_->add(Disc<S>(Vec3<S>(t.point(d.center)), Vec3<S>(normal), S(d.radius * *scale),
                                S(d.hole_radius * *scale)),
                        m, opt);
        } else {
            scene_->add(Transformed<Disc<S>>(Disc<S>(Vec3<S>(d.center), Vec3<S>(d.normal), S(d.radius),
                                                     S(d.hole_radius)),
                                             to_affine<S>(t)),
                        m, opt);
        }
    }
    void add_shape(const TorusShape& tor, const Transform& t, MaterialId m, ObjectOptions opt) {
        if (tor.major == 0)  // the points at distance `minor` from the centre: a sphere
            return add_shape(SphereShape{Vector3(0.0), tor.minor}, t, m, opt);
        scene_->add(Transformed<Torus<S>>(Torus<S>(S(tor.major), S(tor.minor)), to_affine<S>(t)), m, opt);
    }
    void add_shape(const UnionShape&, const Transform&, MaterialId, ObjectOptions) {}
    void add_shape(const LightSource&, const Transform&, MaterialId, ObjectOptions) {}
    void add_shape(const SkippedShape&, const Transform&, MaterialId, ObjectOptions) {}

    MaterialId material_for(const Inherited& in, const Object& o) {
        static const Texture pov_default{};
        const Texture& tex = in.texture ? *in.texture : pov_default;
        const MaterialParams<S> p = material_params<S>(tex, in.interior, desc_.settings, warn_, o.at);
        for (const auto& [params, id] : materials_)
            if (same(params, p)) return id;
        const SourceLocation at = tex.finish.at.known() ? tex.finish.at : (tex.at.known() ? tex.at : o.at);
        try {
            const MaterialId id = scene_->add_material(Material<S>(p));
            materials_.emplace_back(p, id);
            return id;
        } catch (const std::invalid_argument& e) {
            throw Error(at, e.what());
        }
    }
    static bool same(const MaterialParams<S>& a, const MaterialParams<S>& b) {
        return a.diffuse == b.diffuse && a.specular == b.specular && a.transmission == b.transmission &&
               a.ior == b.ior && a.fresnel == b.fresnel && a.phong == b.phong && a.phong_exponent == b.phong_exponent;
    }


    const SceneDescription& desc_;
    Warnings& warn_;
    DefaultScene<S>* scene_ = nullptr;
    std::vector<std::pair<MaterialParams<S>, MaterialId>> materials_;
    std::vector<SourceLocation> object_at_;
    std::size_t max_primitives_;
    std::size_t file_triangles_ = 0;  ///< triangles of mesh files, for every use of them
    MeshFiles mesh_files_;
    std::size_t skipped_ = 0;  ///< objects photon has no shape for
};

}  // namespace photon::dsl::detail
