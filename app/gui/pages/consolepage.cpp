#include "consolepage.h"

#include "framebuilder.h"

#include "protocol/catalogtext.h"
#include "protocol/hexbytes.h"
#include "widgets/placeholderfit.h"

#include <QAction>
#include <QCheckBox>
#include <QClipboard>
#include <QComboBox>
#include <QDateTime>
#include <QFileDialog>
#include <QFontDatabase>
#include <QGuiApplication>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMessageBox>
#include <QRegularExpression>
#include <QScrollBar>
#include <QTableView>
#include <QToolBar>
#include <QVBoxLayout>

namespace tipscope::gui {

using model::ConsoleModel;

namespace {
constexpr int kHiddenBatchMs = 1000;

QString widest(const QFontMetrics &fm, const QStringList &texts) {
    QString out;
    for (const QString &t : texts)
        if (fm.horizontalAdvance(t) > fm.horizontalAdvance(out))
            out = t;
    return out;
}
} // namespace

ConsoleFilterProxy::ConsoleFilterProxy(ConsoleModel *source, QObject *parent)
    : QSortFilterProxyModel(parent)
    , m_console(source) {
    setSourceModel(source);
}

void ConsoleFilterProxy::setFilter(const ConsoleModel::Filter &filter) {
    m_filter = filter;
    invalidateFilter();
}

bool ConsoleFilterProxy::filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const {
    return !sourceParent.isValid() && m_console->filterAccepts(sourceRow, m_filter);
}

QVariant ConsoleFilterProxy::data(const QModelIndex &index, int role) const {
    // The model writes a BCC that happens to be printable as that character ("<ETX>="), which
    // reads like data; for a whole frame the BCC is shown as a byte value instead.
    if (role == Qt::DisplayRole && index.column() == ConsoleModel::Ascii) {
        const model::ConsoleEntry &e = m_console->entry(mapToSource(index).row());
        if (e.frame && e.bytes.size() > 1 && e.bytes.at(e.bytes.size() - 2) == protocol::kEtx)
            return protocol::toAsciiText(e.bytes.chopped(1)) +
                   QStringLiteral("<%1>").arg(protocol::toHexText(e.bytes.right(1)));
    }
    if (role == Qt::FontRole) {
        switch (index.column()) {
        case ConsoleModel::Device:
        case ConsoleModel::Command:
        case ConsoleModel::Data:
        case ConsoleModel::Hex:
        case ConsoleModel::Ascii:
            return QFontDatabase::systemFont(QFontDatabase::FixedFont);
        default:
            break;
        }
    }
    return QSortFilterProxyModel::data(index, role);
}

ConsolePage::ConsolePage(model::Session &session, QWidget *parent)
    : Page(session, parent)
    , m_model(new ConsoleModel(this))
    , m_proxy(new ConsoleFilterProxy(m_model, this)) {
    auto *bar = new QToolBar(this);
    bar->setObjectName(QStringLiteral("consoleToolBar"));
    bar->setAccessibleName(tr("Console tools"));
    buildToolBar(bar);
    buildTable();
    m_builder = new FrameBuilder(m_model->sender(), this);
    m_builder->setObjectName(QStringLiteral("frameBuilder"));
    // The count goes under the table, not at the end of the toolbar: a toolbar too narrow for
    // the page folds its last items away, and the count of held rows must stay in sight.
    m_count = new QLabel(this);
    m_count->setObjectName(QStringLiteral("rowCountLabel"));
    m_count->setToolTip(tr("Older rows go as new ones come; Save… writes the rows kept to a "
                           "file. While paused, new rows are held; they appear on resume."));
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(bar);
    layout->addWidget(m_table, 1);
    layout->addWidget(m_count, 0, Qt::AlignRight);
    layout->addWidget(m_builder);

    // The count is for reading, not for every row of a burst.
    m_countTimer.setSingleShot(true);
    m_countTimer.setInterval(200);
    connect(&m_countTimer, &QTimer::timeout, this, &ConsolePage::updateCount);
    // Started only when idle: restarting it on every row would starve it under steady traffic.
    auto countLater = [this] {
        if (!m_countTimer.isActive())
            m_countTimer.start();
    };
    connect(m_proxy, &QAbstractItemModel::rowsInserted, this, countLater);
    connect(m_proxy, &QAbstractItemModel::rowsRemoved, this, countLater);
    connect(m_proxy, &QAbstractItemModel::modelReset, this, countLater);
    connect(m_proxy, &QAbstractItemModel::layoutChanged, this, countLater);
    connect(m_model, &ConsoleModel::heldCountChanged, this, countLater);

    m_model->follow(&m_session);
    connect(&m_session, &model::Session::devicesChanged, this, &ConsolePage::updateDevices);
    updateDevices();
    applyFilter();
    updateCount();
}

ConsolePage::~ConsolePage() {
    // Children would go after this destructor, in the order they came: the model first, whose
    // end empties the table, which moves its scroll bar into a handler of this half-destroyed
    // page. They go now, while the page is whole: the widgets before what they show.
    delete m_builder; // sends through the model's sender
    delete m_table;
    delete m_proxy;
    delete m_model;
}

void ConsolePage::buildToolBar(QToolBar *bar) {
    m_pause = bar->addAction(tr("Pause"));
    m_pause->setObjectName(QStringLiteral("pauseAction"));
    m_pause->setCheckable(true);
    m_pause->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_P));
    m_pause->setShortcutContext(Qt::WidgetWithChildrenShortcut);
    m_pause->setToolTip(tr("Hold new rows (Ctrl+P); nothing is lost, they appear on resume"));
    addAction(m_pause); // so the shortcut works wherever the focus is on this page
    connect(m_pause, &QAction::toggled, this, &ConsolePage::setPaused);

    m_relative = bar->addAction(tr("Relative time"));
    m_relative->setObjectName(QStringLiteral("relativeTimeAction"));
    m_relative->setCheckable(true);
    m_relative->setToolTip(tr("Show seconds since the first row instead of the clock time"));
    connect(m_relative, &QAction::toggled, m_model, &ConsoleModel::setRelativeTime);
    bar->addSeparator();

    auto box = [this, bar](const QString &text, const char *name, const QString &tip,
                           bool checked) {
        auto *b = new QCheckBox(text, bar);
        b->setObjectName(QLatin1String(name));
        b->setChecked(checked);
        b->setToolTip(tip);
        b->setAccessibleName(tip);
        bar->addWidget(b);
        connect(b, &QCheckBox::toggled, this, &ConsolePage::applyFilter);
        return b;
    };
    bar->addWidget(new QLabel(tr("Show:"), bar));
    m_showTx = box(tr("TX"), "showTx", tr("Show bytes sent"), true);
    // Every received byte is also in a frame or error row, so the chunks (as the driver happened
    // to deliver them) are off by default; they matter when chasing timing or split answers.
    m_showRx = box(tr("RX chunks"), "showRx",
                   tr("Show bytes as the driver delivered them, chunk by chunk (every received "
                      "byte is also in a frame or error row)"),
                   false);
    m_showFrames = box(tr("Frames"), "showFrames", tr("Show received frames, decoded"), true);
    m_showErrors =
        box(tr("Errors"), "showErrors", tr("Show decode errors (BCC, format, garbage)"), true);
    m_showNotes = box(tr("Notes"), "showNotes", tr("Show line notes (timeouts, line state)"), true);
    bar->addSeparator();

    auto *addressLabel = new QLabel(tr("De&vice:"), bar);
    m_address = new QComboBox(bar);
    m_address->setObjectName(QStringLiteral("addressFilter"));
    m_address->setAccessibleName(tr("Device address filter"));
    m_address->setToolTip(tr("Only frames from or to this address; type any address 00-99"));
    m_address->setEditable(true);
    m_address->setInsertPolicy(QComboBox::NoInsert);
    m_address->setMinimumContentsLength(12);
    addressLabel->setBuddy(m_address);
    bar->addWidget(addressLabel);
    bar->addWidget(m_address);
    connect(m_address, &QComboBox::currentTextChanged, this, &ConsolePage::applyFilter);

    auto *commandLabel = new QLabel(tr("Co&mmand:"), bar);
    m_command = new QLineEdit(bar);
    m_command->setObjectName(QStringLiteral("commandFilter"));
    m_command->setAccessibleName(tr("Command filter"));
    m_command->setPlaceholderText(tr("e.g. ST1"));
    m_command->setClearButtonEnabled(true);
    m_command->setMaximumWidth(fontMetrics().horizontalAdvance(QLatin1Char('W')) * 10);
    fitPlaceholders(*m_command, {m_command->placeholderText()});
    commandLabel->setBuddy(m_command);
    bar->addWidget(commandLabel);
    bar->addWidget(m_command);
    connect(m_command, &QLineEdit::textChanged, this, &ConsolePage::applyFilter);
    bar->addSeparator();

    QAction *clear = bar->addAction(tr("Clear"), m_model, &ConsoleModel::clear);
    clear->setObjectName(QStringLiteral("clearAction"));
    clear->setToolTip(tr("Remove every row, held ones included"));
    QAction *save = bar->addAction(tr("Save…"), this, &ConsolePage::save);
    save->setObjectName(QStringLiteral("saveAction"));
    save->setToolTip(tr("Save every row (not only the shown ones) to a text file"));
}

void ConsolePage::buildTable() {
    m_table = new QTableView(this);
    m_table->setObjectName(QStringLiteral("consoleTable"));
    m_table->setAccessibleName(tr("Traffic on the line"));
    m_table->setModel(m_proxy);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->setSelectionMode(QAbstractItemView::ExtendedSelection);
    m_table->setWordWrap(false);
    m_table->setAlternatingRowColors(true);
    m_table->setHorizontalScrollMode(QAbstractItemView::ScrollPerPixel);

    const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    const QFontMetrics text = fontMetrics();
    const QFontMetrics fixed(mono);
    // Fixed row heights keep scrolling through 20000 rows cheap and the rows aligned.
    QHeaderView *rows = m_table->verticalHeader();
    rows->hide();
    rows->setSectionResizeMode(QHeaderView::Fixed);
    rows->setDefaultSectionSize(qMax(text.height(), fixed.height()) + 6);

    QHeaderView *columns = m_table->horizontalHeader();
    columns->setStretchLastSection(true);
    columns->setHighlightSections(false);
    auto width = [&](int column, const QFontMetrics &fm, const QString &sample) {
        const QString title =
            m_model->headerData(column, Qt::Horizontal, Qt::DisplayRole).toString();
        m_table->setColumnWidth(
            column, qMax(fm.horizontalAdvance(sample), text.horizontalAdvance(title)) + 18);
    };
    width(ConsoleModel::Time, text, QStringLiteral("+0000.0000 s"));
    using Direction = model::ConsoleEntry::Direction;
    width(ConsoleModel::Direction, text,
          widest(text, {ConsoleModel::directionText(Direction::Tx),
                        ConsoleModel::directionText(Direction::Rx),
                        ConsoleModel::directionText(Direction::Decoded),
                        ConsoleModel::directionText(Direction::Error),
                        ConsoleModel::directionText(Direction::Note)}));
    width(ConsoleModel::Device, fixed, QStringLiteral("00→00"));
    using protocol::Header;
    width(
        ConsoleModel::Header, text,
        widest(text,
               {ConsoleModel::headerText(Header::Read), ConsoleModel::headerText(Header::Write),
                ConsoleModel::headerText(Header::Answer), ConsoleModel::headerText(Header::Nak)}));
    width(ConsoleModel::Command, fixed, QString(3, QLatin1Char('W'))); // a command's width
    // One of the longest command names, in the interface language.
    width(ConsoleModel::Name, text,
          protocol::catalogText(QStringLiteral("Time to sleep/hibernation")));
    width(ConsoleModel::Data, fixed, QStringLiteral("DME-2C0000"));
    width(ConsoleModel::Bcc, text, tr("bad"));
    // An addressed frame with a 5-character data field is 16 bytes; model names are a bit longer.
    width(ConsoleModel::Hex, fixed, QString(18 * 3 - 1, QLatin1Char('0')));
    width(ConsoleModel::Ascii, fixed, QStringLiteral("<STX>0001W ST100350<ETX><3E>"));

    // Follow the newest row unless the user scrolled away from the bottom to read.
    QScrollBar *scroll = m_table->verticalScrollBar();
    connect(scroll, &QScrollBar::valueChanged, this,
            [this, scroll](int value) { m_followNewest = value >= scroll->maximum(); });
    connect(scroll, &QScrollBar::rangeChanged, this, [this, scroll](int, int max) {
        if (m_followNewest)
            scroll->setValue(max);
    });

    auto *copy = new QAction(tr("Copy rows"), m_table);
    copy->setShortcut(QKeySequence::Copy);
    copy->setShortcutContext(Qt::WidgetShortcut);
    connect(copy, &QAction::triggered, this, &ConsolePage::copySelection);
    m_table->addAction(copy);
    m_table->setContextMenuPolicy(Qt::ActionsContextMenu);
}

void ConsolePage::updateDevices() {
    QList<model::FrameTarget> targets;
    const QString current = m_address->currentText();
    {
        const QSignalBlocker block(m_address);
        m_address->clear();
        m_address->addItem(tr("All"));
        for (const model::DeviceModel *d : m_session.devices()) {
            targets.append(model::FrameTarget::of(*d));
            if (d->address())
                m_address->addItem(targets.last().label, *d->address());
        }
        const int index = m_address->findText(current);
        if (index >= 0)
            m_address->setCurrentIndex(index);
        else
            m_address->setEditText(current.isEmpty() ? tr("All") : current);
    }
    m_builder->setTargets(targets);
}

void ConsolePage::applyFilter() {
    ConsoleModel::Filter filter;
    filter.tx = m_showTx->isChecked();
    filter.rx = m_showRx->isChecked();
    filter.decoded = m_showFrames->isChecked();
    filter.errors = m_showErrors->isChecked();
    filter.notes = m_showNotes->isChecked();
    filter.command = m_command->text().trimmed();

    // "01", "1" and "01 DME-2C" all mean address 1; anything else is shown as not understood.
    const QString text = m_address->currentText().trimmed();
    static const QRegularExpression leadingAddress(QStringLiteral("^(\\d{1,2})(\\s|$)"));
    const QRegularExpressionMatch match = leadingAddress.match(text);
    const bool all = text.isEmpty() || text.compare(tr("All"), Qt::CaseInsensitive) == 0;
    if (!all && match.hasMatch())
        filter.address = match.captured(1).toInt();
    QPalette palette;
    if (!all && !match.hasMatch())
        palette.setColor(QPalette::Text, QColor(0xc0, 0x1c, 0x28));
    if (m_address->lineEdit())
        m_address->lineEdit()->setPalette(palette);
    m_proxy->setFilter(filter);
    updateCount();
}

void ConsolePage::setActive(bool active) {
    Page::setActive(active);
    m_model->setBatchMs(active ? ConsoleModel::kBatchMs : kHiddenBatchMs);
    if (active)
        m_model->flush();
}

void ConsolePage::setPaused(bool paused) {
    m_model->setPaused(paused);
    m_pause->setText(paused ? tr("Resume") : tr("Pause"));
    updateCount();
}

base::Outcome<void> ConsolePage::saveTo(const QString &path) {
    m_model->flush(); // the file has every row up to now
    return m_model->saveText(path);
}

void ConsolePage::save() {
    const QString suggested =
        QStringLiteral("tipscope-console-%1.txt")
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")));
    const QString path = QFileDialog::getSaveFileName(this, tr("Save console"), suggested,
                                                      tr("Text files (*.txt);;All files (*)"));
    if (path.isEmpty())
        return;
    if (const auto saved = saveTo(path); !saved.ok())
        QMessageBox::warning(this, tr("Save console"),
                             tr("The console could not be saved:\n%1").arg(saved.error()));
}

void ConsolePage::copySelection() {
    QStringList lines;
    const QModelIndexList selected = m_table->selectionModel()->selectedRows();
    QList<int> rows;
    for (const QModelIndex &index : selected)
        rows.append(m_proxy->mapToSource(index).row());
    std::sort(rows.begin(), rows.end());
    for (int row : rows)
        lines.append(m_model->lineText(row));
    if (!lines.isEmpty())
        QGuiApplication::clipboard()->setText(lines.join(QLatin1Char('\n')) + QLatin1Char('\n'));
}

void ConsolePage::updateCount() {
    // A busy line fills the console in minutes: people should know the oldest rows go.
    QString text = tr("%1 of %2 rows shown; the newest %3 are kept")
                       .arg(m_proxy->rowCount())
                       .arg(m_model->rowCount())
                       .arg(QLocale().toString(m_model->capacity()));
    if (m_model->isPaused())
        text += QStringLiteral(" · ") + tr("paused: %n held", "", m_model->heldCount());
    m_count->setText(text);
}

} // namespace tipscope::gui
