#include "frametap.h"

#include <QDateTime>
#include <QElapsedTimer>
#include <QMetaMethod>

namespace tipscope::link {

static qint64 monotonicUs() {
    static QElapsedTimer clock = [] {
        QElapsedTimer t;
        t.start();
        return t;
    }();
    return clock.nsecsElapsed() / 1000;
}

void FrameTap::emitEvent(TapEvent e) {
    if (!isSignalConnected(QMetaMethod::fromSignal(&FrameTap::event)))
        return; // nobody watches: keep the hot path free
    e.wallMs = QDateTime::currentMSecsSinceEpoch();
    e.monotonicUs = monotonicUs();
    Q_EMIT event(e);
}

void FrameTap::tx(const QByteArray &bytes) {
    TapEvent e;
    e.kind = TapEvent::Kind::Tx;
    e.bytes = bytes;
    emitEvent(std::move(e));
}

void FrameTap::rx(const QByteArray &bytes) {
    TapEvent e;
    e.kind = TapEvent::Kind::Rx;
    e.bytes = bytes;
    emitEvent(std::move(e));
}

void FrameTap::decoded(const protocol::DecodeEvent &event, bool stray) {
    TapEvent e;
    e.kind = TapEvent::Kind::Decoded;
    e.decoded = event;
    e.stray = stray;
    emitEvent(std::move(e));
}

void FrameTap::note(const QString &text) {
    TapEvent e;
    e.kind = TapEvent::Kind::Note;
    e.note = text;
    emitEvent(std::move(e));
}

} // namespace tipscope::link
