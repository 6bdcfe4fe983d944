// How a pass of several steps (SSAO, the depth pyramid, the depth histogram) asks for the
// barriers before each of its steps: the render graph compiled them from the steps' declared uses
// (renderer/plan/pass_steps.h), and the executor (renderer/executor/graph_executor.h) records them.
// No pass records a barrier or a layout transition itself.
//
// The contract: a pass of one step is begun by the executor before the pass records anything; a
// pass of several steps calls next() before each of its steps, the first included, naming the
// step it is about to record, in the order the plan declares them. Past the last step, next()
// repeats the last step when it repeats (the pyramid's reduction, once per level). The executor
// checks every call against the plan in every build type: another name, another order, a step too
// many or one left out is a programming error (common/programming_error.h) that names the pass,
// the step recorded and the step declared.
#pragma once

#include <string_view>

#include "renderer/vk/vulkan.h"

namespace monoplane::passes {

class StepSync {
  public:
    virtual ~StepSync() = default;
    // Records the barriers step `step` needs; it must be the plan's next step (see above).
    virtual void next(const vk::raii::CommandBuffer& cmd, std::string_view step) = 0;
};

}  // namespace monoplane::passes
