// The protocol's pages in the headset (instructions, the ready screen, breaks, the end screen):
// the prompt under each page's text, and the panel overlay that shows them
// (app/headset/text_panel.h; docs/headsets.md, "What the participant sees").
#pragma once

#include <array>
#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "app/headset/eye_compositor.h"
#include "app/headset/text_panel.h"
#include "study/headset_prompts.h"
#include "study/live_session.h"

namespace monoplane::app {

// Whether the screen is one of the protocol's pages of text.
bool is_page_screen(study::ScreenKind kind);

// A break's remaining time as its countdown shows it, "m:ss" ("h:mm:ss" from an hour): whole
// seconds rounded up, so that it reads 0:01, never 0:00, while confirm does not yet continue.
std::string countdown_text(std::int64_t remaining_ns);

// The lines under a page's text: what the controller's buttons do there, in the protocol's
// words (study::HeadsetPrompts; English by default). Instructions "Page 2 of 3 - CONFIRM: next,
// SWITCH: back" (no back on the first page, last instead of next on the last; a single page
// "Press CONFIRM to begin"); ready "Press CONFIRM to begin"; a break "Break: 0:23", then "Press
// CONFIRM to continue"; the end screen none. A prompt the protocol left empty is left out.
std::vector<std::string> page_footer(const study::LiveScreen& screen,
                                     const study::HeadsetPrompts& prompts = {});

// Everything a page's image shows, as one string: a different one needs a new image (a break's
// changes once a second, not every frame).
std::string page_key(const study::LiveScreen& screen, const study::HeadsetPrompts& prompts = {});

// The page panel of the eyes: one overlay, its image made again only when page_key changes.
class PagePanels {
  public:
    PagePanels(const headset::TextPanelOptions& options, study::HeadsetPrompts prompts)
        : options_(options), prompts_(std::move(prompts)) {}

    // The overlay that shows `screen` (a page) in eyes of these frusta and swapchain size.
    headset::EyeCompositor::Overlay overlay(const study::LiveScreen& screen,
                                            headset::EyeCompositor& compositor,
                                            const std::array<rig::Tangents, 2>& eyes,
                                            vk::Extent2D extent);

    static constexpr const char* kOverlayKey = "page";

  private:
    headset::TextPanelOptions options_;
    study::HeadsetPrompts prompts_;
    std::string shown_;  // page_key (and the eyes') of the image under kOverlayKey
    headset::OverlayPlacement placement_;
    std::set<std::string> warned_;  // pages said to be too long for the view
};

}  // namespace monoplane::app
