# The charts' widgets: the curves as drawn on a real widget, and the page against the demo line.
# Their widget-free parts are tested under tests/model (chart, analysis, recording).
tipscope_add_test(tst_chartwidget SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_chartwidget.cpp
                  LIBS tipscope_gui)
tipscope_add_test(tst_chartspage SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_chartspage.cpp
                  LIBS tipscope_gui tipscope_demosupport TIMEOUT 300)
tipscope_add_test(tst_chartslayout SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_chartslayout.cpp
                  LIBS tipscope_gui tipscope_i18n TIMEOUT 300)
