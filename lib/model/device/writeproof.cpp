#include "writeproof.h"

#include "link/requestqueue.h"

namespace tipscope::model {

using namespace tipscope::link;
using namespace tipscope::protocol;

bool WriteProof::confirms(const ResolvedCommand &cmd, const Value &written, const Value &read) {
    if (cmd.spec->kind != ValueKind::Flags || written.isText || read.isText)
        return written == read;
    const qint64 w = written.number, r = read.number;
    const bool modeOk = (w % 10 == 0) ? r % 10 == 0 : r % 10 >= w % 10;
    return modeOk && (w / 10) % 10 == (r / 10) % 10;
}

WriteProof *WriteProof::start(RequestQueue &queue, std::optional<int> address,
                              const ResolvedCommand &read, const QByteArray &written,
                              QObject *parent) {
    auto *proof = new WriteProof(queue, address, read, written, parent);
    proof->readBack();
    return proof;
}

WriteProof::WriteProof(RequestQueue &queue, std::optional<int> address, const ResolvedCommand &read,
                       const QByteArray &written, QObject *parent)
    : QObject(parent)
    , m_queue(queue)
    , m_address(address)
    , m_read(read)
    , m_written(written) {}

void WriteProof::readBack() {
    ++m_reads;
    Reply *reply = m_queue.enqueue(Request::read(m_address, m_read), this);
    connect(reply, &Reply::finished, this, [this, reply] {
        reply->deleteLater();
        Result result;
        result.reads = m_reads;
        if (!reply->ok()) {
            result.error = reply->error();
            result.errorString = reply->errorString();
            finish(result);
            return;
        }
        result.reported = reply->answer().data;
        result.ageMs = double(reply->answerAgeUs()) / 1000;
        const auto wrote = decodeAnswer(m_read, m_written);
        const auto read = decodeAnswer(m_read, result.reported);
        result.confirmed = wrote && read && confirms(m_read, *wrote, *read);
        if (!result.confirmed && m_reads == 1 && wrote && read) {
            m_queue.holdForLateAnswer(m_address, m_read.code);
            readBack();
            return;
        }
        finish(result);
    });
}

void WriteProof::finish(const Result &result) {
    Q_EMIT finished(result);
    deleteLater();
}

} // namespace tipscope::model
