// The translation catalogues (translations/*.ts, and the English plurals) cannot rot: every entry
// is translated, none is left over from removed source text, and running lupdate over today's
// sources would change nothing. lupdate runs on a copy in a temporary folder; the committed files
// are only read.
#include "testmain.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QHash>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

namespace tst_translationfiles {

namespace {

struct Message {
    QString context;
    QString source;
    QString comment; // the disambiguation, part of what identifies the entry
    QString type;    // the <translation> type attribute: "", "unfinished", "obsolete", "vanished"
    QStringList translations; // one, or one per numerus form
    bool numerus = false;
};

// The <message> elements of a .ts file; `error` says why when it cannot be read.
QList<Message> readCatalogue(const QString &path, QString *error) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = QStringLiteral("cannot open %1: %2").arg(path, file.errorString());
        return {};
    }
    QList<Message> messages;
    QString context;
    Message m;
    QXmlStreamReader xml(&file);
    while (!xml.atEnd()) {
        xml.readNext();
        if (xml.isEndElement() && xml.name() == QLatin1String("message"))
            messages.append(m);
        if (!xml.isStartElement())
            continue;
        const auto name = xml.name();
        if (name == QLatin1String("name")) {
            context = xml.readElementText();
        } else if (name == QLatin1String("message")) {
            m = Message{};
            m.context = context;
            m.numerus = xml.attributes().value(QLatin1String("numerus")) == QLatin1String("yes");
        } else if (name == QLatin1String("source")) {
            m.source = xml.readElementText();
        } else if (name == QLatin1String("comment")) {
            m.comment = xml.readElementText();
        } else if (name == QLatin1String("translation")) {
            m.type = xml.attributes().value(QLatin1String("type")).toString();
            if (!m.numerus)
                m.translations.append(xml.readElementText());
        } else if (name == QLatin1String("numerusform")) {
            m.translations.append(xml.readElementText());
        } else if (name != QLatin1String("TS") && name != QLatin1String("context")) {
            xml.skipCurrentElement();
        }
    }
    if (xml.hasError())
        *error =
            QStringLiteral("%1: %2 at line %3").arg(path, xml.errorString()).arg(xml.lineNumber());
    return messages;
}

QString key(const Message &m) {
    return m.context + QChar(0) + m.source + QChar(0) + m.comment;
}

bool isLeftOver(const Message &m) {
    return m.type == QLatin1String("obsolete") || m.type == QLatin1String("vanished");
}

QString describe(const Message &m) {
    QString source = m.source;
    source.replace(QLatin1Char('\n'), QLatin1String("\\n"));
    if (source.size() > 90)
        source = source.left(87) + QLatin1String("...");
    return QStringLiteral("%1: \"%2\"").arg(m.context, source);
}

// %1..%99 and %n, each once however often it appears.
QSet<QString> placeholders(const QString &text) {
    static const QRegularExpression re(QStringLiteral("%(\\d{1,2}|n)"));
    QSet<QString> found;
    for (auto it = re.globalMatch(text); it.hasNext();)
        found.insert(it.next().captured(0));
    return found;
}

// What makes an entry unfit to ship; empty when it is fine.
QString problem(const Message &m) {
    if (m.type == QLatin1String("unfinished"))
        return QStringLiteral("unfinished");
    if (isLeftOver(m))
        return QStringLiteral("%1 (its source text is gone)").arg(m.type);
    if (m.translations.isEmpty())
        return QStringLiteral("no translation");
    const QSet<QString> wanted = placeholders(m.source);
    for (const QString &t : m.translations) {
        if (t.trimmed().isEmpty())
            return QStringLiteral("empty translation");
        if (placeholders(t) != wanted)
            return QStringLiteral("placeholders differ from the source: \"%1\"").arg(t);
    }
    return {};
}

QStringList tsFiles() {
    return QString::fromUtf8(TIPSCOPE_TS_FILES).split(QLatin1Char(','), Qt::SkipEmptyParts) +
           QStringList{QStringLiteral(TIPSCOPE_PLURALS_TS_FILE)};
}

// The English catalogue holds only the entries with %n: lupdate keeps it so with -pluralonly.
bool isPluralsOnly(const QString &path) {
    return path == QStringLiteral(TIPSCOPE_PLURALS_TS_FILE);
}

} // namespace

class TestTranslationFiles : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void everyEntryIsTranslated_data();
    void everyEntryIsTranslated();
    void lupdateWouldAddOrRemoveNothing_data();
    void lupdateWouldAddOrRemoveNothing();
};

void TestTranslationFiles::everyEntryIsTranslated_data() {
    QTest::addColumn<QString>("path");
    for (const QString &path : tsFiles())
        QTest::newRow(qPrintable(QFileInfo(path).fileName())) << path;
}

void TestTranslationFiles::everyEntryIsTranslated() {
    QFETCH(QString, path);
    QString error;
    const QList<Message> messages = readCatalogue(path, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QVERIFY2(!messages.isEmpty(), qPrintable(path + QStringLiteral(" has no entries")));
    QStringList problems;
    for (const Message &m : messages) {
        if (const QString why = problem(m); !why.isEmpty())
            problems.append(QStringLiteral("  %1 — %2").arg(describe(m), why));
    }
    QVERIFY2(problems.isEmpty(), qPrintable(QStringLiteral("%1 has %2 entries to fix:\n%3")
                                                .arg(path)
                                                .arg(problems.size())
                                                .arg(problems.join(QLatin1Char('\n')))));
}

void TestTranslationFiles::lupdateWouldAddOrRemoveNothing_data() {
    everyEntryIsTranslated_data();
}

void TestTranslationFiles::lupdateWouldAddOrRemoveNothing() {
    QFETCH(QString, path);
    QTemporaryDir dir;
    QVERIFY2(dir.isValid(), qPrintable(dir.errorString()));
    const QString copy = dir.filePath(QFileInfo(path).fileName());
    QVERIFY(QFile::copy(path, copy));
    QVERIFY(QFile::setPermissions(copy, QFile::ReadOwner | QFile::WriteOwner));

    // Without -no-obsolete, so that text gone from the sources shows up as "vanished".
    QProcess lupdate;
    lupdate.setProcessChannelMode(QProcess::MergedChannels);
    QStringList arguments{QStringLiteral("-source-language"), QStringLiteral("en"),
                          QLatin1Char('@') + QStringLiteral(TIPSCOPE_LUPDATE_LIST),
                          QStringLiteral("-ts"), copy};
    if (isPluralsOnly(path))
        arguments.prepend(QStringLiteral("-pluralonly"));
    lupdate.start(QStringLiteral(TIPSCOPE_LUPDATE), arguments);
    QVERIFY2(lupdate.waitForFinished(240000), "lupdate did not finish");
    const QString output = QString::fromUtf8(lupdate.readAll());
    QVERIFY2(lupdate.exitStatus() == QProcess::NormalExit && lupdate.exitCode() == 0,
             qPrintable(output));

    QString error;
    const QList<Message> before = readCatalogue(path, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    const QList<Message> after = readCatalogue(copy, &error);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QHash<QString, Message> committed;
    for (const Message &m : before)
        committed.insert(key(m), m);
    QStringList changes;
    for (const Message &m : after) {
        const auto it = committed.constFind(key(m));
        if (it == committed.cend())
            changes.append(QStringLiteral("  new in the sources: ") + describe(m));
        else if (isLeftOver(m) && !isLeftOver(*it))
            changes.append(QStringLiteral("  gone from the sources: ") + describe(m));
    }
    QVERIFY2(changes.isEmpty(),
             qPrintable(QStringLiteral("lupdate would change %1 entries of %2; run `cmake --build "
                                       "build --target update_translations` and translate:\n%3")
                            .arg(changes.size())
                            .arg(path, changes.join(QLatin1Char('\n')))));
    QCOMPARE(after.size(), before.size());
}

TIPSCOPE_TEST_GUILESS_MAIN(TestTranslationFiles)

} // namespace tst_translationfiles
#include "tst_translationfiles.moc"
