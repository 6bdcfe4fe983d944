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
# A 0-byte file (a copy that failed) is no study database: refused, and left as it was.
file(WRITE ${OUT}/empty.sqlite "")
execute_process(COMMAND ${MONOPLANE} analyze --db ${OUT}/empty.sqlite --out ${OUT}/none
                RESULT_VARIABLE rc ERROR_VARIABLE log)
file(SIZE ${OUT}/empty.sqlite empty_size)
if(rc EQUAL 0 OR NOT log MATCHES "0 bytes: not a study database" OR NOT empty_size EQUAL 0)
  message(FATAL_ERROR "a 0-byte database must be refused and stay 0 bytes (${rc}): ${log}")
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

# Two sites that both code their participants c1, c2, c3 (six people): never merged silently.
set(x ${OUT}/site-x.sqlite)
set(y ${OUT}/site-y.sqlite)
foreach(site site-x site-y)
  foreach(participant c1 c2 c3)
    math(EXPR seed "${seed} + 1")
    set(number_option "")
    if(site STREQUAL site-y)  # site y numbers its participants after site x's: 4, 5, 6
      string(SUBSTRING ${participant} 1 1 index)
      math(EXPR number "${index} + 3")
      set(number_option --participant-number ${number})
    endif()
    run_ok("study run ${site} ${participant}" ${MONOPLANE} study run --protocol ${protocol}
           --participant ${participant} --db ${OUT}/${site}.sqlite --headset none --observer default
           --seed ${seed} ${number_option})
  endforeach()
endforeach()
run_ok("study note" ${MONOPLANE} study note --db ${x} --participant c1
       "<script>alert('x')</script> & \"quoted\"")
execute_process(COMMAND ${MONOPLANE} analyze --db ${x} --db ${y} --out ${OUT}/shared
                RESULT_VARIABLE rc ERROR_VARIABLE log)
if(rc EQUAL 0 OR NOT log MATCHES "c1, c2 and c3 in [^\n]*site-x.sqlite and [^\n]*site-y.sqlite"
   OR NOT log MATCHES "--codes same-person" OR NOT log MATCHES "--codes per-database"
   OR EXISTS ${OUT}/shared)
  message(FATAL_ERROR "a code in two databases must be refused, naming the codes, the files and "
                      "both --codes, with nothing written (${rc}): ${log}")
endif()
run_ok("analyze --codes per-database" ${MONOPLANE} analyze --db ${x} --db ${y} --out
       ${OUT}/per-database --codes per-database)
file(READ ${OUT}/per-database/summary.json json)
string(JSON participants GET "${json}" participants)
string(JSON first GET "${json}" participant_details 0 participant)
string(JSON last GET "${json}" participant_details 5 participant)
string(JSON rule GET "${json}" participant_codes rule)
string(JSON balanced GET "${json}" counterbalancing balanced)
string(JSON rows LENGTH "${json}" counterbalancing rows)
string(JSON row1 GET "${json}" counterbalancing rows 1)
if(NOT participants EQUAL 6 OR NOT first STREQUAL "site-x/c1" OR NOT last STREQUAL "site-y/c3"
   OR NOT rule STREQUAL "per-database" OR NOT balanced OR NOT rows EQUAL 6 OR NOT row1 EQUAL 1)
  message(FATAL_ERROR "--codes per-database: ${participants} participants (6), ${first} "
                      "(site-x/c1) .. ${last} (site-y/c3), rule ${rule}, balanced ${balanced} "
                      "over ${rows} rows (6), row 1: ${row1} (1)")
endif()
file(READ ${OUT}/per-database/report.html html)
if(NOT html MATCHES "site-y/c2" OR html MATCHES "<script"
   OR NOT html MATCHES "&lt;script&gt;alert\\(&apos;x&apos;\\)&lt;/script&gt; &amp; &quot;quoted&quot;")
  message(FATAL_ERROR "report.html must list the prefixed codes and the note, escaped")
endif()
# Two sites' c1 are two people: --codes same-person is refused, naming the clash.
execute_process(COMMAND ${MONOPLANE} analyze --db ${x} --db ${y} --out ${OUT}/not-same
                        --codes same-person RESULT_VARIABLE rc ERROR_VARIABLE log)
if(rc EQUAL 0 OR NOT log MATCHES "c1: session 1 in both" OR EXISTS ${OUT}/not-same)
  message(FATAL_ERROR "--codes same-person over two people must be refused (${rc}): ${log}")
endif()
# One person on two lab PCs: session 1 on the first, session 2 on the second with their number.
set(pc1 ${OUT}/pc-1.sqlite)
set(pc2 ${OUT}/pc-2.sqlite)
file(READ ${protocol} demo_text)
file(WRITE ${OUT}/two-sessions.toml "sessions = 2\n${demo_text}")
foreach(participant c1 c2)
  string(SUBSTRING ${participant} 1 1 number)
  math(EXPR seed "${seed} + 1")
  run_ok("study run pc-1 ${participant}" ${MONOPLANE} study run --protocol ${OUT}/two-sessions.toml
         --participant ${participant} --db ${pc1} --headset none --observer default --seed ${seed})
  math(EXPR seed "${seed} + 1")
  run_ok("study run pc-2 ${participant}" ${MONOPLANE} study run --protocol ${OUT}/two-sessions.toml
         --participant ${participant} --db ${pc2} --headset none --observer default --seed ${seed}
         --session 2 --participant-number ${number})
endforeach()
run_ok("analyze --codes same-person" ${MONOPLANE} analyze --db ${pc1} --db ${pc2} --out
       ${OUT}/same-person --codes same-person)
file(READ ${OUT}/same-person/summary.json json)
string(JSON participants GET "${json}" participants)
string(JSON sessions GET "${json}" sessions)
string(JSON first GET "${json}" participant_details 0 participant)
string(JSON first_sessions LENGTH "${json}" participant_details 0 sources)
if(NOT participants EQUAL 2 OR NOT sessions EQUAL 4 OR NOT first STREQUAL "c1"
   OR NOT first_sessions EQUAL 2)
  message(FATAL_ERROR "--codes same-person: ${participants} participants (2), ${sessions} "
                      "sessions (4), ${first} (c1) from ${first_sessions} files (2)")
endif()
# Without --participant-number each site starts at the first row: unbalanced, and said so.
set(z ${OUT}/site-z.sqlite)
foreach(participant d1 d2 d3)
  math(EXPR seed "${seed} + 1")
  run_ok("study run z ${participant}" ${MONOPLANE} study run --protocol ${protocol}
         --participant ${participant} --db ${z} --headset none --observer default --seed ${seed})
endforeach()
run_ok("analyze x z" ${MONOPLANE} analyze --db ${x} --db ${z} --out ${OUT}/unbalanced)
file(READ ${OUT}/unbalanced/summary.json json)
string(JSON balanced GET "${json}" counterbalancing balanced)
string(JSON row1 GET "${json}" counterbalancing rows 1)
if(balanced OR NOT row1 EQUAL 2 OR NOT stderr MATCHES "warning: the Latin-square rows")
  message(FATAL_ERROR "two databases each from row 1: balanced ${balanced}, row 1: ${row1} (2), "
                      "log ${stderr}")
endif()
file(READ ${OUT}/unbalanced/report.html html)
if(NOT html MATCHES "differ by more than one")
  message(FATAL_ERROR "report.html must warn that the Latin-square rows are unbalanced")
endif()

# A participant variable typed as a formula survives the export's guard and comes back as typed
# through `analyze --csv`; two sessions of two repetitions give 4 trials per distance and scene.
file(WRITE ${OUT}/day.toml "name = \"day\"\nscenes = [\"beams\", \"spheres\"]\n"
     "mono_planes = [3, 8]\nalternatives = [\"stereo\", \"hybrid\"]\npractice_trials = 1\nsessions = 2\nrepetitions = 2\n"
     "[[variables]]\nname = \"remark\"\ntype = \"text\"\n")
set(day ${OUT}/day.sqlite)
run_ok("study run day 1" ${MONOPLANE} study run --protocol ${OUT}/day.toml --participant e1
       --db ${day} --headset none --observer default --seed 71 "--var=remark==1+2 <b>")
run_ok("study run day 2" ${MONOPLANE} study run --protocol ${OUT}/day.toml --participant e1
       --db ${day} --headset none --observer default --seed 72)
run_ok("study export day" ${MONOPLANE} study export --db ${day} --format csv --out ${OUT}/day.csv)
run_ok("analyze --csv day" ${MONOPLANE} analyze --csv ${OUT}/day.csv --out ${OUT}/day)
file(READ ${OUT}/day/summary.json json)
string(JSON remark GET "${json}" participant_details 0 variables remark)
string(JSON sessions LENGTH "${json}" participant_details 0 sessions)
string(JSON fit_participant GET "${json}" psychometric 1 participant)
string(JSON level_trials GET "${json}" psychometric 1 levels 0 trials)
if(NOT remark STREQUAL "=1+2 <b>" OR NOT sessions EQUAL 2 OR NOT fit_participant STREQUAL "e1"
   OR NOT level_trials EQUAL 4)
  message(FATAL_ERROR "analyze --csv: remark '${remark}' ('=1+2 <b>'), ${sessions} sessions (2), "
                      "${fit_participant}'s fit with ${level_trials} trials per distance (4)")
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
