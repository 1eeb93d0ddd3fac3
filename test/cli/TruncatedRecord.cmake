# An interrupted `ropras run` left a record without its end and without a newline: the next appending run ends
# that line first (and says so), so its own records stay whole, and `ropras table` skips the cut-off line with a
# warning naming the file and line.
#   cmake -DROPRAS=ropras -DGOOD=good_runs.jsonl -DFILE=out.jsonl -P TruncatedRecord.cmake
file(STRINGS "${GOOD}" records)
list(GET records 0 first)
string(SUBSTRING "${first}" 0 40 cut)
file(WRITE "${FILE}" "${first}\n${cut}")

execute_process(COMMAND ${ROPRAS} run --scenario light-dark --sims 5 --episodes 1 --seed 7 --quiet --out ${FILE}
                RESULT_VARIABLE code ERROR_VARIABLE err OUTPUT_QUIET TIMEOUT 25)
if(NOT code STREQUAL "0" OR NOT err MATCHES "warning: .*out.jsonl:2 was a truncated record")
  message(FATAL_ERROR "ropras run --out: exit ${code}, expected 0 and a warning naming line 2\n${err}")
endif()
file(STRINGS "${FILE}" lines)
list(LENGTH lines count)
list(GET lines 1 second)
list(GET lines 2 third)
if(NOT count EQUAL 3 OR NOT second STREQUAL cut OR NOT third MATCHES "^{.*\"episode_seed\".*}$")
  message(FATAL_ERROR "expected the first record, the cut-off line and the new record on its own line:\n${lines}")
endif()

execute_process(COMMAND ${ROPRAS} table ${FILE} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err
                TIMEOUT 15)
if(NOT code STREQUAL "0" OR NOT err MATCHES "out.jsonl:2: truncated record" OR NOT out MATCHES "light-dark")
  message(FATAL_ERROR "ropras table: exit ${code}, expected 0, a table and a warning naming line 2\n${out}\n${err}")
endif()
message(STATUS "ok: the cut-off line is ended, skipped by table with a warning")
