// SPDX-License-Identifier: MIT
#pragma once
// Where the files a scene names are looked for (beside the file that names them, then in each
// include folder), and the I/O restrictions every one passes before it is opened
// (file_access.hpp): #include, #fopen, file_exists(), image, height-field, mesh and font files.
// A refused path is never looked at, so a message says nothing of what is outside the
// permitted folders, not even whether a file is there.

#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

#include "parser_class.hpp"

namespace photon::dsl::detail {

/// The places a relative `written` is looked for: beside the file being read, then in each
/// include folder when `include_path`; an absolute one is itself.
inline std::vector<std::filesystem::path> Parser::search_places(const std::filesystem::path& written,
                                                                bool include_path) const {
    if (written.is_absolute()) return {written};
    std::vector<std::filesystem::path> places{files_.back().path.parent_path() / written};
    if (include_path)
        for (const auto& dir : options_.include_paths) places.push_back(dir / written);
    return places;
}

/// The first of `places` that the I/O restrictions permit reading and that is a regular file,
/// resolved (symbolic links and `..`); empty when none is. When none is found and one was
/// refused, the refusal is the error, at `name`.
inline std::filesystem::path Parser::find_readable(const std::vector<std::filesystem::path>& places, const Token& name) {
    bool refused = false;
    for (const auto& place : places) {
        const std::filesystem::path resolved = resolved_path(place);
        if (!access_.permits(resolved, FileAccess::read)) {
            refused = true;
            continue;
        }
        std::error_code ec;
        if (std::filesystem::is_regular_file(resolved, ec)) return resolved;
    }
    if (refused) fail(name.location, access_.refusal(name.text, FileAccess::read));
    return {};
}

/// Fails at `name` unless the I/O restrictions permit writing the file it names: a relative name
/// is from the scene's folder, where photon keeps what the scene writes (file_io.hpp).
inline void Parser::check_writable(const Token& name) const {
    const std::filesystem::path written(name.text);
    const std::filesystem::path place = written.is_absolute() ? written : files_.front().path.parent_path() / written;
    if (!access_.permits(resolved_path(place), FileAccess::write))
        fail(name.location, access_.refusal(name.text, FileAccess::write));
}

}  // namespace photon::dsl::detail
