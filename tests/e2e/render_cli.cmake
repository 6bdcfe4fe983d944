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
