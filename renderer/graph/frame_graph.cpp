#include "renderer/graph/frame_graph.h"

#include <stdexcept>

namespace monoplane::graph {
namespace {

// One resource's uses within one step, merged: a step may sample an image in two shaders, or
// read and write a buffer.
struct MergedUse {
    std::uint16_t resource = 0;
    UseScope scope;
    bool discards = false;  // every use of the step overwrites without reading (colour writes)
};

bool buffer_only(Use use) {
    return use == Use::kIndirectArgs || use == Use::kConditional || use == Use::kHostRead;
}

bool image_only(Use use) {
    switch (use) {
        case Use::kStorageRead:
        case Use::kStorageWrite:
        case Use::kTransferSrc:
        case Use::kTransferDst:
            return false;
        default:
            return !buffer_only(use);
    }
}

std::vector<MergedUse> merge_uses(const ResourceTable& resources, const std::string& where,
                                  const std::vector<ResourceUse>& uses) {
    std::vector<MergedUse> merged;
    for (const ResourceUse& use : uses) {
        const ResourceDesc& desc = resources[use.resource];
        const bool image = desc.kind == ResourceKind::kImage;
        if ((image && buffer_only(use.use)) || (!image && image_only(use.use))) {
            throw std::invalid_argument(where + ": " + use_name(use.use) + " is not a use of " +
                                        (image ? "an image (" : "a buffer (") + desc.name + ")");
        }
        UseScope scope = use_scope(use.use);
        if (!image) scope.layout = Layout::kUndefined;
        MergedUse* same = nullptr;
        for (MergedUse& m : merged) {
            if (m.resource == use.resource) same = &m;
        }
        if (same == nullptr) {
            merged.push_back({use.resource, scope, use.use == Use::kColorWrite});
            continue;
        }
        if (same->scope.layout != scope.layout) {
            throw std::invalid_argument(where + " uses " + desc.name + " in two layouts (" +
                                        layout_name(same->scope.layout) + ", " +
                                        layout_name(scope.layout) + ")");
        }
        same->scope.stages |= scope.stages;
        same->scope.access |= scope.access;
        same->scope.writes = same->scope.writes || scope.writes;
        same->discards = same->discards && use.use == Use::kColorWrite;
    }
    return merged;
}

// The state machine of one resource: the barrier a use needs, and the state after it.
class ResourceTracker {
  public:
    ResourceTracker(ResourceState state, bool is_image) : state_(state), image_(is_image) {}

    std::optional<Barrier> apply(const MergedUse& use) {
        const UseScope& u = use.scope;
        const bool relayout = image_ && state_.layout != u.layout;
        std::optional<Barrier> barrier;
        if (u.writes) {
            if (relayout || any(state_.write_stages) || any(state_.read_stages)) {
                barrier = make(state_.write_stages | state_.read_stages, state_.write_access, u,
                               use.discards);
            }
            state_ = ResourceState{u.layout, u.stages, u.access & kWriteAccesses};
            return barrier;
        }
        if (relayout) {
            barrier = make(state_.write_stages | state_.read_stages, state_.write_access, u, false);
            // The transition is a write the reader's scope has seen; later readers chain after it.
            state_ = ResourceState{u.layout, u.stages, Access::kNone, u.stages, u.access, u.stages};
            return barrier;
        }
        const bool visible =
            covers(state_.visible_stages, u.stages) && covers(state_.visible_access, u.access);
        if (any(state_.write_stages) && !visible) {
            barrier = make(state_.write_stages, state_.write_access, u, false);
            state_.visible_stages |= u.stages;
            state_.visible_access |= u.access;
        }
        state_.read_stages |= u.stages;
        return barrier;
    }

    const ResourceState& state() const { return state_; }

  private:
    Barrier make(Stage src, Access src_access, const UseScope& u, bool discards) const {
        Barrier b;
        b.src_stages = src;
        b.src_access = src_access;
        b.dst_stages = u.stages;
        b.dst_access = u.access;
        if (image_) {
            b.old_layout = discards ? Layout::kUndefined : state_.layout;
            b.new_layout = u.layout;
        }
        return b;
    }

    ResourceState state_;
    bool image_;
};

class Compiler {
  public:
    Compiler(const ResourceTable& resources, const std::vector<ResourceState>& initial)
        : resources_(resources), written_(resources.size(), false) {
        if (initial.size() != resources.size()) {
            throw std::invalid_argument("graph: " + std::to_string(initial.size()) +
                                        " initial states for " + std::to_string(resources.size()) +
                                        " resources");
        }
        for (std::size_t r = 0; r < resources.size(); ++r) {
            trackers_.emplace_back(
                initial[r], resources[static_cast<std::uint16_t>(r)].kind == ResourceKind::kImage);
        }
    }

    std::vector<Barrier> step(const std::string& where, const std::vector<ResourceUse>& uses) {
        std::vector<Barrier> barriers;
        for (const MergedUse& use : merge_uses(resources_, where, uses)) {
            check_produced(where, use);
            if (auto barrier = trackers_[use.resource].apply(use)) {
                barrier->resource = use.resource;
                barriers.push_back(*barrier);
            }
            if (use.scope.writes) written_[use.resource] = true;
        }
        return barriers;
    }

    std::vector<ResourceState> final_states() const {
        std::vector<ResourceState> states;
        for (const ResourceTracker& tracker : trackers_) states.push_back(tracker.state());
        return states;
    }

  private:
    // A transient resource holds nothing until a step of this frame writes it.
    void check_produced(const std::string& where, const MergedUse& use) const {
        const ResourceDesc& desc = resources_[use.resource];
        if (desc.lifetime == Lifetime::kTransient && !written_[use.resource] && !use.scope.writes) {
            throw std::invalid_argument(where + " reads " + desc.name +
                                        ", which no earlier pass of the frame writes");
        }
    }

    const ResourceTable& resources_;
    std::vector<ResourceTracker> trackers_;
    std::vector<bool> written_;
};

}  // namespace

ImageHandle ResourceTable::image(std::string name, Lifetime lifetime) {
    resources_.push_back({std::move(name), ResourceKind::kImage, lifetime});
    return ImageHandle{static_cast<std::uint16_t>(resources_.size() - 1)};
}

BufferHandle ResourceTable::buffer(std::string name, Lifetime lifetime) {
    resources_.push_back({std::move(name), ResourceKind::kBuffer, lifetime});
    return BufferHandle{static_cast<std::uint16_t>(resources_.size() - 1)};
}

std::optional<std::uint16_t> ResourceTable::find(const std::string& name) const {
    for (std::size_t r = 0; r < resources_.size(); ++r) {
        if (resources_[r].name == name) return static_cast<std::uint16_t>(r);
    }
    return std::nullopt;
}

StepBuilder& StepBuilder::use(ImageHandle image, Use use) {
    step_.uses.push_back({image.index, use});
    return *this;
}

StepBuilder& StepBuilder::use(BufferHandle buffer, Use use) {
    step_.uses.push_back({buffer.index, use});
    return *this;
}

std::string describe(const Barrier& b, const ResourceTable& resources) {
    std::string text = resources[b.resource].name + ": " + stage_names(b.src_stages) + "/" +
                       access_names(b.src_access) + " -> " + stage_names(b.dst_stages) + "/" +
                       access_names(b.dst_access);
    if (resources[b.resource].kind == ResourceKind::kImage) {
        text += ", " + layout_name(b.old_layout) + " -> " + layout_name(b.new_layout);
    }
    return text;
}

CompiledFrame compile(const ResourceTable& resources, const std::vector<GraphPass>& passes,
                      const std::vector<ResourceUse>& exports,
                      const std::vector<ResourceState>& initial_states) {
    Compiler compiler(resources, initial_states);
    CompiledFrame frame;
    for (const GraphPass& pass : passes) {
        auto& per_step = frame.steps.emplace_back();
        if (!pass.runs || pass.steps == nullptr) continue;
        for (const Step& step : *pass.steps) {
            const std::string where = pass.name + "/" + step.name;
            CompiledStep& compiled = per_step.emplace_back();
            compiled.before = compiler.step(where, step.uses);
            if (step.repeats) compiled.between_repeats = compiler.step(where, step.uses);
        }
    }
    frame.final_barriers = compiler.step("the frame's exports", exports);
    frame.final_states = compiler.final_states();
    return frame;
}

std::vector<bool> needed_passes(const ResourceTable& resources,
                                const std::vector<GraphPass>& passes,
                                const std::vector<ResourceUse>& exports) {
    std::vector<bool> needed_resource(resources.size(), false);
    for (std::size_t r = 0; r < resources.size(); ++r) {
        needed_resource[r] =
            resources[static_cast<std::uint16_t>(r)].lifetime == Lifetime::kPersistent;
    }
    for (const ResourceUse& use : exports) needed_resource[use.resource] = true;
    std::vector<bool> needed(passes.size(), false);
    for (std::size_t p = passes.size(); p-- > 0;) {
        const GraphPass& pass = passes[p];
        if (!pass.runs || pass.steps == nullptr) continue;
        for (const Step& step : *pass.steps) {
            for (const ResourceUse& use : step.uses) {
                if (use_scope(use.use).writes && needed_resource[use.resource]) needed[p] = true;
            }
        }
        if (!needed[p]) continue;
        // Walk the pass's steps backwards: a plain colour write ends the need for what came
        // before; every read (read-modify-write included) starts one.
        for (auto step = pass.steps->rbegin(); step != pass.steps->rend(); ++step) {
            for (const ResourceUse& use : step->uses) {
                if (use.use == Use::kColorWrite) needed_resource[use.resource] = false;
            }
            for (const ResourceUse& use : step->uses) {
                if (use.use != Use::kColorWrite) needed_resource[use.resource] = true;
            }
        }
    }
    return needed;
}

}  // namespace monoplane::graph
