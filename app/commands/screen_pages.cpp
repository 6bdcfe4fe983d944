#include "app/commands/screen_pages.h"

#include <cstdio>
#include <functional>
#include <iostream>

#include "app/headset/overlay_text.h"

namespace monoplane::app {

using study::ScreenKind;

namespace {

// The page as a warning names it.
std::string page_name(const study::LiveScreen& screen) {
    switch (screen.kind) {
        case ScreenKind::Instructions:
            return "instructions' page " + std::to_string(screen.page + 1);
        case ScreenKind::Ready:
            return "ready page";
        case ScreenKind::Break:
            return "break page";
        default:
            return "end page";
    }
}

}  // namespace

bool is_page_screen(ScreenKind kind) {
    return kind == ScreenKind::Instructions || kind == ScreenKind::Ready ||
           kind == ScreenKind::Break || kind == ScreenKind::End;
}

std::string countdown_text(std::int64_t remaining_ns) {
    constexpr std::int64_t kSecond = 1'000'000'000;
    const std::int64_t s = remaining_ns <= 0 ? 0 : (remaining_ns + kSecond - 1) / kSecond;
    char text[32];
    if (s >= 3600) {
        std::snprintf(text, sizeof(text), "%lld:%02lld:%02lld", static_cast<long long>(s / 3600),
                      static_cast<long long>(s / 60 % 60), static_cast<long long>(s % 60));
    } else {
        std::snprintf(text, sizeof(text), "%lld:%02lld", static_cast<long long>(s / 60),
                      static_cast<long long>(s % 60));
    }
    return text;
}

namespace {

// The instructions' footer: the page, then the action, then going back, as far as each is given.
std::string instructions_footer(const study::LiveScreen& screen,
                                const study::HeadsetPrompts& prompts) {
    if (screen.page_count <= 1) return prompts.begin;
    const bool first = screen.page == 0;
    const bool last = screen.page + 1 >= screen.page_count;
    const std::pair<std::string_view, std::string> numbers[] = {
        {"page", std::to_string(screen.page + 1)}, {"pages", std::to_string(screen.page_count)}};
    std::string actions = last ? prompts.last : prompts.next;
    if (!first && !prompts.back.empty()) actions += (actions.empty() ? "" : ", ") + prompts.back;
    const std::string page = study::fill_prompt(prompts.page, numbers);
    return page + (page.empty() || actions.empty() ? "" : " - ") + actions;
}

std::string break_footer(const study::LiveScreen& screen, const study::HeadsetPrompts& prompts) {
    if (screen.break_remaining_ns <= 0) return prompts.resume;
    const std::pair<std::string_view, std::string> time[] = {
        {"time", countdown_text(screen.break_remaining_ns)}};
    return study::fill_prompt(prompts.countdown, time);
}

}  // namespace

std::vector<std::string> page_footer(const study::LiveScreen& screen,
                                     const study::HeadsetPrompts& prompts) {
    std::string line;
    switch (screen.kind) {
        case ScreenKind::Instructions:
            line = instructions_footer(screen, prompts);
            break;
        case ScreenKind::Ready:
            line = prompts.begin;
            break;
        case ScreenKind::Break:
            line = break_footer(screen, prompts);
            break;
        default:
            break;
    }
    if (line.empty()) return {};
    return {line};
}

std::string page_key(const study::LiveScreen& screen, const study::HeadsetPrompts& prompts) {
    std::string key = std::to_string(static_cast<int>(screen.kind)) + "|" +
                      std::to_string(screen.page) + "|" +
                      std::to_string(std::hash<std::string>{}(screen.text ? *screen.text : ""));
    for (const std::string& line : page_footer(screen, prompts)) key += "|" + line;
    return key;
}

headset::EyeCompositor::Overlay PagePanels::overlay(const study::LiveScreen& screen,
                                                    headset::EyeCompositor& compositor,
                                                    const std::array<rig::Tangents, 2>& eyes,
                                                    vk::Extent2D extent) {
    // The frusta too: a page first drawn in a frame without located views is drawn again for
    // the runtime's own once they come.
    std::string key = page_key(screen, prompts_);
    for (const rig::Tangents& t : eyes) {
        for (const double v : {t.left, t.right, t.down, t.up}) key += "|" + std::to_string(v);
    }
    key += "|" + std::to_string(extent.width) + "x" + std::to_string(extent.height);
    if (key != shown_ || !compositor.has_overlay(kOverlayKey)) {
        const headset::TextPanel panel =
            headset::layout_text_panel(screen.text ? *screen.text : std::string(),
                                       page_footer(screen, prompts_), eyes, extent, options_);
        const std::string page = page_name(screen);
        if (panel.shrunk && warned_.insert(page).second) {
            std::cerr << "warning: the " << page << "'s text does not fit the headset's view "
                      << "with letters " << options_.text_height_deg
                      << " degrees high (text_height_deg); it is shown with letters "
                      << panel.capital_deg << " degrees high\n";
        }
        compositor.set_overlay(kOverlayKey, headset::render_text(panel.lines, panel.style));
        placement_ = panel.placement;
        shown_ = key;
    }
    return {kOverlayKey, placement_};
}

}  // namespace monoplane::app
