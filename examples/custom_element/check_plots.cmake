# A user's liner element gets the program's figures without the program knowing its type:
# the example writes its spring_guide run's result folder, `pistondyn plot` draws it, and
# the liner figures (side force, secondary motion) are there.
#   cmake -DEXAMPLE=<custom_element_example> -DPISTONDYN=<pistondyn> -DWORK_DIR=<dir> -P ...
file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(COMMAND "${EXAMPLE}" --out "${WORK_DIR}/run" RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "custom_element_example --out failed (${rc}):\n${out}\n${err}")
endif()
execute_process(COMMAND "${PISTONDYN}" plot "${WORK_DIR}/run" RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "pistondyn plot of the spring_guide run failed (${rc}):\n${out}\n${err}")
endif()
foreach(figure side_force secondary_motion crank_train_forces)
  if(NOT EXISTS "${WORK_DIR}/run/plots/${figure}.png")
    message(FATAL_ERROR "the spring_guide run has no plots/${figure}.png:\n${out}")
  endif()
endforeach()
message(STATUS "spring_guide run drawn: ${out}")
