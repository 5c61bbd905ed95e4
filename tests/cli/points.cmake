# candela points: illuminance CSV at Radiance-style sensor points (fixtures in tests/data/points).
# room.rad is one 2 m × 2 m light panel (radiance 100) 3 m up, facing down, and nothing else, so
# every value is exact: the panel is wholly visible and the control variate leaves no noise.
# run_cli.sh searches the output with grep -F, one line at a time: expected strings hold no
# newline; a value is anchored by the comma of the error_lux column that follows it.
set(PTS points --points points/desk.pts --quality draft)

candela_cli_test(points.header 0 "x,y,z,dx,dy,dz,illuminance_lux" ${PTS} points/room.rad)
# Under the panel's centre, 2.25 m below it: four 1 m × 1 m corner rectangles (Howell B-3),
# E = 179·π·100·4·F(1/2.25, 1/2.25) = 11218.4965 lux; its standard error is 0.
candela_cli_test(points.value 0 "1,1,0.75,0,0,1,11218.5,0" ${PTS} points/room.rad --error)
candela_cli_test(points.error_column 0 "x,y,z,dx,dy,dz,illuminance_lux,error_lux" ${PTS} points/room.rad --error)
# The direction "0 0 2" is normalised; the blank line and the comment are skipped.
candela_cli_test(points.normalised 0 "0.5,1.5,0.75,0,0,1," ${PTS} points/room.rad)
# No scene: nothing to see.
candela_cli_test(points.no_scene 0 "1,1,0.75,0,0,1,0,0" ${PTS} --error)
# Points from stdin (run_cli.sh feeds STDIN_FILE).
candela_cli_test(points.stdin 0 "1,1,0.75,0,0,1,11218.5,0" points points/room.rad --quality draft --error)
set_tests_properties(cli.points.stdin PROPERTIES ENVIRONMENT "STDIN_FILE=${DATA}/points/desk.pts")

# The same panel as a Wavefront OBJ face listed before the file of its material (OBJ files are
# read after the Radiance files): its usemtl lamp has half the radiance, so half the value
# (5609.24825 lux); mapped to room.rad's material by a mapping file, room.rad's value.
candela_cli_test(points.obj 0 "1,1,0.75,0,0,1,5609.248,0" ${PTS} points/panel.obj points/panel_materials.rad --error)
candela_cli_test(points.obj_map 0 "1,1,0.75,0,0,1,11218.5,0"
                 ${PTS} points/panel.obj points/panel_materials.rad --obj-map points/panel.map --error)
candela_cli_test(points.obj_undefined 2 "panel.obj:7: modifier 'lamp' (usemtl) is not defined" ${PTS} points/panel.obj)

# Bad input: exit 2, one line on stderr naming the file and line, nothing on stdout.
candela_cli_test(points.bad_line 2 "points/bad_line.pts:3: a sensor point needs 6 numbers"
                 points points/room.rad --points points/bad_line.pts)
candela_cli_test(points.bad_scene 2 "bad.rad:4: polygon 'panel' needs at least 3 vertices, got 2" ${PTS} points/bad.rad)
candela_cli_test(points.missing_scene 2 "points/no_such.rad" ${PTS} points/no_such.rad)
candela_cli_test(points.missing_points 2 "points/no_such.pts" points points/room.rad --points points/no_such.pts)
# An annual case is a whole year: `points` refuses it at the [sky] line and points to `run`.
candela_cli_test(points.annual_case 2 "annual/case.toml:8: an annual sky is a whole year: `candela run` computes it"
                 ${PTS} --case ${PROJECT_SOURCE_DIR}/tests/cli/run/annual/case.toml)

# Absurd option values are refused up front (exit 2), never run for hours or ended in exit 1.
candela_cli_test(points.absurd_samples 2 "--samples: Value 2000000000 not in range 1 to 1000000"
                 ${PTS} points/room.rad --samples 2000000000)
candela_cli_test(points.absurd_bounces 2 "--bounces" ${PTS} points/room.rad --bounces 1000000)
# Inputs that are not regular files: a device would be read forever, a folder is no points file.
candela_cli_test(points.device_scene 2 "/dev/zero: the scene file is a device, not a regular file" ${PTS} /dev/zero)
candela_cli_test(points.folder_points 2 "the points file is a folder, not a regular file"
                 points points/room.rad --points points)
# A finite but huge coordinate once aborted the process inside Embree (exit 134).
candela_cli_test(points.far_point 2 "points/far_point.pts:2: a sensor point lies beyond 1e7 m from the origin"
                 points points/room.rad --points points/far_point.pts)
# A direction of 1e200 was normalised to (0, 0, 0) and aborted the process inside Embree (exit 134).
candela_cli_test(points.huge_direction 2 "points/huge_direction.pts:2: sensor direction (1e+200 0 0) cannot be normalised"
                 points points/room.rad --points points/huge_direction.pts)
# Points from an endless stdin without newlines (/dev/zero) once ate memory: the line is bounded.
candela_cli_test(points.endless_stdin 2 "<stdin>:1: a sensor point line is longer than 65536 characters"
                 points points/room.rad)
set_tests_properties(cli.points.endless_stdin PROPERTIES ENVIRONMENT "STDIN_FILE=/dev/zero")

# Patterns candela cannot use (here: its function file is absent): refused with how to proceed;
# --patterns base uses the material unmodified (room.rad's exact value) and says so in a warning
# naming the pattern's line.
candela_cli_test(points.pattern_refused 2
                 "points/patterned.rad:4: specfunc 'dimmer': function file 'rainbow.cal' is not in the working directory, in RAYPATH or in points; run with --patterns base"
                 ${PTS} points/patterned.rad)
candela_cli_test(points.pattern_base 0 "1,1,0.75,0,0,1,11218.5,0" ${PTS} points/patterned.rad --patterns base --error)
candela_cli_test(points.pattern_base_warning 0 "warning: points/patterned.rad:4: specfunc 'dimmer' (rainbow.cal) cannot be read"
                 ${PTS} points/patterned.rad --patterns base)
candela_cli_test(points.pattern_bad_policy 2 "unknown pattern policy 'ignore' (expected refuse or base)"
                 ${PTS} points/patterned.rad --patterns ignore)

# --portal: openings that guide sky sampling (docs/daylight.md#portals). Open sky, no scene: a
# portal changes nothing but the noise; a bad line is an error at its line.
candela_cli_test(points.portal 0 "x,y,z,dx,dy,dz,illuminance_lux" ${PTS} --sky uniform --portal points/roof_portal.txt)
candela_cli_test(points.portal_bad_line 2 "points/bad_portal.txt:2: 'x' is not a number"
                 ${PTS} --sky uniform --portal points/bad_portal.txt)
candela_cli_test(points.portal_missing 2 "no_such_portals.txt" ${PTS} --sky uniform --portal points/no_such_portals.txt)
