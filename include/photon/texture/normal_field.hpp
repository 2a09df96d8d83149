// SPDX-License-Identifier: MIT
#pragma once
// A shading normal that varies over a surface: the concept a user's bump type satisfies (a
// NormalPerturbation does), and the shared, type-erased handle a Material keeps of one.

#include <concepts>
#include <memory>
#include <utility>

#include "../math/vec.hpp"

namespace photon {

/// A normal field: `f(p, n)` is the unit shading normal at world point p of a surface whose unit
/// geometric normal there is n (the outward one, before any turn towards a ray). Evaluated
/// concurrently from many threads: `f(p, n)` must be const and thread-safe.
template <class F, class S>
concept NormalField = Scalar<S> && std::copy_constructible<F> && requires(const F& f, const Vec3<S>& v) {
    { f(v, v) } -> std::convertible_to<Vec3<S>>;
};

/// Any NormalField, shared and immutable; empty (false) when default-constructed. One virtual
/// call per evaluation.
template <Scalar S> class AnyNormalField {
public:
    AnyNormalField() = default;
    // The same-type test comes first, as in AnyReflectanceField (a concept recursion clang rejects).
    template <class F>
        requires(!std::same_as<std::remove_cvref_t<F>, AnyNormalField> && NormalField<F, S>)
    explicit AnyNormalField(F field) : impl_(std::make_shared<const Model<F>>(std::move(field))) {}

    [[nodiscard]] explicit operator bool() const noexcept { return impl_ != nullptr; }
    [[nodiscard]] Vec3<S> operator()(const Vec3<S>& p, const Vec3<S>& n) const { return impl_->at(p, n); }
    /// Two handles to the same field compare equal (a copy shares its field).
    friend bool operator==(const AnyNormalField& a, const AnyNormalField& b) noexcept { return a.impl_ == b.impl_; }

private:
    struct Base {
        virtual ~Base() = default;
        [[nodiscard]] virtual Vec3<S> at(const Vec3<S>& p, const Vec3<S>& n) const = 0;
    };
    template <class F> struct Model final : Base {
        explicit Model(F f) : field(std::move(f)) {}
        [[nodiscard]] Vec3<S> at(const Vec3<S>& p, const Vec3<S>& n) const override { return Vec3<S>(field(p, n)); }
        F field;
    };
    std::shared_ptr<const Base> impl_;
};

}  // namespace photon
