#include "mqttsecret.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

namespace tipscope::mqtt {

namespace {

struct Tr {
    Q_DECLARE_TR_FUNCTIONS(MqttSecret)
};

constexpr qint64 kMaxSecretBytes = 4096;

QByteArray withoutLineEnd(QByteArray value) {
    if (value.endsWith('\n'))
        value.chop(1);
    if (value.endsWith('\r'))
        value.chop(1);
    return value;
}

} // namespace

std::optional<QByteArray> readSecretFile(const QString &path, QString *error) {
    const QFileInfo info(path);
    if (!info.exists()) {
        *error = Tr::tr("The password file %1 does not exist.").arg(path);
        return std::nullopt;
    }
    if (info.size() > kMaxSecretBytes) {
        *error = Tr::tr("The password file %1 is larger than %2 bytes; is it the right file?")
                     .arg(path)
                     .arg(kMaxSecretBytes);
        return std::nullopt;
    }
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        *error = Tr::tr("The password file %1 cannot be read: %2").arg(path, file.errorString());
        return std::nullopt;
    }
    const QByteArray line = withoutLineEnd(file.readLine(kMaxSecretBytes + 1));
    if (line.isEmpty()) {
        *error = Tr::tr("The password file %1 is empty.").arg(path);
        return std::nullopt;
    }
    return line;
}

std::optional<QByteArray> readSecretEnvironment(const QString &name, QString *error) {
    const QByteArray value = withoutLineEnd(qgetenv(name.toLocal8Bit().constData()));
    if (value.isEmpty()) {
        *error = Tr::tr("The environment variable %1 that should hold the password is not set "
                        "or empty.")
                     .arg(name);
        return std::nullopt;
    }
    return value;
}

} // namespace tipscope::mqtt
