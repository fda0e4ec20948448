# Installs the translations (.qm files) that the build made, wherever lrelease put them in the
# build tree, into <prefix>/share/tipscope/translations. Run by `cmake --install` and by CPack;
# installs nothing when the build made none.
#
# Set by packaging/CMakeLists.txt just before this script runs:
#   TIPSCOPE_QM_SEARCH_DIR   the top of the build tree
#   TIPSCOPE_QM_DESTINATION  the folder relative to the install prefix
file(GLOB_RECURSE qmFiles LIST_DIRECTORIES false "${TIPSCOPE_QM_SEARCH_DIR}/*.qm")
# Leave out copies that are themselves installs: CPack's staging folder and the scratch roots
# the packaging tests unpack the package into.
list(FILTER qmFiles EXCLUDE REGEX "/_CPack_Packages/|/share/tipscope/translations/")
list(SORT qmFiles)
if(qmFiles)
    file(INSTALL ${qmFiles} DESTINATION "${CMAKE_INSTALL_PREFIX}/${TIPSCOPE_QM_DESTINATION}")
endif()
