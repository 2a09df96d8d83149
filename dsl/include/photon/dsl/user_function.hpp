// SPDX-License-Identifier: MIT
#pragma once
// User functions (`#declare F = function(a, b) { EXPR }`): the body compiled once, at the
// declaration, into a small tree of nodes, and evaluated at each call with the arguments. POV-Ray
// compiles its functions into a virtual machine for isosurfaces; photon calls them only where an
// expression does, so a tree over doubles is enough. Evaluation is bounded (steps and call depth)
// because a function may call earlier functions, which could otherwise multiply the work.

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "description.hpp"
#include "diagnostics.hpp"
#include "parser/builtin_math.hpp"
#include "value.hpp"

namespace photon::dsl {

struct UserFunction;

/// Bounds on the evaluation's recursion (the stack): calls inside calls, and the height of one
/// body's tree (`1+1+1...` is as high as it is long).
inline constexpr unsigned max_function_calls_deep = 32;
inline constexpr unsigned max_function_body_height = 200;

/// One node of a compiled body; children are indices into UserFunction::nodes.
struct FunctionNode {
    enum class Kind : std::uint8_t {
        constant,    ///< value
        parameter,   ///< slot `index` (a parameter, or the variable of an enclosing sum/prod)
        negate,      ///< -a
        logical_not, ///< !a
        add, subtract, multiply, divide,
        less, less_equal, equal, not_equal, greater_equal, greater,
        logical_and, logical_or,
        conditional,  ///< a ? b : c
        builtin,      ///< a float built-in (`builtin`) of the children
        call,         ///< `callee` of the children; component `index` of its value
        sum, product  ///< slot `index` from a to b (children 0 and 1) over child 2
    };
    Kind kind = Kind::constant;
    detail::FloatBuiltin builtin = detail::FloatBuiltin::abs;
    std::uint32_t index = 0;
    double value = 0;
    std::vector<std::uint32_t> children;
    std::shared_ptr<const UserFunction> callee;
    SourceLocation at;
};

struct UserFunction {
    enum class Kind : std::uint8_t {
        expression,  ///< a compiled body
        pigment,     ///< `function { pigment { } }`: the pigment's colour at (x, y, z)
        transform,   ///< `function { transform { } }`: the transformed point (x, y, z)
        pattern,     ///< `function { pattern { } }`: read, not evaluated by photon
        internal     ///< `function { internal(N) }`: one of POV-Ray's built-in functions
    };
    Kind kind = Kind::expression;
    std::vector<std::string> parameters;  ///< named slots 0..n-1; sum/prod variables follow
    std::uint32_t slots = 0;
    std::vector<FunctionNode> nodes;
    std::uint32_t root = 0;
    Pigment pigment;
    Transform transform;
    int internal_number = 0;
    std::string name;  ///< the identifier first declared, for messages
    SourceLocation at;

    /// Whether a call gives a colour or a vector rather than a number.
    [[nodiscard]] bool vector_valued() const noexcept { return kind == Kind::pigment || kind == Kind::transform; }
};

/// The work one top-level call may do, shared by the calls it makes.
struct FunctionBudget {
    std::uint64_t steps_left;
    unsigned depth_left;
};

namespace detail {

inline double evaluate_node(const UserFunction& f, std::uint32_t i, std::vector<double>& slots, FunctionBudget& b);

/// f(args): a number (dim 0), a colour (pigment functions) or a vector (transform functions).
/// Throws Error at the node where a value is not finite or a function cannot be evaluated.
inline Numeric call_user_function(const UserFunction& f, std::span<const double> args, FunctionBudget& b,
                                  const SourceLocation& at) {
    if (b.depth_left == 0)
        throw Error(at, "functions call each other too deeply (more than " + std::to_string(max_function_calls_deep) +
                            " calls inside each other)");
    auto arg = [&](std::size_t i) { return i < args.size() ? args[i] : 0.0; };
    switch (f.kind) {
        case UserFunction::Kind::pigment:
            return Numeric::from_color(f.pigment.color);  // photon's pigments are one colour everywhere
        case UserFunction::Kind::transform:
            return Numeric::vector(f.transform.point({arg(0), arg(1), arg(2)}));
        case UserFunction::Kind::pattern:
            throw Error(at, "`" + f.name + "` is a pattern function (declared at " + f.at.str() +
                                "): photon reads patterns but does not evaluate them");
        case UserFunction::Kind::internal:
            throw Error(at, "`" + f.name + "` is POV-Ray's internal function " + std::to_string(f.internal_number) +
                                " (declared at " + f.at.str() + "), which photon does not evaluate");
        case UserFunction::Kind::expression:
            break;
    }
    std::vector<double> slots(f.slots, 0.0);
    for (std::size_t i = 0; i < f.parameters.size() && i < args.size(); ++i) slots[i] = args[i];
    --b.depth_left;
    const double v = evaluate_node(f, f.root, slots, b);
    ++b.depth_left;
    return Numeric::scalar(v);
}

inline double evaluate_node(const UserFunction& f, std::uint32_t i, std::vector<double>& slots, FunctionBudget& b) {
    const FunctionNode& n = f.nodes[i];
    if (b.steps_left == 0) throw Error(n.at, "function evaluation too long: the step budget of the scene is used up");
    --b.steps_left;
    auto arg = [&](std::size_t k) { return evaluate_node(f, n.children[k], slots, b); };
    auto finite = [&](double v, const char* what) {
        if (!std::isfinite(v)) throw Error(n.at, std::string("the result of `") + what + "` is not a finite number");
        return v;
    };
    using K = FunctionNode::Kind;
    switch (n.kind) {
        case K::constant: return n.value;
        case K::parameter: return slots[n.index];
        case K::negate: return -arg(0);
        case K::logical_not: return arg(0) == 0.0 ? 1.0 : 0.0;
        case K::add: return finite(arg(0) + arg(1), "+");
        case K::subtract: return finite(arg(0) - arg(1), "-");
        case K::multiply: return finite(arg(0) * arg(1), "*");
        case K::divide: {
            const double a = arg(0), d = arg(1);
            if (d == 0.0) throw Error(n.at, "division by zero");
            return finite(a / d, "/");
        }
        case K::less: return arg(0) < arg(1);
        case K::less_equal: return arg(0) <= arg(1);
        case K::equal: return arg(0) == arg(1);
        case K::not_equal: return arg(0) != arg(1);
        case K::greater_equal: return arg(0) >= arg(1);
        case K::greater: return arg(0) > arg(1);
        case K::logical_and: return arg(0) != 0.0 && arg(1) != 0.0;  // both sides are evaluated in
        case K::logical_or: return arg(0) != 0.0 || arg(1) != 0.0;   // order; C's short cut is fine
        case K::conditional: return arg(0) != 0.0 ? arg(1) : arg(2);
        case K::builtin: {
            double a[8];
            std::vector<double> many;
            std::span<double> values(a, n.children.size());
            if (n.children.size() > 8) many.resize(n.children.size()), values = many;
            for (std::size_t k = 0; k < n.children.size(); ++k) values[k] = arg(k);
            const std::string_view name = float_builtin_name(n.builtin);
            if (zero_divisor(n.builtin, values)) throw Error(n.at, "division by zero in `" + std::string(name) + "`");
            return finite(apply_float_builtin(n.builtin, values), name.data());
        }
        case K::call: {
            std::vector<double> values(n.children.size());
            for (std::size_t k = 0; k < n.children.size(); ++k) values[k] = arg(k);
            const Numeric r = call_user_function(*n.callee, values, b, n.at);
            return r.dim == 0 ? r.c[0] : r.c[n.index];
        }
        case K::sum:
        case K::product: {
            const double from = arg(0), to = arg(1);
            double acc = n.kind == K::sum ? 0.0 : 1.0;
            for (double v = from; v <= to; v += 1.0) {
                slots[n.index] = v;
                const double term = arg(2);
                acc = n.kind == K::sum ? acc + term : acc * term;
            }  // a loop that would not end (from 1e300) ends when the step budget does
            return finite(acc, n.kind == K::sum ? "sum" : "prod");
        }
    }
    return 0;
}

}  // namespace detail
}  // namespace photon::dsl
