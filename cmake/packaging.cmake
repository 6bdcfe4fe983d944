# The .deb of scripts/package.sh, made by CPack's DEB generator from cmake/install.cmake's rules.
# Its version is the project's and the commit's: 0.1.0+g<12 hex digits> (MONOPLANE_PACKAGE_VERSION,
# which scripts/package.sh passes; "+gunknown" outside a git checkout). Dependencies: what
# dpkg-shlibdeps finds the binaries linked against, plus what they load at run time and so do not
# link: a Vulkan driver (lavapipe, the fallback on any machine), the font the headset's pages and
# the launcher use, and the OpenXR loader's runtime registry tools for a real headset's runtime.
include_guard(GLOBAL)

set(MONOPLANE_PACKAGE_VERSION "${PROJECT_VERSION}+gunknown" CACHE STRING
    "The .deb's version (scripts/package.sh sets it from git)")

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME monoplane)
set(CPACK_PACKAGE_VERSION ${MONOPLANE_PACKAGE_VERSION})
set(CPACK_PACKAGE_CONTACT "monoplane developers <monoplane@example.org>")
set(CPACK_PACKAGE_VENDOR "monoplane")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "hybrid mono-stereo rendering and 2AFC perception studies for VR")
# CPack puts the summary above these lines as the synopsis and indents them by one space.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
    "monoplane renders content nearer than a mono plane once per eye and
content beyond it once, mapped into both eyes (Fink et al. 2019), and
runs two-alternative forced-choice studies of the approximation on an
OpenXR headset or a simulated one: the experimenter's launcher
(monoplane lab), sessions logged to SQLite, exports and the analysis. It
also benchmarks run time against error. The simulated headset's runtime
is private to monoplane and is never registered as the system's OpenXR
runtime.")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://example.org/monoplane")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "mesa-vulkan-drivers, fonts-dejavu-core")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "libopenxr-utils")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "vulkan-validationlayers, fonts-wqy-microhei")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION TRUE)
set(CPACK_STRIP_FILES TRUE)
set(CPACK_SET_DESTDIR OFF)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
include(CPack)
