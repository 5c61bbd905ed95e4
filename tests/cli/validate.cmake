# The validation suite runs with every test command (issue "Validation suite"); it fails when any
# case is outside its tolerance (exit code 1). Quick subset at the default quality, and every
# case at high quality (the small-aperture daylight cases need it: docs/validation.md).
candela_cli_test(validate_quick 0 "0 failed" validate --quick --out ${CMAKE_BINARY_DIR}/validation)
candela_cli_test(validate_all_high 0 "0 failed" validate --quality high --out ${CMAKE_BINARY_DIR}/validation-high)
