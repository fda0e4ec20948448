// The one atomic-save helper: a save replaces the file whole, and a save that cannot be done
// leaves what was there, leaves no temporary file behind, and says which file and why.
#include "base/atomicsave.h"
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTest>

namespace tst_atomicsave {

using namespace tipscope::base;

class TestAtomicSave : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aSaveReplacesTheFileWhole();
    void aFailedSaveLeavesWhatWasThereAndSaysWhy_data();
    void aFailedSaveLeavesWhatWasThereAndSaysWhy();
    void aStreamedSaveThatFailsHalfWayLeavesTheOldFile();
};

void TestAtomicSave::aSaveReplacesTheFileWhole() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("out.txt"));
    QVERIFY(io::saveAtomically(path, QByteArray("a much longer first version\n")).ok());
    const auto saved = io::saveAtomically(path, QByteArray("second\n"));
    QVERIFY(saved.ok());
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(f.readAll(), QByteArray("second\n"));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files), QStringList{QStringLiteral("out.txt")});
}

void TestAtomicSave::aFailedSaveLeavesWhatWasThereAndSaysWhy_data() {
    QTest::addColumn<QString>("name");
    QTest::newRow("no such folder") << QStringLiteral("missing/out.txt");
    QTest::newRow("a folder in the way") << QStringLiteral("folder");
}

void TestAtomicSave::aFailedSaveLeavesWhatWasThereAndSaysWhy() {
    QFETCH(QString, name);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    QVERIFY(QDir(dir.path()).mkdir(QStringLiteral("folder")));
    const QString path = dir.filePath(name);

    const auto saved = io::saveAtomically(path, QByteArray("data\n"));

    QVERIFY(!saved.ok());
    QVERIFY2(saved.error().startsWith(QStringLiteral("cannot write %1: ").arg(path)),
             qPrintable(saved.error()));
    QVERIFY2(saved.error().size() > QStringLiteral("cannot write %1: ").arg(path).size(),
             qPrintable(saved.error()));
    QVERIFY(QFileInfo(dir.filePath(QStringLiteral("folder"))).isDir());
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden), QStringList());
}

// A file written piece by piece (a day of a chart as CSV) is replaced whole or not at all too.
void TestAtomicSave::aStreamedSaveThatFailsHalfWayLeavesTheOldFile() {
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString path = dir.filePath(QStringLiteral("out.csv"));
    QVERIFY(io::saveAtomically(path, QByteArray("old\n")).ok());
    const auto failed = io::saveAtomically(path, [](QIODevice &file) {
        file.write("first half of the new file\n");
        return false;
    });
    QVERIFY(!failed.ok());
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(f.readAll(), QByteArray("old\n"));
    f.close();
    const auto streamed = io::saveAtomically(path, [](QIODevice &file) {
        return file.write("new, ") == 5 && file.write("in two pieces\n") == 14;
    });
    QVERIFY2(streamed.ok(), qPrintable(streamed.error()));
    QVERIFY(f.open(QIODevice::ReadOnly));
    QCOMPARE(f.readAll(), QByteArray("new, in two pieces\n"));
    QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden),
             QStringList{QStringLiteral("out.csv")});
}

TIPSCOPE_TEST_GUILESS_MAIN(TestAtomicSave)

} // namespace tst_atomicsave
#include "tst_atomicsave.moc"
