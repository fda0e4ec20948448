#include "settingname.h"

#include "devicemodel.h"
#include "parameter.h"

#include <QCoreApplication>

namespace tipscope::model {

using namespace tipscope::protocol;

namespace {
struct SettingNameTr {
    Q_DECLARE_TR_FUNCTIONS(SettingName)
};

QString toolName(const ResolvedCommand &command, const Catalog &catalog, Wording wording) {
    const QMap<int, QString> tools = catalog.table(QStringLiteral("$toolTable"), command.family);
    if (tools.contains(command.tool))
        return catalogText(tools.value(command.tool), wording);
    return wording == Wording::Catalog ? QStringLiteral("tool %1").arg(command.tool)
                                       : SettingNameTr::tr("tool %1").arg(command.tool);
}
} // namespace

QString settingName(const ResolvedCommand &command, const Catalog &catalog, NameParts parts,
                    Wording wording) {
    QStringList name{catalogText(command.spec->name, wording)};
    if (command.tool >= 0)
        name.append(toolName(command, catalog, wording));
    if (command.port > 0 && parts == NameParts::ToolAndPort)
        name.append(wording == Wording::Catalog ? QStringLiteral("port %1").arg(command.port)
                                                : SettingNameTr::tr("port %1").arg(command.port));
    return name.join(QLatin1String(", "));
}

QString settingName(const Parameter &parameter, NameParts parts, Wording wording) {
    return settingName(parameter.spec(), parameter.device().catalog(), parts, wording);
}

} // namespace tipscope::model
