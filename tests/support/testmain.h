// A test's main(), registered under the test's name in its folder's test executable.
//
// The tests of one folder are linked into one executable (tests/CMakeLists.txt): a unity batch
// of eight test sources shares the cost of starting the compiler, loading the precompiled Qt
// headers and instantiating Qt Test's templates, which was most of each test's compile
// (docs/development.md). CTest still runs each test alone, in a process of its own
// (`tests_model tst_pollscheduler`), so a test sees nothing of the others but their code.
//
// TIPSCOPE_TEST_MAIN and TIPSCOPE_TEST_GUILESS_MAIN do what QTEST_MAIN and QTEST_GUILESS_MAIN do,
// in a function registered under the source's name (tst_pollscheduler.cpp: "tst_pollscheduler").
#pragma once

#include <QTest>

namespace tipscope::testing {

using TestMain = int (*)(int argc, char *argv[]);

struct TestRegistration {
    TestRegistration(const char *sourceFile, TestMain main);
};

} // namespace tipscope::testing

// Qt's own QTEST_MAIN_WRAPPER, with a registered function in place of main(): the same
// application class for the same linked modules (QTEST_MAIN_SETUP), the same initMain() hook.
#define TIPSCOPE_TEST_MAIN_WRAPPER(TestObject, ...)                                                \
    static int tipscopeTestMain_##TestObject(int argc, char *argv[]) {                             \
        QT_PREPEND_NAMESPACE(QTest::Internal::callInitMain)<TestObject>();                         \
        __VA_ARGS__                                                                                \
        TestObject tc;                                                                             \
        QTEST_SET_MAIN_SOURCE_PATH                                                                 \
        return QTest::qExec(&tc, argc, argv);                                                      \
    }                                                                                              \
    static const ::tipscope::testing::TestRegistration tipscopeTestRegistration_##TestObject(      \
        __FILE__, &tipscopeTestMain_##TestObject);

#define TIPSCOPE_TEST_MAIN(TestObject) TIPSCOPE_TEST_MAIN_WRAPPER(TestObject, QTEST_MAIN_SETUP())
#define TIPSCOPE_TEST_GUILESS_MAIN(TestObject)                                                     \
    TIPSCOPE_TEST_MAIN_WRAPPER(TestObject, QTEST_QAPP_SETUP(QCoreApplication))
