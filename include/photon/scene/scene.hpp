// SPDX-License-Identifier: MIT
#pragma once
// A scene: shapes with materials, lights, and optionally a sky (an Environment). Shapes are a closed set given as template
// parameters (a user's own Primitive joins by being listed), stored in a std::variant and
// dispatched with std::visit; a BVH over the bounded ones answers ray queries.

#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "../geometry/blob.hpp"
#include "../geometry/bounding_ball.hpp"
#include "../geometry/box.hpp"
#include "../geometry/bvh.hpp"
#include "../geometry/cone.hpp"
#include "../geometry/csg.hpp"
#include "../geometry/cylinder.hpp"
#include "../geometry/height_field.hpp"
#include "../geometry/disc.hpp"
#include "../geometry/lathe.hpp"
#include "../geometry/plane.hpp"
#include "../geometry/polygon.hpp"
#include "../geometry/polynomial_surface.hpp"
#include "../geometry/primitive.hpp"
#include "../geometry/prism.hpp"
#include "../geometry/quadric.hpp"
#include "../geometry/sor.hpp"
#include "../geometry/sphere.hpp"
#include "../geometry/superellipsoid.hpp"
#include "../geometry/torus.hpp"
#include "../geometry/transformed.hpp"
#include "../geometry/triangle.hpp"
#include "../geometry/triangle_mesh.hpp"
#include "../light/environment.hpp"
#include "fog.hpp"
#include "../material/medium.hpp"
#include "../light/light.hpp"
#include "../material/material.hpp"

namespace photon {

using MaterialId = std::uint32_t;

/// Whether caustic photons are aimed at an object (POV-Ray's `photons { target }`).
enum class CausticTarget : std::uint8_t {
    automatic,  ///< yes when its material is specular (mirror or glass)
    on,
    off,
};

/// Per-object options besides shape and material.
struct ObjectOptions {
    CausticTarget caustic_target = CausticTarget::automatic;
    bool casts_shadow = true;  ///< false: invisible to shadow rays (POV-Ray's no_shadow)
    /// true: photons pass through it (tracing/photon_hit.hpp), as POV-Ray's through a light's
    /// `looks_like` object; camera and gather rays still see it.
    bool passes_photons = false;
};

/// What a ray hit: the geometric hit, the object and its material (the material of the part hit,
/// for an object whose parts have their own: a CSG's leaves, Scene::add).
template <Scalar S> struct SurfaceHit {
    Hit<S> hit;
    std::uint32_t object = 0;
    const Material<S>* material = nullptr;
};

/// Predicates for Scene::any_material_of.
inline constexpr auto is_specular_material = [](const auto& m) { return m.is_specular(); };
inline constexpr auto has_diffuse_material = [](const auto& m) { return m.has_diffuse(); };
inline constexpr auto is_transmissive_material = [](const auto& m) { return !is_black(m.params().transmission); };

template <Scalar S, Primitive... Shapes> class Scene {
    static_assert(sizeof...(Shapes) > 0, "a Scene needs at least one shape type");
    static_assert((std::is_same_v<scalar_of<Shapes>, S> && ...), "all shapes must use the scene's scalar type");

public:
    using scalar_type = S;
    using Shape = std::variant<Shapes...>;

    struct Object {
        Shape shape;
        MaterialId material;
        ObjectOptions options;
        /// Material of each part (Hit::part) where they differ from `material`; parts past
        /// its end use `material`.
        std::vector<MaterialId> part_materials;
    };

    /// Adds a material and returns its id.
    MaterialId add_material(const Material<S>& material) {
        materials_.push_back(material);
        return static_cast<MaterialId>(materials_.size() - 1);
    }
    /// Adds an object; throws std::invalid_argument on an unknown material id. A shape made of
    /// parts (a Csg, whose hits name their leaf in Hit::part) may give each part its own
    /// material in `part_materials` (POV-Ray's textured CSG children); parts without one use
    /// `material`.
    std::uint32_t add(Shape shape, MaterialId material, ObjectOptions options = {},
                      std::vector<MaterialId> part_materials = {}) {
        for (MaterialId id : part_materials)
            if (id >= materials_.size())
                throw std::invalid_argument("scene: material id " + std::to_string(id) + " does not exist");
        if (material >= materials_.size())
            throw std::invalid_argument("scene: material id " + std::to_string(material) + " does not exist");
        objects_.push_back({std::move(shape), material, options, std::move(part_materials)});
        committed_ = false;
        return static_cast<std::uint32_t>(objects_.size() - 1);
    }
    /// Adds a light; throws std::invalid_argument if it is invalid. A parallel light's beam is
    /// fitted to the objects' ball (environment_ball) on commit(), or now if committed.
    void add_light(const Light<S>& light) {
        validate(light);
        lights_.push_back(light);
        if (auto* parallel = std::get_if<ParallelLight<S>>(&lights_.back()); parallel && committed_)
            parallel->fit_beam(environment_ball_);
    }

    /// Labels object `id` or light `index` for what photon prints about it (the effects plan's
    /// reasons): the scene language gives each its `file:line:column`, a program any name.
    /// Unlabelled ones are named by index and kind alone. Throws std::out_of_range on a bad id.
    void set_object_label(std::uint32_t id, std::string label) { set_label(object_labels_, objects_.size(), id, std::move(label)); }
    void set_light_label(std::size_t index, std::string label) { set_label(light_labels_, lights_.size(), index, std::move(label)); }
    /// The label set for object `id` or light `index`; empty when none is.
    [[nodiscard]] std::string_view object_label(std::uint32_t id) const noexcept { return label_of(object_labels_, id); }
    [[nodiscard]] std::string_view light_label(std::size_t index) const noexcept { return label_of(light_labels_, index); }

    /// Sets the sky that rays leaving the scene see and that lights it (environment.hpp).
    void set_environment(Environment<S> environment) { environment_ = std::move(environment); }
    void clear_environment() noexcept { environment_.reset(); }
    [[nodiscard]] const std::optional<Environment<S>>& environment() const noexcept { return environment_; }
    /// Whether a sky with some light in it is set.
    [[nodiscard]] bool has_environment_light() const noexcept { return environment_ && !environment_->is_black(); }
    /// The ball the sky's photons enter through: around the bounded objects (infinite planes
    /// excluded, so they get sky photons only inside it); radius 0 when there are none.
    /// Valid after commit().
    [[nodiscard]] const Ball<S>& environment_ball() const noexcept { return environment_ball_; }

    /// Adds a fog (fog.hpp) that camera, mirror and glass rays see; throws std::invalid_argument
    /// if it is invalid.
    void add_fog(const Fog<S>& fog) {
        fog.validate();
        fogs_.push_back(fog);
    }
    [[nodiscard]] std::span<const Fog<S>> fogs() const noexcept { return fogs_; }

    /// Adds a medium (material/medium.hpp) that fills the space outside objects (POV-Ray's atmospheric
    /// media); throws std::invalid_argument if it is invalid.
    void add_medium(const Medium<S>& medium) {
        medium.validate();
        media_.push_back(medium);
    }
    [[nodiscard]] std::span<const Medium<S>> media() const noexcept { return media_; }

    /// The scene BVH's build options: objects cost far more than a node visit, so leaves are small.
    static constexpr BvhConfig default_bvh_config{.max_leaf_size = 2};
    /// Builds the acceleration structure. Call after the last add() and before any query
    /// (the commit step of Embree's API); queries are then const and thread-safe.
    void commit(BvhConfig config = default_bvh_config);
    [[nodiscard]] bool committed() const noexcept { return committed_; }

    [[nodiscard]] std::span<const Object> objects() const noexcept { return objects_; }
    [[nodiscard]] std::span<const Material<S>> materials() const noexcept { return materials_; }
    [[nodiscard]] std::span<const Light<S>> lights() const noexcept { return lights_; }
    /// The object's material (of its parts without their own, when it has parts).
    [[nodiscard]] const Material<S>& material_of(std::uint32_t object) const noexcept {
        return materials_[objects_[object].material];
    }
    /// The material of part `part` of the object (Hit::part).
    [[nodiscard]] const Material<S>& material_of(std::uint32_t object, std::uint32_t part) const noexcept {
        const auto& parts = objects_[object].part_materials;
        return materials_[part < parts.size() ? parts[part] : objects_[object].material];
    }
    /// Whether `pred` holds for some material of the object (its own or a part's): what a
    /// question about the whole object ("is it a mirror anywhere?") must ask.
    template <class Pred> [[nodiscard]] bool any_material_of(std::uint32_t object, Pred pred) const {
        if (pred(material_of(object))) return true;
        for (MaterialId id : objects_[object].part_materials)
            if (pred(materials_[id])) return true;
        return false;
    }
    [[nodiscard]] BBox<S> object_bounds(std::uint32_t object) const {
        return std::visit([](const auto& shape) { return shape.bounds(); }, objects_[object].shape);
    }
    /// A ball holding the object (bounding_ball.hpp: tight for round shapes); radius infinity
    /// for an unbounded one.
    [[nodiscard]] Ball<S> object_bounding_ball(std::uint32_t object) const {
        return std::visit([](const auto& shape) { return bounding_ball(shape); }, objects_[object].shape);
    }
    /// Bounds of all bounded objects (infinite planes excluded).
    [[nodiscard]] BBox<S> bounds() const noexcept { return bvh_.bounds(); }
    /// Whether caustic photons are aimed at `object`.
    [[nodiscard]] bool is_caustic_target(std::uint32_t object) const noexcept {
        const auto mode = objects_[object].options.caustic_target;
        return mode == CausticTarget::on || (mode == CausticTarget::automatic && any_material_of(object, is_specular_material));
    }

    /// Nearest hit with t in (0, ray.t_max).
    [[nodiscard]] std::optional<SurfaceHit<S>> intersect(const Ray<S>& ray) const {
        return nearest_hit(ray, [](const Object&) { return true; });
    }
    /// Nearest hit of an object that casts shadows, with t in (0, ray.t_max).
    [[nodiscard]] std::optional<SurfaceHit<S>> intersect_shadow_casters(const Ray<S>& ray) const {
        return nearest_hit(ray, [](const Object& o) { return o.options.casts_shadow; });
    }
    /// Whether anything that casts shadows lies on the ray within (0, ray.t_max).
    [[nodiscard]] bool occluded(const Ray<S>& ray) const;

    /// The shadow-casting objects whose bounds touch `region` (infinite planes always), into
    /// `ids`. Many shadow rays that all stay inside one region (from a shading point to an area
    /// light) then need to test only these: one BVH query instead of one traversal per ray.
    /// False, with `ids` incomplete, when there are more than `limit`: testing every one of
    /// them per ray would then cost more than the BVH's traversal.
    bool occluders_in(const BBox<S>& region, std::vector<std::uint32_t>& ids,
                      std::size_t limit = std::numeric_limits<std::size_t>::max()) const;
    /// occluded(ray) for a ray inside a region whose occluders_in() are `ids`.
    [[nodiscard]] bool occluded_by(std::span<const std::uint32_t> ids, const Ray<S>& ray) const {
        for (std::uint32_t id : ids)
            if (occludes(id, ray)) return true;
        return false;
    }

private:
    static void set_label(std::vector<std::string>& labels, std::size_t count, std::size_t i, std::string label) {
        if (i >= count) throw std::out_of_range("scene: no object or light " + std::to_string(i) + " to label");
        if (labels.size() <= i) labels.resize(i + 1);
        labels[i] = std::move(label);
    }
    static std::string_view label_of(const std::vector<std::string>& labels, std::size_t i) noexcept {
        return i < labels.size() ? std::string_view(labels[i]) : std::string_view();
    }

    /// Nearest hit with t in (0, ray.t_max) of the objects `accept` takes.
    template <class Accept>
    [[nodiscard]] std::optional<SurfaceHit<S>> nearest_hit(const Ray<S>& ray, Accept&& accept) const;

    std::optional<Hit<S>> intersect_object(std::uint32_t id, const Ray<S>& ray) const {
        return std::visit([&](const auto& shape) { return shape.intersect(ray); }, objects_[id].shape);
    }
    bool occludes(std::uint32_t id, const Ray<S>& ray) const {
        if (!objects_[id].options.casts_shadow) return false;
        return std::visit([&](const auto& shape) { return photon::occluded(shape, ray); }, objects_[id].shape);
    }

    std::vector<Object> objects_;
    std::vector<Material<S>> materials_;
    std::vector<Light<S>> lights_;
    std::optional<Environment<S>> environment_;
    std::vector<Fog<S>> fogs_;
    std::vector<Medium<S>> media_;
    std::vector<std::string> object_labels_, light_labels_;  ///< set_object_label, set_light_label; may be shorter
    Ball<S> environment_ball_{};
    Bvh<S> bvh_;
    std::vector<std::uint32_t> bvh_objects_;  ///< object id per BVH primitive (leaf order)
    std::vector<std::uint32_t> unbounded_;    ///< objects tested outside the BVH (planes)
    bool committed_ = false;
};

/// The CSG trees the scene language builds: their leaves are the library's solids, placed
/// directly where the transformation allows, else Transformed.
template <Scalar S>
using DefaultCsg = Csg<S, Sphere<S>, Box<S>, Plane<S>, Cylinder<S>, TruncatedCone<S>, Transformed<Sphere<S>>,
                       Transformed<Box<S>>, Transformed<Cylinder<S>>, Transformed<TruncatedCone<S>>,
                       Transformed<Torus<S>>, Quadric<S>, Transformed<Prism<S>>,
                       Transformed<PolynomialSurface<S>>, Transformed<Superellipsoid<S>>, Transformed<Lathe<S>>,
                       Transformed<Sor<S>>, Transformed<HeightField<S>>, Transformed<Blob<S>>>;

/// The shapes the scene language builds; user programs may list their own instead. A cylinder,
/// cone or disc under a similarity (rotation, uniform scale, translation) is placed as the shape
/// itself; only a map that changes its cross-section's shape (non-uniform scale, shear) needs
/// Transformed. A cylinder squashed that way is a Transformed cone with equal radii (one type
/// fewer to dispatch; the same frustum code). A torus is always Transformed: Torus lies around
/// the y axis at the origin, and the matrix costs little beside the quartic. A quadric and a
/// polygon are never Transformed: their transformation is folded into their numbers. A prism (and
/// text, a prism along z) is always Transformed, as the torus, and so is a polynomial surface
/// (its transformation is not folded into its coefficients); so are a superellipsoid, a lathe and
/// a sor (each lies at the origin, around or along the y axis).
/// A height field is always Transformed too (it lies over the unit square), and a blob (its
/// components keep their own transforms; the blob's is applied to the ray once).
template <Scalar S>
using DefaultScene =
    Scene<S, Sphere<S>, Plane<S>, Box<S>, Triangle<S>, TriangleMesh<S>, Cylinder<S>, TruncatedCone<S>, Disc<S>,
          Transformed<Sphere<S>>, Transformed<Box<S>>, Transformed<TruncatedCone<S>>, Transformed<Disc<S>>,
          Transformed<Torus<S>>, DefaultCsg<S>, Quadric<S>, Polygon<S>, Transformed<Prism<S>>,
          Transformed<PolynomialSurface<S>>, Transformed<Superellipsoid<S>>, Transformed<Lathe<S>>, Transformed<Sor<S>>,
          Transformed<HeightField<S>>, Transformed<Blob<S>>>;

template <Scalar S, Primitive... Shapes> void Scene<S, Shapes...>::commit(BvhConfig config) {
    std::vector<BBox<S>> boxes;
    std::vector<std::uint32_t> ids;
    unbounded_.clear();
    for (std::uint32_t i = 0; i < objects_.size(); ++i) {
        const BBox<S> b = object_bounds(i);
        if (b.is_finite()) {
            boxes.push_back(b);
            ids.push_back(i);
        } else if (!b.is_empty()) {
            unbounded_.push_back(i);
        }
    }
    bvh_ = Bvh<S>(boxes, config);
    bvh_objects_.clear();
    for (std::uint32_t p : bvh_.primitive_indices()) bvh_objects_.push_back(ids[p]);
    environment_ball_ = boxes.empty() ? Ball<S>{} : ball_around(bvh_.bounds());
    for (auto& light : lights_)  // parallel lights' photons leave from a beam covering that ball
        if (auto* parallel = std::get_if<ParallelLight<S>>(&light)) parallel->fit_beam(environment_ball_);
    committed_ = true;
}

template <Scalar S, Primitive... Shapes>
template <class Accept>
std::optional<SurfaceHit<S>> Scene<S, Shapes...>::nearest_hit(const Ray<S>& ray, Accept&& accept) const {
    PHOTON_ASSERT(committed_);
    Ray<S> r = ray;
    std::optional<Hit<S>> best;
    std::uint32_t best_object = 0;
    for (std::uint32_t id : unbounded_) {
        if (!accept(objects_[id])) continue;
        if (auto hit = intersect_object(id, r)) {
            r.t_max = hit->t;
            best = hit;
            best_object = id;
        }
    }
    bvh_.intersect(r, [&](std::uint32_t i, Ray<S>& current) {
        const std::uint32_t id = bvh_objects_[i];
        if (!accept(objects_[id])) return false;
        auto hit = intersect_object(id, current);
        if (!hit) return false;
        current.t_max = hit->t;
        best = hit;
        best_object = id;
        return true;
    });
    if (!best) return std::nullopt;
    return SurfaceHit<S>{*best, best_object, &material_of(best_object, best->part)};
}

template <Scalar S, Primitive... Shapes> bool Scene<S, Shapes...>::occluded(const Ray<S>& ray) const {
    PHOTON_ASSERT(committed_);
    for (std::uint32_t id : unbounded_)
        if (occludes(id, ray)) return true;
    return bvh_.any_hit(ray, [&](std::uint32_t i, const Ray<S>& current) { return occludes(bvh_objects_[i], current); });
}

template <Scalar S, Primitive... Shapes>
bool Scene<S, Shapes...>::occluders_in(const BBox<S>& region, std::vector<std::uint32_t>& ids, std::size_t limit) const {
    PHOTON_ASSERT(committed_);
    ids.clear();
    for (std::uint32_t id : unbounded_)
        if (objects_[id].options.casts_shadow) ids.push_back(id);
    // Widened by a few ulps of the coordinates, so that rounding in a ray's points never puts
    // them outside; far below the offset that lifts shading points off their surface.
    const S pad = S(4) * std::numeric_limits<S>::epsilon() * region.magnitude();
    const BBox<S> query{region.min - pad, region.max + pad};
    if (ids.size() > limit) return false;
    bool complete = true;
    bvh_.for_each_overlapping(query, [&](std::uint32_t i) {
        const std::uint32_t id = bvh_objects_[i];
        if (objects_[id].options.casts_shadow && object_bounds(id).overlaps(query)) ids.push_back(id);
        complete = ids.size() <= limit;
        return complete;
    });
    return complete;
}

}  // namespace photon
