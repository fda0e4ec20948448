# The Joints page: the journal's joints and the live ones, with their charts.
target_sources(tipscope_gui PRIVATE
    ${CMAKE_CURRENT_LIST_DIR}/jointspage.h
    ${CMAKE_CURRENT_LIST_DIR}/jointspage.cpp
    ${CMAKE_CURRENT_LIST_DIR}/jointcharts.h
    ${CMAKE_CURRENT_LIST_DIR}/jointcharts.cpp
)
target_link_libraries(tipscope_gui PUBLIC tipscope_journal)
