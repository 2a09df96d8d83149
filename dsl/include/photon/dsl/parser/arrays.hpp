// SPDX-License-Identifier: MIT
#pragma once
// Arrays: `array[N][M] { {..}, {..} }`, elements of any declarable type, and `A[i][j]`. As in
// POV-Ray's tokenizer, the token stream turns `A[i][j]` into one identifier token naming the
// element (text `A[i][j]`, the indices evaluated and checked), so an element goes wherever an
// identifier of its type goes: expressions, `object { A[i] }`, `#declare A[i] =`, `defined(A[i])`.

#include "parser_class.hpp"

namespace photon::dsl::detail {

// ARRAY: array [mixed] [ INT ] {[ INT ]} [ { ELEMENTS } ]
inline Array Parser::parse_array(const Token& kw) {
    Array a;
    a.at = kw.location;
    if (peek().is_identifier("mixed")) {
        next();
        a.mixed = true;
    }
    std::uint64_t count = 1;
    // Looking past the last `]` must not run the next directive: `#declare A = array[2]` then
    // `#declare A[0] = 1` on the next line needs A declared first.
    auto peek_here = [&]() -> const Token& {
        suppress_.push_back(files_.size());
        const Token& t = peek();
        suppress_.pop_back();
        return t;
    };
    while (peek_here().is_symbol("[")) {
        next();
        const double limit = double(options_.max_array_elements);
        const auto n = std::size_t(parse_integer("the size of an array", 1, limit));
        expect_symbol("]", "to close the size of the array");
        count *= n;
        if (count > options_.max_array_elements || a.sizes.size() == 16)
            fail(kw.location, "array too large: more than " + std::to_string(options_.max_array_elements) +
                                  " elements or 16 dimensions");
        a.sizes.push_back(n);
    }
    if (a.sizes.empty()) fail_expected("`[` and the size of the array after `array`", peek());
    if (peek_here().is_symbol("{")) {
        std::size_t next_index = 0;
        parse_array_initialiser(a, 0, next_index, kw);
    }
    return a;
}

/// ELEMENTS: { RVALUE {[,] RVALUE} [,] } for the last dimension, { ELEMENTS {[,] ELEMENTS} [,] }
/// before it; each RVALUE read without comparisons (parse_rvalue's sums_only).
inline void Parser::parse_array_initialiser(Array& a, std::size_t dim, std::size_t& next_index, const Token& kw) {
    const Nest nest(*this, peek().location);
    const Token open = expect_symbol("{", "to open the elements of the array");
    for (std::size_t i = 0; i < a.sizes[dim]; ++i) {
        // POV-Ray's commas between elements are optional (allnormals.pov: `"Average""Boxed"`).
        if (i > 0 && !accept_symbol(",") && (peek().is_symbol("}") || peek().kind == TokenKind::end_of_file))
            fail_expected("`,` between the elements of the array (it has " + std::to_string(a.sizes[dim]) +
                              " in dimension " + std::to_string(dim + 1) + ")",
                          peek());
        if (dim + 1 < a.sizes.size()) {
            parse_array_initialiser(a, dim + 1, next_index, kw);
        } else {
            const SourceLocation at = peek().location;
            bool needs_semicolon = false;
            ValueData v = parse_rvalue("an element of the array", needs_semicolon, true);
            set_element(a, next_index++, std::move(v), "an element", at);
        }
    }
    accept_symbol(",");
    if (!peek().is_symbol("}"))
        fail_expected("`}` to close the " + std::to_string(a.sizes[dim]) + " elements of dimension " +
                          std::to_string(dim + 1) + " of the array (opened at " + position(open.location) + ")",
                      peek());
    next();
}

// Stores `v` at `index` of `a`: of the array's one type unless it is `mixed`; the elements are copied first
// when another value shares them, and counted against max_array_elements when made.
inline void Parser::set_element(Array& a, std::size_t index, ValueData v, const std::string& name,
                                const SourceLocation& at) {
    const int kind = int(v.index());
    if (!a.mixed && a.kind >= 0 && a.kind != kind) {
        std::string held = "another type";
        if (a.elements)
            for (const auto& e : *a.elements)
                if (e) {
                    held = type_name(e->data);
                    break;
                }
        fail(at, "cannot store " + type_name(v) + " in " + name + " of an array of " + held +
                     " (POV-Ray's arrays hold one type; `array mixed` holds any)");
    }
    if (!a.elements || a.elements.use_count() > 1) {
        array_elements_ += a.count();
        if (array_elements_ > options_.max_array_elements)
            fail(at, "arrays too large: more than " + std::to_string(options_.max_array_elements) +
                         " array elements made in all");
        charge_bytes(a.count() * (sizeof(std::shared_ptr<const Value>) + sizeof(Value)), at);  // as if full
        a.elements = a.elements ? std::make_shared<std::vector<std::shared_ptr<const Value>>>(*a.elements)
                                : std::make_shared<std::vector<std::shared_ptr<const Value>>>(a.count());
    }
    if (a.kind < 0) a.kind = kind;
    (*a.elements)[index] = std::make_shared<const Value>(Value{std::move(v), at});
}

/// ARRAY_ELEMENT: ARRAY_IDENT [ FLOAT ] {[ FLOAT ]}, an index for each dimension, after the
/// identifier `t` of an array: `t` becomes the element's name.
inline void Parser::expand_array_element(Token& t) {
    const Value* v = lookup(t.text);
    const Array* found = v ? std::get_if<Array>(&v->data) : nullptr;
    if (!found) return;
    const std::vector<std::size_t> sizes = found->sizes;
    const SourceLocation declared = v->at;
    auto next_is_bracket = [&] {
        const FileFrame& f = files_.back();
        if (f.macro && f.lexer.state().pos >= f.macro->body_end) return false;
        Lexer probe = f.lexer;
        return probe.next().is_symbol("[");
    };
    std::string name = t.text;
    std::size_t dims = 0;
    while (next_is_bracket()) {
        next();
        const SourceLocation at = peek().location;
        const bool saved = in_vector_;
        in_vector_ = false;
        const double x = to_float(parse_expression_for("an array index"), "an array index", at);
        in_vector_ = saved;
        expect_symbol("]", "to close the index of `" + t.text + "`");
        if (dims == sizes.size())
            fail(at, "too many indices: `" + t.text + "` has " + std::to_string(sizes.size()) + " dimension" +
                         (sizes.size() == 1 ? "" : "s"));
        if (!(x >= 0 && x < double(sizes[dims])))
            fail(at, "index " + format_number(x) + " is out of the bounds of `" + t.text + "` (indices 0 to " +
                         std::to_string(sizes[dims] - 1) + " in dimension " + std::to_string(dims + 1) +
                         ", declared at " + position_in(declared, at) + ")");
        name += '[';
        name += std::to_string(std::size_t(x));
        name += ']';
        ++dims;
    }
    if (dims == 0) return;
    if (dims < sizes.size())
        fail(t.location, "`" + t.text + "` has " + std::to_string(sizes.size()) + " dimensions: expected " +
                             std::to_string(sizes.size()) + " indices, found " + std::to_string(dims));
    t.text = std::move(name);
    if (reading_name_ == 0 && !lookup(t.text)) {
        const Value* array = lookup(t.text.substr(0, t.text.find('[')));
        if (array) fail_unset_element(t, *array);
    }
}

// The error for an element read before it is set.
[[noreturn]] inline void Parser::fail_unset_element(const Token& t, const Value& array) {
    fail(t.location, "the array element `" + t.text + "` is used before it is set (the array is declared at " +
                         position_in(array.at, t.location) + ")");
}

/// `A[1][2]` -> `A` and {1, 2}; false for a plain name.
inline bool Parser::split_element(const std::string& name, std::string& base, std::vector<std::size_t>& indices) {
    const std::size_t open = name.find('[');
    if (open == std::string::npos) {
        base = name;
        return false;
    }
    base = name.substr(0, open);
    indices.clear();
    std::size_t i = open;
    while (i < name.size() && name[i] == '[') {
        std::size_t v = 0;
        for (++i; i < name.size() && name[i] >= '0' && name[i] <= '9'; ++i) v = v * 10 + std::size_t(name[i] - '0');
        indices.push_back(v);
        ++i;  // `]`
    }
    return true;
}

// The index into the elements of `a` of the element at `indices`, row by row; past the end when an
// index is out of bounds.
inline std::size_t Parser::flat_index(const Array& a, const std::vector<std::size_t>& indices) {
    std::size_t flat = 0;
    for (std::size_t d = 0; d < indices.size() && d < a.sizes.size(); ++d) {
        if (indices[d] >= a.sizes[d]) return std::size_t(-1);
        flat = flat * a.sizes[d] + indices[d];
    }
    return flat;
}

// ARRAY_FUNCTION: dimensions ( ARRAY_IDENT ) | dimension_size ( ARRAY_IDENT , INT )
inline Numeric Parser::parse_array_function(const Token& f) {
    expect_symbol("(", "after `" + f.text + "`");
    const Token id = next();
    const Value* v = id.kind == TokenKind::identifier ? lookup(id.text) : nullptr;
    const Array* a = v ? std::get_if<Array>(&v->data) : nullptr;
    if (!a) fail_expected("an array identifier in `" + f.text + "( )`", id, v ? " (" + type_name(v->data) + ")" : "");
    const std::size_t dims = a->sizes.size();
    if (f.text == "dimensions") {
        expect_symbol(")", "to close `dimensions(`");
        return Numeric::scalar(double(dims));
    }
    const std::vector<std::size_t> sizes = a->sizes;
    expect_symbol(",", "after the array in `dimension_size(`");
    const auto d = std::size_t(parse_integer("the dimension in `dimension_size`", 1, double(dims)));
    expect_symbol(")", "to close `dimension_size(`");
    return Numeric::scalar(double(sizes[d - 1]));
}

}  // namespace photon::dsl::detail
