#include "framebuilder.h"

#include "protocol/catalog.h"
#include "protocol/datafield.h"
#include "protocol/framedecoder.h"
#include "protocol/hexbytes.h"
#include "protocol/valuecodec.h"

#include <QComboBox>
#include <QCompleter>
#include <QCoreApplication>
#include <QFontDatabase>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalBlocker>

namespace tipscope::gui {

using namespace tipscope::protocol;

namespace {
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(FrameBuilder)
};

const QString kSeparator = QStringLiteral(" — ");

bool isPrintable(const QString &text) {
    for (QChar c : text)
        if (c.unicode() < 0x20 || c.unicode() > 0x7e)
            return false;
    return true;
}

// What is wrong with `data` for a catalog write, in words; empty when the catalog agrees.
QString writeProblem(const ResolvedCommand &cmd, const QString &data) {
    const CommandSpec &spec = *cmd.spec;
    if (spec.kind == ValueKind::Action)
        return data.toLatin1() == spec.fixedData
                   ? QString()
                   : Tr::tr("%1 carries the data field %2.")
                         .arg(QString::fromLatin1(cmd.code), QString::fromLatin1(spec.fixedData));
    if (data.isEmpty())
        return Tr::tr("A write needs a data field: %1.").arg(allowedText(cmd));
    QString error;
    const std::optional<qint64> value = parseUserValue(cmd, data, &error);
    if (!value)
        return error;
    if (const QString why = validate(cmd, *value); !why.isEmpty())
        return why;
    // The device parses fixed-width fields, so "375" is not the same frame as "00375".
    const bool delay = spec.kind == ValueKind::Delay && !spec.special.contains(int(*value));
    const auto wire = delay ? encodeDelay(int(*value)) : encodeNumber(*value);
    if (wire && *wire != data.toLatin1())
        return Tr::tr("On the wire this value is written %1.").arg(QString::fromLatin1(*wire));
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
        return warn(Tr::tr("Unknown device family: the catalog cannot check this frame."));
    const Catalog &catalog = Catalog::builtin();
    const bool write = in.header == Header::Write;
    const Direction dir = write ? Direction::Write : Direction::Read;
    const auto cmd = catalog.resolve(in.family, code.toLatin1(), dir);
    if (!cmd) {
        QString text = write ? Tr::tr("%1 is not a %2 write command in the catalog.")
                             : Tr::tr("%1 is not a %2 read command in the catalog.");
        text = text.arg(code, in.family);
        if (code != code.toUpper() && catalog.resolve(in.family, code.toUpper().toLatin1(), dir))
            text += QLatin1Char(' ') + Tr::tr("Did you mean %1?").arg(code.toUpper());
        return warn(text + QLatin1Char(' ') + Tr::tr("It is sent as typed."));
    }
    const CommandSpec &spec = *cmd->spec;
    if (!write) {
        if (!in.data.isEmpty())
            return warn(Tr::tr("Reads carry no data field; the device may refuse this frame."));
        draft.hint = describe(spec);
        return;
    }
    const QString problem = writeProblem(*cmd, in.data);
    if (spec.dangerous)
        return warn(Tr::tr("Dangerous: %1")
                        .arg(catalogText(spec.danger.isEmpty() ? spec.description : spec.danger)) +
                    (problem.isEmpty() ? QString() : QLatin1Char(' ') + problem));
    if (!problem.isEmpty())
        return warn(Tr::tr("Catalog check: %1").arg(problem));
    draft.hint = describe(spec);
}

enum class Tone { Normal, Warning, Error };

void setTone(QLabel *label, Tone tone) {
    // Red as the console's error rows for what is refused; amber for advice that does not stop
    // sending. A default palette with nothing set inherits the parent's again.
    QPalette p;
    if (tone == Tone::Error)
        p.setColor(QPalette::WindowText, QColor(0xc0, 0x1c, 0x28));
    else if (tone == Tone::Warning)
        p.setColor(QPalette::WindowText, QColor(0x9c, 0x5b, 0x00));
    label->setPalette(p);
}
} // namespace

FrameDraft composeFrame(const FrameInput &in) {
    FrameDraft draft;
    const QString code = in.command.trimmed();
    if (code.size() != 3 || !isPrintable(code)) {
        draft.problem =
            Tr::tr("Not sendable: the command must be 3 printable characters, e.g. SMN.");
        return draft;
    }
    if (!isPrintable(in.data)) {
        draft.problem = Tr::tr("Not sendable: the data field may only hold printable ASCII.");
        return draft;
    }
    if (in.target &&
        (*in.target < 0 || *in.target > kMaxAddress || in.source < 0 || in.source > kMaxAddress)) {
        draft.problem = Tr::tr("Not sendable: addresses go from 00 to 99.");
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

FrameBuilder::FrameBuilder(QWidget *parent)
    : QGroupBox(tr("Send a frame"), parent) {
    buildLayout();
    connect(m_device, &QComboBox::currentIndexChanged, this, &FrameBuilder::fillCommands);
    connect(m_header, &QComboBox::currentIndexChanged, this, &FrameBuilder::fillCommands);
    connect(m_command, &QComboBox::currentTextChanged, this, &FrameBuilder::updateDraft);
    connect(m_command, &QComboBox::activated, this, &FrameBuilder::onCommandPicked);
    connect(m_data, &QLineEdit::textChanged, this, &FrameBuilder::updateDraft);
    connect(m_data, &QLineEdit::returnPressed, this, &FrameBuilder::sendFrame);
    connect(m_sendFrame, &QPushButton::clicked, this, &FrameBuilder::sendFrame);
    connect(m_rawHex, &QLineEdit::textChanged, this, &FrameBuilder::updateRawHex);
    connect(m_rawHex, &QLineEdit::returnPressed, this, &FrameBuilder::sendRaw);
    connect(m_sendRaw, &QPushButton::clicked, this, &FrameBuilder::sendRaw);
    setMonitorOnly(false);
    fillCommands();
}

void FrameBuilder::buildLayout() {
    const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    auto named = [](QWidget *w, const char *objectName, const QString &accessible) {
        w->setObjectName(QLatin1String(objectName));
        w->setAccessibleName(accessible);
    };
    m_device = new QComboBox(this);
    named(m_device, "deviceCombo", tr("Device"));
    m_device->setSizeAdjustPolicy(QComboBox::AdjustToContents);
    m_header = new QComboBox(this);
    named(m_header, "headerCombo", tr("Header"));
    m_header->addItem(tr("R (read)"), QChar(QLatin1Char('R')));
    m_header->addItem(tr("W (write)"), QChar(QLatin1Char('W')));
    m_command = new QComboBox(this);
    named(m_command, "commandCombo", tr("Command"));
    m_command->setEditable(true);
    m_command->setInsertPolicy(QComboBox::NoInsert);
    m_command->setMinimumContentsLength(30);
    m_command->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    // Searching by name ("temp") matters more than prefix completion of 3-letter codes.
    m_command->completer()->setCompletionMode(QCompleter::PopupCompletion);
    m_command->completer()->setFilterMode(Qt::MatchContains);
    m_command->completer()->setCaseSensitivity(Qt::CaseInsensitive);
    m_data = new QLineEdit(this);
    named(m_data, "dataEdit", tr("Data field"));
    m_data->setFont(mono);
    m_data->setMaxLength(40);
    m_data->setMinimumWidth(QFontMetrics(mono).horizontalAdvance(QLatin1Char('0')) * 16);
    m_sendFrame = new QPushButton(tr("&Send frame"), this);
    named(m_sendFrame, "sendFrameButton", tr("Send frame"));
    m_preview = new QLabel(this);
    named(m_preview, "framePreview", tr("Frame to be sent"));
    m_preview->setFont(mono);
    m_preview->setTextInteractionFlags(Qt::TextSelectableByMouse | Qt::TextSelectableByKeyboard);
    m_hint = new QLabel(this);
    named(m_hint, "hintLabel", tr("Catalog check"));
    m_hint->setWordWrap(true);
    m_rawHex = new QLineEdit(this);
    named(m_rawHex, "rawHexEdit", tr("Raw bytes in hex"));
    m_rawHex->setFont(mono);
    m_rawHex->setPlaceholderText(QStringLiteral("02 30 30 30 31 52 53 4D 4E 03 5E"));
    m_rawHex->setClearButtonEnabled(true);
    m_sendRaw = new QPushButton(tr("Send ra&w hex"), this);
    named(m_sendRaw, "sendRawButton", tr("Send raw hex"));
    m_rawStatus = new QLabel(this);
    named(m_rawStatus, "rawStatusLabel", tr("Raw bytes check"));
    m_outcome = new QLabel(tr("Nothing sent yet."), this);
    named(m_outcome, "outcomeLabel", tr("Outcome of the last send"));
    m_outcome->setTextInteractionFlags(Qt::TextSelectableByMouse);

    auto *grid = new QGridLayout(this);
    auto label = [this, grid](const QString &text, QWidget *buddy, int row, int column) {
        auto *l = new QLabel(text, this);
        l->setBuddy(buddy);
        grid->addWidget(l, row, column);
    };
    label(tr("&Device"), m_device, 0, 0);
    grid->addWidget(m_device, 0, 1);
    label(tr("&Header"), m_header, 0, 2);
    grid->addWidget(m_header, 0, 3);
    label(tr("C&ommand"), m_command, 0, 4);
    grid->addWidget(m_command, 0, 5);
    label(tr("D&ata"), m_data, 0, 6);
    grid->addWidget(m_data, 0, 7);
    grid->addWidget(m_sendFrame, 0, 8);
    label(tr("Frame"), m_preview, 1, 0);
    grid->addWidget(m_preview, 1, 1, 1, 8);
    grid->addWidget(m_hint, 2, 1, 1, 8);
    label(tr("&Raw hex"), m_rawHex, 3, 0);
    grid->addWidget(m_rawHex, 3, 1, 1, 7);
    grid->addWidget(m_sendRaw, 3, 8);
    grid->addWidget(m_rawStatus, 4, 1, 1, 8);
    label(tr("Last send"), m_outcome, 5, 0);
    grid->addWidget(m_outcome, 5, 1, 1, 8);
    grid->setColumnStretch(5, 1);
    setTabOrder(m_device, m_header);
    setTabOrder(m_header, m_command);
    setTabOrder(m_command, m_data);
    setTabOrder(m_data, m_sendFrame);
    setTabOrder(m_sendFrame, m_rawHex);
    setTabOrder(m_rawHex, m_sendRaw);
}

void FrameBuilder::setTargets(const QList<Target> &targets) {
    const QString current = m_device->currentText();
    {
        const QSignalBlocker block(m_device);
        m_targets = targets;
        m_device->clear();
        for (const Target &t : targets)
            m_device->addItem(t.label);
        m_device->setCurrentIndex(qMax(0, m_device->findText(current)));
    }
    fillCommands();
}

void FrameBuilder::setRobotAddress(int address) {
    m_robotAddress = address;
    updateDraft();
}

void FrameBuilder::setMonitorOnly(bool on) {
    m_monitorOnly = on;
    m_sendRaw->setEnabled(!on);
    m_sendRaw->setToolTip(
        on ? tr("Monitor-only mode is on: raw bytes are not sent, since they "
                "may be a write. Reads can still be sent with Send frame.")
           : tr("Send these bytes exactly as typed; the answer appears in the table."));
    updateDraft();
}

void FrameBuilder::showOutcome(const QString &text, bool failed) {
    m_outcome->setText(text);
    setTone(m_outcome, failed ? Tone::Error : Tone::Normal);
}

Header FrameBuilder::header() const {
    return m_header->currentData().toChar() == QLatin1Char('W') ? Header::Write : Header::Read;
}

QString FrameBuilder::commandCode() const {
    const QString text = m_command->currentText();
    const int i = m_command->currentIndex();
    if (i >= 0 && m_command->itemText(i) == text)
        return m_command->itemData(i).toString();
    return text.section(kSeparator, 0, 0).trimmed();
}

FrameDraft FrameBuilder::draft() const {
    const int i = m_device->currentIndex();
    if (i < 0 || i >= m_targets.size()) {
        FrameDraft none;
        none.problem = tr("No device is known on this line: connect first, or send raw hex.");
        return none;
    }
    FrameInput in;
    in.source = m_robotAddress;
    in.target = m_targets.at(i).address;
    in.family = m_targets.at(i).family;
    in.header = header();
    in.command = commandCode();
    in.data = m_data->text();
    return composeFrame(in);
}

void FrameBuilder::fillCommands() {
    const QString keep = commandCode();
    const int i = m_device->currentIndex();
    const QString family = i >= 0 && i < m_targets.size() ? m_targets.at(i).family : QString();
    const Direction dir = header() == Header::Write ? Direction::Write : Direction::Read;
    {
        const QSignalBlocker block(m_command);
        m_command->clear();
        for (const ResolvedCommand &c : Catalog::builtin().expand(family, dir)) {
            const QString code = QString::fromLatin1(c.code);
            m_command->addItem(code + kSeparator + catalogText(c.spec->name), code);
        }
        // Keep what the person chose; with nothing chosen yet, start from the model-name read
        // every device answers.
        int found = m_command->findData(keep.isEmpty() ? QStringLiteral("SMN") : keep);
        if (found < 0 && keep.isEmpty() && m_command->count() > 0)
            found = 0;
        m_command->setCurrentIndex(found);
        if (found < 0)
            m_command->setEditText(keep);
    }
    updateDraft();
}

void FrameBuilder::onCommandPicked() {
    // Picking from the list fills the data field with what the command takes by construction;
    // typed values are left alone.
    const FrameDraft d = draft();
    if (header() == Header::Read) {
        m_data->clear();
        return;
    }
    const int i = m_device->currentIndex();
    if (!d.encodable || i < 0 || i >= m_targets.size())
        return;
    const auto cmd =
        Catalog::builtin().resolve(m_targets.at(i).family, d.frame.command, Direction::Write);
    if (cmd && cmd->spec->kind == ValueKind::Action)
        m_data->setText(QString::fromLatin1(cmd->spec->fixedData));
}

void FrameBuilder::updateDraft() {
    const FrameDraft d = draft();
    if (d.encodable) {
        const QByteArray bytes = d.frame.encode();
        // The BCC apart: as ASCII it would read as data ("<ETX>6").
        m_preview->setText(
            QStringLiteral("%1    %2    BCC %3")
                .arg(toHexText(bytes), toAsciiText(bytes.chopped(1)), toHexText(bytes.right(1))));
    } else {
        m_preview->setText(tr("(nothing to send)"));
    }
    m_hint->setText(d.encodable ? d.hint : d.problem);
    setTone(m_hint, !d.encodable ? Tone::Error : d.warning ? Tone::Warning : Tone::Normal);
    m_data->setPlaceholderText(header() == Header::Read ? tr("none for reads") : tr("e.g. 00350"));
    const bool blocked = m_monitorOnly && header() == Header::Write;
    m_sendFrame->setEnabled(d.encodable && !blocked);
    const QString blockedText =
        tr("Monitor-only mode is on: W frames are not sent. Reads still are.");
    if (blocked && d.encodable) {
        // Said in the panel too: a greyed-out button alone does not tell anyone why.
        m_hint->setText(blockedText + QLatin1Char(' ') + d.hint);
        setTone(m_hint, Tone::Warning);
    }
    if (blocked)
        m_sendFrame->setToolTip(blockedText);
    else if (!d.encodable)
        m_sendFrame->setToolTip(d.problem);
    else
        m_sendFrame->setToolTip(
            tr("Send this frame once, as shown (no retries; catalog warnings do not stop it). "
               "Its answer appears in the table."));
}

void FrameBuilder::updateRawHex() {
    const QString text = m_rawHex->text();
    QString error;
    const auto bytes = text.trimmed().isEmpty() ? std::nullopt : parseHexBytes(text, &error);
    if (!bytes) {
        m_rawStatus->setText(error);
        setTone(m_rawStatus, Tone::Error);
        return;
    }
    QString why;
    const auto frame = parseFrame(*bytes, nullptr, &why);
    if (frame)
        m_rawStatus->setText(
            tr("%n byte(s), a valid frame: %1", "", int(bytes->size())).arg(frame->toString()));
    else
        m_rawStatus->setText(
            tr("%n byte(s), not a valid frame (%1): sent as typed", "", int(bytes->size()))
                .arg(why));
    setTone(m_rawStatus, frame ? Tone::Normal : Tone::Warning);
}

void FrameBuilder::sendFrame() {
    const FrameDraft d = draft();
    if (!d.encodable || (m_monitorOnly && d.frame.header == Header::Write))
        return;
    Q_EMIT sendRequested(d.frame.encode(), d.frame.header == Header::Write);
}

void FrameBuilder::sendRaw() {
    if (m_monitorOnly)
        return;
    QString error;
    const auto bytes = parseHexBytes(m_rawHex->text(), &error);
    if (!bytes) {
        m_rawStatus->setText(tr("Not sent: %1").arg(error));
        setTone(m_rawStatus, Tone::Error);
        return;
    }
    // Bytes that are not a valid frame could be anything, a write included.
    const auto frame = parseFrame(*bytes);
    Q_EMIT sendRequested(*bytes, !frame || frame->header != Header::Read);
}

} // namespace tipscope::gui
