# candela render: both projections render and report their glare ratings; bad input exits 2 with
# one line.
set(RENDER_CASE ${PROJECT_SOURCE_DIR}/tests/cli/render/case.toml)
set(RENDER_OUT ${CMAKE_CURRENT_BINARY_DIR}/render_out)
candela_cli_test(render.perspective 0 "luminaires, background" render ${RENDER_CASE} --view door --out ${RENDER_OUT})
candela_cli_test(render.perspective_files 0 "door.exr, ${RENDER_OUT}/door.png, ${RENDER_OUT}/door_preview.png"
                 render ${RENDER_CASE} --view door --out ${RENDER_OUT} --threads 1)
candela_cli_test(render.fisheye 0 "glare sources above" render ${RENDER_CASE} --view eye --out ${RENDER_OUT} --scale linear)
candela_cli_test(render.no_such_view 2 "render/case.toml: no [[view]] named 'nope' (views: door, eye)"
                 render ${RENDER_CASE} --view nope --out ${RENDER_OUT})
candela_cli_test(render.view_required 2 "--view" render ${RENDER_CASE})
candela_cli_test(render.bad_scale 2 "--scale" render ${RENDER_CASE} --view door --scale cubic)
candela_cli_test(render.missing_case 2 "no_such_case.toml" render no_such_case.toml --view door)
candela_cli_test(render.min_above_max 2 "--max must be above --min" render ${RENDER_CASE} --view door --min 100 --max 10)
candela_cli_test(render.log_min_zero 2 "--min must be above 0 cd/m2 on a log scale" render ${RENDER_CASE} --view door --min 0)
# Contrast: a floor point against the wall behind it (different materials), then two floor points
# (the same material: no reference contrast, refused).
candela_cli_test(render.contrast 0 ", CRF " render ${RENDER_CASE} --view door --out ${RENDER_OUT}
                 --task 2.0 2.5 0.0 --background 2.0 3.0 0.3)
candela_cli_test(render.contrast_same_material 2 "task and background look alike under the reference sphere"
                 render ${RENDER_CASE} --view door --out ${RENDER_OUT} --task 2.0 2.0 0.0 --background 2.0 2.5 0.0)
# The three pictures are one set: a render that cannot replace one of them replaces none.
add_test(NAME cli.render.keeps_previous_set COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/render_keeps_set.sh
         $<TARGET_FILE:candela> ${RENDER_CASE} door)
# The issue's contract from the command line: a matte floor (rho 0.5) under a uniform sky of
# 179 x 10 = 1790 cd/m2 reads rho L = 895 cd/m2 (E = pi L, L = rho E / pi) in every pixel, so the
# mean is 895.0 and its standard error 0 (tests/study/run_case_test.cpp checks every pixel).
candela_cli_test(render.glow_floor_exact 0 "luminance: mean 895.0 cd/m2 +/- 0.00 % (standard error)"
                 render ${PROJECT_SOURCE_DIR}/tests/data/study/glow_floor.toml --view down --out ${RENDER_OUT})
