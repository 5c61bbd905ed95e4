# Distribution (docs/distributed.md): the same bytes for any split of a run. Each case's
# one-process result is made once (a fixture) and every split is compared with it. Shards and
# merge need no MPI; the mpirun tests run when candela is built with MPI and mpirun is installed,
# with the flags a root container needs (Open MPI refuses root, and more ranks than cores,
# otherwise).
set(DISTRIBUTED ${CMAKE_CURRENT_SOURCE_DIR}/distributed.sh)
set(DISTRIBUTED_REFERENCE ${CMAKE_BINARY_DIR}/distributed_reference)
find_program(MPIRUN mpirun)

# candela_distributed_case(NAME CASE ARGS...): the fixture and the shard test; with MPI, the
# mpirun test.
function(candela_distributed_case name case_file)
  set(ref ${DISTRIBUTED_REFERENCE}/${name})
  add_test(NAME cli.distributed.${name}.reference
           COMMAND bash ${DISTRIBUTED} reference 1 $<TARGET_FILE:candela> ${case_file} ${ref} ${ARGN})
  set_tests_properties(cli.distributed.${name}.reference PROPERTIES FIXTURES_SETUP distributed_${name})
  add_test(NAME cli.distributed.${name}.shards
           COMMAND bash ${DISTRIBUTED} shards 3 $<TARGET_FILE:candela> ${case_file} ${ref} ${ARGN})
  set(tests cli.distributed.${name}.shards)
  if(CANDELA_HAVE_MPI AND MPIRUN)
    add_test(NAME cli.distributed.${name}.mpi
             COMMAND bash ${DISTRIBUTED} mpi 2 $<TARGET_FILE:candela> ${case_file} ${ref} ${ARGN})
    list(APPEND tests cli.distributed.${name}.mpi)
  endif()
  set_tests_properties(${tests} PROPERTIES FIXTURES_REQUIRED distributed_${name})
endfunction()

candela_distributed_case(small_room ${PROJECT_SOURCE_DIR}/cases/small-room/case.toml --quality draft)
# Window states (docs/annual.md): every state's year and the switched one, the per-state metrics.
candela_distributed_case(window_states ${PROJECT_SOURCE_DIR}/cases/window-states/case.toml --quality draft)
# The office demo with its two views at a quarter of their pixels each way: the views took most of
# the office's time (a shard traces both whole), and what the tests check (the same bytes for any
# split) does not depend on the image size. Made at configure time from the demo itself, so that
# every other part of the demo is what the tests run; a demo whose resolutions changed stops the
# configure here instead of testing full-size views silently.
set(OFFICE_CASE ${PROJECT_SOURCE_DIR}/cases/office/case.toml)
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${OFFICE_CASE})
file(READ ${OFFICE_CASE} office_text)
foreach(pair "file = \"|file = \"${PROJECT_SOURCE_DIR}/cases/office/" "resolution = [480, 320]|resolution = [120, 80]"
             "resolution = [300, 300]|resolution = [76, 76]")
  string(REPLACE "|" ";" pair "${pair}")
  list(GET pair 0 from)
  list(GET pair 1 to)
  string(FIND "${office_text}" "${from}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "tests/cli/distributed.cmake: cases/office/case.toml no longer has '${from}'")
  endif()
  string(REPLACE "${from}" "${to}" office_text "${office_text}")
endforeach()
set(OFFICE_TEST_CASE ${CMAKE_BINARY_DIR}/distributed_cases/office/case.toml)
file(WRITE ${OFFICE_TEST_CASE} "${office_text}")
candela_distributed_case(office ${OFFICE_TEST_CASE} --quality draft)
candela_distributed_case(annual ${PROJECT_SOURCE_DIR}/cases/office-annual/case.toml --quality draft)
# The office's views take most of its time: its tests start first.
set_tests_properties(cli.distributed.office.reference PROPERTIES COST 6000)
set_tests_properties(cli.distributed.office.shards PROPERTIES COST 5000)

if(CANDELA_HAVE_MPI AND MPIRUN)
  set_tests_properties(cli.distributed.office.mpi PROPERTIES COST 5000)
  set(SMALL_ROOM_REFERENCE ${DISTRIBUTED_REFERENCE}/small_room)
  add_test(NAME cli.distributed.small_room.mpi_points
           COMMAND bash ${DISTRIBUTED} points 2 $<TARGET_FILE:candela> ${PROJECT_SOURCE_DIR}/cases/small-room/case.toml
                   ${SMALL_ROOM_REFERENCE} --quality draft)
  set_tests_properties(cli.distributed.small_room.mpi_points PROPERTIES FIXTURES_REQUIRED distributed_small_room)
  # candela render under mpirun: one cheap rendering of the office's first view.
  add_test(NAME cli.distributed.office.mpi_render
           COMMAND bash ${DISTRIBUTED} render 2 $<TARGET_FILE:candela> ${OFFICE_TEST_CASE}
                   - --quality draft --pixel-samples 1 --coarse-step 16 --irradiance-samples 4)
  # Commands that do not share their work are refused under mpirun (rank 0 says so; exit 2).
  add_test(NAME cli.distributed.validate_refused
           COMMAND bash ${DISTRIBUTED} refused 2 $<TARGET_FILE:candela> - - validate --quick)
  add_test(NAME cli.distributed.office.mpi_rank_killed
           COMMAND bash ${DISTRIBUTED} kill 2 $<TARGET_FILE:candela> ${OFFICE_TEST_CASE}
                   - --quality draft)
  # The annual study streams its hourly files while it runs: a kill leaves none of them.
  add_test(NAME cli.distributed.annual.mpi_rank_killed
           COMMAND bash ${DISTRIBUTED} kill 2 $<TARGET_FILE:candela> ${PROJECT_SOURCE_DIR}/cases/office-annual/case.toml
                   - --quality draft)
endif()
