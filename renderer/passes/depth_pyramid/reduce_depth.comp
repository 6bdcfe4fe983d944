#version 460
// One level of the merged depth pyramid from the level below: the farthest (minimum reversed-Z)
// depth of the texels it covers. Sizes halve rounding down, so a coarser texel at the odd end of
// a row or column also takes the finer level's last texel.
layout(local_size_x = 8, local_size_y = 8) in;

layout(set = 0, binding = 0, r32f) uniform readonly image2D finer;
layout(set = 0, binding = 1, r32f) uniform writeonly image2D coarser;

void main() {
    ivec2 texel = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(coarser);
    if (any(greaterThanEqual(texel, size))) return;
    ivec2 finer_size = imageSize(finer);
    ivec2 first = texel * 2;
    ivec2 last = min(texel * 2 + 1, finer_size - 1);
    if (texel.x == size.x - 1) last.x = finer_size.x - 1;
    if (texel.y == size.y - 1) last.y = finer_size.y - 1;
    float farthest = 1.0;
    for (int y = first.y; y <= last.y; ++y) {
        for (int x = first.x; x <= last.x; ++x) {
            farthest = min(farthest, imageLoad(finer, ivec2(x, y)).r);
        }
    }
    imageStore(coarser, texel, vec4(farthest));
}
