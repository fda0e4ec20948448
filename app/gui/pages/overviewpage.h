// OverviewPage: the whole line at a glance: the station's identity, errors and transformer
// temperature, a PortCard per port (large tip temperatures, setpoints, power, status, errors,
// and the robot's controls), and the feeder's state. Shows every port, so every port's live
// values are polled fast while it is open.
#pragma once

#include "page.h"

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

private:
    void rebuild();
    void refreshStation();
    void refreshFeeder();
    void updateWritesAllowed();

    QLabel *m_station;
    QLabel *m_stationProblem;
    QLabel *m_feeder;
    QGridLayout *m_grid;
    QWidget *m_cardsHost;
    QList<PortCard *> m_cards;
};

} // namespace tipscope::gui
