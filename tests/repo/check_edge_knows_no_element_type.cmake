# The edge (io/, app/, design/, python/) reads elements through their roles (LinerElement,
# NodalFieldSource, LinerOilSource, declared outputs), never by their concrete type: no
# dynamic_cast and no getElementAs<...> in its sources, so that a user's element gets the
# summary, the files and the figures of a built-in one. Fails naming each file:line.
#   cmake -DSOURCE_DIR=<repository> -P check_edge_knows_no_element_type.cmake
set(found "")
foreach(part io app design python)
  file(GLOB_RECURSE sources "${SOURCE_DIR}/${part}/*.cpp" "${SOURCE_DIR}/${part}/*.h")
  foreach(source IN LISTS sources)
    file(STRINGS "${source}" lines)
    set(number 0)
    foreach(line IN LISTS lines)
      math(EXPR number "${number} + 1")
      if(line MATCHES "dynamic_cast[ ]*<|getElementAs[ ]*<")
        file(RELATIVE_PATH rel "${SOURCE_DIR}" "${source}")
        string(APPEND found "\n  ${rel}:${number}: ${line}")
      endif()
    endforeach()
  endforeach()
endforeach()
if(found)
  message(FATAL_ERROR "the edge reaches an element by its concrete type (use a role):${found}")
endif()
message(STATUS "io/, app/, design/, python/: no dynamic_cast, no getElementAs")
