#include "analysis/psychometric_fits.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>

#include "analysis/exclusions.h"

namespace monoplane::analysis {
namespace {

constexpr const char* kGroup = "all";

std::string metres(double m) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g m", m);
    return text;
}

// Sorted by m, equal distances merged, empty levels and distances <= 0 (which have no place on
// the function's log-m axis; a study never shows them) dropped.
std::vector<StimulusLevel> normalized(std::vector<StimulusLevel> levels) {
    std::sort(levels.begin(), levels.end(),
              [](const StimulusLevel& a, const StimulusLevel& b) { return a.m < b.m; });
    std::vector<StimulusLevel> out;
    for (const StimulusLevel& level : levels) {
        if (level.trials == 0 || !(level.m > 0.0)) continue;
        if (!out.empty() && out.back().m == level.m) {
            out.back().reference += level.reference;
            out.back().trials += level.trials;
        } else {
            out.push_back(level);
        }
    }
    return out;
}

// Why these levels cannot locate a threshold before any fit, or "" when they might.
std::string unidentifiable(const std::vector<StimulusLevel>& levels, int n) {
    if (levels.empty()) return "no analysable trials";
    if (levels.size() == 1) {
        return "all " + std::to_string(n) + " trials are at one distance (" +
               metres(levels.front().m) + "): a threshold needs several";
    }
    int reference = 0;
    for (const StimulusLevel& level : levels) reference += level.reference;
    if (reference == n) {
        return "the reference was chosen in all " + std::to_string(n) +
               " trials: the threshold lies beyond the largest distance tested (" +
               metres(levels.back().m) + ")";
    }
    return "";
}

// The maximum-likelihood curve without an interval, or the reason there is none.
PsychometricFit point_fit(std::vector<StimulusLevel> levels) {
    PsychometricFit fit;
    fit.levels = normalized(std::move(levels));
    for (const StimulusLevel& level : fit.levels) fit.n += level.trials;
    fit.reason = unidentifiable(fit.levels, fit.n);
    if (!fit.reason.empty()) return fit;
    const PsychometricMaximum maximum =
        maximize_psychometric_likelihood(fit.levels, bounds_for(fit.levels));
    const double threshold = maximum.parameters.threshold;
    const double m_min = fit.levels.front().m, m_max = fit.levels.back().m;
    if (threshold < m_min) {
        fit.reason = "the fitted threshold (" + metres(threshold) +
                     ") lies below the smallest distance tested (" + metres(m_min) +
                     "): the choices are near chance there already";
        return fit;
    }
    if (threshold > m_max) {
        fit.reason = "the fitted threshold (" + metres(threshold) +
                     ") lies beyond the largest distance tested (" + metres(m_max) +
                     "): the reference is still chosen more often than chance there";
        return fit;
    }
    fit.estimable = true;
    fit.parameters = maximum.parameters;
    fit.log_likelihood = maximum.log_likelihood;
    return fit;
}

// Hyndman & Fan type 7 quantile of sorted values.
double quantile(const std::vector<double>& sorted, double probability) {
    const double h = (static_cast<double>(sorted.size()) - 1.0) * probability;
    const auto below = static_cast<std::size_t>(std::floor(h));
    const std::size_t above = std::min(below + 1, sorted.size() - 1);
    return sorted[below] + (h - static_cast<double>(below)) * (sorted[above] - sorted[below]);
}

// FNV-1a: a seed per scene that does not depend on the standard library's std::hash.
std::uint64_t scene_seed(std::uint64_t seed, const std::string& scene) {
    std::uint64_t hash = 14695981039346656037ull ^ seed;
    for (const char c : scene) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    return hash;
}

// The group's percentile interval from refitting R resamples of whole participants.
void bootstrap_interval(PsychometricFit& group,
                        const std::vector<std::vector<StimulusLevel>>& by_participant,
                        const PsychometricOptions& options) {
    const PsychometricBounds bounds = bounds_for(group.levels);
    std::mt19937_64 random(scene_seed(options.seed, group.scene));
    std::uniform_int_distribution<std::size_t> pick(0, by_participant.size() - 1);
    std::vector<double> thresholds;
    for (int r = 0; r < options.bootstrap_replicates; ++r) {
        std::vector<StimulusLevel> resample;
        for (std::size_t i = 0; i < by_participant.size(); ++i) {
            const std::vector<StimulusLevel>& drawn = by_participant[pick(random)];
            resample.insert(resample.end(), drawn.begin(), drawn.end());
        }
        // A resample without data trials cannot occur: every participant has some.
        thresholds.push_back(
            maximize_psychometric_likelihood(normalized(resample), bounds).parameters.threshold);
    }
    std::sort(thresholds.begin(), thresholds.end());
    const double lower = quantile(thresholds, (1.0 - options.confidence) / 2.0);
    const double upper = quantile(thresholds, (1.0 + options.confidence) / 2.0);
    // Beyond the tested distances the resamples' thresholds sit where the data stop constraining
    // them (on the search bounds): an end there is unbounded, not a number.
    if (lower >= group.levels.front().m) group.threshold_lower = lower;
    if (upper <= group.levels.back().m) group.threshold_upper = upper;
    group.interval_method = "participant bootstrap";
    group.bootstrap_replicates = options.bootstrap_replicates;
}

void add_profile_interval(PsychometricFit& fit, double confidence) {
    if (!fit.estimable) return;
    const ThresholdInterval interval = profile_threshold_interval(
        fit.levels, bounds_for(fit.levels), {fit.parameters, fit.log_likelihood},
        fit.levels.front().m, fit.levels.back().m, confidence);
    fit.threshold_lower = interval.lower;
    fit.threshold_upper = interval.upper;
    fit.interval_method = "profile likelihood";
}

using LevelsByParticipant = std::map<std::string, std::vector<StimulusLevel>>;

PsychometricFit group_fit(const std::string& scene, const LevelsByParticipant& participants,
                          const PsychometricOptions& options) {
    std::vector<StimulusLevel> pooled;
    std::vector<std::vector<StimulusLevel>> each;
    for (const auto& [code, levels] : participants) {
        pooled.insert(pooled.end(), levels.begin(), levels.end());
        each.push_back(normalized(levels));
    }
    PsychometricFit group = point_fit(std::move(pooled));
    group.participant = kGroup;
    group.scene = scene;
    group.participants = static_cast<int>(participants.size());
    if (!group.estimable) return group;
    // One participant has no between-participant variation to resample.
    if (participants.size() >= 2 && options.bootstrap_replicates > 0) {
        bootstrap_interval(group, each, options);
    } else {
        add_profile_interval(group, options.confidence);
    }
    return group;
}

}  // namespace

PsychometricFit fit_levels(std::vector<StimulusLevel> levels, double confidence) {
    PsychometricFit fit = point_fit(std::move(levels));
    add_profile_interval(fit, confidence);
    return fit;
}

std::vector<PsychometricFit> fit_psychometric_functions(const std::vector<TrialRow>& trials,
                                                        const PsychometricOptions& options) {
    std::map<std::string, LevelsByParticipant> by_scene;
    for (const TrialRow& t : trials) {
        if (!is_analysable(t)) continue;
        by_scene[t.scene][t.participant].push_back({t.mono_plane, t.chose_test ? 0 : 1, 1});
    }
    std::vector<PsychometricFit> fits;
    for (const auto& [scene, participants] : by_scene) {
        fits.push_back(group_fit(scene, participants, options));
        for (const auto& [code, levels] : participants) {
            PsychometricFit fit = fit_levels(levels, options.confidence);
            fit.participant = code;
            fit.scene = scene;
            fit.participants = 1;
            fits.push_back(std::move(fit));
        }
    }
    return fits;
}

}  // namespace monoplane::analysis
