# Runs the example deck ENGINE with default settings (from the source folder, so the
# deck path in the outputs is the one the reference was made with) and compares the
# results with REFERENCE. Variables: EXE, COMPARE, ENGINE, REFERENCE, OUT.
file(REMOVE_RECURSE "${OUT}")
execute_process(COMMAND "${EXE}" run "examples/engines/${ENGINE}/engine.yaml" --out "${OUT}" --quiet
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pistondyn run failed (${rc}):\n${out}\n${err}")
endif()
execute_process(COMMAND "${COMPARE}" "${REFERENCE}" "${OUT}" RESULT_VARIABLE rc OUTPUT_VARIABLE out)
message(STATUS "${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "results differ from ${REFERENCE}:\n${out}")
endif()
