// SPDX-License-Identifier: MIT
#pragma once
// The image files a scene names (image_map, bump_map, height_field), read in the build step
// through the reader the program supplies (BuildOptions::read_image): the scene language needs
// no image library itself, and the photon program loads OpenImageIO only when a scene names an
// image (src/image_io_module). Programs that link OpenImageIO pass photon::read_pixel_grid
// (photon/io/image_file.hpp). Errors point at the file's name in the scene.

#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

#include <photon/texture/pixel_grid.hpp>

#include "description.hpp"
#include "diagnostics.hpp"
#include "mesh_files.hpp"

namespace photon::dsl {

/// Reads an image file into pixels decoded by the gamma given; throws (any std::exception) when
/// it cannot.
using ImageReader = std::function<PixelGrid(const std::filesystem::path&, ImageGamma)>;

/// How POV-Ray 3.7 decodes a scene's input images (parser_materials.cpp, Parse_Image).
struct ImageDecoding {
    /// The scene's assumed_gamma, if it writes one, and its #version (none: 3.62 for POV-Ray).
    std::optional<double> assumed_gamma, version;

    /// For image_map (colours): the `gamma` written, else the file's own; but no decoding in a
    /// scene older than 3.7 (POV-Ray 3.6 left images as stored, or decoded them by the working
    /// gamma it encodes them with again). For height fields and bump maps (`colour` false): only
    /// a written `gamma`.
    [[nodiscard]] ImageGamma gamma_for(const ImageFile& f, bool colour) const {
        if (f.gamma) return *f.gamma == 0 ? ImageGamma{ImageGamma::Kind::srgb} : ImageGamma{ImageGamma::Kind::power, *f.gamma};
        if (!colour || version.value_or(3.62) < 3.7 - 1e-9) return {ImageGamma::Kind::none};
        return {ImageGamma::Kind::file};
    }
    /// The working gamma linear colours are encoded with, for image_map's colours (1: linear).
    [[nodiscard]] double working_gamma() const {
        return version.value_or(3.62) < 3.7 - 1e-9 ? 1.0 : assumed_gamma.value_or(1.0);
    }
};

/// Reads each image once per decoding, however many textures use it.
class ImageFiles {
public:
    /// For geometry alone (object_geometry.hpp): image maps' colours are not read, one grey pixel
    /// stands for each.
    static constexpr struct ColoursAsGrey {} colours_as_grey{};

    ImageFiles(ImageReader reader, ImageDecoding decoding) : reader_(std::move(reader)), decoding_(decoding) {}
    ImageFiles(ImageReader reader, ImageDecoding decoding, ColoursAsGrey)
        : reader_(std::move(reader)), decoding_(decoding), grey_colours_(true) {}

    /// Files are read (a reader was given).
    [[nodiscard]] bool reads() const noexcept { return static_cast<bool>(reader_); }

    /// The pixels of `file`, decoded for colours (`colour`) or as stored values. Throws
    /// dsl::Error at the file's name in the scene when it cannot be read.
    std::shared_ptr<const PixelGrid> grid(const ImageFile& file, bool colour) {
        if (colour && grey_colours_) return std::make_shared<const PixelGrid>(1u, 1u, std::vector<PixelGrid::Pixel>{{0.5f, 0.5f, 0.5f, 1.0f}});
        const ImageGamma g = decoding_.gamma_for(file, colour);
        const double working = colour ? decoding_.working_gamma() : 1.0;
        auto& slot = read_[{file.path, int(g.kind), g.gamma, working}];
        if (!slot) slot = std::make_shared<const PixelGrid>(read(file, g, working));
        return slot;
    }

private:
    [[nodiscard]] PixelGrid read(const ImageFile& file, ImageGamma g, double working) const {
        if (!reader_)
            throw Error(file.at, "this program reads no images (photon::dsl::BuildOptions::read_image is not set): "
                                 "cannot read \"" + file.written + "\"");
        PixelGrid grid;
        try {
            grid = reader_(std::filesystem::path(display_path(file.path)), g);
        } catch (const std::exception& e) {
            throw Error(file.at, std::string("cannot read the image: ") + e.what());
        }
        if (working != 1.0)  // linear values encoded in the scene's working space, as POV-Ray keeps them
            for (auto& p : grid.pixels())
                for (int c = 0; c < 3; ++c) p[std::size_t(c)] = float(std::pow(std::max(0.0f, p[std::size_t(c)]), 1.0 / working));
        return grid;
    }

    ImageReader reader_;
    ImageDecoding decoding_;
    bool grey_colours_ = false;
    std::map<std::tuple<std::filesystem::path, int, double, double>, std::shared_ptr<const PixelGrid>> read_;
};

}  // namespace photon::dsl
