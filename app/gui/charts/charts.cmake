# The charts page and the only widget that uses Qt Charts (see chartwidget.h). What they show is
# computed in lib/model (chart, analysis, recording); these files only lay out and paint it.
# Global imported targets: tipscope_gui links Qt Charts publicly, so the tests and the bench,
# in other directories, link it too (with its OpenGL dependencies, found by this call).
set(CMAKE_FIND_PACKAGE_TARGETS_GLOBAL ON)
find_package(Qt6 COMPONENTS Charts REQUIRED)
unset(CMAKE_FIND_PACKAGE_TARGETS_GLOBAL)
target_sources(tipscope_gui PRIVATE
    ${CMAKE_CURRENT_LIST_DIR}/chartwidget.h
    ${CMAKE_CURRENT_LIST_DIR}/chartwidget_p.h
    ${CMAKE_CURRENT_LIST_DIR}/chartwidget.cpp
    ${CMAKE_CURRENT_LIST_DIR}/chartplotview.cpp
    ${CMAKE_CURRENT_LIST_DIR}/chartspage.h
    ${CMAKE_CURRENT_LIST_DIR}/chartspage.cpp
    ${CMAKE_CURRENT_LIST_DIR}/chartspageactions.cpp
    ${CMAKE_CURRENT_LIST_DIR}/chartspageexport.cpp
    ${CMAKE_CURRENT_LIST_DIR}/chartspageoverlays.cpp
    ${CMAKE_CURRENT_LIST_DIR}/chartspagereplay.cpp
    ${CMAKE_CURRENT_LIST_DIR}/readoutpanel.h
    ${CMAKE_CURRENT_LIST_DIR}/readoutpanel.cpp
)
target_link_libraries(tipscope_gui PUBLIC Qt6::Charts tipscope_analysis tipscope_recording)
