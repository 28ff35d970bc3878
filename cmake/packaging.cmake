# `cpack -G DEB` in the build folder: a Debian package of what `cmake --install` installs, under
# /usr. Its Depends line is computed by dpkg-shlibdeps (package dpkg-dev) from the libraries the
# program links, so it follows the build (with or without MPI) instead of a list kept by hand.
set(STRATA_PACKAGE_MAINTAINER "Strata maintainers <maintainers@users.noreply.h-seed-bb8e34dd.example>"
  CACHE STRING "The .deb's Maintainer field (default: the address the repository's commits carry)")

set(CPACK_PACKAGE_NAME strata)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT ${STRATA_PACKAGE_MAINTAINER})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "progressive path tracer with the 24-stratum hemisphere estimator")
# Lines of at most 80 columns, as Debian's tools show them.
string(JOIN "\n" CPACK_PACKAGE_DESCRIPTION
  "Strata renders OBJ scenes with Embree 3 and compares the 24-stratum hemisphere"
  "estimator of Dimov, Penzov and Stoilova with uniform and importance sampling:"
  "strata render writes images headless, strata view is the interactive"
  "split-view viewer, strata bench measures error against time. The bundled"
  "scenes are in /usr/share/strata.")
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
