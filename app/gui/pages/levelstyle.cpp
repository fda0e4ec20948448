#include "levelstyle.h"

#include <QApplication>
#include <QColor>
#include <QStyle>

namespace tipscope::gui {

using model::Level;

QIcon levelIcon(Level level) {
    const QStyle *style = QApplication::style();
    switch (level) {
    case Level::Unknown:
        return {};
    case Level::Ok:
        return style->standardIcon(QStyle::SP_DialogApplyButton);
    case Level::Info:
        return style->standardIcon(QStyle::SP_MessageBoxInformation);
    case Level::Warning:
        return style->standardIcon(QStyle::SP_MessageBoxWarning);
    case Level::Error:
        return style->standardIcon(QStyle::SP_MessageBoxCritical);
    }
    return {};
}

// Translucent, so the tint reads on light and dark palettes alike.
QVariant levelTint(Level level) {
    switch (level) {
    case Level::Error:
        return QColor(220, 40, 40, 70);
    case Level::Warning:
        return QColor(235, 165, 0, 80);
    case Level::Info:
        return QColor(40, 120, 220, 35);
    default:
        return {};
    }
}

LevelStyleProxy::LevelStyleProxy(int levelRole, int iconColumn, QObject *parent)
    : QIdentityProxyModel(parent)
    , m_levelRole(levelRole)
    , m_iconColumn(iconColumn) {}

QVariant LevelStyleProxy::data(const QModelIndex &index, int role) const {
    if (role != Qt::DecorationRole && role != Qt::BackgroundRole)
        return QIdentityProxyModel::data(index, role);
    const Level level = Level(QIdentityProxyModel::data(index, m_levelRole).toInt());
    if (role == Qt::DecorationRole)
        return index.column() == m_iconColumn ? QVariant(levelIcon(level)) : QVariant();
    // Only problems are tinted, so they stand out among status changes and writes.
    return level >= Level::Warning ? levelTint(level) : QVariant();
}

} // namespace tipscope::gui
