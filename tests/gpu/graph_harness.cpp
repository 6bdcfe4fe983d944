#include "tests/gpu/graph_harness.h"

#include "common/programming_error.h"

namespace monoplane::testing {

graph::ImageHandle GraphHarness::input(plan::ViewId view, plan::ImageRole role) {
    // The key PlanResources::image looks up, so that steps built later find this handle.
    const plan::ResourceKey key{view, false, role, plan::BufferRole::kDrawLists};
    const std::string name = plan::resource_name(key);
    if (plan_.handle(key)) {
        programming_error("graph harness: " + name + " declared an input after a step used it");
    }
    const graph::ImageHandle image = plan_.resources.image(name, graph::Lifetime::kPersistent);
    plan_.keys.push_back(key);
    // Should PlanResources ever key images differently, steps would get a second, transient
    // handle and the input would silently go unused.
    if (resources_.image(view, role) != image) {
        programming_error("graph harness: PlanResources does not find the input " + name);
    }
    return image;
}

void GraphHarness::bind(graph::ImageHandle image, std::vector<vk_core::ImageRange> images) {
    bound_[image.index] = std::move(images);
}

void GraphHarness::add_pass(plan::PassKind kind, std::string name, std::vector<graph::Step> steps,
                            Recorder record) {
    plan::PlannedPass& pass = plan_.passes.emplace_back();
    pass.kind = kind;
    pass.name = std::move(name);
    pass.steps = std::move(steps);
    recorders_.push_back(std::move(record));
}

void GraphHarness::add_readback(
    const std::vector<std::pair<graph::ImageHandle, graph::BufferHandle>>& copies,
    Recorder record) {
    std::vector<graph::Step> steps(1);
    steps.front().name = "copy";
    graph::StepBuilder copy(steps.front());
    for (const auto& [image, buffer] : copies) {
        copy.use(image, graph::Use::kTransferSrc).use(buffer, graph::Use::kTransferDst);
        host_reads(buffer);
    }
    add_pass(plan::PassKind::kReadback, "readback", std::move(steps), std::move(record));
}

void GraphHarness::host_reads(graph::BufferHandle buffer) {
    plan_.exports.push_back({buffer.index, graph::Use::kHostRead});
}

std::vector<executor::BoundResource> GraphHarness::bindings() const {
    std::vector<executor::BoundResource> bindings(plan_.resources.size());
    for (const auto& [index, images] : bound_) bindings.at(index).images = images;
    // An unbound image would get no barriers at all: the pass would then run on whatever layout
    // the image happens to be in, and the test would check nothing of the graph.
    const auto check = [&](std::uint16_t resource) {
        if (plan_.resources[resource].kind == graph::ResourceKind::kImage &&
            bindings[resource].images.empty()) {
            programming_error("graph harness: " + plan_.resources[resource].name +
                              " is used but not bound");
        }
    };
    for (const plan::PlannedPass& pass : plan_.passes) {
        for (const graph::Step& step : pass.steps) {
            for (const graph::ResourceUse& use : step.uses) check(use.resource);
        }
    }
    for (const graph::ResourceUse& use : plan_.exports) check(use.resource);
    return bindings;
}

void GraphHarness::record(const vk::raii::CommandBuffer& cmd) {
    executor_.plan_changed();  // the harness's plan may have gained passes since the last record
    executor_.begin_frame(plan_, bindings());
    for (std::size_t p = 0; p < plan_.passes.size(); ++p) {
        passes::StepSync& sync = executor_.begin_pass(cmd, p);
        recorders_[p](cmd, sync);
        executor_.end_pass();
    }
    executor_.end_frame(cmd);
}

}  // namespace monoplane::testing
