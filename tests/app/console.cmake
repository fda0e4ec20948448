# The raw frame console page, driven through its widgets against the demo line.
tipscope_add_test(tst_consolepage SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_consolepage.cpp LIBS tipscope_gui tipscope_demosupport)
