// How many work groups a compute dispatch needs along one axis: enough groups of `group_size`
// invocations (the shader's local size) to cover `size` texels; the last group may stick out,
// and the shaders skip invocations outside the image.
#pragma once

#include <cstdint>

namespace monoplane::passes {

constexpr std::uint32_t groups_covering(std::uint32_t size, std::uint32_t group_size) {
    return (size + group_size - 1) / group_size;
}

}  // namespace monoplane::passes
