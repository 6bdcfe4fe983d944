#include "analysis/small_sample_covariance.h"

#include <cmath>

#include <Eigen/Dense>

#include "common/programming_error.h"

namespace monoplane::analysis {
namespace {

// clubSandwich's matrix_power(x, -1/2): eigenvalues at or below this are treated as zero.
constexpr double kEigenvalueTolerance = 1e-12;

Eigen::MatrixXd to_eigen(const Matrix& m) {
    Eigen::MatrixXd out(static_cast<Eigen::Index>(m.rows()),
                        static_cast<Eigen::Index>(m.columns()));
    for (std::size_t r = 0; r < m.rows(); ++r)
        for (std::size_t c = 0; c < m.columns(); ++c)
            out(static_cast<Eigen::Index>(r), static_cast<Eigen::Index>(c)) = m(r, c);
    return out;
}

Matrix from_eigen(const Eigen::MatrixXd& m) {
    Matrix out(m.rows(), m.cols());
    for (Eigen::Index r = 0; r < m.rows(); ++r)
        for (Eigen::Index c = 0; c < m.cols(); ++c) out(r, c) = m(r, c);
    return out;
}

Eigen::MatrixXd inverse_square_root(const Eigen::MatrixXd& symmetric) {
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(symmetric);
    Eigen::VectorXd powered = eigen.eigenvalues();
    for (Eigen::Index i = 0; i < powered.size(); ++i)
        powered(i) = powered(i) > kEigenvalueTolerance ? 1.0 / std::sqrt(powered(i)) : 0.0;
    return eigen.eigenvectors() * powered.asDiagonal() * eigen.eigenvectors().transpose();
}

// What one cluster contributes: its score u_g = X_g' A_g e_g to the meat, and for the degrees of
// freedom the rows of M X_g' A_g (one per coefficient) in two forms.
struct ClusterTerms {
    Eigen::VectorXd score;           // k
    Eigen::VectorXd own_variance;    // k: sum_t (M X_g' A_g)(i, t)^2 v_t
    Eigen::MatrixXd through_design;  // k x k: M X_g' A_g V_g X_g
};

ClusterTerms cluster_terms(const Eigen::MatrixXd& x, const Eigen::VectorXd& residual,
                           const Eigen::VectorXd& variance, const Eigen::MatrixXd& bread) {
    const Eigen::MatrixXd vx = variance.asDiagonal() * x;
    // Working-model covariance of the cluster's residuals: V_g - V_g X_g M X_g' V_g.
    Eigen::MatrixXd c = -vx * bread * vx.transpose();
    c.diagonal() += variance;
    const Eigen::VectorXd root = variance.cwiseSqrt();
    const Eigen::MatrixXd adjustment =
        root.asDiagonal() * inverse_square_root(root.asDiagonal() * c * root.asDiagonal()) *
        root.asDiagonal();
    const Eigen::MatrixXd estimating = x.transpose() * adjustment;  // k x n_g
    const Eigen::MatrixXd weighted = bread * estimating;
    ClusterTerms terms;
    terms.score = estimating * residual;
    terms.own_variance = weighted.cwiseAbs2() * variance;
    terms.through_design = weighted * vx;
    return terms;
}

// Pustejovsky & Tipton's P for coefficient i: P_gh = [g = h] own_g - h_g' M h_h, with h_g the
// i-th row of cluster g's through_design; df = (tr P)^2 / sum(P^2).
double satterthwaite_df(const std::vector<ClusterTerms>& terms, const Eigen::MatrixXd& bread,
                        Eigen::Index coefficient) {
    const Eigen::Index g = static_cast<Eigen::Index>(terms.size());
    Eigen::MatrixXd rows(g, bread.rows());
    for (Eigen::Index j = 0; j < g; ++j) rows.row(j) = terms[j].through_design.row(coefficient);
    Eigen::MatrixXd p = -rows * bread * rows.transpose();
    for (Eigen::Index j = 0; j < g; ++j) p(j, j) += terms[j].own_variance(coefficient);
    const double trace = p.trace();
    return trace * trace / p.cwiseAbs2().sum();
}

}  // namespace

SmallSampleCovariance cr2_covariance(const ClusteredLogisticFit& fit) {
    const std::size_t n = fit.y.size();
    const std::size_t k = fit.x.columns();
    MONOPLANE_EXPECTS(fit.x.rows() == n && fit.mu.size() == n && fit.cluster.size() == n);
    MONOPLANE_EXPECTS(fit.bread.rows() == k && fit.bread.columns() == k && fit.clusters >= 2);
    std::vector<std::vector<Eigen::Index>> rows_of(static_cast<std::size_t>(fit.clusters));
    for (std::size_t i = 0; i < n; ++i) {
        MONOPLANE_EXPECTS(fit.cluster[i] >= 0 && fit.cluster[i] < fit.clusters);
        MONOPLANE_EXPECTS(fit.mu[i] > 0.0 && fit.mu[i] < 1.0);
        rows_of[static_cast<std::size_t>(fit.cluster[i])].push_back(static_cast<Eigen::Index>(i));
    }
    const Eigen::MatrixXd x = to_eigen(fit.x);
    const Eigen::MatrixXd bread = to_eigen(fit.bread);

    std::vector<ClusterTerms> terms;
    Eigen::MatrixXd meat =
        Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(k));
    for (const std::vector<Eigen::Index>& rows : rows_of) {
        MONOPLANE_EXPECTS(!rows.empty());
        const auto size = static_cast<Eigen::Index>(rows.size());
        Eigen::MatrixXd xg(size, x.cols());
        Eigen::VectorXd residual(size), variance(size);
        for (Eigen::Index t = 0; t < size; ++t) {
            const auto i = static_cast<std::size_t>(rows[t]);
            xg.row(t) = x.row(rows[t]);
            residual(t) = fit.y[i] - fit.mu[i];
            variance(t) = fit.mu[i] * (1.0 - fit.mu[i]);
        }
        terms.push_back(cluster_terms(xg, residual, variance, bread));
        meat += terms.back().score * terms.back().score.transpose();
    }

    SmallSampleCovariance result;
    result.covariance = from_eigen(bread * meat * bread);
    for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(k); ++i)
        result.satterthwaite_df.push_back(satterthwaite_df(terms, bread, i));
    return result;
}

}  // namespace monoplane::analysis
