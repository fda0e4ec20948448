// PrefixedOutput: a write-only device that passes what it is given to a standard stream in whole
// lines, each prefixed ("[cell-3] "), so the lines of several threads writing at once never mix.
// A last line without its newline comes out when the device is closed or destroyed. Asked to, it
// also keeps what it passed on (without the prefix), for a summary that quotes it.
#pragma once

#include <QIODevice>
#include <cstdio>

namespace tipscope::cli {

class PrefixedOutput : public QIODevice {
public:
    enum class Keep { Nothing, Text };
    PrefixedOutput(const QString &prefix, std::FILE *target, Keep keep = Keep::Nothing);
    ~PrefixedOutput() override;
    void close() override;
    // The lines passed on so far, when kept.
    [[nodiscard]] QString keptText() const { return QString::fromUtf8(m_kept); }

protected:
    qint64 readData(char *, qint64) override { return -1; }
    qint64 writeData(const char *data, qint64 size) override;

private:
    void emitLine(QByteArrayView line);

    QByteArray m_prefix;
    QByteArray m_pending;
    std::FILE *m_target;
    Keep m_keep;
    QByteArray m_kept;
};

} // namespace tipscope::cli
