// PrefixedOutput: a write-only device that passes what it is given to a standard stream in whole
// lines, each prefixed ("[cell-3] "), so the lines of several threads writing at once never mix.
// A last line without its newline comes out when the device is closed or destroyed.
#pragma once

#include <QIODevice>
#include <cstdio>

namespace tipscope::cli {

class PrefixedOutput : public QIODevice {
public:
    PrefixedOutput(const QString &prefix, std::FILE *target);
    ~PrefixedOutput() override;
    void close() override;

protected:
    qint64 readData(char *, qint64) override { return -1; }
    qint64 writeData(const char *data, qint64 size) override;

private:
    void emitLine(QByteArrayView line);

    QByteArray m_prefix;
    QByteArray m_pending;
    std::FILE *m_target;
};

} // namespace tipscope::cli
