# Request queue, line and discovery tests (included by tests/link/CMakeLists.txt).
tipscope_add_test(tst_requestqueue
    SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_requestqueue.cpp
            ${CMAKE_CURRENT_LIST_DIR}/scriptedtransport.h
            ${CMAKE_CURRENT_LIST_DIR}/scriptedtransport.cpp
    LIBS tipscope_link SANITIZED)
tipscope_add_test(tst_line SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_line.cpp LIBS tipscope_link SANITIZED)
tipscope_add_test(tst_discovery SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_discovery.cpp
    LIBS tipscope_link SANITIZED)
tipscope_add_test(tst_serialtransport SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_serialtransport.cpp
    LIBS tipscope_link tipscope_testsupport SANITIZED
    DEPENDS tipscope-sim)
tipscope_add_test(tst_linklogging SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_linklogging.cpp
    LIBS tipscope_link)
tipscope_add_test(tst_simtransport SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_simtransport.cpp
    LIBS tipscope_link SANITIZED)
