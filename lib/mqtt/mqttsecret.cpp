#include "mqttsecret.h"

#include "base/elide.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>

namespace tipscope::mqtt {

namespace {

struct MqttSecretTr {
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

base::Outcome<QByteArray> readSecretFile(const QString &path) {
    using base::failure;
    const QFileInfo info(path);
    const QString shown = base::elidedPath(path); // named by a file: quoted cut
    if (!info.exists())
        return failure(MqttSecretTr::tr("The password file %1 does not exist.").arg(shown));
    if (info.size() > kMaxSecretBytes)
        return failure(
            MqttSecretTr::tr("The password file %1 is larger than %2 bytes; is it the right file?")
                .arg(shown)
                .arg(kMaxSecretBytes));
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return failure(MqttSecretTr::tr("The password file %1 cannot be read: %2")
                           .arg(shown, file.errorString()));
    const QByteArray line = withoutLineEnd(file.readLine(kMaxSecretBytes + 1));
    if (line.isEmpty())
        return failure(MqttSecretTr::tr("The password file %1 is empty.").arg(shown));
    return line;
}

base::Outcome<QByteArray> readSecretEnvironment(const QString &name) {
    const QByteArray value = withoutLineEnd(qgetenv(name.toLocal8Bit().constData()));
    if (value.isEmpty())
        return base::failure(
            MqttSecretTr::tr("The environment variable %1 that should hold the password is not set "
                             "or empty.")
                .arg(base::elided(name)));
    return value;
}

} // namespace tipscope::mqtt
