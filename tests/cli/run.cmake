# candela run: a good case writes every output; each bad case exits 2 with one line naming the
# file and line, and leaves no output folder behind (run_case.sh checks both).
set(RUN_CASE ${CMAKE_CURRENT_SOURCE_DIR}/run_case.sh)
set(RUN_DATA ${CMAKE_CURRENT_SOURCE_DIR}/run)

# candela_run_test(NAME EXIT_CODE EXPECT_SUBSTRING CASE [ARGS...])
function(candela_run_test name code expect case_file)
  add_test(NAME cli.run.${name} COMMAND ${RUN_CASE} ${code} "${expect}" $<TARGET_FILE:candela> ${case_file} ${ARGN})
  set_tests_properties(cli.run.${name} PROPERTIES WORKING_DIRECTORY ${RUN_DATA})
endfunction()

candela_run_test(small_room 0 "\"name\": \"workplane\"" ${PROJECT_SOURCE_DIR}/cases/small-room/case.toml --quality draft)
candela_run_test(bad_key 2 "bad_key/case.toml:8: unknown key 'hieght'" bad_key/case.toml)
candela_run_test(missing_scene 2 "missing_scene/case.toml:3: scene file 'no_such_room.rad' not found"
                 missing_scene/case.toml)
candela_run_test(bad_scene 2 "bad.rad:6: polygon 'broken' needs at least 3 vertices" bad_scene/case.toml)
# A grid beyond the box of the scene and its luminaires is a warning (it was refused; a car park
# over a flat ground could not be computed).
candela_run_test(grid_outside 0 "outside/case.toml:9: grid 'terrace' reaches outside the scene" outside/case.toml --quality draft)
candela_run_test(gensky_sky 0 "\"sky\": \"scene:gensky CIE overcast (skybright.cal)\"" gensky_sky/case.toml --quality draft)
candela_run_test(gensky_sky_replaced 0 "[scene_sky_replaced]" gensky_sky/replaced.toml --quality draft)
candela_run_test(gensky_bad_option 2 "sky.rad:3: gensky: unknown option '-z'" gensky_bad/case.toml)
candela_run_test(df_needs_overcast 2 "df_needs_overcast/case.toml:5: grid 'df': daylight_factor needs"
                 df_needs_overcast/case.toml)
candela_run_test(daylight_factor 0 "\"unit\": \"%\"" daylight_factor/case.toml)
candela_run_test(same_csv 2 "same_file/case.toml:10: grids 'a b' and 'a_b' would both write a_b.csv"
                 same_file/case.toml)
candela_run_test(grid_named_summary 2 "grid_named_summary/case.toml:5: grid name 'summary'"
                 grid_named_summary/case.toml)
# A sensor direction of 1e200 once aborted the process inside Embree (exit 134).
candela_run_test(huge_direction 2 "huge_direction/sensors.pts:2: sensor direction (1e+200 0 0) cannot be normalised"
                 huge_direction/case.toml)
candela_run_test(missing_case 2 "no_such_case.toml" no_such_case.toml)
# Options are checked by the command-line parser before anything is read.
candela_run_test(bad_quality 2 "--quality" ${PROJECT_SOURCE_DIR}/cases/small-room/case.toml --quality best)
# Views with contrast keys: the report carries the contrast rendition factor.
candela_run_test(view_contrast 0 "Contrast rendition factor" view_contrast/case.toml --quality draft)
# Annual daylight ([sky] type = "annual"): the summary carries LM-83's names; bad annual input is
# refused before anything is traced.
candela_run_test(annual 0 "\"sDA300_50\"" annual/case.toml)
candela_run_test(annual_needs_annual_sky 2 "annual_no_sky/case.toml:4: an [annual] table needs [sky] type = \"annual\""
                 annual_no_sky/case.toml)
candela_run_test(annual_needs_full_year 2 "one_day.epw:32: the file ends after 24 hourly records; an annual study needs a full year" annual_short_epw/case.toml)
candela_run_test(annual_report_sensor 2 "annual_bad_sensor/case.toml:9: report_sensor 99 is beyond grid 'desk'"
                 annual_bad_sensor/case.toml)

# Patterns: refused at their line by default; [settings] patterns = "base" (or --patterns base)
# runs with the material unmodified and the replacement in summary.json and the report.
candela_run_test(pattern_refused 2 "pattern_base/room.rad:8: specfunc 'dimmer': function file 'rainbow.cal' is not in the working directory"
                 pattern_base/refused.toml)
# A function pattern read from its .cal file beside the scene; summary.json names the file.
candela_run_test(function_pattern 0 "function_pattern/checker.cal" function_pattern/case.toml --quality draft)
candela_run_test(pattern_base_summary 0 "\"code\": \"pattern_replaced\"" pattern_base/case.toml --quality draft)
candela_run_test(pattern_base_option 0 "\"code\": \"pattern_replaced\"" pattern_base/refused.toml --quality draft --patterns base)

# An OBJ file as a [[scene]], its materials in a Radiance file listed after it (docs/engine.md):
# the panel's exact illuminance, 11218.4965 lx.
candela_run_test(obj_scene 0 "\"average\": 11218.49" obj_scene/case.toml --quality draft)

# Modelling (EN 12464-1:2021, docs/quantities.md): summary.json's grids[i].modelling holds the
# averages of the grid's cylindrical and horizontal CSV columns, their ratio and its verdict; a
# cylindrical grid takes its own values as Ē_z. A modelling grid away from 1.2 m and 1.6 m is
# warned of at its `modelling` line.
add_test(NAME cli.run.modelling COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/modelling.sh $<TARGET_FILE:candela>
         ${RUN_DATA}/modelling/case.toml 0:seated 1:standing)
candela_run_test(modelling_summary 0 "\"horizontal_average_lux\"" modelling/case.toml)
candela_run_test(modelling_height_warning 0 "modelling (EN 12464-1:2021) is assessed at 1.2 m (seated) or 1.6 m (standing) above the floor; this grid has a point at 0.8 m"
                 ${DATA}/study/quantities.toml)
candela_run_test(quantity_unknown 2 "quantity_unknown.toml:8: unknown quantity 'cylinder'"
                 ${DATA}/cases/errors/quantity_unknown.toml)
candela_run_test(quantity_needs_facing 2 "quantity_missing_facing.toml:8: quantity \"vertical\" needs 'facing'"
                 ${DATA}/cases/errors/quantity_missing_facing.toml)
# EN 12464-1:2021 task areas (docs/en12464.md): the task area, its surrounding and background as
# grids with their own CSVs, and the task area's verdict in summary.json.
candela_run_test(task_area 0 "\"surrounding_grid\": \"desk surrounding\"" task_area/case.toml --quality draft)
candela_run_test(task_area_bad 2 "no_corners.toml:1: a task area needs 'corners'" task_area/no_corners.toml)
# Walls and ceilings (docs/en12464.md): [[surface_grid]] grids in summary.json; a pattern that names
# no surface at the line of 'surfaces'.
candela_run_test(surface_grid 0 "\"room_surface\": \"wall\"" surface_grid/case.toml)
candela_run_test(surface_grid_typo 2 "typo.toml:5: no surface of the scene is named 'cieling'" surface_grid/typo.toml)
# Energy and the luminaire schedule (docs/en12464.md): summary.json's energy and luminaires, a
# bad power_w at its line, and a luminaire of unknown power warned of at its entry.
candela_run_test(energy_summary 0 "\"power_density_w_m2_per_100lx\"" ${PROJECT_SOURCE_DIR}/cases/small-room/case.toml
                 --quality draft)
candela_run_test(power_w_bad 2 "bad_power_w.toml:5: 'power_w' must be greater than 0 W" ${DATA}/cases/errors/bad_power_w.toml)
candela_run_test(floor_area_bad 2 "bad_floor_area.toml:4: 'floor_area' must be greater than 0" ${DATA}/cases/errors/bad_floor_area.toml)
candela_run_test(power_unknown_warning 0 "power_unknown/case.toml:7: luminaire 'spot': its photometric file defined.ies gives no input power"
                 power_unknown/case.toml)
candela_run_test(power_unknown_summary 0 "\"installed_power_is_lower_bound\": true" power_unknown/case.toml)
# [[compliance]] (docs/compliance.md): refused in a point-in-time case and, for another standard's
# key, at that key's line.
candela_run_test(compliance_needs_annual 2 "point_in_time.toml:10: [[compliance]] needs an annual study"
                 compliance/point_in_time.toml)
candela_run_test(compliance_other_standard 2 "typo.toml:13: 'view_points' belongs to standard = \"en17037\""
                 compliance/typo.toml)
# A glare view's check hours: the form when the case is read, the weather year's hours before any
# tracing.
candela_run_test(compliance_check_hour_form 2 "bad_hour.toml:17:" compliance/bad_hour.toml)
candela_run_test(compliance_check_hour_not_in_year 2
                 "leap_day.toml:17: 'check_hours': 2028-02-29T12:00 is not an hour of the weather file"
                 compliance/leap_day.toml)
# EN 1838 tables (docs/emergency.md): bad input exits 2 naming its line.
candela_run_test(en1838_route_one_point 2 "en1838_route_one_point.toml:4: 'path' needs at least 2 points"
                 ${DATA}/cases/errors/en1838_route_one_point.toml)
candela_run_test(en1838_route_width 2 "en1838_route_width.toml:4: 'width' must be greater than 0"
                 ${DATA}/cases/errors/en1838_route_width.toml)
candela_run_test(en1838_open_area_corners 2 "en1838_open_area_corners.toml:4: 'polygon' needs at least 3 corners"
                 ${DATA}/cases/errors/en1838_open_area_corners.toml)
# EN 13201 roads (docs/road.md): bad input exits 2 naming its line.
candela_run_test(en13201_bad_class 2 "en13201_bad_class.toml:7: unknown road lighting class 'ME3'"
                 ${DATA}/cases/errors/en13201_bad_class.toml)
candela_run_test(en13201_surface_w4 2 "en13201_surface_w4.toml:8: 'surface' W4 is no r-table candela has"
                 ${DATA}/cases/errors/en13201_surface_w4.toml)
candela_run_test(en13201_no_compliance 2 "en13201_no_compliance.toml:2: [[road]] needs a [[compliance]] entry"
                 ${DATA}/cases/errors/en13201_no_compliance.toml)
candela_run_test(en13201_lanes 2 "en13201_lanes.toml:7: 'lanes' must be between 1 and 20"
                 ${DATA}/cases/errors/en13201_lanes.toml)
# The road example runs and reports its road.
candela_run_test(road_example 0 "\"edge_illuminance_ratio\"" ${PROJECT_SOURCE_DIR}/cases/road/case.toml)
# EN 12464-2 outdoor task areas and GR observers (docs/outdoor.md): bad input exits 2 naming its line.
candela_run_test(en12464_2_gr_limit 2 "en12464_2_gr_limit.toml:6: 'gr_limit' must be between 10 and 90"
                 ${DATA}/cases/errors/en12464_2_gr_limit.toml)
candela_run_test(en12464_2_observer_kind 2 "en12464_2_observer_kind.toml:3: an observer's 'kind' must be"
                 ${DATA}/cases/errors/en12464_2_observer_kind.toml)
candela_run_test(en12464_2_no_reflectance 2 "en12464_2_no_reflectance.toml:3: task area 'yard': no surface of the scene lies under it"
                 ${DATA}/cases/errors/en12464_2_no_reflectance.toml)
