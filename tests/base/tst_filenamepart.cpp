// io::fileNamePart(): a workspace line's name becomes part of a file name (monitor --csv's file
// per line) and can never take the file out of its folder (issue 38: a line named
// "/../../ESCAPED" wrote two folders up).
#include "base/filenamepart.h"
#include "testmain.h"

#include <QDir>
#include <QFileInfo>
#include <QTest>

namespace tst_filenamepart {

using tipscope::base::io::fileNamePart;
using tipscope::base::io::kFileNamePartChars;

class TestFileNamePart : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void ordinaryNamesAreKept_data() {
        QTest::addColumn<QString>("name");
        QTest::newRow("plain") << QStringLiteral("cell-3");
        QTest::newRow("spaces and accents") << QStringLiteral("Lötplatz 2");
        QTest::newRow("dots inside") << QStringLiteral("line.2.a");
        QTest::newRow("leading dot and more") << QStringLiteral(".line");
    }
    void ordinaryNamesAreKept() {
        QFETCH(QString, name);
        QCOMPARE(fileNamePart(name), name);
    }

    void namesThatWouldLeaveTheFolderAreMadeSafe_data() {
        QTest::addColumn<QString>("name");
        QTest::addColumn<QString>("part");
        QTest::newRow("climbing") << QStringLiteral("/../../ESCAPED")
                                  << QStringLiteral("_.._.._ESCAPED");
        QTest::newRow("the folder above") << QStringLiteral("..") << QStringLiteral("__");
        QTest::newRow("this folder") << QStringLiteral(".") << QStringLiteral("_");
        QTest::newRow("empty") << QString() << QStringLiteral("_");
        QTest::newRow("backslashes") << QStringLiteral("..\\..\\x") << QStringLiteral(".._.._x");
        QTest::newRow("control characters")
            << QStringLiteral("a\nb\x1b[2Jc") << QStringLiteral("a_b_[2Jc");
        QTest::newRow("a NUL") << QString(QStringLiteral("a") + QChar(0) + QStringLiteral("b"))
                               << QStringLiteral("a_b");
    }
    void namesThatWouldLeaveTheFolderAreMadeSafe() {
        QFETCH(QString, name);
        QFETCH(QString, part);
        QCOMPARE(fileNamePart(name), part);
        // Whatever the name, the file is where it is meant to be.
        const QDir folder(QDir::tempPath());
        const QFileInfo file(folder.filePath(QStringLiteral("plant-") + fileNamePart(name)));
        QCOMPARE(QDir::cleanPath(file.absolutePath()), QDir::cleanPath(folder.absolutePath()));
    }

    void aHugeNameIsCut() {
        const QString part = fileNamePart(QString(100 * 1024, QLatin1Char('n')));
        QCOMPARE(part.size(), kFileNamePartChars);
        QVERIFY(part.toUtf8().size() + QByteArrayLiteral("plant-.csv").size() < 255);
    }
};

TIPSCOPE_TEST_GUILESS_MAIN(TestFileNamePart)

} // namespace tst_filenamepart
#include "tst_filenamepart.moc"
