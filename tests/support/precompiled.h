// Qt Test, precompiled after cmake/precompiled.h (and app/gui/precompiled.h for widget tests)
// for the test executables. <QTest> alone takes longer to parse than most
// test sources take to compile.
#pragma once

#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
