#include "app/commands/threshold_recovery.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "analysis/psychometric_fits.h"
#include "charts/svg_writer.h"
#include "study/adaptive_procedure.h"

namespace monoplane::app {
namespace {

bool covers(const RecoveryEstimate& e, double t) {
    return e.estimable && (!e.lower_m || *e.lower_m <= t) && (!e.upper_m || t <= *e.upper_m);
}

double median(std::vector<double> values) {
    if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
    std::ranges::sort(values);
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

RecoverySummary summarise(const std::vector<const RecoveryEstimate*>& group, double t) {
    RecoverySummary s;
    s.estimator = group.front()->estimator;
    s.trials = group.front()->trials;
    s.estimates = static_cast<int>(group.size());
    double sum = 0.0, square = 0.0;
    std::vector<double> widths;
    for (const RecoveryEstimate* e : group) {
        s.mean_answers += static_cast<double>(e->answers) / s.estimates;
        s.covered += covers(*e, t);
        if (!e->estimable) continue;
        ++s.estimable;
        const double error = std::log10(e->threshold_m / t);
        sum += error;
        square += error * error;
        if (e->lower_m && e->upper_m) widths.push_back(std::log10(*e->upper_m / *e->lower_m));
    }
    s.coverage = static_cast<double>(s.covered) / s.estimates;
    s.coverage_ci = analysis::wilson_interval({s.covered, s.estimates});
    if (s.estimable > 0) {
        const double n = s.estimable;
        s.bias_log10 = sum / n;
        s.rmse_log10 = std::sqrt(square / n);
        const double variance =
            n > 1 ? std::max(0.0, (square - n * s.bias_log10 * s.bias_log10) / (n - 1)) : 0.0;
        s.bias_log10_se = std::sqrt(variance / n);
    }
    s.median_width_log10 = median(std::move(widths));
    return s;
}

std::string number_or_na(const std::optional<double>& value) {
    return value ? charts::format_fixed(*value, 6) : "NA";
}

}  // namespace

void add_posterior_estimates(int run, const std::string& scene, const std::vector<Answer>& answers,
                             const study::StaircaseSettings& settings,
                             const std::vector<double>& mono_planes,
                             const std::vector<int>& checkpoints,
                             std::vector<RecoveryEstimate>& out) {
    study::StaircaseSettings quest = settings;
    quest.rule = study::StaircaseRule::QuestPlus;  // the posterior of any placement of trials
    const auto procedure = study::make_adaptive_procedure(quest, mono_planes);
    std::size_t next = 0;
    for (int n : checkpoints) {
        for (; next < static_cast<std::size_t>(n) && next < answers.size(); ++next) {
            procedure->record(answers[next].m, answers[next].reference);
        }
        const study::ThresholdEstimate e = procedure->estimate();
        out.push_back(
            {run, scene, "posterior", n, e.trials, true, e.threshold_m, e.lower_m, e.upper_m});
    }
}

void add_ml_estimates(int run, const std::string& scene, const std::vector<Answer>& answers,
                      const std::vector<int>& checkpoints, std::vector<RecoveryEstimate>& out) {
    for (int n : checkpoints) {
        const int used = std::min(n, static_cast<int>(answers.size()));
        std::map<double, analysis::StimulusLevel> levels;
        for (int i = 0; i < used; ++i) {
            analysis::StimulusLevel& level = levels[answers[static_cast<std::size_t>(i)].m];
            level.m = answers[static_cast<std::size_t>(i)].m;
            level.reference += answers[static_cast<std::size_t>(i)].reference;
            ++level.trials;
        }
        std::vector<analysis::StimulusLevel> list;
        list.reserve(levels.size());
        for (const auto& [m, level] : levels) list.push_back(level);
        const analysis::PsychometricFit fit = analysis::fit_levels(std::move(list));
        out.push_back({run, scene, "ml", n, used, fit.estimable, fit.parameters.threshold,
                       fit.threshold_lower, fit.threshold_upper});
    }
}

std::vector<RecoverySummary> summarise_recovery(const std::vector<RecoveryEstimate>& estimates,
                                                double true_threshold_m) {
    std::map<std::pair<std::string, int>, std::vector<const RecoveryEstimate*>> groups;
    for (const RecoveryEstimate& e : estimates) groups[{e.estimator, e.trials}].push_back(&e);
    std::vector<RecoverySummary> summaries;
    summaries.reserve(groups.size());
    for (const auto& [key, group] : groups) {
        summaries.push_back(summarise(group, true_threshold_m));
    }
    return summaries;
}

std::optional<int> trials_to_precision(const std::vector<RecoverySummary>& summaries,
                                       std::string_view estimator, double precision_log10) {
    // From the most trials backwards (summaries come in trial order per estimator): the first n
    // of the last unbroken run of checkpoints that meet the precision, so an early lucky
    // checkpoint (the prior's median near the true threshold) does not count.
    std::optional<int> from;
    for (auto s = summaries.rbegin(); s != summaries.rend(); ++s) {
        if (s->estimator != estimator) continue;
        const bool meets = s->estimable > 0 && s->estimable >= 0.95 * s->estimates &&
                           s->rmse_log10 <= precision_log10;
        if (!meets) break;
        from = s->trials;
    }
    return from;
}

std::string recovery_csv(const std::vector<RecoveryEstimate>& estimates, double true_threshold_m) {
    std::string csv =
        "run,scene,estimator,trials,answers,estimable,threshold_m,lower_m,upper_m,covered\n";
    for (const RecoveryEstimate& e : estimates) {
        csv += std::to_string(e.run) + "," + e.scene + "," + e.estimator + "," +
               std::to_string(e.trials) + "," + std::to_string(e.answers) + "," +
               (e.estimable ? "TRUE" : "FALSE") + "," +
               (e.estimable ? charts::format_fixed(e.threshold_m, 6) : "NA") + "," +
               number_or_na(e.estimable ? e.lower_m : std::nullopt) + "," +
               number_or_na(e.estimable ? e.upper_m : std::nullopt) + "," +
               (covers(e, true_threshold_m) ? "TRUE" : "FALSE") + "\n";
    }
    return csv;
}

}  // namespace monoplane::app
