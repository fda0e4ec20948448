# The charts page and the only widget that uses Qt Charts (see chartwidget.h), plus the
# non-widget pieces it is built from (frames, viewport, measurements, CSV, recorder).
# Global imported targets: tipscope_gui links Qt Charts publicly, so the tests and the bench,
# in other directories, link it too (with its OpenGL dependencies, found by this call).
set(CMAKE_FIND_PACKAGE_TARGETS_GLOBAL ON)
find_package(Qt6 COMPONENTS Charts REQUIRED)
unset(CMAKE_FIND_PACKAGE_TARGETS_GLOBAL)
target_sources(tipscope_gui PRIVATE
    ${CMAKE_CURRENT_LIST_DIR}/chartseries.h
    ${CMAKE_CURRENT_LIST_DIR}/chartseries.cpp
    ${CMAKE_CURRENT_LIST_DIR}/chartframe.h
    ${CMAKE_CURRENT_LIST_DIR}/chartframe.cpp
    ${CMAKE_CURRENT_LIST_DIR}/chartviewport.h
    ${CMAKE_CURRENT_LIST_DIR}/chartviewport.cpp
    ${CMAKE_CURRENT_LIST_DIR}/chartevents.h
    ${CMAKE_CURRENT_LIST_DIR}/chartevents.cpp
    ${CMAKE_CURRENT_LIST_DIR}/measurements.h
    ${CMAKE_CURRENT_LIST_DIR}/measurements.cpp
    ${CMAKE_CURRENT_LIST_DIR}/measurementreport.h
    ${CMAKE_CURRENT_LIST_DIR}/measurementreport.cpp
    ${CMAKE_CURRENT_LIST_DIR}/chartcsv.h
    ${CMAKE_CURRENT_LIST_DIR}/chartcsv.cpp
    ${CMAKE_CURRENT_LIST_DIR}/chartcsvreader.h
    ${CMAKE_CURRENT_LIST_DIR}/chartcsvreader.cpp
    ${CMAKE_CURRENT_LIST_DIR}/chartrecorder.h
    ${CMAKE_CURRENT_LIST_DIR}/chartrecorder.cpp
    ${CMAKE_CURRENT_LIST_DIR}/chartwidget.h
    ${CMAKE_CURRENT_LIST_DIR}/chartwidget_p.h
    ${CMAKE_CURRENT_LIST_DIR}/chartwidget.cpp
    ${CMAKE_CURRENT_LIST_DIR}/chartplotview.cpp
    ${CMAKE_CURRENT_LIST_DIR}/chartspage.h
    ${CMAKE_CURRENT_LIST_DIR}/chartspage.cpp
    ${CMAKE_CURRENT_LIST_DIR}/chartspageactions.cpp
    ${CMAKE_CURRENT_LIST_DIR}/chartspageoverlays.cpp
)
target_link_libraries(tipscope_gui PUBLIC Qt6::Charts)
