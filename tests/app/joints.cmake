# The Joints page: history from a real journal file, live joints from the demo station, filters,
# CSV export, and a joint opened on the Charts page.
tipscope_add_test(tst_jointspage SOURCES ${CMAKE_CURRENT_LIST_DIR}/tst_jointspage.cpp
                  LIBS tipscope_gui tipscope_i18n tipscope_demosupport TIMEOUT 300)
