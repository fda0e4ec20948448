// Unix signals as Qt signals: SIGHUP (reload), SIGTERM and SIGINT (stop). The handler only writes
// a byte to a socket pair, the one thing a signal handler may safely do; a QSocketNotifier reads
// it on the event loop, where the work is done. One instance per process.
#pragma once

#include <QObject>

class QSocketNotifier;

namespace tipscope::agent {

class UnixSignals : public QObject {
    Q_OBJECT
public:
    explicit UnixSignals(QObject *parent = nullptr);
    ~UnixSignals() override;

Q_SIGNALS:
    void reloadRequested();
    void stopRequested();

private:
    void onReadable();

    QSocketNotifier *m_notifier = nullptr;
};

} // namespace tipscope::agent
