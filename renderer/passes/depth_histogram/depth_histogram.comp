#version 460
#extension GL_GOOGLE_include_directive : require
// The depth histogram of one eye's linear depth (renderer/plan/depth_histogram.h): each
// invocation counts a 4 x 4 block of pixels, each workgroup its 64 x 64 pixels into shared bins,
// then adds them to the frame's buffer, which both eyes' dispatches share. Log-spaced bins from
// near to far; the sky counted apart; the farthest non-sky depth by atomicMax on its float bits
// (positive floats order as their bits).
//
// Why blocks: depth is coherent across neighbouring pixels, so an invocation adds a run of pixels
// of one bin with one shared atomic instead of one per pixel. Atomics on shared memory are
// serialised on CPU rasterizers (llvmpipe): one per pixel made this pass 5 % of a SPHERES frame
// (36 ms of 700), more than the gap it finds could save. The counts are exact, as before.
#include "renderer/plan/depth_histogram_constants.h"
#include "renderer/passes/shared/view_constants.h"

layout(local_size_x = 16, local_size_y = 16) in;
const uint kBlock = 4u;  // pixels per invocation along each axis (depth_histogram_pass.cpp)

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
    uvec2 origin = gl_GlobalInvocationID.xy * kBlock;
    int run_bin = -1;  // the bin of the run of pixels being counted, and its length
    uint run_length = 0u;
    uint sky_pixels = 0u;
    float farthest = 0.0;
    for (uint y = 0u; y < kBlock; ++y) {
        for (uint x = 0u; x < kBlock; ++x) {
            uvec2 pixel = origin + uvec2(x, y);
            if (!all(lessThan(pixel, size))) continue;
            float depth = texelFetch(linear_depth, ivec2(pixel), 0).r;
            if (depth >= 0.5 * MONOPLANE_SKY_LINEAR_DEPTH) {
                ++sky_pixels;
                continue;
            }
            float position = (log(max(depth, 1e-30)) - log_near) * bins_per_log_unit;
            int bin = clamp(int(floor(position)), 0, MONOPLANE_DEPTH_HISTOGRAM_BINS - 1);
            if (bin != run_bin) {
                if (run_length != 0u) atomicAdd(bins[run_bin], run_length);
                run_bin = bin;
                run_length = 0u;
            }
            ++run_length;
            farthest = max(farthest, max(depth, 0.0));
        }
    }
    if (run_length != 0u) atomicAdd(bins[run_bin], run_length);
    if (sky_pixels != 0u) atomicAdd(sky, sky_pixels);
    if (farthest > 0.0) atomicMax(farthest_bits, floatBitsToUint(farthest));
    barrier();
    if (lane < MONOPLANE_DEPTH_HISTOGRAM_BINS && bins[lane] != 0u) atomicAdd(words[lane], bins[lane]);
    if (lane == 0u) {
        if (sky != 0u) atomicAdd(words[MONOPLANE_DEPTH_HISTOGRAM_SKY_WORD], sky);
        atomicMax(words[MONOPLANE_DEPTH_HISTOGRAM_FARTHEST_WORD], farthest_bits);
    }
}
