// GPU tests of single passes under the render graph: a hand-made frame plan of the passes a test
// records, each resource bound to the test's own images, and record(), which runs the graph's
// executor (renderer/executor/graph_executor.h) around the passes' recordings. The passes record no
// barriers of their own, so a test that called them bare would sample images in the wrong layout;
// through the harness it exercises the barriers and transitions the renderer's frames get.
//
// Steps come from renderer/plan/pass_steps.h (the uses the plan declares for the pass) or from a
// graph::StepBuilder over resources(). Images the test filled before the frame (uploads, clears)
// are declared with input() before any step names them, and must be finished (submitted and
// waited for) with their ImageRange's initial_layout saying the layout they were left in: the
// executor starts from that layout, with no earlier access of the frame to wait for.
//
// When may this be called: from the test's thread; record() inside a command buffer the test
// submits and waits for, after every pass was added and every image a step uses was bound.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "renderer/executor/graph_executor.h"
#include "renderer/graph/frame_graph.h"
#include "renderer/passes/shared/step_sync.h"
#include "renderer/plan/frame_plan.h"
#include "renderer/plan/pass_steps.h"
#include "renderer/vk/image.h"

namespace monoplane::testing {

class GraphHarness {
  public:
    // Records one pass's commands: sync.next(cmd) before each step when the pass has several
    // (passes::StepSync's contract); a pass of one step is begun before this is called.
    using Recorder = std::function<void(const vk::raii::CommandBuffer&, passes::StepSync&)>;

    GraphHarness() = default;
    // resources() refers to the plan inside: neither may move.
    GraphHarness(const GraphHarness&) = delete;
    GraphHarness& operator=(const GraphHarness&) = delete;

    // The plan's resources by key, created on first use, for building steps.
    plan::PlanResources& resources() { return resources_; }
    const plan::FramePlan& plan() const { return plan_; }

    // An image the test filled before the frame. Persistent, because the graph refuses a read of
    // a transient resource no earlier step of the frame wrote. A programming error when a step
    // already named it (it would be transient by then).
    graph::ImageHandle input(plan::ViewId view, plan::ImageRole role);

    // The device images a resource is this frame (several for SSAO's scratch images).
    void bind(graph::ImageHandle image, std::vector<vk_core::ImageRange> images);
    void bind(graph::ImageHandle image, const vk_core::Image& device_image) {
        bind(image, std::vector{device_image.range()});
    }

    // A pass, recorded after those added before it.
    void add_pass(plan::PassKind kind, std::string name, std::vector<graph::Step> steps,
                  Recorder record);
    // A read-back pass of one step: each image copied (a transfer source) into its buffer, which
    // the host reads after the submission (an export, so the frame ends with the barrier that
    // makes the copies visible to the host).
    void add_readback(const std::vector<std::pair<graph::ImageHandle, graph::BufferHandle>>& copies,
                      Recorder record);
    // A buffer the host reads after the submission.
    void host_reads(graph::BufferHandle buffer);

    // Records every pass in order with the graph's barriers (begin_frame, begin_pass and end_pass
    // around each, end_frame). Called again, it records the next frame from the states this one
    // left. A programming error for an image a step uses that was never bound, as the graph's
    // and the executor's refusals of a plan the passes do not follow are.
    void record(const vk::raii::CommandBuffer& cmd);

  private:
    std::vector<executor::BoundResource> bindings() const;

    plan::FramePlan plan_;
    plan::PlanResources resources_{plan_};
    std::map<std::uint16_t, std::vector<vk_core::ImageRange>> bound_;
    std::vector<Recorder> recorders_;  // one per plan_.passes
    executor::GraphExecutor executor_;
};

}  // namespace monoplane::testing
