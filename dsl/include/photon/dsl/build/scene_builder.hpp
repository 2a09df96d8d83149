// SPDX-License-Identifier: MIT
#pragma once
// The objects of a SceneDescription added to a DefaultScene: unions flattened with their modifiers
// inherited, each shape placed by its transformation (kept as the library's own shape where the
// transformation allows, wrapped in Transformed otherwise), materials shared between equal textures.
// A CSG (difference, intersection, merge) becomes one DefaultCsg object whose leaves are its solid
// children, each leaf with the material of its own texture (or the one it inherits). An object
// with `clipped_by` (its own or its unions') becomes a DefaultCsg clipped by the clip objects.

#include <algorithm>
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
#include "../font_files.hpp"
#include "../mesh_files.hpp"
#include "layers.hpp"
#include "lights.hpp"
#include "material.hpp"
#include "media.hpp"
#include "normal.hpp"
#include "shape_placement.hpp"
#include "warnings.hpp"

namespace photon::dsl::detail {

template <Scalar S>
class Builder {
public:
    Builder(const SceneDescription& desc, Warnings& warn, std::size_t max_primitives, ImageFiles& images)
        : desc_(desc), warn_(warn), max_primitives_(max_primitives), images_(images),
          mesh_files_([&warn](const SourceLocation& at, const std::string& m) { warn(at, m); }) {}

    /// Threads for the meshes' BVH builds (RenderSettings::threads; the trees do not depend on it).
    void set_build_threads(unsigned threads) { build_threads_ = threads; }

    void add_all(DefaultScene<S>& scene) {
        scene_ = &scene;
        for (const Object& o : desc_.objects) add(o, Inherited{});
        if (scene.objects().empty() && skipped_ > 0)
            warn_(desc_.at,
                  "nothing renders: photon skipped every object of the scene (" + std::to_string(skipped_) +
                      (skipped_ == 1 ? " object" : " objects") + " it has no shape for)",
                  "nothing renders", "");
        if (scene.lights().empty() && !scene.has_environment_light()) {
            bool glows = false;  // POV-Ray's ambient and emission show without lights
            for (const auto& m : scene.materials()) glows = glows || m.params().ambient != Rgb<S>(S(0));
            bool media_glow = false;  // emitting media (POV-Ray's micro.pov) show without lights too
            const auto emits = [](const Medium<S>& m) { return !is_black(m.emission); };
            for (const auto& m : scene.materials())
                media_glow = media_glow || std::any_of(m.params().media.begin(), m.params().media.end(), emits);
            media_glow = media_glow || std::any_of(scene.media().begin(), scene.media().end(), emits);
            // What shows is what POV-Ray shows: a note, not a warning, unless nothing will.
            if (media_glow)
                warn_.note(desc_.at, "the scene has no light_source: only emission (of surfaces and media) and ambient will show");
            else if (glows)
                warn_.note(desc_.at, "the scene has no light_source: only its surfaces' ambient and emission will show");
            else
                warn_(desc_.at, "the scene has no light_source: the image will be black");
        }
    }

    /// Reads every mesh file the scene names, first, so that a missing one is the build's first
    /// message (as when the parser read them).
    void read_files() {
        std::function<void(const Object&)> visit = [&](const Object& o) {
            if (const auto* m = std::get_if<MeshShape>(&o.shape); m && m->file) (void)mesh_files_.triangles(*m->file);
            if (const auto* t = std::get_if<TextShape>(&o.shape)) (void)font_files_.set(*t);
            if (const auto* u = std::get_if<UnionShape>(&o.shape))
                for (const auto& child : u->children) visit(*child);
            if (const auto* c = std::get_if<CsgShape>(&o.shape))
                for (const auto& child : c->children) visit(*child);
        };
        for (const Object& o : desc_.objects) visit(o);
    }

    /// Where each object of the scene was written (a mesh or a union's objects share one place).
    [[nodiscard]] const std::vector<SourceLocation>& object_locations() const noexcept { return object_at_; }
    [[nodiscard]] const std::vector<SourceLocation>& light_locations() const noexcept { return light_at_; }

private:
    struct Inherited;
    /// A `clipped_by` object and the space it was written in (the clipped object's).
    struct ClipRef {
        const Object* clip;
        std::shared_ptr<const Inherited> space;
    };
    struct Inherited {
        const Texture* texture = nullptr;
        const Interior* interior = nullptr;
        const ObjectPhotons* photons = nullptr;
        bool no_shadow = false;
        Transform transform;
        Transform texture_placement;  ///< the texture's pattern space to the world
        Transform normal_placement;   ///< its normal's pattern space to the world
        Transform texture_world;      ///< the space the texture was written in to the world (for its layers)
        Transform interior_world;     ///< the space the interior was written in to the world (its media's densities)
        /// The clips of the unions around (set by add(): a CSG's children take none from them).
        std::vector<ClipRef> clips;
        /// POV-Ray keeps the bounds of the objects here: inside a CSG, or in a union it does not
        /// split into its objects (one with a bound or a clip of its own; Parser::Link_To_Frame).
        bool bounds_kept = false;
        bool passes_photons = false;  ///< inside a light's looks_like object (add_looks_like)
        /// The world ball around the bounded_by of the innermost union around with one: a
        /// polynomial surface inside, which photon cannot bound, takes it as its gate.
        std::optional<std::pair<Vector3, double>> bound_ball;
    };

    static Inherited inherit(const Object& o, const Inherited& parent) {
        const Texture* inherited =
            parent.texture ? parent.texture : (o.default_texture ? &*o.default_texture : nullptr);
        // A texture moves with the transformations written after it on its object (folded into
        // its pigment's by the parser), and with those of the unions around that object.
        const Transform placement = o.texture ? o.texture->pigment.transform.then(parent.transform)
                                    : parent.texture ? parent.texture_placement
                                    : o.default_texture ? o.default_texture->pigment.transform
                                                        : Transform{};
        // The normal's placement is composed as the pigment's is.
        const auto normal_transform = [](const Texture& t) { return t.normal ? t.normal->transform : Transform{}; };
        const Transform normal_placement = o.texture ? normal_transform(*o.texture).then(parent.transform)
                                           : parent.texture ? parent.normal_placement
                                           : o.default_texture ? normal_transform(*o.default_texture)
                                                               : Transform{};
        const Transform texture_world = o.texture ? parent.transform : parent.texture ? parent.texture_world : Transform{};
        return {o.texture ? &*o.texture : inherited, o.interior ? &*o.interior : parent.interior,
                o.photons ? &*o.photons : parent.photons, o.no_shadow || parent.no_shadow,
                o.transform.then(parent.transform), placement, normal_placement, texture_world,
                o.interior ? parent.transform : parent.interior_world, {}, false, parent.passes_photons};
    }

    void add(const Object& o, const Inherited& parent) {
        Inherited mine = inherit(o, parent);
        if (const auto* l = std::get_if<LightSource>(&o.shape)) {
            add_pov_light(*scene_, *l, mine.transform, o.at, warn_);
            if (l->media_attenuation && std::any_of(desc_.fogs.begin(), desc_.fogs.end(),
                                                    [](const FogDescription& f) { return f.distance > 0.0; }))
                warn_(o.at,
                      "`media_attenuation on` under a fog: POV-Ray blends this light's shadow rays toward the fog's "
                      "colour (trace.cpp, ComputeShadowMedia); photon's fog fades camera, mirror and glass rays only, "
                      "so the light arrives undimmed",
                      "approximated light", "media_attenuation");
            light_at_.resize(scene_->lights().size(), o.at);
            return add_looks_like(*l, mine);
        }
        if (parent.bounds_kept || pov_keeps_bound(o.shape)) warn_bound(o);
        mine.clips = parent.clips;
        append_clips(o, mine);
        if (const auto* u = std::get_if<UnionShape>(&o.shape)) {
            if (o.inverse)
                warn_(o.at, "`inverse` on a `union` is ignored: photon adds a union's objects one by one",
                      "ignored effect", "inverse");
            mine.bounds_kept = parent.bounds_kept || !o.bounded_by.empty() || !o.clipped_by.empty();
            if (!o.bounded_by.empty()) mine.bound_ball = world_ball(o.bounded_by, mine.transform);
            for (const auto& child : u->children) add(*child, mine);
            return;
        }
        if (std::holds_alternative<SkippedShape>(o.shape)) {  // the parser warned at its place
            ++skipped_;
            return;
        }
        if (std::holds_alternative<CsgShape>(o.shape)) return add_csg(o, mine);
        if (!mine.clips.empty()) {
            if (std::visit([](const auto& s) { return is_solid_shape(s); }, o.shape)) return add_csg(o, mine);
            warn_(o.clipped_at.known() ? o.clipped_at : o.at,
                  std::string("`clipped_by` on a `") + keyword(o.shape) +
                      "` is ignored: it has no inside, and photon clips only through CSG",
                  "ignored effect", "clipped_by");
        }
        if (o.inverse) {
            if (std::visit([](const auto& s) { return is_solid_shape(s); }, o.shape)) return add_csg(o, mine);
            warn_(o.at, std::string("`inverse` on a `") + keyword(o.shape) + "` is ignored: it has no inside",
                  "ignored effect", "inverse");
        }
        try {
            const MaterialId material = material_for(mine, o);
            const ObjectOptions options = options_for(mine, material);
            warn_hollow_without_media(o, scene_->materials()[material]);
            const Transform& t = mine.transform;
            if (const auto* poly = std::get_if<PolynomialShape>(&o.shape); poly && !poly->gate && mine.bound_ball) {
                // POV-Ray hides the surface from rays that miss the union's bound: a gate around
                // it, in the surface's own coordinates, does the same (a little wider) and bounds it.
                PolynomialShape gated = *poly;
                gated.gate = ball_gate(*mine.bound_ball, t);
                add_shape(gated, t, material, options);
            } else {
                std::visit([&](const auto& shape) { add_shape(shape, t, material, options); }, o.shape);
            }
            object_at_.resize(scene_->objects().size(), o.at);
        } catch (const std::invalid_argument& e) {
            throw Error(o.at, e.what());
        }
    }

    /// A light's `looks_like` object, as POV-Ray 3.7 places it (Parse_Light_Source): its own
    /// modifiers, then moved to the light's position, then the light's transformations; with
    /// no_shadow, and photons pass through it (PH_PASSTHRU_FLAG), so it lights nothing less.
    void add_looks_like(const LightSource& l, const Inherited& light) {
        if (!l.looks_like_object) return;
        Object shape = *l.looks_like_object;
        shape.transform = shape.transform.then(Transform::translate(l.position));
        shape.no_shadow = true;
        Inherited parent = light;
        parent.passes_photons = true;
        add(shape, parent);
    }

    ObjectOptions options_for(const Inherited& mine, MaterialId material) {
            ObjectOptions options;
            options.casts_shadow = !mine.no_shadow;
            options.passes_photons = mine.passes_photons;
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
            return options;
    }

    // CSG ------------------------------------------------------------------------------------

    /// A CSG object (or a solid with `inverse`, a CSG of one leaf): one DefaultCsg, its leaves'
    /// materials in leaf order. Lights among its children light the scene as in a union.
    void add_csg(const Object& o, const Inherited& mine) {
        try {
            std::vector<MaterialId> parts;
            std::optional<DefaultCsg<S>> tree = csg_node(o, mine, parts);
            if (!tree) return;
            tree = clipped(std::move(*tree), mine.clips, parts);
            if (tree->bounds().is_empty())
                warn_(o.at, std::string("this `") + keyword(o.shape) + "` is empty (its objects do not overlap): nothing renders");
            const MaterialId material = material_for(mine, o);
            if (std::all_of(parts.begin(), parts.end(), [&](MaterialId m) { return m == material; })) parts.clear();
            scene_->add(std::move(*tree), material, options_for(mine, material), std::move(parts));
            object_at_.resize(scene_->objects().size(), o.at);
        } catch (const std::invalid_argument& e) {
            throw Error(o.at, e.what());
        }
    }

    /// The tree of `o` (inherited modifiers already applied in `mine`), or nothing when it has no
    /// solid to render (said where). Leaves append their materials to `parts` in leaf order.
    std::optional<DefaultCsg<S>> csg_node(const Object& o, const Inherited& mine, std::vector<MaterialId>& parts) {
        std::optional<DefaultCsg<S>> tree;
        if (const auto* c = std::get_if<CsgShape>(&o.shape)) {
            tree = csg_operation(o, *c, mine, parts);
        } else if (const auto* u = std::get_if<UnionShape>(&o.shape)) {  // a merge inside a CSG
            tree = csg_operation(o, CsgShape{CsgShape::Operation::merge, u->children}, mine, parts);
        } else {
            std::visit([&](const auto& shape) { tree = csg_leaf(shape, mine.transform); }, o.shape);
            if (tree) parts.push_back(material_for(mine, o));
        }
        if (tree && o.inverse) tree->invert();
        return tree;
    }

    std::optional<DefaultCsg<S>> csg_operation(const Object& o, const CsgShape& c, const Inherited& mine,
                                               std::vector<MaterialId>& parts) {
        using Op = CsgShape::Operation;
        std::vector<DefaultCsg<S>> children;
        for (std::size_t k = 0; k < c.children.size(); ++k) {
            const Object& child = *c.children[k];
            const Inherited theirs = inherit(child, mine);
            if (const auto* l = std::get_if<LightSource>(&child.shape)) {
                add_pov_light(*scene_, *l, theirs.transform, child.at, warn_);
                light_at_.resize(scene_->lights().size(), child.at);
                add_looks_like(*l, theirs);
                continue;
            }
            if (std::holds_alternative<SkippedShape>(child.shape)) ++skipped_;  // the parser warned
            warn_bound(child);  // POV-Ray keeps every bound inside a CSG
            if (auto tree = csg_node(child, theirs, parts)) {
                Inherited space = theirs;
                append_clips(child, space);
                children.push_back(clipped(std::move(*tree), space.clips, parts));
                continue;
            }
            // A child with no inside: what it takes from the result cannot be known, except in a
            // merge (it joins as in a union) or when it is cut away (it cuts nothing).
            const bool decides = c.operation == Op::intersection || (c.operation == Op::difference && k == 0);
            const std::string what = "`" + std::string(keyword(child.shape)) + "`";
            if (std::holds_alternative<SkippedShape>(child.shape)) {
                if (decides) {
                    warn_(o.at, std::string("`") + keyword(c.operation) + "` is skipped: its " + what +
                                    " decides its shape and photon skipped it",
                          "skipped object", keyword(c.operation));
                    return std::nullopt;
                }
                continue;
            }
            if (decides) {
                warn_(child.at, what + " has no inside: the `" + keyword(c.operation) + "` is skipped",
                      "skipped object", keyword(c.operation));
                return std::nullopt;
            }
            if (c.operation == Op::merge) {
                warn_(child.at, what + " in `merge` has no inside: it is added as in a `union` (its surfaces inside "
                                       "the others stay)",
                      "approximated object", "merge");
                add(child, mine);
            } else {
                warn_(child.at, what + " in `difference` has no inside and cuts nothing: ignored",
                      "approximated object", "difference");
            }
        }
        if (children.empty()) return std::nullopt;
        if (children.size() == 1) return std::move(children.front());
        switch (c.operation) {
        case Op::difference: return DefaultCsg<S>::difference(std::move(children));
        case Op::intersection: return DefaultCsg<S>::intersection(std::move(children));
        case Op::merge: break;
        }
        return DefaultCsg<S>::merge(std::move(children));
    }

    /// Adds o's own `clipped_by` objects to `mine.clips`, in o's space.
    static void append_clips(const Object& o, Inherited& mine) {
        if (o.clipped_by.empty()) return;
        auto space = std::make_shared<Inherited>(mine);
        space->clips.clear();
        for (const auto& clip : o.clipped_by) mine.clips.push_back({clip.get(), space});
    }

    /// `tree` clipped by `clips` (their leaves' materials appended to `parts`, never shown); a
    /// clip with no inside is left out, with a warning.
    DefaultCsg<S> clipped(DefaultCsg<S> tree, const std::vector<ClipRef>& clips, std::vector<MaterialId>& parts) {
        std::vector<DefaultCsg<S>> trees;
        for (const ClipRef& c : clips) {
            if (auto t = csg_node(*c.clip, inherit(*c.clip, *c.space), parts))
                trees.push_back(std::move(*t));
            else if (!std::holds_alternative<SkippedShape>(c.clip->shape))  // a skipped one was warned
                warn_(c.clip->at, std::string("this `") + keyword(c.clip->shape) +
                                      "` has no inside: photon's `clipped_by` leaves it out",
                      "ignored effect", "clipped_by");
        }
        return trees.empty() ? tree : DefaultCsg<S>::clipped(std::move(tree), std::move(trees));
    }

    /// A world ball holding `bounds` (in the space `to_world` places): around their boxes. Empty
    /// when one of them has no finite box.
    std::optional<std::pair<Vector3, double>> world_ball(const std::vector<std::shared_ptr<const Object>>& bounds,
                                                         const Transform& to_world) {
        BBox<double> box;
        bool finite = true;
        for (const auto& b : bounds)
            std::visit(
                [&](const auto& shape) {
                    if constexpr (requires { placement_.place(shape, to_world, [](const auto&) {}); }) {
                        placement_.place(shape, b->transform.then(to_world), [&](const auto& placed) {
                            const auto bb = placed.bounds();
                            finite = finite && bb.is_finite();
                            box.extend(BBox<double>{Vec3<double>(bb.min), Vec3<double>(bb.max)});
                        });
                    } else {
                        finite = false;
                    }
                },
                b->shape);
        if (!finite || box.is_empty()) return std::nullopt;
        const Vec3<double> c = 0.5 * (box.min + box.max);
        return std::pair<Vector3, double>{Vector3(c), 0.5 * glm::length(box.max - box.min)};
    }
    /// A polynomial's sphere gate around world ball `ball`, in the coordinates `to_world` places:
    /// the ball mapped back, widened by the inverse's largest stretch (its Frobenius norm, a bound).
    static PolynomialShape::Gate ball_gate(const std::pair<Vector3, double>& ball, const Transform& to_world) {
        const Transform to_local = to_world.inverse();
        const glm::dmat3& m = to_local.linear;
        double stretch = 0.0;
        for (int i = 0; i < 3; ++i) stretch += glm::dot(m[i], m[i]);
        PolynomialShape::Gate gate;
        gate.sphere = true;
        gate.center = to_local.point(ball.first);
        gate.radius = ball.second * std::sqrt(stretch) * (1.0 + 1e-9);
        return gate;
    }

    /// The `bounded_by` of `o` that photon could not show to hold it, where POV-Ray keeps it.
    void warn_bound(const Object& o) {
        if (o.bound_may_cut)
            warn_(*o.bound_may_cut,
                  "`bounded_by` is ignored: photon bounds every object itself; the image is the same unless the "
                  "bound cuts the object (POV-Ray then hides it from the rays that miss the bound), which photon "
                  "could not rule out here",
                  "ignored effect", "bounded_by");
    }

    std::optional<DefaultCsg<S>> csg_leaf(const SphereShape& s, const Transform& t) {
        std::optional<DefaultCsg<S>> leaf;
        place(s, t, [&](auto shape) { leaf.emplace(std::move(shape)); });
        return leaf;
    }
    std::optional<DefaultCsg<S>> csg_leaf(const BoxShape& b, const Transform& t) {
        std::optional<DefaultCsg<S>> leaf;
        place(b, t, [&](auto shape) { leaf.emplace(std::move(shape)); });
        return leaf;
    }
    std::optional<DefaultCsg<S>> csg_leaf(const PlaneShape& p, const Transform& t) { return DefaultCsg<S>(place(p, t)); }
    template <class Round>
        requires(std::is_same_v<Round, CylinderShape> || std::is_same_v<Round, ConeShape> ||
                 std::is_same_v<Round, TorusShape>)
    std::optional<DefaultCsg<S>> csg_leaf(const Round& r, const Transform& t) {
        std::optional<DefaultCsg<S>> leaf;
        place(r, t, [&](auto shape) { leaf.emplace(std::move(shape)); });
        return leaf;
    }
    std::optional<DefaultCsg<S>> csg_leaf(const PrismShape& g, const Transform& t) {
        std::optional<DefaultCsg<S>> leaf;
        place(g, t, [&](auto shape) { leaf.emplace(std::move(shape)); });
        return leaf;
    }
    std::optional<DefaultCsg<S>> csg_leaf(const PolynomialShape& p, const Transform& t) {
        std::optional<DefaultCsg<S>> leaf;
        place(p, t, [&](auto shape) { leaf.emplace(std::move(shape)); });
        return leaf;
    }
    template <class AlwaysTransformed>
        requires(std::is_same_v<AlwaysTransformed, SuperellipsoidShape> || std::is_same_v<AlwaysTransformed, LatheShape> ||
                 std::is_same_v<AlwaysTransformed, SorShape> || std::is_same_v<AlwaysTransformed, BlobShape>)
    std::optional<DefaultCsg<S>> csg_leaf(const AlwaysTransformed& r, const Transform& t) {
        std::optional<DefaultCsg<S>> leaf;
        place(r, t, [&](auto shape) { leaf.emplace(std::move(shape)); });
        return leaf;
    }
    std::optional<DefaultCsg<S>> csg_leaf(const TextShape& text, const Transform& t) {
        std::optional<DefaultCsg<S>> leaf;
        place(text, t, [&](auto shape) { leaf.emplace(std::move(shape)); });
        return leaf;
    }
    std::optional<DefaultCsg<S>> csg_leaf(const HeightFieldShape& g, const Transform& t) {
        std::optional<DefaultCsg<S>> leaf;
        place(g, t, [&](auto shape) { leaf.emplace(std::move(shape)); });
        return leaf;
    }
    std::optional<DefaultCsg<S>> csg_leaf(const QuadricShape& q, const Transform& t) {
        std::optional<DefaultCsg<S>> leaf;
        place(q, t, [&](auto shape) { leaf.emplace(std::move(shape)); });
        return leaf;
    }
    /// Not solids (no inside), or not shapes.
    template <class Other> std::optional<DefaultCsg<S>> csg_leaf(const Other&, const Transform&) { return std::nullopt; }
    /// The shapes csg_leaf makes a leaf of.
    template <class Shape> static constexpr bool is_solid_shape(const Shape&) {
        return std::is_same_v<Shape, SphereShape> || std::is_same_v<Shape, BoxShape> || std::is_same_v<Shape, PlaneShape> ||
               std::is_same_v<Shape, CylinderShape> || std::is_same_v<Shape, ConeShape> || std::is_same_v<Shape, TorusShape> ||
               std::is_same_v<Shape, QuadricShape> || std::is_same_v<Shape, PrismShape> || std::is_same_v<Shape, TextShape> ||
               std::is_same_v<Shape, PolynomialShape> || std::is_same_v<Shape, SuperellipsoidShape> ||
               std::is_same_v<Shape, LatheShape> || std::is_same_v<Shape, SorShape> ||
               std::is_same_v<Shape, HeightFieldShape> || std::is_same_v<Shape, BlobShape>;
    }

    // Shapes ---------------------------------------------------------------------------------

    /// Each shape placed by its transformation (shape_placement.hpp), handed to `f`.
    template <class Shape, class... F> decltype(auto) place(const Shape& shape, const Transform& t, F&&... f) {
        return placement_.place(shape, t, std::forward<F>(f)...);
    }

    void add_shape(const SphereShape& s, const Transform& t, MaterialId m, ObjectOptions opt) {
        place(s, t, [&](auto shape) { scene_->add(std::move(shape), m, opt); });
    }
    void add_shape(const BoxShape& b, const Transform& t, MaterialId m, ObjectOptions opt) {
        place(b, t, [&](auto shape) { scene_->add(std::move(shape), m, opt); });
    }
    void add_shape(const PlaneShape& p, const Transform& t, MaterialId m, ObjectOptions opt) {
        scene_->add(place(p, t), m, opt);
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
        scene_->add(TriangleMesh<S>(std::move(positions), std::move(indices), BvhConfig{.threads = build_threads_}), m, opt);
    }
    void add_shape(const CylinderShape& c, const Transform& t, MaterialId m, ObjectOptions opt) {
        place(c, t, [&](auto shape) { scene_->add(std::move(shape), m, opt); });
    }
    void add_shape(const ConeShape& c, const Transform& t, MaterialId m, ObjectOptions opt) {
        place(c, t, [&](auto shape) { scene_->add(std::move(shape), m, opt); });
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
        place(tor, t, [&](auto shape) { scene_->add(std::move(shape), m, opt); });
    }
    void add_shape(const PrismShape& g, const Transform& t, MaterialId m, ObjectOptions opt) {
        place(g, t, [&](auto shape) { scene_->add(std::move(shape), m, opt); });
    }
    void add_shape(const PolynomialShape& p, const Transform& t, MaterialId m, ObjectOptions opt) {
        place(p, t, [&](auto shape) { scene_->add(std::move(shape), m, opt); });
    }
    template <class AlwaysTransformed>
        requires(std::is_same_v<AlwaysTransformed, SuperellipsoidShape> || std::is_same_v<AlwaysTransformed, LatheShape> ||
                 std::is_same_v<AlwaysTransformed, SorShape> || std::is_same_v<AlwaysTransformed, BlobShape>)
    void add_shape(const AlwaysTransformed& g, const Transform& t, MaterialId m, ObjectOptions opt) {
        place(g, t, [&](auto shape) { scene_->add(std::move(shape), m, opt); });
    }
    void add_shape(const TextShape& text, const Transform& t, MaterialId m, ObjectOptions opt) {
        place(text, t, [&](auto shape) { scene_->add(std::move(shape), m, opt); });
    }
    void add_shape(const HeightFieldShape& g, const Transform& t, MaterialId m, ObjectOptions opt) {
        place(g, t, [&](auto shape) { scene_->add(std::move(shape), m, opt); });
    }
    void add_shape(const QuadricShape& q, const Transform& t, MaterialId m, ObjectOptions opt) {
        place(q, t, [&](auto shape) { scene_->add(std::move(shape), m, opt); });
    }
    /// The polygon's points moved by the transformation (an affine map keeps them in one plane and
    /// keeps which points the even-odd rule fills).
    void add_shape(const PolygonShape& g, const Transform& t, MaterialId m, ObjectOptions opt) {
        std::vector<std::vector<Vec3<S>>> loops;
        for (const auto& loop : polygon_loops(*g.points)) {
            loops.emplace_back();
            for (const Vector3& p : loop) loops.back().push_back(Vec3<S>(t.point(p)));
        }
        scene_->add(Polygon<S>(loops), m, opt);
    }
    void add_shape(const UnionShape&, const Transform&, MaterialId, ObjectOptions) {}
    void add_shape(const CsgShape&, const Transform&, MaterialId, ObjectOptions) {}
    void add_shape(const LightSource&, const Transform&, MaterialId, ObjectOptions) {}
    void add_shape(const SkippedShape&, const Transform&, MaterialId, ObjectOptions) {}

    MaterialId material_for(const Inherited& in, const Object& o) {
        static const Texture pov_default{};
        const Texture& tex = in.texture ? *in.texture : pov_default;
        if (!tex.layers.empty()) return layered_material_for(in, tex, o);
        MaterialParams<S> p = material_params<S>(tex, in.interior, desc_.settings, desc_.version, warn_, o.at);
        if (in.interior) p.media = build_media<S>(in.interior->media, in.interior_world, warn_);
        const PigmentPattern* pattern = tex.pigment.pattern.get();
        const Transform placement = pattern ? in.texture_placement : Transform{};
        const Normal* normal = tex.normal && tex.normal->pattern ? &*tex.normal : nullptr;
        const MadeNormal made_normal = normal ? MadeNormal{normal->pattern.get(), normal->amount, normal->accuracy,
                                                           in.normal_placement}
                                              : MadeNormal{};
        for (const auto& m : materials_)
            if (same(m.params, p) && m.pattern == pattern && m.placement == placement && m.normal == made_normal)
                return m.id;
        const SourceLocation at = tex.finish.at.known() ? tex.finish.at : (tex.at.known() ? tex.at : o.at);
        try {
            // A pigment_map of patterned pigments: one layer (its colour times its opacity, as
            // library_pigment's albedos) whose entries nest.
            if (pattern && pattern->image) warn_image_clearness(*pattern->image, tex);
            // So is an image map: its pixels' colour times their opacity.
            if (pattern && (!pattern->nested.empty() || pattern->image))
                p.diffuse_texture = AnyReflectanceField<S>(LayeredPigment<S>(
                    {layers_detail::pattern_layer<S>(*pattern, placement, Vector3(1.0), warn_, at, &images_)}));
            else if (pattern)
                p.diffuse_texture = AnyReflectanceField<S>(library_pigment<S>(*pattern, placement));
            if (normal) p.normal_field = library_normal_field<S>(*normal, in.normal_placement, &images_);
            const MaterialId id = scene_->add_material(Material<S>(p));
            materials_.push_back({p, pattern, placement, made_normal, id});
            return id;
        } catch (const std::invalid_argument& e) {
            throw Error(at, e.what());
        }
    }
    /// A layered texture's material, shared by the objects that inherit the same texture in the
    /// same place and interior.
    MaterialId layered_material_for(const Inherited& in, const Texture& tex, const Object& o) {
        for (const auto& m : layered_)
            if (m.texture == &tex && m.interior == in.interior && m.world == in.texture_world &&
                m.interior_world == in.interior_world)
                return m.id;
        const SourceLocation at = tex.finish.at.known() ? tex.finish.at : (tex.at.known() ? tex.at : o.at);
        try {
            MaterialParams<S> p = layered_material_params<S>(tex, in.texture_world, in.interior, desc_.settings,
                                                             desc_.version, warn_, o.at, &images_);
            if (in.interior) p.media = build_media<S>(in.interior->media, in.interior_world, warn_);
            const MaterialId id = scene_->add_material(Material<S>(p));
            layered_.push_back({&tex, in.interior, in.texture_world, in.interior_world, id});
            return id;
        } catch (const std::invalid_argument& e) {
            throw Error(at, e.what());
        }
    }
    /// A single texture's transmission is one value everywhere (its pigment's average colour's):
    /// said where an image map's pixels would let more or less through, as POV-Ray's do.
    void warn_image_clearness(const ImageMapDesc& m, const Texture& tex) {
        const bool alpha = images_.grid(m.file, true)->has_alpha;
        if (!alpha && !m.once && m.filter_all == 0 && m.transmit_all == 0) return;
        const SourceLocation at = tex.pigment.at.known() ? tex.pigment.at : m.file.at;
        warn_(at,
              std::string("the image map's pixels differ in how much they let through (") +
                  (alpha ? "the image's alpha" : m.once ? "clear outside the image (`once`)" : "`filter`/`transmit all`") +
                  "): photon's transmission is the same everywhere (filter " + format_number(m.filter_all) +
                  ", transmit " + format_number(m.transmit_all) +
                  "); its colour is weighed by each pixel's opacity. A layer under it (`texture { ... } texture "
                  "{ image_map ... }`) shows through exactly",
              "approximated pigment", "image_map");
    }
    /// POV-Ray fills a `hollow` object with the media around it (an enclosing object's, or the
    /// atmosphere); photon keeps no stack of nested objects, so a transmissive one without media
    /// of its own is clear inside: said where the scene has media.
    void warn_hollow_without_media(const Object& o, const Material<S>& material) {
        if (!o.hollow.value_or(false) || !material.params().media.empty() || is_black(material.params().transmission))
            return;
        if (!scene_has_media()) return;
        warn_(o.at,
              "`hollow` does not fill this transmissive object with the media around it: photon keeps no stack of "
              "nested objects, so its inside is clear (give it an interior media to fill it)",
              "approximated media", "hollow");
    }
    [[nodiscard]] bool scene_has_media() {
        if (!has_media_) {
            const std::function<bool(const Object&)> any = [&](const Object& o) {
                if (o.interior && !o.interior->media.empty()) return true;
                const auto* u = std::get_if<UnionShape>(&o.shape);
                const auto* c = std::get_if<CsgShape>(&o.shape);
                for (const auto& child : u ? u->children : c ? c->children : std::vector<std::shared_ptr<const Object>>{})
                    if (any(*child)) return true;
                return false;
            };
            has_media_ = !desc_.media.empty() ||
                         std::any_of(desc_.objects.begin(), desc_.objects.end(), [&](const Object& o) { return any(o); });
        }
        return *has_media_;
    }

    static bool same(const MaterialParams<S>& a, const MaterialParams<S>& b) {
        return a.diffuse == b.diffuse && a.specular == b.specular && a.transmission == b.transmission &&
               a.ior == b.ior && a.fresnel == b.fresnel && a.phong == b.phong && a.phong_exponent == b.phong_exponent &&
               a.blinn == b.blinn && a.blinn_exponent == b.blinn_exponent && a.metallic == b.metallic &&
               a.highlight_color == b.highlight_color && a.brilliance == b.brilliance && a.ambient == b.ambient &&
               a.absorption == b.absorption && a.media.empty() && b.media.empty();  // media: never shared
    }


    const SceneDescription& desc_;
    Warnings& warn_;
    DefaultScene<S>* scene_ = nullptr;
    /// What makes two materials' normals the same (pattern null: no normal).
    struct MadeNormal {
        const PigmentPattern* pattern = nullptr;
        double amount = 0, accuracy = 0;
        Transform placement;
        friend bool operator==(const MadeNormal&, const MadeNormal&) = default;
    };
    struct MadeMaterial {
        MaterialParams<S> params;
        const PigmentPattern* pattern;  ///< null: untextured
        Transform placement;
        MadeNormal normal;
        MaterialId id;
    };
    std::vector<MadeMaterial> materials_;
    struct MadeLayered {
        const Texture* texture;
        const Interior* interior;
        Transform world;
        Transform interior_world;
        MaterialId id;
    };
    std::vector<MadeLayered> layered_;
    std::optional<bool> has_media_;  ///< whether any media are written (scene_has_media)
    std::vector<SourceLocation> object_at_, light_at_;  ///< where each of the scene's objects and lights is written
    std::size_t max_primitives_;
    unsigned build_threads_ = 0;
    std::size_t file_triangles_ = 0;  ///< triangles of mesh files, for every use of them
    ImageFiles& images_;
    MeshFiles mesh_files_;
    FontFiles font_files_;
    ShapePlacement<S> placement_{font_files_, images_};
    std::size_t skipped_ = 0;  ///< objects photon has no shape for
};

}  // namespace photon::dsl::detail
