// Small-sample cluster-robust covariance for the choice model: CR2, the bias-reduced
// linearization of Bell & McCaffrey (2002) as Pustejovsky & Tipton (2018) define it for
// generalized linear models, with their Satterthwaite degrees of freedom per coefficient.
//
// Why: the CR1 sandwich with normal p-values (logistic_regression.h) rejects a true null far more
// often than alpha when there are few participants (8-9 % instead of 5 % with 6-10 of them,
// docs/analysis.md): each participant's score is shrunk towards zero by their own leverage, and
// the normal reference ignores how uncertain a variance built from G scores is. CR2 inflates each
// participant's residuals by (their part of I - H)^(-1/2), which makes the sandwich unbiased when
// the trials are independent Bernoulli draws (the working model), and the t reference with
// Satterthwaite degrees of freedom accounts for its variance. clubSandwich's vcovCR(type = "CR2")
// and coef_test(test = "Satterthwaite") for R's glm are the reference (tests/fixtures/analysis).
#pragma once

#include <vector>

#include "analysis/linear_algebra.h"

namespace monoplane::analysis {

// A fitted logistic regression, as the covariance needs it.
struct ClusteredLogisticFit {
    const Matrix& x;                  // n x k design
    const std::vector<double>& y;     // n outcomes, 0 or 1
    const std::vector<double>& mu;    // n fitted probabilities, strictly inside (0, 1)
    const std::vector<int>& cluster;  // n cluster indices in [0, clusters)
    int clusters = 0;                 // every index in [0, clusters) used by at least one row
    const Matrix& bread;              // (X' diag(mu (1 - mu)) X)^-1, k x k
};

struct SmallSampleCovariance {
    Matrix covariance;                     // k x k, CR2
    std::vector<double> satterthwaite_df;  // per coefficient, > 0
};

// CR2 covariance M (sum over clusters g of X_g' A_g e_g e_g' A_g X_g) M with M = bread, e the
// response residuals y - mu and, with V = diag(mu (1 - mu)) and C_g = V_g - V_g X_g M X_g' V_g
// (the working-model variance of cluster g's residuals), A_g = V_g^(1/2) (V_g^(1/2) C_g
// V_g^(1/2))^(-1/2) V_g^(1/2), the symmetric inverse square root taken over eigenvalues above
// 1e-12 as clubSandwich does (a participant whose trials determine a coefficient alone gets a
// generalized inverse rather than an infinite adjustment). The Satterthwaite df of coefficient i:
// (tr P)^2 / sum(P^2) where P (clusters x clusters) is the covariance of the clusters'
// contributions to its variance under the working model (Pustejovsky & Tipton 2018, sect. 3).
// May be called with any converged fit whose preconditions above hold (asserted); cannot fail.
SmallSampleCovariance cr2_covariance(const ClusteredLogisticFit& fit);

}  // namespace monoplane::analysis
