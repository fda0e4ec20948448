#include "cfxconsumerprocess.h"

namespace tipscope::testing {

namespace {
const QString kPython = QStringLiteral("/usr/bin/python3");
} // namespace

CfxConsumerProcess::CfxConsumerProcess(LineHandler onLine)
    : m_onLine(std::move(onLine)) {
    m_process.setProcessChannelMode(QProcess::MergedChannels);
}

CfxConsumerProcess::~CfxConsumerProcess() {
    if (m_process.state() != QProcess::NotRunning) {
        m_process.kill();
        m_process.waitForFinished(5000);
    }
}

QString CfxConsumerProcess::skipReason() {
    QProcess probe;
    probe.start(kPython, {QStringLiteral("-c"), QStringLiteral("import proton")});
    if (!probe.waitForFinished(20000) || probe.exitCode() != 0)
        return QStringLiteral("python3-qpid-proton is not installed for /usr/bin/python3");
    return {};
}

void CfxConsumerProcess::start(const QString &url, const QString &source, qint64 count,
                               int timeoutS, const QStringList &more) {
    m_process.start(kPython, QStringList{QStringLiteral(CFX_CONSUMER_SCRIPT),
                                         QStringLiteral("--url"), url, QStringLiteral("--source"),
                                         source, QStringLiteral("--count"), QString::number(count),
                                         QStringLiteral("--timeout"), QString::number(timeoutS)} +
                                 more);
}

void CfxConsumerProcess::read() {
    m_pending += m_process.readAll();
    qsizetype end;
    while ((end = m_pending.indexOf('\n')) >= 0) {
        const QByteArray line = m_pending.left(end).trimmed();
        m_pending.remove(0, end + 1);
        if (line == "READY")
            m_ready = true;
        m_onLine(line);
    }
}

} // namespace tipscope::testing
