// SPDX-License-Identifier: MIT
#pragma once
// Which files a scene may open: POV-Ray's I/O restrictions (povray.conf's [File I/O Security]
// and [Permitted Paths], vfe/unix/unixoptions.cpp and vfeplatform.cpp's TestAccessAllowed in
// POV-Ray 3.7). A scene file is a program that names paths (#include, #fopen, image, mesh and
// font files); each is checked here before it is opened, its symbolic links and `..` resolved
// first, so that a scene from elsewhere reads only the folders its user permits.

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace photon::dsl {

/// POV-Ray's three levels of [File I/O Security].
enum class IoRestrictions {
    none,        ///< any file the user can read or write
    read_only,   ///< read anything; write only in `read+write` folders
    restricted,  ///< read and write only in the permitted folders
};

/// The level's name as povray.conf and `--io-restrictions` write it.
[[nodiscard]] inline std::string_view io_restrictions_name(IoRestrictions level) {
    switch (level) {
    case IoRestrictions::none: return "none";
    case IoRestrictions::read_only: return "read-only";
    case IoRestrictions::restricted: return "restricted";
    }
    return "restricted";
}

/// The level named `name`; nullopt for another word.
[[nodiscard]] inline std::optional<IoRestrictions> io_restrictions_named(std::string_view name) {
    for (const IoRestrictions l : {IoRestrictions::none, IoRestrictions::read_only, IoRestrictions::restricted})
        if (name == io_restrictions_name(l)) return l;
    return std::nullopt;
}

/// POV-Ray's install folder, povray.conf's %INSTALLDIR% (Debian's POVLIBDIR).
inline constexpr std::string_view povray_install_folder = "/usr/share/povray-3.7";

/// `p` made absolute (from the current folder) with its symbolic links and `..` resolved as far
/// as it exists, the rest appended as written but normalised: the path a check must judge,
/// since opening `p` opens this.
[[nodiscard]] inline std::filesystem::path resolved_path(const std::filesystem::path& p) {
    std::error_code ec;
    std::filesystem::path absolute = std::filesystem::absolute(p, ec);
    if (ec) absolute = p;
    std::filesystem::path r = std::filesystem::weakly_canonical(absolute, ec);
    if (ec) r = absolute.lexically_normal();
    return r;
}

/// One [Permitted Paths] entry: `read = folder`, `read* = folder`, `read+write = folder`, ...
struct PermittedFolder {
    std::filesystem::path folder;  ///< resolved (resolved_path)
    bool descend = false;          ///< `*`: its subfolders too
    bool writable = false;         ///< `read+write`: writing too (writing implies reading)
    std::string origin;            ///< who permitted it, for messages: "the scene's folder", "povray.conf:52"

    /// Whether this entry covers the resolved path `file` (POV-Ray's TestPath: the file's own
    /// folder is this folder, or below it when `descend`).
    [[nodiscard]] bool covers(const std::filesystem::path& file) const {
        const std::filesystem::path dir = file.parent_path();
        auto f = dir.begin();
        for (auto it = folder.begin(); it != folder.end(); ++it, ++f) {
            if (it->empty() && std::next(it) == folder.end()) break;  // a trailing separator
            if (f == dir.end() || *f != *it) return false;
        }
        return f == dir.end() || descend;
    }
};

enum class FileAccess { read, write };

/// The level and the permitted folders a read of a scene follows.
struct FileAccessRules {
    IoRestrictions level = IoRestrictions::restricted;
    std::string level_origin = "photon's default";  ///< where the level was set, for messages
    std::vector<PermittedFolder> permitted;
    /// How a refused path can be permitted, for messages: what the program reading the scene
    /// offers (the `photon` program names its options).
    std::string how_to_permit = "permit its folder in photon::dsl::ParseOptions::file_access";

    void permit(const std::filesystem::path& folder, bool descend, bool writable, std::string origin) {
        permitted.push_back({resolved_path(folder), descend, writable, std::move(origin)});
    }

    /// Whether the resolved path `file` may be opened for `access` (TestAccessAllowed).
    [[nodiscard]] bool permits(const std::filesystem::path& file, FileAccess access) const {
        if (level == IoRestrictions::none) return true;
        if (access == FileAccess::read && level == IoRestrictions::read_only) return true;
        return std::any_of(permitted.begin(), permitted.end(), [&](const PermittedFolder& p) {
            return (access == FileAccess::read || p.writable) && p.covers(file);
        });
    }

    /// Why `written` (as the scene wrote it; it resolves to a refused path) may not be opened.
    /// It names the rule and how to permit the path, and no path the scene did not write: the
    /// target of a link or of `..` stays unsaid, as does whether the file exists.
    [[nodiscard]] std::string refusal(const std::string& written, FileAccess access) const {
        const bool write = access == FileAccess::write;
        std::string folders;
        for (const PermittedFolder& p : permitted)
            if (!write || p.writable) folders += (folders.empty() ? "" : ", ") + p.origin;
        return std::string(write ? "writing" : "reading") + " \"" + written + "\" is not permitted: it is outside the folders a scene may " +
               (write ? "write" : "read") + " under the I/O restrictions `" + std::string(io_restrictions_name(level)) +
               "` (" + level_origin + ")" + (folders.empty() ? "" : ": " + folders) + "; " + how_to_permit;
    }
};

}  // namespace photon::dsl
