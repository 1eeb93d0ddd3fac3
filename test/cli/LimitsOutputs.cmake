# Issue 17 (bad input and first use), included by CMakeLists.txt. Outputs: never an input (compared by device and inode: symbolic and hard links, other spellings)
file(WRITE ${in}/overwrite/runs.jsonl
     "{\"scenario\": \"light-dark\", \"solver\": \"pomcp\", \"seed\": 1, \"episode\": 0}\n")
file(CREATE_LINK ${in}/overwrite/runs.jsonl ${in}/overwrite/symlink.jsonl SYMBOLIC)
file(CREATE_LINK ${in}/overwrite/runs.jsonl ${in}/overwrite/hardlink.jsonl)
configure_file(${in}/good_recording.json ${in}/overwrite/recording.json COPYONLY)
function(ropras_not_overwritten name input regex)
  string(JOIN "|" cmd "$<TARGET_FILE:ropras>" ${ARGN})
  add_test(NAME cli.${name} COMMAND ${CMAKE_COMMAND} "-DCMD=${cmd}" -DEXPECT_CODE=2 "-DEXPECT_REGEX=${regex}"
                                    "-DUNCHANGED=${input}" -P ${CMAKE_CURRENT_SOURCE_DIR}/ExpectExit.cmake)
  set_tests_properties(cli.${name} PROPERTIES LABELS cli TIMEOUT 30)
endfunction()
set(refuse "refusing to overwrite an input")
set(ow ${in}/overwrite)
ropras_not_overwritten(table.out_is_input ${ow}/runs.jsonl "--out '.*runs.jsonl' is the input .*${refuse}" table
                       ${ow}/runs.jsonl --out ${ow}/runs.jsonl)
ropras_not_overwritten(table.out_is_symlink_to_input ${ow}/runs.jsonl "--out '.*symlink.jsonl' is the input .*${refuse}"
                       table ${ow}/runs.jsonl --out ${ow}/symlink.jsonl)
ropras_not_overwritten(table.out_is_hard_link_to_input ${ow}/runs.jsonl "--out '.*hardlink.jsonl' is the input"
                       table ${ow}/runs.jsonl --out ${ow}/hardlink.jsonl)
ropras_not_overwritten(table.out_is_input_spelt_differently ${ow}/runs.jsonl "is the input" table
                       ${ow}/../overwrite/./runs.jsonl --out ${ow}//runs.jsonl)
ropras_not_overwritten(table.out_is_second_input ${ow}/runs.jsonl "is the input" table ${in}/missing_key_runs.jsonl
                       ${ow}/symlink.jsonl --out ${ow}/runs.jsonl)
ropras_not_overwritten(render.out_is_input ${ow}/recording.json "--out '.*recording.json' is the input" render
                       ${ow}/recording.json --out ${ow}/recording.json)
ropras_not_overwritten(run.out_is_config ${in}/unknown_key_config.json "--out '.*' is the input" ${ld} --config
                       ${in}/unknown_key_config.json --out ${in}/unknown_key_config.json)
configure_file(${arm_srdf} ${ow}/arm.srdf COPYONLY)  # a copy: a failing test must not overwrite the shipped file
ropras_not_overwritten(bench_collision.json_is_srdf ${ow}/arm.srdf "--json '.*arm.srdf' is the input" ${bc} --srdf
                       ${ow}/arm.srdf --json ${ow}/arm.srdf)
