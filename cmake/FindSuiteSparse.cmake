# Find SuiteSparse 5.x (Debian ships neither a CMake config nor pkg-config files).
# Provides the imported target SuiteSparse::SuiteSparse and SuiteSparse_VERSION.
find_path(SuiteSparse_INCLUDE_DIR NAMES cholmod.h umfpack.h klu.h
          PATH_SUFFIXES suitesparse)
set(_ss_libs umfpack cholmod klu btf amd colamd camd ccolamd suitesparseconfig)
set(SuiteSparse_LIBRARIES)
foreach(_l IN LISTS _ss_libs)
  find_library(SuiteSparse_${_l}_LIBRARY NAMES ${_l})
  mark_as_advanced(SuiteSparse_${_l}_LIBRARY)
  if(SuiteSparse_${_l}_LIBRARY)
    list(APPEND SuiteSparse_LIBRARIES ${SuiteSparse_${_l}_LIBRARY})
  else()
    set(_ss_missing ${_ss_missing} ${_l})
  endif()
endforeach()
if(SuiteSparse_INCLUDE_DIR AND EXISTS "${SuiteSparse_INCLUDE_DIR}/SuiteSparse_config.h")
  file(STRINGS "${SuiteSparse_INCLUDE_DIR}/SuiteSparse_config.h" _ss_ver
       REGEX "^#define SUITESPARSE_(MAIN|SUB|SUBSUB)_VERSION[ \t]+[0-9]+")
  string(REGEX REPLACE ".*MAIN_VERSION[ \t]+([0-9]+).*" "\\1" _maj "${_ss_ver}")
  string(REGEX REPLACE ".*SUB_VERSION[ \t]+([0-9]+).*SUBSUB.*" "\\1" _min "${_ss_ver}")
  string(REGEX REPLACE ".*SUBSUB_VERSION[ \t]+([0-9]+).*" "\\1" _pat "${_ss_ver}")
  set(SuiteSparse_VERSION "${_maj}.${_min}.${_pat}")
endif()
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(SuiteSparse
  REQUIRED_VARS SuiteSparse_INCLUDE_DIR SuiteSparse_LIBRARIES
  VERSION_VAR SuiteSparse_VERSION)
if(SuiteSparse_FOUND AND NOT TARGET SuiteSparse::SuiteSparse)
  add_library(SuiteSparse::SuiteSparse INTERFACE IMPORTED)
  set_target_properties(SuiteSparse::SuiteSparse PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${SuiteSparse_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${SuiteSparse_LIBRARIES}")
endif()
