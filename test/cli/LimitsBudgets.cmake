# Issue 17 (bad input and first use), included by CMakeLists.txt. Budgets: a documented maximum; the tree stops at its memory cap and says so
ropras_cli_test(run.plan_time_1e300 2 "--plan-time: Value 1e300 exceeds the maximum 86400" run --scenario light-dark
                --episodes 1 --plan-time 1e300 --quiet)
ropras_cli_test(run.sims_huge 2 "--sims: Value 1000000000000 exceeds the maximum 1000000000" ${ld} --sims
                1000000000000)
ropras_cli_test(plan.time_1e300 2 "--time: Value 1e300 exceeds the maximum 86400" ${plan} --time 1e300)
ropras_cli_test(pomdp_run.seconds_1e300 2 "--seconds: Value 1e300 exceeds the maximum 86400" pomdp-run --episodes 1
                --seconds 1e300)
ropras_cli_test(pomdp_run.simulations_huge 2 "--simulations: Value 10000000000 exceeds the maximum 1000000000"
                pomdp-run --episodes 1 --simulations 10000000000)
ropras_cli_test(pomdp_run.tree_mb_zero 2 "max_tree_mb = 0.* must be in \\[1, 1048576\\]" pomdp-run --episodes 1
                --simulations 10 --param max_tree_mb=0)
string(JOIN "|" tree_cap_cmd "$<TARGET_FILE:ropras>" pomdp-run --episodes 1 --steps 2 --simulations 0 --seconds
       86400 --param max_tree_mb=1)
add_test(NAME cli.pomdp_run.tree_memory_cap
         COMMAND ${CMAKE_COMMAND} "-DCMD=${tree_cap_cmd}" -DEXPECT_CODE=0
                 "-DEXPECT_REGEX=2 planning calls stopped early because the search tree reached its memory cap"
                 "-DEXPECT_STDOUT=tree memory +largest [0-9.]+ MiB, 2 plans stopped at the cap" -P
                 ${CMAKE_CURRENT_SOURCE_DIR}/ExpectExit.cmake)
set_tests_properties(cli.pomdp_run.tree_memory_cap PROPERTIES LABELS cli TIMEOUT 30)
