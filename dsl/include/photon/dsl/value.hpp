// SPDX-License-Identifier: MIT
#pragma once
// Values of POV-Ray's expressions and declarations: numbers, vectors and colours (one numeric
// type of 0 to 5 components, as POV-Ray promotes between them), strings, the declarable
// blocks (pigment, finish, interior, texture, transform, object, camera, material), arrays,
// splines and user functions.

#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "description.hpp"
#include "spline.hpp"

namespace photon::dsl {

/// A float (dim 0) or a vector of 2 to 5 components; colours are 5-component vectors (red,
/// green, blue, filter, transmit) flagged `color`.
struct Numeric {
    std::array<double, 5> c{};
    int dim = 0;
    bool color = false;

    [[nodiscard]] static Numeric scalar(double v) {
        Numeric n;
        n.c[0] = v;
        return n;
    }
    [[nodiscard]] static Numeric vector(const Vector3& v) {
        Numeric n;
        n.c = {v.x, v.y, v.z, 0, 0};
        n.dim = 3;
        return n;
    }
    [[nodiscard]] static Numeric from_color(const Color& col) {
        Numeric n;
        n.c = {col.rgb.x, col.rgb.y, col.rgb.z, col.filter, col.transmit};
        n.dim = 5;
        n.color = true;
        return n;
    }
    [[nodiscard]] bool is_float() const noexcept { return dim == 0; }
    /// Component i as POV-Ray promotes: a float fills every component, a short vector pads with 0.
    [[nodiscard]] double at(int i) const noexcept { return dim == 0 ? c[0] : (i < dim ? c[std::size_t(i)] : 0.0); }
    [[nodiscard]] bool finite() const noexcept {
        for (int i = 0; i < (dim == 0 ? 1 : dim); ++i)
            if (!std::isfinite(c[std::size_t(i)])) return false;
        return true;
    }
};

/// Shortest text that reads back as the same double.
[[nodiscard]] inline std::string format_number(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

[[nodiscard]] inline std::string describe(const Numeric& n) {
    if (n.dim == 0) return "the number " + format_number(n.c[0]);
    std::string s = n.color ? "the colour <" : "the vector <";
    for (int i = 0; i < n.dim; ++i) s += (i ? ", " : "") + format_number(n.c[std::size_t(i)]);
    return s + ">";
}

/// `material { texture { } interior { } }`: what it sets on the object it is used in.
struct MaterialBlock {
    std::optional<Texture> texture;
    std::optional<Interior> interior;
    SourceLocation at;
};

/// A declared blend map (`color_map`, `pigment_map`, `texture_map`, `normal_map`, ...): what photon
/// keeps of it, each entry's value and colour (a pigment or texture entry reduced to its colour),
/// and for a texture_map the first entry's finish.
struct BlendMap {
    std::string keyword;
    std::vector<std::pair<double, Color>> entries;
    /// A pigment_map's entries as pigments where patterned (null where a colour); empty otherwise.
    std::vector<std::shared_ptr<const Pigment>> pigments;
    std::optional<Finish> finish;
    bool reduced = false;  ///< an entry was a patterned pigment or texture, kept as its average colour
};

/// A declared block photon reads but does not render (`fog`, `media`, `rainbow`, ...).
struct IgnoredBlock {
    std::string keyword;
};

struct UserFunction;  // user_function.hpp

struct Value;

/// `array[N][M]...`: the sizes, and the elements in row-major order, each unset until assigned.
/// Elements are shared between copies (copy on write), so `#declare B = A` and passing an
/// array to a macro cost one pointer, as values keep POV-Ray's copy semantics.
struct Array {
    std::vector<std::size_t> sizes;
    /// Null until an element is set; changed only where no other copy shares it.
    std::shared_ptr<std::vector<std::shared_ptr<const Value>>> elements;
    bool mixed = false;  ///< POV-Ray 3.8's `array mixed`: elements of different types
    int kind = -1;       ///< the ValueData index of the elements (POV-Ray's arrays hold one type)
    SourceLocation at;
    [[nodiscard]] std::size_t count() const noexcept {
        std::size_t n = 1;
        for (std::size_t s : sizes) n *= s;
        return n;
    }
};

using ValueData = std::variant<Numeric, std::string, Pigment, Finish, Interior, Texture, Transform, Object,
                               CameraDescription, MaterialBlock, Array, Spline, std::shared_ptr<const UserFunction>,
                               BlendMap, IgnoredBlock, Normal, SkySphere, FogDescription,
                               MediaDescription>;

/// A declared identifier's value and where it was declared. A macro parameter passed by
/// reference (a bare identifier as the argument, as in POV-Ray) holds no value of its own but
/// names the caller's identifier: `ref_name` in the scope `ref_scope`.
struct Value {
    Value() = default;
    Value(ValueData d, SourceLocation a) : data(std::move(d)), at(std::move(a)) {}
    ValueData data;
    SourceLocation at;
    std::size_t ref_scope = no_ref;
    std::string ref_name;
    static constexpr std::size_t no_ref = std::size_t(-1);
    [[nodiscard]] bool is_reference() const noexcept { return ref_scope != no_ref; }
};

/// "a texture", "an object", ... for messages.
[[nodiscard]] inline std::string type_name(const ValueData& v) {
    switch (v.index()) {
        case 0: {
            const auto& n = std::get<Numeric>(v);
            return n.dim == 0 ? "a number" : (n.color ? "a colour" : "a vector");
        }
        case 1:
            return "a string";
        case 2:
            return "a pigment";
        case 3:
            return "a finish";
        case 4:
            return "an interior";
        case 5:
            return "a texture";
        case 6:
            return "a transform";
        case 7:
            return std::holds_alternative<LightSource>(std::get<Object>(v).shape) ? "a light_source" : "an object";
        case 8:
            return "a camera";
        case 9:
            return "a material";
        case 10:
            return "an array";
        case 11:
            return "a spline";
        case 12:
            return "a function";
        case 13:
            return "a " + std::get<BlendMap>(v).keyword;
        case 14:
            return "a " + std::get<IgnoredBlock>(v).keyword;
        case 15:
            return "a normal";
        case 16:
            return "a sky_sphere";
        case 17:
            return "a fog";
        default:
            return "a media";
    }
}

}  // namespace photon::dsl
