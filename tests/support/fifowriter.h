// FifoWriter: a FIFO in a temporary folder and a thread writing into it, for the tests that
// read recordings from FIFOs (what a size check before reading cannot bound). Unix only.
#pragma once

#include <QtGlobal>

#ifdef Q_OS_UNIX
#include <QByteArray>
#include <QFile>
#include <QTemporaryDir>
#include <atomic>
#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>

// A FIFO in `dir` and a thread writing `content` into it, then holding it open until released:
// the reader sees data arrive, then nothing, never the end unless `close` is set.
class FifoWriter {
public:
    FifoWriter(const QTemporaryDir &dir, QByteArray content, bool close)
        : m_path(dir.filePath(QStringLiteral("fifo.csv"))) {
        ::signal(SIGPIPE, SIG_IGN); // the reader may close first: write() fails, no signal
        m_ok = ::mkfifo(QFile::encodeName(m_path).constData(), 0600) == 0;
        if (m_ok)
            m_thread = std::thread([this, content, close] { run(content, close); });
    }
    ~FifoWriter() {
        m_release = true;
        if (!m_thread.joinable())
            return;
        // A writer still waiting in open() for a reader gets one, and one in write() gets its
        // data taken, until it has noticed the release.
        const int fd = ::open(QFile::encodeName(m_path).constData(), O_RDONLY | O_NONBLOCK);
        char sink[65536];
        while (!m_done) {
            if (fd < 0 || ::read(fd, sink, sizeof sink) <= 0)
                std::this_thread::sleep_for(std::chrono::milliseconds(1));
        }
        m_thread.join();
        if (fd >= 0)
            ::close(fd);
    }
    [[nodiscard]] bool ok() const { return m_ok; }
    [[nodiscard]] const QString &path() const { return m_path; }
    [[nodiscard]] qint64 written() const { return m_written; }

private:
    void run(const QByteArray &content, bool close) {
        const int fd = ::open(QFile::encodeName(m_path).constData(), O_WRONLY);
        if (fd < 0) {
            m_done = true;
            return;
        }
        // In pieces, so that a release is noticed between them.
        for (qint64 at = 0; at < content.size() && !m_release;) {
            const size_t piece = size_t(qMin<qint64>(content.size() - at, 65536));
            const ssize_t n = ::write(fd, content.constData() + at, piece);
            if (n <= 0)
                break;
            at += n;
            m_written = at;
        }
        while (!close && !m_release)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
        ::close(fd);
        m_done = true;
    }

    QString m_path;
    bool m_ok = false;
    std::atomic<bool> m_release{false};
    std::atomic<bool> m_done{false};
    std::atomic<qint64> m_written{0};
    std::thread m_thread;
};
#endif
