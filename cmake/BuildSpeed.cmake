# What makes the build fast, and only what the figures in docs/development.md say helps. None of
# it is needed: without mold, lld or ccache the build is the same, only slower.
#
# A faster linker. Debian's mold (or lld) links the test executables several times faster than
# ld.bfd.
set(TIPSCOPE_LINKER "auto" CACHE STRING "Linker: auto (mold, else lld, else the default), mold, lld or default")
if(TIPSCOPE_LINKER STREQUAL "auto")
    find_program(TIPSCOPE_MOLD_PROGRAM mold)
    find_program(TIPSCOPE_LLD_PROGRAM ld.lld)
    if(TIPSCOPE_MOLD_PROGRAM)
        add_link_options(-fuse-ld=mold)
    elseif(TIPSCOPE_LLD_PROGRAM)
        add_link_options(-fuse-ld=lld)
    endif()
elseif(NOT TIPSCOPE_LINKER STREQUAL "default")
    add_link_options(-fuse-ld=${TIPSCOPE_LINKER})
endif()

# ccache, when installed, serves what was compiled before, in this checkout or another one.
option(TIPSCOPE_CCACHE "Compile through ccache when it is installed" ON)
find_program(TIPSCOPE_CCACHE_PROGRAM ccache)
if(TIPSCOPE_CCACHE AND TIPSCOPE_CCACHE_PROGRAM AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
    # The precompiled headers are only cached with these sloppinesses (ccache's manual,
    # "Precompiled headers"); the base folder lets another checkout of the same sources hit.
    set(CMAKE_CXX_COMPILER_LAUNCHER env
        CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
        CCACHE_BASEDIR=${PROJECT_SOURCE_DIR} ${TIPSCOPE_CCACHE_PROGRAM})
endif()

# moc without the compiler's own include folders. Given them, moc reads the standard library's
# headers behind every Qt header a file includes, to learn their macros: two seconds for a test
# file, a quarter of that without them. Nothing there concerns moc (no QObject, no
# Q_DECLARE_METATYPE, no macro moc expands): over every file AUTOMOC reads here, moc's output is
# the same to the byte either way (docs/development.md, "moc"). Qt's and the project's folders
# stay, as moc needs them to know which types are QObjects.
option(TIPSCOPE_FAST_MOC "Run moc without the compiler's own include folders" ON)
if(TIPSCOPE_FAST_MOC)
    get_target_property(QT_MOC Qt6::moc IMPORTED_LOCATION)
    list(TRANSFORM CMAKE_CXX_IMPLICIT_INCLUDE_DIRECTORIES PREPEND "-I" OUTPUT_VARIABLE systemIncludes)
    list(JOIN systemIncludes " " SYSTEM_INCLUDES)
    configure_file(${CMAKE_CURRENT_LIST_DIR}/moc-without-system-includes.in
        ${PROJECT_BINARY_DIR}/moc-without-system-includes @ONLY
        FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE
                         WORLD_READ WORLD_EXECUTE)
endif()

# Precompiled headers: the Qt and standard headers that nearly every translation unit includes,
# parsed once per configuration instead of once per source (docs/development.md has the figures).
#
# GCC uses a precompiled header only where every macro it looked at is defined the same way, so
# there is one flavour per combination that matters: core (lib/ and app/), widgets (the window),
# test and test with widgets (Qt Test looks at QT_GUI_LIB, QT_WIDGETS_LIB and QT_NETWORK_LIB).
# Each flavour is a small object library that compiles its header once; every other target
# reuses the flavour that matches what it links (tipscope_assign_precompiled_headers, run when
# all targets exist). TIPSCOPE_PRECOMPILE_HEADERS=OFF builds without them.
option(TIPSCOPE_PRECOMPILE_HEADERS "Parse the common Qt headers once per configuration" ON)

# The tests' own code (what links Qt Test: the tests, their support and their precompiled
# headers) is compiled without optimisation in every configuration. The code under test keeps its
# configuration's options (-O2 as shipped, -O1 under the sanitizers); a test's own code runs
# for microseconds, and optimising it was a third of its compile (docs/development.md, "test
# code"). Appended after the configuration's flags, so it wins; empty keeps them.
set(TIPSCOPE_TEST_CODE_OPTIONS "-O0" CACHE STRING "Compile options for the tests' own code")

set(TIPSCOPE_CORE_PCH ${CMAKE_CURRENT_LIST_DIR}/precompiled.h)
set(TIPSCOPE_PCH_SOURCE ${CMAKE_CURRENT_LIST_DIR}/precompiled.cpp)

# A flavour: `name` precompiles HEADERS (in order) with the macros that LIBS define.
function(tipscope_add_pch name)
    cmake_parse_arguments(P "" "" "HEADERS;LIBS" ${ARGN})
    if(NOT TIPSCOPE_PRECOMPILE_HEADERS)
        return()
    endif()
    add_library(${name} OBJECT ${TIPSCOPE_PCH_SOURCE})
    set_target_properties(${name} PROPERTIES AUTOMOC OFF AUTOUIC OFF AUTORCC OFF)
    target_link_libraries(${name} PRIVATE ${P_LIBS})
    target_precompile_headers(${name} PRIVATE ${P_HEADERS})
    if("Qt6::Test" IN_LIST P_LIBS) # compiled as the tests that reuse it
        target_compile_options(${name} PRIVATE ${TIPSCOPE_TEST_CODE_OPTIONS})
    endif()
    set_property(GLOBAL APPEND PROPERTY TIPSCOPE_PCH_TARGETS ${name})
endfunction()

tipscope_add_pch(tipscope_pch_core HEADERS ${TIPSCOPE_CORE_PCH} LIBS Qt6::Core)

# The targets that `targets` (one or a list) link, directly or through the project's own
# libraries, with themselves.
function(tipscope_link_closure targets out)
    set(seen)
    set(todo ${targets})
    while(todo)
        list(POP_FRONT todo current)
        if(current IN_LIST seen OR NOT TARGET ${current})
            continue()
        endif()
        list(APPEND seen ${current})
        get_target_property(imported ${current} IMPORTED)
        if(imported)
            continue()
        endif()
        get_target_property(type ${current} TYPE)
        set(links)
        if(NOT type STREQUAL "INTERFACE_LIBRARY")
            get_target_property(links ${current} LINK_LIBRARIES)
        endif()
        get_target_property(interfaceLinks ${current} INTERFACE_LINK_LIBRARIES)
        foreach(link IN LISTS links interfaceLinks)
            if(link AND NOT link MATCHES "NOTFOUND$" AND NOT link MATCHES "^\\$<")
                list(APPEND todo ${link})
            endif()
        endforeach()
    endwhile()
    set(${out} ${seen} PARENT_SCOPE)
endfunction()

# Every compiled target under `dir` runs the faster moc and reuses the precompiled headers that
# match what it links.
function(tipscope_speed_up_targets dir)
    get_property(flavours GLOBAL PROPERTY TIPSCOPE_PCH_TARGETS)
    tipscope_targets_under(${dir} targets)
    foreach(target IN LISTS targets)
        get_target_property(type ${target} TYPE)
        if(NOT type MATCHES "^(STATIC_LIBRARY|SHARED_LIBRARY|OBJECT_LIBRARY|EXECUTABLE)$"
           OR target IN_LIST flavours)
            continue()
        endif()
        get_target_property(automoc ${target} AUTOMOC)
        if(automoc AND TIPSCOPE_FAST_MOC)
            set_target_properties(${target} PROPERTIES
                AUTOMOC_EXECUTABLE ${PROJECT_BINARY_DIR}/moc-without-system-includes)
        endif()
        tipscope_link_closure(${target} closure)
        if("Qt6::Test" IN_LIST closure)
            target_compile_options(${target} PRIVATE ${TIPSCOPE_TEST_CODE_OPTIONS})
        endif()
        if(NOT TIPSCOPE_PRECOMPILE_HEADERS)
            continue()
        endif()
        get_target_property(sources ${target} SOURCES)
        list(FILTER sources INCLUDE REGEX "\\.cpp$")
        if(NOT sources)
            continue()
        endif()
        set(flavour tipscope_pch_core)
        if("Qt6::Test" IN_LIST closure)
            set(flavour tipscope_pch_test)
            if("Qt6::Widgets" IN_LIST closure)
                set(flavour tipscope_pch_testwidgets)
            endif()
            # What Qt Test's headers look at, alike in every test (see tests/CMakeLists.txt).
            target_link_libraries(${target} PRIVATE Qt6::Gui Qt6::Network)
            set_target_properties(${target} PROPERTIES QT_TESTCASE_BUILDDIR ${PROJECT_BINARY_DIR})
        elseif("Qt6::Widgets" IN_LIST closure)
            set(flavour tipscope_pch_widgets)
        endif()
        if(TARGET ${flavour})
            target_precompile_headers(${target} REUSE_FROM ${flavour})
            # What moc leaves to compile is empty for a test (its source includes its moc output)
            # and small for a library: loading the precompiled header would be most of its cost.
            get_target_property(binaryDir ${target} BINARY_DIR)
            set_source_files_properties(${binaryDir}/${target}_autogen/mocs_compilation.cpp
                TARGET_DIRECTORY ${target} PROPERTIES SKIP_PRECOMPILE_HEADERS ON)
        endif()
    endforeach()
endfunction()

# Every target defined in `dir` and below it (also used by lib/i18n).
function(tipscope_targets_under dir out)
    get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
    get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
    foreach(subdir IN LISTS subdirs)
        tipscope_targets_under(${subdir} more)
        list(APPEND targets ${more})
    endforeach()
    set(${out} ${targets} PARENT_SCOPE)
endfunction()
