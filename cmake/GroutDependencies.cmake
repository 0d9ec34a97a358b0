# Third-party dependencies, all from Debian 12 packages (see tools/build).
# Trilinos 13.2 has no namespaced targets: wrap its variables in interface targets.

find_package(MPI REQUIRED COMPONENTS C CXX)  # Trilinos configs carry no MPI include dirs

find_package(Kokkos REQUIRED)  # TriBITS flavour: Kokkos_LIBRARIES / Kokkos_INCLUDE_DIRS
find_package(Trilinos 13.2 REQUIRED
  COMPONENTS Teuchos Kokkos KokkosKernels Tpetra Belos MueLu Amesos2 Ifpack2 NOX Sacado Zoltan2)

# Kokkos + Sacado only: what kernels/ may use. Debian's Sacado is built with Teuchos support,
# so its headers pull in Teuchos (and through it mpi.h): add those, but nothing of Tpetra.
if(NOT TARGET grout_kokkos_deps)
  add_library(grout_kokkos_deps INTERFACE)
  target_include_directories(grout_kokkos_deps SYSTEM INTERFACE ${Kokkos_INCLUDE_DIRS})
  target_link_libraries(grout_kokkos_deps INTERFACE ${Kokkos_LIBRARIES} trilinos_sacado
    trilinos_teuchoscore MPI::MPI_CXX)
endif()

# Kokkos, Teuchos (its core, parser, parameter list and comm libraries: Sacado's headers, which
# the contact evaluation includes, use Teuchos' RCP and TimeMonitor) and MPI only: what the
# embedding API (Grout::mortar) and the contact code it runs link (api/CMakeLists.txt).
if(NOT TARGET grout_kokkos_core_deps)
  add_library(grout_kokkos_core_deps INTERFACE)
  target_include_directories(grout_kokkos_core_deps SYSTEM INTERFACE ${Kokkos_INCLUDE_DIRS})
  target_link_libraries(grout_kokkos_core_deps INTERFACE ${Kokkos_LIBRARIES} trilinos_teuchoscomm
    MPI::MPI_CXX)
endif()

# The whole Trilinos closure plus MPI: what assembly/ and nonlinear/ use.
if(NOT TARGET grout_trilinos_deps)
  add_library(grout_trilinos_deps INTERFACE)
  target_include_directories(grout_trilinos_deps SYSTEM INTERFACE
    ${Trilinos_INCLUDE_DIRS} ${Trilinos_TPL_INCLUDE_DIRS})
  target_link_libraries(grout_trilinos_deps INTERFACE
    ${Trilinos_LIBRARIES} ${Trilinos_TPL_LIBRARIES} MPI::MPI_CXX)
endif()

# Exodus II ships no CMake or pkg-config file.
find_path(EXODUS_INCLUDE_DIR exodusII.h REQUIRED)
find_library(EXODUS_LIBRARY NAMES exoIIv2c REQUIRED)
find_path(MUPARSER_INCLUDE_DIR muParser.h REQUIRED)
find_library(MUPARSER_LIBRARY NAMES muparser REQUIRED)

# MUMPS, Debian's PT-SCOTCH build (libmumps-ptscotch-dev: SCOTCH and PT-SCOTCH orderings; the
# plain libmumps-dev has PORD/AMD only). No CMake or pkg-config file either.
find_path(MUMPS_INCLUDE_DIR dmumps_c.h REQUIRED)
find_library(MUMPS_DMUMPS_LIBRARY NAMES dmumps_ptscotch REQUIRED)
find_library(MUMPS_COMMON_LIBRARY NAMES mumps_common_ptscotch REQUIRED)
# SCOTCH's header (libscotch-dev, which libptscotch-dev pulls in): MumpsSolver seeds the
# SCOTCH that MUMPS loaded, found at run time (nonlinear/mumps_solver.cpp).
find_path(SCOTCH_INCLUDE_DIR scotch.h PATH_SUFFIXES scotch REQUIRED)
