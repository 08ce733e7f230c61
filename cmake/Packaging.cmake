# Debian package (`cpack -G DEB` in the build folder): floorcover and floorcover-cli with
# the desktop entry and icon. Runtime libraries are found by dpkg-shlibdeps.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME floorcover)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "${PROJECT_DESCRIPTION}")
set(CPACK_PACKAGE_DESCRIPTION
    "Coverage path planning for cleaning and disinfection robots on polygonal floor plans: a desktop editor (floorcover) and a command line (floorcover-cli).")
set(CPACK_PACKAGE_VENDOR "FloorCover")
set(CPACK_PACKAGE_CONTACT "FloorCover maintainers <floorcover@example.invalid>")
set(CPACK_PACKAGE_HOMEPAGE_URL "${PROJECT_HOMEPAGE_URL}")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_LICENSE "GPL-3.0-or-later")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Qt's own translations for standard dialogs; the editor runs without them.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "qt6-translations-l10n")
set(CPACK_STRIP_FILES ON)
include(CPack)
