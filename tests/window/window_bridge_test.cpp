// What the experimenter window is told of the session's pages and notes: the phase for each
// screen, the page mirrored as the headset shows it, the page heading, and the note field's
// report; and the keyboard on the pages.
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include "app/commands/window_bridge.h"
#include "app/window/key_commands.h"
#include "app/window/view_text.h"

namespace monoplane::app {
namespace {

using study::LiveScreen;
using study::ScreenKind;
using window::Phase;

constexpr std::int64_t kSecond = 1'000'000'000;

TEST(WindowPhase, EveryScreenHasItsPhase) {
    LiveScreen screen;
    const std::pair<ScreenKind, Phase> pairs[] = {{ScreenKind::Neutral, Phase::Neutral},
                                                  {ScreenKind::Trial, Phase::Trial},
                                                  {ScreenKind::Questionnaire, Phase::Questionnaire},
                                                  {ScreenKind::Finished, Phase::Finished},
                                                  {ScreenKind::Aborted, Phase::Aborted},
                                                  {ScreenKind::Instructions, Phase::Instructions},
                                                  {ScreenKind::Ready, Phase::Ready},
                                                  {ScreenKind::Break, Phase::Break},
                                                  {ScreenKind::End, Phase::End}};
    for (const auto& [kind, phase] : pairs) {
        screen.kind = kind;
        EXPECT_EQ(window_phase(screen), phase) << window::phase_name(phase);
    }
    screen.kind = ScreenKind::Trial;
    screen.paused = true;
    EXPECT_EQ(window_phase(screen), Phase::Paused);
}

TEST(MirrorPage, ThePageAsTheHeadsetShowsIt) {
    const std::string text = "Take a short break \xe2\x80\x94 remove the headset if you like.";
    LiveScreen screen;
    screen.kind = ScreenKind::Break;
    screen.text = &text;
    screen.break_remaining_ns = 22 * kSecond + 300'000'000;
    window::ExperimenterView view;
    view.phase = window_phase(screen);
    mirror_page(screen, view);
    // The headset draws the protocol's characters as written (its font has the dash), and the
    // window mirrors them so.
    EXPECT_EQ(view.page_text, "Take a short break \xe2\x80\x94 remove the headset if you like.");
    EXPECT_EQ(view.break_countdown, "0:23");
    EXPECT_EQ(window::page_heading(view), "Break: 0:23 until CONFIRM continues");
    screen.break_remaining_ns = 0;
    mirror_page(screen, view);
    EXPECT_EQ(view.break_countdown, "");
    EXPECT_EQ(window::page_heading(view), "Break over: waiting for CONFIRM to continue");

    const std::string page2 = "Second page.\tZweite Seite.\r";
    screen = LiveScreen{};
    screen.kind = ScreenKind::Instructions;
    screen.text = &page2;
    screen.page = 1;
    screen.page_count = 3;
    view.phase = window_phase(screen);
    mirror_page(screen, view);
    EXPECT_EQ(view.page_text, "Second page. Zweite Seite.");  // a tab as a space, no CR
    EXPECT_EQ(window::page_heading(view).rfind("Instructions, page 2 of 3", 0), 0u);
    EXPECT_TRUE(window::shows_page(view.phase));

    // Off the pages nothing of them stays.
    screen = LiveScreen{};
    screen.kind = ScreenKind::Neutral;
    view.phase = window_phase(screen);
    mirror_page(screen, view);
    EXPECT_EQ(view.page_text, "");
    EXPECT_EQ(view.page_count, 0);
    EXPECT_FALSE(window::shows_page(view.phase));
    EXPECT_EQ(window::page_heading(view), "");
}

TEST(NoteOutcome, StoredAtTheTrialOrWhyNot) {
    EXPECT_EQ(note_outcome(Result<void>(Ok{}), "adjusted the headset", 12),
              "note stored at trial 12");
    EXPECT_EQ(note_outcome(Result<void>(Ok{}), "before we start", 0),
              "note stored before the first trial");
    const std::string refused =
        note_outcome(Result<void>(Error{"a note cannot be blank"}), "  ", 3);
    EXPECT_EQ(refused.rfind("note not stored: a note cannot be blank", 0), 0u);
    // What was typed is not lost with the cleared field.
    EXPECT_NE(note_outcome(Result<void>(Error{"disk full"}), "participant sneezed", 3)
                  .find("participant sneezed"),
              std::string::npos);
}

TEST(PageKeys, TheControllersButtonsOnTheKeyboard) {
    using Kind = window::Command::Kind;
    const auto kind_for = [](int key, Phase phase) -> std::optional<Kind> {
        const auto command = window::command_for_key(key, phase);
        if (!command) return std::nullopt;
        return command->kind;
    };
    for (const Phase phase : {Phase::Instructions, Phase::Ready, Phase::Break}) {
        EXPECT_EQ(kind_for(GLFW_KEY_ENTER, phase), Kind::Confirm);
        EXPECT_EQ(kind_for(GLFW_KEY_KP_ENTER, phase), Kind::Confirm);
        EXPECT_FALSE(kind_for(GLFW_KEY_P, phase));  // no pause on a page
    }
    EXPECT_EQ(kind_for(GLFW_KEY_SPACE, Phase::Instructions), Kind::Switch);  // back a page
    EXPECT_FALSE(kind_for(GLFW_KEY_SPACE, Phase::Ready));
    EXPECT_FALSE(kind_for(GLFW_KEY_SPACE, Phase::Break));
    for (const int key : {GLFW_KEY_ENTER, GLFW_KEY_SPACE, GLFW_KEY_P}) {
        EXPECT_FALSE(kind_for(key, Phase::End));
    }
}

}  // namespace
}  // namespace monoplane::app
