# lbm_pore_liggghts_checks(PREFIX <p> SCRIPT <script.py> LABEL <label> TIMEOUT <s>
#                          CASES <case>... [ENVIRONMENT <VAR=value>...] [ARGS <arg>...])
# One CTest test <p>_<case> per case: python3 <script.py> --driver liggghts-lbm --scripts
# <the calling folder> [ARGS] <case>, with tests/harness (liggghts_run.py, the harness the
# check scripts import) on PYTHONPATH. Registers nothing without liggghts-lbm or Python 3.
set(LBM_PORE_HARNESS_DIR "${CMAKE_CURRENT_LIST_DIR}")

function(lbm_pore_liggghts_checks)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "PREFIX;SCRIPT;LABEL;TIMEOUT" "CASES;ENVIRONMENT;ARGS")
  if(NOT TARGET liggghts-lbm)
    return()  # LIGGGHTS or MPI not found
  endif()
  find_package(Python3 COMPONENTS Interpreter)
  if(NOT Python3_FOUND)
    return()
  endif()
  set(_environment "PYTHONPATH=${LBM_PORE_HARNESS_DIR}" ${arg_ENVIRONMENT})
  foreach(_case IN LISTS arg_CASES)
    add_test(NAME ${arg_PREFIX}_${_case}
             COMMAND Python3::Interpreter ${CMAKE_CURRENT_SOURCE_DIR}/${arg_SCRIPT}
                     --driver $<TARGET_FILE:liggghts-lbm> --scripts ${CMAKE_CURRENT_SOURCE_DIR}
                     ${arg_ARGS} ${_case})
    set_tests_properties(${arg_PREFIX}_${_case} PROPERTIES TIMEOUT ${arg_TIMEOUT} LABELS ${arg_LABEL}
      ENVIRONMENT "${_environment}")
  endforeach()
endfunction()
