// readJsonObject(): every way a small JSON settings file can fail comes back as its own kind, so
// each reader can say it in its own words; a good file comes back as its object.
#include "base/jsonfile.h"
#include "testmain.h"

#include <QTemporaryDir>
#include <QTest>

namespace tst_jsonfile {

using namespace tipscope::base::io;

namespace {
QString writeFile(const QTemporaryDir &dir, const QString &name, const QByteArray &bytes) {
    const QString path = dir.filePath(name);
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly) || f.write(bytes) != bytes.size())
        return {};
    return path;
}

JsonFileProblem::Kind kindOf(const std::variant<QJsonObject, JsonFileProblem> &read) {
    return std::get<JsonFileProblem>(read).kind;
}
} // namespace

class TestJsonFile : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void aGoodFileGivesItsObject();
    void eachFailureHasItsKind();
};

void TestJsonFile::aGoodFileGivesItsObject() {
    QTemporaryDir dir;
    const QString path = writeFile(dir, QStringLiteral("good.json"), R"({"a": 1})");
    const auto read = readJsonObject(path, 1024);
    QVERIFY(std::holds_alternative<QJsonObject>(read));
    QCOMPARE(std::get<QJsonObject>(read).value(QStringLiteral("a")).toInt(), 1);
}

void TestJsonFile::eachFailureHasItsKind() {
    QTemporaryDir dir;
    using Kind = JsonFileProblem::Kind;
    QCOMPARE(kindOf(readJsonObject(dir.filePath(QStringLiteral("absent.json")), 1024)),
             Kind::Missing);
    QCOMPARE(kindOf(readJsonObject(dir.path(), 1024)), Kind::Unreadable); // a folder
    const QString big = writeFile(dir, QStringLiteral("big.json"), QByteArray(2048, ' ') + "{}");
    QCOMPARE(kindOf(readJsonObject(big, 1024)), Kind::TooBig);
    QVERIFY(!std::holds_alternative<JsonFileProblem>(readJsonObject(big, 4096)));
    const auto list = readJsonObject(writeFile(dir, QStringLiteral("list.json"), "[1, 2]"), 1024);
    QCOMPARE(kindOf(list), Kind::NotAnObject);
    QVERIFY(std::get<JsonFileProblem>(list).detail.isEmpty()); // JSON, but not an object
    const auto broken = readJsonObject(writeFile(dir, QStringLiteral("bad.json"), "{\"a\":"), 1024);
    QCOMPARE(kindOf(broken), Kind::NotAnObject);
    QVERIFY(!std::get<JsonFileProblem>(broken).detail.isEmpty()); // the parser's reason
}

TIPSCOPE_TEST_GUILESS_MAIN(TestJsonFile)

} // namespace tst_jsonfile
#include "tst_jsonfile.moc"
