// JointTableModel: joints as a table, newest first, for any front end; and the CSV the table is
// exported as.
//
// A row is a joint and the work order it was made under (empty: none known). A joint is listed
// once: rows are keyed by device key, port and start time (jointKey()), and add() refuses a
// joint already listed, so a live joint and the same joint read back from the journal are one
// row. Temperatures read in the chosen unit (a dip depth is a difference: K or °F); each cell
// carries the joint's verdict (VerdictRole, LevelRole) so a front end can colour the row, while the
// Verdict column says it in words. Bounded: above kCapacity rows the oldest go.
//
// The CSV (csv()) is for files another program reads: English column names with their units,
// the start as ISO 8601 with the UTC offset, '.' as the decimal point, the verdict as its
// stable name ("slow recovery"), an empty recovery cell for a joint that never recovered.
#pragma once

#include "model/device/displayunits.h"
#include "model/events/problemlevel.h"
#include "model/joints/jointrecord.h"

#include <QAbstractTableModel>
#include <QList>
#include <QSet>

namespace tipscope::model {

struct JointRow {
    JointRecord joint;
    QString workOrder;
};

// "device key|port|start ms": what makes a joint the same joint wherever it was read from.
[[nodiscard]] QString jointKey(const JointRecord &joint);
// How a verdict looks among other problems: ok is Ok, a broken limit a Warning, a joint not
// judged Info.
[[nodiscard]] Level jointLevel(JointVerdict verdict);

class JointTableModel : public QAbstractTableModel {
    Q_OBJECT
public:
    enum Column {
        Time,
        Device,
        Port,
        Tool,
        Setpoint,
        Lowest,
        Dip,
        Recovery,
        Duration,
        PowerPeak,
        PowerIntegral,
        Verdict,
        WorkOrder,
        ColumnCount
    };
    // int(JointVerdict) and int(jointLevel()), in every column.
    static constexpr int VerdictRole = Qt::UserRole;
    static constexpr int LevelRole = Qt::UserRole + 1;
    static constexpr int kCapacity = 20000;

    using QAbstractTableModel::QAbstractTableModel;

    void setTemperatureUnit(TemperatureUnit unit);
    [[nodiscard]] TemperatureUnit temperatureUnit() const { return m_unit; }
    // Replaces every row (duplicates dropped), sorted newest first.
    void reset(QList<JointRow> rows);
    // Puts the joint at its place by start time; false when it is listed already.
    bool add(const JointRow &row);
    [[nodiscard]] bool contains(const JointRecord &joint) const;
    [[nodiscard]] const JointRow &row(int r) const { return m_rows.at(r); }
    [[nodiscard]] const QList<JointRow> &rows() const { return m_rows; }

    int rowCount(const QModelIndex &parent = {}) const override;
    int columnCount(const QModelIndex &parent = {}) const override;
    QVariant data(const QModelIndex &index, int role) const override;
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override;

    // What a cell says on screen, in the user interface language.
    [[nodiscard]] static QString text(const JointRow &row, int column, TemperatureUnit unit);
    // What a cell's figure is worth: how sure it is, or why it is only bounded.
    [[nodiscard]] static QString toolTip(const JointRow &row, int column);
    [[nodiscard]] static QString columnName(int column);
    // The verdict in the user interface language ("slow recovery", "langsame Erholung").
    [[nodiscard]] static QString verdictText(JointVerdict verdict);
    [[nodiscard]] static QString secondsText(qint64 ms);

    // Every row, in table order, as CSV (see the class comment).
    [[nodiscard]] QByteArray csv() const;

private:
    QList<JointRow> m_rows;
    QSet<QString> m_keys;
    TemperatureUnit m_unit = TemperatureUnit::Celsius;
};

} // namespace tipscope::model
