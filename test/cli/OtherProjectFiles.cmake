# Files from other projects (issue 16, item 4) and point clouds in scenes (item 3): what MoveIt accepts is a warning
# on standard error and the command runs; bad groups, bad options and bad cloud files exit 2 naming them.
# Included from CMakeLists.txt (uses its ${in}, ${arm_urdf}, ${arm_srdf}, ${scene}, ${plan}, ${mbm}, ${bc}).
ropras_cli_test(check_collision.srdf_unknown_link_warns 0
                "warning: SRDF '[^']*unknown_link.srdf': <disable_collisions> on line 3 names link 'no_such_link', which the URDF does not define; skipped"
                check-collision --urdf ${arm_urdf} --srdf ${in}/unknown_link.srdf --scenes ${scene} --samples 200)
ropras_cli_test(plan.request_unknown_joint_warns 0
                "warning: [^\n]*request_unknown_joint.yaml: goal: names joints robot 'ropras_arm' [^\n]*ignored: elbow_jiont"
                plan --urdf ${arm_urdf} --srdf ${arm_srdf} --scene ${scene} --request ${in}/request_unknown_joint.yaml
                --time 0.5)
ropras_cli_test(plan.unknown_group 2 "no group 'arms'; groups: arm" ${plan} --group arms)
ropras_cli_test(plan.group_without_srdf 2 "planning group 'arm' needs an SRDF" plan --urdf ${arm_urdf} --scene
                ${scene} --request ${in}/request.yaml --group arm)
ropras_cli_test(plan.group_and_joints 2 "--joints excludes --group|--group excludes --joints" ${plan} --group arm
                --joints shoulder_pan_joint)
ropras_cli_test(plan.nan_limit_tolerance 2 "--limit-tolerance" ${plan} --limit-tolerance nan)
ropras_cli_test(plan.negative_limit_tolerance 2 "--limit-tolerance" ${plan} --limit-tolerance -1)
# a goal 5e-5 rad past the limit 3 of wrist_3_joint: clamped with a warning; refused with --strict
file(WRITE ${in}/request_past_limit.yaml
     "group_name: arm\n${start}goal_constraints:\n  - joint_constraints:\n"
     "      - {joint_name: shoulder_pan_joint, position: 0.3}\n      - {joint_name: shoulder_lift_joint, position: 0.3}\n"
     "      - {joint_name: elbow_joint, position: 0.3}\n      - {joint_name: wrist_1_joint, position: 0.3}\n"
     "      - {joint_name: wrist_2_joint, position: 0.3}\n      - {joint_name: wrist_3_joint, position: 3.00005}\n")
ropras_cli_test(plan.goal_past_limit_clamped 0
                "warning: [^\n]*request_past_limit.yaml: goal: joint 'wrist_3_joint' value 3.00005 is [^\n]*clamped to"
                plan --urdf ${arm_urdf} --srdf ${arm_srdf} --scene ${scene} --request ${in}/request_past_limit.yaml
                --time 0.5)
ropras_cli_test(plan.goal_past_limit_strict 2 "the goal is invalid: outside the joint limits: joint 'wrist_3_joint'"
                plan --urdf ${arm_urdf} --srdf ${arm_srdf} --scene ${scene} --request ${in}/request_past_limit.yaml
                --time 0.5 --strict)
ropras_cli_test(bench_mbm.unknown_group 2 "no group 'arms'" ${mbm} --group arms)
ropras_cli_test(bench_collision.unknown_group 2 "no group 'arms'" ${bc} --srdf ${arm_srdf} --group arms)

# point clouds: the shipped scene (its cloud beside it), a scene naming a missing cloud, a cloud with a NaN point
set(cloud_scene ${PROJECT_SOURCE_DIR}/scenes/pointcloud-shelf.yaml)
configure_file(${cloud_scene} ${in}/cloudscenes/scene0001.yaml COPYONLY)
configure_file(${PROJECT_SOURCE_DIR}/scenes/clouds/shelf-scan.pcd ${in}/cloudscenes/clouds/shelf-scan.pcd COPYONLY)
file(WRITE ${in}/cloudscenes/request0001.yaml "${start}${goal}")
file(WRITE ${in}/missing_cloud_scene.yaml "world:\n  point_clouds:\n    - {id: scan, file: gone.pcd, point_radius: 0.01}\n")
file(WRITE ${in}/nan_cloud.pcd "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nWIDTH 2\nHEIGHT 1\nPOINTS 2\nDATA ascii\n1 2 3\nnan 0 0\n")
file(WRITE ${in}/nan_cloud_scene.yaml "world:\n  point_clouds:\n    - {id: scan, file: nan_cloud.pcd}\n")
ropras_cli_test(check_collision.cloud_scene 0 ".*" check-collision --urdf ${arm_urdf} --srdf ${arm_srdf} --scenes
                ${cloud_scene} --samples 500)
ropras_cli_test(check_collision.cloud_missing 2
                "missing_cloud_scene.yaml:3: world.point_clouds\\[0\\] 'scan'.file: point cloud '[^']*gone.pcd'"
                check-collision --urdf ${arm_urdf} --scenes ${in}/missing_cloud_scene.yaml --samples 10)
ropras_cli_test(check_collision.cloud_nan 2 "nan_cloud_scene.yaml:3: .*nan_cloud.pcd': point 1 is \\(nan, 0, 0\\)"
                check-collision --urdf ${arm_urdf} --scenes ${in}/nan_cloud_scene.yaml --samples 10)
ropras_cli_test(plan.cloud_missing 2 "missing_cloud_scene.yaml:3: .*gone.pcd" plan --urdf ${arm_urdf} --scene
                ${in}/missing_cloud_scene.yaml --request ${in}/request.yaml)
ropras_cli_test(bench_collision.cloud_scene 0 ".*" bench-collision --urdf ${arm_urdf} --scenes ${in}/cloudscenes
                --repeat 1 --configs 50 --edges 4 --fcl-configs 10)
ropras_cli_test(bench_mbm.cloud_scene 0 ".*" bench-mbm --urdf ${arm_urdf} --srdf ${arm_srdf} --problems ${in}
                --categories cloudscenes --time 0.5 --checkers ropras,fcl_sphere --quiet)
