# The charts: their non-widget logic on hand-made telemetry (decimation to points, readout,
# time window, measurements; the CSV and the recorder), the curves as drawn on a real widget,
# and the page against the demo line.
tipscope_add_test(tst_chartsdata SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_chartsdata.cpp
                  LIBS tipscope_gui)
tipscope_add_test(tst_chartscsv SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_chartscsv.cpp
                  LIBS tipscope_gui)
tipscope_add_test(tst_chartwidget SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_chartwidget.cpp
                  LIBS tipscope_gui)
tipscope_add_test(tst_chartspage SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_chartspage.cpp
                  LIBS tipscope_gui TIMEOUT 300)
