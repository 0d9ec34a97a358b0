# grout_load_busiest_libraries_first(<target>): the executable names the shared libraries that
# most symbol look-ups end in first among its DT_NEEDED entries, so that the dynamic loader
# meets them first in the process's global scope.
#
# Why: Debian links Trilinos, OpenBLAS and their dependencies with BIND_NOW, so the loader
# resolves every symbol relocation of the ~90 libraries in grout's closure before main, each
# by walking the global scope (the executable, then the libraries breadth-first in NEEDED
# order) until a library defines the symbol. Most look-ups end in a few libraries, mostly
# their own references to themselves (OpenBLAS 13.5 k of 74 k, Teuchos ParameterList 7.7 k,
# Tpetra 6.5 k, libcrypto 4.0 k, ...), which the natural order put at positions 47, 9, 6 and
# 59. Named first, the scope positions walked by `grout --help`'s look-ups fall from 1.96 M to
# 0.81 M (docs/performance.md, "Process start-up").
#
# Which definition wins does not change where it matters: a symbol defined strongly by two
# libraries binds to the one earlier in the scope, so the list keeps the order of the
# libraries that share strong symbols (ScaLAPACK, then LAPACK, BLAS, OpenBLAS: the first three
# wrap or extend OpenBLAS; libdmumps_ptscotch, which defines Open MPI's Fortran sentinels, stays
# before libmpi). Only C++ vague-linkage definitions (weak or unique: inline functions,
# template instantiations, type info) move to another, identical copy. ctest
# driver_load_order checks both on the built driver. A library that is not installed is left
# out (the BLAS group only as a whole); -DGROUT_LOAD_ORDER=OFF turns the reordering off.
# Amesos2 is not listed: the driver calls KLU2 from its headers (nonlinear/klu_solve.hpp) and
# links no Amesos2.
option(GROUT_LOAD_ORDER "Name the busiest shared libraries first in the driver's DT_NEEDED" ON)

set(GROUT_BUSIEST_LIBRARIES
  # kept in this relative order (shared strong symbols, above)
  libscalapack-openmpi.so.2.2 liblapack.so.3 libblas.so.3 libopenblas.so.0
  # by the number of start-up look-ups that end in them (LD_DEBUG=bindings, 2D Hertz level 1)
  libtrilinos_teuchosparameterlist.so.13.2 libtrilinos_tpetra.so.13.2 libcrypto.so.3
  libstdc++.so.6 libtrilinos_thyracore.so.13.2 libtrilinos_kokkoskernels.so.13.2
  libtrilinos_nox.so.13.2 libtrilinos_epetra.so.13.2
  libnetcdf_mpi.so.19 libtrilinos_teuchoscomm.so.13.2 libopen-pal.so.40 libgnutls.so.30
  libopen-rte.so.40 libnettle.so.8 libtrilinos_teuchoscore.so.13.2)
set(grout_blas_group libscalapack-openmpi.so.2.2 liblapack.so.3 libblas.so.3 libopenblas.so.0)

function(grout_load_busiest_libraries_first target)
  if(NOT GROUT_LOAD_ORDER OR NOT CMAKE_SYSTEM_NAME STREQUAL "Linux")
    return()
  endif()
  set(paths "")
  set(blas_paths "")
  foreach(name IN LISTS GROUT_BUSIEST_LIBRARIES)
    string(MAKE_C_IDENTIFIER "GROUT_LIB_${name}" var)
    find_library(${var} NAMES ${name})
    mark_as_advanced(${var})
    if(name IN_LIST grout_blas_group)
      if(${var})
        list(APPEND blas_paths ${${var}})
      else()
        set(blas_missing TRUE)
      endif()
    elseif(${var})
      list(APPEND paths ${${var}})
    endif()
  endforeach()
  if(NOT blas_missing)
    list(PREPEND paths ${blas_paths})
  endif()
  if(paths)
    # LINK_OPTIONS come before the objects and the link libraries on the link line, so these
    # become the first DT_NEEDED entries; --no-as-needed keeps them although the executable
    # may reference none of their symbols itself.
    target_link_options(${target} PRIVATE "LINKER:--push-state,--no-as-needed" ${paths}
      "LINKER:--pop-state")
  endif()
  # For ctest driver_load_order (unit_tests/check_load_order.py).
  set_property(TARGET ${target} PROPERTY GROUT_BUSIEST_LIBRARIES "${paths}")
endfunction()
