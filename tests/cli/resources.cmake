# Resource bounds (docs/reliability.md): cases whose memory exceeds --max-memory are refused up
# front with exit 2 and the estimate at the line of the largest item; the estimate against a
# measured peak.
set(RES ${CMAKE_CURRENT_SOURCE_DIR}/resources)
set(RUN_CASE ${CMAKE_CURRENT_SOURCE_DIR}/run_case.sh)
# A valid 16384 x 16384 view: refused at its [[view]] line, by run and by render; a small view of
# the same case renders under the same limit.
add_test(NAME cli.resources.big_view_run COMMAND ${RUN_CASE} 2 "big_view.toml:18: view 'x' needs about"
         $<TARGET_FILE:candela> ${RES}/big_view.toml --max-memory 1G)
add_test(NAME cli.resources.big_view_limit_named COMMAND ${RUN_CASE} 2 "in all, more than allowed (--max-memory 1.0 GiB)"
         $<TARGET_FILE:candela> ${RES}/big_view.toml --max-memory 1G)
candela_cli_test(resources.big_view_render 2 "big_view.toml:18: view 'x' needs about"
                 render ${RES}/big_view.toml --view x --max-memory 1G --out ${CMAKE_CURRENT_BINARY_DIR}/res_out)
candela_cli_test(resources.small_view_render 0 "view small: 32 x 24"
                 render ${RES}/big_view.toml --view small --max-memory 1G --out ${CMAKE_CURRENT_BINARY_DIR}/res_out)
# A 10⁷-point grid (3637 x 2728): refused at its [[grid]] line before its points are made.
add_test(NAME cli.resources.huge_grid COMMAND ${RUN_CASE} 2 "huge_grid.toml:3: grid 'floor' needs about"
         $<TARGET_FILE:candela> ${RES}/huge_grid.toml --max-memory 1G)
# Units: 8G, 512M, 1.5GiB or a plain number of GiB; anything else is a usage error.
candela_cli_test(resources.bad_unit 2 "--max-memory" run ${RES}/big_view.toml --max-memory 8X)
candela_cli_test(resources.points 2 "points/desk.pts: the input of"
                 points --points points/desk.pts --quality draft points/room.rad --max-memory 1K)
# The estimate against the measured peak resident set, within a factor 1.5 (docs/reliability.md).
add_test(NAME cli.resources.peak_view COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/peak_memory.sh 1.5 $<TARGET_FILE:candela>
         render ${RES}/peak_view.toml --view v --out ${CMAKE_CURRENT_BINARY_DIR}/res_peak
         --pixel-samples 1 --irradiance-samples 0 --bounces 0 -q)
add_test(NAME cli.resources.peak_grid COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/peak_memory.sh 1.5 $<TARGET_FILE:candela>
         run ${RES}/peak_grid.toml --out ${CMAKE_CURRENT_BINARY_DIR}/res_peak_run --bounces 0 --samples 4 -q)
# The annual study, past one block of sensors: its peak is the block's, not the grid's hours.
add_test(NAME cli.resources.peak_annual COMMAND ${CMAKE_CURRENT_SOURCE_DIR}/peak_memory.sh 1.5 $<TARGET_FILE:candela>
         run ${RES}/peak_annual.toml --out ${CMAKE_CURRENT_BINARY_DIR}/res_peak_annual --bounces 0 --samples 4 -q)
set_tests_properties(cli.resources.peak_view cli.resources.peak_grid cli.resources.peak_annual PROPERTIES SKIP_RETURN_CODE 77
                     WORKING_DIRECTORY ${DATA})
# A 1000 × 1000 luminaire array is refused before its luminaires are placed (placing them takes
# about a minute), at its [[luminaire]] line.
add_test(NAME cli.resources.luminaire_array COMMAND ${RUN_CASE} 2
         "luminaire_array.toml:3: the data of 1000000 luminaires needs about 1.3 GiB"
         $<TARGET_FILE:candela> ${RES}/luminaire_array.toml --max-memory 100M)
set_tests_properties(cli.resources.luminaire_array PROPERTIES TIMEOUT 30)
