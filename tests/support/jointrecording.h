// A chart recording of a 4-port station making joints, written as TipScope writes recordings
// (ChartCsvWriter), for the tests that play one recorded stream through a front end.
//
// Every port samples on its own uneven clock (70-130 ms apart) and makes joints of the
// simulator's shapes (sim::JointShape) of every kind the detector must take: shallow and deep,
// quick and slow, exponential and linear, with an overshoot, two on one port within 1.5 s; port 3
// stops answering for a while (a recorded gap); port 4 rests in its stand for a while; a joint is
// still in progress on port 2 when the recording ends. The readings are whole degrees, with a
// wobble of ±1 K between joints.
#pragma once

#include "sim/jointshape.h"

#include <QList>
#include <QString>

namespace tipscope::testing {

struct RecordedJoints {
    QList<sim::SimJoint> made; // the truth, oldest first
    qint64 firstMs = 0;
    qint64 lastMs = 0;
    int samples = 0;
};

// Writes the recording to `path`; false (and `*error`) when it cannot be written.
[[nodiscard]] bool writeJointRecording(const QString &path, RecordedJoints *truth, QString *error);

} // namespace tipscope::testing
