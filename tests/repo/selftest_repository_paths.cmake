# The repository-path check must fail on a planted reference: it runs on a scratch git
# repository with one planted reference of each kind and with legitimate look-alikes, and
# must name exactly the planted ones; on a folder that is not a git checkout it must pass
# with a message. The planted paths are assembled from pieces so that this file itself
# names no path outside the repository.
# Variables: CHECK_SCRIPT (check_repository_paths.cmake), WORK_DIR (scratch folder).
cmake_minimum_required(VERSION 3.22)
find_program(GIT_EXECUTABLE git)
if(NOT GIT_EXECUTABLE)
  message(STATUS "repository paths self-test: skipped, git not found")
  return()
endif()

set(up "..")
set(root_slash "/")
set(repo "${WORK_DIR}/repo")
file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${repo}/docs" "${repo}/examples/engines" "${repo}/examples/sweeps")

# Planted: a relative escape, an absolute machine path, and a citation of a file beside the
# repository (what the check was written for).
set(escape "${up}/${up}/outside/notes.txt")
set(absolute "${root_slash}work/someone/notes.txt")
set(marked "${root_slash}tmp/x.txt")
set(beside "${up}/shared/DESIGN.md")
file(WRITE "${repo}/docs/notes.md"
  "The notes are in ${escape}.\n"
  "A copy lies in ${absolute} as well.\n"
  "A URL with a parent step is not a file: https://example.org/a/${up}/b.\n"
  "Marked on purpose: ${marked} (repository-paths: allow).\n")
file(WRITE "${repo}/CMakeLists.txt" "# Layout: see ${beside}\n")
# Legitimate: a deck that names its neighbour, and a README snippet of that deck whose
# path is relative to the deck's folder, not to the README's.
file(WRITE "${repo}/examples/engines/engine.yaml" "engine: {}\n")
file(WRITE "${repo}/examples/sweeps/sweep.yaml" "base_deck: ${up}/engines/engine.yaml\n")
file(WRITE "${repo}/README.md" "base_deck: ${up}/engines/engine.yaml   # relative to the sweep deck\n")
# Binary (a NUL byte near the start): skipped whatever it holds.
execute_process(COMMAND sh -c "printf 'a\\000b ${up}/${up}/${up}/binary\\n' > data.bin"
  WORKING_DIRECTORY "${repo}" RESULT_VARIABLE rc)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "repository paths self-test: could not write the binary file")
endif()

execute_process(COMMAND "${GIT_EXECUTABLE}" init -q WORKING_DIRECTORY "${repo}" RESULT_VARIABLE rc)
execute_process(COMMAND "${GIT_EXECUTABLE}" add -A WORKING_DIRECTORY "${repo}" RESULT_VARIABLE rc2)
if(NOT rc EQUAL 0 OR NOT rc2 EQUAL 0)
  message(FATAL_ERROR "repository paths self-test: could not make the scratch repository")
endif()

execute_process(COMMAND "${CMAKE_COMMAND}" -DSOURCE_DIR=${repo} -P "${CHECK_SCRIPT}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(text "${out}${err}")
set(failures "")
if(rc EQUAL 0)
  list(APPEND failures "the check passed on planted references")
endif()
foreach(expected "docs/notes.md:1: ${escape}" "docs/notes.md:2: ${absolute}"
                 "CMakeLists.txt:1: ${beside}" "3 reference(s)")
  string(FIND "${text}" "${expected}" pos)
  if(pos EQUAL -1)
    list(APPEND failures "not reported: ${expected}")
  endif()
endforeach()
foreach(unexpected "example.org" "${marked}" "engine.yaml" "binary")
  string(FIND "${text}" "${unexpected}" pos)
  if(NOT pos EQUAL -1)
    list(APPEND failures "false alarm: ${unexpected}")
  endif()
endforeach()

# Not a git checkout: passes with a message.
file(MAKE_DIRECTORY "${WORK_DIR}/plain")
execute_process(COMMAND "${CMAKE_COMMAND}" -DSOURCE_DIR=${WORK_DIR}/plain -P "${CHECK_SCRIPT}"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0 OR NOT "${out}${err}" MATCHES "skipped")
  list(APPEND failures "outside a git checkout: exit ${rc}, output ${out}${err}")
endif()

if(failures)
  list(JOIN failures "\n  " f)
  message(FATAL_ERROR "repository paths self-test:\n  ${f}\ncheck output:\n${text}")
endif()
file(REMOVE_RECURSE "${WORK_DIR}")
message(STATUS "repository paths self-test: the planted references reported, no false alarm")
