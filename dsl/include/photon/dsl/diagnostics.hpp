// SPDX-License-Identifier: MIT
#pragma once
// Source locations, diagnostics and the located error of the scene language. Messages follow the
// compilers' convention, `file:line:column: error: what was expected, found what was found`,
// followed by the source line and a caret under the column (as GCC and Clang print them).

#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace photon::dsl {

/// A scene file as read: the name shown in messages and its whole text.
struct SourceFile {
    std::string name;
    std::string text;
};

/// Where something was written: 1-based line and column (in bytes) of `file`. A default
/// location (no file) prints as `<unknown>`.
struct SourceLocation {
    std::shared_ptr<const SourceFile> file;
    std::uint32_t line = 0, column = 0;

    [[nodiscard]] bool known() const noexcept { return file != nullptr && line > 0; }
    [[nodiscard]] std::string file_name() const { return file ? file->name : std::string("<unknown>"); }
    /// `file:line:column`, or the file name alone when the line is unknown.
    [[nodiscard]] std::string str() const {
        if (!known()) return file_name();
        return file->name + ":" + std::to_string(line) + ":" + std::to_string(column);
    }
};

/// A note informs without saying photon approximated anything (a scene without lights, the
/// scene's own #warning); a warning says what photon skipped or approximated; an error stops.
enum class Severity { warning, error, note };

struct Diagnostic {
    Severity severity = Severity::error;
    SourceLocation location;
    std::string message;
    /// What photon did with a construct it reads but does not render ("skipped object",
    /// "approximated pigment", "ignored effect", ...) and that construct's keyword, for the
    /// summary of `photon check`; empty for other warnings.
    std::string kind, keyword;
};

/// Receives warnings as they are found (errors are thrown as dsl::Error). Tests collect them.
using DiagnosticSink = std::function<void(const Diagnostic&)>;

/// Line `line` (1-based) of `text` without its line break; empty when out of range.
[[nodiscard]] inline std::string_view source_line(std::string_view text, std::uint32_t line) {
    std::size_t begin = 0;
    for (std::uint32_t l = 1; l < line; ++l) {
        begin = text.find('\n', begin);
        if (begin == std::string_view::npos) return {};
        ++begin;
    }
    if (begin > text.size()) return {};
    std::size_t end = text.find('\n', begin);
    if (end == std::string_view::npos) end = text.size();
    if (end > begin && text[end - 1] == '\r') --end;
    return text.substr(begin, end - begin);
}

/// `file:line:column: error: message`, then the source line and a caret under the column. With
/// `quote_source` false, the first line alone: a program decides which files its messages may
/// quote (the `photon` program quotes only those the scene may read).
[[nodiscard]] inline std::string format_diagnostic(const Diagnostic& d, bool quote_source = true) {
    std::string out = d.location.str() + ": " + (d.severity == Severity::error ? "error: " : d.severity == Severity::note ? "note: " : "warning: ") + d.message;
    if (!d.location.known() || !quote_source) return out;
    const std::string_view line = source_line(d.location.file->text, d.location.line);
    if (line.empty() && d.location.column <= 1) return out;
    out += "\n  ";
    out += line;
    out += "\n  ";
    // Keep tabs so that the caret lines up with the echoed line in any terminal.
    for (std::uint32_t c = 1; c < d.location.column; ++c)
        out += (c - 1 < line.size() && line[c - 1] == '\t') ? '\t' : ' ';
    out += '^';
    return out;
}

/// Bad input: a message tied to a place in a scene file. what() is the full formatted text.
class Error : public std::runtime_error {
public:
    Error(SourceLocation location, std::string message)
        : std::runtime_error(format_diagnostic({Severity::error, location, message, {}, {}})),
          location_(std::move(location)),
          message_(std::move(message)) {}

    [[nodiscard]] const SourceLocation& location() const noexcept { return location_; }
    /// The message alone, without location and source line.
    [[nodiscard]] const std::string& message() const noexcept { return message_; }

private:
    SourceLocation location_;
    std::string message_;
};

}  // namespace photon::dsl
