#include "model/joints/jointlimitsfile.h"

#include "base/atomicsave.h"
#include "base/jsonfile.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QStandardPaths>

namespace tipscope::model {

namespace {
struct JointLimitsFileTr {
    Q_DECLARE_TR_FUNCTIONS(JointLimitsFile)
};
constexpr qint64 kMaxBytes = 1024 * 1024;
} // namespace

QString defaultJointLimitsPath() {
    const QString config = QStandardPaths::writableLocation(QStandardPaths::GenericConfigLocation);
    return QDir(config).filePath(QStringLiteral("TipScope/joint-limits.json"));
}

base::Outcome<JointLimitRules> loadJointLimits(const QString &path) {
    const auto read = base::io::readJsonObject(path, kMaxBytes);
    if (const auto *problem = std::get_if<base::io::JsonFileProblem>(&read)) {
        using Kind = base::io::JsonFileProblem::Kind;
        switch (problem->kind) {
        case Kind::Missing:
            return JointLimitRules{};
        case Kind::Unreadable:
            return base::failure(JointLimitsFileTr::tr("cannot read the joint limits %1: %2")
                                     .arg(path, problem->detail));
        case Kind::TooBig:
            return base::failure(
                JointLimitsFileTr::tr("the joint limits %1 are too big").arg(path));
        case Kind::NotAnObject:
            return base::failure(
                JointLimitsFileTr::tr("the joint limits %1 are not a JSON object: %2")
                    .arg(path, problem->detail));
        }
    }
    const auto rules = JointLimitRules::fromJson(std::get<QJsonObject>(read));
    if (!rules)
        return base::failure(QStringLiteral("%1: %2").arg(path, rules.error()));
    return rules;
}

base::Outcome<void> saveJointLimits(const QString &path, const JointLimitRules &rules) {
    QDir().mkpath(QFileInfo(path).absolutePath());
    return base::io::saveAtomically(path,
                                    QJsonDocument(rules.toJson()).toJson(QJsonDocument::Indented));
}

} // namespace tipscope::model
