// The panels' words: above all, the modes behind the blind labels only when unblinded.
#include <gtest/gtest.h>

#include <algorithm>

#include "app/window/mirror_texture.h"
#include "app/window/view_text.h"

namespace monoplane::window {
namespace {

ExperimenterView trial_view() {
    ExperimenterView view;
    view.trial_number = 4;
    view.trial_count = 30;
    view.phase = Phase::Trial;
    view.visible_label = 2;
    view.switches = 3;
    view.both_seen = true;
    view.label_modes = {"stereo", "hybrid"};
    return view;
}

bool mentions(const std::vector<std::string>& lines, const std::string& word) {
    return std::any_of(lines.begin(), lines.end(), [&](const std::string& line) {
        return line.find(word) != std::string::npos;
    });
}

TEST(TrialStateLines, HideTheModesWhileBlinded) {
    const auto lines = trial_state_lines(trial_view());
    EXPECT_FALSE(mentions(lines, "hybrid"));
    EXPECT_FALSE(mentions(lines, "stereo"));
    EXPECT_TRUE(mentions(lines, "blinded"));
}

TEST(TrialStateLines, ShowTheModesWhenUnblinded) {
    ExperimenterView view = trial_view();
    view.unblinded = true;
    const auto lines = trial_state_lines(view);
    EXPECT_TRUE(mentions(lines, "Label 1 = stereo"));
    EXPECT_TRUE(mentions(lines, "Label 2 = hybrid"));
}

TEST(TrialStateLines, SayWhichLabelIsVisibleAndTheCounts) {
    const auto lines = trial_state_lines(trial_view());
    EXPECT_TRUE(mentions(lines, "Label 2 visible"));
    EXPECT_TRUE(mentions(lines, "Switches: 3"));
    EXPECT_TRUE(mentions(lines, "Both seen: yes"));
    ExperimenterView none = trial_view();
    none.visible_label = 0;
    EXPECT_TRUE(mentions(trial_state_lines(none), "No label visible"));
}

TEST(ProgressText, CountsTrialsAndMarksPractice) {
    ExperimenterView view = trial_view();
    EXPECT_EQ(progress_text(view), "Trial 4 of 30");
    view.practice = true;
    EXPECT_EQ(progress_text(view), "Trial 4 of 30 (practice)");
    view.trial_number = 0;
    EXPECT_EQ(progress_text(view), "Before the first trial");
}

TEST(ProgressFraction, CountsFinishedTrials) {
    ExperimenterView view = trial_view();
    EXPECT_FLOAT_EQ(progress_fraction(view), 3.0f / 30.0f);
    view.phase = Phase::Finished;
    EXPECT_FLOAT_EQ(progress_fraction(view), 1.0f);
    view.trial_count = 0;
    EXPECT_FLOAT_EQ(progress_fraction(view), 0.0f);
}

TEST(FormatDuration, MinutesSecondsTenthsThenHours) {
    EXPECT_EQ(format_duration(0.0), "0:00.0");
    EXPECT_EQ(format_duration(75.26), "1:15.2");
    EXPECT_EQ(format_duration(3725.0), "1:02:05");
    EXPECT_EQ(format_duration(-3.0), "0:00.0");
}

TEST(QuestionnaireComplete, OnlyWhenEveryItemHasAnAnswerOnTheScale) {
    ExperimenterView view;
    view.questionnaire_items = {"a", "b"};
    view.scale_points = 7;
    view.answers = {3, 0};
    EXPECT_FALSE(questionnaire_complete(view));
    view.answers = {3, 7};
    EXPECT_TRUE(questionnaire_complete(view));
    view.answers = {3, 8};
    EXPECT_FALSE(questionnaire_complete(view));
    view.answers = {3};
    EXPECT_FALSE(questionnaire_complete(view));
}

TEST(FitAspect, KeepsTheAspectAndCentres) {
    const FitRect wide = fit_aspect(800, 600, 1600, 900);
    EXPECT_FLOAT_EQ(wide.width, 800);
    EXPECT_FLOAT_EQ(wide.height, 450);
    EXPECT_FLOAT_EQ(wide.x, 0);
    EXPECT_FLOAT_EQ(wide.y, 75);
    const FitRect tall = fit_aspect(800, 600, 300, 600);
    EXPECT_FLOAT_EQ(tall.width, 300);
    EXPECT_FLOAT_EQ(tall.x, 250);
    EXPECT_FLOAT_EQ(fit_aspect(0, 600, 1, 1).width, 0);
}

}  // namespace
}  // namespace monoplane::window
