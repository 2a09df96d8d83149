// SPDX-License-Identifier: MIT
#pragma once
// The build step's warnings: each said once per place and message, to the caller's sink.

#include <set>
#include <string>
#include <utility>

#include "../diagnostics.hpp"

namespace photon::dsl {

/// Reports a warning (or a note) once per place and message.
class Warnings {
public:
    explicit Warnings(DiagnosticSink sink) : sink_(std::move(sink)) {}
    void operator()(const SourceLocation& at, const std::string& message, std::string kind = {},
                    std::string keyword = {}) {
        if (!seen_.insert(at.str() + '\x1f' + message).second) return;
        if (sink_) sink_({Severity::warning, at, message, std::move(kind), std::move(keyword)});
    }
    /// Reports a note (Severity::note) once per place and message.
    void note(const SourceLocation& at, const std::string& message) {
        if (!seen_.insert(at.str() + '\x1f' + message).second) return;
        if (sink_) sink_({Severity::note, at, message, {}, {}});
    }

private:
    DiagnosticSink sink_;
    std::set<std::string> seen_;
};

}  // namespace photon::dsl
