#include "cfxsettings.h"

#include <QRegularExpression>

namespace tipscope::cfx {

bool isBrokerAddress(const QString &address) {
    static const QRegularExpression kForm(
        QStringLiteral("^/(exchange/[^/\\s]+(/[^/\\s]+)?|queue/[^/\\s]+|topic/[^/\\s]+)$"));
    return kForm.match(address).hasMatch();
}

bool isRequestQueue(const QString &address) {
    return address.startsWith(QLatin1String("/queue/")) && isBrokerAddress(address);
}

} // namespace tipscope::cfx
