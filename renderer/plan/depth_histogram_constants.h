// The depth histogram's layout, declared once for C++ and GLSL (depth_histogram.h and
// renderer/passes/depth_histogram/depth_histogram.comp): bins, then the sky count and the
// farthest depth's bits.
#ifndef MONOPLANE_DEPTH_HISTOGRAM_CONSTANTS_H
#define MONOPLANE_DEPTH_HISTOGRAM_CONSTANTS_H

#define MONOPLANE_DEPTH_HISTOGRAM_BINS 64
// Words of the result buffer: the bins, the sky's pixel count, the farthest non-sky depth as
// float bits (positive floats order as their bits do, so atomicMax finds it).
#define MONOPLANE_DEPTH_HISTOGRAM_SKY_WORD 64
#define MONOPLANE_DEPTH_HISTOGRAM_FARTHEST_WORD 65
#define MONOPLANE_DEPTH_HISTOGRAM_WORDS 66

#endif
