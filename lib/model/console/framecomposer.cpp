#include "framecomposer.h"

#include "model/device/devicemodel.h"

#include "protocol/catalog.h"
#include "protocol/datafield.h"
#include "protocol/framedecoder.h"
#include "protocol/hexbytes.h"
#include "protocol/valuecodec.h"

#include <QCoreApplication>

namespace tipscope::model {

using namespace tipscope::protocol;

namespace {
struct FrameComposerTr {
    Q_DECLARE_TR_FUNCTIONS(FrameComposer)
};

const QString kNameSeparator = QStringLiteral(" — ");
bool isPrintable(const QString &text) {
    for (QChar c : text)
        if (c.unicode() < 0x20 || c.unicode() > 0x7e)
            return false;
    return true;
}

Direction directionOf(Header header) {
    return header == Header::Write ? Direction::Write : Direction::Read;
}

// What is wrong with `data` for a catalog write, in words; empty when the catalog agrees.
QString writeProblem(const ResolvedCommand &cmd, const QString &data) {
    const CommandSpec &spec = *cmd.spec;
    if (spec.kind == ValueKind::Action)
        return data.toLatin1() == spec.fixedData
                   ? QString()
                   : FrameComposerTr::tr("%1 carries the data field %2.")
                         .arg(QString::fromLatin1(cmd.code), QString::fromLatin1(spec.fixedData));
    if (data.isEmpty())
        return FrameComposerTr::tr("A write needs a data field: %1.").arg(allowedText(cmd));
    const auto value = parseUserValue(cmd, data);
    if (!value)
        return value.error();
    if (const QString why = validate(cmd, *value); !why.isEmpty())
        return why;
    // The device parses fixed-width fields, so "375" is not the same frame as "00375".
    const bool delay = spec.kind == ValueKind::Delay && !spec.special.contains(int(*value));
    const auto wire = delay ? encodeDelay(int(*value)) : encodeNumber(*value);
    if (wire && *wire != data.toLatin1())
        return FrameComposerTr::tr("On the wire this value is written %1.")
            .arg(QString::fromLatin1(*wire));
    return {};
}

// "Name: description", as the catalog says it in the user interface language.
QString describe(const CommandSpec &spec) {
    return QStringLiteral("%1: %2").arg(catalogText(spec.name), catalogText(spec.description));
}

void addCatalogAdvice(const FrameInput &in, const QString &code, FrameDraft &draft) {
    auto warn = [&draft](const QString &text) {
        draft.hint = text;
        draft.warning = true;
    };
    if (in.family.isEmpty())
        return warn(
            FrameComposerTr::tr("Unknown device family: the catalog cannot check this frame."));
    const Catalog &catalog = Catalog::builtin();
    const bool write = in.header == Header::Write;
    const Direction dir = directionOf(in.header);
    // The catalog reads codes in any case, as people type them; the device does not.
    const auto cmd =
        code == code.toUpper() ? catalog.resolve(in.family, code.toLatin1(), dir) : std::nullopt;
    if (!cmd) {
        QString text = write ? FrameComposerTr::tr("%1 is not a %2 write command in the catalog.")
                             : FrameComposerTr::tr("%1 is not a %2 read command in the catalog.");
        text = text.arg(code, in.family);
        if (code != code.toUpper() && catalog.resolve(in.family, code.toUpper().toLatin1(), dir))
            text += QLatin1Char(' ') + FrameComposerTr::tr("Did you mean %1?").arg(code.toUpper());
        return warn(text + QLatin1Char(' ') + FrameComposerTr::tr("It is sent as typed."));
    }
    const CommandSpec &spec = *cmd->spec;
    if (!write) {
        if (!in.data.isEmpty())
            return warn(FrameComposerTr::tr(
                "Reads carry no data field; the device may refuse this frame."));
        draft.hint = describe(spec);
        return;
    }
    const QString problem = writeProblem(*cmd, in.data);
    if (spec.dangerous)
        return warn(FrameComposerTr::tr("Dangerous: %1")
                        .arg(catalogText(spec.danger.isEmpty() ? spec.description : spec.danger)) +
                    (problem.isEmpty() ? QString() : QLatin1Char(' ') + problem));
    if (!problem.isEmpty())
        return warn(FrameComposerTr::tr("Catalog check: %1").arg(problem));
    draft.hint = describe(spec);
}

// The first read that identifies a device, for every family: the model name.
QByteArray identityRead() {
    const CommandSpec *spec = Catalog::builtin().command(Role::ModelName);
    return spec ? spec->pattern.toLatin1() : QByteArray();
}
} // namespace

FrameTarget FrameTarget::of(const DeviceModel &device) {
    const link::DeviceInfo &info = device.info();
    const QString label = device.address() ? info.addressText() + QLatin1Char(' ') + info.model
                                           : FrameComposerTr::tr("%1 (no address)").arg(info.model);
    return {label, device.address(), device.family()};
}

QString FrameComposer::familyOf(int target) const {
    return target >= 0 && target < m_targets.size() ? m_targets.at(target).family : QString();
}

QList<CommandChoice> FrameComposer::commands(int target, Header header) const {
    QList<CommandChoice> choices;
    for (const ResolvedCommand &c :
         Catalog::builtin().expand(familyOf(target), directionOf(header))) {
        const QString code = QString::fromLatin1(c.code);
        choices.append({code, code + kNameSeparator + catalogText(c.spec->name)});
    }
    return choices;
}

QString FrameComposer::firstCommand(int target, Header header) const {
    const QList<CommandChoice> choices = commands(target, header);
    const QString identity = QString::fromLatin1(identityRead());
    for (const CommandChoice &c : choices)
        if (c.code == identity)
            return c.code;
    return choices.isEmpty() ? QString() : choices.constFirst().code;
}

std::optional<QString> FrameComposer::dataOfPicked(int target, Header header,
                                                   const QString &code) const {
    if (header == Header::Read)
        return QString();
    const auto cmd =
        Catalog::builtin().resolve(familyOf(target), codeOf(code).toLatin1(), Direction::Write);
    if (cmd && cmd->spec->kind == ValueKind::Action)
        return QString::fromLatin1(cmd->spec->fixedData);
    return std::nullopt;
}

FrameDraft FrameComposer::compose(int target, Header header, const QString &command,
                                  const QString &data) const {
    if (target < 0 || target >= m_targets.size()) {
        FrameDraft none;
        none.problem =
            FrameComposerTr::tr("No device is known on this line: connect first, or send raw hex.");
        return none;
    }
    FrameInput in;
    in.source = m_robotAddress;
    in.target = m_targets.at(target).address;
    in.family = m_targets.at(target).family;
    in.header = header;
    in.command = codeOf(command);
    in.data = data;
    return compose(in);
}

FrameDraft FrameComposer::compose(const FrameInput &in) {
    FrameDraft draft;
    const QString code = in.command.trimmed();
    if (code.size() != 3 || !isPrintable(code)) {
        draft.problem = FrameComposerTr::tr(
            "Not sendable: the command must be 3 printable characters, e.g. SMN.");
        return draft;
    }
    if (!isPrintable(in.data)) {
        draft.problem =
            FrameComposerTr::tr("Not sendable: the data field may only hold printable ASCII.");
        return draft;
    }
    if (in.target &&
        (*in.target < 0 || *in.target > kMaxAddress || in.source < 0 || in.source > kMaxAddress)) {
        draft.problem = FrameComposerTr::tr("Not sendable: addresses go from 00 to 99.");
        return draft;
    }
    Frame frame;
    frame.header = in.header;
    frame.command = code.toLatin1();
    frame.data = in.data.toLatin1();
    draft.frame = in.target ? frame.addressed(in.source, *in.target) : frame;
    draft.encodable = true;
    addCatalogAdvice(in, code, draft);
    return draft;
}

QString FrameComposer::codeOf(const QString &typed) {
    return typed.section(kNameSeparator, 0, 0).trimmed();
}

RawHex FrameComposer::readHex(const QString &text) {
    RawHex raw;
    auto bytes = parseHexBytes(text);
    if (!bytes.ok()) {
        raw.text = bytes.error();
        return raw;
    }
    raw.bytes = std::move(bytes).value();
    auto frame = parseFrame(*raw.bytes);
    const int n = int(raw.bytes->size());
    if (frame) {
        raw.frame = std::move(frame).value();
        raw.text =
            FrameComposerTr::tr("%n byte(s), a valid frame: %1", "", n).arg(raw.frame->toString());
    } else {
        raw.text = FrameComposerTr::tr("%n byte(s), not a valid frame (%1): sent as typed", "", n)
                       .arg(frame.error().why);
        raw.warning = true;
    }
    return raw;
}

QString FrameComposer::exampleHex() {
    return toHexText(Frame::read(identityRead()).addressed(0, 1).encode());
}

} // namespace tipscope::model
