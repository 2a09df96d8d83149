// SPDX-License-Identifier: MIT
#pragma once
// Bit-for-bit comparison of two films, for the render tests that require the same image.

#include <photon/film/film.hpp>

#include <cstring>

namespace photon {

inline bool identical(const Film& a, const Film& b) {
    return a.width() == b.width() && a.height() == b.height() &&
           std::memcmp(a.pixels().data(), b.pixels().data(), a.pixels().size() * sizeof(Rgb<float>)) == 0;
}

}  // namespace photon
