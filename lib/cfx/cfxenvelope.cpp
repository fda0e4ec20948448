#include "cfxenvelope.h"

#include <QCoreApplication>
#include <QJsonDocument>
#include <zlib.h>

namespace tipscope::cfx {

using base::failure;
using base::Outcome;

namespace {

struct CfxTr {
    Q_DECLARE_TR_FUNCTIONS(Cfx)
};

const QString kType = QStringLiteral("$type");

// A field that is absent or null reads as empty; one of another kind is refused.
Outcome<QString> optionalText(const QJsonObject &json, const QString &name) {
    const QJsonValue value = json.value(name);
    if (value.isUndefined() || value.isNull())
        return QString();
    if (!value.isString())
        return failure(CfxTr::tr("The CFX envelope's %1 is not a text.").arg(name));
    return value.toString();
}

} // namespace

QString sdkTypeName(const QString &messageName) {
    return messageName + QStringLiteral(", CFX");
}

QString cfxTopic(const QString &messageName) {
    return messageName.left(messageName.lastIndexOf(QLatin1Char('.')));
}

QString cfxDateTime(const QDateTime &time) {
    return time.toUTC().toString(Qt::ISODateWithMs);
}

QJsonValue cfxText(const QString &text) {
    return text.isEmpty() ? QJsonValue(QJsonValue::Null) : QJsonValue(text);
}

QString cfxTimeSpan(qint64 ms) {
    const qint64 days = ms / 86400000;
    const qint64 hours = ms / 3600000 % 24, minutes = ms / 60000 % 60, seconds = ms / 1000 % 60;
    QString text = QStringLiteral("%1:%2:%3")
                       .arg(hours, 2, 10, QLatin1Char('0'))
                       .arg(minutes, 2, 10, QLatin1Char('0'))
                       .arg(seconds, 2, 10, QLatin1Char('0'));
    if (days > 0)
        text.prepend(QStringLiteral("%1.").arg(days));
    if (ms % 1000 != 0) // .NET writes seven digits of ticks when there is a fraction
        text += QStringLiteral(".%1").arg((ms % 1000) * 10000, 7, 10, QLatin1Char('0'));
    return text;
}

QJsonObject Envelope::toJson() const {
    QJsonObject typed{{kType, sdkTypeName(messageName)}};
    for (auto it = body.begin(); it != body.end(); ++it)
        typed.insert(it.key(), it.value());
    return {{QStringLiteral("MessageName"), messageName},
            {QStringLiteral("Version"), QString::fromLatin1(kCfxVersion)},
            {QStringLiteral("TimeStamp"), cfxDateTime(timeStamp)},
            {QStringLiteral("UniqueID"), uniqueId.toString(QUuid::WithoutBraces)},
            {QStringLiteral("Source"), cfxText(source)},
            {QStringLiteral("Target"), cfxText(target)},
            {QStringLiteral("RequestID"), cfxText(requestId)},
            {QStringLiteral("MessageBody"), typed}};
}

QByteArray Envelope::toBytes() const {
    return QJsonDocument(toJson()).toJson(QJsonDocument::Compact);
}

Outcome<Envelope> Envelope::fromBytes(const QByteArray &bytes) {
    if (bytes.size() > kMaxRequestBytes)
        return failure(CfxTr::tr("A CFX message of %1 bytes is larger than the %2 accepted.")
                           .arg(bytes.size())
                           .arg(kMaxRequestBytes));
    QJsonParseError error;
    const QJsonDocument document = QJsonDocument::fromJson(bytes, &error);
    if (!document.isObject())
        return failure(CfxTr::tr("A CFX message is not a JSON object: %1.")
                           .arg(error.error == QJsonParseError::NoError ? CfxTr::tr("not an object")
                                                                        : error.errorString()));
    const QJsonObject json = document.object();
    Envelope envelope;
    for (const auto &[name, field] :
         {std::pair{QStringLiteral("MessageName"), &envelope.messageName},
          std::pair{QStringLiteral("Source"), &envelope.source},
          std::pair{QStringLiteral("Target"), &envelope.target},
          std::pair{QStringLiteral("RequestID"), &envelope.requestId}}) {
        const auto text = optionalText(json, name);
        if (!text)
            return failure(text.error());
        *field = *text;
    }
    if (envelope.messageName.isEmpty())
        return failure(CfxTr::tr("A CFX message has no MessageName."));
    const auto unique = optionalText(json, QStringLiteral("UniqueID"));
    if (!unique)
        return failure(unique.error());
    envelope.uniqueId = QUuid::fromString(*unique);
    const auto stamp = optionalText(json, QStringLiteral("TimeStamp"));
    if (!stamp)
        return failure(stamp.error());
    envelope.timeStamp = QDateTime::fromString(*stamp, Qt::ISODateWithMs);
    const QJsonValue body = json.value(QStringLiteral("MessageBody"));
    if (!body.isObject() && !body.isNull() && !body.isUndefined())
        return failure(CfxTr::tr("The CFX envelope's MessageBody is not an object."));
    envelope.body = body.toObject();
    envelope.body.remove(kType);
    return envelope;
}

AmqpMessage toAmqpMessage(const Envelope &envelope, Codec codec) {
    AmqpMessage message;
    const QByteArray json = envelope.toBytes();
    message.body = codec == Codec::Gzip ? gzip(json) : json;
    message.contentEncoding = codec == Codec::Gzip ? QStringLiteral("gzip") : QString();
    message.messageId = envelope.uniqueId.toString(QUuid::WithoutBraces);
    message.to = envelope.target;
    message.replyTo = envelope.source;
    message.correlationId = envelope.requestId;
    message.contentType = QString::fromLatin1(kContentType);
    message.creationTimeMs = envelope.timeStamp.toMSecsSinceEpoch();
    message.subject = envelope.source + QLatin1Char('.') + envelope.messageName;
    message.applicationProperties = {
        {QStringLiteral("cfx-topic"), cfxTopic(envelope.messageName)},
        {QStringLiteral("cfx-message"), envelope.messageName},
        {QStringLiteral("cfx-handle"), envelope.source},
        {QStringLiteral("cfx-target"), envelope.target.isEmpty() ? QString() : envelope.target}};
    return message;
}

Outcome<Envelope> envelopeFromAmqp(const QByteArray &body, const QString &contentEncoding) {
    if (contentEncoding.compare(QLatin1String("gzip"), Qt::CaseInsensitive) != 0)
        return Envelope::fromBytes(body);
    const auto unpacked = gunzip(body, kMaxRequestBytes);
    if (!unpacked)
        return failure(unpacked.error());
    return Envelope::fromBytes(*unpacked);
}

QByteArray gzip(const QByteArray &data) {
    z_stream stream{};
    constexpr int kGzipWindow = 15 + 16; // zlib's way of asking for a gzip header and trailer
    if (deflateInit2(&stream, Z_DEFAULT_COMPRESSION, Z_DEFLATED, kGzipWindow, 8,
                     Z_DEFAULT_STRATEGY) != Z_OK)
        return {};
    QByteArray out(int(deflateBound(&stream, uLong(data.size()))) + 32, Qt::Uninitialized);
    stream.next_in = reinterpret_cast<Bytef *>(const_cast<char *>(data.data()));
    stream.avail_in = uInt(data.size());
    stream.next_out = reinterpret_cast<Bytef *>(out.data());
    stream.avail_out = uInt(out.size());
    const int rc = deflate(&stream, Z_FINISH);
    out.resize(qsizetype(stream.total_out));
    deflateEnd(&stream);
    return rc == Z_STREAM_END ? out : QByteArray();
}

Outcome<QByteArray> gunzip(const QByteArray &data, qsizetype maxBytes) {
    z_stream stream{};
    if (inflateInit2(&stream, 15 + 16) != Z_OK)
        return failure(CfxTr::tr("Cannot unpack a gzip CFX message."));
    stream.next_in = reinterpret_cast<Bytef *>(const_cast<char *>(data.data()));
    stream.avail_in = uInt(data.size());
    QByteArray out;
    char chunk[16384];
    int rc = Z_OK;
    while (rc == Z_OK) {
        stream.next_out = reinterpret_cast<Bytef *>(chunk);
        stream.avail_out = sizeof chunk;
        rc = inflate(&stream, Z_NO_FLUSH);
        out.append(chunk, qsizetype(sizeof chunk - stream.avail_out));
        if (out.size() > maxBytes)
            rc = Z_BUF_ERROR;
    }
    inflateEnd(&stream);
    if (rc != Z_STREAM_END)
        return failure(
            CfxTr::tr("A gzip CFX message is damaged or larger than %1 bytes.").arg(maxBytes));
    return out;
}

} // namespace tipscope::cfx
