# Finds SuiteSparse's CHOLMOD (supernodal sparse Cholesky) with the libraries it needs for METIS
# ordering. Defines the imported target SuiteSparse::CHOLMOD.
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse)
find_library(CHOLMOD_LIBRARY NAMES cholmod)
set(_cholmod_parts amd camd colamd ccolamd suitesparseconfig metis)
set(CHOLMOD_DEPENDENCIES "")
foreach(part IN LISTS _cholmod_parts)
  find_library(CHOLMOD_${part}_LIBRARY NAMES ${part})
  mark_as_advanced(CHOLMOD_${part}_LIBRARY)
  if(CHOLMOD_${part}_LIBRARY)
    list(APPEND CHOLMOD_DEPENDENCIES "${CHOLMOD_${part}_LIBRARY}")
  endif()
endforeach()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(CHOLMOD REQUIRED_VARS CHOLMOD_LIBRARY CHOLMOD_INCLUDE_DIR)

if(CHOLMOD_FOUND AND NOT TARGET SuiteSparse::CHOLMOD)
  add_library(SuiteSparse::CHOLMOD UNKNOWN IMPORTED)
  set_target_properties(SuiteSparse::CHOLMOD PROPERTIES
    IMPORTED_LOCATION "${CHOLMOD_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${CHOLMOD_DEPENDENCIES}")
endif()
mark_as_advanced(CHOLMOD_INCLUDE_DIR CHOLMOD_LIBRARY)
