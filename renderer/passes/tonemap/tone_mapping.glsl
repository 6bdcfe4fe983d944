// The display transform of every tone-mapped image: exposure, then the ACES filmic fit of
// Narkowicz (2015); the sRGB attachment applies the transfer function on store. Shared by
// tonemap.frag and the composite that writes the display image itself
// (renderer/passes/composite/composite_display.frag), so that the two cannot diverge.
vec3 monoplane_tone_map(vec3 hdr, float exposure) {
    vec3 x = hdr * exposure;
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}
