// SPDX-License-Identifier: MIT
// `photon export-pov`: the scene as one self-contained POV-Ray 3.7 file (photon/dsl/export_pov.hpp),
// written to a temporary file and renamed, so a failed write leaves no half file.

#include "commands.hpp"

// g++ 12 at -O3 warns -Wrestrict on `"<" + std::string(...)` inlined from export_pov.hpp: a false
// positive of libstdc++'s operator+ (GCC bug 105651), which the CLI's single unit happened not to
// trigger. This unit holds only the export, so the warning is off for it alone.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ == 12
#pragma GCC diagnostic ignored "-Wrestrict"
#endif
#include <photon/dsl/export_pov.hpp>
#include <photon/dsl/parser.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <unistd.h>

namespace photon::cli {

namespace fs = std::filesystem;

int run_export(SceneOptions& so, const std::string& output) {
    const dsl::SceneDescription desc = dsl::parse_file(so.scene, so.parse_options({}));
    const std::string text = dsl::export_pov(desc, so.sink());
    if (output.empty() || output == "-") {
        std::cout << text;
    } else {
        const fs::path path(output);
        fs::path tmp = path;
        tmp.replace_filename("." + path.filename().string() + ".tmp-" + std::to_string(::getpid()));
        {
            std::ofstream out(tmp, std::ios::binary);
            out << text;
            out.close();
            if (!out) {
                std::error_code ec;
                fs::remove(tmp, ec);
                throw std::runtime_error("cannot write " + output);
            }
        }
        std::error_code ec;
        fs::rename(tmp, path, ec);
        if (ec) {
            fs::remove(tmp, ec);
            throw std::runtime_error("cannot write " + output + ": " + ec.message());
        }
        if (!so.quiet) std::cerr << "photon: wrote " << output << '\n';
    }
    return so.failed_strict() ? exit_error : EXIT_SUCCESS;
}

}  // namespace photon::cli
