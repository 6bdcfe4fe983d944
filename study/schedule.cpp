#include "study/schedule.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <utility>

#include "common/programming_error.h"
#include "study/random.h"

namespace monoplane::study {
namespace {

// Independent streams of one seed: a protocol with more practice trials, say, keeps the same
// block order, distance order and labels for the data trials.
enum Stream : std::uint64_t {
    kPractice = 1,
    kBlockOrder = 2,
    kDistanceOrder = 3,
    kLabels = 4,
    kRoundOrder = 5,  // the staircase's interleaving
};

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

using AppendTrial = std::function<void(ScheduledTrial)>;

// The data trials of one constant block: every distance `repetitions` times, shuffled together
// or listed repetition by repetition; a copy's repetition is its showing's 1-based rank.
std::vector<ScheduledTrial> constant_conditions(const Protocol& protocol,
                                                const std::vector<std::string>& scenes,
                                                Rng& distance_rng) {
    std::vector<ScheduledTrial> trials;
    for (int repetition = 1; repetition <= protocol.day.repetitions; ++repetition) {
        for (const std::string& scene : scenes) {
            for (double m : protocol.mono_planes) {
                ScheduledTrial trial;
                trial.scene = scene;
                trial.mono_plane = m;
                trials.push_back(std::move(trial));
            }
        }
    }
    if (protocol.order == TrialOrder::Randomized) distance_rng.shuffle(trials);
    std::map<std::pair<std::string, double>, int> shown;
    for (ScheduledTrial& trial : trials)
        trial.repetition = ++shown[{trial.scene, trial.mono_plane}];
    return trials;
}

// Constant procedure: one block per scene (or one block of all scenes with blocking = "none"),
// every distance `repetitions` times, in random or listed order.
void append_constant_trials(const Protocol& protocol, const Schedule& schedule, Rng& labels,
                            const AppendTrial& append) {
    Rng distance_rng(schedule.seed, kDistanceOrder);
    std::vector<std::vector<std::string>> blocks;
    if (protocol.day.blocking == Blocking::None) {
        blocks.push_back(schedule.block_order);
    } else {
        for (const std::string& scene : schedule.block_order) blocks.push_back({scene});
    }
    for (std::size_t block = 0; block < blocks.size(); ++block) {
        for (ScheduledTrial trial : constant_conditions(protocol, blocks[block], distance_rng)) {
            trial.block = static_cast<int>(block);
            assign_labels(trial, protocol, labels);
            append(std::move(trial));
        }
    }
}

// Staircase procedure: rounds of one slot per scene, so every staircase advances at the same
// pace through the session (fatigue and practice spread alike over the scenes), and the order
// within a round does not let a participant predict the next scene.
void append_staircase_trials(const Protocol& protocol, const Schedule& schedule, Rng& labels,
                             const AppendTrial& append) {
    Rng round_rng(schedule.seed, kRoundOrder);
    std::vector<int> positions(schedule.block_order.size());
    for (std::size_t i = 0; i < positions.size(); ++i) positions[i] = static_cast<int>(i);
    for (int round = 0; round < protocol.staircase.trials_per_scene; ++round) {
        std::vector<int> order = positions;
        if (round > 0 && protocol.order == TrialOrder::Randomized) round_rng.shuffle(order);
        for (int block : order) {
            ScheduledTrial trial;
            trial.block = block;
            trial.scene = schedule.block_order[static_cast<std::size_t>(block)];
            trial.mono_plane = std::numeric_limits<double>::quiet_NaN();
            trial.adaptive = true;
            assign_labels(trial, protocol, labels);
            append(std::move(trial));
        }
    }
}

}  // namespace

int Schedule::practice_count() const {
    return static_cast<int>(
        std::ranges::count_if(trials, [](const ScheduledTrial& t) { return t.practice; }));
}

Schedule make_schedule(const Protocol& protocol, std::uint64_t seed, int participant_index,
                       int session_number) {
    MONOPLANE_EXPECTS(session_number >= 1);
    Schedule schedule;
    schedule.seed = seed;
    schedule.participant_index = participant_index;
    schedule.session_number = session_number;
    schedule.block_order = block_order(protocol, seed, participant_index);
    if (!schedule.block_order.empty()) {
        const auto shift = static_cast<std::ptrdiff_t>(
            static_cast<std::size_t>(session_number - 1) % schedule.block_order.size());
        std::ranges::rotate(schedule.block_order, schedule.block_order.begin() + shift);
    }

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

    Rng label_rng(seed, kLabels);
    if (protocol.procedure == Procedure::Staircase) {
        append_staircase_trials(protocol, schedule, label_rng, append);
    } else {
        append_constant_trials(protocol, schedule, label_rng, append);
    }
    return schedule;
}

}  // namespace monoplane::study
