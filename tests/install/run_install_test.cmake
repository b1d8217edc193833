# Installs the build tree into a scratch prefix, builds tests/install/downstream against
# it (Release) and runs its two programs (a C++ model on pistondyn::pistondyn, a deck run
# on pistondyn::io), then runs the installed bin/pistondyn on an example deck.
# Variables: BUILD_DIR, SOURCE_DIR, WORK_DIR, GENERATOR.
file(REMOVE_RECURSE "${WORK_DIR}")
set(prefix "${WORK_DIR}/prefix")
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message(STATUS "${what}: ${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
endfunction()
run("install" ${CMAKE_COMMAND} --install "${BUILD_DIR}" --prefix "${prefix}")
foreach(f bin/pistondyn lib/cmake/pistondyn/pistondynConfig.cmake
          include/pistondyn/plugin/ForceElement.h include/pistondyn/mbd_models/CrankTrain.h
          include/pistondyn/io/RunDeck.h include/pistondyn/io/DeckSection.h
          include/pistondyn/io/LinerRegistry.h)
  if(NOT EXISTS "${prefix}/${f}")
    message(FATAL_ERROR "install is missing ${f}")
  endif()
endforeach()
run("configure downstream" ${CMAKE_COMMAND} -S "${SOURCE_DIR}/tests/install/downstream"
    -B "${WORK_DIR}/build" -G "${GENERATOR}" -DCMAKE_BUILD_TYPE=Release
    "-DCMAKE_PREFIX_PATH=${prefix}")
run("build downstream" ${CMAKE_COMMAND} --build "${WORK_DIR}/build")
run("run downstream" "${WORK_DIR}/build/downstream")
# The user's program on the ideal guide (a second), the installed program on the deck's
# lubricated skirt, one coarse cycle (its skirt profile table beside the deck).
run("run downstream run_deck" "${WORK_DIR}/build/run_deck"
    "${SOURCE_DIR}/examples/engines/briggs_stratton_500/engine.yaml" "${WORK_DIR}/user_results"
    simulation.output_step_deg=5 liner.model=ideal_guide simulation.integrator=rk_merson
    simulation.until_periodic=false simulation.cycles=1)
if(NOT EXISTS "${WORK_DIR}/user_results/cycle.csv" OR
   NOT EXISTS "${WORK_DIR}/user_results/summary.json")
  message(FATAL_ERROR "run_deck (pistondyn::io) wrote no results")
endif()
run("installed pistondyn" "${prefix}/bin/pistondyn" run
    "${SOURCE_DIR}/examples/engines/briggs_stratton_500/engine.yaml"
    --out "${WORK_DIR}/results" --quiet --set simulation.output_step_deg=5
    --set simulation.cycles=1 --set simulation.until_periodic=false
    --set liner.grid.nodes_circumferential=16 --set liner.grid.nodes_axial=12)
if(NOT EXISTS "${WORK_DIR}/results/cycle.csv" OR NOT EXISTS "${WORK_DIR}/results/summary.json")
  message(FATAL_ERROR "installed pistondyn wrote no results")
endif()
# What the installed program points its users to: the deck reference it prints itself,
# the README and example decks beside it, the pressure-table generator with its --help.
run("installed pistondyn keys" "${prefix}/bin/pistondyn" keys)
foreach(f share/doc/pistondyn/README.md
          share/doc/pistondyn/examples/engines/gasoline_1400_2000rpm/engine.yaml
          share/doc/pistondyn/examples/studies/flooding.yaml)
  if(NOT EXISTS "${prefix}/${f}")
    message(FATAL_ERROR "install is missing ${f}")
  endif()
endforeach()
if(EXISTS "${BUILD_DIR}/examples")
  run("installed make_pressure_curve --help" "${prefix}/bin/make_pressure_curve" --help)
endif()
file(REMOVE_RECURSE "${WORK_DIR}")
