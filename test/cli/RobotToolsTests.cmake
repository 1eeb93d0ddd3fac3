# `ropras spherize` and `ropras collision-matrix`: bad input exits 2 naming the problem; good input works.
# Included from CMakeLists.txt (uses ropras_cli_test, ${in}, ${arm_urdf}, ${missing}).
set(sph spherize --urdf ${arm_urdf})
ropras_cli_test(spherize.missing_urdf 2 "--urdf.*does_not_exist.urdf" spherize --urdf ${missing} --output
                ${in}/out.urdf)
ropras_cli_test(spherize.malformed_urdf 2 "malformed.urdf'?: malformed XML" spherize --urdf ${in}/malformed.urdf
                --output ${in}/out.urdf)
ropras_cli_test(spherize.no_output 2 "--output is required" ${sph})
ropras_cli_test(spherize.zero_tolerance 2 "--tolerance.*must be a finite number > 0" ${sph} --output ${in}/out.urdf
                --tolerance 0)
ropras_cli_test(spherize.nan_tolerance 2 "--tolerance.*must be a finite number > 0" ${sph} --output
                ${in}/out.urdf --tolerance nan)
ropras_cli_test(spherize.zero_spheres 2 "--max-spheres.*whole number >= 1" ${sph} --output ${in}/out.urdf
                --max-spheres 0)
ropras_cli_test(spherize.huge_spheres 2 "--max-spheres.*100000" ${sph} --output ${in}/out.urdf --max-spheres 1e9)
ropras_cli_test(spherize.unwritable_output 2 "--output: cannot write '${in}/no_such_dir/out.urdf'" ${sph} --output
                ${in}/no_such_dir/out.urdf)
ropras_cli_test(spherize.unknown_link 2 "no link 'no_such_link'|no_such_link" ${sph} --output ${in}/out.urdf --link
                no_such_link=0.01)
ropras_cli_test(spherize.malformed_link 2 "--link base_link=0.01/x: expected TOLERANCE or TOLERANCE/MAX_SPHERES" ${sph}
                --output ${in}/out.urdf --link base_link=0.01/x)
ropras_cli_test(spherize.link_without_value 2 "--link expects key=value, got 'base_link'" ${sph} --output
                ${in}/out.urdf --link base_link)
ropras_cli_test(spherize.link_zero_tolerance 2 "--link base_link=0/8: .*tolerance must be a finite number > 0" ${sph}
                --output ${in}/out.urdf --link base_link=0/8)
ropras_cli_test(spherize.link_huge_count 2 "--link base_link=0.01/1e9: .*whole number in \\[1, 100000\\]" ${sph}
                --output ${in}/out.urdf --link base_link=0.01/1e9)
ropras_cli_test(spherize.good_input 0 ".*" ${sph} --output ${in}/arm_spherized.urdf --link tool_link=0.01/40)
# the written URDF is a valid robot: every element is a sphere now, and it loads again
ropras_cli_test(collision_matrix.good_input 0 ".*" collision-matrix --urdf ${in}/arm_spherized.urdf --samples 200)
set_tests_properties(cli.collision_matrix.good_input PROPERTIES DEPENDS cli.spherize.good_input)

set(cm collision-matrix --urdf ${arm_urdf})
ropras_cli_test(collision_matrix.missing_urdf 2 "--urdf.*does_not_exist.urdf" collision-matrix --urdf ${missing})
ropras_cli_test(collision_matrix.malformed_srdf 2 "malformed.srdf.*malformed XML" ${cm} --srdf ${in}/malformed.srdf)
ropras_cli_test(collision_matrix.zero_samples 2 "--samples.*whole number >= 1" ${cm} --samples 0)
ropras_cli_test(collision_matrix.huge_samples 2 "--samples.*100000000" ${cm} --samples 1e12)
ropras_cli_test(collision_matrix.unwritable_output 2 "--output: cannot write" ${cm} --samples 10 --output
                ${in}/no_such_dir/pairs.xml)
