#include "renderer/graph/frame_graph.h"

#include "common/programming_error.h"

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
            programming_error(where + ": " + use_name(use.use) + " is not a use of " +
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
            programming_error(where + " uses " + desc.name + " in two layouts (" +
                              layout_name(same->scope.layout) + ", " + layout_name(scope.layout) +
                              ")");
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

    // The memory is taken over from a resource in state `before`: this one's contents and layout
    // are gone, and its first use waits for that one's accesses.
    void take_over(const ResourceState& before) {
        state_ = ResourceState{Layout::kUndefined, before.write_stages, before.write_access,
                               Stage::kNone,       Access::kNone,       before.read_stages};
    }

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
    Compiler(const ResourceTable& resources, const std::vector<ResourceState>& initial,
             const Aliasing& aliasing)
        : resources_(resources),
          written_(resources.size(), false),
          used_(resources.size(), false),
          aliasing_(aliasing) {
        if (initial.size() != resources.size()) {
            programming_error("graph: " + std::to_string(initial.size()) + " initial states for " +
                              std::to_string(resources.size()) + " resources");
        }
        for (std::size_t r = 0; r < resources.size(); ++r) {
            trackers_.emplace_back(
                initial[r], resources[static_cast<std::uint16_t>(r)].kind == ResourceKind::kImage);
        }
        check_aliasing();
        for (const MemoryHolder& holder : aliasing_.initial) holders_.push_back(holder.resource);
    }

    std::vector<Barrier> step(const std::string& where, const std::vector<ResourceUse>& uses) {
        std::vector<Barrier> barriers;
        for (const MergedUse& use : merge_uses(resources_, where, uses)) {
            check_produced(where, use);
            const bool takes_over = take_memory(where, use.resource);
            if (auto barrier = trackers_[use.resource].apply(use)) {
                barrier->resource = use.resource;
                barrier->aliasing = takes_over;
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

    const std::vector<std::int32_t>& holders() const { return holders_; }

    // What shares memory must be neither read after the frame nor carried to the next.
    void check_not_shared(const std::vector<ResourceUse>& exports) const {
        for (const ResourceUse& use : exports) {
            if (memory_of(use.resource) >= 0) {
                programming_error("graph: " + resources_[use.resource].name +
                                  " is exported and shares memory");
            }
        }
    }

  private:
    std::int32_t memory_of(std::uint16_t resource) const {
        return aliasing_.memory.empty() ? -1 : aliasing_.memory[resource];
    }

    void check_aliasing() const {
        if (aliasing_.memory.empty()) return;
        if (aliasing_.memory.size() != resources_.size()) {
            programming_error("graph: aliasing names the memory of " +
                              std::to_string(aliasing_.memory.size()) + " of " +
                              std::to_string(resources_.size()) + " resources");
        }
        for (std::size_t r = 0; r < resources_.size(); ++r) {
            const std::int32_t memory = aliasing_.memory[r];
            if (memory < 0) continue;
            const ResourceDesc& desc = resources_[static_cast<std::uint16_t>(r)];
            if (static_cast<std::size_t>(memory) >= aliasing_.initial.size()) {
                programming_error("graph: " + desc.name + " is bound to memory " +
                                  std::to_string(memory) + " of " +
                                  std::to_string(aliasing_.initial.size()));
            }
            if (desc.lifetime != Lifetime::kTransient) {
                programming_error("graph: " + desc.name + " is persistent and shares memory");
            }
        }
    }

    // Before a use of `resource`: whether the use takes its memory over from another resource
    // that accessed it (what its barrier must wait for). Its first use in the frame takes over
    // when another one used the memory last; a later use finds itself the holder unless the uses
    // of two resources sharing memory interleave.
    bool take_memory(const std::string& where, std::uint16_t resource) {
        const std::int32_t memory = memory_of(resource);
        if (memory < 0) return false;
        std::int32_t& holder = holders_[static_cast<std::size_t>(memory)];
        const bool first_use = !used_[resource];
        used_[resource] = true;
        if (holder == resource) return false;
        if (!first_use) {
            programming_error(where + " uses " + resources_[resource].name + " after " +
                              resources_[static_cast<std::uint16_t>(holder)].name +
                              ", which shares its memory, took it over");
        }
        const ResourceState before =
            holder >= 0 ? trackers_[static_cast<std::size_t>(holder)].state()
                        : aliasing_.initial[static_cast<std::size_t>(memory)].state;
        trackers_[resource].take_over(before);
        holder = resource;
        return any(before.write_stages) || any(before.read_stages);
    }

    // A transient resource holds nothing until a step of this frame writes it.
    void check_produced(const std::string& where, const MergedUse& use) const {
        const ResourceDesc& desc = resources_[use.resource];
        if (desc.lifetime == Lifetime::kTransient && !written_[use.resource] && !use.scope.writes) {
            programming_error(where + " reads " + desc.name +
                              ", which no earlier pass of the frame writes");
        }
    }

    const ResourceTable& resources_;
    std::vector<ResourceTracker> trackers_;
    std::vector<bool> written_;
    std::vector<bool> used_;
    const Aliasing& aliasing_;
    std::vector<std::int32_t> holders_;  // per shared memory: the resource that used it last
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
    if (b.aliasing) text += " (takes over shared memory)";
    return text;
}

CompiledFrame compile(const ResourceTable& resources, const std::vector<GraphPass>& passes,
                      const std::vector<ResourceUse>& exports,
                      const std::vector<ResourceState>& initial_states, const Aliasing& aliasing) {
    Compiler compiler(resources, initial_states, aliasing);
    compiler.check_not_shared(exports);
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
    frame.final_holders = compiler.holders();
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
