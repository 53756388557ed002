# A Debian package of this build: `cpack -G DEB` in the build folder writes
# subd_<version>_<arch>.deb. It installs under /usr, where Debian's python3 finds the `subd`
# package (lib/python3/dist-packages) and the programs find the libraries through their
# RUNPATH. The libraries' dependencies (VTK 9.1, Qt 5, ParaView for the plugin, Open MPI for
# subd-mpi) are read from the binaries by dpkg-shlibdeps; the Python modules' are declared.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME subd)
set(CPACK_PACKAGE_VENDOR "SubD")
set(CPACK_PACKAGE_CONTACT "SubD developers <subd@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION "Subdivision surfaces and curves as VTK filters: Catmull-Clark, Loop, Doo-Sabin,
 modified butterfly, midpoint, sqrt(3), linear and curve schemes, with creases, limit
 positions, normals and curvature. The subd and subd-explorer programs, the libraries, headers
 and CMake package, the Python package (import subd) and the ParaView plugin.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# SubD's own libraries are in the package: dpkg-shlibdeps finds them in the staging tree.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3, python3-vtk9, python3-numpy")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "python3-meshio, paraview")
include(CPack)
