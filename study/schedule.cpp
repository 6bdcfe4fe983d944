#include "study/schedule.h"

#include <algorithm>
#include <cassert>

#include "study/random.h"

namespace monoplane::study {
namespace {

// Independent streams of one seed: a protocol with more practice trials, say, keeps the same
// block order, distance order and labels for the data trials.
enum Stream : std::uint64_t { kPractice = 1, kBlockOrder = 2, kDistanceOrder = 3, kLabels = 4 };

void assign_labels(ScheduledTrial& trial, const Protocol& protocol, Rng& rng) {
    // Independent fair coin per trial (not balanced within a session): the assignment carries no
    // information about the previous trials, so a participant cannot infer it.
    trial.label1_alternative = rng.below(2);
    trial.label1_mode = protocol.alternatives[static_cast<std::size_t>(trial.label1_alternative)];
    trial.label2_mode =
        protocol.alternatives[static_cast<std::size_t>(1 - trial.label1_alternative)];
}

std::vector<std::string> block_order(const Protocol& protocol, std::uint64_t seed,
                                     int participant_index) {
    std::vector<std::string> order = protocol.scenes;
    const int n = static_cast<int>(order.size());
    if (n < 2) return order;
    switch (protocol.first_scene) {
        case FirstSceneBalance::LatinSquare: {
            const int rows = balanced_latin_square_rows(n);
            const int row = ((participant_index % rows) + rows) % rows;
            const std::vector<int> perm = balanced_latin_square_row(n, row);
            for (int i = 0; i < n; ++i) {
                order[static_cast<std::size_t>(i)] =
                    protocol.scenes[static_cast<std::size_t>(perm[static_cast<std::size_t>(i)])];
            }
            break;
        }
        case FirstSceneBalance::Random: {
            Rng rng(seed, kBlockOrder);
            rng.shuffle(order);
            break;
        }
        case FirstSceneBalance::Fixed:
            break;
    }
    return order;
}

}  // namespace

int Schedule::practice_count() const {
    return static_cast<int>(
        std::ranges::count_if(trials, [](const ScheduledTrial& t) { return t.practice; }));
}

Schedule make_schedule(const Protocol& protocol, std::uint64_t seed, int participant_index) {
    Schedule schedule;
    schedule.seed = seed;
    schedule.participant_index = participant_index;
    schedule.block_order = block_order(protocol, seed, participant_index);

    const auto append = [&schedule](ScheduledTrial trial) {
        trial.index = static_cast<int>(schedule.trials.size());
        schedule.trials.push_back(std::move(trial));
    };

    // Practice: any scene at any distance, drawn independently; apart from the data (block -1).
    if (!protocol.scenes.empty() && !protocol.mono_planes.empty()) {
        Rng rng(seed, kPractice);
        for (int i = 0; i < protocol.practice_trials; ++i) {
            ScheduledTrial trial;
            trial.practice = true;
            trial.block = -1;
            trial.scene = protocol.scenes[static_cast<std::size_t>(
                rng.below(static_cast<int>(protocol.scenes.size())))];
            trial.mono_plane = protocol.mono_planes[static_cast<std::size_t>(
                rng.below(static_cast<int>(protocol.mono_planes.size())))];
            assign_labels(trial, protocol, rng);
            append(std::move(trial));
        }
    }

    Rng distance_rng(seed, kDistanceOrder);
    Rng label_rng(seed, kLabels);
    for (std::size_t block = 0; block < schedule.block_order.size(); ++block) {
        std::vector<double> distances = protocol.mono_planes;
        if (protocol.order == TrialOrder::Randomized) distance_rng.shuffle(distances);
        for (double m : distances) {
            ScheduledTrial trial;
            trial.block = static_cast<int>(block);
            trial.scene = schedule.block_order[block];
            trial.mono_plane = m;
            assign_labels(trial, protocol, label_rng);
            append(std::move(trial));
        }
    }
    return schedule;
}

}  // namespace monoplane::study
