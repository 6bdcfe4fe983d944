#version 460
#extension GL_GOOGLE_include_directive : require
// The depth histogram of one eye's linear depth (renderer/plan/depth_histogram.h): each
// workgroup counts its 16 x 16 pixels into shared bins, then adds them to the frame's buffer,
// which both eyes' dispatches share. Log-spaced bins from near to far; the sky counted apart;
// the farthest non-sky depth by atomicMax on its float bits (positive floats order as their bits).
#include "renderer/plan/depth_histogram_constants.h"
#include "renderer/passes/shared/view_constants.h"

layout(local_size_x = 16, local_size_y = 16) in;

layout(set = 0, binding = 0) uniform sampler2D linear_depth;  // metres in front of the eyes
layout(std430, set = 0, binding = 1) buffer Histogram { uint words[MONOPLANE_DEPTH_HISTOGRAM_WORDS]; };
layout(push_constant) uniform Push {
    float log_near;
    float bins_per_log_unit;  // kBins / log(far / near)
    uvec2 size;
};

shared uint bins[MONOPLANE_DEPTH_HISTOGRAM_BINS];
shared uint sky;
shared uint farthest_bits;

void main() {
    uint lane = gl_LocalInvocationIndex;
    if (lane < MONOPLANE_DEPTH_HISTOGRAM_BINS) bins[lane] = 0u;
    if (lane == 0u) {
        sky = 0u;
        farthest_bits = 0u;
    }
    barrier();
    uvec2 pixel = gl_GlobalInvocationID.xy;
    if (all(lessThan(pixel, size))) {
        float depth = texelFetch(linear_depth, ivec2(pixel), 0).r;
        if (depth >= 0.5 * MONOPLANE_SKY_LINEAR_DEPTH) {
            atomicAdd(sky, 1u);
        } else {
            float position = (log(max(depth, 1e-30)) - log_near) * bins_per_log_unit;
            int bin = clamp(int(floor(position)), 0, MONOPLANE_DEPTH_HISTOGRAM_BINS - 1);
            atomicAdd(bins[bin], 1u);
            atomicMax(farthest_bits, floatBitsToUint(max(depth, 0.0)));
        }
    }
    barrier();
    if (lane < MONOPLANE_DEPTH_HISTOGRAM_BINS && bins[lane] != 0u) atomicAdd(words[lane], bins[lane]);
    if (lane == 0u) {
        if (sky != 0u) atomicAdd(words[MONOPLANE_DEPTH_HISTOGRAM_SKY_WORD], sky);
        atomicMax(words[MONOPLANE_DEPTH_HISTOGRAM_FARTHEST_WORD], farthest_bits);
    }
}
