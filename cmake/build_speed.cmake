# How the tests build fast on the 2-core CI machine (two clean builds per run: scripts/test.sh's
# and scripts/test-sanitizers.sh's). Included at the end of the top-level CMakeLists.txt, once
# every target exists and after SharedVulkanPch.cmake has given the Vulkan targets their shared
# precompiled header.
#
# Every GoogleTest executable under tests/ is compiled
#   - without optimisation (-O0): the test code is assertions and set-up, the libraries it tests
#     keep the build type's optimisation; -O0 compiles a gtest-heavy file in about 60 % of the
#     CPU time of -O2 (tests/unit/study_live_session_test.cpp: 18.7 s -> 11.9 s) and of -O1
#     under the sanitizers (21 s -> 9 s);
#   - with one shared precompiled header of GoogleTest and the standard library, built once
#     (about 9 s) by monoplane_test_pch: a further third off each file
#     (tests/e2e/study_day_cli_test.cpp at -O0: 14.8 s -> 9.7 s); the tests that compile
#     against Vulkan (about 55 files under tests/gpu, headset and window) share
#     monoplane_vk_test_pch instead, the same with Vulkan-Hpp, rather than monoplane_vk's -O2
#     header (tests/gpu/alpha_blend_test.cpp: 12.7 s -> 7.9 s; the 181 tests of those executables
#     ran 19 s longer in all, 257 s -> 277 s, against some 270 s of compiling saved).
# Measured as user + sys CPU time of single compiles (others build beside them, so wall time
# says little). ccache gains nothing on a fresh machine. The libraries and the executable are
# unity builds (monoplane_unity_build_libraries below): names in a file's anonymous namespace
# must therefore differ from those of the other files of its target.
include_guard(GLOBAL)
if(NOT COMMAND _monoplane_targets_below)
  include(${CMAKE_CURRENT_LIST_DIR}/SharedVulkanPch.cmake)
endif()

# TRUE in `out` when `target` is an executable that links GoogleTest.
function(_monoplane_is_gtest_executable target out)
  set(${out} FALSE PARENT_SCOPE)
  get_target_property(type ${target} TYPE)
  if(NOT type STREQUAL "EXECUTABLE")
    return()
  endif()
  get_target_property(libraries ${target} LINK_LIBRARIES)
  if(libraries AND ("GTest::gtest" IN_LIST libraries OR "GTest::GTest" IN_LIST libraries))
    set(${out} TRUE PARENT_SCOPE)
  endif()
endfunction()

# An object library of one empty file that owns a precompiled header of `headers` at -O0, as
# the tests that reuse it are compiled; `libraries` give it their include paths and definitions.
function(_monoplane_add_test_pch name libraries headers)
  set(source ${PROJECT_BINARY_DIR}/${name}.cpp)
  file(CONFIGURE OUTPUT ${source} CONTENT "// A precompiled header of the tests (cmake/build_speed.cmake).\n")
  add_library(${name} OBJECT ${source})
  target_link_libraries(${name} PRIVATE ${libraries})
  target_include_directories(${name} PRIVATE ${PROJECT_SOURCE_DIR})
  target_compile_options(${name} PRIVATE -O0)
  target_precompile_headers(${name} PRIVATE ${headers})
endfunction()

function(monoplane_speed_up_tests)
  if(NOT BUILD_TESTING OR NOT EXISTS ${PROJECT_SOURCE_DIR}/tests)
    return()
  endif()
  # tests/CMakeLists.txt's GTest::gtest is imported in that folder only; this scope finds its own.
  find_package(GTest QUIET)
  if(NOT TARGET GTest::gtest)
    return()
  endif()
  set(headers
    <gtest/gtest.h> <algorithm> <array> <chrono> <cmath> <cstdint> <filesystem> <fstream>
    <functional> <iostream> <map> <memory> <optional> <set> <sstream> <string> <string_view>
    <thread> <utility> <variant> <vector>)
  _monoplane_add_test_pch(monoplane_test_pch GTest::gtest "${headers}")
  # The tests that compile against Vulkan (GPU, headset and window tests) would otherwise reuse
  # monoplane_vk's -O2 header: theirs adds Vulkan-Hpp at -O0.
  if(TARGET monoplane_vk)
    _monoplane_add_test_pch(monoplane_vk_test_pch "GTest::gtest;monoplane_vk"
                            "${PROJECT_SOURCE_DIR}/renderer/vk/vulkan.h;${headers}")
  endif()

  _monoplane_targets_below(${PROJECT_SOURCE_DIR}/tests targets)
  foreach(target IN LISTS targets)
    _monoplane_is_gtest_executable(${target} is_test)
    get_target_property(reuse ${target} PRECOMPILE_HEADERS_REUSE_FROM)
    get_target_property(own ${target} PRECOMPILE_HEADERS)
    get_target_property(optimized ${target} MONOPLANE_OPTIMIZED_TEST)
    # An optimised test (monoplane_test's OPTIMIZED) cannot reuse the -O0 header either: GCC
    # refuses a precompiled header built without __OPTIMIZE__.
    if(NOT is_test OR own OR optimized)
      continue()
    elseif(NOT reuse)
      set(reuse monoplane_test_pch)
    elseif(reuse STREQUAL "monoplane_vk")
      set(reuse monoplane_vk_test_pch)
    else()
      continue()
    endif()
    target_compile_options(${target} PRIVATE -O0)
    set_target_properties(${target} PROPERTIES PRECOMPILE_HEADERS_REUSE_FROM ${reuse})
  endforeach()
endfunction()

# The project's own libraries and executables (not the tests) compile as unity builds: batches of
# up to `MONOPLANE_UNITY_BATCH` source files of one target compiled as one translation unit, so
# the headers each file of a folder shares (CLI11 in app/commands, nlohmann/json in scenes/gltf,
# SQLite and toml++ in study) are parsed and their inline functions generated once per batch
# rather than once per file. Files that define a header library's implementation
# (`#define ..._IMPLEMENTATION`) stay on their own: in a batch the header's include guard could
# already be set by a file before them. MONOPLANE_UNITY_BUILD=OFF compiles file by file, which
# rebuilds less after a one-file change.
option(MONOPLANE_UNITY_BUILD "Compile the libraries and the executable as unity builds" ON)
set(MONOPLANE_UNITY_BATCH 8 CACHE STRING "Source files per unity translation unit")

function(_monoplane_is_unity_candidate target out)
  set(${out} FALSE PARENT_SCOPE)
  get_target_property(type ${target} TYPE)
  get_target_property(imported ${target} IMPORTED)
  if(imported OR NOT type MATCHES "^(STATIC_LIBRARY|SHARED_LIBRARY|MODULE_LIBRARY|OBJECT_LIBRARY|EXECUTABLE)$")
    return()
  endif()
  get_target_property(sources ${target} SOURCES)
  list(FILTER sources INCLUDE REGEX "\\.cpp$")
  list(LENGTH sources count)
  if(count GREATER 1)
    set(${out} TRUE PARENT_SCOPE)
  endif()
endfunction()

# Marks the files of `target` that define a header library's implementation to compile alone.
function(_monoplane_keep_implementations_alone target)
  get_target_property(sources ${target} SOURCES)
  get_target_property(source_dir ${target} SOURCE_DIR)
  list(FILTER sources INCLUDE REGEX "\\.cpp$")
  foreach(source IN LISTS sources)
    cmake_path(ABSOLUTE_PATH source BASE_DIRECTORY ${source_dir} OUTPUT_VARIABLE path)
    if(NOT EXISTS ${path})
      continue()  # generated at build time: no implementation defines in those
    endif()
    file(STRINGS ${path} implementation REGEX "^#define [A-Z_]+_IMPLEMENTATION")
    if(implementation)
      set_source_files_properties(${path} TARGET_DIRECTORY ${target}
                                  PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
    endif()
  endforeach()
endfunction()

function(monoplane_unity_build_libraries)
  if(NOT MONOPLANE_UNITY_BUILD)
    return()
  endif()
  get_property(top_folders DIRECTORY ${PROJECT_SOURCE_DIR} PROPERTY SUBDIRECTORIES)
  list(REMOVE_ITEM top_folders "${PROJECT_SOURCE_DIR}/tests")
  foreach(folder IN LISTS top_folders)
    _monoplane_targets_below(${folder} targets)
    foreach(target IN LISTS targets)
      _monoplane_is_unity_candidate(${target} candidate)
      if(candidate)
        set_target_properties(${target} PROPERTIES UNITY_BUILD ON
                                                   UNITY_BUILD_BATCH_SIZE ${MONOPLANE_UNITY_BATCH})
        _monoplane_keep_implementations_alone(${target})
      endif()
    endforeach()
  endforeach()
endfunction()

monoplane_speed_up_tests()
monoplane_unity_build_libraries()
