# End-to-end: `monoplane --validation render` writes the stereo pair and the statistics, for each
# scene, and refuses bad input with a non-zero exit. Arguments: MONOPLANE, OUT.
foreach(scene beams landscape spheres)
  set(dir ${OUT}/${scene})
  file(REMOVE_RECURSE ${dir})
  execute_process(
    COMMAND ${MONOPLANE} --validation render --scene ${scene} --mode stereo --hmd vive
            --width 96 --height 108 --detail test --shadow-resolution 512 --out ${dir} --json
    RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE log)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "render ${scene} failed (${rc}):\n${log}")
  endif()
  foreach(file left.png right.png stats.json)
    if(NOT EXISTS ${dir}/${file})
      message(FATAL_ERROR "render ${scene} did not write ${file}")
    endif()
  endforeach()
  # Keys other tools read (DESIGN.md section 8 and docs/benchmarks.md).
  foreach(key scene mode width height device frame_ms_median passes views primitives fragments)
    string(JSON value ERROR_VARIABLE missing GET "${json}" ${key})
    if(missing)
      message(FATAL_ERROR "render ${scene}: --json lacks '${key}': ${json}")
    endif()
  endforeach()
  string(JSON width GET "${json}" width)
  string(JSON primitives GET "${json}" views left input_primitives)
  if(NOT width EQUAL 96 OR primitives LESS 1000)
    message(FATAL_ERROR "render ${scene}: width ${width}, left input primitives ${primitives}")
  endif()
endforeach()

execute_process(COMMAND ${MONOPLANE} render --scene cubes --out ${OUT}/bad
                RESULT_VARIABLE rc ERROR_VARIABLE log)
if(rc EQUAL 0 OR NOT log MATCHES "--scene cubes")
  message(FATAL_ERROR "an unknown scene must fail with a message naming it (${rc}): ${log}")
endif()

# Hybrid with the comparison against stereo: mono.png, SSIM heat maps, the keys tools read.
set(dir ${OUT}/hybrid)
file(REMOVE_RECURSE ${dir})
execute_process(
  COMMAND ${MONOPLANE} --validation render --scene beams --mode hybrid --mono-plane 3 --hmd vive
          --width 96 --height 108 --detail test --shadow-resolution 512 --compare-stereo
          --out ${dir} --json
  RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "hybrid render failed (${rc}):\n${log}")
endif()
foreach(file left.png right.png mono.png ssim_left.png ssim_heat_right.png stats.json)
  if(NOT EXISTS ${dir}/${file})
    message(FATAL_ERROR "hybrid render did not write ${file}")
  endif()
endforeach()
string(JSON ssim GET "${json}" ssim_vs_stereo)
string(JSON skipped GET "${json}" mono_skipped)
if(NOT ssim GREATER 0.5 OR NOT ssim LESS 1.0 OR skipped)
  message(FATAL_ERROR "hybrid: ssim_vs_stereo ${ssim}, mono_skipped ${skipped}: ${json}")
endif()

# The rig as other tools read it (DESIGN.md section 8), for the Vive at m = 8: s = 0.0230 m and
# a largest offset of about 3.9 px, the paper's "4 pixels".
execute_process(COMMAND ${MONOPLANE} rig --hmd vive --mono-plane 8 --json
                RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "rig failed (${rc}):\n${log}")
endif()
foreach(key offset_behind_eyes tan_left tan_right tan_down tan_up width height near far)
  string(JSON value ERROR_VARIABLE missing GET "${json}" mono_camera ${key})
  if(missing)
    message(FATAL_ERROR "rig --json lacks mono_camera.${key}: ${json}")
  endif()
endforeach()
string(JSON s GET "${json}" mono_camera offset_behind_eyes)
string(JSON error GET "${json}" max_error_px)
string(JSON error_2d GET "${json}" max_error_px_2d)
string(JSON overlap GET "${json}" overlap)
if(s LESS 0.0229 OR s GREATER 0.0231 OR error LESS 3.8 OR error GREATER 3.95
   OR error_2d LESS error OR overlap LESS 0.36 OR overlap GREATER 0.37)
  message(FATAL_ERROR "rig: s ${s}, max_error_px ${error}, 2d ${error_2d}, overlap ${overlap}")
endif()
execute_process(COMMAND ${MONOPLANE} rig --hmd vive --fig2 ${OUT}/fig2 RESULT_VARIABLE rc
                ERROR_VARIABLE log)
if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT}/fig2/fig2.csv OR NOT EXISTS ${OUT}/fig2/fig2.svg)
  message(FATAL_ERROR "rig --fig2 failed (${rc}): ${log}")
endif()
execute_process(COMMAND ${MONOPLANE} rig --hmd vive --mono-plane 0.05 RESULT_VARIABLE rc
                ERROR_VARIABLE log)
if(rc EQUAL 0 OR NOT log MATCHES "mono_plane|mono plane")
  message(FATAL_ERROR "m <= near must fail naming the mono plane (${rc}): ${log}")
endif()
