# Debian package of everything `cmake --install` installs (the executables, the desktop entry,
# the application icon). Build first, then in the build directory: `cpack -G DEB`.
# The translations need no install rule: the .qm files are embedded in the executables (:/i18n).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME learnid)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)

set(LEARNID_PACKAGE_MAINTAINER "learnid developers <learnid@example.org>"
    CACHE STRING "Maintainer field of the Debian package")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${LEARNID_PACKAGE_MAINTAINER}")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT) # learnid_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "Identifies a robot's dynamic parameters by learning identification: the robot runs its\n\
production trajectory a few times, and the estimate is corrected after each trial from the\n\
measured joint angles and torques. Desktop commissioning window (learnid), command line\n\
(learnid-cli) and a simulated CANopen robot (learnid-robot-sim).")
# The shared libraries the installed binaries link (the Qt 6 runtime) become Depends through
# dpkg-shlibdeps (package dpkg-dev, part of build-essential).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# The window's icons are SVG: Qt's SVG icon engine plugin (package libqt6svg6) loads them. A build
# with Qt6::Svg links that library anyway; without it the plugin is a run-time dependency only.
find_package(Qt6 QUIET COMPONENTS Svg)
if(NOT Qt6Svg_FOUND)
    set(CPACK_DEBIAN_PACKAGE_DEPENDS "libqt6svg6")
endif()

include(CPack)
