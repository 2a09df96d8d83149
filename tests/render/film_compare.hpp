// SPDX-License-Identifier: MIT
#pragma once
// Comparing films in the render tests: bit for bit where they require the same image, block by
// block where modes must agree within noise.

#include <photon/film/film.hpp>

#include <cstring>
#include <vector>

namespace photon {

inline bool identical(const Film& a, const Film& b) {
    // An empty film (no error image) has no pixel array: memcmp must not see its null pointer.
    return a.width() == b.width() && a.height() == b.height() &&
           (a.pixels().empty() ||
            std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size() * sizeof(Rgb<float>)) == 0);
}

/// Mean red, green and blue of the pixels of each of bx x by equal blocks (row-major; pixels
/// beyond the last whole block are left out).
inline std::vector<Rgb<double>> block_means(const Film& film, unsigned bx, unsigned by) {
    std::vector<Rgb<double>> means(std::size_t(bx) * by, Rgb<double>(0.0));
    const unsigned w = film.width() / bx, h = film.height() / by;
    for (unsigned y = 0; y < by * h; ++y)
        for (unsigned x = 0; x < bx * w; ++x) means[(y / h) * bx + x / w] += Rgb<double>(film.at(x, y)) / double(w * h);
    return means;
}

}  // namespace photon
