# `cmake --install` into a scratch prefix, then the Python module imported from that prefix
# alone (PYTHONPATH=<prefix>/<PYDIR>, run from a folder without the build tree) and a deck
# run through it. Variables: BUILD_DIR, PYTHON, PYDIR, WORK_DIR, SOURCE_DIR.
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")
execute_process(COMMAND ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}"
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "install failed: ${err}")
endif()
file(GLOB module "${prefix}/${PYDIR}/pistondyn/_pistondyn*.so")
if(NOT module OR NOT EXISTS "${prefix}/${PYDIR}/pistondyn/__init__.py")
  message(FATAL_ERROR "the Python package is not installed under ${prefix}/${PYDIR}/pistondyn")
endif()
set(script "
import os, sys, pistondyn
here = os.path.realpath(pistondyn.__file__)
assert here.startswith(os.path.realpath(sys.argv[1])), here
deck = os.path.join(sys.argv[2], 'examples/engines/briggs_stratton_500/engine.yaml')
r = pistondyn.run(deck, overrides={'liner.model': 'ideal_guide', 'simulation.integrator': 'rk_merson',
                                   'simulation.until_periodic': False, 'simulation.cycles': 1,
                                   'simulation.output_step_deg': 10})
assert len(r.cycle['crank_angle_deg']) == 73, r
print('imported from', here, 'imep', r.figures['imep_kPa'])
")
execute_process(COMMAND ${CMAKE_COMMAND} -E env "PYTHONPATH=${prefix}/${PYDIR}"
                        ${PYTHON} -c "${script}" "${prefix}" "${SOURCE_DIR}"
                WORKING_DIRECTORY "${WORK_DIR}" RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
message(STATUS "${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "importing the installed module failed:\n${out}\n${err}")
endif()
file(REMOVE_RECURSE "${WORK_DIR}")
