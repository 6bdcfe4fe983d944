#include "study/adaptive_procedure.h"

#include <algorithm>
#include <cmath>

#include "common/programming_error.h"
#include "study/quest_plus.h"
#include "study/weighted_up_down.h"

namespace monoplane::study {

std::unique_ptr<AdaptiveProcedure> make_adaptive_procedure(const StaircaseSettings& settings,
                                                           const std::vector<double>& mono_planes) {
    MONOPLANE_EXPECTS(mono_planes.size() >= 2);
    const auto [low, high] = std::ranges::minmax(mono_planes);
    if (settings.rule == StaircaseRule::QuestPlus) {
        const std::array<double, 2> range =
            settings.threshold_range.value_or(std::array<double, 2>{low, high});
        QuestPlusGrid grid{log_spaced(range[0], range[1], settings.threshold_steps),
                           settings.slopes, settings.lapses};
        return std::make_unique<QuestPlus>(mono_planes, std::move(grid));
    }
    const double start = settings.start_m.value_or(std::sqrt(low * high));
    return std::make_unique<WeightedUpDown>(low, high, start, settings.target, settings.step_log10,
                                            settings.skip_reversals);
}

}  // namespace monoplane::study
