// Screen-space velocity of a world point (w = 1) or direction (w = 0, the sky) for TAA (Karis
// 2014): its NDC position in this frame minus its NDC position in the previous frame, both
// without the jitter. Needs `view` (ViewConstants) in scope.
vec2 ndc_velocity(vec4 world) {
    vec4 now = view.velocity_view_proj * world;
    vec4 before = view.prev_view_proj * world;
    return now.xy / now.w - before.xy / before.w;
}
