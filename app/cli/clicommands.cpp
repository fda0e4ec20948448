#include "clicommands.h"

#include "base/elide.h"
#include "cliunits.h"
#include "model/device/displayunits.h"
#include "model/device/writeproof.h"
#include "protocol/framedecoder.h"
#include "protocol/hexbytes.h"
#include "protocol/valuecodec.h"

#include <QEventLoop>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <algorithm>

namespace tipscope::cli {

using namespace tipscope::link;
using namespace tipscope::protocol;

namespace {

struct CliCommandsTr {
    Q_DECLARE_TR_FUNCTIONS(CliCommands)
};

QString unitSuffix(const ResolvedCommand &cmd, const Value &v) {
    if (v.isText || cmd.spec->special.contains(int(v.number)))
        return {};
    const QString unit = wireUnitSymbol(cmd);
    return unit.isEmpty() ? QString() : QLatin1Char(' ') + unit;
}

QJsonObject deviceJson(const DeviceInfo &d) {
    return {{QStringLiteral("address"), d.address ? QJsonValue(*d.address) : QJsonValue()},
            {QStringLiteral("model"), d.model},
            {QStringLiteral("family"), d.family},
            {QStringLiteral("softwareVersion"), d.softwareVersion}};
}

void reportFailure(CliSession &s, const Reply &reply, const QString &what) {
    s.err() << CliCommandsTr::tr("tipscope-cli: %1: %2").arg(what, reply.errorString()) << Qt::endl;
}

void reportFailure(CliSession &s, const Reply &reply) {
    reportFailure(s, reply, reply.request().toString());
}

// Raw bytes as people read them: decoded when they are a frame, else why they are not one.
QString describeRaw(const QByteArray &bytes) {
    const auto frame = parseFrame(bytes);
    if (frame)
        return frame->toString();
    return CliCommandsTr::tr("%n raw byte(s), not a frame (%1)", nullptr, int(bytes.size()))
        .arg(frame.error().why);
}

} // namespace

QString formatReading(const ResolvedCommand &cmd, const QByteArray &data, bool raw) {
    const QString code = QString::fromLatin1(cmd.code);
    if (raw)
        return code + QLatin1Char(' ') + QString::fromLatin1(data);
    const auto value = decodeAnswer(cmd, data);
    if (!value)
        return CliCommandsTr::tr("%1 unreadable data field '%2'")
            .arg(code, QString::fromLatin1(data));
    // Data for scripts: the catalog's English labels, whatever the language of the messages.
    const QString described = describeValue(cmd, *value, Wording::Catalog);
    const ValueKind k = cmd.spec->kind;
    if ((k == ValueKind::Enum || k == ValueKind::Flags) && !value->isText &&
        !cmd.spec->special.contains(int(value->number)))
        return QStringLiteral("%1 %2 %3").arg(code).arg(value->number).arg(described);
    if (shownConverted(cmd) && !value->isText && !cmd.spec->special.contains(int(value->number)))
        return code + QLatin1Char(' ') + shownNumber(cmd, value->number);
    return code + QLatin1Char(' ') + described + unitSuffix(cmd, *value);
}

int runOnLine(CliSession &s) {
    static const QMap<QString, int (*)(CliSession &)> commands = {
        {QStringLiteral("detect"), runDetect}, {QStringLiteral("read"), runRead},
        {QStringLiteral("write"), runWrite},   {QStringLiteral("send"), runSend},
        {QStringLiteral("dump"), runDump},     {QStringLiteral("profile"), runProfile}};
    const auto run = commands.value(s.options().command);
    return run ? run(s) : kUsage;
}

int runDetect(CliSession &s) {
    if (const int rc = s.resolveDevices(); rc != kOk)
        return rc;
    if (s.options().flags.contains(QStringLiteral("json"))) {
        QJsonArray arr;
        for (const DeviceInfo &d : s.devices())
            arr.append(deviceJson(d));
        s.out() << QJsonDocument(arr).toJson(QJsonDocument::Indented);
        return kOk;
    }
    for (const DeviceInfo &d : s.devices())
        s.out() << d.summary() << Qt::endl;
    return kOk;
}

int runRead(CliSession &s) {
    if (s.options().args.isEmpty()) {
        s.err() << CliCommandsTr::tr(
                       "tipscope-cli: read needs at least one command code, e.g. read ST1")
                << Qt::endl;
        return kUsage;
    }
    if (const int rc = s.resolveDevices(); rc != kOk)
        return rc;
    int worst = kOk;
    for (const QString &arg : s.options().args) {
        const QByteArray code = arg.toUpper().toLatin1();
        const DeviceInfo *d = s.deviceFor(code, Direction::Read);
        if (!d) {
            s.err() << CliCommandsTr::tr("tipscope-cli: no device here can read '%1'")
                           .arg(base::elided(arg))
                    << Qt::endl;
            worst = qMax(worst, int(kRefused));
            continue;
        }
        const auto cmd = *Catalog::builtin().resolve(d->family, code, Direction::Read);
        Reply *reply = s.ask(Request::read(d->address, cmd));
        if (!reply->ok()) {
            reportFailure(s, *reply);
            worst = qMax(worst, CliSession::exitCodeFor(*reply));
            continue;
        }
        s.out() << formatReading(cmd, reply->answer().data,
                                 s.options().flags.contains(QStringLiteral("raw")))
                << Qt::endl;
    }
    return worst;
}

// The write proved as the window proves it (model::WriteProof): read back, and read once more
// when the first answer may be a late one from before the write.
static int verifyWrite(CliSession &s, const DeviceInfo &d, const ResolvedCommand &cmd,
                       const QByteArray &data) {
    const auto readCmd = Catalog::builtin().resolve(d.family, cmd.code, Direction::Read);
    if (!readCmd || cmd.spec->kind == ValueKind::Action) {
        s.out() << CliCommandsTr::tr("%1 written").arg(QString::fromLatin1(cmd.code)) << Qt::endl;
        return kOk;
    }
    model::WriteProof::Result proved;
    QEventLoop loop;
    model::WriteProof *proof =
        model::WriteProof::start(s.line().queue(), d.address, *readCmd, data);
    QObject::connect(proof, &model::WriteProof::finished, &loop,
                     [&](const model::WriteProof::Result &r) {
                         proved = r;
                         loop.quit();
                     });
    loop.exec();
    if (proved.error != ReplyError::None) {
        s.err() << CliCommandsTr::tr("tipscope-cli: %1 was accepted but could not be read back: %2")
                       .arg(QString::fromLatin1(cmd.code), proved.errorString)
                << Qt::endl;
        return CliSession::exitCodeFor(proved.error);
    }
    if (!proved.confirmed) {
        s.err() << CliCommandsTr::tr(
                       "tipscope-cli: verification failed: wrote %1, the device reports %2")
                       .arg(QString::fromLatin1(data), QString::fromLatin1(proved.reported))
                << Qt::endl;
        return kNak;
    }
    s.out()
        << CliCommandsTr::tr("%1 (verified)").arg(formatReading(*readCmd, proved.reported, false))
        << Qt::endl;
    return kOk;
}

// Reads `limit` until it holds a value, as many times as any read is tried: an answer whose data
// is no value (a garbled field) says no more than no answer. Empty, or why it stays unknown.
static QString readLimit(CliSession &s, const DeviceInfo &d, model::Parameter &limit) {
    QString why;
    for (int attempt = 0; attempt <= s.options().line.queue.retries; ++attempt) {
        Reply *r = s.ask(Request::read(d.address, limit.code()));
        if (!r->ok())
            return r->errorString(); // the queue has already tried it again
        limit.deviceReported(r->answer().data);
        if (limit.value())
            return {};
        why = CliCommandsTr::tr("the device answered '%1', which is no value")
                  .arg(base::elided(QString::fromLatin1(r->answer().data)));
    }
    return why;
}

// The device's own limits (MIT and MAT for a selected temperature) are read now and the value
// is checked with the Parameter logic the GUI's editors use. A limit that stays unknown refuses
// the write, as it refuses a profile: the value cannot be proved inside it. kOk, or the exit code
// after saying why nothing was sent.
static int checkDeviceLimits(CliSession &s, const DeviceInfo &d, const QByteArray &code,
                             qint64 wire) {
    const auto device = s.model(d);
    model::Parameter *p = device->parameter(code);
    if (!p)
        return kOk; // an action or a write-only command: the catalog's check is all there is
    for (const QString &limit : {p->meta().limitMin, p->meta().limitMax}) {
        model::Parameter *l = limit.isEmpty() ? nullptr : device->parameter(limit.toLatin1());
        if (!l)
            continue;
        if (const QString why = readLimit(s, d, *l); !why.isEmpty()) {
            s.err() << CliCommandsTr::tr("tipscope-cli: refused, nothing was sent: %1 is bounded "
                                         "by %2, which could not be read: %3")
                           .arg(QString::fromLatin1(code), limit, why)
                    << Qt::endl;
            return kRefused;
        }
    }
    if (const QString why = p->validate(wire); !why.isEmpty()) {
        s.err() << CliCommandsTr::tr("tipscope-cli: refused, nothing was sent: %1").arg(why)
                << Qt::endl;
        return kRefused;
    }
    return kOk;
}

// The data field of `write --raw`, held to the catalog like a typed value unless `force`; `wire`
// gets its value, so that the device's limits are checked too.
static base::Outcome<QByteArray> rawField(const ResolvedCommand &cmd, const QString &typed,
                                          bool force, std::optional<qint64> *wire) {
    // Checked before toLatin1(), which would turn anything outside Latin-1 into '?'.
    const bool printable = std::all_of(typed.begin(), typed.end(), [](QChar c) {
        return c.unicode() >= 0x20 && c.unicode() <= 0x7e;
    });
    if (typed.isEmpty() || !printable)
        return base::failure(CliCommandsTr::tr("the data field must be printable ASCII"));
    const QByteArray data = typed.toLatin1();
    if (data.size() > 32)
        return base::failure(CliCommandsTr::tr("the data field is longer than 32 characters"));
    if (force)
        return data;
    if (const QString why = validateData(cmd, data); !why.isEmpty())
        return base::failure(CliCommandsTr::tr("%1 (--force sends it anyway)").arg(why));
    if (const auto value = decodeAnswer(cmd, data);
        value && !value->isText && cmd.spec->kind != ValueKind::Action)
        *wire = value->number;
    return data;
}

int runWrite(CliSession &s) {
    const QStringList &args = s.options().args;
    const bool raw = s.options().flags.contains(QStringLiteral("raw"));
    if (args.size() != 2 && !(args.size() == 1 && !raw)) {
        s.err() << CliCommandsTr::tr("tipscope-cli: write takes CODE VALUE, e.g. write ST1 350")
                << Qt::endl;
        return kUsage;
    }
    if (const int rc = s.resolveDevices(); rc != kOk)
        return rc;
    const QByteArray code = args.at(0).toUpper().toLatin1();
    const DeviceInfo *d = s.deviceFor(code, Direction::Write);
    if (!d) {
        s.err() << CliCommandsTr::tr("tipscope-cli: no device here accepts writes of '%1'")
                       .arg(base::elided(args.at(0)))
                << Qt::endl;
        return kRefused;
    }
    const auto cmd = *Catalog::builtin().resolve(d->family, code, Direction::Write);
    QByteArray data;
    std::optional<qint64> wire;
    QString error;
    if (raw) {
        const auto field =
            rawField(cmd, args.at(1), s.options().flags.contains(QStringLiteral("force")), &wire);
        data = field ? *field : QByteArray();
        error = field.error();
    } else if (cmd.spec->kind == ValueKind::Action && args.size() == 1) {
        data = cmd.spec->fixedData;
    } else if (const auto typed =
                   shownConverted(cmd)
                       ? model::parseDisplayText(cmd, args.value(1),
                                                 model::TemperatureUnit::Celsius, QLocale::c())
                       : parseUserValue(cmd, args.value(1));
               !typed) {
        error = typed.error();
    } else if (const auto field = encodeWrite(cmd, *typed); !field) {
        error = field.error();
    } else {
        wire = *typed;
        data = *field;
    }
    if (!error.isEmpty()) {
        s.err() << CliCommandsTr::tr("tipscope-cli: refused, nothing was sent: %1").arg(error)
                << Qt::endl;
        return kRefused;
    }
    if (wire)
        if (const int rc = checkDeviceLimits(s, *d, code, *wire); rc != kOk)
            return rc;
    Reply *reply = s.ask(Request::write(d->address, code, data, !cmd.spec->dangerous));
    if (!reply->ok()) {
        reportFailure(s, *reply);
        return CliSession::exitCodeFor(*reply);
    }
    return verifyWrite(s, *d, cmd, data);
}

int runSend(CliSession &s) {
    if (s.options().args.isEmpty()) {
        s.err() << CliCommandsTr::tr(
                       "tipscope-cli: send takes the frame in hex, e.g. send 02 30 30 30 31 "
                       "52 53 4D 4E 03 02")
                << Qt::endl;
        return kUsage;
    }
    const auto bytes = parseHexBytes(s.options().args.join(QLatin1Char(' ')));
    if (!bytes.ok()) {
        s.err()
            << CliCommandsTr::tr("tipscope-cli: refused, nothing was sent: %1").arg(bytes.error())
            << Qt::endl;
        return kRefused;
    }
    Request r;
    r.raw = *bytes;
    r.retries = 0;
    s.out() << "TX " << toHexText(*bytes) << "  " << toAsciiText(*bytes) << Qt::endl;
    Reply *reply = s.ask(r);
    if (reply->error() != ReplyError::None && reply->error() != ReplyError::Nak) {
        reportFailure(s, *reply, describeRaw(*bytes));
        return CliSession::exitCodeFor(*reply);
    }
    const Frame &a = reply->answer();
    QString meaning;
    if (a.header == Header::Nak)
        meaning = QStringLiteral(" (") + reply->errorString() + QLatin1Char(')');
    s.out() << "RX " << toHexText(a.encode()) << "  " << a.toString() << meaning << Qt::endl;
    return CliSession::exitCodeFor(*reply);
}

int runDump(CliSession &s) {
    if (const int rc = s.resolveDevices(); rc != kOk)
        return rc;
    const bool json = s.options().flags.contains(QStringLiteral("json"));
    QJsonArray devices;
    int worst = kOk;
    for (const DeviceInfo &d : s.devices()) {
        QJsonArray values;
        if (!json)
            s.out() << "# " << d.summary() << Qt::endl;
        for (const ResolvedCommand &cmd : Catalog::builtin().expand(d.family, Direction::Read)) {
            Reply *reply = s.ask(Request::read(d.address, cmd, Priority::Background));
            QJsonObject v{{QStringLiteral("code"), QString::fromLatin1(cmd.code)},
                          {QStringLiteral("name"), cmd.spec->name}};
            if (reply->ok()) {
                const QByteArray &data = reply->answer().data;
                v.insert(QStringLiteral("data"), QString::fromLatin1(data));
                v.insert(QStringLiteral("text"), formatReading(cmd, data, false));
                if (!json)
                    s.out() << qSetFieldWidth(30) << Qt::left << formatReading(cmd, data, false)
                            << qSetFieldWidth(0) << " # " << cmd.spec->name << Qt::endl;
            } else {
                v.insert(QStringLiteral("error"), reply->errorString());
                worst = qMax(worst, CliSession::exitCodeFor(*reply));
                if (!json)
                    s.out() << qSetFieldWidth(30) << Qt::left
                            << QString::fromLatin1(cmd.code) + QStringLiteral(" ?")
                            << qSetFieldWidth(0) << " # " << cmd.spec->name << ": "
                            << reply->errorString() << Qt::endl;
            }
            values.append(v);
        }
        QJsonObject dev = deviceJson(d);
        dev.insert(QStringLiteral("values"), values);
        devices.append(dev);
    }
    if (json)
        s.out() << QJsonDocument(devices).toJson(QJsonDocument::Indented);
    return worst;
}

int runCommands(const CliOptions &o, QTextStream &out, QTextStream &err) {
    const Catalog &cat = Catalog::builtin();
    const QString family = o.values.value(QStringLiteral("family")).toUpper();
    if (!family.isEmpty() && !cat.family(family)) {
        err << CliCommandsTr::tr("tipscope-cli: unknown family '%1'; known: %2")
                   .arg(base::elided(family), cat.familyNames().join(QLatin1String(", ")))
            << Qt::endl;
        return kUsage;
    }
    for (const CommandSpec &c : cat.commands()) {
        if (!family.isEmpty() && !c.families.contains(family))
            continue;
        const QString access = QString(c.readable ? QStringLiteral("R") : QString()) +
                               (c.writable ? QStringLiteral("W") : QString());
        QString range;
        if (const FamilyInfo *f = cat.family(family.isEmpty() ? c.families.first() : family)) {
            QByteArray code = c.pattern.toLatin1().replace('x', "1");
            if (!f->tools.isEmpty())
                code.replace('y', QByteArray::number(f->tools.first()));
            if (auto r =
                    cat.resolve(f->name, code, c.writable ? Direction::Write : Direction::Read);
                r && c.writable)
                range = allowedText(*r);
        }
        out << qSetFieldWidth(5) << Qt::left << c.pattern << qSetFieldWidth(3) << access
            << qSetFieldWidth(0) << catalogText(c.name);
        if (c.dangerous)
            out << CliCommandsTr::tr(" [dangerous]");
        out << "\n      " << catalogText(c.description);
        if (!range.isEmpty())
            out << "\n      " << CliCommandsTr::tr("values: %1").arg(range);
        out << "\n      "
            << CliCommandsTr::tr("families: %1").arg(c.families.join(QLatin1Char(' '))) << Qt::endl;
    }
    return kOk;
}

} // namespace tipscope::cli
