// Discovery: finds the devices on a line and identifies them.
//
// In addressed mode it probes the factory addresses first (station 01, feeder 10, extractor 20)
// and, when asked, every other address 00-99; in the mode without addresses it sends one probe
// without addresses; Auto does both. Each probe is R-SMN; a device that answers is identified by
// the family its model name starts with, and asked for its software version (R-SVR) where its
// family has that command. Probes go through the request queue like everything else, so
// discovery can run beside other traffic and is cancelled by deleting it.
#pragma once

#include <QList>
#include <QObject>
#include <optional>

namespace tipscope::link {

class RequestQueue;
class Reply;

struct DeviceInfo {
    std::optional<int> address; // nullopt: the device answers frames without addresses
    QString model;
    QString family; // empty when the model name matches no known family
    QString softwareVersion;

    [[nodiscard]] QString addressText() const; // "01" or "--"
    [[nodiscard]] QString summary() const;     // "01 DME-2C DME 9996780"
};

class Discovery : public QObject {
    Q_OBJECT
public:
    enum class Mode { Auto, Addressed, Unaddressed };

    explicit Discovery(RequestQueue &queue, QObject *parent = nullptr);

    void setMode(Mode mode) { m_mode = mode; }
    void setScanAllAddresses(bool on) { m_scanAll = on; }
    void start();
    [[nodiscard]] bool isRunning() const { return m_outstanding > 0; }
    [[nodiscard]] QList<DeviceInfo> devices() const;

Q_SIGNALS:
    void progress(int done, int total);
    void deviceFound(const tipscope::link::DeviceInfo &device);
    void finished();

private:
    void probe(std::optional<int> address, int slot);
    void identify(int slot);
    void settle();

    RequestQueue &m_queue;
    Mode m_mode = Mode::Auto;
    bool m_scanAll = false;
    QList<std::optional<DeviceInfo>> m_found; // by probe slot, to keep probe order
    int m_outstanding = 0;
    int m_done = 0;
    int m_total = 0;
};

} // namespace tipscope::link
