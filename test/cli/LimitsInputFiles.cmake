# Issue 17 (bad input and first use), included by CMakeLists.txt. Input files: regular files within the size limit (one reader for every input)
execute_process(COMMAND mkfifo ${in}/fifo.jsonl ERROR_QUIET)
ropras_cli_test(check_collision.urdf_dev_zero 2 "URDF '/dev/zero': is a character device, not a regular file"
                check-collision --urdf /dev/zero --scenes ${scene})
ropras_cli_test(check_collision.scenes_dev_zero 2 "scene '/dev/zero': is a character device" ${cc} --urdf ${arm_urdf}
                --scenes /dev/zero)
ropras_cli_test(demo.scene_dev_zero 2 "scene '/dev/zero': is a character device" demo --scene /dev/zero)
ropras_cli_test(plan.request_dev_zero 2 "request '/dev/zero': is a character device" plan --urdf ${arm_urdf} --scene
                ${scene} --request /dev/zero)
ropras_cli_test(table.dev_zero 2 "results file '/dev/zero': is a character device" table /dev/zero)
ropras_cli_test(table.fifo 2 "results file '.*fifo.jsonl': is a FIFO" table ${in}/fifo.jsonl)
ropras_cli_test(render.dev_zero 2 "recording '/dev/zero': is a character device" render /dev/zero --out
                ${in}/zero.svg)
ropras_cli_test(run.config_dev_zero 2 "--config '/dev/zero': is a character device" ${ld} --config /dev/zero)
ropras_cli_test(check_collision.urdf_too_large 2 "URDF '.*ropras_arm.urdf': the file is .*, more than the input size limit 100 bytes \\(ropras --max-input-size\\)"
                --max-input-size 100 ${cc} --urdf ${arm_urdf} --scenes ${scene})
ropras_cli_test(plan.scene_too_large_after 2 "the file is [0-9]+ bytes, more than the input size limit 4096 bytes"
                ${plan} --max-input-size 4KiB)
ropras_cli_test(table.too_large 2 "results file '.*missing_key_runs.jsonl': the file is .*, more than the input size limit 10 bytes"
                --max-input-size 10 table ${in}/missing_key_runs.jsonl)
