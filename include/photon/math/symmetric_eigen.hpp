// SPDX-License-Identifier: MIT
#pragma once
// Eigenvalues and eigenvectors of a symmetric 3x3 matrix by cyclic Jacobi rotations: a few
// sweeps reach full double precision, and the eigenvectors stay orthonormal (what a quadric's
// bounding box needs: which axes its solid extends along forever, and how far along the others).

#include <cmath>

#include <glm/mat3x3.hpp>

namespace photon {

struct SymmetricEigen3 {
    glm::dvec3 values{0.0};
    glm::dmat3 vectors{1.0};  ///< column k is the unit eigenvector of values[k]
};

/// `m` must be symmetric (only its upper triangle is read).
[[nodiscard]] inline SymmetricEigen3 symmetric_eigen(const glm::dmat3& m) noexcept {
    double a[3][3];
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) a[i][j] = i <= j ? m[j][i] : m[i][j];  // glm: m[column][row]
    glm::dmat3 v(1.0);
    for (int sweep = 0; sweep < 32; ++sweep) {
        const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (!(off > 1e-36 * diag)) break;
        for (int p = 0; p < 2; ++p)
            for (int q = p + 1; q < 3; ++q) {
                if (a[p][q] == 0.0) continue;
                // The rotation that zeroes a[p][q] (Golub and Van Loan, algorithm 8.4.2).
                const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
                const double t = std::copysign(1.0, theta) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
                const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
                for (int k = 0; k < 3; ++k) {  // columns p and q
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - s * akq;
                    a[k][q] = s * akp + c * akq;
                }
                for (int k = 0; k < 3; ++k) {  // rows p and q
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - s * aqk;
                    a[q][k] = s * apk + c * aqk;
                }
                for (int k = 0; k < 3; ++k) {
                    const double vkp = v[p][k], vkq = v[q][k];
                    v[p][k] = c * vkp - s * vkq;
                    v[q][k] = s * vkp + c * vkq;
                }
            }
    }
    return {glm::dvec3(a[0][0], a[1][1], a[2][2]), v};
}

}  // namespace photon
