# Fails if EXE's library closure (ldd) holds MueLu, Belos or Xpetra, or if MODULE (the iterative
# path's module grout_iterative) does not link MueLu and Belos: the driver must load them only at
# the first iterative solve (nonlinear/iterative_module.hpp), since Debian's BIND_NOW Trilinos
# makes every library in the closure cost start-up relocations.
# Usage: cmake -DEXE=<executable> -DMODULE=<libgrout_iterative.so> -P check_no_iterative_libraries.cmake
set(iterative "libtrilinos_(muelu|belos|xpetra)")
execute_process(COMMAND ldd ${EXE} OUTPUT_VARIABLE closure RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "ldd ${EXE} failed")
endif()
string(REGEX MATCHALL "${iterative}[^ ]*" found "${closure}")
if(found)
  message(FATAL_ERROR "${EXE} loads iterative-path libraries at start-up: ${found}")
endif()
string(REGEX MATCHALL "\n" lines "${closure}")
list(LENGTH lines count)
execute_process(COMMAND readelf -d ${MODULE} OUTPUT_VARIABLE needed RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR NOT needed MATCHES "libtrilinos_muelu" OR NOT needed MATCHES "libtrilinos_belos")
  message(FATAL_ERROR "${MODULE} does not link MueLu and Belos:\n${needed}")
endif()
message(STATUS "${EXE}: ${count} libraries, none of MueLu, Belos, Xpetra; the module links MueLu and Belos")
