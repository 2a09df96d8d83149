// SPDX-License-Identifier: MIT
#pragma once
// POV-Ray's povray.conf, the I/O restrictions it sets: [File I/O Security] (none, read-only,
// restricted) and [Permitted Paths] (`read`, `read*`, `read+write`, `read+write*` = folder), as
// POV-Ray 3.7 reads them (vfe/unix/unixoptions.cpp, parse_conf_file and add_permitted_path):
// `;` starts a comment, a folder may be quoted, %INSTALLDIR% and %HOME% are replaced, and a
// relative folder is from the current folder. [Shellout Security] is accepted and has no
// effect (photon runs no commands); other sections are POV-Ray's custom ones, skipped as POV-Ray
// skips them. Where POV-Ray warns and ignores a bad line, photon stops with a located error: a
// security setting read wrongly is no setting to guess.

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>

#include "diagnostics.hpp"
#include "file_access.hpp"

namespace photon::dsl {

namespace povray_conf_detail {

inline std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

inline void replace_all(std::string& s, std::string_view what, std::string_view with) {
    for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + with.size()))
        s.replace(at, what.size(), with);
}

}  // namespace povray_conf_detail

/// Applies the povray.conf text `text` (named `name` in messages) to `rules`: its level, if it
/// sets one, replaces theirs, and its folders are added. Throws dsl::Error at a line it cannot read.
inline void apply_povray_conf(FileAccessRules& rules, std::string text, const std::string& name) {
    using povray_conf_detail::trim;
    const auto file = std::make_shared<SourceFile>(SourceFile{name, std::move(text)});
    enum class Section { none, file_io, shellout, permitted_paths, other } section = Section::none;
    std::istringstream in(file->text);
    std::string raw;
    for (std::uint32_t line = 1; std::getline(in, raw); ++line) {
        std::string_view s = raw;
        if (const auto semicolon = s.find(';'); semicolon != std::string_view::npos) s = s.substr(0, semicolon);
        s = trim(s);
        if (s.empty()) continue;
        const SourceLocation at{file, line, std::uint32_t(raw.find_first_not_of(" \t") + 1)};
        if (s.front() == '[') {
            section = s.rfind("[File I/O Security]", 0) == 0   ? Section::file_io
                      : s.rfind("[Shellout Security]", 0) == 0 ? Section::shellout
                      : s.rfind("[Permitted Paths]", 0) == 0   ? Section::permitted_paths
                                                               : Section::other;
            continue;
        }
        switch (section) {
        case Section::file_io: {
            const auto level = io_restrictions_named(s);
            if (!level) throw Error(at, "expected `none`, `read-only` or `restricted` in [File I/O Security], found `" + std::string(s) + "`");
            rules.level = *level;
            rules.level_origin = name + ":" + std::to_string(line);
            break;
        }
        case Section::shellout:
            if (s != "allowed" && s != "forbidden")
                throw Error(at, "expected `allowed` or `forbidden` in [Shellout Security], found `" + std::string(s) + "`");
            break;  // photon runs no commands: forbidden whatever it says
        case Section::permitted_paths: {
            // read[+write][*] = FOLDER, FOLDER bare, or in single or double quotes
            const bool writable = s.rfind("read+write", 0) == 0;
            if (s.rfind("read", 0) != 0) throw Error(at, "expected `read`, `read*`, `read+write` or `read+write*` = FOLDER, found `" + std::string(s) + "`");
            std::string_view rest = s.substr(writable ? 10 : 4);
            const bool descend = !rest.empty() && rest.front() == '*';
            if (descend) rest.remove_prefix(1);
            rest = trim(rest);
            if (rest.empty() || rest.front() != '=')
                throw Error(at, std::string("expected `=` and a folder after `") + (writable ? "read+write" : "read") +
                                    (descend ? "*" : "") + "`");
            rest = trim(rest.substr(1));
            std::string folder;
            if (!rest.empty() && (rest.front() == '"' || rest.front() == '\'')) {
                const auto close = rest.find(rest.front(), 1);
                if (close == std::string_view::npos) throw Error(at, std::string("no closing ") + rest.front() + " after the folder");
                folder = rest.substr(1, close - 1);
            } else {
                folder = rest.substr(0, std::min(rest.size(), rest.find_first_of(" \t")));
            }
            if (folder.empty()) throw Error(at, "expected a folder after `=`");
            povray_conf_detail::replace_all(folder, "%INSTALLDIR%", povray_install_folder);
            if (folder.find("%HOME%") != std::string::npos) {
                const char* home = std::getenv("HOME");
                if (!home || !*home) throw Error(at, "%HOME% names no folder: HOME is not set");
                povray_conf_detail::replace_all(folder, "%HOME%", home);
            }
            rules.permit(folder, descend, writable, name + ":" + std::to_string(line));
            break;
        }
        case Section::none:
            throw Error(at, "expected a section ([File I/O Security], [Shellout Security] or [Permitted Paths]) before `" + std::string(s) + "`");
        case Section::other: break;  // POV-Ray's custom sections: not I/O settings
        }
    }
}

/// apply_povray_conf with the file at `path`; throws dsl::Error when it cannot be read.
inline void apply_povray_conf_file(FileAccessRules& rules, const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::error_code ec;
    if (!in || std::filesystem::is_directory(path, ec))
        throw Error({std::make_shared<SourceFile>(SourceFile{path.string(), {}}), 0, 0}, "cannot read the configuration file");
    std::ostringstream text;
    text << in.rdbuf();
    apply_povray_conf(rules, text.str(), path.string());
}

}  // namespace photon::dsl
