# The validation suite runs with every test command (issue "Validation suite"); it fails when any
# case is outside its tolerance (exit code 1): every case at the default quality (what users run)
# and every case at high quality. The default run goes without --out, in an empty folder: the
# files go to validation-results/ there, and nothing else is written.
add_test(NAME cli.validate_all_default
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/validate_default_out.sh $<TARGET_FILE:candela>)
candela_cli_test(validate_all_high 0 "0 failed" validate --quality high --out ${CMAKE_BINARY_DIR}/validation-high)
# An --out that cannot be a folder is exit 2 before any case runs (no table on stdout).
candela_cli_test(validate_out_is_file 2 "cannot be created" validate --quick --out ${DATA}/rad/good.rad)
# The two longest tests of the suite start first (a fresh CI has no timing of an earlier run for
# ctest to order by), so that the other core works through the short ones meanwhile.
set_tests_properties(cli.validate_all_default cli.validate_all_high PROPERTIES COST 10000)
