// FrameTap: every byte on the wire as it happened, for the raw frame console.
//
// The request queue reports each TX chunk, each RX chunk, and each decode event (a good frame,
// with whether it answered a request or was stray, or an error) with wall-clock and monotonic
// timestamps. The tap only forwards: keeping history and filtering belong to the console model.
#pragma once

#include "protocol/framedecoder.h"

#include <QObject>

namespace tipscope::link {

struct TapEvent {
    enum class Kind { Tx, Rx, Decoded, Note };
    Kind kind = Kind::Tx;
    qint64 wallMs = 0;      // ms since the epoch
    qint64 monotonicUs = 0; // for relative time
    QByteArray bytes;       // Tx/Rx
    protocol::DecodeEvent decoded;
    bool stray = false; // a decoded frame that answered nothing
    QString note;       // Note: line state changes, timeouts
};

class FrameTap : public QObject {
    Q_OBJECT
public:
    using QObject::QObject;
    void tx(const QByteArray &bytes);
    void rx(const QByteArray &bytes);
    void decoded(const protocol::DecodeEvent &event, bool stray);
    void note(const QString &text);

Q_SIGNALS:
    void event(const tipscope::link::TapEvent &event);

private:
    void emitEvent(TapEvent e);
};

} // namespace tipscope::link
