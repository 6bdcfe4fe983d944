# Where `cmake --install` (and the .deb, scripts/package.sh) puts monoplane, in the system's
# places, and the build folder's share/monoplane that mirrors it, so that the executable finds
# its files the same way from either (app/install/install_layout.h):
#   bin/monoplane                          the program
#   lib/<multiarch>/monoplane/libmonoplane_simxr.so
#                                          the simulated headset's OpenXR runtime (private: never
#   share/monoplane/simxr/simxr.json       registered as the system's active runtime)
#   share/monoplane/protocols/             the demo and the paper's protocols
#   share/doc/monoplane/                   README and docs/ (with their images)
#   share/man/man1/                        one page per command (scripts/package.sh, help2man)
#   share/applications/, share/icons/      the launcher's menu entry and icon
# The simulated runtime's rules are in simxr/CMakeLists.txt. Shaders, HMD profiles and the
# study scenes are compiled into the executable; fonts are the system's (fonts-dejavu-core).
include_guard(GLOBAL)

# The build folder's share/monoplane: the source tree's protocols, seen through a link (edits show
# at once), and simxr's manifest for this folder (simxr/CMakeLists.txt).
file(MAKE_DIRECTORY ${PROJECT_BINARY_DIR}/share/monoplane)
file(CREATE_LINK ${PROJECT_SOURCE_DIR}/protocols ${PROJECT_BINARY_DIR}/share/monoplane/protocols
     SYMBOLIC)

install(TARGETS monoplane RUNTIME DESTINATION bin)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/protocols/ DESTINATION share/monoplane/protocols)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION share/doc/monoplane)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION share/doc/monoplane/docs)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/monoplane-lab.desktop
        DESTINATION share/applications)
install(FILES ${PROJECT_SOURCE_DIR}/packaging/monoplane.svg
        DESTINATION share/icons/hicolor/scalable/apps)

# The man pages, the changelog and the copyright file scripts/package.sh makes or copies into the
# build folder before CPack runs (absent in a plain build: nothing to install then).
install(DIRECTORY ${PROJECT_BINARY_DIR}/man/ DESTINATION share/man/man1 OPTIONAL
        FILES_MATCHING PATTERN "*.1.gz")
install(DIRECTORY ${PROJECT_BINARY_DIR}/package-doc/ DESTINATION share/doc/monoplane OPTIONAL)
