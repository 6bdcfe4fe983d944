# The foundation (rig/) depends on nothing of the project but common/; scenes/ and hmd/ build on it,
# never on the renderer. Fails if a Vulkan-free folder includes Vulkan, the GPU side of the renderer, or the app;
# study/ and analysis/ may not include renderer headers at all; analysis/ reads plain rows and
# knows nothing of the study library (the app converts the database into rows).
set(violations "")
function(check folder pattern)
  file(GLOB_RECURSE files ${SOURCE_DIR}/${folder}/*.h ${SOURCE_DIR}/${folder}/*.cpp)
  foreach(f ${files})
    file(STRINGS ${f} lines REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"](${pattern})")
    foreach(line ${lines})
      file(RELATIVE_PATH rel ${SOURCE_DIR} ${f})
      list(APPEND violations "${rel}: ${line}")
    endforeach()
  endforeach()
  set(violations ${violations} PARENT_SCOPE)
endfunction()
set(gpu "vulkan/|GLFW/|openxr/|renderer/vk/|renderer/passes/|renderer/modes/|renderer/profile/|app/")
check(rig "${gpu}|renderer/|scenes/|hmd/|study/|analysis/")
check(scenes "${gpu}|renderer/|study/|analysis/|hmd/")
check(hmd "${gpu}|renderer/|scenes/|study/|analysis/")
# simxr, a runtime any OpenXR application loads, knows the rig and the profiles, not monoplane.
check(simxr "renderer/|app/|GLFW/|scenes/|study/|analysis/")
check(renderer/plan "${gpu}|scenes/|hmd/|study/|analysis/")
check(renderer/quality "${gpu}|scenes/|hmd/|study/|analysis/")
check(charts "${gpu}|renderer/|scenes/|hmd/|study/|analysis/")
check(study "${gpu}|renderer/|analysis/|hmd/|scenes/")
# text/ (fonts, line breaking, glyph coverage) serves the study's checks and the headset alike.
check(text "${gpu}|renderer/|scenes/|hmd/|study/|analysis/")
check(analysis "${gpu}|renderer/|hmd/|scenes/|study/")
if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "dependency rule broken (docs/architecture.md):\n  ${text}")
endif()
message(STATUS "dependency rule holds")
