// Throwaway TLS certificates for tests, made with the openssl command at test time: a CA, a
// server certificate for localhost and 127.0.0.1, and a client certificate, all signed by the
// CA (elliptic-curve keys, valid two days), plus a second CA that signed none of them, for tests
// that a wrong CA is refused. The server certificate names only localhost: a client that
// connects to 127.0.0.1 and checks the host name must refuse it. A test without openssl QSKIPs with
// skipReason().
#pragma once

#include <QString>
#include <QTemporaryDir>

namespace tipscope::testing {

class TestCertificates {
public:
    [[nodiscard]] static QString skipReason();
    [[nodiscard]] bool generate(QString *error);

    [[nodiscard]] QString caFile() const { return path(QStringLiteral("ca.crt")); }
    [[nodiscard]] QString otherCaFile() const { return path(QStringLiteral("other-ca.crt")); }
    [[nodiscard]] QString serverCertificate() const { return path(QStringLiteral("server.crt")); }
    [[nodiscard]] QString serverKey() const { return path(QStringLiteral("server.key")); }
    [[nodiscard]] QString clientCertificate() const { return path(QStringLiteral("client.crt")); }
    [[nodiscard]] QString clientKey() const { return path(QStringLiteral("client.key")); }

private:
    [[nodiscard]] QString path(const QString &name) const { return m_dir.filePath(name); }
    [[nodiscard]] bool makeCa(const QString &name, QString *error);
    [[nodiscard]] bool makeSigned(const QString &name, const QString &subject,
                                  const QString &extensions, QString *error);

    QTemporaryDir m_dir;
};

} // namespace tipscope::testing
