# Issue 17 (bad input and first use), included by CMakeLists.txt. Episodes: a maximum, and a shard's episodes are computed, not searched for among all indices
ropras_cli_test(run.episodes_1e12 2 "--episodes: Value 1000000000000 exceeds the maximum 1000000" ${ld} --episodes
                1000000000000)
ropras_cli_test(run.episodes_1e12_shard 2 "--episodes: Value 1000000000000 exceeds the maximum 1000000" ${ld}
                --episodes 1000000000000 --shard 3/7)
ropras_cli_test(pomdp_run.episodes_1e12 2 "--episodes: Value 1000000000000 exceeds the maximum 1000000" pomdp-run
                --episodes 1000000000000)
string(JOIN "|" big_shard_cmd "$<TARGET_FILE:ropras>" ${ld} --episodes 1000000 --shard 999999/1000000)
add_test(NAME cli.run.last_shard_of_a_million
         COMMAND ${CMAKE_COMMAND} "-DCMD=${big_shard_cmd}" -DEXPECT_CODE=0 -DEXPECT_REGEX=.*
                 "-DEXPECT_STDOUT=light-dark.*\\| 1 \\|" -P ${CMAKE_CURRENT_SOURCE_DIR}/ExpectExit.cmake)
set_tests_properties(cli.run.last_shard_of_a_million PROPERTIES LABELS cli TIMEOUT 30)
