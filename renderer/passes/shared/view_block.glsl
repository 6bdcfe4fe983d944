// Set 0, binding 0: the view constants, and `view`, those of the view being drawn.
// Single-pass stereo binds both eyes' constants as one array (left, right) and selects by the
// view index: gl_ViewIndex with VK_KHR_multiview (MONOPLANE_STEREO_MULTIVIEW), the layer the
// geometry shader sent the primitive to (MONOPLANE_STEREO_GS), or the instance's eye
// (MONOPLANE_STEREO_INSTANCED); the last two through MONOPLANE_VIEW_INDEX, which each stage
// defines before including this.
#include "renderer/passes/shared/view_constants.h"
#if defined(MONOPLANE_STEREO_MULTIVIEW)
#extension GL_EXT_multiview : require
#define MONOPLANE_VIEW_INDEX gl_ViewIndex
#endif
#if defined(MONOPLANE_STEREO_MULTIVIEW) || defined(MONOPLANE_STEREO_GS) || \
    defined(MONOPLANE_STEREO_INSTANCED)
#define MONOPLANE_SINGLE_PASS_STEREO
layout(std140, set = 0, binding = 0) uniform ViewBlock { ViewConstants views[2]; };
#define view views[MONOPLANE_VIEW_INDEX]
#else
layout(std140, set = 0, binding = 0) uniform ViewBlock { ViewConstants view; };
#endif
