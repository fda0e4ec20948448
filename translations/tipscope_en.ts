<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en" sourcelanguage="en">
<context>
    <name>AgentMain</name>
    <message numerus="yes">
        <location filename="../app/agent/main.cpp" line="42"/>
        <source>site %1, %n line(s) (%2), no MQTT broker: CFX only</source>
        <translation>
            <numerusform>site %1, %n line (%2), no MQTT broker: CFX only</numerusform>
            <numerusform>site %1, %n lines (%2), no MQTT broker: CFX only</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/agent/main.cpp" line="45"/>
        <source>site %1, %n line(s) (%2), broker %3:%4%5 %6</source>
        <translation>
            <numerusform>site %1, %n line (%2), broker %3:%4%5 %6</numerusform>
            <numerusform>site %1, %n lines (%2), broker %3:%4%5 %6</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>CliCommands</name>
    <message numerus="yes">
        <location filename="../app/cli/clicommands.cpp" line="55"/>
        <source>%n raw byte(s), not a frame (%1)</source>
        <translation>
            <numerusform>%n raw byte, not a frame (%1)</numerusform>
            <numerusform>%n raw bytes, not a frame (%1)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>CliMonitorMqtt</name>
    <message numerus="yes">
        <location filename="../app/cli/climonitormqtt.cpp" line="136"/>
        <source>%n device(s), %1 live messages, %2 joints and events forwarded, %3 waiting. %4</source>
        <translation>
            <numerusform>%n device, %1 live messages, %2 joints and events forwarded, %3 waiting. %4</numerusform>
            <numerusform>%n devices, %1 live messages, %2 joints and events forwarded, %3 waiting. %4</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>CliRecord</name>
    <message numerus="yes">
        <location filename="../app/cli/clirecord.cpp" line="178"/>
        <source>recorded %n row(s) to %1</source>
        <translation>
            <numerusform>recorded %n row to %1</numerusform>
            <numerusform>recorded %n rows to %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>EventText</name>
    <message numerus="yes">
        <location filename="../lib/model/events/eventtext.cpp" line="16"/>
        <source>%1 (%n times, until %2)</source>
        <translation>
            <numerusform>%1 (%n time, until %2)</numerusform>
            <numerusform>%1 (%n times, until %2)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>FrameComposer</name>
    <message numerus="yes">
        <location filename="../lib/model/console/framecomposer.cpp" line="214"/>
        <source>%n byte(s), a valid frame: %1</source>
        <translation>
            <numerusform>%n byte, a valid frame: %1</numerusform>
            <numerusform>%n bytes, a valid frame: %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/console/framecomposer.cpp" line="216"/>
        <source>%n byte(s), not a valid frame (%1): sent as typed</source>
        <translation>
            <numerusform>%n byte, not a valid frame (%1): sent as typed</numerusform>
            <numerusform>%n bytes, not a valid frame (%1): sent as typed</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>FrameDecoder</name>
    <message numerus="yes">
        <location filename="../lib/protocol/framedecoder.cpp" line="144"/>
        <source>%n byte(s) outside any frame</source>
        <translation>
            <numerusform>%n byte outside any frame</numerusform>
            <numerusform>%n bytes outside any frame</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>Journal</name>
    <message numerus="yes">
        <location filename="../lib/journal/journalreader.cpp" line="122"/>
        <source>The journal %1 is damaged (%n finding(s), the first: %2).</source>
        <translation>
            <numerusform>The journal %1 is damaged (%n finding, the first: %2).</numerusform>
            <numerusform>The journal %1 is damaged (%n findings, the first: %2).</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>MeasurementReport</name>
    <message numerus="yes">
        <location filename="../lib/model/analysis/measurementreport.cpp" line="52"/>
        <source>… %n more heat-up(s)</source>
        <translation>
            <numerusform>… %n more heat-up</numerusform>
            <numerusform>… %n more heat-ups</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/analysis/measurementreport.cpp" line="70"/>
        <source>… %n more recovery(s)</source>
        <translation>
            <numerusform>… %n more recovery</numerusform>
            <numerusform>… %n more recoveries</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>ProfileApplier</name>
    <message numerus="yes">
        <location filename="../lib/model/profiles/profileapplier.cpp" line="61"/>
        <source>%n difference(s)</source>
        <translation>
            <numerusform>%n difference</numerusform>
            <numerusform>%n differences</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/profiles/profileapplier.cpp" line="53"/>
        <source>%n skipped</source>
        <translation>
            <numerusform>%n skipped</numerusform>
            <numerusform>%n skipped</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RecordingPlayback</name>
    <message numerus="yes">
        <location filename="../lib/model/recording/recordingplayback.cpp" line="105"/>
        <source>the recording %1 played: %n sample(s)</source>
        <translation>
            <numerusform>the recording %1 played: %n sample</numerusform>
            <numerusform>the recording %1 played: %n samples</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RemoteApply</name>
    <message numerus="yes">
        <location filename="../lib/plant/remoteapply.cpp" line="125"/>
        <source>%n setting(s) not taken</source>
        <translation>
            <numerusform>%n setting not taken</numerusform>
            <numerusform>%n settings not taken</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>Session</name>
    <message numerus="yes">
        <location filename="../lib/model/session.cpp" line="241"/>
        <source>%1, %n device(s)</source>
        <translation>
            <numerusform>%1, %n device</numerusform>
            <numerusform>%1, %n devices</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ChartWidget</name>
    <message numerus="yes">
        <location filename="../app/gui/charts/chartwidget.cpp" line="508"/>
        <source>… and %n more</source>
        <translation>
            <numerusform>… and %n more</numerusform>
            <numerusform>… and %n more</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ChartsPage</name>
    <message numerus="yes">
        <location filename="../app/gui/charts/chartspageactions.cpp" line="158"/>
        <source>Replay: %1 (%Ln row(s))</source>
        <translation>
            <numerusform>Replay: %1 (%Ln row)</numerusform>
            <numerusform>Replay: %1 (%Ln rows)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ConsolePage</name>
    <message numerus="yes">
        <location filename="../app/gui/pages/consolepage.cpp" line="383"/>
        <source>paused: %n held</source>
        <translation>
            <numerusform>paused: %n held</numerusform>
            <numerusform>paused: %n held</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tipscope::gui::EventHistoryPanel</name>
    <message numerus="yes">
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="298"/>
        <source>%n older events were dropped</source>
        <translation>
            <numerusform>%n older event was dropped</numerusform>
            <numerusform>%n older events were dropped</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tipscope::gui::JointsPage</name>
    <message numerus="yes">
        <location filename="../app/gui/pages/jointspage.cpp" line="272"/>
        <source>%n joint(s) listed.</source>
        <translation>
            <numerusform>%n joint listed.</numerusform>
            <numerusform>%n joints listed.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pages/jointspage.cpp" line="362"/>
        <source>%n joint(s) written to %1.</source>
        <translation>
            <numerusform>%n joint written to %1.</numerusform>
            <numerusform>%n joints written to %1.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tipscope::gui::MainWindow</name>
    <message numerus="yes">
        <location filename="../app/gui/mainwindow.cpp" line="299"/>
        <source>TipScope — %1 (%n line(s))</source>
        <translation>
            <numerusform>TipScope — %1 (%n line)</numerusform>
            <numerusform>TipScope — %1 (%n lines)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/mainwindowworkspace.cpp" line="123"/>
        <source>Workspace: %1 of %n line(s) connected</source>
        <translation>
            <numerusform>Workspace: %1 of %n line connected</numerusform>
            <numerusform>Workspace: %1 of %n lines connected</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/mainwindowworkspace.cpp" line="133"/>
        <source>the workspace&apos;s %n line(s) are in the tree</source>
        <translation>
            <numerusform>the workspace&apos;s %n line is in the tree</numerusform>
            <numerusform>the workspace&apos;s %n lines are in the tree</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ProfileDialog</name>
    <message numerus="yes">
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="185"/>
        <source>Profile from %1 (%2, software %3), created %4: %n setting(s) differ from the device.</source>
        <translation>
            <numerusform>Profile from %1 (%2, software %3), created %4: %n setting differs from the device.</numerusform>
            <numerusform>Profile from %1 (%2, software %3), created %4: %n settings differ from the device.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="176"/>
        <source>Dry run: %n frame(s) would be sent; nothing was written.</source>
        <translation>
            <numerusform>Dry run: %n frame would be sent; nothing was written.</numerusform>
            <numerusform>Dry run: %n frames would be sent; nothing was written.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="165"/>
        <source>%n setting(s) of the profile skipped: this device does not take them.</source>
        <translation>
            <numerusform>%n setting of the profile skipped: this device does not take it.</numerusform>
            <numerusform>%n settings of the profile skipped: this device does not take them.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tipscope::gui::RecoveryHistogramView</name>
    <message numerus="yes">
        <location filename="../app/gui/pages/jointcharts.cpp" line="70"/>
        <source>Recovery time of %n joint(s)</source>
        <translation>
            <numerusform>Recovery time of %n joint</numerusform>
            <numerusform>Recovery time of %n joints</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pages/jointcharts.cpp" line="73"/>
        <source>%1 (%n did not recover)</source>
        <translation>
            <numerusform>%1 (%n did not recover)</numerusform>
            <numerusform>%1 (%n did not recover)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tipscope::gui::SettingsPage</name>
    <message numerus="yes">
        <location filename="../app/gui/pages/settingspage.cpp" line="372"/>
        <source>✓ Profile saved: %n setting(s) of %1 in %2</source>
        <translation>
            <numerusform>✓ Profile saved: %n setting of %1 in %2</numerusform>
            <numerusform>✓ Profile saved: %n settings of %1 in %2</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tipscope::link::Discovery</name>
    <message numerus="yes">
        <location filename="../lib/link/discovery.cpp" line="100"/>
        <source>%n NAK(s) %1 (%2)</source>
        <translation>
            <numerusform>%n NAK %1 (%2)</numerusform>
            <numerusform>%n NAKs %1 (%2)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/link/discovery.cpp" line="104"/>
        <source>%n answer(s) with a bad block check or format</source>
        <translation>
            <numerusform>%n answer with a bad block check or format</numerusform>
            <numerusform>%n answers with a bad block check or format</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/link/discovery.cpp" line="106"/>
        <source>%n frame(s) from an address not asked</source>
        <translation>
            <numerusform>%n frame from an address not asked</numerusform>
            <numerusform>%n frames from an address not asked</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/link/discovery.cpp" line="108"/>
        <source>%n byte(s) that were no frame</source>
        <translation>
            <numerusform>%n byte that was no frame</numerusform>
            <numerusform>%n bytes that were no frame</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tipscope::link::RequestQueue</name>
    <message numerus="yes">
        <location filename="../lib/link/requestqueue.cpp" line="334"/>
        <source>%1 after %n attempt(s)</source>
        <translation>
            <numerusform>%1 after %n attempt</numerusform>
            <numerusform>%1 after %n attempts</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/link/requestqueue.cpp" line="337"/>
        <source>%n byte(s) of garbage came instead</source>
        <translation>
            <numerusform>%n byte of garbage came instead</numerusform>
            <numerusform>%n bytes of garbage came instead</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tipscope::model::ConsoleSender</name>
    <message numerus="yes">
        <location filename="../lib/model/console/consolesender.cpp" line="69"/>
        <source>%n raw byte(s)</source>
        <translation>
            <numerusform>%n raw byte</numerusform>
            <numerusform>%n raw bytes</numerusform>
        </translation>
    </message>
</context>
</TS>
