// SPDX-License-Identifier: MIT
#pragma once
// Constructive solid geometry with POV-Ray's rules: `merge` (the union of the children's
// volumes, no inner surfaces), `intersection` (inside every child), `difference` (the first child
// minus the union of the others), `clip` (POV-Ray's `clipped_by`: the first child inside all the
// others, whose surfaces never show) and `inverse` on any node (inside and outside swap).
//
// A Csg is a tree stored flat: its leaves are Solid shapes (one std::variant of the leaf types,
// so it fits a Scene's closed set of shapes), its inner nodes the operations. A ray meets it
// where the membership of the whole tree changes: every leaf's crossings are walked in order
// along the ray (each leaf's intersect restarted just past its last crossing), each crossing
// sets that leaf's inside state (entering when its outward normal faces the ray), and the first
// crossing after which the tree's membership differs is the hit. Its normal is the leaf's,
// turned to point out of the result (so it flips on subtracted parts and under `inverse`).
// A crossing of a clipping leaf changes the membership but is never the hit: the walk goes on,
// so a sphere clipped by a plane shows its inside through the cut, as in POV-Ray.
//
// Choices where the rules are silent:
// - A leaf's state at the ray's origin is that implied by its first crossing (leaving: inside),
//   or contains(origin) when it has none before t_max; the crossings themselves decide after,
//   so contains() and the intersector cannot disagree mid-walk.
// - Coincident surfaces: crossings of several leaves within the rounding bound of the hit point
//   (geometry/offset.hpp) are applied together before the membership is judged, so a face shared
//   by a solid and the part cut from it disappears instead of speckling.
// - A `union` nested in a CSG node is a merge (its inner surfaces cannot change membership);
//   POV-Ray keeps them, which shows only through transparent objects.
// - A walk that exceeds 8 crossings per leaf plus 16 (only a degenerate leaf could) reports a miss.

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <variant>
#include <vector>

#include "half_space_bounds.hpp"
#include "offset.hpp"
#include "plane.hpp"
#include "solid.hpp"

namespace photon {

/// What a CSG node does with its children.
enum class CsgOp : std::uint8_t {
    leaf,          ///< one solid shape
    merge,         ///< inside any child
    intersection,  ///< inside every child
    difference,    ///< inside the first child and no other
    clip,          ///< inside every child, showing only the first child's surfaces
};

template <Scalar S, Solid... Leaves> class Csg {
    static_assert(sizeof...(Leaves) > 0, "a Csg needs at least one leaf type");
    static_assert((std::is_same_v<scalar_of<Leaves>, S> && ...), "all leaves must use the Csg's scalar type");

public:
    using scalar_type = S;
    using Leaf = std::variant<Leaves...>;

    /// One solid, a tree of one leaf (implicit, so that lists of children read naturally).
    template <class L>
        requires(!std::is_same_v<std::remove_cvref_t<L>, Csg> && std::is_constructible_v<Leaf, L>)
    Csg(L&& leaf) {  // NOLINT(google-explicit-constructor)
        leaves_.emplace_back(std::forward<L>(leaf));
        nodes_.push_back({CsgOp::leaf, false, 0, 1});
        update_bounds();
    }

    /// Throw std::invalid_argument when `children` is empty.
    [[nodiscard]] static Csg merge(std::vector<Csg> children) { return Csg(CsgOp::merge, std::move(children)); }
    [[nodiscard]] static Csg intersection(std::vector<Csg> children) {
        return Csg(CsgOp::intersection, std::move(children));
    }
    /// The first child minus the union of the others (POV-Ray's difference).
    [[nodiscard]] static Csg difference(std::vector<Csg> children) {
        return Csg(CsgOp::difference, std::move(children));
    }

    /// POV-Ray's `clipped_by`: the parts of `object`'s surface inside every one of `clips`
    /// (its inside is theirs and object's, as POV-Ray's Inside test with a clip). Throw
    /// std::invalid_argument when `clips` is empty.
    [[nodiscard]] static Csg clipped(Csg object, std::vector<Csg> clips) {
        if (clips.empty()) throw std::invalid_argument("csg: clipped needs at least one clipping object");
        clips.insert(clips.begin(), std::move(object));
        return Csg(CsgOp::clip, std::move(clips));
    }

    /// POV-Ray's `inverse`: inside and outside of this tree swap, and so do its normals.
    Csg& invert() noexcept {
        nodes_.back().inverted = !nodes_.back().inverted;
        bounds_ = node_bounds(root());
        return *this;
    }

    [[nodiscard]] CsgOp op() const noexcept { return nodes_.back().op; }
    [[nodiscard]] bool inverted() const noexcept { return nodes_.back().inverted; }
    /// The leaves in order; Hit::part of a hit is the index of the leaf whose surface it is on.
    [[nodiscard]] std::span<const Leaf> leaves() const noexcept { return leaves_; }
    /// The children of the root (empty for a leaf), as trees of their own.
    [[nodiscard]] std::vector<Csg> children() const {
        std::vector<Csg> out;
        const Node& root = nodes_.back();
        if (root.op != CsgOp::leaf)
            for (std::uint32_t k = 0; k < root.count; ++k) out.push_back(subtree(children_[root.first + k]));
        return out;
    }

    /// Merge: the children's boxes joined; intersection: their overlap (empty if they do not
    /// overlap: nothing to render); difference: the first child's; inverted: unbounded.
    [[nodiscard]] BBox<S> bounds() const noexcept { return bounds_; }

    [[nodiscard]] bool contains(const Vec3<S>& p) const noexcept {
        return with_states([&](std::span<std::uint8_t> inside) {
            for (std::size_t i = 0; i < leaves_.size(); ++i)
                inside[i] = std::visit([&](const auto& leaf) { return leaf.contains(p); }, leaves_[i]);
            return member(root(), inside.data());
        });
    }

    /// Nearest point with t in (0, ray.t_max) where the ray crosses the tree's boundary; the
    /// normal points out of the tree's volume and `part` names the leaf.
    [[nodiscard]] std::optional<Hit<S>> intersect(const Ray<S>& ray) const noexcept {
        if (bounds_.is_empty()) return std::nullopt;
        const std::size_t n = leaves_.size();
        if (n <= inline_leaves) {
            std::array<Walk, inline_leaves> walks;
            std::array<std::uint8_t, inline_leaves> inside;
            return walk(ray, std::span<Walk>(walks.data(), n), std::span<std::uint8_t>(inside.data(), n));
        }
        std::vector<Walk> walks(n);
        std::vector<std::uint8_t> inside(n);
        return walk(ray, walks, inside);
    }

private:
    struct Node {
        CsgOp op;
        bool inverted;
        std::uint32_t first;  ///< leaf: its index in leaves_; else its first entry in children_
        std::uint32_t count;  ///< number of children (1 for a leaf)
    };
    /// One leaf's progress along the ray: its next crossing, in the ray's own t.
    struct Walk {
        Hit<S> next{};
        bool found = false;
        Vec3<S> origin{};  ///< where its current ray starts
        S start = S(0);    ///< the ray's t at that origin
    };
    static constexpr std::size_t inline_leaves = 16;

    Csg() = default;
    Csg(CsgOp op, std::vector<Csg> children) {
        if (children.empty()) throw std::invalid_argument("csg: an operation needs at least one child");
        std::vector<std::uint32_t> roots;
        for (Csg& c : children) {
            const auto node_offset = std::uint32_t(nodes_.size()), leaf_offset = std::uint32_t(leaves_.size()),
                       child_offset = std::uint32_t(children_.size());
            for (Leaf& leaf : c.leaves_) leaves_.push_back(std::move(leaf));
            for (std::uint32_t k : c.children_) children_.push_back(k + node_offset);
            for (Node node : c.nodes_) {
                node.first += node.op == CsgOp::leaf ? leaf_offset : child_offset;
                nodes_.push_back(node);
            }
            roots.push_back(std::uint32_t(nodes_.size() - 1));
        }
        nodes_.push_back({op, false, std::uint32_t(children_.size()), std::uint32_t(roots.size())});
        children_.insert(children_.end(), roots.begin(), roots.end());
        update_bounds();
    }

    [[nodiscard]] std::uint32_t root() const noexcept { return std::uint32_t(nodes_.size() - 1); }

    /// The tree below `node`, copied out (nodes are stored children first, so it is a prefix-
    /// closed range ending at `node`; only the leaves it reaches are kept).
    [[nodiscard]] Csg subtree(std::uint32_t node) const {
        const Node& n = nodes_[node];
        if (n.op == CsgOp::leaf) {
            Csg c(leaves_[n.first]);
            if (n.inverted) c.invert();
            return c;
        }
        std::vector<Csg> kids;
        for (std::uint32_t k = 0; k < n.count; ++k) kids.push_back(subtree(children_[n.first + k]));
        Csg c(n.op, std::move(kids));
        if (n.inverted) c.invert();
        return c;
    }

    [[nodiscard]] bool member(std::uint32_t node, const std::uint8_t* inside) const noexcept {
        const Node& n = nodes_[node];
        const std::uint32_t* kids = children_.data() + n.first;
        bool in = false;
        switch (n.op) {
        case CsgOp::leaf: in = inside[n.first] != 0; break;
        case CsgOp::merge:
            for (std::uint32_t k = 0; k < n.count && !in; ++k) in = member(kids[k], inside);
            break;
        case CsgOp::intersection:
        case CsgOp::clip:
            in = true;
            for (std::uint32_t k = 0; k < n.count && in; ++k) in = member(kids[k], inside);
            break;
        case CsgOp::difference:
            in = member(kids[0], inside);
            for (std::uint32_t k = 1; k < n.count && in; ++k) in = !member(kids[k], inside);
            break;
        }
        return in != n.inverted;
    }

    [[nodiscard]] BBox<S> node_bounds(std::uint32_t node) const noexcept {
        const Node& n = nodes_[node];
        if (n.inverted) return BBox<S>::infinite();
        const std::uint32_t* kids = children_.data() + n.first;
        switch (n.op) {
        case CsgOp::leaf: return std::visit([](const auto& leaf) { return leaf.bounds(); }, leaves_[n.first]);
        case CsgOp::merge: {
            BBox<S> b;
            for (std::uint32_t k = 0; k < n.count; ++k) b.extend(node_bounds(kids[k]));
            return b;
        }
        case CsgOp::intersection:
        case CsgOp::clip: {
            BBox<S> b = BBox<S>::infinite();
            std::vector<HalfSpace> planes;  // children that are planes bound it together
            for (std::uint32_t k = 0; k < n.count; ++k) {
                const Node& kid = nodes_[kids[k]];
                if constexpr ((std::is_same_v<Leaves, Plane<S>> || ...)) {
                    if (const auto* plane = kid.op == CsgOp::leaf ? std::get_if<Plane<S>>(&leaves_[kid.first]) : nullptr) {
                        const double sign = kid.inverted ? -1.0 : 1.0;
                        planes.push_back({sign * glm::dvec3(plane->normal()), sign * double(plane->offset())});
                        continue;
                    }
                }
                const BBox<S> c = node_bounds(kids[k]);
                b.min = glm::max(b.min, c.min);
                b.max = glm::min(b.max, c.max);
            }
            if (b.is_empty()) return BBox<S>{};
            if (planes.empty()) return b;
            for (int a = 0; a < 3; ++a) {  // the other children's box closes the planes too
                glm::dvec3 axis(0.0);
                axis[a] = 1.0;
                if (std::isfinite(b.max[a])) planes.push_back({axis, double(b.max[a])});
                if (std::isfinite(b.min[a])) planes.push_back({-axis, -double(b.min[a])});
            }
            const BBox<S> p = half_space_bounds<S>(planes);
            b.min = glm::max(b.min, p.min);
            b.max = glm::min(b.max, p.max);
            return b.is_empty() ? BBox<S>{} : b;
        }
        case CsgOp::difference: return node_bounds(kids[0]);
        }
        return BBox<S>::infinite();
    }
    /// The bounds, and which leaves only clip (their crossings are never hits).
    void update_bounds() {
        bounds_ = node_bounds(root());
        hidden_.assign(leaves_.size(), 0);
        mark_hidden(root(), false);
    }
    void mark_hidden(std::uint32_t node, bool hidden) {
        const Node& n = nodes_[node];
        if (n.op == CsgOp::leaf) {
            hidden_[n.first] = hidden;
            return;
        }
        for (std::uint32_t k = 0; k < n.count; ++k)
            mark_hidden(children_[n.first + k], hidden || (n.op == CsgOp::clip && k > 0));
    }

    template <class F> auto with_states(F&& f) const {
        if (leaves_.size() <= inline_leaves) {
            std::array<std::uint8_t, inline_leaves> inside{};
            return f(std::span<std::uint8_t>(inside.data(), leaves_.size()));
        }
        std::vector<std::uint8_t> inside(leaves_.size());
        return f(std::span<std::uint8_t>(inside));
    }

    /// Finds leaf i's next crossing from its current origin, before the ray's t_max.
    void advance_to_next(std::size_t i, Walk& w, const Ray<S>& ray) const noexcept {
        w.found = false;
        const Ray<S> r{w.origin, ray.direction, ray.t_max - w.start};
        if (!(r.t_max > S(0))) return;
        auto hit = std::visit([&](const auto& leaf) { return leaf.intersect(r); }, leaves_[i]);
        if (!hit) return;
        hit->t += w.start;
        w.next = *hit;
        w.found = true;
    }

    /// Restarts leaf i just past its crossing: pushed off the surface by the rounding bound of
    /// the hit point, towards where the ray goes, and as far along the ray (for grazing rays).
    void step_past(std::size_t i, Walk& w, const Ray<S>& ray, S inv_speed2) const noexcept {
        const Hit<S>& h = w.next;
        const S error = intersection_error(h.point, w.origin);
        const Vec3<S> side = glm::dot(h.normal, ray.direction) >= S(0) ? h.normal : -h.normal;
        w.origin = offset_origin(h.point, side, error) + ray.direction * (error * std::sqrt(inv_speed2));
        w.start = h.t + glm::dot(w.origin - h.point, ray.direction) * inv_speed2;
        advance_to_next(i, w, ray);
    }

    std::optional<Hit<S>> walk(const Ray<S>& ray, std::span<Walk> walks, std::span<std::uint8_t> inside) const noexcept {
        const S speed2 = glm::dot(ray.direction, ray.direction);
        if (!(speed2 > S(0)) || !std::isfinite(speed2)) return std::nullopt;
        const S inv_speed2 = S(1) / speed2;
        for (std::size_t i = 0; i < walks.size(); ++i) {
            Walk& w = walks[i];
            w.origin = ray.origin;
            w.start = S(0);
            advance_to_next(i, w, ray);
            inside[i] = w.found ? glm::dot(w.next.normal, ray.direction) > S(0)
                                : std::visit([&](const auto& leaf) { return leaf.contains(ray.origin); }, leaves_[i]);
        }
        bool was_inside = member(root(), inside.data());
        const std::size_t max_steps = 8 * walks.size() + 16;
        for (std::size_t step = 0; step < max_steps; ++step) {
            std::size_t nearest = walks.size();
            for (std::size_t i = 0; i < walks.size(); ++i)
                if (walks[i].found && (nearest == walks.size() || walks[i].next.t < walks[nearest].next.t)) nearest = i;
            if (nearest == walks.size()) return std::nullopt;
            const Hit<S>& first = walks[nearest].next;
            // Crossings this close to the nearest one are the same place up to rounding.
            const S together = first.t + S(2) * intersection_error(first.point, ray.origin) * std::sqrt(inv_speed2);
            for (std::size_t i = 0; i < walks.size(); ++i)
                if (walks[i].found && walks[i].next.t <= together)
                    inside[i] = glm::dot(walks[i].next.normal, ray.direction) < S(0);
            const bool now_inside = member(root(), inside.data());
            // The surface that shows here: the nearest crossing of a leaf that is not a clip's.
            std::size_t shown = walks.size();
            for (std::size_t i = 0; i < walks.size(); ++i)
                if (walks[i].found && walks[i].next.t <= together && !hidden_[i] &&
                    (shown == walks.size() || walks[i].next.t < walks[shown].next.t))
                    shown = i;
            if (now_inside != was_inside && shown != walks.size()) {
                const Hit<S>& crossing = walks[shown].next;
                if (!(crossing.t > S(0)) || !(crossing.t < ray.t_max)) return std::nullopt;
                Hit<S> hit = crossing;
                const bool faces_ray = glm::dot(hit.normal, ray.direction) < S(0);
                if (faces_ray != now_inside) hit.normal = -hit.normal;  // out of the result's volume
                hit.part = std::uint32_t(shown);
                return hit;
            }
            if (!(first.t < ray.t_max)) return std::nullopt;
            was_inside = now_inside;
            for (std::size_t i = 0; i < walks.size(); ++i)
                if (walks[i].found && walks[i].next.t <= together) step_past(i, walks[i], ray, inv_speed2);
        }
        return std::nullopt;
    }

    std::vector<Leaf> leaves_;
    std::vector<Node> nodes_;                ///< children before parents; the root is last
    std::vector<std::uint32_t> children_;  ///< node indices of each operation's children
    std::vector<std::uint8_t> hidden_;     ///< per leaf: 1 when it only clips (never a hit)
    BBox<S> bounds_;
};

}  // namespace photon
