// WriteProof: the one proof that a device took a written value, used by Parameter (the window,
// the agent's remote apply, profiles) and by the CLI's `write` alike.
//
// The value is read back and compared with what was written; flags digit by digit, as a port sent
// to the stand may have moved on to sleep or hibernation by the time it is read. Frames carry no
// sequence number, so a read-back that differs may be the late answer of an earlier read, from
// before the write: it is read once more, after the window in which such an answer could still
// arrive (RequestQueue::holdForLateAnswer), and only that second answer decides.
#pragma once

#include "link/reply.h"
#include "protocol/catalog.h"

#include <QObject>
#include <optional>

namespace tipscope::link {
class RequestQueue;
}

namespace tipscope::model {

class WriteProof : public QObject {
    Q_OBJECT
public:
    struct Result {
        bool confirmed = false;
        // The device's answer to the read that decided; empty when no read was answered.
        QByteArray reported;
        double ageMs = 0; // how old the reported value was when its answer was taken
        int reads = 0;
        // Why no read was answered (None when one was).
        link::ReplyError error = link::ReplyError::None;
        QString errorString;
    };

    // Whether the value read proves that `written` was taken (both decoded with `cmd`, the read
    // command).
    [[nodiscard]] static bool confirms(const protocol::ResolvedCommand &cmd,
                                       const protocol::Value &written, const protocol::Value &read);

    // Reads `read` back from the device at `address` and proves `written` (a write's data field)
    // against it; finished() says the result once, and the proof deletes itself after that.
    static WriteProof *start(link::RequestQueue &queue, std::optional<int> address,
                             const protocol::ResolvedCommand &read, const QByteArray &written,
                             QObject *parent = nullptr);

Q_SIGNALS:
    void finished(const tipscope::model::WriteProof::Result &result);

private:
    WriteProof(link::RequestQueue &queue, std::optional<int> address,
               const protocol::ResolvedCommand &read, const QByteArray &written, QObject *parent);
    void readBack();
    void finish(const Result &result);

    link::RequestQueue &m_queue;
    std::optional<int> m_address;
    protocol::ResolvedCommand m_read;
    QByteArray m_written;
    int m_reads = 0;
};

} // namespace tipscope::model

Q_DECLARE_METATYPE(tipscope::model::WriteProof::Result)
