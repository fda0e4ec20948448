# The fleet overview: a tile per device of every line of a workspace.
target_sources(tipscope_gui PRIVATE
    ${CMAKE_CURRENT_LIST_DIR}/fleetpage.h
    ${CMAKE_CURRENT_LIST_DIR}/fleetpage.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fleettilewidget.h
    ${CMAKE_CURRENT_LIST_DIR}/fleettilewidget.cpp
)
target_link_libraries(tipscope_gui PUBLIC tipscope_workspace)
