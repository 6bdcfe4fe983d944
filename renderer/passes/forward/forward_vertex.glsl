// The body of forward.vert and forward_show_routing.vert (compiled twice).
#include "renderer/passes/shared/view_constants.h"
#include "renderer/passes/shared/scene_vertex.glsl"

layout(std140, set = 0, binding = 0) uniform ViewBlock { ViewConstants view; };

layout(location = 0) out vec3 out_world;
layout(location = 1) out vec3 out_normal;
layout(location = 2) out vec3 out_albedo;
layout(location = 3) flat out uint out_material;
#ifdef MONOPLANE_SHOW_ROUTING
layout(location = 4) flat out uint out_chunk;  // the draw's first instance: its chunk index
#endif

void main() {
    out_world = in_position;
    out_normal = in_normal;
    out_albedo = in_albedo.rgb;
    out_material = in_material;
#ifdef MONOPLANE_SHOW_ROUTING
    out_chunk = uint(gl_InstanceIndex);
#endif
    gl_Position = view.view_proj * vec4(in_position, 1.0);
}
