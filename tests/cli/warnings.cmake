# Warnings (docs/warnings.md): without --strict the command succeeds, prints each warning as one
# line on stderr (also with --quiet) and summary.json holds it; with --strict the first warning is
# the one error line (exit 2) and nothing is written.
set(WARN ${DATA}/study/warnings)
candela_run_test(warning_in_summary 0 "\"code\": \"grid_spacing_exceeds_extent\"" ${WARN}/spacing.toml)
candela_run_test(warning_on_stderr 0 "warning: ${WARN}/spacing.toml:12: grid 'wide': spacing 5 m exceeds"
                 ${WARN}/spacing.toml)
candela_run_test(warning_strict 2 "${WARN}/spacing.toml:12: grid 'wide': spacing 5 m exceeds its calculation area"
                 ${WARN}/spacing.toml --strict)
candela_run_test(warning_strict_no_light 2 "dark_view.toml: the scene has no light source" ${WARN}/dark_view.toml
                 --strict)
candela_cli_test(points.warning 0 "warning: study/warnings/sensors.pts:5: points: 1 of 10 sensor points lies on or within 5 mm"
                 points study/warnings/room.rad --sky cie-overcast --quality draft --points study/warnings/sensors.pts)
candela_cli_test(points.warning_strict 2 "study/warnings/sensors.pts:5: points: 1 of 10 sensor points lies on or within 5 mm"
                 points study/warnings/room.rad --sky cie-overcast --quality draft --points study/warnings/sensors.pts
                 --strict)
candela_cli_test(render.warning_strict 2 "dark_view.toml: the scene has no light source" render
                 study/warnings/dark_view.toml --view look --out render_strict_never_written --strict)
candela_cli_test(render.warning 0 "warning: study/warnings/dark_view.toml: the scene has no light source" render
                 study/warnings/dark_view.toml --view look --out ${CMAKE_CURRENT_BINARY_DIR}/render_warning --quiet)
