#include "cliprefixedoutput.h"

#include <QMutex>
#include <QMutexLocker>

namespace tipscope::cli {

namespace {
// One lock for every prefixed device: a line is written whole before another starts.
QMutex &outputLock() {
    static QMutex lock;
    return lock;
}
} // namespace

PrefixedOutput::PrefixedOutput(const QString &prefix, std::FILE *target, Keep keep)
    : m_prefix(prefix.toUtf8())
    , m_target(target)
    , m_keep(keep) {
    QIODevice::open(QIODevice::WriteOnly | QIODevice::Unbuffered);
}

PrefixedOutput::~PrefixedOutput() {
    PrefixedOutput::close();
}

void PrefixedOutput::close() {
    if (!m_pending.isEmpty())
        emitLine(m_pending);
    m_pending.clear();
    QIODevice::close();
}

qint64 PrefixedOutput::writeData(const char *data, qint64 size) {
    m_pending.append(data, size);
    qsizetype start = 0;
    for (qsizetype end = m_pending.indexOf('\n'); end >= 0; end = m_pending.indexOf('\n', start)) {
        emitLine(QByteArrayView(m_pending).sliced(start, end - start));
        start = end + 1;
    }
    m_pending.remove(0, start);
    return size;
}

void PrefixedOutput::emitLine(QByteArrayView line) {
    if (m_keep == Keep::Text)
        m_kept.append(line).append('\n');
    QMutexLocker lock(&outputLock());
    std::fwrite(m_prefix.constData(), 1, size_t(m_prefix.size()), m_target);
    std::fwrite(line.data(), 1, size_t(line.size()), m_target);
    std::fputc('\n', m_target);
    std::fflush(m_target);
}

} // namespace tipscope::cli
