// Discovery: finds the devices on a line and identifies them; the one place that does.
//
// start() searches both ways: it probes the factory addresses (station 01, feeder 10, extractor
// 20) and, when asked, every other address 00-99, and sends one probe without addresses.
// identify() asks one named device (any address, or the device without addresses; what a line
// set to one way of addressing asks) and reports why it could not be identified. Each
// probe asks the catalog's model-name command (R-SMN); a device that answers is identified by the
// family its model name starts with, and asked for its software version (R-SVR) where its family
// has that command. A search probe is tried twice and its silence is normal; identify() asks as
// firmly as any read (the queue's retries), since the device was named, and gives each attempt
// at least kNamedDeviceTurnaroundMs: a device that answers late (a loaded PC, a converter that
// wakes up with the line) is still found, an absent one costs a second more. A search probe
// whose answers all came after it gave up (they arrive as frames nobody asked, from its address)
// has found a device all the same: it is asked again with the same patience. Requests go through
// the request queue like everything else, so discovery runs beside other traffic and is cancelled
// by deleting it. finished() is emitted once per start() or identify().
#pragma once

#include "frametap.h"
#include "linkstats.h"
#include "reply.h"
#include "requestqueue.h"

#include "base/outcome.h"

#include <QHash>
#include <QList>
#include <QObject>
#include <QSet>
#include <optional>

namespace tipscope::protocol {
struct ResolvedCommand;
} // namespace tipscope::protocol

namespace tipscope::link {

class Reply;

struct DeviceInfo {
    std::optional<int> address; // nullopt: the device answers frames without addresses
    QString model;
    QString family; // empty when the model name matches no known family
    QString softwareVersion;

    [[nodiscard]] QString addressText() const; // "01" or "--"
    [[nodiscard]] QString summary() const;     // "01 DME-2C DME 9996780"
};

// Why identify() could not name the device.
struct IdentifyFailure {
    enum class Kind {
        NoModelNameCommand, // the catalog names no command that identifies a device
        Unanswered,         // the model-name request failed: replyError says how
        UnknownModel,       // it answered with a model name of no known family
    };
    Kind kind = Kind::Unanswered;
    ReplyError replyError = ReplyError::None; // for Unanswered: Timeout, Nak, Corrupted, ...
    QString reason;                           // for Unanswered: the reply's error text
    QString model;                            // for UnknownModel: the name it gave
    QByteArray command;                       // the model-name command asked (R-SMN)

    // Why the device at `address` (none: the device without addresses) is not identified, in
    // the user's language: the one wording the window, the command line and the agent show.
    [[nodiscard]] QString text(std::optional<int> address) const;
};

using Identification = base::Outcome<DeviceInfo, IdentifyFailure>;

class Discovery : public QObject {
    Q_OBJECT
public:
    static constexpr int kNamedDeviceTurnaroundMs = 500;

    explicit Discovery(RequestQueue &queue, QObject *parent = nullptr);

    void setScanAllAddresses(bool on) { m_scanAll = on; }
    void start();
    // Identifies the one device at `address` (nullopt: the device without addresses). On
    // success devices() holds it; identification() says either way once finished() came.
    void identify(std::optional<int> address);
    [[nodiscard]] bool isRunning() const { return m_outstanding > 0; }
    [[nodiscard]] QList<DeviceInfo> devices() const;
    // What the line brought back since the last start() or identify() that named no device, in
    // words: NAKs by code, answers with a bad block check or format, frames from an address not
    // asked, bytes that were no frame. Empty when the line stayed silent, which is the one case
    // where the cable is the first thing to check.
    [[nodiscard]] QString whatCameBack() const;
    // The result of the last identify(); unset while it runs or after start().
    [[nodiscard]] const std::optional<Identification> &identification() const {
        return m_identification;
    }

Q_SIGNALS:
    void progress(int done, int total);
    void deviceFound(const tipscope::link::DeviceInfo &device);
    void finished();

private:
    void begin(int probes);
    void probe(std::optional<int> address, int slot);
    void take(const Reply &reply, std::optional<int> address, int slot);
    void askVersion(int slot, const protocol::ResolvedCommand &version);
    void settle();
    [[nodiscard]] Identification identificationOf(const std::optional<DeviceInfo> &found) const;
    // A frame nobody asked for during a search: a probe's late answer names a device there.
    void onTap(const TapEvent &event);
    // The model-name read every probe sends; `patient` waits as long as for a named device.
    // None when the catalog has no model-name command.
    [[nodiscard]] static std::optional<Request> modelNameRequest(std::optional<int> address,
                                                                 bool patient);
    void askAgain(int address);

    RequestQueue &m_queue;
    bool m_scanAll = false;
    QList<std::optional<DeviceInfo>> m_found; // by probe slot, to keep probe order
    int m_outstanding = 0;
    int m_done = 0;
    int m_total = 0;
    bool m_named = false; // identify(): one device was named, its failure is reported
    std::optional<IdentifyFailure> m_failure;
    QByteArray m_asked; // the model-name request, "R-SMN", for the failure's words
    std::optional<Identification> m_identification;
    LinkStats m_statsAtBegin;     // the queue's, to tell what this search brought back
    QHash<int, int> m_unanswered; // a search's probes that got no answer: address → slot
    QSet<int> m_heardLate;        // addresses whose model name came after their probe gave up
    QSet<int> m_askedAgain;
    QMetaObject::Connection m_tap;
};

} // namespace tipscope::link
