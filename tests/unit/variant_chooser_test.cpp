// --variant auto's measurement policy (renderer/plan/variant_chooser.h), with frame times chosen
// by the test: which variant each frame gets, which one is chosen, and when it measures again.
#include <gtest/gtest.h>

#include <map>
#include <vector>

#include "renderer/plan/variant_chooser.h"

namespace monoplane::plan {
namespace {

// Renders `frames` frames, each costing what `cost` says for the variant the chooser picked;
// returns the variants in order.
std::vector<MonoCulling> run(VariantChooser& chooser, int frames,
                             const std::map<MonoCulling, double>& cost) {
    std::vector<MonoCulling> used;
    for (int i = 0; i < frames; ++i) {
        const MonoCulling v = chooser.next();
        used.push_back(v);
        chooser.record(cost.at(v));
    }
    return used;
}

TEST(VariantChooser, ExploresInterleavedThenUsesTheFastest) {
    VariantChooser chooser({4, 5});
    const std::map<MonoCulling, double> cost = {{MonoCulling::kNoOpt, 30.0},
                                                {MonoCulling::kDiscard, 20.0},
                                                {MonoCulling::kOcclusionCull, 25.0}};
    EXPECT_FALSE(chooser.chosen().has_value());
    const std::vector<MonoCulling> used = run(chooser, 12 + 5, cost);
    // 4 rounds of (no-opt, discard, occlusion-cull), then 5 frames of the cheapest.
    for (int i = 0; i < 12; ++i) {
        EXPECT_EQ(used[static_cast<std::size_t>(i)],
                  VariantChooser::kCandidates[static_cast<std::size_t>(i % 3)])
            << i;
    }
    for (int i = 12; i < 17; ++i)
        EXPECT_EQ(used[static_cast<std::size_t>(i)], MonoCulling::kDiscard);
    ASSERT_TRUE(chooser.chosen().has_value());
    EXPECT_EQ(*chooser.chosen(), MonoCulling::kDiscard);
    // After the exploitation frames it measures again, from the first candidate.
    EXPECT_EQ(chooser.next(), MonoCulling::kNoOpt);
}

TEST(VariantChooser, IgnoresTheFirstRoundAndTakesTheMedian) {
    VariantChooser chooser({4, 100});
    // No-opt's first frame is slow (pipelines), then fast; discard has one outlier frame that a
    // mean would count and the median does not; occlusion-cull is steady in between.
    const std::vector<std::vector<double>> times = {
        {500.0, 10.0, 11.0, 12.0},  // no-opt: first round ignored -> median 11
        {9.0, 9.0, 50.0, 9.5},      // discard: median 9.5, mean of the last three 22.8
        {10.5, 10.5, 10.5, 10.5},   // occlusion-cull: 10.5
    };
    for (int round = 0; round < 4; ++round) {
        for (std::size_t c = 0; c < 3; ++c) {
            EXPECT_EQ(chooser.next(), VariantChooser::kCandidates[c]);
            chooser.record(times[c][static_cast<std::size_t>(round)]);
        }
    }
    ASSERT_TRUE(chooser.chosen().has_value());
    EXPECT_EQ(*chooser.chosen(), MonoCulling::kDiscard);
}

TEST(VariantChooser, TiesKeepTheSimplerVariantAndResetMeasuresAgain) {
    VariantChooser chooser({2, 100});
    const std::map<MonoCulling, double> equal = {{MonoCulling::kNoOpt, 10.0},
                                                 {MonoCulling::kDiscard, 10.0},
                                                 {MonoCulling::kOcclusionCull, 10.0}};
    run(chooser, 6, equal);
    ASSERT_TRUE(chooser.chosen().has_value());
    EXPECT_EQ(*chooser.chosen(), MonoCulling::kNoOpt);
    EXPECT_EQ(chooser.next(), MonoCulling::kNoOpt);
    run(chooser, 3, equal);
    chooser.reset();
    // Exploring again: the next frames walk the candidates; occlusion-cull now wins.
    const std::map<MonoCulling, double> culled_wins = {{MonoCulling::kNoOpt, 10.0},
                                                       {MonoCulling::kDiscard, 10.0},
                                                       {MonoCulling::kOcclusionCull, 5.0}};
    const std::vector<MonoCulling> used = run(chooser, 6, culled_wins);
    EXPECT_EQ(used[1], MonoCulling::kDiscard);
    EXPECT_EQ(used[2], MonoCulling::kOcclusionCull);
    EXPECT_EQ(*chooser.chosen(), MonoCulling::kOcclusionCull);
}

TEST(VariantChooser, RefusesATrialWithoutCountedRounds) {
    EXPECT_DEATH(VariantChooser({1, 10}), "programming error.*rounds_per_trial >= 2");
    EXPECT_DEATH(VariantChooser({3, 0}), "programming error.*exploit_frames >= 1");
}

}  // namespace
}  // namespace monoplane::plan
