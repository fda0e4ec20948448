# The support pages: usage counters and errors (current state and history).
target_sources(tipscope_gui PRIVATE
    ${CMAKE_CURRENT_LIST_DIR}/counterspage.h
    ${CMAKE_CURRENT_LIST_DIR}/counterspage.cpp
    ${CMAKE_CURRENT_LIST_DIR}/errorspage.h
    ${CMAKE_CURRENT_LIST_DIR}/errorspage.cpp
    ${CMAKE_CURRENT_LIST_DIR}/errorstatepanel.h
    ${CMAKE_CURRENT_LIST_DIR}/errorstatepanel.cpp
    ${CMAKE_CURRENT_LIST_DIR}/eventhistorypanel.h
    ${CMAKE_CURRENT_LIST_DIR}/eventhistorypanel.cpp
    ${CMAKE_CURRENT_LIST_DIR}/levelstyle.h
    ${CMAKE_CURRENT_LIST_DIR}/levelstyle.cpp
)
