# Sanitizer and fuzzer builds (issue 13, item 7). Included by the top CMakeLists.txt
# before any target is made, so the flags reach every target of the build folder:
# libraries, the program, tests, examples.
#
#   -DPISTONDYN_SANITIZE=address,undefined   (gcc or clang) the whole build under
#       AddressSanitizer (+ LeakSanitizer) and UndefinedBehaviorSanitizer. UB stops the
#       program (-fno-sanitize-recover), so a test that hits UB fails instead of printing
#       a line nobody reads. CI: .ci/run-sanitizers, with the run-time options of .ci/sanitize-env
#       (third-party suppressions, symbolised stacks).
#   -DPISTONDYN_FUZZ=ON                      (clang only) libFuzzer targets in fuzz/,
#       with every library compiled for coverage (-fsanitize=fuzzer-no-link) under
#       AddressSanitizer and UndefinedBehaviorSanitizer. See fuzz/README.md.
#
# Both keep the project's Release flags (optimised, NDEBUG off) and add -g and frame
# pointers for readable reports.

set(PISTONDYN_SANITIZE "" CACHE STRING
    "Comma-separated sanitizers for the whole build: address, undefined (empty: none)")
option(PISTONDYN_FUZZ "Build the libFuzzer targets in fuzz/ (clang; with ASan and UBSan)" OFF)

set(pistondyn_sanitizers "")
if(PISTONDYN_SANITIZE)
  string(REPLACE "," ";" pistondyn_sanitizers "${PISTONDYN_SANITIZE}")
  foreach(s IN LISTS pistondyn_sanitizers)
    if(NOT s MATCHES "^(address|undefined)$")
      message(FATAL_ERROR "PISTONDYN_SANITIZE: '${s}' is not one of: address, undefined")
    endif()
  endforeach()
endif()
if(PISTONDYN_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "PISTONDYN_FUZZ needs clang (libFuzzer), not "
                        "${CMAKE_CXX_COMPILER_ID}: configure with -DCMAKE_CXX_COMPILER=clang++")
  endif()
  list(APPEND pistondyn_sanitizers address undefined)
  list(REMOVE_DUPLICATES pistondyn_sanitizers)
endif()

if(pistondyn_sanitizers)
  list(JOIN pistondyn_sanitizers "," pistondyn_sanitize_list)
  set(pistondyn_compile_sanitize "-fsanitize=${pistondyn_sanitize_list}")
  if(PISTONDYN_FUZZ)
    # Coverage instrumentation for libFuzzer in every library; only the fuzz targets
    # link libFuzzer itself (-fsanitize=fuzzer, fuzz/CMakeLists.txt).
    string(APPEND pistondyn_compile_sanitize ",fuzzer-no-link")
  endif()
  add_compile_options(${pistondyn_compile_sanitize} -fno-omit-frame-pointer -g)
  if("undefined" IN_LIST pistondyn_sanitizers)
    add_compile_options(-fno-sanitize-recover=undefined)
  endif()
  add_link_options(-fsanitize=${pistondyn_sanitize_list})
  message(STATUS "pistondyn: built with -fsanitize=${pistondyn_sanitize_list}"
                 " (libFuzzer coverage: ${PISTONDYN_FUZZ})")
endif()
