# The fleet overview: a tile per device of every line of a workspace and of a watched plant, and
# the read-only page of a device another TipScope publishes.
target_sources(tipscope_gui PRIVATE
    ${CMAKE_CURRENT_LIST_DIR}/fleetpage.h
    ${CMAKE_CURRENT_LIST_DIR}/fleetpage.cpp
    ${CMAKE_CURRENT_LIST_DIR}/fleettilewidget.h
    ${CMAKE_CURRENT_LIST_DIR}/fleettilewidget.cpp
    ${CMAKE_CURRENT_LIST_DIR}/remotedevicepage.h
    ${CMAKE_CURRENT_LIST_DIR}/remotedevicepage.cpp
)
target_link_libraries(tipscope_gui PUBLIC tipscope_workspace)
