// How a pass of several steps (SSAO, the depth pyramid, the depth histogram) asks for the
// barriers before each of its steps: the render graph compiled them from the steps' declared uses
// (renderer/plan/pass_steps.h), and the executor (renderer/executor/graph_executor.h) records them.
// No pass records a barrier or a layout transition itself.
//
// The contract: a pass of one step is begun by the executor before the pass records anything; a
// pass of several steps calls next() before each of its steps, the first included, in the order
// the plan declares them. Past the last step, next() repeats the last step when it repeats (the
// pyramid's reduction, once per level); anything else is a programming error (asserted).
#pragma once

#include "renderer/vk/vulkan.h"

namespace monoplane::passes {

class StepSync {
  public:
    virtual ~StepSync() = default;
    // Records the barriers the next step needs.
    virtual void next(const vk::raii::CommandBuffer& cmd) = 0;
};

}  // namespace monoplane::passes
