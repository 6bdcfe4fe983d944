#include "renderer/graph/transient_aliasing.h"

#include <algorithm>
#include <numeric>
#include <string>

#include "common/programming_error.h"

namespace monoplane::graph {

std::vector<FrameLifetime> frame_lifetimes(const ResourceTable& resources,
                                           const std::vector<GraphPass>& passes,
                                           const std::vector<ResourceUse>& exports) {
    std::vector<FrameLifetime> lifetimes(resources.size());
    for (std::size_t r = 0; r < resources.size(); ++r) {
        lifetimes[r].may_alias =
            resources[static_cast<std::uint16_t>(r)].lifetime == Lifetime::kTransient;
    }
    for (const ResourceUse& use : exports) lifetimes.at(use.resource).may_alias = false;
    std::uint32_t step_index = 0;
    for (const GraphPass& pass : passes) {
        if (!pass.runs || pass.steps == nullptr) continue;
        for (const Step& step : *pass.steps) {
            for (const ResourceUse& use : step.uses) {
                std::optional<Interval>& interval = lifetimes.at(use.resource).interval;
                if (!interval) interval = Interval{step_index, step_index};
                interval->last = step_index;
            }
            ++step_index;
        }
    }
    return lifetimes;
}

bool may_share(const AliasCandidate& a, const AliasCandidate& b) {
    if (a.lifetimes.size() != b.lifetimes.size()) {
        programming_error("aliasing: candidates with lifetimes in " +
                          std::to_string(a.lifetimes.size()) + " and " +
                          std::to_string(b.lifetimes.size()) + " plans");
    }
    for (std::size_t p = 0; p < a.lifetimes.size(); ++p) {
        const FrameLifetime& x = a.lifetimes[p];
        const FrameLifetime& y = b.lifetimes[p];
        if ((x.interval && !x.may_alias) || (y.interval && !y.may_alias)) return false;
        if (x.interval && y.interval && overlap(*x.interval, *y.interval)) return false;
    }
    return true;
}

std::vector<AliasGroup> plan_aliasing(const std::vector<AliasCandidate>& candidates) {
    std::vector<std::size_t> order(candidates.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
        return candidates[a].bytes > candidates[b].bytes;
    });
    std::vector<AliasGroup> groups;
    for (std::size_t c : order) {
        const AliasCandidate& candidate = candidates[c];
        AliasGroup* home = nullptr;
        for (AliasGroup& group : groups) {
            if ((group.memory_type_bits & candidate.memory_type_bits) == 0) continue;
            const bool fits = std::all_of(
                group.members.begin(), group.members.end(),
                [&](std::size_t member) { return may_share(candidates[member], candidate); });
            if (fits) {
                home = &group;
                break;
            }
        }
        if (home == nullptr) {
            // Checked against itself too: mismatched plan counts are refused even for one.
            (void)may_share(candidate, candidates[order.front()]);
            home = &groups.emplace_back();
        }
        home->members.push_back(c);
        home->bytes = std::max(home->bytes, candidate.bytes);
        home->memory_type_bits &= candidate.memory_type_bits;
    }
    return groups;
}

std::uint64_t aliased_bytes(const std::vector<AliasGroup>& groups) {
    std::uint64_t bytes = 0;
    for (const AliasGroup& group : groups) bytes += group.bytes;
    return bytes;
}

std::uint64_t unaliased_bytes(const std::vector<AliasCandidate>& candidates) {
    std::uint64_t bytes = 0;
    for (const AliasCandidate& candidate : candidates) bytes += candidate.bytes;
    return bytes;
}

}  // namespace monoplane::graph
