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
  # Keys other tools read (docs/benchmarks.md).
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

# --depth-profile (docs/scenes.md): per fink2019 mono plane the fractions of the left eye's
# triangles and pixels nearer than it, non-decreasing in m and within [0, 1]; it needs --json.
set(dir ${OUT}/depth_profile)
file(REMOVE_RECURSE ${dir})
execute_process(
  COMMAND ${MONOPLANE} --validation render --scene spheres --detail test --width 96 --height 108
          --shadow-resolution 512 --json --depth-profile --out ${dir}
  RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "render --depth-profile failed (${rc}):\n${log}")
endif()
foreach(key mono_planes primitives_nearer pixels_nearer)
  string(JSON count ERROR_VARIABLE missing LENGTH "${json}" depth_profile ${key})
  if(missing OR NOT count EQUAL 10)
    message(FATAL_ERROR "render --depth-profile: depth_profile.${key} is not 10 long: ${json}")
  endif()
endforeach()
string(JSON last GET "${json}" depth_profile mono_planes 9)
if(NOT last EQUAL 39.5)
  message(FATAL_ERROR "render --depth-profile: the last mono plane is ${last}, not 39.5")
endif()
foreach(key primitives_nearer pixels_nearer)
  set(previous 0)
  foreach(i RANGE 9)
    string(JSON f GET "${json}" depth_profile ${key} ${i})
    if(f LESS previous OR f GREATER 1)
      message(FATAL_ERROR "render --depth-profile: ${key}[${i}] = ${f} after ${previous}")
    endif()
    set(previous ${f})
  endforeach()
endforeach()
execute_process(COMMAND ${MONOPLANE} render --scene spheres --depth-profile --out ${OUT}/bad
                RESULT_VARIABLE rc ERROR_VARIABLE log)
if(rc EQUAL 0 OR NOT log MATCHES "--depth-profile needs --json")
  message(FATAL_ERROR "--depth-profile without --json must fail naming it (${rc}): ${log}")
endif()

# Instanced stereo (docs/single-pass-stereo.md): both eyes in one pass, the stereo pair written,
# two passes' images within 1/255.
set(dir ${OUT}/instanced)
file(REMOVE_RECURSE ${dir})
execute_process(
  COMMAND ${MONOPLANE} --validation render --scene spheres --mode stereo-instanced --hmd vive
          --width 96 --height 108 --detail test --shadow-resolution 512 --compare-stereo
          --out ${dir} --json
  RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "stereo-instanced render failed (${rc}):\n${log}")
endif()
foreach(file left.png right.png stats.json)
  if(NOT EXISTS ${dir}/${file})
    message(FATAL_ERROR "stereo-instanced render did not write ${file}")
  endif()
endforeach()
string(JSON mode GET "${json}" mode)
string(JSON pass GET "${json}" stereo_pass)
string(JSON difference GET "${json}" max_channel_difference_vs_stereo)
if(NOT mode STREQUAL "stereo-instanced" OR NOT pass STREQUAL "instanced" OR difference GREATER 1)
  message(FATAL_ERROR "stereo-instanced: mode ${mode}, stereo_pass ${pass}, max channel "
                      "difference ${difference}: ${json}")
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
# The executed frame plan (docs/architecture.md): hybrid at m = 3 with occlusion culling runs C and
# both composites; the mono tone mapping runs because the images are read back.
string(JSON passes LENGTH "${json}" plan)
set(executed "")
math(EXPR last "${passes} - 1")
foreach(i RANGE ${last})
  string(JSON name GET "${json}" plan ${i} pass)
  string(JSON why GET "${json}" plan ${i} skipped)
  if(why STREQUAL "null" OR why STREQUAL "")
    list(APPEND executed ${name})
  endif()
endforeach()
set(expected culling shadow left.forward right.forward depth_pyramid occlusion_culling mono.forward
    left.composite right.composite left.tonemap right.tonemap mono.tonemap readback)
if(NOT executed STREQUAL expected)
  message(FATAL_ERROR "hybrid plan: executed '${executed}', expected '${expected}': ${json}")
endif()

# The rig as other tools read it, for the Vive at m = 8: s = 0.0230 m and
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
# The overlap covers surfaces down to 1 degree to the rays: one C texel on the plane,
# (2.80 / 1422) * 8.023 m, over tan(1 degree) = 0.905 m (docs/hybrid.md); --grazing-deg 0 leaves
# the paper's k s m = 2 * 0.02299 * 8 = 0.368 m.
if(s LESS 0.0229 OR s GREATER 0.0231 OR error LESS 3.8 OR error GREATER 3.95
   OR error_2d LESS error OR overlap LESS 0.89 OR overlap GREATER 0.92)
  message(FATAL_ERROR "rig: s ${s}, max_error_px ${error}, 2d ${error_2d}, overlap ${overlap}")
endif()
execute_process(COMMAND ${MONOPLANE} rig --hmd vive --mono-plane 8 --grazing-deg 0 --json
                RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE log)
string(JSON overlap GET "${json}" overlap)
if(NOT rc EQUAL 0 OR overlap LESS 0.36 OR overlap GREATER 0.37)
  message(FATAL_ERROR "rig --grazing-deg 0: overlap ${overlap} (${rc}): ${log}")
endif()
# A canted headset: the cants are reported, in degrees.
execute_process(COMMAND ${MONOPLANE} rig --hmd canted-15 --mono-plane 8 --json
                RESULT_VARIABLE rc OUTPUT_VARIABLE json ERROR_VARIABLE log)
string(JSON left_cant GET "${json}" eyes left_cant_deg)
string(JSON right_cant GET "${json}" eyes right_cant_deg)
if(NOT rc EQUAL 0 OR NOT left_cant EQUAL 15 OR NOT right_cant EQUAL -15)
  message(FATAL_ERROR "rig --hmd canted-15: cants ${left_cant} ${right_cant} (${rc}): ${log}")
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

# The study from the command line: a session with the simulated observer, its export in both
# formats, a duplicate participant refused, a completed session not resumable, a bad protocol.
set(db ${OUT}/study.sqlite)
# A new database is a new study: its exports do not replace an earlier run's without --force.
file(REMOVE ${db} ${db}-wal ${db}-shm ${db}-holds ${OUT}/study.csv ${OUT}/study.csv.source
     ${OUT}/study.json ${OUT}/study.json.source)
execute_process(COMMAND ${MONOPLANE} study run --protocol ${SOURCE}/protocols/demo.toml
                        --participant E2E1 --db ${db} --headset none --seed 11
                RESULT_VARIABLE rc ERROR_VARIABLE log)
if(NOT rc EQUAL 0 OR NOT log MATCHES "data trials: 6 of 6 decided; practice: 1 of 1")
  message(FATAL_ERROR "study run failed (${rc}): ${log}")
endif()
foreach(format csv json)
  execute_process(COMMAND ${MONOPLANE} study export --db ${db} --format ${format}
                          --out ${OUT}/study.${format} RESULT_VARIABLE rc ERROR_VARIABLE log)
  if(NOT rc EQUAL 0 OR NOT EXISTS ${OUT}/study.${format})
    message(FATAL_ERROR "study export ${format} failed (${rc}): ${log}")
  endif()
endforeach()
file(STRINGS ${OUT}/study.csv rows)
list(LENGTH rows row_count)
list(GET rows 0 header)
if(NOT row_count EQUAL 8 OR NOT header MATCHES "^participant,session,trial_index,block,scene,mono_plane,label1_mode,choice,chosen_mode,valid,switches,time_label1_s,time_label2_s,decision_time_s")
  message(FATAL_ERROR "study.csv: ${row_count} lines, header ${header}")
endif()
file(READ ${OUT}/study.json json)
string(JSON trials LENGTH "${json}")
if(NOT trials EQUAL 7)
  message(FATAL_ERROR "study.json holds ${trials} trials")
endif()
execute_process(COMMAND ${MONOPLANE} study run --protocol ${SOURCE}/protocols/demo.toml
                        --participant E2E1 --db ${db} --headset none
                RESULT_VARIABLE rc ERROR_VARIABLE log)
if(rc EQUAL 0 OR NOT log MATCHES "resume")
  message(FATAL_ERROR "a duplicate participant must be refused, pointing to resume (${rc}): ${log}")
endif()
execute_process(COMMAND ${MONOPLANE} study resume --db ${db} --session-id 1
                RESULT_VARIABLE rc ERROR_VARIABLE log)
if(rc EQUAL 0 OR NOT log MATCHES "completed")
  message(FATAL_ERROR "resuming a completed session must be refused (${rc}): ${log}")
endif()
file(WRITE ${OUT}/bad.toml "name = \"bad\"\nscenes = [\"beams\"]\nmono_planes = [3, 3]\nalternatives = [\"stereo\", \"hybrid\"]\nordr = \"fixed\"\n")
execute_process(COMMAND ${MONOPLANE} protocol check ${OUT}/bad.toml
                RESULT_VARIABLE rc ERROR_VARIABLE log)
if(rc EQUAL 0 OR NOT log MATCHES "bad.toml:3" OR NOT log MATCHES "ordr")
  message(FATAL_ERROR "protocol check must name file, line and key (${rc}): ${log}")
endif()

# The benchmark on a tiny sweep: the files, the keys tools read, one run per configuration,
# m = far equal to stereo in primitives, the turning-head pairs compiling nothing in the driver
# (where counted: lavapipe; else null), and bad input refused.
set(dir ${OUT}/bench)
file(REMOVE_RECURSE ${dir})
execute_process(
  COMMAND ${MONOPLANE} --validation bench --scenes spheres --modes stereo,hybrid,hybrid-farfield
          --mono-planes 3,far --hmd vive --width 64 --height 72 --detail test --frames 1
          --warmup 0 --turning-frames 2 --out ${dir}
  RESULT_VARIABLE rc ERROR_VARIABLE log)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "bench failed (${rc}):\n${log}")
endif()
foreach(file bench.json bench.csv spheres_time.svg spheres_primitives.svg
        spheres_time_vs_error.svg)
  if(NOT EXISTS ${dir}/${file})
    message(FATAL_ERROR "bench did not write ${file}")
  endif()
endforeach()
file(READ ${dir}/bench.json json)
string(JSON runs LENGTH "${json}" runs)
# stereo + hybrid (3 variants x 2 planes) + hybrid-farfield (2 planes)
if(NOT runs EQUAL 9)
  message(FATAL_ERROR "bench.json holds ${runs} runs, expected 9")
endif()
math(EXPR last "${runs} - 1")
foreach(i RANGE ${last})
  foreach(key scene mode variant mono_plane frame_ms_median frame_ms_p90 passes primitives
          fragments ssim_vs_stereo max_error_px drift_px)
    string(JSON value ERROR_VARIABLE missing GET "${json}" runs ${i} ${key})
    if(missing)
      message(FATAL_ERROR "bench run ${i} lacks '${key}'")
    endif()
  endforeach()
  string(JSON turning_ratio ERROR_VARIABLE missing GET "${json}" runs ${i} turning_time_ratio)
  string(JSON compiles ERROR_VARIABLE missing_compiles GET "${json}" runs ${i}
         turning_driver_compiles)
  if(missing OR missing_compiles
     OR NOT (compiles STREQUAL "0" OR compiles STREQUAL "null" OR compiles STREQUAL ""))
    message(FATAL_ERROR "bench run ${i}: turning_time_ratio '${turning_ratio}', "
                        "turning_driver_compiles '${compiles}' (expected 0 or null)")
  endif()
  string(JSON mode GET "${json}" runs ${i} mode)
  string(JSON far GET "${json}" runs ${i} mono_plane_is_far)
  string(JSON primitives GET "${json}" runs ${i} primitives)
  if(mode STREQUAL "stereo")
    set(stereo_primitives ${primitives})
  elseif(far AND NOT primitives EQUAL stereo_primitives)
    message(FATAL_ERROR "bench: at m = far ${mode} drew ${primitives} primitives, stereo "
                        "${stereo_primitives}")
  endif()
endforeach()
execute_process(COMMAND ${MONOPLANE} bench --mono-planes 3,nine --out ${OUT}/bad-bench
                RESULT_VARIABLE rc ERROR_VARIABLE log)
if(rc EQUAL 0 OR NOT log MATCHES "nine")
  message(FATAL_ERROR "bench must refuse a bad mono plane, naming it (${rc}): ${log}")
endif()
