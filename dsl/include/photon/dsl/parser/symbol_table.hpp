// SPDX-License-Identifier: MIT
#pragma once
// The symbol table: the identifiers a scene declares, by scope. `scopes_` (parser_class.hpp)
// holds one map per scope, the global one first; a macro call and an include file each push one
// for their #local identifiers (a macro's parameters among them). A parameter passed by
// reference is a Value naming the caller's identifier (ref_scope, ref_name), followed here on
// reading and on assigning. `A[i][j]` names an array element, as the token stream writes it.

#include "parser_class.hpp"

namespace photon::dsl::detail {

// A global identifier set before the scene is read: photon_version and the caller's defines.
inline void Parser::declare_global(const std::string& name, ValueData v, const SourceLocation& at) {
    scopes_.front()[name] = Value{std::move(v), at};
}

/// The value `name` has in the innermost scope that declares it, following macro parameters
/// passed by reference; `A[i][j]` (as the token stream writes an element) names an element.
inline const Value* Parser::lookup(const std::string& name) const {
    for (std::size_t i = scopes_.size(); i-- > 0;)
        if (const Value* v = lookup_in(i, name)) return v;
    return nullptr;
}

// The value `name` has in `scope` alone, following a reference; an element `A[i]` is found in
// its array there.
inline const Value* Parser::lookup_in(std::size_t scope, const std::string& name) const {
    if (scope >= scopes_.size()) return nullptr;
    if (name.find('[') != std::string::npos) {  // split only an element's name: this runs for every name read
        std::string base;
        std::vector<std::size_t> indices;
        split_element(name, base, indices);
        const auto f = scopes_[scope].find(base);
        const Value* v = f == scopes_[scope].end() ? nullptr : follow(&f->second);
        const Array* a = v ? std::get_if<Array>(&v->data) : nullptr;
        if (!a || !a->elements || indices.size() != a->sizes.size()) return nullptr;
        const std::size_t i = flat_index(*a, indices);
        return i < a->elements->size() ? (*a->elements)[i].get() : nullptr;
    }
    const auto f = scopes_[scope].find(name);
    return f == scopes_[scope].end() ? nullptr : follow(&f->second);
}

/// A reference names a scope below its own, so following references ends.
inline const Value* Parser::follow(const Value* v) const {
    return v && v->is_reference() ? lookup_in(v->ref_scope, v->ref_name) : v;
}

/// `#declare` changes the identifier where it is visible (a macro's parameter, an include
/// file's local, the caller's identifier a parameter refers to) and makes a new one global;
/// `#local` makes or changes one in the innermost scope. These are POV-Ray's rules.
inline void Parser::assign(const Token& id, ValueData v, bool local) {
    std::string base;
    std::vector<std::size_t> indices;
    const bool element = split_element(id.text, base, indices);
    std::size_t found = Value::no_ref;
    for (std::size_t i = scopes_.size(); i-- > 0;)
        if (scopes_[i].count(base)) {
            found = i;
            break;
        }
    if (element && found == Value::no_ref) fail(id.location, "undefined array `" + base + "`");
    if (element && local && found != scopes_.size() - 1)
        fail(id.location, "cannot use `#local` to assign an element of `" + base +
                              "`, which is not local here: use `#declare`");
    std::size_t scope = found;
    std::string key = base;
    if (local && found != scopes_.size() - 1) {
        scope = scopes_.size() - 1;
    } else if (found == Value::no_ref) {
        scope = 0;
    } else {
        // Follow parameters passed by reference to the identifier they name.
        for (;;) {
            const auto f = scopes_[scope].find(key);
            if (f == scopes_[scope].end() || !f->second.is_reference()) break;
            const std::size_t s = f->second.ref_scope;
            key = f->second.ref_name;
            scope = s;
            if (key.find('[') != std::string::npos) break;
        }
    }
    if (element) {
        if (key.find('[') != std::string::npos)
            fail(id.location, "`" + base + "` refers to an array element, not an array: cannot index it");
        key += id.text.substr(base.size());
    }
    store_at(scope, key, std::move(v), id.location);
}

// Stores `v` as `key` in `scope`: an element `A[i]` goes into its array (through a parameter that
// refers to the array); a global name replaces a macro of that name.
inline void Parser::store_at(std::size_t scope, const std::string& key, ValueData v, const SourceLocation& at) {
    std::string base;
    std::vector<std::size_t> indices;
    if (!split_element(key, base, indices)) {
        if (scope == 0) macros_.erase(key);
        scopes_[scope][key] = Value{std::move(v), at};
        return;
    }
    const auto f = scopes_[scope].find(base);
    if (f != scopes_[scope].end() && f->second.is_reference()) {
        const std::size_t to = f->second.ref_scope;
        store_at(to, f->second.ref_name + key.substr(base.size()), std::move(v), at);
        return;
    }
    Array* a = f == scopes_[scope].end() ? nullptr : std::get_if<Array>(&f->second.data);
    if (!a) fail(at, "`" + base + "` is not an array");
    if (indices.size() != a->sizes.size()) fail(at, "`" + key + "`: wrong number of indices");
    set_element(*a, flat_index(*a, indices), std::move(v), key, at);
}

}  // namespace photon::dsl::detail
