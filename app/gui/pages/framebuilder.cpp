#include "framebuilder.h"

#include "protocol/hexbytes.h"
#include "widgets/placeholderfit.h"

#include <QComboBox>
#include <QCompleter>
#include <QFontDatabase>
#include <QGridLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSignalBlocker>

namespace tipscope::gui {

using namespace tipscope::protocol;

namespace {
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

FrameBuilder::FrameBuilder(model::ConsoleSender &sender, QWidget *parent)
    : QGroupBox(tr("Send a frame"), parent)
    , m_sender(sender) {
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
    connect(&m_sender, &model::ConsoleSender::gateChanged, this, &FrameBuilder::onGateChanged);
    connect(&m_sender, &model::ConsoleSender::outcome, this, &FrameBuilder::showOutcome);
    m_composer.setRobotAddress(m_sender.robotAddress());
    fillCommands();
    updateRawHex();
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
    // Its few short entries are never cut ("01 DME-2C" in Spanish was): the command box gives.
    m_device->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Fixed);
    m_header = new QComboBox(this);
    named(m_header, "headerCombo", tr("Header"));
    m_header->addItem(tr("R (read)"), QChar(QLatin1Char('R')));
    m_header->addItem(tr("W (write)"), QChar(QLatin1Char('W')));
    m_command = new QComboBox(this);
    named(m_command, "commandCombo", tr("Command"));
    m_command->setEditable(true);
    m_command->setInsertPolicy(QComboBox::NoInsert);
    // Room for a code and most of its name; the list shows them whole. At 30 the Console was the
    // one page wider than the others in Spanish, which narrowed the device tree while it showed.
    m_command->setMinimumContentsLength(24);
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
    // Both examples, so the field does not change width with the header.
    fitPlaceholders(*m_data, {tr("none for reads"), tr("e.g. 00350")});
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
    m_rawHex->setPlaceholderText(model::FrameComposer::exampleHex());
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

void FrameBuilder::setTargets(const QList<model::FrameTarget> &targets) {
    const QString current = m_device->currentText();
    {
        const QSignalBlocker block(m_device);
        m_composer.setTargets(targets);
        m_device->clear();
        for (const model::FrameTarget &t : targets)
            m_device->addItem(t.label);
        m_device->setCurrentIndex(qMax(0, m_device->findText(current)));
    }
    fillCommands();
}

void FrameBuilder::onGateChanged() {
    m_composer.setRobotAddress(m_sender.robotAddress());
    updateDraft();
    updateRawHex();
}

void FrameBuilder::showOutcome(const QString &text, bool failed) {
    m_outcome->setText(text);
    setTone(m_outcome, failed ? Tone::Error : Tone::Normal);
}

Header FrameBuilder::header() const {
    return m_header->currentData().toChar() == QLatin1Char('W') ? Header::Write : Header::Read;
}

model::FrameDraft FrameBuilder::draft() const {
    return m_composer.compose(m_device->currentIndex(), header(), m_command->currentText(),
                              m_data->text());
}

void FrameBuilder::fillCommands() {
    const QString keep = model::FrameComposer::codeOf(m_command->currentText());
    const int target = m_device->currentIndex();
    {
        const QSignalBlocker block(m_command);
        m_command->clear();
        for (const model::CommandChoice &c : m_composer.commands(target, header()))
            m_command->addItem(c.label, c.code);
        // Keep what the person chose; with nothing chosen yet, start where the composer says.
        const int found =
            m_command->findData(keep.isEmpty() ? m_composer.firstCommand(target, header()) : keep);
        m_command->setCurrentIndex(found);
        if (found < 0)
            m_command->setEditText(keep);
    }
    updateDraft();
}

void FrameBuilder::onCommandPicked() {
    // Picking from the list fills the data field with what the command takes by construction;
    // typed values are left alone.
    const std::optional<QString> data =
        m_composer.dataOfPicked(m_device->currentIndex(), header(), m_command->currentText());
    if (data)
        m_data->setText(*data);
}

void FrameBuilder::updateDraft() {
    const model::FrameDraft d = draft();
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
    const QString refusal = d.encodable ? m_sender.refusal(d.frame) : QString();
    m_sendFrame->setEnabled(d.encodable && refusal.isEmpty());
    if (!refusal.isEmpty()) {
        // Said in the panel too: a greyed-out button alone does not tell anyone why.
        m_hint->setText(refusal + QLatin1Char(' ') + d.hint);
        setTone(m_hint, Tone::Warning);
        m_sendFrame->setToolTip(refusal);
    } else if (!d.encodable) {
        m_sendFrame->setToolTip(d.problem);
    } else {
        m_sendFrame->setToolTip(
            tr("Send this frame once, as shown (no retries; catalog warnings do not stop it). "
               "Its answer appears in the table."));
    }
}

void FrameBuilder::updateRawHex() {
    const bool empty = m_rawHex->text().trimmed().isEmpty();
    const model::RawHex raw = model::FrameComposer::readHex(m_rawHex->text());
    const QString refusal = m_sender.refusal(raw.bytes.value_or(QByteArray()));
    m_sendRaw->setEnabled(refusal.isEmpty());
    m_sendRaw->setToolTip(
        !refusal.isEmpty()
            ? refusal
            : tr("Send these bytes exactly as typed; the answer appears in the table."));
    if (!empty && !raw.bytes) {
        m_rawStatus->setText(raw.text);
        setTone(m_rawStatus, Tone::Error);
    } else if (!refusal.isEmpty()) {
        m_rawStatus->setText(refusal);
        setTone(m_rawStatus, Tone::Warning);
    } else {
        m_rawStatus->setText(empty ? QString() : raw.text);
        setTone(m_rawStatus, raw.warning ? Tone::Warning : Tone::Normal);
    }
}

void FrameBuilder::sendFrame() {
    const model::FrameDraft d = draft();
    if (d.encodable)
        m_sender.send(d.frame); // refusals are reported like any outcome
}

void FrameBuilder::sendRaw() {
    const model::RawHex raw = model::FrameComposer::readHex(m_rawHex->text());
    if (!raw.bytes) {
        m_rawStatus->setText(tr("Not sent: %1").arg(raw.text));
        setTone(m_rawStatus, Tone::Error);
        return;
    }
    m_sender.send(*raw.bytes);
}

} // namespace tipscope::gui
