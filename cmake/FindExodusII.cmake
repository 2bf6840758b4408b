# Finds Exodus II (Debian's libexodusii-dev 6.02 ships no CMake config) and the netCDF library it
# is built on. Defines the imported target ExodusII::ExodusII.
find_path(ExodusII_INCLUDE_DIR exodusII.h)
find_library(ExodusII_LIBRARY NAMES exoIIv2c exodus)
find_path(NetCDF_INCLUDE_DIR netcdf.h)
find_library(NetCDF_LIBRARY NAMES netcdf)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(ExodusII
  REQUIRED_VARS ExodusII_LIBRARY ExodusII_INCLUDE_DIR NetCDF_LIBRARY NetCDF_INCLUDE_DIR)

if(ExodusII_FOUND AND NOT TARGET ExodusII::ExodusII)
  add_library(ExodusII::ExodusII UNKNOWN IMPORTED)
  set_target_properties(ExodusII::ExodusII PROPERTIES
    IMPORTED_LOCATION "${ExodusII_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${ExodusII_INCLUDE_DIR};${NetCDF_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${NetCDF_LIBRARY}")
endif()
mark_as_advanced(ExodusII_INCLUDE_DIR ExodusII_LIBRARY NetCDF_INCLUDE_DIR NetCDF_LIBRARY)
