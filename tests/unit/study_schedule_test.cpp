// Session schedules: balanced Latin squares, the session's layout,
// determinism, and statistical checks that the seeded orders are uniform. The statistical tests use
// fixed seeds, so they are deterministic: a failure means a biased generator, not bad luck.
#include <gtest/gtest.h>

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <cmath>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "study/schedule.h"

namespace monoplane::study {
namespace {

Protocol fink2019() {
    Protocol p;
    p.name = "fink2019";
    p.scenes = {"beams", "landscape", "spheres"};
    p.mono_planes = {1.6, 3, 5, 8, 12, 16, 20, 25, 31, 39.5};
    p.alternatives = {RenderMode::Stereo, RenderMode::Hybrid};
    p.order = TrialOrder::Randomized;
    p.first_scene = FirstSceneBalance::LatinSquare;
    p.practice_trials = 2;
    return p;
}

// Upper-tail p-value of a chi-square goodness-of-fit test of `counts` against equal frequencies.
struct ChiSquare {
    double statistic = 0.0;
    int dof = 0;
    double p() const {
        return boost::math::cdf(boost::math::complement(boost::math::chi_squared(dof), statistic));
    }
};

ChiSquare uniform_fit(const std::vector<long>& counts) {
    long total = 0;
    for (long c : counts) total += c;
    const double expected = static_cast<double>(total) / static_cast<double>(counts.size());
    ChiSquare chi;
    for (long c : counts) chi.statistic += (c - expected) * (c - expected) / expected;
    chi.dof = static_cast<int>(counts.size()) - 1;
    return chi;
}

bool same_trial(const ScheduledTrial& a, const ScheduledTrial& b) {
    return a.index == b.index && a.practice == b.practice && a.block == b.block &&
           a.scene == b.scene && a.mono_plane == b.mono_plane &&
           a.label1_alternative == b.label1_alternative && a.label1_mode == b.label1_mode &&
           a.label2_mode == b.label2_mode;
}

bool same_trials(const std::vector<ScheduledTrial>& a, const std::vector<ScheduledTrial>& b) {
    return std::ranges::equal(a, b, same_trial);
}

TEST(BalancedLatinSquare, FirstRowIsWilliamsSequence) {
    EXPECT_EQ(balanced_latin_square_row(4, 0), (std::vector<int>{0, 1, 3, 2}));
    EXPECT_EQ(balanced_latin_square_row(6, 0), (std::vector<int>{0, 1, 5, 2, 4, 3}));
    EXPECT_EQ(balanced_latin_square_row(4, 1), (std::vector<int>{1, 2, 0, 3}));
    // Odd n: the mirrored rows follow.
    EXPECT_EQ(balanced_latin_square_row(3, 0), (std::vector<int>{0, 1, 2}));
    EXPECT_EQ(balanced_latin_square_row(3, 3), (std::vector<int>{2, 1, 0}));
    EXPECT_EQ(balanced_latin_square_rows(1), 1);
    EXPECT_EQ(balanced_latin_square_row(1, 0), (std::vector<int>{0}));
}

TEST(BalancedLatinSquare, IsBalancedForPositionsAndOrderedPairs) {
    for (int n = 2; n <= 8; ++n) {
        const int rows = balanced_latin_square_rows(n);
        EXPECT_EQ(rows, n % 2 == 0 ? n : 2 * n) << n;
        std::vector<std::vector<int>> at_position(n, std::vector<int>(n, 0));
        std::vector<std::vector<int>> pair(n, std::vector<int>(n, 0));
        for (int r = 0; r < rows; ++r) {
            const std::vector<int> row = balanced_latin_square_row(n, r);
            ASSERT_EQ(static_cast<int>(row.size()), n);
            std::vector<int> sorted = row;
            std::ranges::sort(sorted);
            for (int i = 0; i < n; ++i) ASSERT_EQ(sorted[i], i) << "n " << n << " row " << r;
            for (int i = 0; i < n; ++i) ++at_position[row[i]][i];
            for (int i = 0; i + 1 < n; ++i) ++pair[row[i]][row[i + 1]];
        }
        for (int item = 0; item < n; ++item) {
            for (int pos = 0; pos < n; ++pos) {
                EXPECT_EQ(at_position[item][pos], rows / n) << "n " << n;
            }
            for (int next = 0; next < n; ++next) {
                EXPECT_EQ(pair[item][next], next == item ? 0 : rows / n) << "n " << n;
            }
        }
    }
}

TEST(Schedule, PracticeFirstThenOneBlockPerScene) {
    const Protocol protocol = fink2019();
    for (std::uint64_t seed : {0ull, 1ull, 42ull, 0xFFFF'FFFF'FFFF'FFFFull}) {
        for (int participant = 0; participant < 7; ++participant) {
            const Schedule s = make_schedule(protocol, seed, participant);
            EXPECT_EQ(s.seed, seed);
            EXPECT_EQ(s.participant_index, participant);
            ASSERT_EQ(s.trials.size(), 32u);
            EXPECT_EQ(s.practice_count(), 2);
            std::vector<std::string> order = s.block_order;
            std::ranges::sort(order);
            EXPECT_EQ(order, protocol.scenes);

            std::map<int, std::set<double>> distances_in_block;
            for (std::size_t i = 0; i < s.trials.size(); ++i) {
                const ScheduledTrial& t = s.trials[i];
                EXPECT_EQ(t.index, static_cast<int>(i));
                ASSERT_TRUE(t.label1_alternative == 0 || t.label1_alternative == 1);
                EXPECT_EQ(t.label1_mode, protocol.alternatives[t.label1_alternative]);
                EXPECT_EQ(t.label2_mode, protocol.alternatives[1 - t.label1_alternative]);
                EXPECT_TRUE(std::ranges::count(protocol.mono_planes, t.mono_plane) == 1);
                if (i < 2) {
                    EXPECT_TRUE(t.practice);
                    EXPECT_EQ(t.block, -1);
                    EXPECT_TRUE(std::ranges::count(protocol.scenes, t.scene) == 1);
                    continue;
                }
                // Data trials: never practice, block b holds positions 2 + 10b .. 11 + 10b.
                EXPECT_FALSE(t.practice);
                ASSERT_EQ(t.block, static_cast<int>(i - 2) / 10);
                EXPECT_EQ(t.scene, s.block_order[t.block]);
                EXPECT_TRUE(distances_in_block[t.block].insert(t.mono_plane).second)
                    << "distance twice in a block";
            }
            ASSERT_EQ(distances_in_block.size(), 3u);
            for (const auto& [block, distances] : distances_in_block) {
                EXPECT_EQ(distances.size(), 10u);
            }
        }
    }
}

TEST(Schedule, SameInputsSameScheduleDifferentSeedDifferentSchedule) {
    const Protocol protocol = fink2019();
    for (std::uint64_t seed = 0; seed < 100; ++seed) {
        const Schedule a = make_schedule(protocol, seed, static_cast<int>(seed % 6));
        const Schedule b = make_schedule(protocol, seed, static_cast<int>(seed % 6));
        EXPECT_EQ(a.block_order, b.block_order);
        EXPECT_TRUE(same_trials(a.trials, b.trials)) << seed;
        const Schedule c = make_schedule(protocol, seed + 1, static_cast<int>(seed % 6));
        EXPECT_FALSE(same_trials(a.trials, c.trials)) << seed;
    }
}

// Scene initial, mono plane in decimetres, label1_alternative; printed by IsPortable.
constexpr const char* kPinnedSchedule =
    "s200:1 b120:0 b120:1 b50:0 b250:0 b30:0 b80:1 b16:1 b310:1 b395:0 b160:0 b200:1 s120:0 "
    "s80:1 s16:1 s250:1 s30:0 s160:0 s310:1 s395:0 s50:1 s200:0 l120:1 l160:0 l80:1 l310:0 l16:0 "
    "l395:1 l30:0 l200:0 l50:1 l250:1 ";

// A recorded seed must give the same schedule on every platform and build: pins one schedule.
TEST(Schedule, IsPortable) {
    const Schedule s = make_schedule(fink2019(), 2019, 4);
    std::string text;
    for (const ScheduledTrial& t : s.trials) {
        text += t.scene.substr(0, 1) + std::to_string(static_cast<int>(t.mono_plane * 10)) + ":" +
                std::to_string(t.label1_alternative) + " ";
    }
    std::cout << "[ schedule(2019, 4) ] " << text << "\n";
    EXPECT_EQ(s.block_order, (std::vector<std::string>{"beams", "spheres", "landscape"}));
    EXPECT_EQ(text, kPinnedSchedule);
}

TEST(Schedule, PracticeCountDoesNotChangeTheDataTrials) {
    Protocol without = fink2019();
    without.practice_trials = 0;
    const Schedule a = make_schedule(fink2019(), 7, 3);
    const Schedule b = make_schedule(without, 7, 3);
    EXPECT_EQ(b.practice_count(), 0);
    ASSERT_EQ(b.trials.size(), 30u);
    for (std::size_t i = 0; i < 30; ++i) {
        ScheduledTrial shifted = a.trials[i + 2];
        shifted.index -= 2;
        EXPECT_TRUE(same_trial(shifted, b.trials[i])) << i;
    }
}

TEST(Schedule, FixedOrdersAreAsListed) {
    Protocol protocol = fink2019();
    protocol.order = TrialOrder::Fixed;
    protocol.first_scene = FirstSceneBalance::Fixed;
    for (int participant = 0; participant < 6; ++participant) {
        const Schedule s = make_schedule(protocol, 99, participant);
        EXPECT_EQ(s.block_order, protocol.scenes);
        for (int i = 0; i < 30; ++i) {
            const ScheduledTrial& t = s.trials[2 + i];
            EXPECT_EQ(t.scene, protocol.scenes[i / 10]);
            EXPECT_EQ(t.mono_plane, protocol.mono_planes[i % 10]);
        }
    }
}

TEST(Schedule, LatinSquareBalancesTheFirstSceneExactly) {
    const Protocol protocol = fink2019();
    constexpr int k = 8;  // 6k participants: whole cycles of the square's 6 rows
    std::map<std::string, std::vector<int>> at_block;
    for (int participant = 0; participant < 6 * k; ++participant) {
        const Schedule s = make_schedule(protocol, 1000 + participant, participant);
        const std::vector<int> row = balanced_latin_square_row(3, participant % 6);
        for (int b = 0; b < 3; ++b) {
            EXPECT_EQ(s.block_order[b], protocol.scenes[row[b]]);
            at_block[s.block_order[b]].resize(3);
            ++at_block[s.block_order[b]][b];
        }
    }
    for (const std::string& scene : protocol.scenes) {
        EXPECT_EQ(at_block[scene], (std::vector<int>{2 * k, 2 * k, 2 * k})) << scene;
    }
}

TEST(Schedule, RandomFirstSceneIsUniformOverSeeds) {
    Protocol protocol = fink2019();
    protocol.first_scene = FirstSceneBalance::Random;
    std::map<std::vector<std::string>, long> orders;
    for (std::uint64_t seed = 0; seed < 6000; ++seed)
        ++orders[make_schedule(protocol, seed, 0).block_order];
    ASSERT_EQ(orders.size(), 6u);  // all 3! block orders occur
    std::vector<long> counts;
    for (const auto& [order, count] : orders) counts.push_back(count);
    const ChiSquare chi = uniform_fit(counts);
    std::cout << "[ random block order ] chi2 " << chi.statistic << " p " << chi.p() << "\n";
    EXPECT_GT(chi.p(), 0.001);
}

// Over seeds, each scene x distance must be equally likely at each of the 30 data positions.
// Block order follows the participant's Latin square row, so only whole cycles of the 6 rows are
// balanced: participant index i % 6 with seed i, for 6 * 1667 = 10002 (about 10^4) sessions.
TEST(Schedule, EveryConditionIsEquallyLikelyAtEveryPosition) {
    const Protocol protocol = fink2019();
    constexpr int kSessions = 6 * 1667;
    std::vector<std::vector<long>> counts(30, std::vector<long>(30, 0));
    long label1_is_first = 0;
    long first_trial_label1_is_first = 0;
    for (int i = 0; i < kSessions; ++i) {
        const Schedule s = make_schedule(protocol, static_cast<std::uint64_t>(i), i % 6);
        for (int pos = 0; pos < 30; ++pos) {
            const ScheduledTrial& t = s.trials[2 + pos];
            const auto scene =
                std::ranges::find(protocol.scenes, t.scene) - protocol.scenes.begin();
            const auto distance = std::ranges::find(protocol.mono_planes, t.mono_plane) -
                                  protocol.mono_planes.begin();
            ++counts[pos][scene * 10 + distance];
            if (t.label1_alternative == 0) ++label1_is_first;
        }
        if (s.trials[2].label1_alternative == 0) ++first_trial_label1_is_first;
    }
    ChiSquare global;
    double min_p = 1.0;
    for (int pos = 0; pos < 30; ++pos) {
        const ChiSquare chi = uniform_fit(counts[pos]);
        std::cout << "[ position " << pos << " ] chi2 " << chi.statistic << " p " << chi.p()
                  << "\n";
        EXPECT_GT(chi.p(), 0.001) << "position " << pos;
        min_p = std::min(min_p, chi.p());
        global.statistic += chi.statistic;
        global.dof += chi.dof;
    }
    std::cout << "[ positions ] min p " << min_p << "; global chi2 " << global.statistic << " dof "
              << global.dof << " p " << global.p() << "\n";
    EXPECT_GT(global.p(), 0.001);

    // Label assignment: a fair coin, over all data trials and over sessions for one position.
    const auto within_4_sigma = [](long hits, double n) {
        return std::abs(static_cast<double>(hits) - n / 2) <= 4 * std::sqrt(n / 4);
    };
    std::cout << "[ labels ] label1 = alternative 0 in " << label1_is_first << " of "
              << 30L * kSessions << "\n";
    EXPECT_TRUE(within_4_sigma(label1_is_first, 30.0 * kSessions)) << label1_is_first;
    EXPECT_TRUE(within_4_sigma(first_trial_label1_is_first, kSessions))
        << first_trial_label1_is_first;
}

// Staircase procedure (issue 21): after the practice trials, trials_per_scene rounds of one slot
// per scene; round 0 in the counterbalanced block order, later rounds shuffled; every slot an
// adaptive data trial whose m is not chosen yet, in its scene's block.
// The position of round `round`'s k-th slot, after the 2 practice trials of 3 scenes.
std::size_t slot(int round, int k) {
    return 2 + 3 * static_cast<std::size_t>(round) + static_cast<std::size_t>(k);
}

Protocol staircase(int trials_per_scene) {
    Protocol p = fink2019();
    p.procedure = Procedure::Staircase;
    p.staircase.trials_per_scene = trials_per_scene;
    return p;
}

TEST(Schedule, StaircaseSlotsComeInRoundsOfEveryScene) {
    const Protocol protocol = staircase(20);
    for (int participant = 0; participant < 6; ++participant) {
        const Schedule s = make_schedule(protocol, 99, participant);
        ASSERT_EQ(s.trials.size(), 2u + 3u * 20u);
        EXPECT_EQ(s.practice_count(), 2);
        // The Latin square's row for this participant, as for the constant procedure.
        const std::vector<int> row = balanced_latin_square_row(3, participant);
        for (int round = 0; round < 20; ++round) {
            std::set<std::string> scenes;
            for (int k = 0; k < 3; ++k) {
                const ScheduledTrial& t = s.trials[slot(round, k)];
                EXPECT_TRUE(t.adaptive && !t.practice && std::isnan(t.mono_plane)) << t.index;
                EXPECT_EQ(s.block_order[static_cast<std::size_t>(t.block)], t.scene);
                EXPECT_EQ(t.label1_mode, protocol.alternatives[t.label1_alternative]);
                scenes.insert(t.scene);
                if (round == 0) {
                    EXPECT_EQ(t.scene, protocol.scenes[static_cast<std::size_t>(row[k])]);
                    EXPECT_EQ(t.block, k);
                }
            }
            EXPECT_EQ(scenes.size(), 3u) << "round " << round;
        }
        for (int i = 0; i < 2; ++i) {
            EXPECT_FALSE(s.trials[static_cast<std::size_t>(i)].adaptive);  // practice: m known
            EXPECT_TRUE(std::isfinite(s.trials[static_cast<std::size_t>(i)].mono_plane));
        }
    }
}

TEST(Schedule, StaircaseRoundsAreShuffledUnlessTheOrderIsFixed) {
    // Over 200 rounds each of the 3! orders comes up; with order = "fixed" only the block order.
    std::map<std::string, int> orders;
    const Schedule s = make_schedule(staircase(200), 5, 0);
    for (int round = 1; round < 200; ++round) {
        std::string order;
        for (int k = 0; k < 3; ++k) order += s.trials[slot(round, k)].scene + " ";
        ++orders[order];
    }
    EXPECT_EQ(orders.size(), 6u);
    for (const auto& [order, count] : orders) EXPECT_GT(count, 15) << order;  // expected 33

    Protocol fixed = staircase(10);
    fixed.order = TrialOrder::Fixed;
    const Schedule f = make_schedule(fixed, 5, 0);
    for (std::size_t i = 2; i < f.trials.size(); ++i) {
        EXPECT_EQ(f.trials[i].block, static_cast<int>((i - 2) % 3)) << i;
    }
    // The same seed gives the same slots, labels included.
    const Schedule again = make_schedule(staircase(200), 5, 0);
    for (std::size_t i = 0; i < s.trials.size(); ++i) {
        EXPECT_EQ(again.trials[i].scene, s.trials[i].scene);
        EXPECT_EQ(again.trials[i].label1_alternative, s.trials[i].label1_alternative);
    }
}

}  // namespace
}  // namespace monoplane::study
