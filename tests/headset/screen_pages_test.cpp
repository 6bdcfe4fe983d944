// The prompts under the protocol's pages in the headset and when a page's image is made again:
// a break's countdown changes once a second, not every frame.
#include <gtest/gtest.h>

#include <set>

#include "app/commands/screen_pages.h"

namespace monoplane::app {
namespace {

using study::LiveScreen;
using study::ScreenKind;

constexpr std::int64_t kSecond = 1'000'000'000;

LiveScreen page(ScreenKind kind, const std::string* text, int page = 0, int count = 0) {
    LiveScreen screen;
    screen.kind = kind;
    screen.text = text;
    screen.page = page;
    screen.page_count = count;
    return screen;
}

TEST(PageFooter, InstructionsSayWhatTheButtonsDo) {
    const std::string text = "Read me.";
    EXPECT_EQ(page_footer(page(ScreenKind::Instructions, &text, 0, 3)),
              std::vector<std::string>{"Page 1 of 3 - CONFIRM: next"});
    EXPECT_EQ(page_footer(page(ScreenKind::Instructions, &text, 1, 3)),
              std::vector<std::string>{"Page 2 of 3 - CONFIRM: next, SWITCH: back"});
    EXPECT_EQ(page_footer(page(ScreenKind::Instructions, &text, 2, 3)),
              std::vector<std::string>{"Page 3 of 3 - CONFIRM: begin, SWITCH: back"});
    EXPECT_EQ(page_footer(page(ScreenKind::Instructions, &text, 0, 1)),
              std::vector<std::string>{"Press CONFIRM to begin"});
    EXPECT_EQ(page_footer(page(ScreenKind::Ready, &text)),
              std::vector<std::string>{"Press CONFIRM to begin"});
    EXPECT_TRUE(page_footer(page(ScreenKind::End, &text)).empty());
}

TEST(PageFooter, ABreakCountsDownThenAsksForConfirm) {
    const std::string text = "Take a short break.";
    LiveScreen screen = page(ScreenKind::Break, &text);
    screen.break_remaining_ns = 23 * kSecond;
    EXPECT_EQ(page_footer(screen), std::vector<std::string>{"Break: 0:23"});
    screen.break_remaining_ns = 22 * kSecond + 1;  // rounded up: never 0:00 while refused
    EXPECT_EQ(page_footer(screen), std::vector<std::string>{"Break: 0:23"});
    screen.break_remaining_ns = 1;
    EXPECT_EQ(page_footer(screen), std::vector<std::string>{"Break: 0:01"});
    screen.break_remaining_ns = 0;
    EXPECT_EQ(page_footer(screen), std::vector<std::string>{"Press CONFIRM to continue"});
    EXPECT_EQ(countdown_text(95 * kSecond), "1:35");
    EXPECT_EQ(countdown_text(3725 * kSecond), "1:02:05");
}

// The protocol's own words ([text.prompts]): the footer composed of the given parts, a part
// left empty left out with its separator, the countdown filled into its template.
TEST(PageFooter, ThePromptsOfTheProtocolsLanguage) {
    study::HeadsetPrompts de;
    de.page = "Seite {page} von {pages}";
    de.next = "CONFIRM: weiter";
    de.last = "CONFIRM: anfangen";
    de.back = "SWITCH: zur\u00fcck";
    de.begin = "Zum Beginnen CONFIRM dr\u00fccken";
    de.resume = "Weiter mit CONFIRM";
    de.countdown = "Pause: noch {time}";
    const std::string text = "Lies mich.";
    EXPECT_EQ(page_footer(page(ScreenKind::Instructions, &text, 0, 3), de),
              std::vector<std::string>{"Seite 1 von 3 - CONFIRM: weiter"});
    EXPECT_EQ(page_footer(page(ScreenKind::Instructions, &text, 2, 3), de),
              std::vector<std::string>{"Seite 3 von 3 - CONFIRM: anfangen, SWITCH: zur\u00fcck"});
    EXPECT_EQ(page_footer(page(ScreenKind::Instructions, &text, 0, 1), de),
              std::vector<std::string>{"Zum Beginnen CONFIRM dr\u00fccken"});
    LiveScreen pause = page(ScreenKind::Break, &text);
    pause.break_remaining_ns = 95 * kSecond;
    EXPECT_EQ(page_footer(pause, de), std::vector<std::string>{"Pause: noch 1:35"});
    pause.break_remaining_ns = 0;
    EXPECT_EQ(page_footer(pause, de), std::vector<std::string>{"Weiter mit CONFIRM"});
    // Parts left empty: no back, then no page number either, then nothing at all.
    de.back.clear();
    EXPECT_EQ(page_footer(page(ScreenKind::Instructions, &text, 1, 3), de),
              std::vector<std::string>{"Seite 2 von 3 - CONFIRM: weiter"});
    de.page.clear();
    EXPECT_EQ(page_footer(page(ScreenKind::Instructions, &text, 1, 3), de),
              std::vector<std::string>{"CONFIRM: weiter"});
    de.next.clear();
    EXPECT_TRUE(page_footer(page(ScreenKind::Instructions, &text, 1, 3), de).empty());
    // Another wording is another image.
    EXPECT_NE(page_key(page(ScreenKind::Ready, &text), de),
              page_key(page(ScreenKind::Ready, &text)));
}

TEST(PageKey, ABreaksImageChangesOncePerSecond) {
    // 30 s of break at 90 Hz: one image per second of countdown and one for "press confirm".
    const std::string text = "Take a short break.";
    LiveScreen screen = page(ScreenKind::Break, &text);
    std::set<std::string> keys;
    int changes = 0;
    std::string previous;
    for (std::int64_t t = 0; t <= 30 * kSecond + kSecond / 2; t += kSecond / 90) {
        screen.break_remaining_ns = std::max<std::int64_t>(0, 30 * kSecond - t);
        const std::string key = page_key(screen);
        if (key != previous) ++changes;
        previous = key;
        keys.insert(key);
    }
    EXPECT_EQ(keys.size(), 31u);
    EXPECT_EQ(changes, 31);
}

TEST(PageKey, DistinctPagesDistinctImages) {
    const std::string a = "First page.", b = "Second page.";
    const std::string key1 = page_key(page(ScreenKind::Instructions, &a, 0, 2));
    EXPECT_EQ(key1, page_key(page(ScreenKind::Instructions, &a, 0, 2)));
    EXPECT_NE(key1, page_key(page(ScreenKind::Instructions, &b, 1, 2)));
    EXPECT_NE(page_key(page(ScreenKind::Ready, &a)), page_key(page(ScreenKind::End, &a)));
    EXPECT_TRUE(is_page_screen(ScreenKind::Break));
    EXPECT_FALSE(is_page_screen(ScreenKind::Questionnaire));
}

}  // namespace
}  // namespace monoplane::app
