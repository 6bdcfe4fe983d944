#include "study/psychometric.h"

#include <cmath>

#include "common/programming_error.h"

namespace monoplane::study {
namespace {

// s = 1 / (1 + (m / threshold)^slope) and 1 - s as logistic functions of z = slope ln(m / T),
// each exact where it is small.
struct Logistic {
    double s, one_minus_s;
};

Logistic logistic(const PsychometricFunction& f, double m) {
    MONOPLANE_EXPECTS(m > 0.0 && f.threshold > 0.0 && f.slope > 0.0 && f.lapse >= 0.0 &&
                      f.lapse < 0.5);
    const double z = f.slope * std::log(m / f.threshold);
    const double e = std::exp(-std::abs(z));
    const double small = e / (1.0 + e), large = 1.0 / (1.0 + e);
    return z > 0.0 ? Logistic{small, large} : Logistic{large, small};
}

}  // namespace

double reference_probability(const PsychometricFunction& function, double m) {
    const Logistic l = logistic(function, m);
    return 0.5 + (0.5 - function.lapse) * l.s;
}

double test_probability(const PsychometricFunction& function, double m) {
    const Logistic l = logistic(function, m);
    return 0.5 * l.one_minus_s + function.lapse * l.s;
}

}  // namespace monoplane::study
