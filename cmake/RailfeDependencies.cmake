# Every external package railfe uses, found once. cmake/install-dependencies.sh installs them.
find_package(MPI REQUIRED COMPONENTS C CXX)
set(RAILFE_TRILINOS_PACKAGES
    Teuchos Kokkos Tpetra Belos Ifpack2 MueLu Amesos2 Zoltan2 Xpetra Anasazi)
find_package(Trilinos 13.2 REQUIRED COMPONENTS ${RAILFE_TRILINOS_PACKAGES})
find_package(ExodusII REQUIRED)
find_package(CHOLMOD REQUIRED)
find_package(MuParser REQUIRED)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
# FFTW 3 (Debian's libfftw3-dev): the exact contact solver's half-space convolutions.
find_package(PkgConfig REQUIRED)
pkg_check_modules(FFTW3 REQUIRED IMPORTED_TARGET fftw3)
find_package(GTest REQUIRED)

# Trilinos' exported MPI library list is empty, so MPI is linked explicitly. Trilinos headers are
# marked SYSTEM so their warnings do not drown ours.
add_library(railfe_trilinos INTERFACE)
target_include_directories(railfe_trilinos SYSTEM INTERFACE
  ${Trilinos_INCLUDE_DIRS} ${Trilinos_TPL_INCLUDE_DIRS})
target_link_libraries(railfe_trilinos INTERFACE
  ${Trilinos_LIBRARIES} ${Trilinos_TPL_LIBRARIES} MPI::MPI_CXX)
