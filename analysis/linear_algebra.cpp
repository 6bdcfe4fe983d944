#include "analysis/linear_algebra.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace monoplane::analysis {

Matrix operator*(const Matrix& a, const Matrix& b) {
    assert(a.columns() == b.rows());
    Matrix product(a.rows(), b.columns());
    for (std::size_t i = 0; i < a.rows(); ++i)
        for (std::size_t k = 0; k < a.columns(); ++k)
            for (std::size_t j = 0; j < b.columns(); ++j) product(i, j) += a(i, k) * b(k, j);
    return product;
}

std::optional<Matrix> inverse_positive_definite(const Matrix& a) {
    assert(a.rows() == a.columns());
    const std::size_t n = a.rows();
    // a = L L^T.
    Matrix l(n, n);
    for (std::size_t j = 0; j < n; ++j) {
        double pivot = a(j, j);
        for (std::size_t k = 0; k < j; ++k) pivot -= l(j, k) * l(j, k);
        // Relative to the diagonal entry, so the test does not depend on the columns' units.
        if (!(pivot > 1e-10 * std::abs(a(j, j))) || a(j, j) <= 0.0) return std::nullopt;
        l(j, j) = std::sqrt(pivot);
        for (std::size_t i = j + 1; i < n; ++i) {
            double sum = a(i, j);
            for (std::size_t k = 0; k < j; ++k) sum -= l(i, k) * l(j, k);
            l(i, j) = sum / l(j, j);
        }
    }
    // L^-1 by forward substitution, then a^-1 = L^-T L^-1.
    Matrix l_inverse(n, n);
    for (std::size_t c = 0; c < n; ++c) {
        for (std::size_t i = c; i < n; ++i) {
            double sum = i == c ? 1.0 : 0.0;
            for (std::size_t k = c; k < i; ++k) sum -= l(i, k) * l_inverse(k, c);
            l_inverse(i, c) = sum / l(i, i);
        }
    }
    Matrix inverse(n, n);
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < n; ++j) {
            double sum = 0.0;
            for (std::size_t k = std::max(i, j); k < n; ++k)
                sum += l_inverse(k, i) * l_inverse(k, j);
            inverse(i, j) = sum;
        }
    return inverse;
}

}  // namespace monoplane::analysis
