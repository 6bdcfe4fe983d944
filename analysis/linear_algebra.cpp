#include "analysis/linear_algebra.h"

#include <cmath>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "common/programming_error.h"

namespace monoplane::analysis {
namespace {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

Eigen::Map<const RowMajor> view(const Matrix& m) {
    return {m.data(), static_cast<Eigen::Index>(m.rows()), static_cast<Eigen::Index>(m.columns())};
}

Eigen::Map<RowMajor> view(Matrix& m) {
    return {m.data(), static_cast<Eigen::Index>(m.rows()), static_cast<Eigen::Index>(m.columns())};
}

}  // namespace

Matrix operator*(const Matrix& a, const Matrix& b) {
    MONOPLANE_EXPECTS(a.columns() == b.rows());
    Matrix product(a.rows(), b.columns());
    view(product).noalias() = view(a) * view(b);
    return product;
}

std::optional<Matrix> inverse_positive_definite(const Matrix& a) {
    MONOPLANE_EXPECTS(a.rows() == a.columns());
    const Eigen::LLT<RowMajor> llt(view(a));
    if (llt.info() != Eigen::Success) return std::nullopt;
    // Eigen refuses only pivots at or below zero; a pivot (L_jj^2) tiny next to its diagonal
    // entry is singular too. Relative, so the test does not depend on the columns' units.
    const RowMajor l = llt.matrixL();
    for (Eigen::Index j = 0; j < l.rows(); ++j) {
        const double diagonal = view(a)(j, j);
        if (!(diagonal > 0.0) || !(l(j, j) * l(j, j) > 1e-10 * diagonal)) return std::nullopt;
    }
    const RowMajor solved = llt.solve(RowMajor::Identity(l.rows(), l.cols()));
    Matrix inverse(a.rows(), a.columns());
    // Exactly symmetric, as the covariance matrices made of it are read (only one triangle of
    // them by Eigen's self-adjoint solvers).
    view(inverse) = 0.5 * (solved + solved.transpose());
    return inverse;
}

}  // namespace monoplane::analysis
