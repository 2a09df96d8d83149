// SPDX-License-Identifier: MIT
#pragma once
// A reflectance that varies over space: the concept a user's texture type satisfies (a Pigment
// does), and the shared, type-erased handle a Material keeps of one.

#include <concepts>
#include <memory>
#include <utility>

#include "../math/vec.hpp"

namespace photon {

/// A texture: `f(p)` is the colour (each channel in [0, upper_bound()]) at world point p, and
/// `f.upper_bound()` bounds it per channel (a Material checks energy conservation with it).
/// Evaluated concurrently from many threads: `f(p)` must be const and thread-safe.
template <class F, class S>
concept ReflectanceField = Scalar<S> && std::copy_constructible<F> && requires(const F& f, const Vec3<S>& p) {
    { f(p) } -> std::convertible_to<Rgb<S>>;
    { f.upper_bound() } -> std::convertible_to<Rgb<S>>;
};

/// Any ReflectanceField, shared and immutable; empty (false) when default-constructed. One
/// virtual call per evaluation.
template <Scalar S> class AnyReflectanceField {
public:
    AnyReflectanceField() = default;
    // The same-type test comes first: it stops the concept's copy_constructible check from
    // asking about this constructor again (a recursion clang rejects).
    template <class F>
        requires(!std::same_as<std::remove_cvref_t<F>, AnyReflectanceField> && ReflectanceField<F, S>)
    explicit AnyReflectanceField(F field)
        : bound_(Rgb<S>(field.upper_bound())), impl_(std::make_shared<const Model<F>>(std::move(field))) {}

    [[nodiscard]] explicit operator bool() const noexcept { return impl_ != nullptr; }
    [[nodiscard]] Rgb<S> operator()(const Vec3<S>& p) const { return impl_->at(p); }
    [[nodiscard]] Rgb<S> upper_bound() const noexcept { return bound_; }
    /// Two handles to the same field compare equal (a copy shares its field).
    friend bool operator==(const AnyReflectanceField& a, const AnyReflectanceField& b) noexcept {
        return a.impl_ == b.impl_;
    }

private:
    struct Base {
        virtual ~Base() = default;
        [[nodiscard]] virtual Rgb<S> at(const Vec3<S>& p) const = 0;
    };
    template <class F> struct Model final : Base {
        explicit Model(F f) : field(std::move(f)) {}
        [[nodiscard]] Rgb<S> at(const Vec3<S>& p) const override { return Rgb<S>(field(p)); }
        F field;
    };
    Rgb<S> bound_{S(0)};
    std::shared_ptr<const Base> impl_;
};

}  // namespace photon
