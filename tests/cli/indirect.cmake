# candela points --method cache and --target-error (fixtures in tests/data/points, see points.cmake:
# one light panel and nothing else, so every value is exact whatever the method).
candela_cli_test(points.cache_exact 0 "1,1,0.75,0,0,1,11218.5,0" points points/room.rad --points points/desk.pts
                 --quality draft --method cache --error)
candela_cli_test(points.target_error_exact 0 "1,1,0.75,0,0,1,11218.5,0" points points/room.rad
                 --points points/desk.pts --quality draft --target-error 1 --error)
candela_cli_test(points.bad_method 2 "--method: method must be path or cache, not 'bogus'" points points/room.rad
                 --points points/desk.pts --method bogus)
candela_cli_test(points.bad_target_error 2 "--target-error" points points/room.rad --points points/desk.pts
                 --target-error 101)
# --target-error 0: one batch per point, as before the presets had a target (the same numbers as
# --quality normal with the target off, whatever the point's error).
candela_cli_test(points.target_error_off 0 "1,1,0.75,0,0,1," points points/room.rad
                 --points points/desk.pts --target-error 0)
# The speed-accuracy study, quick form: both methods on every scene, CSV and SVG written.
candela_cli_test(validate.chart_quick 0 "furnished-office,cache" validate --chart --quick
                 --out ${CMAKE_BINARY_DIR}/speed-accuracy-quick)
