#include "model/joints/jointlimitsfile.h"

#include "model/io/atomicsave.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QStandardPaths>

namespace tipscope::model {

namespace {
struct Tr {
    Q_DECLARE_TR_FUNCTIONS(JointLimitsFile)
};
constexpr qint64 kMaxBytes = 1024 * 1024;
} // namespace

QString defaultJointLimitsPath() {
    const QString config = QStandardPaths::writableLocation(QStandardPaths::GenericConfigLocation);
    return QDir(config).filePath(QStringLiteral("TipScope/joint-limits.json"));
}

protocol::Outcome<JointLimitRules> loadJointLimits(const QString &path) {
    QFile file(path);
    if (!file.exists())
        return JointLimitRules{};
    if (!file.open(QIODevice::ReadOnly))
        return protocol::failure(
            Tr::tr("cannot read the joint limits %1: %2").arg(path, file.errorString()));
    if (file.size() > kMaxBytes)
        return protocol::failure(Tr::tr("the joint limits %1 are too big").arg(path));
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &error);
    if (!doc.isObject())
        return protocol::failure(
            Tr::tr("the joint limits %1 are not a JSON object: %2").arg(path, error.errorString()));
    const auto rules = JointLimitRules::fromJson(doc.object());
    if (!rules)
        return protocol::failure(QStringLiteral("%1: %2").arg(path, rules.error()));
    return rules;
}

protocol::Outcome<void> saveJointLimits(const QString &path, const JointLimitRules &rules) {
    QDir().mkpath(QFileInfo(path).absolutePath());
    return io::saveAtomically(path, QJsonDocument(rules.toJson()).toJson(QJsonDocument::Indented));
}

} // namespace tipscope::model
