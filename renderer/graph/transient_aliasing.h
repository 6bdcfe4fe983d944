// Memory aliasing of transient resources: which of a renderer's transient images may share one
// allocation, because in every frame plan the renderer can execute their uses never overlap.
//
// A resource's lifetime in a frame is the interval of steps from its first use to its last, over
// the passes that run (a repeated step counts once). Two resources may share memory when, in each
// plan, at most one of them is used or their intervals are disjoint; and only transient resources
// that no export reads (what the host or a headset reads after the frame must survive it; what is
// persistent must survive into the next frame). The plans differ from frame to frame (C skipped
// when nothing lies beyond m, the shadow map reused, a debug view, GPU predicates or not), so the
// caller passes the lifetimes in each of them.
//
// The assignment is a greedy interval colouring: the candidates, largest first, each join the
// first group whose members it never overlaps (and whose memory types it shares), or open a group
// of their own. Every member of a group is bound at offset 0 of the group's memory, which is as
// large as its largest member.
//
// The compile step (frame_graph.h, compile's `aliasing`) then orders each member's first use in a
// frame after the accesses of the member that held the memory before it (in the frame, or at the
// end of the last one), and transitions it from the undefined layout.
//
// When may this be called: any time; pure, no device.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "renderer/graph/frame_graph.h"

namespace monoplane::graph {

// Steps from the first use to the last, both included, counted over the steps of the passes that
// run.
struct Interval {
    std::uint32_t first = 0;
    std::uint32_t last = 0;
    bool operator==(const Interval&) const = default;
};

constexpr bool overlap(const Interval& a, const Interval& b) {
    return a.first <= b.last && b.first <= a.last;
}

// One resource as one frame uses it.
struct FrameLifetime {
    std::optional<Interval> interval;  // nullopt: no step that runs uses it
    // Transient and read by no export: its contents need not outlive its last use in the frame.
    bool may_alias = false;
    bool operator==(const FrameLifetime&) const = default;
};

// Each resource's lifetime in the frame (one per resource of the table), from the passes that
// run (GraphPass::runs) and the exports.
std::vector<FrameLifetime> frame_lifetimes(const ResourceTable& resources,
                                           const std::vector<GraphPass>& passes,
                                           const std::vector<ResourceUse>& exports);

// A resource that might share memory: what its memory must be (the device's requirements) and its
// lifetime in each of the plans (the same plans, in the same order, for every candidate; a
// default FrameLifetime where a plan does not have the resource).
struct AliasCandidate {
    std::uint64_t bytes = 0;
    std::uint32_t memory_type_bits = ~0u;
    std::vector<FrameLifetime> lifetimes;
};

struct AliasGroup {
    std::vector<std::size_t> members;      // candidate indices, the largest first
    std::uint64_t bytes = 0;               // the largest member's
    std::uint32_t memory_type_bits = ~0u;  // the types every member allows
    bool operator==(const AliasGroup&) const = default;
};

// Whether a and b may share memory: in no plan both are used with overlapping intervals, and
// neither is used in a plan where it may not alias.
bool may_share(const AliasCandidate& a, const AliasCandidate& b);

// Every candidate in exactly one group (a group of one keeps its memory to itself). Groups are in
// the order they were opened: by their first member's size, largest first, ties by index.
// Candidates with lifetimes for different numbers of plans are a programming error.
std::vector<AliasGroup> plan_aliasing(const std::vector<AliasCandidate>& candidates);

// The bytes the groups take, and the bytes the candidates would take with one allocation each.
std::uint64_t aliased_bytes(const std::vector<AliasGroup>& groups);
std::uint64_t unaliased_bytes(const std::vector<AliasCandidate>& candidates);

}  // namespace monoplane::graph
