# Issue 17 (bad input and first use), included by CMakeLists.txt. JSON lines: each record is written whole; a line an interrupted run cut off is ended and skipped with a warning
add_test(NAME cli.run.truncated_record
         COMMAND ${CMAKE_COMMAND} -DROPRAS=$<TARGET_FILE:ropras> -DGOOD=${in}/good_runs.jsonl
                 -DFILE=${in}/truncated/out.jsonl -P ${CMAKE_CURRENT_SOURCE_DIR}/TruncatedRecord.cmake)
set_tests_properties(cli.run.truncated_record PROPERTIES LABELS cli TIMEOUT 60 FIXTURES_REQUIRED ropras_run_output)
