// The built-in HMD profiles' TOML text, compiled into the library from hmd/profiles/*.toml by
// hmd/embed_profiles.cmake. Internal to monoplane_hmd: users go through load_hmd_profile().
#pragma once

#include <span>
#include <string_view>

namespace monoplane::hmd {

struct BuiltinProfile {
    std::string_view name;  // e.g. "vive": the file name without .toml
    std::string_view toml_text;
};

// May be called at any time, including during static initialisation (constant data).
std::span<const BuiltinProfile> builtin_profiles();

}  // namespace monoplane::hmd
