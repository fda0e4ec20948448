#include "jointtable.h"

#include "base/csv.h"
#include "base/timetext.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QLocale>
#include <algorithm>

namespace tipscope::model {

namespace {
struct JointTableModelTr {
    Q_DECLARE_TR_FUNCTIONS(JointTableModel)
};

bool newerFirst(const JointRow &a, const JointRow &b) {
    return a.joint.startMs > b.joint.startMs;
}

bool fahrenheit(TemperatureUnit unit) {
    return unit == TemperatureUnit::Fahrenheit;
}
// A temperature, and a difference of temperatures (no 32), in the chosen unit; the estimated
// lowest tip and dip to a tenth.
int shown(int celsius, TemperatureUnit unit) {
    return fahrenheit(unit) ? qRound(celsius * 1.8 + 32) : celsius;
}
double shownTenths(double celsius, TemperatureUnit unit) {
    return std::round((fahrenheit(unit) ? celsius * 1.8 + 32 : celsius) * 10) / 10;
}
double shownDifference(double kelvin, TemperatureUnit unit) {
    return std::round((fahrenheit(unit) ? kelvin * 1.8 : kelvin) * 10) / 10;
}
QString unitText(TemperatureUnit unit) {
    return fahrenheit(unit) ? QStringLiteral("°F") : QStringLiteral("°C");
}
QString differenceUnitText(TemperatureUnit unit) {
    return fahrenheit(unit) ? QStringLiteral("°F") : QStringLiteral("K");
}
// Short, as a table column has room for ("DME-2C (01)"); the tooltip has the whole description.
QString deviceText(const DeviceIdentity &device) {
    return device.address ? QStringLiteral("%1 (%2)")
                                .arg(device.model)
                                .arg(*device.address, 2, 10, QLatin1Char('0'))
                          : device.model;
}
QString csvNumber(double value, int decimals) {
    return QString::number(value, 'f', decimals);
}
} // namespace

QString jointKey(const JointRecord &joint) {
    return QStringLiteral("%1|%2|%3").arg(joint.device.key()).arg(joint.port).arg(joint.startMs);
}

Level jointLevel(JointVerdict verdict) {
    switch (verdict) {
    case JointVerdict::Ok:
        return Level::Ok;
    case JointVerdict::SlowRecovery:
    case JointVerdict::TooDeep:
        return Level::Warning;
    case JointVerdict::Incomplete:
        return Level::Info;
    }
    return Level::Unknown;
}

void JointTableModel::setTemperatureUnit(TemperatureUnit unit) {
    if (unit == m_unit)
        return;
    m_unit = unit;
    if (!m_rows.isEmpty())
        Q_EMIT dataChanged(index(0, 0), index(rowCount() - 1, ColumnCount - 1));
    Q_EMIT headerDataChanged(Qt::Horizontal, 0, ColumnCount - 1);
}

void JointTableModel::reset(QList<JointRow> rows) {
    beginResetModel();
    std::stable_sort(rows.begin(), rows.end(), newerFirst);
    m_rows.clear();
    m_keys.clear();
    for (JointRow &r : rows) {
        if (m_rows.size() >= kCapacity)
            break;
        const QString key = jointKey(r.joint);
        if (m_keys.contains(key))
            continue;
        m_keys.insert(key);
        m_rows.append(std::move(r));
    }
    endResetModel();
}

bool JointTableModel::add(const JointRow &row) {
    const QString key = jointKey(row.joint);
    if (m_keys.contains(key))
        return false;
    const auto at = std::upper_bound(m_rows.begin(), m_rows.end(), row, newerFirst);
    const int position = int(at - m_rows.begin());
    if (position >= kCapacity)
        return false; // older than everything a full table keeps
    beginInsertRows({}, position, position);
    m_rows.insert(position, row);
    m_keys.insert(key);
    endInsertRows();
    if (m_rows.size() > kCapacity) {
        const int last = int(m_rows.size()) - 1;
        beginRemoveRows({}, last, last);
        m_keys.remove(jointKey(m_rows.takeLast().joint));
        endRemoveRows();
    }
    return true;
}

bool JointTableModel::contains(const JointRecord &joint) const {
    return m_keys.contains(jointKey(joint));
}

int JointTableModel::rowCount(const QModelIndex &parent) const {
    return parent.isValid() ? 0 : int(m_rows.size());
}

int JointTableModel::columnCount(const QModelIndex &parent) const {
    return parent.isValid() ? 0 : ColumnCount;
}

QVariant JointTableModel::data(const QModelIndex &index, int role) const {
    if (!index.isValid() || index.row() >= m_rows.size())
        return {};
    const JointRow &r = m_rows.at(index.row());
    switch (role) {
    case Qt::DisplayRole:
        return text(r, index.column(), m_unit);
    case Qt::ToolTipRole:
        return toolTip(r, index.column());
    case Qt::TextAlignmentRole:
        return index.column() >= Port && index.column() < Verdict && index.column() != Tool
                   ? QVariant(Qt::AlignRight | Qt::AlignVCenter)
                   : QVariant();
    case VerdictRole:
        return int(r.joint.verdict);
    case LevelRole:
        return int(jointLevel(r.joint.verdict));
    default:
        return {};
    }
}

QVariant JointTableModel::headerData(int section, Qt::Orientation orientation, int role) const {
    if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
        return {};
    return columnName(section);
}

QString JointTableModel::secondsText(qint64 ms) {
    return JointTableModelTr::tr("%1 s").arg(QLocale().toString(ms / 1000.0, 'f', 1));
}

QString JointTableModel::verdictText(JointVerdict verdict) {
    switch (verdict) {
    case JointVerdict::Ok:
        return JointTableModelTr::tr("ok");
    case JointVerdict::SlowRecovery:
        return JointTableModelTr::tr("slow recovery");
    case JointVerdict::TooDeep:
        return JointTableModelTr::tr("too deep");
    case JointVerdict::Incomplete:
        return JointTableModelTr::tr("incomplete");
    }
    return {};
}

QString JointTableModel::text(const JointRow &row, int column, TemperatureUnit unit) {
    const JointRecord &j = row.joint;
    const QLocale locale;
    switch (column) {
    case Time:
        return base::clockText(QDateTime::fromMSecsSinceEpoch(j.startMs));
    case Device:
        return deviceText(j.device);
    case Port:
        return QString::number(j.port);
    case Tool:
        return j.tool;
    case Setpoint:
        return QStringLiteral("%1 %2").arg(shown(j.setpoint, unit)).arg(unitText(unit));
    case Lowest:
        return QStringLiteral("%1 %2").arg(locale.toString(shownTenths(j.lowestTip, unit), 'f', 1),
                                           unitText(unit));
    case Dip:
        return QStringLiteral("%1 %2").arg(
            locale.toString(shownDifference(j.dipDepth, unit), 'f', 1), differenceUnitText(unit));
    case Recovery:
        if (!j.recoveryMs)
            return JointTableModelTr::tr("none");
        if (j.recoveryBounded) {
            // Only bounded: the interval it lies in, never one figure that looks measured.
            const qint64 lo = qMax<qint64>(0, *j.recoveryMs - j.recoveryUncertaintyMs);
            return JointTableModelTr::tr("%1–%2 s").arg(
                locale.toString(lo / 1000.0, 'f', 1),
                locale.toString((*j.recoveryMs + j.recoveryUncertaintyMs) / 1000.0, 'f', 1));
        }
        return secondsText(*j.recoveryMs);
    case Duration:
        return secondsText(j.durationMs);
    case PowerPeak:
        return QStringLiteral("%1 %").arg(j.powerPeak);
    case PowerIntegral:
        return JointTableModelTr::tr("%1 %·s").arg(locale.toString(j.powerIntegral, 'f', 1));
    case Verdict:
        return verdictText(j.verdict);
    case WorkOrder:
        return row.workOrder;
    default:
        return {};
    }
}

QString JointTableModel::toolTip(const JointRow &row, int column) {
    const JointRecord &j = row.joint;
    const QLocale locale;
    switch (column) {
    case Device:
        return j.device.description();
    case Time:
        return JointTableModelTr::tr("Began within ± %1 ms of this time").arg(j.startUncertaintyMs);
    case Lowest:
    case Dip:
        return JointTableModelTr::tr("Measured to ± %1 K")
            .arg(locale.toString(j.dipUncertaintyK, 'f', 1));
    case Recovery:
        if (!j.recoveryMs)
            return JointTableModelTr::tr("The tip was not seen back within the band");
        if (j.recoveryBounded)
            return JointTableModelTr::tr(
                "Only bounded: the readings around the tip's return were too far apart, or broke "
                "off, to say when within the interval shown");
        return JointTableModelTr::tr("Measured to ± %1 ms").arg(j.recoveryUncertaintyMs);
    default:
        return {};
    }
}

QString JointTableModel::columnName(int column) {
    switch (column) {
    case Time:
        return JointTableModelTr::tr("Time");
    case Device:
        return JointTableModelTr::tr("Device");
    case Port:
        return JointTableModelTr::tr("Port");
    case Tool:
        return JointTableModelTr::tr("Tool");
    case Setpoint:
        return JointTableModelTr::tr("Setpoint");
    case Lowest:
        return JointTableModelTr::tr("Lowest");
    case Dip:
        return JointTableModelTr::tr("Dip");
    case Recovery:
        return JointTableModelTr::tr("Recovery");
    case Duration:
        return JointTableModelTr::tr("Duration");
    case PowerPeak:
        return JointTableModelTr::tr("Power peak");
    case PowerIntegral:
        return JointTableModelTr::tr("Power·time");
    case Verdict:
        return JointTableModelTr::tr("Verdict");
    case WorkOrder:
        return JointTableModelTr::tr("Work order");
    default:
        return {};
    }
}

QByteArray JointTableModel::csv() const {
    const QString t = unitText(m_unit);
    const QStringList header = {QStringLiteral("time"),
                                QStringLiteral("device"),
                                QStringLiteral("port"),
                                QStringLiteral("tool"),
                                QStringLiteral("setpoint [%1]").arg(t),
                                QStringLiteral("lowest tip [%1]").arg(t),
                                QStringLiteral("dip [%1]").arg(differenceUnitText(m_unit)),
                                QStringLiteral("recovery [s]"),
                                QStringLiteral("recovery uncertainty [s]"),
                                QStringLiteral("recovery bounded"),
                                QStringLiteral("duration [s]"),
                                QStringLiteral("power peak [%]"),
                                QStringLiteral("power time [%·s]"),
                                QStringLiteral("verdict"),
                                QStringLiteral("work order")};
    QByteArray out = header.join(QLatin1Char(',')).toUtf8() + '\n';
    for (const JointRow &r : m_rows) {
        const JointRecord &j = r.joint;
        const QStringList cells = {
            base::isoTimeWithOffset(QDateTime::fromMSecsSinceEpoch(j.startMs)),
            base::csv::quoted(j.device.key()),
            QString::number(j.port),
            base::csv::quoted(j.tool),
            QString::number(shown(j.setpoint, m_unit)),
            QString::number(shownTenths(j.lowestTip, m_unit), 'f', 1),
            QString::number(shownDifference(j.dipDepth, m_unit), 'f', 1),
            j.recoveryMs ? csvNumber(*j.recoveryMs / 1000.0, 3) : QString(),
            j.recoveryMs ? csvNumber(j.recoveryUncertaintyMs / 1000.0, 3) : QString(),
            j.recoveryBounded ? QStringLiteral("true") : QStringLiteral("false"),
            csvNumber(j.durationMs / 1000.0, 3),
            QString::number(j.powerPeak),
            csvNumber(j.powerIntegral, 2),
            jointVerdictName(j.verdict),
            base::csv::quoted(r.workOrder)};
        out += cells.join(QLatin1Char(',')).toUtf8() + '\n';
    }
    return out;
}

} // namespace tipscope::model
