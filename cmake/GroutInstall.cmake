# `cmake --install` puts the libraries, headers and a GroutConfig.cmake under the prefix,
# so that another CMake project does
#   find_package(Grout REQUIRED)
#   target_link_libraries(app PRIVATE Grout::grout)   # or Grout::kernels for kernels only
#   target_link_libraries(app PRIVATE Grout::mortar)  # the embedding API, <grout/mortar_coupling.hpp>
# (find_package(Grout REQUIRED COMPONENTS mortar) finds only MPI, Kokkos and Teuchos).
# Everything is installed under a grout/ prefix: <prefix>/include/grout/mortar_coupling.hpp,
# <prefix>/include/grout/{kernels,io,assembly,nonlinear}/ for Grout::grout's users.
include(CMakePackageConfigHelpers)

set_target_properties(grout_kokkos_deps PROPERTIES EXPORT_NAME kokkos_deps)
set_target_properties(grout_kokkos_core_deps PROPERTIES EXPORT_NAME kokkos_core_deps)
set_target_properties(grout_contact_core PROPERTIES EXPORT_NAME contact_core)
set_target_properties(grout_trilinos_deps PROPERTIES EXPORT_NAME trilinos_deps)
set_target_properties(grout_kernels PROPERTIES EXPORT_NAME kernels)
set_target_properties(grout_io PROPERTIES EXPORT_NAME io)
set_target_properties(grout_assembly PROPERTIES EXPORT_NAME assembly)
set_target_properties(grout_nonlinear PROPERTIES EXPORT_NAME nonlinear)
set_target_properties(grout_mortar PROPERTIES EXPORT_NAME mortar)
set_target_properties(grout PROPERTIES EXPORT_NAME grout)

install(TARGETS grout_kokkos_deps grout_kokkos_core_deps grout_trilinos_deps grout_kernels
                grout_contact_core grout_io grout_assembly grout_nonlinear grout_mortar grout
  EXPORT GroutTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
# (No INCLUDES DESTINATION: it would add <prefix>/include/grout to every exported target,
# Grout::mortar included; each target names its own install include directory.)
# The iterative path's module (nonlinear/iterative_module.hpp): found by the installed grout and
# by find_package(Grout) consumers in <libdir>/grout (the path compiled into grout_nonlinear)
# or, for a relocated install, beside the executable in ../lib/grout.
install(TARGETS grout_iterative LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/grout)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/kernels ${PROJECT_SOURCE_DIR}/io
                  ${PROJECT_SOURCE_DIR}/assembly ${PROJECT_SOURCE_DIR}/nonlinear
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/grout FILES_MATCHING PATTERN "*.hpp")
# The embedding API: <grout/mortar_coupling.hpp> (Grout::mortar).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/api/grout DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.hpp")

set(grout_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/Grout)
install(EXPORT GroutTargets NAMESPACE Grout:: DESTINATION ${grout_cmake_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/GroutConfig.cmake.in
  ${PROJECT_BINARY_DIR}/GroutConfig.cmake INSTALL_DESTINATION ${grout_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/GroutConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/GroutConfig.cmake ${PROJECT_BINARY_DIR}/GroutConfigVersion.cmake
  DESTINATION ${grout_cmake_dir})
