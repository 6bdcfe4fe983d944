#include "analysis/choice_rates.h"

#include <map>
#include <utility>

#include "analysis/exclusions.h"

namespace monoplane::analysis {
namespace {

// Counts per key; std::map gives the documented order (scenes alphabetical, distances
// ascending). Distances are grouped by exact value: every trial of a protocol level carries the
// same double, read from the same text.
template <class Key, class KeyOf>
std::map<Key, Proportion> count_by(const std::vector<TrialRow>& trials, KeyOf key_of) {
    std::map<Key, Proportion> counts;
    for (const TrialRow& trial : trials) {
        if (!is_analysable(trial)) continue;
        Proportion& count = counts[key_of(trial)];
        ++count.trials;
        count.successes += trial.chose_test ? 1 : 0;
    }
    return counts;
}

ChoiceRate make_rate(Proportion count, std::string scene, double mono_plane) {
    ChoiceRate rate;
    rate.scene = std::move(scene);
    rate.mono_plane = mono_plane;
    rate.test_chosen = count.successes;
    rate.n = count.trials;
    if (count.trials == 0) {
        rate.wilson = rate.clopper_pearson = {0.0, 1.0};
        return rate;
    }
    rate.rate = estimate(count);
    rate.wilson = wilson_interval(count);
    rate.clopper_pearson = clopper_pearson_interval(count);
    rate.binomial_p = binomial_two_sided_p(count, 0.5);
    return rate;
}

constexpr double kAllDistances = std::numeric_limits<double>::quiet_NaN();

}  // namespace

ChoiceRate choice_rate(const std::vector<TrialRow>& trials, std::string scene, double mono_plane) {
    Proportion count;
    for (const TrialRow& trial : trials) {
        if (!is_analysable(trial)) continue;
        ++count.trials;
        count.successes += trial.chose_test ? 1 : 0;
    }
    return make_rate(count, std::move(scene), mono_plane);
}

std::vector<ChoiceRate> rates_by_scene(const std::vector<TrialRow>& trials) {
    std::vector<ChoiceRate> rates;
    for (const auto& [scene, count] :
         count_by<std::string>(trials, [](const TrialRow& t) { return t.scene; }))
        rates.push_back(make_rate(count, scene, kAllDistances));
    return rates;
}

std::vector<ChoiceRate> rates_by_distance(const std::vector<TrialRow>& trials) {
    std::vector<ChoiceRate> rates;
    for (const auto& [distance, count] :
         count_by<double>(trials, [](const TrialRow& t) { return t.mono_plane; }))
        rates.push_back(make_rate(count, "", distance));
    return rates;
}

std::vector<ChoiceRate> rates_by_scene_and_distance(const std::vector<TrialRow>& trials) {
    std::vector<ChoiceRate> rates;
    using Key = std::pair<std::string, double>;
    for (const auto& [key, count] : count_by<Key>(trials, [](const TrialRow& t) {
             return Key{t.scene, t.mono_plane};
         }))
        rates.push_back(make_rate(count, key.first, key.second));
    return rates;
}

ChoiceRate overall_rate(const std::vector<TrialRow>& trials) {
    return choice_rate(trials);
}

}  // namespace monoplane::analysis
