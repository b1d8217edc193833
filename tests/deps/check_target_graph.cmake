# The dependency picture of docs/DESIGN.md §2, checked on CMake's own target graph:
#   app (pistondyn_exe -> pistondyn_app) -> design -> io -> plugin -> mbd_models + the numerics
# and the numerics (mapping, contact_forces, lubrication, and the Simbody-free gap terms
# plugin/skirt) link no Simbody and nothing of mbd_models, plugin, io or app, not even
# indirectly (the header-only pistondyn_common is allowed everywhere).
#
# Configures the source tree once more in a scratch folder with --graphviz (tests,
# examples and benchmarks off: only the product's targets) and reads the edges CMake
# writes as comments ("node3" -> "node5"  // pistondyn_io -> pistondyn_plugin).
# Variables: SOURCE_DIR, WORK_DIR, GENERATOR.
cmake_minimum_required(VERSION 3.22)  # policies for IN_LIST and friends in script mode
file(REMOVE_RECURSE "${WORK_DIR}")
execute_process(
  COMMAND ${CMAKE_COMMAND} -S "${SOURCE_DIR}" -B "${WORK_DIR}" -G "${GENERATOR}"
          -DPISTONDYN_BUILD_TESTS=OFF -DPISTONDYN_BUILD_EXAMPLES=OFF
          -DPISTONDYN_BUILD_BENCHMARKS=OFF "--graphviz=${WORK_DIR}/targets.dot"
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "configure for the target graph failed:\n${out}\n${err}")
endif()
file(STRINGS "${WORK_DIR}/targets.dot" lines REGEX "// .+ -> ")
set(targets "")
foreach(line IN LISTS lines)
  if(line MATCHES "// ([^ ]+) -> ([^ ]+)$")
    set(from "${CMAKE_MATCH_1}")
    set(to "${CMAKE_MATCH_2}")
    string(MAKE_C_IDENTIFIER "${from}" id)
    list(APPEND deps_${id} "${to}")
    list(APPEND targets "${from}")
  endif()
endforeach()

# Direct dependencies of `target` that are pistondyn's own libraries (but the header-only
# pistondyn_common, which every module may use).
function(own_deps target out)
  string(MAKE_C_IDENTIFIER "${target}" id)
  set(own "")
  foreach(d IN LISTS deps_${id})
    if(d MATCHES "^pistondyn_" AND NOT d STREQUAL "pistondyn_common")
      list(APPEND own "${d}")
    endif()
  endforeach()
  list(REMOVE_DUPLICATES own)
  list(SORT own)
  set(${out} "${own}" PARENT_SCOPE)
endfunction()

# Every target `target` reaches through the graph.
function(closure target out)
  set(seen "")
  set(todo "${target}")
  while(todo)
    list(POP_FRONT todo t)
    string(MAKE_C_IDENTIFIER "${t}" id)
    foreach(d IN LISTS deps_${id})
      if(NOT d IN_LIST seen)
        list(APPEND seen "${d}")
        list(APPEND todo "${d}")
      endif()
    endforeach()
  endwhile()
  set(${out} "${seen}" PARENT_SCOPE)
endfunction()

set(failures "")
macro(expect_own_deps target expected)
  own_deps(${target} got)
  set(want "${expected}")
  list(SORT want)
  if(NOT got STREQUAL want)
    string(REPLACE ";" ", " got_text "${got}")
    string(REPLACE ";" ", " want_text "${want}")
    list(APPEND failures "${target} links ${got_text}, expected exactly ${want_text}")
  endif()
  message(STATUS "${target} -> ${got}")
endmacro()

expect_own_deps(pistondyn_exe "pistondyn_app")
expect_own_deps(pistondyn_app "pistondyn_design;pistondyn_io")
expect_own_deps(pistondyn_design "pistondyn_io")
expect_own_deps(pistondyn_io "pistondyn_plugin")

own_deps(pistondyn_plugin plugin_deps)
message(STATUS "pistondyn_plugin -> ${plugin_deps}")
foreach(needed pistondyn_mbd_models pistondyn_mapping pistondyn_contact_forces
               pistondyn_lubrication)
  if(NOT needed IN_LIST plugin_deps)
    list(APPEND failures "pistondyn_plugin does not link ${needed}")
  endif()
endforeach()
foreach(layer pistondyn_mbd_models pistondyn_plugin)
  closure(${layer} reach)
  foreach(above pistondyn_io pistondyn_design pistondyn_app pistondyn_exe)
    if(above IN_LIST reach)
      list(APPEND failures "${layer} reaches ${above} (dependencies point downwards only)")
    endif()
  endforeach()
endforeach()

foreach(numerics pistondyn_mapping pistondyn_contact_forces pistondyn_lubrication pistondyn_skirt)
  if(NOT numerics IN_LIST targets)
    list(APPEND failures "no target ${numerics} in the graph")
  endif()
  closure(${numerics} reach)
  message(STATUS "${numerics} reaches: ${reach}")
  foreach(d IN LISTS reach)
    if(d MATCHES "SimTK|[Ss]imbody|^pistondyn_(mbd_models|plugin|io|design|app)$|^pistondyn_exe$|yaml|nlohmann|CLI11|NLopt")
      list(APPEND failures "${numerics} reaches ${d} (the numerics link no Simbody, no I/O)")
    endif()
  endforeach()
endforeach()

if(failures)
  list(JOIN failures "\n  " text)
  message(FATAL_ERROR "target graph:\n  ${text}")
endif()
message(STATUS "target graph: app -> design -> io -> plugin -> mbd_models + numerics; numerics Simbody-free")
file(REMOVE_RECURSE "${WORK_DIR}")
