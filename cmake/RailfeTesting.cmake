# Test helpers. Unit tests live beside the code they test and run under mpirun at the rank counts
# given; whole-deck checks are registered by regression/CMakeLists.txt.
set(RAILFE_MPIEXEC_FLAGS "")
execute_process(COMMAND id -u OUTPUT_VARIABLE _railfe_uid OUTPUT_STRIP_TRAILING_WHITESPACE)
if(_railfe_uid STREQUAL "0")
  list(APPEND RAILFE_MPIEXEC_FLAGS --allow-run-as-root)
endif()
# Two ranks on a machine that may have fewer free cores than ranks.
list(APPEND RAILFE_MPIEXEC_FLAGS --oversubscribe --bind-to none)
# Open MPI's mpiexec waits odls_base_sigkill_timeout (1 s) between SIGTERM and SIGKILL after a rank
# exits non-zero, even when every rank has already exited: 2 s of each of the ~300 refused-deck
# runs, a fifth of the suite's time. The ranks agree on errors and exit together, so nothing is
# left to wait for.
execute_process(COMMAND ${MPIEXEC_EXECUTABLE} --version OUTPUT_VARIABLE _railfe_mpi_version
                ERROR_QUIET)
if(_railfe_mpi_version MATCHES "Open MPI|OpenRTE")
  list(APPEND RAILFE_MPIEXEC_FLAGS --mca odls_base_sigkill_timeout 0)
endif()

# railfe_mpi_command(<out-var> <ranks>) gives the command prefix that starts <ranks> processes.
function(railfe_mpi_command out_var ranks)
  set(${out_var} ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${ranks} ${RAILFE_MPIEXEC_FLAGS}
      PARENT_SCOPE)
endfunction()

# railfe_add_unit_test(NAME <name> SOURCES <files> LIBRARIES <targets> RANKS <n...>)
# Builds one googletest executable and registers it once per rank count as <name>.np<n>.
function(railfe_add_unit_test)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;LIBRARIES;RANKS" ${ARGN})
  if(NOT ARG_RANKS)
    set(ARG_RANKS 1)
  endif()
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  target_link_libraries(${ARG_NAME} PRIVATE ${ARG_LIBRARIES} railfe_test_main)
  set_target_properties(${ARG_NAME} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${CMAKE_BINARY_DIR}/tests)
  foreach(ranks IN LISTS ARG_RANKS)
    railfe_mpi_command(launcher ${ranks})
    add_test(NAME ${ARG_NAME}.np${ranks} COMMAND ${launcher} $<TARGET_FILE:${ARG_NAME}>)
    set_tests_properties(${ARG_NAME}.np${ranks} PROPERTIES
      PROCESSORS ${ranks} LABELS "unit;np${ranks}" TIMEOUT 600
      ENVIRONMENT "RAILFE_SOURCE_DIR=${PROJECT_SOURCE_DIR};OMPI_MCA_rmaps_base_oversubscribe=1")
  endforeach()
endfunction()
