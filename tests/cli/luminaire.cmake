# candela luminaire: summary on stdout, polar plot SVG (written into the build tree here).
set(LUM_SVG ${CMAKE_CURRENT_BINARY_DIR}/luminaire_polar.svg)
candela_cli_test(luminaire.ies 0 "Luminous flux:" luminaire ies/lambert_full.ies --svg ${LUM_SVG})
candela_cli_test(luminaire.ldt 0 "Format:               EULUMDAT" luminaire ldt/asym_isym0.ldt --svg ${LUM_SVG})
candela_cli_test(luminaire.no_svg 0 "Beam angle (50%):" luminaire ies/typeb.ies --no-svg)
candela_cli_test(luminaire.case_panel_ies 0 "LED panel 600 x 600 mm" luminaire
                 ${PROJECT_SOURCE_DIR}/cases/luminaires/led_panel_600.ies --svg ${LUM_SVG})
candela_cli_test(luminaire.case_panel_ldt 0 "LED panel 600 x 600 mm" luminaire
                 ${PROJECT_SOURCE_DIR}/cases/luminaires/led_panel_600.ldt --svg ${LUM_SVG})
candela_cli_test(luminaire.case_downlight 0 "IES LM-63-2019" luminaire
                 ${PROJECT_SOURCE_DIR}/cases/luminaires/downlight_150.ies --svg ${LUM_SVG})
candela_cli_test(luminaire.bad_ies 2 "bad_negative.ies:11:" luminaire ies/bad_negative.ies --svg ${LUM_SVG})
candela_cli_test(luminaire.bad_ldt 2 "bad_isym.ldt:3:" luminaire ldt/bad_isym.ldt --svg ${LUM_SVG})
candela_cli_test(luminaire.missing 2 "cannot open file" luminaire ies/no_such.ies --svg ${LUM_SVG})
candela_cli_test(luminaire.unknown_type 2 "expected .ies or .ldt" luminaire ies/tilt_table.tlt --svg ${LUM_SVG})
# An output path named on the command line is a regular file or a new name: as root,
# `--svg /dev/null` once replaced the device node with a file.
candela_cli_test(luminaire.svg_device 2 "/dev/null: the output is a device; only a regular file is replaced"
                 luminaire ies/lambert_full.ies --svg /dev/null)
# Control characters of a hostile first line are escaped in the one error line.
candela_cli_test(luminaire.escaped_message 2 "unknown IES edition 'IESNA:LM-63-2002\\x1b]0;pwned"
                 luminaire ies/escape_sequences.ies --no-svg)
# --ugr-table: the CIE 190 UGR table of manufacturers' files (tests/data/reference, read only); a
# file without a luminous area is refused at the line of its opening.
set(UGR_REF ${PROJECT_SOURCE_DIR}/tests/data/reference/photometry/eulumdat-rs)
set(UGR_OUT --ugr-csv ${CMAKE_CURRENT_BINARY_DIR}/luminaire_ugr.csv --ugr-svg ${CMAKE_CURRENT_BINARY_DIR}/luminaire_ugr.svg)
candela_cli_test(luminaire.ugr_table_ldt 0 "Viewed crosswise" luminaire ${UGR_REF}/fluorescent_luminaire.ldt
                 --no-svg --ugr-table ${UGR_OUT})
candela_cli_test(luminaire.ugr_table_ies 0 "luminaire flux, absolute photometry" luminaire
                 ${UGR_REF}/ABSOLUTE_LED.ies --no-svg --ugr-table ${UGR_OUT})
candela_cli_test(luminaire.ugr_point_source 2
                 "OutdoorRoadway IES OS 8988-2022 03 AM01 60W 4000K.ies:18: luminous opening is a point"
                 luminaire "${UGR_REF}/OutdoorRoadway IES OS 8988-2022 03 AM01 60W 4000K.ies" --no-svg --ugr-table
                 ${UGR_OUT})
candela_cli_test(luminaire.ugr_csv_device 2 "/dev/null: the output is a device" luminaire
                 ${UGR_REF}/fluorescent_luminaire.ldt --no-svg --ugr-table --ugr-csv /dev/null)
add_test(NAME cli.luminaire.ugr_default_out
         COMMAND bash ${CMAKE_CURRENT_SOURCE_DIR}/luminaire_ugr_default_out.sh $<TARGET_FILE:candela>
                 ${UGR_REF}/fluorescent_luminaire.ldt ${PROJECT_SOURCE_DIR}/tests/data/ies/lambert_full.ies)
