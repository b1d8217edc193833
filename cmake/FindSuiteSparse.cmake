# FindSuiteSparse — SuiteSparse 5.x as shipped by Debian 12 has no CMake config
# (docs/DESIGN.md §5). Headers live under <prefix>/include/suitesparse/.
#
# Components: cholmod umfpack klu (and their support libraries, found always:
# suitesparseconfig amd colamd camd ccolamd btf).
# Defines imported targets SuiteSparse::<component> and SuiteSparse_INCLUDE_DIR.

find_path(SuiteSparse_INCLUDE_DIR NAMES cholmod.h umfpack.h PATH_SUFFIXES suitesparse)

set(_ss_support suitesparseconfig amd colamd camd ccolamd btf)
set(_ss_all ${_ss_support})
foreach(_c IN LISTS SuiteSparse_FIND_COMPONENTS)
  list(APPEND _ss_all ${_c})
endforeach()
list(REMOVE_DUPLICATES _ss_all)

set(_ss_required_vars SuiteSparse_INCLUDE_DIR)
foreach(_lib IN LISTS _ss_all)
  find_library(SuiteSparse_${_lib}_LIBRARY NAMES ${_lib})
  if(SuiteSparse_${_lib}_LIBRARY)
    set(SuiteSparse_${_lib}_FOUND TRUE)
  endif()
  list(APPEND _ss_required_vars SuiteSparse_${_lib}_LIBRARY)
  mark_as_advanced(SuiteSparse_${_lib}_LIBRARY)
endforeach()
mark_as_advanced(SuiteSparse_INCLUDE_DIR)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(SuiteSparse
  REQUIRED_VARS ${_ss_required_vars}
  HANDLE_COMPONENTS)

if(SuiteSparse_FOUND)
  foreach(_lib IN LISTS _ss_all)
    if(NOT TARGET SuiteSparse::${_lib})
      add_library(SuiteSparse::${_lib} UNKNOWN IMPORTED)
      set_target_properties(SuiteSparse::${_lib} PROPERTIES
        IMPORTED_LOCATION "${SuiteSparse_${_lib}_LIBRARY}"
        INTERFACE_INCLUDE_DIRECTORIES "${SuiteSparse_INCLUDE_DIR}")
    endif()
  endforeach()
  # Link order: the solvers need the ordering and config libraries behind them.
  if(TARGET SuiteSparse::cholmod)
    set_property(TARGET SuiteSparse::cholmod APPEND PROPERTY INTERFACE_LINK_LIBRARIES
      SuiteSparse::amd SuiteSparse::colamd SuiteSparse::camd SuiteSparse::ccolamd
      SuiteSparse::suitesparseconfig)
  endif()
  if(TARGET SuiteSparse::umfpack)
    set_property(TARGET SuiteSparse::umfpack APPEND PROPERTY INTERFACE_LINK_LIBRARIES
      SuiteSparse::cholmod SuiteSparse::amd SuiteSparse::suitesparseconfig)
  endif()
  if(TARGET SuiteSparse::klu)
    set_property(TARGET SuiteSparse::klu APPEND PROPERTY INTERFACE_LINK_LIBRARIES
      SuiteSparse::btf SuiteSparse::amd SuiteSparse::colamd SuiteSparse::suitesparseconfig)
  endif()
endif()
