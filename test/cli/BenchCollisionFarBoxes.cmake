# `ropras bench-collision --far-boxes N [--far-radius R]`: N boxes in a shared base under every scene, from R to
# R + 3 m from the world origin. Out of reach they change no verdict; in reach they do (so the option is not
# ignored). The arm's default 8 configurations (seed 1): 3 valid and 5 invalid in the one-problem folder.

# bad values: exit 2 naming the option and the value
ropras_cli_test(bench_collision.far_boxes_huge 2 "--far-boxes: Value 2000000 not in range 0 to 1000000" ${bc}
                --far-boxes 2000000)
ropras_cli_test(bench_collision.far_boxes_text 2 "--far-boxes: Value abc" ${bc} --far-boxes abc)
ropras_cli_test(bench_collision.far_boxes_negative 2 "--far-boxes: Value -3" ${bc} --far-boxes -3)
ropras_cli_test(bench_collision.far_radius_negative 2 "--far-radius: Value -1 not in range" ${bc} --far-radius -1)
ropras_cli_test(bench_collision.far_radius_huge 2 "--far-radius: Value 5000 not in range" ${bc} --far-radius 5000)
ropras_cli_test(bench_collision.far_radius_text 2 "--far-radius: Value near" ${bc} --far-radius near)

# ropras_far_boxes_test(<name> <stdout regex> <ropras arguments>...): exit 0 and standard output matching
function(ropras_far_boxes_test name stdout)
  string(JOIN "|" cmd "$<TARGET_FILE:ropras>" ${ARGN})
  add_test(NAME cli.${name}
           COMMAND ${CMAKE_COMMAND} "-DCMD=${cmd}" -DEXPECT_CODE=0 -DEXPECT_REGEX=.* "-DEXPECT_STDOUT=${stdout}" -P
                   ${CMAKE_CURRENT_SOURCE_DIR}/ExpectExit.cmake)
  set_tests_properties(cli.${name} PROPERTIES LABELS cli TIMEOUT 30)
endfunction()
set(far_verdicts "single config, valid +[0-9.]+ +3\nsingle config, invalid +[0-9.]+ +5\n")
# the verdicts without far boxes, with 10 and with 40 (40 and more go through the obstacle tree) beyond 2 m
ropras_far_boxes_test(bench_collision.far_boxes_none "${far_verdicts}" ${bc})
ropras_far_boxes_test(bench_collision.far_boxes_10 "${far_verdicts}" ${bc} --far-boxes 10)
ropras_far_boxes_test(bench_collision.far_boxes_40 "${far_verdicts}" ${bc} --far-boxes 40 --far-radius 2)
# 400 boxes from the origin outwards: some in reach, a configuration more in collision
ropras_far_boxes_test(bench_collision.far_boxes_in_reach
                      "single config, valid +[0-9.]+ +2\nsingle config, invalid +[0-9.]+ +6\n" ${bc} --far-boxes 400
                      --far-radius 0)
