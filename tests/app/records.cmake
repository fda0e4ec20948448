# Widget tests of the support pages, on a real Session in demo mode (a simulated 19200 Bd wire,
# so a test waits for real polls).
tipscope_add_test(tst_counterspage SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_counterspage.cpp
                  LIBS tipscope_gui tipscope_demosupport TIMEOUT 300)
tipscope_add_test(tst_errorspage SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_errorspage.cpp
                  LIBS tipscope_gui tipscope_demosupport TIMEOUT 300)
# A command added to the catalog (and nowhere else) reaches the Settings and Counters pages.
tipscope_add_test(tst_newcatalogentry SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_newcatalogentry.cpp
                  LIBS tipscope_gui tipscope_demosupport TIMEOUT 300)
# The ALE's dispensing page against tipscope-sim serving an ALE over TCP.
tipscope_add_test(tst_dispensingpage SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_dispensingpage.cpp
                  LIBS tipscope_gui tipscope_testsupport tipscope_sim TIMEOUT 300
    DEPENDS tipscope-sim)
