# SPDX-License-Identifier: Apache-2.0
# Installation (`cmake --install build [--prefix P]`) and the Debian package (`cpack` in the build
# folder: CPack's DEB generator, prefix /usr, dependencies from dpkg-shlibdeps):
#   P/bin/wrc                      the front end (wrc-cli of the build)
#   P/bin/wrc-contactd, wrc-geometryd, wrc-dynamicsd, wrc-pingd   the services
#   P/share/wrc/profiles, parameters   the shipped profile files, launch profiles, run parameters
#   P/share/java/wrc_lcmtypes_java.jar  the message types for lcm-spy
#   P/share/doc/wrc                README.md, CHANGELOG.md, LICENSE, NOTICE and docs/
# An installed wrc finds its services next to itself and its data in P/share/wrc
# (services/bus/process/build_paths.hpp).
include(GNUInstallDirs)
install(TARGETS wrc-contactd wrc-geometryd wrc-dynamicsd wrc-pingd RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(PROGRAMS $<TARGET_FILE:wrc-cli> DESTINATION ${CMAKE_INSTALL_BINDIR} RENAME wrc)
install(DIRECTORY "${PROJECT_SOURCE_DIR}/profiles/" DESTINATION ${CMAKE_INSTALL_DATADIR}/wrc/profiles)
install(DIRECTORY "${PROJECT_SOURCE_DIR}/parameters/" DESTINATION ${CMAKE_INSTALL_DATADIR}/wrc/parameters)
install(FILES $<TARGET_PROPERTY:wrc_lcmtypes_java,JAR_FILE> DESTINATION ${CMAKE_INSTALL_DATADIR}/java)
install(FILES "${PROJECT_SOURCE_DIR}/README.md" "${PROJECT_SOURCE_DIR}/CHANGELOG.md" "${PROJECT_SOURCE_DIR}/LICENSE"
              "${PROJECT_SOURCE_DIR}/NOTICE" DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY "${PROJECT_SOURCE_DIR}/docs/" DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME wrc)
set(CPACK_PACKAGE_VENDOR "The wrc developers")
set(CPACK_PACKAGE_CONTACT "The wrc developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "wheel-rail contact after M. Arnold: exact geometry, Hertz and FASTSIM, spline model, wheelset dynamics")
set(CPACK_PACKAGE_DESCRIPTION
    "The contact between a railway wheelset and its track (S1002 on UIC60 and profile files): all potential common points, the rigid wheelset, four contact models as LCM services, and the wheelset's dynamics with SUNDIALS IDA.")
set(CPACK_RESOURCE_FILE_LICENSE "${PROJECT_SOURCE_DIR}/LICENSE")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Not linked, but what `wrc plot` and `wrc spy` run.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "gnuplot-nox, liblcm-java, libjchart2d-java, default-jre-headless")
include(CPack)
