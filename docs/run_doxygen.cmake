# Builds the API reference with doxygen and reports its warnings, counted per file.
# Variables: DOXYGEN, DOXYFILE, WARNINGS (doxygen's warning log), OUTPUT (its output folder),
# SOURCE_DIR (stripped from file names), STRICT (ON: any warning fails).
cmake_minimum_required(VERSION 3.22)
file(REMOVE "${WARNINGS}")
file(REMOVE_RECURSE "${OUTPUT}/html")
execute_process(COMMAND "${DOXYGEN}" "${DOXYFILE}" RESULT_VARIABLE rc
  OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "doxygen failed (exit ${rc}):\n${out}${err}")
endif()

set(warnings "")
if(EXISTS "${WARNINGS}")
  file(STRINGS "${WARNINGS}" lines ENCODING UTF-8)
  foreach(line IN LISTS lines)
    string(REPLACE "${SOURCE_DIR}/" "" line "${line}")
    # One warning per line that does not continue the one before (continuations are
    # indented).
    if(NOT line MATCHES "^[ \t]" AND NOT line STREQUAL "")
      list(APPEND warnings "${line}")
    endif()
  endforeach()
endif()
# An inherited undocumented member is reported once per derived class: count each once.
list(REMOVE_DUPLICATES warnings)
list(LENGTH warnings count)

if(count EQUAL 0)
  message(STATUS "API reference: no doxygen warnings; ${OUTPUT}/html/index.html")
  return()
endif()

set(files "")
foreach(w IN LISTS warnings)
  string(REGEX REPLACE ":[0-9]+: .*" "" f "${w}")
  list(APPEND files "${f}")
endforeach()
set(per_file "")
list(REMOVE_DUPLICATES files)
foreach(f IN LISTS files)
  set(n 0)
  foreach(w IN LISTS warnings)
    string(FIND "${w}" "${f}:" pos)
    if(pos EQUAL 0)
      math(EXPR n "${n} + 1")
    endif()
  endforeach()
  list(APPEND per_file "${n}  ${f}")
endforeach()
list(JOIN per_file "\n  " per_file_text)
list(JOIN warnings "\n" warning_text)
set(report "${count} doxygen warning(s) (an undocumented public declaration is one):\n"
           "${warning_text}\nper file:\n  ${per_file_text}\n")
if(STRICT)
  message(FATAL_ERROR "API reference: ${report}")
endif()
message(WARNING "API reference: ${report}HTML written to ${OUTPUT}/html/index.html")
