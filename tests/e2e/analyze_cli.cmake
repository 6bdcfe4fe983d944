# End-to-end: `monoplane analyze` over sessions from two databases and a CSV export, its refusals,
# and `monoplane simulate` (power analysis). Headless (`--headset none`): seconds.
# Arguments: MONOPLANE, OUT, SOURCE.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
set(protocol ${SOURCE}/protocols/demo.toml)  # 1 practice + 3 scenes x 2 distances per session

function(run_ok what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE log)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${log}")
  endif()
  set(stdout "${out}" PARENT_SCOPE)
  set(stderr "${log}" PARENT_SCOPE)
endfunction()

# Site a: three participants; site b: one, also exported as CSV.
set(a ${OUT}/site-a.sqlite)
set(b ${OUT}/site-b.sqlite)
set(seed 1)
foreach(participant A1 A2 A3)
  math(EXPR seed "${seed} + 1")
  run_ok("study run ${participant}" ${MONOPLANE} study run --protocol ${protocol}
         --participant ${participant} --db ${a} --headset none --observer default --seed ${seed})
endforeach()
run_ok("study run B1" ${MONOPLANE} study run --protocol ${protocol} --participant B1 --db ${b}
       --headset none --observer default --seed 21)
run_ok("study export" ${MONOPLANE} study export --db ${b} --format csv --out ${OUT}/site-b.csv)

# Merge of two databases: 4 sessions x 6 data trials, 4 x 7 trials in all.
set(dir ${OUT}/merged)
run_ok("analyze --db a --db b" ${MONOPLANE} analyze --db ${a} --db ${b} --out ${dir})
if(NOT stdout MATCHES "report: .*report.html")
  message(FATAL_ERROR "analyze must say where the report is: ${stdout}")
endif()
foreach(file report.html summary.json rates_by_scene.csv rates_by_distance.csv
        rates_by_scene_distance.csv logistic.csv questionnaire.csv figures/choices.svg
        figures/choices.png figures/decision_times.svg figures/decision_times.png
        figures/switches.svg figures/switches.png)
  if(NOT EXISTS ${dir}/${file})
    message(FATAL_ERROR "analyze did not write ${file}")
  endif()
endforeach()
file(READ ${dir}/summary.json json)
string(JSON data GET "${json}" trials data)
string(JSON total GET "${json}" trials total)
string(JSON practice GET "${json}" trials practice)
string(JSON sessions GET "${json}" sessions)
string(JSON sources LENGTH "${json}" sources)
string(JSON items LENGTH "${json}" questionnaire)
string(JSON answered GET "${json}" questionnaire 0 n)
if(NOT data EQUAL 24 OR NOT total EQUAL 28 OR NOT practice EQUAL 4 OR NOT sessions EQUAL 4
   OR NOT sources EQUAL 2 OR NOT items EQUAL 2 OR NOT answered EQUAL 4)
  message(FATAL_ERROR "summary.json: data ${data} (24), total ${total} (28), practice "
                      "${practice} (4), sessions ${sessions} (4), sources ${sources} (2), "
                      "questionnaire items ${items} (2) answered ${answered} (4) times")
endif()
file(READ ${dir}/report.html html)
if(NOT html MATCHES "<svg" OR html MATCHES "https?://")
  message(FATAL_ERROR "report.html must inline its figures and refer to nothing outside")
endif()

# A database and a CSV export: the same counts as both databases.
run_ok("analyze --db a --csv b.csv" ${MONOPLANE} analyze --db ${a} --csv ${OUT}/site-b.csv
       --out ${OUT}/mixed --log2-distance)
file(READ ${OUT}/mixed/summary.json json)
string(JSON data GET "${json}" trials data)
string(JSON term GET "${json}" logistic distance_term)
if(NOT data EQUAL 24 OR NOT term STREQUAL "log2_mono_plane_m")
  message(FATAL_ERROR "analyze --db --csv: ${data} data trials (24), distance term ${term}")
endif()

# One participant: the regression is not estimable, the report still comes out.
run_ok("analyze --db b" ${MONOPLANE} analyze --db ${b} --out ${OUT}/single)
file(READ ${OUT}/single/summary.json json)
string(JSON estimable GET "${json}" logistic estimable)
if(estimable OR NOT stderr MATCHES "not estimable" OR NOT EXISTS ${OUT}/single/report.html)
  message(FATAL_ERROR "one participant: estimable ${estimable}, log ${stderr}")
endif()

# Refusals, each with a message naming the problem.
execute_process(COMMAND ${MONOPLANE} analyze --out ${OUT}/none RESULT_VARIABLE rc
                ERROR_VARIABLE log)
if(rc EQUAL 0 OR NOT log MATCHES "no input")
  message(FATAL_ERROR "analyze without input must fail saying so (${rc}): ${log}")
endif()
execute_process(COMMAND ${MONOPLANE} analyze --db ${OUT}/missing.sqlite --out ${OUT}/none
                RESULT_VARIABLE rc ERROR_VARIABLE log)
if(rc EQUAL 0 OR NOT log MATCHES "missing.sqlite" OR EXISTS ${OUT}/missing.sqlite)
  message(FATAL_ERROR "a missing database must fail naming it, and not be created (${rc}): ${log}")
endif()
execute_process(COMMAND ${MONOPLANE} study export --db ${OUT}/empty.sqlite --format csv
                        --out ${OUT}/empty.csv RESULT_VARIABLE rc ERROR_VARIABLE log)
execute_process(COMMAND ${MONOPLANE} analyze --db ${OUT}/empty.sqlite --out ${OUT}/none
                RESULT_VARIABLE rc ERROR_VARIABLE log)
if(rc EQUAL 0 OR NOT log MATCHES "no sessions")
  message(FATAL_ERROR "a database without sessions must be refused (${rc}): ${log}")
endif()
file(WRITE ${OUT}/garbage.csv "this,is\nnot,an export\n")
execute_process(COMMAND ${MONOPLANE} analyze --csv ${OUT}/garbage.csv --out ${OUT}/none
                RESULT_VARIABLE rc ERROR_VARIABLE log)
if(rc EQUAL 0 OR NOT log MATCHES "garbage.csv")
  message(FATAL_ERROR "an unreadable CSV must be refused naming it (${rc}): ${log}")
endif()
execute_process(COMMAND ${MONOPLANE} analyze --db ${a} --db ${a} --out ${OUT}/none
                RESULT_VARIABLE rc ERROR_VARIABLE log)
if(rc EQUAL 0 OR NOT log MATCHES "twice")
  message(FATAL_ERROR "a database given twice must be refused (${rc}): ${log}")
endif()

# Power: the chance observer with 4 participants, then the default observer with the full
# protocol (ten distances), whose distance effect is strong: more power than chance.
function(read_power dir out_var)
  file(STRINGS ${dir}/power.csv rows)
  list(POP_FRONT rows header)
  # The CR1 columns first, as before the CR2 columns were added (keys are only ever added).
  if(NOT header STREQUAL "participants,runs,detected,not_estimable,power,ci_lower,ci_upper,detected_cr2,power_cr2,ci_lower_cr2,ci_upper_cr2")
    message(FATAL_ERROR "${dir}/power.csv header: ${header}")
  endif()
  foreach(row ${rows})
    string(REPLACE "," ";" fields "${row}")
    list(GET fields 4 power)
    list(GET fields 8 power_cr2)
    foreach(value ${power} ${power_cr2})
      if(value LESS 0 OR value GREATER 1)
        message(FATAL_ERROR "${dir}/power.csv: power ${value} outside [0, 1]: ${row}")
      endif()
    endforeach()
  endforeach()
  set(${out_var} ${power} PARENT_SCOPE)  # at the largest n
endfunction()
run_ok("simulate chance" ${MONOPLANE} simulate --protocol ${protocol} --participants 4
       --runs 20 --observer chance --out ${OUT}/power-chance --seed 5)
foreach(file power.csv power.json power.svg power.png)
  if(NOT EXISTS ${OUT}/power-chance/${file})
    message(FATAL_ERROR "simulate did not write ${file}")
  endif()
endforeach()
read_power(${OUT}/power-chance chance_demo)
run_ok("simulate chance fink2019" ${MONOPLANE} simulate --protocol ${SOURCE}/protocols/fink2019.toml
       --participants 8 --runs 20 --observer chance --out ${OUT}/power-chance-full --seed 5)
read_power(${OUT}/power-chance-full chance)
run_ok("simulate default" ${MONOPLANE} simulate --protocol ${SOURCE}/protocols/fink2019.toml
       --participants 8 --runs 20 --observer default --out ${OUT}/power-default --seed 5)
read_power(${OUT}/power-default default)
if(NOT default GREATER chance)
  message(FATAL_ERROR "power with the default observer (${default}) must exceed chance (${chance})")
endif()
# Deterministic for a seed.
run_ok("simulate again" ${MONOPLANE} simulate --protocol ${protocol} --participants 4
       --runs 20 --observer chance --out ${OUT}/power-chance-again --seed 5)
file(READ ${OUT}/power-chance/power.csv first)
file(READ ${OUT}/power-chance-again/power.csv second)
if(NOT first STREQUAL second)
  message(FATAL_ERROR "simulate with one seed must give the same power.csv:\n${first}\n${second}")
endif()
execute_process(COMMAND ${MONOPLANE} simulate --protocol ${protocol} --participants 4 --runs 5
                        --observer psychic --out ${OUT}/none RESULT_VARIABLE rc ERROR_VARIABLE log)
if(rc EQUAL 0 OR NOT log MATCHES "psychic")
  message(FATAL_ERROR "an unknown observer must be refused naming it (${rc}): ${log}")
endif()
