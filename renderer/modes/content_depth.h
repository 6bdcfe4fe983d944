// How far the content of a frame can reach (issue 20, `--mono-plane auto`): the error budget must
// hold for every visible pixel beyond m, and content ends somewhere (a room's walls, a street's
// last house), so the error at that depth, not at infinity, is what counts. CPU, from the chunks'
// bounds: an upper bound that is never too small, unlike the last frame's pixels, which miss what
// a turn of the head brings into view.
#pragma once

#include "renderer/modes/view_setup.h"
#include "scenes/scene.h"

namespace monoplane::modes {

// The largest depth (metres in front of the eyes' plane, along the head's forward axis) of any
// corner of any chunk whose bounds meet either eye's frustum (near..far) widened by
// `widen_tangent` on every side, so that content about to come into view counts already. The
// eyes' near plane when no chunk is in view (nothing but sky). Any time; O(chunks).
double farthest_content_depth(const scenes::Scene& scene, const StereoViewInputs& views,
                              double widen_tangent = 0.25);

}  // namespace monoplane::modes
