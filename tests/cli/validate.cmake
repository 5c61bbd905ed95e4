# The quick validation suite runs with every test command (issue "Validation suite"); it fails
# when any case is outside its tolerance (exit code 1).
candela_cli_test(validate_quick 0 "0 failed" validate --quick --out ${CMAKE_BINARY_DIR}/validation)
