// The few dense matrix operations the logistic regression needs, for matrices of a handful of
// rows (one per model coefficient), computed by Eigen. The header stays Eigen-free so that the
// analysis' plain types need no Eigen where they are used.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

namespace monoplane::analysis {

class Matrix {
  public:
    Matrix() = default;
    Matrix(std::size_t rows, std::size_t columns)
        : rows_(rows), columns_(columns), values_(rows * columns, 0.0) {}

    std::size_t rows() const { return rows_; }
    std::size_t columns() const { return columns_; }
    double& operator()(std::size_t r, std::size_t c) { return values_[r * columns_ + c]; }
    double operator()(std::size_t r, std::size_t c) const { return values_[r * columns_ + c]; }
    // The values row by row (row-major), rows() * columns() of them.
    double* data() { return values_.data(); }
    const double* data() const { return values_.data(); }

  private:
    std::size_t rows_ = 0, columns_ = 0;
    std::vector<double> values_;
};

Matrix operator*(const Matrix& a, const Matrix& b);

// The inverse of a symmetric positive definite matrix through its Cholesky factor, or nullopt
// when a pivot falls below 1e-10 of its diagonal entry: the matrix is singular to working
// precision (in a regression: columns that are linear combinations of others). Only the lower
// triangle is read.
std::optional<Matrix> inverse_positive_definite(const Matrix& a);

}  // namespace monoplane::analysis
