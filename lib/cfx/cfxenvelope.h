// The IPC-CFX envelope and the AMQP 1.0 message that carries it, as the IPC's SDK writes them
// (CFX/CFXEnvelope.cs, CFX/Transport/AmqpUtilities.cs), so that an MES built on the SDK reads
// TipScope like any other machine. Plain values, no transport: the sender (amqpsender.h) copies an
// AmqpMessage into a Proton message field by field, and the tests read both without a broker.
//
// A message name is the SDK's full class name ("CFX.ResourcePerformance.FaultOccurred"); the body
// is written with the SDK's "$type" ("CFX.ResourcePerformance.FaultOccurred, CFX") first, as
// Newtonsoft writes a body declared `object`. Times are UTC ISO 8601 with milliseconds; a period
// is .NET's TimeSpan text ("00:01:00"). The UniqueID is chosen by the caller: a message made from
// a journal record takes the record's id, so a message sent again is the same message.
#pragma once

#include "base/outcome.h"

#include <QByteArray>
#include <QDateTime>
#include <QJsonObject>
#include <QJsonValue>
#include <QMap>
#include <QString>
#include <QUuid>

namespace tipscope::cfx {

// The SDK's CFXEnvelope.CFXVERSION, the version this endpoint speaks.
inline constexpr char kCfxVersion[] = "2.1";
inline constexpr char kContentType[] = "application/json; charset=\"utf-8\"";
// A request larger than this is refused before it is parsed: no CFX request comes near it.
inline constexpr qsizetype kMaxRequestBytes = 256 * 1024;

struct Envelope {
    QString messageName;
    QDateTime timeStamp;
    QUuid uniqueId;
    QString source;    // the sender's CFX handle
    QString target;    // empty: a broadcast (null in JSON)
    QString requestId; // empty: not an answer (null in JSON)
    QJsonObject body;  // the message's fields, without "$type"

    [[nodiscard]] QJsonObject toJson() const;
    [[nodiscard]] QByteArray toBytes() const; // compact UTF-8 JSON
    // A received envelope (a request on the endpoint's queue): bounded, and every envelope field
    // of the right kind, or a failure naming what is wrong.
    [[nodiscard]] static base::Outcome<Envelope> fromBytes(const QByteArray &bytes);
};

// How the body of an AMQP message is encoded (the SDK's CFXCodec).
enum class Codec { Raw, Gzip };

// What the SDK puts into an AMQP message besides the body.
struct AmqpMessage {
    QByteArray body; // one Data section
    QString messageId;
    QString to;            // the envelope's Target; empty: none
    QString replyTo;       // the envelope's Source
    QString correlationId; // the envelope's RequestID; empty: none
    QString contentType;
    QString contentEncoding; // "gzip" or empty
    QString subject;         // {Source}.{MessageName}
    qint64 creationTimeMs = 0;
    bool durable = true;
    // cfx-topic, cfx-message, cfx-handle, cfx-target; a null QString is written as AMQP null.
    QMap<QString, QString> applicationProperties;
};

// A message taken from an endpoint's request queue, as it came.
struct AmqpRequest {
    QByteArray body;
    QString contentEncoding;
    QString messageId;
    QString replyTo;
};

[[nodiscard]] AmqpMessage toAmqpMessage(const Envelope &envelope, Codec codec);
// The envelope inside a received body, unpacked first when its encoding is "gzip".
[[nodiscard]] base::Outcome<Envelope> envelopeFromAmqp(const QByteArray &body,
                                                       const QString &contentEncoding);

// "CFX.ResourcePerformance.FaultOccurred" → "CFX.ResourcePerformance.FaultOccurred, CFX".
[[nodiscard]] QString sdkTypeName(const QString &messageName);
// The message's namespace, the SDK's cfx-topic: "CFX.ResourcePerformance".
[[nodiscard]] QString cfxTopic(const QString &messageName);
// A time as the SDK's JSON writes a UTC DateTime.
[[nodiscard]] QString cfxDateTime(const QDateTime &time);
// A duration as .NET's TimeSpan text: "00:01:00", "00:00:25.1230000", "1.02:03:04".
[[nodiscard]] QString cfxTimeSpan(qint64 ms);
// A field the SDK writes as null (Newtonsoft writes every null property).
inline const QJsonValue kCfxNull{QJsonValue::Null};
// A text as the SDK writes it: null when empty.
[[nodiscard]] QJsonValue cfxText(const QString &text);

// gzip (RFC 1952) as the SDK's GZipStream writes and reads it.
[[nodiscard]] QByteArray gzip(const QByteArray &data);
// Refuses a damaged stream and one that unpacks to more than `maxBytes`.
[[nodiscard]] base::Outcome<QByteArray> gunzip(const QByteArray &data, qsizetype maxBytes);

} // namespace tipscope::cfx
