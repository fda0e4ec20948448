#include "jsonfile.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonParseError>

namespace tipscope::base::io {

std::variant<QJsonObject, JsonFileProblem> readJsonObject(const QString &path, qint64 maxBytes) {
    QFile file(path);
    if (!file.exists())
        return JsonFileProblem{JsonFileProblem::Kind::Missing, {}};
    if (!file.open(QIODevice::ReadOnly))
        return JsonFileProblem{JsonFileProblem::Kind::Unreadable, file.errorString()};
    if (file.size() > maxBytes)
        return JsonFileProblem{JsonFileProblem::Kind::TooBig, {}};
    QJsonParseError error;
    const QJsonDocument doc = QJsonDocument::fromJson(file.readAll(), &error);
    if (!doc.isObject())
        return JsonFileProblem{JsonFileProblem::Kind::NotAnObject,
                               error.error == QJsonParseError::NoError ? QString()
                                                                       : error.errorString()};
    return doc.object();
}

} // namespace tipscope::base::io
