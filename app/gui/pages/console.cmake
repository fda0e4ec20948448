# The raw frame console page and its frame builder.
target_sources(tipscope_gui PRIVATE
    ${CMAKE_CURRENT_LIST_DIR}/consolepage.h
    ${CMAKE_CURRENT_LIST_DIR}/consolepage.cpp
    ${CMAKE_CURRENT_LIST_DIR}/framebuilder.h
    ${CMAKE_CURRENT_LIST_DIR}/framebuilder.cpp
)
