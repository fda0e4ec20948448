// A simulated line wired to the real link stack: SimLine -> SimTransport -> Line/RequestQueue,
// and device models on top, as demo mode builds them.
#pragma once

#include "link/line.h"
#include "link/simtransport.h"
#include "model/device/feedermodel.h"
#include "model/device/stationmodel.h"
#include "sim/simline.h"

#include <QSignalSpy>
#include <QTest>
#include <memory>

namespace tipscope::testing {

struct SimFixture {
    std::unique_ptr<sim::SimLine> simLine;
    std::unique_ptr<link::Line> line;
    link::SimTransport *transport = nullptr;

    explicit SimFixture(std::unique_ptr<sim::SimLine> sl)
        : simLine(std::move(sl)) {
        link::LineSettings settings;
        settings.kind = link::LineSettings::Kind::Demo;
        auto t = std::make_unique<link::SimTransport>(*simLine);
        transport = t.get();
        line = std::make_unique<link::Line>(std::move(t), settings);
        line->open();
        QTRY_VERIFY(line->state() == link::Line::State::Open);
    }

    static link::DeviceInfo infoOf(const sim::SimDevice &d) {
        link::DeviceInfo i;
        if (d.isAddressed())
            i.address = d.address();
        i.model = d.modelName();
        i.family = d.family().name;
        i.softwareVersion = d.softwareVersion();
        return i;
    }

    std::unique_ptr<model::StationModel> station(int index = 0) {
        return std::make_unique<model::StationModel>(line->queue(),
                                                     infoOf(*simLine->devices().at(index)));
    }
    std::unique_ptr<model::FeederModel> feeder() {
        return std::make_unique<model::FeederModel>(line->queue(), infoOf(*simLine->feeder()));
    }

    // Waits until every request in the queue is done.
    void settle(int timeoutMs = 20000) {
        QTRY_VERIFY_WITH_TIMEOUT(line->queue().pendingCount() == 0, timeoutMs);
    }
};

// The wire codes of parameters, in their order: what a list holds, in the guides' words.
inline QList<QByteArray> codesOf(const QList<model::Parameter *> &parameters) {
    QList<QByteArray> codes;
    for (const model::Parameter *p : parameters)
        codes.append(p->code());
    return codes;
}

inline std::unique_ptr<sim::SimLine> singleDevice(const QString &family) {
    auto l = std::make_unique<sim::SimLine>();
    if (family == QLatin1String("SFR"))
        l->addDevice(std::make_unique<sim::SimFeeder>());
    else
        l->addDevice(std::make_unique<sim::SimStation>(family));
    return l;
}

} // namespace tipscope::testing
