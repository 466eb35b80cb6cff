# What `cmake --install` and the Debian package (`cpack -G DEB`) install: the binary, the share
# files it reads (found next to it, <prefix>/share/sfcv), the man page, the bash and zsh
# completions and the documentation that --help points to.
include(GNUInstallDirs)
install(TARGETS sfcv RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(FILES share/sfcv/properties.sfq share/sfcv/patterns.spec share/sfcv/check-result.schema.json
              share/sfcv/info.schema.json share/sfcv/lint.schema.json share/sfcv/query.schema.json
              share/sfcv/rsg.schema.json
        DESTINATION ${CMAKE_INSTALL_DATADIR}/sfcv)
install(FILES docs/man/sfcv.1 DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES share/completions/sfcv.bash
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions RENAME sfcv)
install(FILES share/completions/_sfcv DESTINATION ${CMAKE_INSTALL_DATADIR}/zsh/vendor-completions)
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}
        FILES_MATCHING PATTERN "*.md" PATTERN "*.png" PATTERN "man" EXCLUDE)
install(DIRECTORY examples/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/examples)

# The Debian package: `cpack -G DEB` in the build folder (scripts/test-package.sh tests it).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME sfcv)
set(CPACK_PACKAGE_VENDOR "sfcv")
set(CPACK_PACKAGE_CONTACT "sfcv maintainers <sfcv@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "verifier for Sequential Function Charts (IEC 61131-3) and Grafcet (IEC 60848)")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION devel)
# The shared libraries it links (BuDDy, pugixml, the C++ runtime) become Depends.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "graphviz, spin")
include(CPack)
