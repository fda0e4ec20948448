// The main() of a folder's test executable: `tests_model tst_pollscheduler [Qt Test options]` runs
// the one test named, as its own executable did before (testmain.h says why they share one).
#include "testmain.h"

#include <QCoreApplication>
#include <QFileInfo>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

namespace tipscope::testing {

namespace {

std::map<std::string, TestMain> &registeredTests() {
    // Built on first use: the registrations are static objects in other translation units.
    static std::map<std::string, TestMain> tests;
    return tests;
}

int usage(const char *program) {
    std::fprintf(stderr, "usage: %s TEST [Qt Test options]\n       %s --list\ntests:\n", program,
                 program);
    for (const auto &[name, main] : registeredTests())
        std::fprintf(stderr, "  %s\n", name.c_str());
    return 2;
}

} // namespace

TestRegistration::TestRegistration(const char *sourceFile, TestMain main) {
    const std::string name = QFileInfo(QString::fromLocal8Bit(sourceFile)).baseName().toStdString();
    if (!registeredTests().emplace(name, main).second) {
        std::fprintf(stderr, "two tests are named %s\n", name.c_str());
        std::abort();
    }
}

} // namespace tipscope::testing

int main(int argc, char *argv[]) {
    using tipscope::testing::registeredTests;
    if (argc >= 2 && std::string(argv[1]) == "--list") {
        for (const auto &[name, main] : registeredTests())
            std::printf("%s\n", name.c_str());
        return 0;
    }
    if (argc < 2 || registeredTests().count(argv[1]) == 0)
        return tipscope::testing::usage(argv[0]);
    const std::string name = argv[1];
    // What the test's own executable was called: QTemporaryDir's and QSettings' default names.
    QCoreApplication::setApplicationName(QString::fromStdString(name));
    std::vector<char *> args{argv[0]};
    args.insert(args.end(), argv + 2, argv + argc);
    args.push_back(nullptr);
    return registeredTests().at(name)(int(args.size()) - 1, args.data());
}
