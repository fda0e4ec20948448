#include "testcertificates.h"

#include "mosquittobroker.h"

#include <QFile>
#include <QStandardPaths>

namespace tipscope::testing {

namespace {

const QString kOpenssl = QStringLiteral("openssl");

QStringList newKey(const QString &keyFile) {
    return {QStringLiteral("-newkey"),
            QStringLiteral("ec"),
            QStringLiteral("-pkeyopt"),
            QStringLiteral("ec_paramgen_curve:prime256v1"),
            QStringLiteral("-nodes"),
            QStringLiteral("-keyout"),
            keyFile};
}

} // namespace

QString TestCertificates::skipReason() {
    if (QStandardPaths::findExecutable(kOpenssl).isEmpty())
        return QStringLiteral("openssl is not installed: no certificates for the TLS tests");
    return {};
}

bool TestCertificates::makeCa(const QString &name, QString *error) {
    return runTool(kOpenssl,
                   QStringList{QStringLiteral("req"), QStringLiteral("-x509")} +
                       newKey(path(name + QStringLiteral(".key"))) +
                       QStringList{QStringLiteral("-out"), path(name + QStringLiteral(".crt")),
                                   QStringLiteral("-days"), QStringLiteral("2"),
                                   QStringLiteral("-subj"),
                                   QStringLiteral("/CN=TipScope test ") + name},
                   error);
}

bool TestCertificates::makeSigned(const QString &name, const QString &subject,
                                  const QString &extensions, QString *error) {
    const QString request = path(name + QStringLiteral(".csr"));
    const QString extensionFile = path(name + QStringLiteral(".ext"));
    QFile ext(extensionFile);
    if (!ext.open(QIODevice::WriteOnly) || ext.write(extensions.toUtf8() + '\n') < 0) {
        *error = QStringLiteral("cannot write ") + extensionFile;
        return false;
    }
    ext.close();
    return runTool(
               kOpenssl,
               QStringList{QStringLiteral("req")} + newKey(path(name + QStringLiteral(".key"))) +
                   QStringList{QStringLiteral("-out"), request, QStringLiteral("-subj"), subject},
               error) &&
           runTool(kOpenssl,
                   {QStringLiteral("x509"), QStringLiteral("-req"), QStringLiteral("-in"), request,
                    QStringLiteral("-CA"), caFile(), QStringLiteral("-CAkey"),
                    path(QStringLiteral("ca.key")), QStringLiteral("-CAcreateserial"),
                    QStringLiteral("-out"), path(name + QStringLiteral(".crt")),
                    QStringLiteral("-days"), QStringLiteral("2"), QStringLiteral("-extfile"),
                    extensionFile},
                   error, m_dir.path());
}

bool TestCertificates::generate(QString *error) {
    if (!m_dir.isValid()) {
        *error = QStringLiteral("no temporary folder for the certificates");
        return false;
    }
    return makeCa(QStringLiteral("ca"), error) && makeCa(QStringLiteral("other-ca"), error) &&
           makeSigned(QStringLiteral("server"), QStringLiteral("/CN=localhost"),
                      QStringLiteral("subjectAltName=DNS:localhost"), error) &&
           makeSigned(QStringLiteral("client"), QStringLiteral("/CN=tipscope-test-client"),
                      QStringLiteral("extendedKeyUsage=clientAuth"), error);
}

} // namespace tipscope::testing
