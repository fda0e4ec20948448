// OverviewPage: the whole line at a glance: the station's identity, errors and transformer
// temperature, a PortCard per port (large tip temperatures, setpoints, power, status, errors,
// a sparkline of the last minute, and the robot's controls), and the feeder's state. Shows every
// port, so every port's live values are polled fast while it is open. The cards share the page's
// height, so a larger window gives the sparklines the room. While the line is down everything is
// greyed and a notice at the top says since when the values are old and why the controls are
// off; in monitor-only mode it says that instead. Each card shows its port's last joint.
#pragma once

#include "page.h"

#include "model/joints/jointrecord.h"

#include <QHash>

class QGridLayout;
class QLabel;

namespace tipscope::gui {

class PortCard;

class OverviewPage : public Page {
    Q_OBJECT
public:
    explicit OverviewPage(model::Session &session, QWidget *parent = nullptr);

    [[nodiscard]] QString title() const override { return tr("Overview"); }
    [[nodiscard]] QSet<int> visiblePorts() const override;
    [[nodiscard]] PortCard *card(int port) const { return m_cards.value(port - 1); }
    [[nodiscard]] QString stationText() const;
    // The notice at the top, as shown (empty when hidden).
    [[nodiscard]] QString noticeText() const;

private:
    void rebuild();
    void refreshStation();
    void refreshFeeder();
    void updateWritesAllowed();
    void showJoint(const model::JointRecord &joint);

    QLabel *m_notice;
    QLabel *m_station;
    QLabel *m_stationProblem;
    QLabel *m_feeder;
    QGridLayout *m_grid;
    QWidget *m_cardsHost;
    QList<PortCard *> m_cards;
    QHash<QString, model::JointRecord> m_lastJoints; // by device key and port, across rebuilds
};

} // namespace tipscope::gui
