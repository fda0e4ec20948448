// ConsolePage: the raw frame console, every byte on the wire for people who read frames.
//
// The table shows the session line's FrameTap through a ConsoleModel: TX and RX chunks, decoded
// frames with their catalog names and BCC check, decode errors and line notes, newest at the
// bottom and followed unless the user scrolled up. The toolbar pauses (nothing is lost: held
// rows appear on resume, and their count stays in sight under the table), switches
// absolute/relative time, filters by kind, device address and command, clears, and saves every
// row to a text file. The FrameBuilder below composes a frame from the catalog or takes raw hex;
// both are sent once, verbatim, by the model's ConsoleSender, so the answer shows up in the table
// like any other traffic, and the outcome of the last send is shown under the builder.
//
// The model follows the session (ConsoleModel::follow()): a new line's traffic is shown and
// sends go to it; history stays until Clear. In monitor-only mode the sender refuses W frames
// and raw bytes that may be a write; reads still go out.
#pragma once

#include "page.h"

#include "model/console/consolemodel.h"

#include <QSortFilterProxyModel>
#include <QTimer>

class QAction;
class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QTableView;
class QToolBar;

namespace tipscope::gui {

class FrameBuilder;

// The console's filters, applied by the model's own rules (ConsoleModel::filterAccepts), plus
// a fixed-width font for the columns people compare byte by byte.
class ConsoleFilterProxy : public QSortFilterProxyModel {
    Q_OBJECT
public:
    explicit ConsoleFilterProxy(model::ConsoleModel *source, QObject *parent = nullptr);

    void setFilter(const model::ConsoleModel::Filter &filter);
    [[nodiscard]] const model::ConsoleModel::Filter &filter() const { return m_filter; }
    [[nodiscard]] QVariant data(const QModelIndex &index, int role) const override;

protected:
    [[nodiscard]] bool filterAcceptsRow(int sourceRow,
                                        const QModelIndex &sourceParent) const override;

private:
    model::ConsoleModel *m_console;
    model::ConsoleModel::Filter m_filter;
};

class ConsolePage : public Page {
    Q_OBJECT
public:
    explicit ConsolePage(model::Session &session, QWidget *parent = nullptr);
    ~ConsolePage() override;

    [[nodiscard]] QString title() const override { return tr("Console"); }
    // Hidden, the table takes new frames once a second; shown, it catches up at once.
    void setActive(bool active) override;

    // Writes every row (not only the filtered ones) as tab-separated text.
    [[nodiscard]] base::Outcome<void> saveTo(const QString &path);
    [[nodiscard]] model::ConsoleModel &consoleModel() { return *m_model; }
    [[nodiscard]] QAbstractItemModel *visibleRows() { return m_proxy; }

private:
    void buildToolBar(QToolBar *bar);
    void buildTable();
    void updateDevices();
    void applyFilter();
    void setPaused(bool paused);
    void save();
    void copySelection();
    void updateCount();

    model::ConsoleModel *m_model = nullptr;
    ConsoleFilterProxy *m_proxy = nullptr;
    QTableView *m_table = nullptr;
    FrameBuilder *m_builder = nullptr;
    QAction *m_pause = nullptr;
    QAction *m_relative = nullptr;
    QCheckBox *m_showTx = nullptr;
    QCheckBox *m_showRx = nullptr;
    QCheckBox *m_showFrames = nullptr;
    QCheckBox *m_showErrors = nullptr;
    QCheckBox *m_showNotes = nullptr;
    QComboBox *m_address = nullptr;
    QLineEdit *m_command = nullptr;
    QLabel *m_count = nullptr;
    QTimer m_countTimer;
    bool m_followNewest = true;
};

} // namespace tipscope::gui
