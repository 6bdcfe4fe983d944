# End-to-end (issue 21): protocols/threshold.toml passes `protocol check`; a staircase session with
# a psychometric observer (T = 8 m) runs headless, exports with the procedure column and the m its
# staircases chose, and analyze locates the threshold; `simulate` runs a staircase protocol; and
# `simulate-threshold` at a small size: QUEST+'s posterior covers and hits the known threshold
# and is more precise at 50 trials per scene than the constant procedure's. Seconds.
# Arguments: MONOPLANE, OUT, SOURCE.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
set(protocol ${SOURCE}/protocols/threshold.toml)
set(observer psychometric:threshold=8,slope=3,lapse=0.02)

function(run_ok what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE log)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${log}")
  endif()
  set(stdout "${out}" PARENT_SCOPE)
  set(stderr "${log}" PARENT_SCOPE)
endfunction()

run_ok("protocol check" ${MONOPLANE} protocol check ${protocol})
if(NOT stdout MATCHES "procedure: +staircase, quest\\+, up to 50 trials per scene")
  message(FATAL_ERROR "protocol check must describe the staircase:\n${stdout}")
endif()

# A session of threshold.toml with at most 25 trials per scene (each event is a durable write:
# the whole protocol's session takes 4 s): every data trial a staircase's, at one of the
# protocol's distances.
file(READ ${protocol} text)
string(REPLACE "trials_per_scene = 50" "trials_per_scene = 25" text "${text}")
string(REPLACE "min_trials_per_scene = 20" "min_trials_per_scene = 15" text "${text}")
file(WRITE ${OUT}/threshold25.toml "${text}")
set(db ${OUT}/threshold.sqlite)
run_ok("study run" ${MONOPLANE} study run --protocol ${OUT}/threshold25.toml --participant T1
       --db ${db} --headset none --observer ${observer} --seed 5)
set(run_stderr "${stderr}")
run_ok("study export" ${MONOPLANE} study export --db ${db} --format csv --out ${OUT}/t.csv)
file(STRINGS ${OUT}/t.csv lines)
list(GET lines 0 header)
if(NOT header MATCHES ",procedure,staircase_threshold_m,staircase_lower_m,staircase_upper_m,")
  message(FATAL_ERROR "the export must carry procedure and the staircase columns: ${header}")
endif()
# The session's end names each scene's estimate (replayed from the stored decisions).
foreach(scene beams landscape spheres)
  if(NOT run_stderr MATCHES "staircase ${scene}: threshold [0-9.]+ m \\(95 % credible interval")
    message(FATAL_ERROR "study run must print ${scene}'s staircase estimate:\n${run_stderr}")
  endif()
endforeach()
list(REMOVE_AT lines 0)
# The staircase columns counted from the end (the quoted observer holds commas; columns added
# after them, such as runs, shift nothing here).
string(REPLACE "," ";" header_fields "${header}")
list(LENGTH header_fields header_length)
list(FIND header_fields staircase_threshold_m estimate_column)
math(EXPR estimate_from_end "${estimate_column} - ${header_length}")
math(EXPR lower_from_end "${estimate_from_end} + 1")
math(EXPR upper_from_end "${estimate_from_end} + 2")
set(data 0)
foreach(line IN LISTS lines)
  if(NOT line MATCHES ",staircase,[^,]+,[^,]+,[^,]+,")
    message(FATAL_ERROR "a trial of a staircase session without procedure staircase: ${line}")
  endif()
  string(REPLACE "," ";" fields "${line}")
  list(GET fields 5 m)
  list(GET fields 14 practice)
  list(GET fields ${estimate_from_end} estimate)
  list(GET fields ${lower_from_end} lower)
  list(GET fields ${upper_from_end} upper)
  # Data trials carry QUEST+'s estimate inside its interval and the distances' range; practice
  # trials none.
  if(practice STREQUAL "TRUE" AND NOT estimate STREQUAL "NA")
    message(FATAL_ERROR "a practice trial with a staircase estimate: ${line}")
  endif()
  if(practice STREQUAL "FALSE" AND (estimate LESS 1.6 OR estimate GREATER 39.5
                                    OR lower GREATER estimate OR upper LESS estimate))
    message(FATAL_ERROR "a data trial's staircase estimate outside its interval: ${line}")
  endif()
  if(NOT m MATCHES "^(1\\.6|2|2\\.5|3|4|5|6\\.3|8|10|12\\.5|16|20|25|31|39\\.5)$")
    message(FATAL_ERROR "m = ${m} is not one of the protocol's distances: ${line}")
  endif()
  if(practice STREQUAL "FALSE")
    math(EXPR data "${data} + 1")
  endif()
endforeach()
# 15 to 25 trials per scene (the posterior-width rule may stop a scene after 15).
if(data LESS 45 OR data GREATER 75)
  message(FATAL_ERROR "${data} data trials; expected 45 to 75")
endif()

run_ok("analyze" ${MONOPLANE} analyze --db ${db} --out ${OUT}/analysis)
file(READ ${OUT}/analysis/summary.json json)
string(JSON fits LENGTH "${json}" psychometric)
set(located 0)
math(EXPR last "${fits} - 1")
foreach(i RANGE ${last})
  string(JSON who GET "${json}" psychometric ${i} participant)
  string(JSON estimable GET "${json}" psychometric ${i} estimable)
  if(who STREQUAL "T1" AND estimable)
    string(JSON t GET "${json}" psychometric ${i} threshold_m)
    # Within a factor 2 of the observer's 8 m.
    if(t GREATER_EQUAL 4 AND t LESS_EQUAL 16)
      math(EXPR located "${located} + 1")
    endif()
  endif()
endforeach()
if(located LESS 2)
  message(FATAL_ERROR "analyze located T1's threshold within [4, 16] m in ${located} of 3 scenes")
endif()

# The power analysis with a staircase protocol.
run_ok("simulate" ${MONOPLANE} simulate --protocol ${protocol} --participants 2 --runs 2
       --observer ${observer} --out ${OUT}/power)
if(NOT EXISTS ${OUT}/power/power.json)
  message(FATAL_ERROR "simulate wrote no power.json")
endif()

# Validation at a small size: 20 participants x 3 scenes.
run_ok("simulate-threshold staircase" ${MONOPLANE} simulate-threshold --protocol ${protocol}
       --observer ${observer} --runs 20 --seed 7 --precision-log10 0.15 --out ${OUT}/stair)
run_ok("simulate-threshold constant" ${MONOPLANE} simulate-threshold
       --protocol ${SOURCE}/protocols/fink2019.toml --observer ${observer} --runs 20 --sessions 5
       --seed 7 --precision-log10 0.15 --out ${OUT}/constant)
foreach(file thresholds.csv thresholds.json)
  if(NOT EXISTS ${OUT}/stair/${file})
    message(FATAL_ERROR "simulate-threshold wrote no ${file}")
  endif()
endforeach()

# The summary of `estimator` at `trials` trials per scene in a thresholds.json: key's value.
function(summary_value file estimator trials key out)
  file(READ ${file} json)
  string(JSON count LENGTH "${json}" estimators)
  math(EXPR last "${count} - 1")
  foreach(i RANGE ${last})
    string(JSON e GET "${json}" estimators ${i} estimator)
    string(JSON n GET "${json}" estimators ${i} trials)
    if(e STREQUAL estimator AND n EQUAL trials)
      string(JSON value GET "${json}" estimators ${i} ${key})
      set(${out} ${value} PARENT_SCOPE)
      return()
    endif()
  endforeach()
  message(FATAL_ERROR "${file}: no ${estimator} summary at ${trials} trials")
endfunction()

summary_value(${OUT}/stair/thresholds.json posterior 50 coverage coverage)
summary_value(${OUT}/stair/thresholds.json posterior 50 bias_log10 bias)
summary_value(${OUT}/stair/thresholds.json posterior 50 rmse_log10 rmse)
summary_value(${OUT}/constant/thresholds.json posterior 50 rmse_log10 rmse_constant)
# 60 intervals of nominal 95 %: 54 or more cover (binomial(60, 0.95) puts 0.98 there); the
# mean log10 error within 0.05 (its standard error is about 0.013); RMSE below the constant's
# (0.10 against 0.16 log10 over 1000 runs, docs/analysis.md).
if(coverage LESS 0.9)
  message(FATAL_ERROR "posterior coverage ${coverage} at 50 trials; expected at least 0.9")
endif()
if(bias GREATER 0.05 OR bias LESS -0.05)
  message(FATAL_ERROR "posterior bias ${bias} log10 at 50 trials; expected within 0.05")
endif()
if(NOT rmse LESS rmse_constant)
  message(FATAL_ERROR "staircase RMSE ${rmse} not below the constant procedure's ${rmse_constant}")
endif()
file(READ ${OUT}/stair/thresholds.json json)
string(JSON reached GET "${json}" trials_to_precision posterior)
if(reached STREQUAL "null" OR reached GREATER 50)
  message(FATAL_ERROR "the staircase did not reach RMSE 0.15 log10 within 50 trials: ${reached}")
endif()
message(STATUS "staircase: ${data} data trials; posterior at 50: coverage ${coverage}, bias "
               "${bias}, RMSE ${rmse} (constant ${rmse_constant}); RMSE 0.15 from ${reached}")
