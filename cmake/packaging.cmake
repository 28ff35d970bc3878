# `cpack -G DEB` in the build folder: a Debian package of what `cmake --install` installs, under
# /usr. Its Depends line is computed by dpkg-shlibdeps (package dpkg-dev) from the libraries the
# program links, so it follows the build (with or without MPI) instead of a list kept by hand.
# The project, not a person, maintains the package; its address is the one every commit of the
# repository carries, the only one the project has. A distributor sets their own here.
set(STRATA_PACKAGE_MAINTAINER "Strata developers <maintainers@users.noreply.h-seed-bb8e34dd.example>"
  CACHE STRING "The .deb's Maintainer field")

set(CPACK_PACKAGE_NAME strata)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT ${STRATA_PACKAGE_MAINTAINER})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "progressive path tracer with the 24-stratum hemisphere estimator")
# Lines of at most 80 columns, as Debian's tools show them.
string(JOIN "\n" CPACK_PACKAGE_DESCRIPTION
  "Strata path traces OBJ and glTF 2.0 scenes with Embree 3 and compares the"
  "24-stratum hemisphere estimator of Dimov, Penzov and Stoilova with uniform and"
  "importance sampling: strata render writes images headless (split over MPI"
  "ranks under mpirun), strata view is the interactive split-view viewer,"
  "strata bench measures error against time. The bundled scenes are in"
  "/usr/share/strata.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # strata_VERSION_ARCH.deb
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The viewer's software offscreen context opens OSMesa at run time rather than linking it
# (app/viewer/offscreen_context.cpp), so dpkg-shlibdeps cannot see it; CPack adds this line to its.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libosmesa6")
# Programs `strata bench` runs when present: mpiexec for its rank comparison, gnuplot for its
# plots, Embree's tutorial path tracer for --vs-embree.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "openmpi-bin, gnuplot-nox, embree-tools, blender")
include(CPack)

# The documentation a Debian package carries: the machine-readable copyright file (Strata's own
# licence status and the notices of the code compiled into the program), the changelog and the
# manual page, the last two compressed as Debian ships them (gzip -9n: no name or time stamp).
include(GNUInstallDirs)
file(STRINGS ${PROJECT_SOURCE_DIR}/cmake/changelog changelogHead LIMIT_COUNT 1)
if(NOT changelogHead MATCHES "^strata \\(${PROJECT_VERSION}\\) ")
  message(FATAL_ERROR "cmake/changelog: its first entry is not version ${PROJECT_VERSION}: add one")
endif()
configure_file(${PROJECT_SOURCE_DIR}/cmake/changelog ${PROJECT_BINARY_DIR}/doc/changelog COPYONLY)
configure_file(${PROJECT_SOURCE_DIR}/cmake/strata.1.in ${PROJECT_BINARY_DIR}/doc/strata.1 @ONLY)
add_custom_command(
  OUTPUT ${PROJECT_BINARY_DIR}/doc/changelog.gz ${PROJECT_BINARY_DIR}/doc/strata.1.gz
  COMMAND gzip -9nkf changelog strata.1
  WORKING_DIRECTORY ${PROJECT_BINARY_DIR}/doc
  DEPENDS ${PROJECT_BINARY_DIR}/doc/changelog ${PROJECT_BINARY_DIR}/doc/strata.1
  VERBATIM)
add_custom_target(strata_package_docs ALL
  DEPENDS ${PROJECT_BINARY_DIR}/doc/changelog.gz ${PROJECT_BINARY_DIR}/doc/strata.1.gz)
install(FILES ${PROJECT_SOURCE_DIR}/cmake/copyright ${PROJECT_BINARY_DIR}/doc/changelog.gz
  DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(FILES ${PROJECT_BINARY_DIR}/doc/strata.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
