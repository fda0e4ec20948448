// How a model::Level looks on the Errors page: a standard icon and a translucent tint, and a
// proxy that dresses a model's LevelRole in them (the icon in one column, the tint on rows that
// are warnings or errors), so the models stay free of widgets.
#pragma once

#include "model/events/problemlevel.h"

#include <QIcon>
#include <QIdentityProxyModel>
#include <QVariant>

namespace tipscope::gui {

[[nodiscard]] QIcon levelIcon(model::Level level);
// A background brush colour, or an empty QVariant for levels that are not tinted.
[[nodiscard]] QVariant levelTint(model::Level level);

class LevelStyleProxy : public QIdentityProxyModel {
public:
    // `levelRole`: where the source model keeps each cell's Level; the icon goes in `iconColumn`.
    LevelStyleProxy(int levelRole, int iconColumn, QObject *parent = nullptr);

    QVariant data(const QModelIndex &index, int role) const override;

private:
    int m_levelRole;
    int m_iconColumn;
};

} // namespace tipscope::gui
