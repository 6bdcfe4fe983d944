#include "analysis/logistic_regression.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>

#include "analysis/exclusions.h"
#include "analysis/linear_algebra.h"
#include "analysis/small_sample_covariance.h"

namespace monoplane::analysis {
namespace {

constexpr int kMaxIterations = 50;
// R's glm.control: stop when the deviance changes by less than this, relative.
constexpr double kDevianceTolerance = 1e-10;
// A fitted probability this close to 0 or 1 means the likelihood has no maximum in the finite
// parameter space: the estimates are still growing (R warns "fitted probabilities numerically 0
// or 1 occurred" at a smaller threshold; here it stops the fit).
constexpr double kBoundaryProbability = 1e-8;

struct Design {
    Matrix x;  // n x k
    std::vector<double> y;
    std::vector<int> cluster;  // participant index of each row
    std::vector<std::string> names;
    int clusters = 0;
    int skipped_without_predictor = 0;
};

double logistic(double eta) {
    return eta >= 0 ? 1.0 / (1.0 + std::exp(-eta)) : std::exp(eta) / (1.0 + std::exp(eta));
}

// The analysable trials that have a value of the predictor, with what the checks need.
struct Selection {
    std::vector<const TrialRow*> rows;
    std::vector<double> predictor;  // per row
    std::set<std::string> scenes;
    std::set<double> predictor_values;
    std::map<std::string, int> participants;                       // code -> cluster index
    std::map<std::string, std::pair<int, int>> outcomes_by_scene;  // scene -> {test, reference}
    int skipped_without_predictor = 0;
};

Result<Selection> select_rows(const std::vector<TrialRow>& trials, const LogisticOptions& options) {
    const bool gaze = options.predictor == ChoicePredictor::GazeError;
    Selection s;
    for (const TrialRow& trial : trials) {
        if (!is_analysable(trial)) continue;
        double value = trial.mono_plane;
        if (gaze) {
            if (!trial.gaze_error_test_arcmin || !std::isfinite(*trial.gaze_error_test_arcmin)) {
                ++s.skipped_without_predictor;
                continue;
            }
            value = *trial.gaze_error_test_arcmin;
        } else if (options.log2_distance) {
            if (!(trial.mono_plane > 0.0))
                return Error{
                    "logistic regression: log2 distance needs distances > 0 m, a trial has " +
                    std::to_string(trial.mono_plane)};
            value = std::log2(trial.mono_plane);
        }
        s.rows.push_back(&trial);
        s.predictor.push_back(value);
        s.scenes.insert(trial.scene);
        s.predictor_values.insert(value);
        s.participants.emplace(trial.participant, static_cast<int>(s.participants.size()));
        auto& outcome = s.outcomes_by_scene[trial.scene];
        ++(trial.chose_test ? outcome.first : outcome.second);
    }
    return s;
}

// The refusals before any fitting: too few trials, participants or predictor values, and
// outcomes that leave the odds without a finite estimate.
Result<void> check_estimable(const Selection& s, std::size_t k, const LogisticOptions& options) {
    const std::size_t n = s.rows.size();
    const bool gaze = options.predictor == ChoicePredictor::GazeError;
    if (n <= k)
        return Error{"logistic regression: " + std::to_string(n) + " analysable trials " +
                     (gaze ? "with a gaze error " : "") + "are too few for " + std::to_string(k) +
                     " coefficients"};
    // The sandwich's meat is a sum of G outer products of one score each, so its rank is at most
    // G - 1 (the scores sum to zero at the estimate): with G <= K some coefficient gets a zero
    // or undefined standard error (Cameron and Miller 2015, sect. VI).
    if (s.participants.size() <= k)
        return Error{
            "logistic regression: clustered standard errors need more participants "
            "than coefficients; the trials come from " +
            std::to_string(s.participants.size()) + " participant(s) for " + std::to_string(k) +
            " coefficients"};
    if (s.predictor_values.size() < 2)
        return Error{gaze ? "logistic regression: the trials have only one gaze error, so its "
                            "effect cannot be estimated (singular design)"
                          : "logistic regression: the trials have only one distance, so its "
                            "effect cannot be estimated (singular design)"};
    int test_total = 0;
    for (const auto& [scene, outcome] : s.outcomes_by_scene) test_total += outcome.first;
    if (test_total == 0 || test_total == static_cast<int>(n))
        return Error{
            "logistic regression: every analysable trial has the same outcome (complete "
            "separation); the odds cannot be estimated"};
    if (!options.scene_terms) return Ok{};
    for (const auto& [scene, outcome] : s.outcomes_by_scene)
        if (outcome.first == 0 || outcome.second == 0)
            return Error{"logistic regression: in scene '" + scene + "' every trial chose the " +
                         (outcome.first == 0 ? "reference" : "test") +
                         " alternative (quasi-complete separation): its coefficient has no "
                         "finite estimate; fit without scene terms or report the rates"};
    return Ok{};
}

Result<Design> build_design(const std::vector<TrialRow>& trials, const LogisticOptions& options) {
    if (options.predictor == ChoicePredictor::GazeError) {
        const bool any_gaze = std::any_of(trials.begin(), trials.end(), [](const TrialRow& t) {
            return is_analysable(t) && t.gaze_error_test_arcmin.has_value();
        });
        if (!any_gaze)
            return Error{
                "logistic regression: no analysable trial has a gaze error (no session recorded "
                "eye gaze on the test alternative)"};
    }
    Result<Selection> selected = select_rows(trials, options);
    MONOPLANE_TRY(selected);
    const Selection& s = *selected;

    Design design;
    design.names = {"intercept", predictor_term(options)};
    std::vector<std::string> dummies;
    if (options.scene_terms)
        for (auto it = s.scenes.begin(); it != s.scenes.end(); ++it)
            if (it != s.scenes.begin()) dummies.push_back(*it);
    for (const std::string& scene : dummies) design.names.push_back("scene[" + scene + "]");
    MONOPLANE_TRY(check_estimable(s, design.names.size(), options));

    const std::size_t n = s.rows.size();
    design.x = Matrix(n, design.names.size());
    design.y.resize(n);
    design.cluster.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const TrialRow& t = *s.rows[i];
        design.x(i, 0) = 1.0;
        design.x(i, 1) = s.predictor[i];
        for (std::size_t d = 0; d < dummies.size(); ++d)
            design.x(i, 2 + d) = t.scene == dummies[d] ? 1.0 : 0.0;
        design.y[i] = t.chose_test ? 1.0 : 0.0;
        design.cluster[i] = s.participants.at(t.participant);
    }
    design.clusters = static_cast<int>(s.participants.size());
    design.skipped_without_predictor = s.skipped_without_predictor;
    return design;
}

struct State {
    std::vector<double> mu;
    double log_likelihood = 0;
};

State evaluate(const Design& d, const std::vector<double>& beta) {
    State s;
    s.mu.resize(d.y.size());
    for (std::size_t i = 0; i < d.y.size(); ++i) {
        double eta = 0.0;
        for (std::size_t j = 0; j < beta.size(); ++j) eta += d.x(i, j) * beta[j];
        s.mu[i] = logistic(eta);
        // log(1 - mu) as log(logistic(-eta)) keeps precision when mu is near 1.
        s.log_likelihood += d.y[i] > 0.5 ? std::log(s.mu[i]) : std::log(logistic(-eta));
    }
    return s;
}

// X'WX with W = diag(mu (1 - mu)): the Fisher information, the sandwich's bread.
Matrix information(const Design& d, const std::vector<double>& mu) {
    const std::size_t k = d.x.columns();
    Matrix info(k, k);
    for (std::size_t i = 0; i < mu.size(); ++i) {
        const double w = mu[i] * (1.0 - mu[i]);
        for (std::size_t a = 0; a < k; ++a)
            for (std::size_t b = 0; b < k; ++b) info(a, b) += w * d.x(i, a) * d.x(i, b);
    }
    return info;
}

// Sandwich: bread = (X'WX)^-1 at the estimate, meat = sum_g s_g s_g', scaled by the CR1 factor
// G/(G-1) * (N-1)/(N-K).
Matrix cr1_covariance(const Design& d, const std::vector<double>& mu, const Matrix& bread) {
    const std::size_t n = d.y.size();
    const std::size_t k = d.x.columns();
    std::vector<std::vector<double>> cluster_score(d.clusters, std::vector<double>(k, 0.0));
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t j = 0; j < k; ++j)
            cluster_score[d.cluster[i]][j] += d.x(i, j) * (d.y[i] - mu[i]);
    Matrix meat(k, k);
    for (const std::vector<double>& s : cluster_score)
        for (std::size_t a = 0; a < k; ++a)
            for (std::size_t b = 0; b < k; ++b) meat(a, b) += s[a] * s[b];
    const double g = d.clusters;
    const double correction = g / (g - 1.0) * (static_cast<double>(n) - 1.0) /
                              (static_cast<double>(n) - static_cast<double>(k));
    Matrix covariance = bread * meat * bread;
    for (std::size_t a = 0; a < k; ++a)
        for (std::size_t b = 0; b < k; ++b) covariance(a, b) *= correction;
    return covariance;
}

// The CR1 columns of one coefficient: z test and interval from the normal distribution.
Result<Coefficient> coefficient(const std::string& name, double estimate, double variance) {
    if (!std::isfinite(variance) || !(variance > 0.0)) {
        return Error{"logistic regression: the clustered variance of '" + name +
                     "' is not positive: the participants' choices do not vary enough "
                     "to estimate it"};
    }
    const boost::math::normal_distribution<double> normal;
    const double z975 = boost::math::quantile(normal, 0.975);
    Coefficient c;
    c.name = name;
    c.estimate = estimate;
    c.std_error = std::sqrt(variance);
    c.z = c.estimate / c.std_error;
    c.p = 2.0 * boost::math::cdf(boost::math::complement(normal, std::abs(c.z)));
    c.odds_ratio = std::exp(c.estimate);
    c.ci_lower = std::exp(c.estimate - z975 * c.std_error);
    c.ci_upper = std::exp(c.estimate + z975 * c.std_error);
    return c;
}

// The CR2 columns: t test on `df` degrees of freedom. A variance of 0 (a coefficient the
// clusters do not inform beyond what CR1 saw) leaves NaN, which the outputs write as empty/null.
void add_small_sample_test(Coefficient& c, double variance, double df) {
    c.df_cr2 = df;
    c.std_error_cr2 = variance > 0.0 ? std::sqrt(variance) : NAN;
    c.t_cr2 = c.estimate / c.std_error_cr2;
    if (!std::isfinite(c.t_cr2) || !(df > 0.0)) {
        c.p_cr2 = c.ci_lower_cr2 = c.ci_upper_cr2 = NAN;
        return;
    }
    const boost::math::students_t_distribution<double> t(df);
    const double t975 = boost::math::quantile(t, 0.975);
    c.p_cr2 = 2.0 * boost::math::cdf(boost::math::complement(t, std::abs(c.t_cr2)));
    c.ci_lower_cr2 = std::exp(c.estimate - t975 * c.std_error_cr2);
    c.ci_upper_cr2 = std::exp(c.estimate + t975 * c.std_error_cr2);
}

// The maximum of the likelihood: Newton-Raphson (= IRLS for the canonical logit link) from
// b = 0, halving a step that lowers the likelihood; nullopt when X'WX becomes singular.
struct Maximum {
    std::vector<double> beta;
    State state;
    int iterations = 0;
    bool converged = false;
};

std::optional<Maximum> newton_raphson(const Design& d) {
    const std::size_t n = d.y.size();
    const std::size_t k = d.x.columns();
    Maximum m;
    m.beta.assign(k, 0.0);
    m.state = evaluate(d, m.beta);
    for (int iteration = 1; iteration <= kMaxIterations; ++iteration) {
        const std::optional<Matrix> covariance =
            inverse_positive_definite(information(d, m.state.mu));
        if (!covariance) return std::nullopt;
        std::vector<double> score(k, 0.0);
        for (std::size_t i = 0; i < n; ++i)
            for (std::size_t j = 0; j < k; ++j) score[j] += d.x(i, j) * (d.y[i] - m.state.mu[i]);
        std::vector<double> step(k, 0.0);
        for (std::size_t a = 0; a < k; ++a)
            for (std::size_t b = 0; b < k; ++b) step[a] += (*covariance)(a, b) * score[b];

        std::vector<double> next(k);
        State next_state;
        double scale = 1.0;
        for (int halving = 0; halving < 30; ++halving, scale /= 2.0) {
            for (std::size_t j = 0; j < k; ++j) next[j] = m.beta[j] + scale * step[j];
            next_state = evaluate(d, next);
            if (std::isfinite(next_state.log_likelihood) &&
                next_state.log_likelihood >= m.state.log_likelihood - 1e-12)
                break;
        }
        // Deviance = -2 log-likelihood for 0/1 outcomes; R's convergence test.
        const double deviance = -2.0 * next_state.log_likelihood;
        const double change = std::abs(deviance + 2.0 * m.state.log_likelihood);
        m.beta = next;
        m.state = std::move(next_state);
        m.iterations = iteration;
        if (change / (std::abs(deviance) + 0.1) < kDevianceTolerance) {
            m.converged = true;
            break;
        }
    }
    return m;
}

}  // namespace

Result<LogisticFit> fit_choice_model(const std::vector<TrialRow>& trials,
                                     const LogisticOptions& options) {
    Result<Design> built = build_design(trials, options);
    MONOPLANE_TRY(built);
    const Design& d = *built;
    const std::size_t k = d.x.columns();
    const Error singular{
        "logistic regression: the design is singular (a column is a combination of others, e.g. "
        "a scene seen at one distance only); fit without scene terms"};
    const std::optional<Maximum> maximum = newton_raphson(d);
    if (!maximum) return singular;
    const std::vector<double>& beta = maximum->beta;
    const State& state = maximum->state;
    LogisticFit fit;
    fit.iterations = maximum->iterations;
    fit.converged = maximum->converged;
    const Error separation{
        "logistic regression: the choices are (quasi-)completely separated by the predictors "
        "(fitted probabilities of 0 or 1): the estimates have no finite maximum; report the "
        "rates per distance instead"};
    if (!fit.converged) return separation;
    for (double mu : state.mu)
        if (mu < kBoundaryProbability || mu > 1.0 - kBoundaryProbability) return separation;

    const std::optional<Matrix> bread = inverse_positive_definite(information(d, state.mu));
    if (!bread) return singular;
    const Matrix cr1 = cr1_covariance(d, state.mu, *bread);
    const SmallSampleCovariance cr2 =
        cr2_covariance({d.x, d.y, state.mu, d.cluster, d.clusters, *bread});
    for (std::size_t j = 0; j < k; ++j) {
        Result<Coefficient> c = coefficient(d.names[j], beta[j], cr1(j, j));
        MONOPLANE_TRY(c);
        add_small_sample_test(c.value(), cr2.covariance(j, j), cr2.satterthwaite_df[j]);
        fit.coefficients.push_back(std::move(c).value());
    }
    fit.n = static_cast<int>(d.y.size());
    fit.clusters = d.clusters;
    fit.log_likelihood = state.log_likelihood;
    fit.distance_term = d.names[1];
    fit.skipped_without_predictor = d.skipped_without_predictor;
    return fit;
}

std::string predictor_term(const LogisticOptions& options) {
    if (options.predictor == ChoicePredictor::GazeError) return "gaze_error_test_arcmin";
    return options.log2_distance ? "log2_mono_plane_m" : "mono_plane_m";
}

}  // namespace monoplane::analysis
