# Helper functions shared by every module's CMakeLists.txt.

set(PISTONDYN_WARNINGS -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Woverloaded-virtual)

# pistondyn_add_library(<module>
#     SOURCES <files...>
#     [PUBLIC_DEPS <targets...>] [PRIVATE_DEPS <targets...>]
#     [USES_SIMBODY])
# pistondyn_add_library(<module> INTERFACE [PUBLIC_DEPS <targets...>])
# Creates target pistondyn_<module> (alias and exported name pistondyn::<module>)
# with public include folder <module>/include (headers under include/pistondyn/<module>/),
# installs it and its headers. USES_SIMBODY adds -UNDEBUG to the target and to its
# consumers (docs/DESIGN.md §5). INTERFACE makes a header-only library: no sources, its
# PUBLIC_DEPS become interface dependencies of every consumer.
function(pistondyn_add_library module)
  cmake_parse_arguments(ARG "USES_SIMBODY;INTERFACE" "" "SOURCES;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  set(tgt pistondyn_${module})
  if(ARG_INTERFACE)
    if(ARG_SOURCES OR ARG_PRIVATE_DEPS OR ARG_USES_SIMBODY)
      message(FATAL_ERROR "pistondyn_add_library(${module} INTERFACE): no SOURCES, "
                          "PRIVATE_DEPS or USES_SIMBODY for a header-only library")
    endif()
    add_library(${tgt} INTERFACE)
    set(scope INTERFACE)
  else()
    add_library(${tgt} ${ARG_SOURCES})
    set(scope PUBLIC)
  endif()
  add_library(pistondyn::${module} ALIAS ${tgt})
  set_target_properties(${tgt} PROPERTIES EXPORT_NAME ${module})
  target_include_directories(${tgt} ${scope}
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  target_compile_features(${tgt} ${scope} cxx_std_17)
  if(ARG_INTERFACE)
    target_link_libraries(${tgt} INTERFACE ${ARG_PUBLIC_DEPS})
  else()
    set_target_properties(${tgt} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    target_compile_options(${tgt} PRIVATE ${PISTONDYN_WARNINGS})
    target_link_libraries(${tgt} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  endif()
  if(ARG_USES_SIMBODY)
    target_compile_options(${tgt} PUBLIC -UNDEBUG)
  endif()
  install(TARGETS ${tgt} EXPORT pistondynTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  # A module may have no public headers yet (git keeps no empty folders).
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/include)
    install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
endfunction()

# pistondyn_add_gtest(<name> SOURCES <files...> LIBS <targets...> [LABELS <labels...>]
#                     [TIMEOUT <seconds>])
# One GoogleTest executable; each TEST becomes its own CTest test (TIMEOUT: each test's,
# for the slow whole-cycle studies that outlast CTest's default).
function(pistondyn_add_gtest name)
  cmake_parse_arguments(ARG "" "TIMEOUT" "SOURCES;LIBS;LABELS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_compile_options(${name} PRIVATE ${PISTONDYN_WARNINGS})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} GTest::gtest GTest::gtest_main)
  gtest_discover_tests(${name}
    WORKING_DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}
    DISCOVERY_TIMEOUT 120)
  # Labels are set by a script CTest includes after the discovered tests: the PROPERTIES
  # option of gtest_discover_tests writes a list unquoted, so "plugin;cycle" became LABELS
  # plugin and a property named "cycle" (every label after the first was lost and
  # `ctest -LE cycle` ran the slow tests).
  if(ARG_LABELS OR ARG_TIMEOUT)
    set(properties "")
    if(ARG_LABELS)
      string(APPEND properties " LABELS \"${ARG_LABELS}\"")
    endif()
    if(ARG_TIMEOUT)
      string(APPEND properties " TIMEOUT ${ARG_TIMEOUT}")
    endif()
    set(script "${CMAKE_CURRENT_BINARY_DIR}/${name}_labels.cmake")
    file(WRITE "${script}"
      "foreach(t IN LISTS ${name}_TESTS)\n"
      "  set_tests_properties(\"\${t}\" PROPERTIES${properties})\n"
      "endforeach()\n")
    set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES "${script}")
  endif()
endfunction()

# pistondyn_add_benchmark(<name> SOURCES <files...> LIBS <targets...>)
function(pistondyn_add_benchmark name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
  add_executable(${name} ${ARG_SOURCES})
  target_compile_options(${name} PRIVATE ${PISTONDYN_WARNINGS})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} benchmark::benchmark)
endfunction()
