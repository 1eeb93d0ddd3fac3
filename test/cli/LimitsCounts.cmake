# Issue 17 (bad input and first use), included by CMakeLists.txt. Counts: exact whole numbers within a stated maximum (no overflow, no wrap-around, no saturation)
ropras_cli_test(check_collision.samples_2_64_minus_1 2
                "--samples: Value 18446744073709551615 exceeds the maximum 1000000000" ${cc} --urdf ${arm_urdf}
                --scenes ${scene} --samples 18446744073709551615)
ropras_cli_test(check_collision.samples_2_64 2 "--samples: Value 18446744073709551616 exceeds the maximum" ${cc}
                --urdf ${arm_urdf} --scenes ${scene} --samples 18446744073709551616)
ropras_cli_test(check_collision.samples_above_limit 2 "--samples: Value 1000000001 exceeds the maximum 1000000000"
                ${cc} --urdf ${arm_urdf} --scenes ${scene} --samples 1000000001)
ropras_cli_test(check_collision.mesh_samples_huge 2 "--mesh-samples: Value 99999999999999999999 exceeds" ${cc}
                --urdf ${arm_urdf} --scenes ${scene} --mesh-samples 99999999999999999999)
ropras_cli_test(check_collision.samples_fraction 2 "--samples: Value 2.5 must be a whole number >= 1" ${cc} --urdf
                ${arm_urdf} --scenes ${scene} --samples 2.5)
ropras_cli_test(bench_collision.configs_huge 2 "--configs: Value 18446744073709551615 exceeds the maximum"
                ${bc_base} --configs 18446744073709551615)
ropras_cli_test(bench_collision.repeat_huge 2 "--repeat: Value 4294967296 exceeds the maximum 1000000" ${bc}
                --repeat 4294967296)
ropras_cli_test(bench_mbm.limit_huge 2 "--limit: Value 4294967296 exceeds the maximum 4294967295" ${mbm} --limit
                4294967296)
ropras_cli_test(bench_solvers.depth_huge 2 "--depth: Value 4294967296 exceeds the maximum 4294967295" bench-solvers
                --depth 4294967296)
ropras_cli_test(pomdp_run.steps_huge 2 "--steps: Value 1000000000000 exceeds the maximum 10000000" pomdp-run
                --steps 1000000000000)
ropras_cli_test(pomdp_run.param_depth_truncated 2 "parameter \"depth\" = 4294967296 exceeds the maximum 4294967295"
                pomdp-run --episodes 1 --simulations 10 --param depth=4294967296)
