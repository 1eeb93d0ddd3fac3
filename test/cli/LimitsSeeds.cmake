# Issue 17 (bad input and first use), included by CMakeLists.txt. Seeds: exact 64-bit (or 32-bit) numbers; -1 never wraps to 2^64 - 1, 2^64 never saturates
ropras_cli_test(check_collision.negative_seed 2 "--seed: Value -1 must be a whole number >= 0" ${cc} --urdf
                ${arm_urdf} --scenes ${scene} --seed -1)
ropras_cli_test(demo.negative_seed 2 "--seed: Value -1 must be a whole number >= 0" demo --seed -1)
ropras_cli_test(pomdp_run.negative_seed 2 "--seed: Value -1 must be a whole number >= 0" pomdp-run --seed -1)
ropras_cli_test(bench_solvers.negative_seed 2 "--seed: Value -1 must be a whole number >= 0" bench-solvers --seed -1)
ropras_cli_test(run.seed_2_64 2 "--seed: Value 18446744073709551616 exceeds the maximum 18446744073709551615" ${ld}
                --seed 18446744073709551616)
ropras_cli_test(plan.seed_2_32 2 "--seed: Value 4294967296 exceeds the maximum 4294967295" ${plan} --seed 4294967296)
string(JOIN "|" max_seed_cmd "$<TARGET_FILE:ropras>" ${ld} --seed 18446744073709551615 --print-config)
add_test(NAME cli.run.seed_2_64_minus_1
         COMMAND ${CMAKE_COMMAND} "-DCMD=${max_seed_cmd}" -DEXPECT_CODE=0 -DEXPECT_REGEX=.*
                 "-DEXPECT_STDOUT=\"seed\": 18446744073709551615" -P ${CMAKE_CURRENT_SOURCE_DIR}/ExpectExit.cmake)
set_tests_properties(cli.run.seed_2_64_minus_1 PROPERTIES LABELS cli TIMEOUT 30)
