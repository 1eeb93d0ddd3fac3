# `ropras view`: bad recordings, bad path CSVs, missing files and three.js (exit code 2, the file named), and controls
# (a recording and a motion of the shipped arm that it accepts). Included by test/cli/CMakeLists.txt after the
# recordings of `render` (no_scene_recording.json, malformed_recording.json, good_recording.json) are written.
set(arm_joints shoulder_pan_joint,shoulder_lift_joint,elbow_joint,wrist_1_joint,wrist_2_joint,wrist_3_joint)
file(WRITE ${in}/arm_path.csv "${arm_joints}\n0,0,0,0,0,0\n0.3,0.3,0.3,0.3,0.3,0.3\n")
file(WRITE ${in}/arm_path_empty.csv "")
file(WRITE ${in}/arm_path_header_only.csv "${arm_joints}\n")
file(WRITE ${in}/arm_path_unknown_joint.csv "shoulder_pan_joint,elbow_jiont\n0,0\n")
file(WRITE ${in}/arm_path_missing_joint.csv "shoulder_pan_joint\n0\n")
file(WRITE ${in}/arm_path_nan.csv "${arm_joints}\n0,0,nan,0,0,0\n")
file(WRITE ${in}/arm_path_text.csv "${arm_joints}\n0,0,0.1x,0,0,0\n")
file(WRITE ${in}/arm_path_short_row.csv "${arm_joints}\n0,0,0,0,0,0\n0,0,0\n")
file(WRITE ${in}/arm_path_limits.csv "${arm_joints}\n0,0,0,0,0,0\n0,0,0,0,0,1e6\n")
set(rec_head "{\"scene\": {\"bounds\": [[0, 0], [2, 2]]}, \"trajectory\": [[[0.5, 0.5]], [[1, 1]]]")
file(WRITE ${in}/view_robot_count.json
     "${rec_head}, \"robot\": {\"urdf\": \"embedded:navigation/maze2d/robot.urdf\", \"configurations\": [[0.5]]}}\n")
file(WRITE ${in}/view_robot_nan.json
     "${rec_head}, \"robot\": {\"urdf\": \"embedded:navigation/maze2d/robot.urdf\", "
     "\"configurations\": [[0.5, 0.5], [1, null]]}}\n")
file(WRITE ${in}/view_robot_unknown_urdf.json
     "${rec_head}, \"robot\": {\"urdf\": \"missing_robot.urdf\", \"configurations\": [[0.5, 0.5], [1, 1]]}}\n")
file(WRITE ${in}/view_bad_rays.json "${rec_head}, \"rays\": [{\"step\": 0, \"segments\": [[[0, 0, 0]]]}]}\n")
file(WRITE ${in}/view_huge_number.json "${rec_head}, \"rewards\": [1e400]}\n")

set(arm_motion view --urdf ${arm_urdf} --srdf ${arm_srdf} --scene ${scene} --out ${in}/view_out.html --path)
ropras_cli_test(view.missing_recording 2 "File does not exist: .*no_recording.json" view ${in}/no_recording.json)
ropras_cli_test(view.malformed_recording 2 "recording \".*malformed_recording.json\": malformed JSON" view
                ${in}/malformed_recording.json --out ${in}/view_out.html)
ropras_cli_test(view.huge_number 2 "view_huge_number.json\": malformed JSON.*1e400" view ${in}/view_huge_number.json
                --out ${in}/view_out.html)
ropras_cli_test(view.no_scene 2 "no_scene_recording.json: key \"scene\" is missing" view
                ${in}/no_scene_recording.json --out ${in}/view_out.html)
ropras_cli_test(view.robot_configuration_count 2
                "view_robot_count.json: robot.configurations has 1 entries, the trajectory 2 steps" view
                ${in}/view_robot_count.json --out ${in}/view_out.html)
ropras_cli_test(view.robot_configuration_nan 2
                "view_robot_nan.json: robot.configurations\\[1\\]\\[1\\] must be a finite number, not null" view
                ${in}/view_robot_nan.json --out ${in}/view_out.html)
ropras_cli_test(view.robot_urdf_missing 2 "missing_robot.urdf" view ${in}/view_robot_unknown_urdf.json --out
                ${in}/view_out.html)
ropras_cli_test(view.bad_rays 2 "view_bad_rays.json: rays\\[0\\].segments\\[0\\] must be \\[origin, end\\]" view
                ${in}/view_bad_rays.json --out ${in}/view_out.html)
ropras_cli_test(view.recording_and_motion 2 "give either a recording .* or a motion" view ${in}/good_recording.json
                --urdf ${arm_urdf} --path ${in}/arm_path.csv)
ropras_cli_test(view.path_without_urdf 2 "give either a recording .* or a motion|needs both --urdf and --path"
                view --path ${in}/arm_path.csv)
ropras_cli_test(view.missing_path 2 "--path: File does not exist: .*no_path.csv" ${arm_motion} ${in}/no_path.csv)
ropras_cli_test(view.path_empty 2 "path CSV '.*arm_path_empty.csv': the file is empty" ${arm_motion}
                ${in}/arm_path_empty.csv)
ropras_cli_test(view.path_no_rows 2 "path CSV '.*arm_path_header_only.csv': no waypoints after the header"
                ${arm_motion} ${in}/arm_path_header_only.csv)
ropras_cli_test(view.path_unknown_joint 2 "arm_path_unknown_joint.csv':1: header names 'elbow_jiont', which is not"
                ${arm_motion} ${in}/arm_path_unknown_joint.csv)
ropras_cli_test(view.path_missing_joint 2 "arm_path_missing_joint.csv':1: header lacks joint 'shoulder_lift_joint'"
                ${arm_motion} ${in}/arm_path_missing_joint.csv)
ropras_cli_test(view.path_nan 2 "arm_path_nan.csv':2: joint 'elbow_joint': 'nan' is not a finite number"
                ${arm_motion} ${in}/arm_path_nan.csv)
ropras_cli_test(view.path_text 2 "arm_path_text.csv':2: joint 'elbow_joint': '0.1x' is not a finite number"
                ${arm_motion} ${in}/arm_path_text.csv)
ropras_cli_test(view.path_short_row 2 "arm_path_short_row.csv':3: has 3 values, the header 6 joints" ${arm_motion}
                ${in}/arm_path_short_row.csv)
ropras_cli_test(view.path_outside_limits 2 "arm_path_limits.csv':3: joint 'wrist_3_joint' = 1e6 is outside its limits"
                ${arm_motion} ${in}/arm_path_limits.csv)
ropras_cli_test(view.path_dev_zero 2 "path CSV '/dev/zero': is a character device" view --urdf ${arm_urdf} --path
                /dev/zero --out ${in}/view_out.html)
ropras_cli_test(view.malformed_urdf 2 "malformed.urdf'?: malformed XML" view --urdf ${in}/malformed.urdf --path
                ${in}/arm_path.csv --out ${in}/view_out.html)
ropras_cli_test(view.zero_step 2 "--step: Value 0 must be" ${arm_motion} ${in}/arm_path.csv --step 0)
ropras_cli_test(view.unknown_tip 2 "no_such_link" ${arm_motion} ${in}/arm_path.csv --tip no_such_link)
ropras_cli_test(view.three_missing 2 "three.js '.*no_three/three.min.js'.*apt-get install libjs-three" view
                ${in}/good_recording.json --three ${in}/no_three --out ${in}/view_out.html)
ropras_cli_test(view.out_is_input 2 "--out '.*arm_path.csv' is the input" view --urdf ${arm_urdf} --path
                ${in}/arm_path.csv --out ${in}/arm_path.csv)
ropras_cli_test(view.unwritable_out 2 "--out: cannot write \".*no_such_dir/v.html\"" view ${in}/good_recording.json
                --out ${in}/no_such_dir/v.html)
# controls (need three.js; CI installs libjs-three)
ropras_cli_test(view.good_recording 0 "" view ${in}/good_recording.json --out ${in}/good_recording.html)
ropras_cli_test(view.good_motion 0 "" ${arm_motion} ${in}/arm_path.csv)
