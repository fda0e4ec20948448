<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE" sourcelanguage="en">
<context>
    <name>Action</name>
    <message>
        <location filename="../lib/model/device/action.cpp" line="28"/>
        <source>monitor-only mode is on: nothing is written</source>
        <translation>der Modus „Nur beobachten“ ist aktiv: es wird nichts geschrieben</translation>
    </message>
    <message>
        <location filename="../lib/model/device/action.cpp" line="30"/>
        <source>%1 needs an explicit confirmation: %2</source>
        <translation>%1 erfordert eine ausdrückliche Bestätigung: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/action.cpp" line="32"/>
        <source>%1 is already running</source>
        <translation>%1 läuft bereits</translation>
    </message>
    <message>
        <location filename="../lib/model/device/action.cpp" line="43"/>
        <source>%1 done</source>
        <translation>%1 erledigt</translation>
    </message>
</context>
<context>
    <name>AgentConfig</name>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="38"/>
        <source>%1 must be text</source>
        <translation>%1 muss ein Text sein</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="47"/>
        <source>%1 must be a whole number from %2 to %3</source>
        <translation>%1 muss eine ganze Zahl von %2 bis %3 sein</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="58"/>
        <source>%1 must be true or false</source>
        <translation>%1 muss true oder false sein</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="64"/>
        <source>%1 must be an object</source>
        <translation>%1 muss ein Objekt sein</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="82"/>
        <source>not a TipScope agent configuration (&quot;format&quot; is not &quot;%1&quot;)</source>
        <translation>keine Konfiguration des TipScope-Agenten (&quot;format&quot; ist nicht &quot;%1&quot;)</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="87"/>
        <source>&quot;version&quot; must be a whole number from 1</source>
        <translation>&quot;version&quot; muss eine ganze Zahl ab 1 sein</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="90"/>
        <source>written for a later TipScope (version %1); this one reads version %2 and older</source>
        <translation>für ein neueres TipScope geschrieben (Version %1); dieses liest Version %2 und ältere</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="118"/>
        <source>broker.protocol must be &quot;3.1.1&quot; or &quot;5&quot;</source>
        <translation>broker.protocol muss &quot;3.1.1&quot; oder &quot;5&quot; sein</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="130"/>
        <source>broker.host must name the broker</source>
        <translation>broker.host muss den Broker nennen</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="133"/>
        <source>broker.password_file and broker.password_env: give one of them</source>
        <translation>broker.password_file und broker.password_env: nur eines von beiden angeben</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="148"/>
        <source>file %1</source>
        <translation>Datei %1</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="154"/>
        <source>environment variable %1</source>
        <translation>Umgebungsvariable %1</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="188"/>
        <source>cfx.host must name the AMQP broker</source>
        <translation>cfx.host muss den AMQP-Broker nennen</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="190"/>
        <source>cfx.address must be /exchange/NAME, /exchange/NAME/KEY or /queue/NAME, not &quot;%1&quot;</source>
        <translation>cfx.address muss /exchange/NAME, /exchange/NAME/KEY oder /queue/NAME sein, nicht „%1“</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="194"/>
        <source>cfx.request_address must be a queue, /queue/NAME, not &quot;%1&quot;</source>
        <translation>cfx.request_address muss eine Warteschlange sein, /queue/NAME, nicht „%1“</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="197"/>
        <source>cfx.vendor must be a name of at most %1 characters</source>
        <translation>cfx.vendor muss ein Name mit höchstens %1 Zeichen sein</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="200"/>
        <source>cfx.tls.cert_file and cfx.tls.key_file: give both or neither</source>
        <translation>cfx.tls.cert_file und cfx.tls.key_file: beide oder keines angeben</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="202"/>
        <source>cfx.password_file and cfx.password_env: give one of them</source>
        <translation>cfx.password_file und cfx.password_env: nur eines von beiden angeben</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="230"/>
        <source>broker is false: then a cfx section must say where the lines are published</source>
        <translation>broker ist false: dann muss ein cfx-Abschnitt sagen, wohin die Linien veröffentlicht werden</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="233"/>
        <source>site must name the site</source>
        <translation>site muss den Standort nennen</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="235"/>
        <source>site must be at most %1 characters long, not %2</source>
        <translation>site darf höchstens %1 Zeichen lang sein, nicht %2</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="240"/>
        <source>site must not hold control characters</source>
        <translation>site darf keine Steuerzeichen enthalten</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="242"/>
        <source>workspace must name the workspace file of the lines to run</source>
        <translation>workspace muss die Arbeitsbereichsdatei der zu betreibenden Linien nennen</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="271"/>
        <source>cannot read the configuration %1: there is no such file</source>
        <translation>die Konfiguration %1 kann nicht gelesen werden: diese Datei gibt es nicht</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="274"/>
        <source>cannot read the configuration %1: %2</source>
        <translation>die Konfiguration %1 kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="278"/>
        <source>the configuration %1 is too big to be one</source>
        <translation>die Konfiguration %1 ist zu groß, um eine zu sein</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="280"/>
        <source>the configuration %1 is not a JSON object: %2</source>
        <translation>die Konfiguration %1 ist kein JSON-Objekt: %2</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="282"/>
        <source>it is a list</source>
        <translation>es ist eine Liste</translation>
    </message>
</context>
<context>
    <name>AgentMain</name>
    <message>
        <location filename="../app/agent/main.cpp" line="33"/>
        <source>without a user name</source>
        <translation>ohne Benutzernamen</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="35"/>
        <source>as %1, without a password</source>
        <translation>als %1, ohne Passwort</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="36"/>
        <source>as %1, password from the %2</source>
        <translation>als %1, Passwort aus %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/agent/main.cpp" line="42"/>
        <source>site %1, %n line(s) (%2), no MQTT broker: CFX only</source>
        <translation>
            <numerusform>Standort %1, %n Linie (%2), kein MQTT-Broker: nur CFX</numerusform>
            <numerusform>Standort %1, %n Linien (%2), kein MQTT-Broker: nur CFX</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/agent/main.cpp" line="45"/>
        <source>site %1, %n line(s) (%2), broker %3:%4%5 %6</source>
        <translation>
            <numerusform>Standort %1, %n Linie (%2), Broker %3:%4%5 %6</numerusform>
            <numerusform>Standort %1, %n Linien (%2), Broker %3:%4%5 %6</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="49"/>
        <source> with TLS</source>
        <translation> mit TLS</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="64"/>
        <source>Runs the lines of a workspace without a screen, keeps their joints and events in the journal and publishes them to an MQTT broker.</source>
        <translation>Betreibt die Linien eines Arbeitsbereichs ohne Bildschirm, hält ihre Lötstellen und Ereignisse im Journal fest und veröffentlicht sie an einen MQTT-Broker.</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="71"/>
        <source>The agent&apos;s configuration (default %1).</source>
        <translation>Die Konfiguration des Agenten (Vorgabe %1).</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="72"/>
        <source>file</source>
        <translation>Datei</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="75"/>
        <source>Reads the configuration and its workspace, says what is wrong, and exits.</source>
        <translation>Liest die Konfiguration und ihren Arbeitsbereich, meldet Fehler und beendet sich.</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="82"/>
        <source>unexpected argument %1</source>
        <translation>unerwartetes Argument %1</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="98"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="102"/>
        <source>%1 is good: %2</source>
        <translation>%1 ist in Ordnung: %2</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="114"/>
        <source>configuration refused, the running one stays: %1</source>
        <translation>Konfiguration abgelehnt, die laufende bleibt: %1</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="118"/>
        <source>reloading: %1</source>
        <translation>neu laden: %1</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="122"/>
        <source>tipscope-agent %1 starting: %2</source>
        <translation>tipscope-agent %1 startet: %2</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="127"/>
        <source>stopped: %1</source>
        <translation>beendet: %1</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="130"/>
        <source>stopped</source>
        <translation>beendet</translation>
    </message>
</context>
<context>
    <name>AmqpProblem</name>
    <message>
        <location filename="../lib/cfx/amqpproblem.cpp" line="20"/>
        <source>The broker refused the login: check the user and the password (file or environment variable).</source>
        <translation>Der Broker hat die Anmeldung abgelehnt: Benutzer und Passwort (Datei oder Umgebungsvariable) prüfen.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpproblem.cpp" line="23"/>
        <source>The broker does not speak AMQP 1.0: enable its plugin (rabbitmq-plugins enable rabbitmq_amqp1_0).</source>
        <translation>Der Broker spricht kein AMQP 1.0: sein Plugin aktivieren (rabbitmq-plugins enable rabbitmq_amqp1_0).</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpproblem.cpp" line="26"/>
        <source>The broker does not know the address %1: RabbitMQ wants /exchange/NAME, /exchange/NAME/KEY or /queue/NAME.</source>
        <translation>Der Broker kennt die Adresse %1 nicht: RabbitMQ erwartet /exchange/NAME, /exchange/NAME/KEY oder /queue/NAME.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpproblem.cpp" line="30"/>
        <source>The exchange or queue of %1 does not exist on the broker: declare it there, or fix the address.</source>
        <translation>Den Exchange oder die Queue von %1 gibt es auf dem Broker nicht: dort anlegen oder die Adresse korrigieren.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpproblem.cpp" line="34"/>
        <source>TLS failed: check the CA file, the client certificate and that the host name matches the broker&apos;s certificate.</source>
        <translation>TLS ist fehlgeschlagen: CA-Datei und Client-Zertifikat prüfen, und ob der Hostname zum Zertifikat des Brokers passt.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpproblem.cpp" line="37"/>
        <source>Nothing accepts connections there: check the host and port, and that the broker runs.</source>
        <translation>Dort nimmt nichts Verbindungen an: Host und Port prüfen, und ob der Broker läuft.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpproblem.cpp" line="41"/>
        <source>The broker&apos;s host name cannot be found: check it.</source>
        <translation>Der Hostname des Brokers ist nicht auffindbar: bitte prüfen.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpproblem.cpp" line="51"/>
        <source>The broker said: %1.</source>
        <translation>Der Broker meldete: %1.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpproblem.cpp" line="52"/>
        <source>%1 (The broker said: %2)</source>
        <translation>%1 (Der Broker meldete: %2)</translation>
    </message>
</context>
<context>
    <name>AppSettings</name>
    <message>
        <location filename="../lib/model/appsettings.cpp" line="116"/>
        <source>choose a serial port</source>
        <translation>wählen Sie eine serielle Schnittstelle</translation>
    </message>
    <message>
        <location filename="../lib/model/appsettings.cpp" line="124"/>
        <source>&apos;%1&apos; is not HOST:PORT (for example 192.168.1.20:4001)</source>
        <translation>&apos;%1&apos; hat nicht die Form HOST:PORT (zum Beispiel 192.168.1.20:4001)</translation>
    </message>
</context>
<context>
    <name>AtomicSave</name>
    <message>
        <location filename="../lib/model/io/atomicsave.cpp" line="27"/>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>BoardReport</name>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="66"/>
        <source>PASS: every joint within its limits</source>
        <translation>BESTANDEN: jede Lötstelle innerhalb ihrer Grenzen</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="68"/>
        <source>FAIL: joints outside their limits</source>
        <translation>NICHT BESTANDEN: Lötstellen außerhalb ihrer Grenzen</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="70"/>
        <source>NOT JUDGED: no joint failed, but some could not be judged</source>
        <translation>NICHT BEURTEILT: keine Lötstelle fiel durch, aber einige ließen sich nicht beurteilen</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="74"/>
        <source>NO JOINTS: the journal holds events of this board only</source>
        <translation>KEINE LÖTSTELLEN: das Journal enthält nur Ereignisse dieser Platine</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="106"/>
        <source>%1 ± %2</source>
        <translation>%1 ± %2</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="115"/>
        <source>%1 (bounded)</source>
        <translation>%1 (eingegrenzt)</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="116"/>
        <source>%1 ± %2 ms</source>
        <translation>%1 ± %2 ms</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="127"/>
        <source>≤ %1 K, ≤ %2 s</source>
        <translation>≤ %1 K, ≤ %2 s</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="166"/>
        <location filename="../lib/report/boardpdf.cpp" line="357"/>
        <source>Board record: %1</source>
        <translation>Platinenbericht: %1</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="176"/>
        <source>Made: %1 to %2</source>
        <translation>Gefertigt: %1 bis %2</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="179"/>
        <source>Work order: %1</source>
        <translation>Auftrag: %1</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="182"/>
        <source>Operator: %1</source>
        <translation>Bediener: %1</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="185"/>
        <source>Joints: %1 (%2)</source>
        <translation>Lötstellen: %1 (%2)</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="200"/>
        <location filename="../lib/report/boardpdf.cpp" line="268"/>
        <location filename="../lib/report/boardpdf.cpp" line="295"/>
        <source>Station</source>
        <translation>Station</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="203"/>
        <source>Operator</source>
        <translation>Bediener</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="209"/>
        <source>Limits (dip, recovery)</source>
        <translation>Grenzen (Einbruch, Erholung)</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="211"/>
        <location filename="../lib/report/boardpdf.cpp" line="269"/>
        <source>Joints</source>
        <translation>Lötstellen</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="214"/>
        <source>Judged by: a dip of at most %1 K, back within %2 K of the setpoint in at most %3 s.</source>
        <translation>Beurteilt nach: ein Einbruch von höchstens %1 K, zurück auf %2 K am Sollwert in höchstens %3 s.</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="231"/>
        <source>#%1 %2, port %3: dip %4, recovery %5, %6</source>
        <translation>#%1 %2, Port %3: Einbruch %4, Erholung %5, %6</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="238"/>
        <source>Worst joints</source>
        <translation>Schlechteste Lötstellen</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="239"/>
        <source>No curves: the journal keeps each joint&apos;s figures, not the tip&apos;s readings during it.</source>
        <translation>Keine Kurven: das Journal behält die Kennwerte jeder Lötstelle, nicht die Messwerte der Spitze währenddessen.</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="246"/>
        <source>not yet known: %1 joints of this tip; its first %2 recovered ones are the baseline</source>
        <translation>noch nicht bekannt: %1 Lötstellen dieser Spitze; ihre ersten %2 erholten bilden die Grundlinie</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="251"/>
        <source>%1 s when plugged in; no joint since</source>
        <translation>%1 s beim Einstecken; seitdem keine Lötstelle</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="252"/>
        <source>recovers in %1 s now, %2 s when plugged in (%3)</source>
        <translation>erholt sich jetzt in %1 s, beim Einstecken in %2 s (%3)</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="268"/>
        <source>Port</source>
        <translation>Port</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="269"/>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="270"/>
        <source>Setpoints</source>
        <translation>Sollwerte</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="270"/>
        <source>Plugged in</source>
        <translation>Eingesteckt</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="271"/>
        <source>Tip wear</source>
        <translation>Spitzenverschleiß</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="272"/>
        <source>Tools and settings</source>
        <translation>Werkzeuge und Einstellungen</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="282"/>
        <source>, port %1</source>
        <translation>, Port %1</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="295"/>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="296"/>
        <source>What happened</source>
        <translation>Was geschah</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="298"/>
        <source>None in the journal.</source>
        <translation>Keine im Journal.</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="303"/>
        <source>Profile applied before</source>
        <translation>Zuvor angewendetes Profil</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="304"/>
        <source>Faults and events while it was made</source>
        <translation>Fehler und Ereignisse während der Fertigung</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="310"/>
        <source>The limits %1 of the %2 joints were judged by: they were journaled before the journal kept them; a failed joint&apos;s warning among the events names the limit it broke.</source>
        <translation>Die Grenzen, nach denen %1 der %2 Lötstellen beurteilt wurden: sie wurden aufgezeichnet, bevor das Journal Grenzen behielt; die Warnung einer durchgefallenen Lötstelle unter den Ereignissen nennt die verletzte Grenze.</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="316"/>
        <source>The station&apos;s settings as they stood: the journal keeps only changes made through TipScope (writes and profiles), not those made at the station.</source>
        <translation>Die Einstellungen der Station, wie sie waren: das Journal behält nur Änderungen über TipScope (Schreibvorgänge und Profile), nicht die an der Station selbst.</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="319"/>
        <source>Curves of the joints: the journal keeps each joint&apos;s figures, not the tip&apos;s readings.</source>
        <translation>Kurven der Lötstellen: das Journal behält die Kennwerte jeder Lötstelle, nicht die Messwerte der Spitze.</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="322"/>
        <source>Not in the journal</source>
        <translation>Nicht im Journal</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="327"/>
        <source>Written by TipScope %1 on %2 from the journal %3</source>
        <translation>Erstellt von TipScope %1 am %2 aus dem Journal %3</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="329"/>
        <source>Times are local; figures as measured from the station&apos;s readings, each with how sure it is.</source>
        <translation>Zeiten in Ortszeit; Kennwerte wie aus den Messwerten der Station gemessen, jeweils mit ihrer Unsicherheit.</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="331"/>
        <source>Checked by: ______________________   Date: ____________   Signature: ______________________</source>
        <translation>Geprüft von: ______________________   Datum: ____________   Unterschrift: ______________________</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="348"/>
        <source>cannot write %1: a PDF needs fonts, which need a graphical application (QGuiApplication)</source>
        <translation>kann %1 nicht schreiben: ein PDF braucht Schriften, und die brauchen eine grafische Anwendung (QGuiApplication)</translation>
    </message>
</context>
<context>
    <name>Catalog</name>
    <message>
        <location filename="../lib/protocol/catalog.cpp" line="195"/>
        <source>Unknown NAK code %1</source>
        <translation>Unbekannter NAK-Code %1</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalog.cpp" line="200"/>
        <source>Unknown station error %1</source>
        <translation>Unbekannter Stationsfehler %1</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalog.cpp" line="209"/>
        <source>Unknown port error %1</source>
        <translation>Unbekannter Portfehler %1</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="13"/>
        <source>Port status</source>
        <translation>Portstatus</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="14"/>
        <source>Tool operating status: working, stand, sleep, hibernation, with cooling, suction and motor flags</source>
        <translation>Betriebszustand des Werkzeugs: in Betrieb, Ablage, Ruhemodus, Tiefschlaf, mit Flags für Abkühlen, Absaugung und Motor</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="15"/>
        <source>Working</source>
        <translation>In Betrieb</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="16"/>
        <source>Stand</source>
        <translation>Ablage</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="17"/>
        <source>Cooling</source>
        <translation>Abkühlen</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="18"/>
        <source>Tool operating status: no stand (working), stand, sleep, hibernation, with extractor and suction flags</source>
        <translation>Betriebszustand des Werkzeugs: nicht in der Ablage (in Betrieb), Ablage, Ruhemodus, Tiefschlaf, mit Flags für Rauchabsaugung und Absaugung</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="19"/>
        <source>Selected temperature</source>
        <translation>Eingestellte Temperatur</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="20"/>
        <source>Tip working temperature, in steps of 5 °C between the station&apos;s minimum and maximum; volatile until saved</source>
        <translation>Arbeitstemperatur der Spitze, in Schritten von 5 °C zwischen Minimum und Maximum der Station; flüchtig bis zum Speichern</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="21"/>
        <source>Tip temperature</source>
        <translation>Spitzentemperatur</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="22"/>
        <source>Current tip temperature</source>
        <translation>Aktuelle Spitzentemperatur</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="23"/>
        <source>Power</source>
        <translation>Leistung</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="24"/>
        <source>Power delivered to the tip, in thousandths of the station&apos;s maximum</source>
        <translation>An die Spitze abgegebene Leistung, in Tausendsteln des Stationsmaximums</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="25"/>
        <source>Time to sleep/hibernation</source>
        <translation>Zeit bis Ruhemodus/Tiefschlaf</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="26"/>
        <source>Seconds left before the tool enters sleep or hibernation</source>
        <translation>Verbleibende Sekunden, bis das Werkzeug in den Ruhemodus oder Tiefschlaf wechselt</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="27"/>
        <source>Transistor temperature</source>
        <translation>Transistortemperatur</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="28"/>
        <source>Temperature of the port&apos;s power transistor</source>
        <translation>Temperatur des Leistungstransistors des Ports</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="29"/>
        <source>Connected tool</source>
        <translation>Angeschlossenes Werkzeug</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="30"/>
        <source>Tool connected to the port</source>
        <translation>Am Port angeschlossenes Werkzeug</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="31"/>
        <source>Port error</source>
        <translation>Portfehler</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="32"/>
        <source>Current error of the port</source>
        <translation>Aktueller Fehler des Ports</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="33"/>
        <source>High temperature alarm</source>
        <translation>Übertemperaturalarm</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="34"/>
        <source>Upper tip temperature alarm limit, in steps of 5 °C</source>
        <translation>Obere Alarmgrenze der Spitzentemperatur, in Schritten von 5 °C</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="35"/>
        <source>Low temperature alarm</source>
        <translation>Untertemperaturalarm</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="36"/>
        <source>Lower tip temperature alarm limit, in steps of 5 °C</source>
        <translation>Untere Alarmgrenze der Spitzentemperatur, in Schritten von 5 °C</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="37"/>
        <source>High alarm delay</source>
        <translation>Verzögerung Alarm hoch</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="38"/>
        <source>How long the tip must stay above the high alarm limit before the alarm is set (ss.cc)</source>
        <translation>Wie lange die Spitze über der oberen Alarmgrenze bleiben muss, bevor der Alarm ausgelöst wird (ss.cc)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="39"/>
        <source>disabled</source>
        <translation>deaktiviert</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="40"/>
        <source>Low alarm delay</source>
        <translation>Verzögerung Alarm tief</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="41"/>
        <source>How long the tip must stay below the low alarm limit before the alarm is set (ss.cc)</source>
        <translation>Wie lange die Spitze unter der unteren Alarmgrenze bleiben muss, bevor der Alarm ausgelöst wird (ss.cc)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="42"/>
        <source>Temperature alarm</source>
        <translation>Temperaturalarm</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="43"/>
        <source>Alarm flags: units digit high alarm, tens digit low alarm (DDR/HDR clear them when read)</source>
        <translation>Alarm-Flags: Einerstelle Alarm hoch, Zehnerstelle Alarm tief (DDR/HDR löschen sie beim Lesen)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="44"/>
        <source>Plugged hours</source>
        <translation>Einschaltstunden</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="45"/>
        <source>Hours with a tool plugged into the port</source>
        <translation>Stunden mit am Port angeschlossenem Werkzeug</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="52"/>
        <source>No-tool hours</source>
        <translation>Stunden ohne Werkzeug</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="53"/>
        <source>Hours the port was powered with no tool</source>
        <translation>Stunden, in denen der Port ohne Werkzeug eingeschaltet war</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="48"/>
        <source>Sleep hours</source>
        <translation>Ruhemodus-Stunden</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="49"/>
        <source>Hours in sleep</source>
        <translation>Stunden im Ruhemodus</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="50"/>
        <source>Hibernation hours</source>
        <translation>Tiefschlafstunden</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="51"/>
        <source>Hours in hibernation</source>
        <translation>Stunden im Tiefschlaf</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="46"/>
        <source>Work hours</source>
        <translation>Arbeitsstunden</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="47"/>
        <source>Hours working</source>
        <translation>Stunden in Betrieb</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="54"/>
        <source>Sleep cycles</source>
        <translation>Ruhemodus-Zyklen</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="55"/>
        <source>Number of times the tool went into sleep</source>
        <translation>Anzahl der Wechsel des Werkzeugs in den Ruhemodus</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="56"/>
        <source>Desoldering cycles</source>
        <translation>Entlötzyklen</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="57"/>
        <source>Number of times the desoldering tool was activated</source>
        <translation>Anzahl der Aktivierungen des Entlötwerkzeugs</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="58"/>
        <source>Dispensed cycles</source>
        <translation>Dosierzyklen</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="59"/>
        <source>Number of dispensing cycles of the built-in wire feed</source>
        <translation>Anzahl der Dosierzyklen des eingebauten Drahtvorschubs</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="60"/>
        <source>Dispensed length</source>
        <translation>Dosierte Länge</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="61"/>
        <source>Total wire length dispensed (hexadecimal on the wire)</source>
        <translation>Insgesamt dosierte Drahtlänge (auf der Leitung hexadezimal)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="62"/>
        <source>Temperature adjust</source>
        <translation>Temperaturkorrektur</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="63"/>
        <source>Offset added to the tool&apos;s temperature, ±50 °C in steps of 1</source>
        <translation>Zur Werkzeugtemperatur addierter Offset, ±50 °C in Schritten von 1</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="64"/>
        <source>Sleep temperature</source>
        <translation>Ruhemodus-Temperatur</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="65"/>
        <source>Tip temperature in sleep, in steps of 5 °C</source>
        <translation>Spitzentemperatur im Ruhemodus, in Schritten von 5 °C</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="66"/>
        <source>Sleep delay</source>
        <translation>Ruhemodus-Verzögerung</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="67"/>
        <source>Minutes in the stand before sleep, 0 to 9, or disabled</source>
        <translation>Minuten in der Ablage bis zum Ruhemodus, 0 bis 9, oder deaktiviert</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="68"/>
        <source>Hibernation delay</source>
        <translation>Tiefschlafverzögerung</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="69"/>
        <source>Minutes in sleep before hibernation, 0 to 60 in steps of 5, or disabled</source>
        <translation>Minuten im Ruhemodus bis zum Tiefschlaf, 0 bis 60 in Schritten von 5, oder deaktiviert</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="70"/>
        <source>Maximum temperature</source>
        <translation>Höchsttemperatur</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="71"/>
        <source>Highest temperature selectable with the selected temperature</source>
        <translation>Höchste als eingestellte Temperatur wählbare Temperatur</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="72"/>
        <source>Minimum temperature</source>
        <translation>Mindesttemperatur</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="73"/>
        <source>Lowest temperature selectable with the selected temperature</source>
        <translation>Niedrigste als eingestellte Temperatur wählbare Temperatur</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="74"/>
        <source>Power limit</source>
        <translation>Leistungsgrenze</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="75"/>
        <source>Maximum power delivered to a tool, in thousandths of the station&apos;s maximum</source>
        <translation>Maximale an ein Werkzeug abgegebene Leistung, in Tausendsteln des Stationsmaximums</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="76"/>
        <source>Transformer temperature</source>
        <translation>Transformatortemperatur</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="77"/>
        <source>Temperature of the power supply transformer (R-TT; see protocol notes)</source>
        <translation>Temperatur des Netztransformators (R-TT; siehe Protokollhinweise)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="78"/>
        <source>Station error</source>
        <translation>Stationsfehler</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="79"/>
        <source>Current error of the station</source>
        <translation>Aktueller Fehler der Station</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="80"/>
        <source>Fuse status</source>
        <translation>Sicherungsstatus</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="81"/>
        <source>Whether the station&apos;s fuse is in place</source>
        <translation>Ob die Sicherung der Station eingesetzt ist</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="82"/>
        <source>No fuse (blown or missing)</source>
        <translation>Keine Sicherung (durchgebrannt oder fehlt)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="83"/>
        <source>Fuse present</source>
        <translation>Sicherung vorhanden</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="84"/>
        <source>Model name</source>
        <translation>Modellname</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="85"/>
        <source>The device&apos;s model name</source>
        <translation>Modellname des Geräts</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="86"/>
        <source>Software version</source>
        <translation>Softwareversion</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="87"/>
        <source>The device&apos;s software version</source>
        <translation>Softwareversion des Geräts</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="88"/>
        <source>Save to station memory</source>
        <translation>Im Stationsspeicher sichern</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="89"/>
        <source>Stores the volatile settings (selected temperature; feeder mode, speed, length) in non-volatile memory</source>
        <translation>Speichert die flüchtigen Einstellungen (eingestellte Temperatur; Vorschubmodus, -geschwindigkeit, -länge) im nichtflüchtigen Speicher</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="90"/>
        <source>Factory reset</source>
        <translation>Werkseinstellungen wiederherstellen</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="91"/>
        <source>Resets every parameter of the device to its factory value</source>
        <translation>Setzt alle Parameter des Geräts auf ihre Werkswerte zurück</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="92"/>
        <source>Every setting of the device returns to its factory value; the feeder restarts and goes back to address 10 in addressed mode.</source>
        <translation>Alle Einstellungen des Geräts werden auf ihre Werkswerte zurückgesetzt; der Lotdrahtvorschub startet neu und kehrt im adressierten Betrieb zur Adresse 10 zurück.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="93"/>
        <source>Restart station</source>
        <translation>Station neu starten</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="94"/>
        <source>Restarts the control unit</source>
        <translation>Startet das Steuergerät neu</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="95"/>
        <source>The control unit restarts: tools cool down and the station does not answer until it is back.</source>
        <translation>Das Steuergerät startet neu: die Werkzeuge kühlen ab, und die Station antwortet erst wieder, wenn sie bereit ist.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="96"/>
        <source>Device address</source>
        <translation>Geräteadresse</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="97"/>
        <source>Sets the device&apos;s own address (1-99); 0 switches it to frames without addresses</source>
        <translation>Setzt die eigene Adresse des Geräts (1-99); 0 schaltet auf Telegramme ohne Adressen um</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="98"/>
        <source>The device answers only at the new address (or only without addresses for 0); TipScope must reconnect with the new setting.</source>
        <translation>Das Gerät antwortet nur noch unter der neuen Adresse (bzw. bei 0 nur ohne Adressen); TipScope muss sich mit der neuen Einstellung neu verbinden.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="99"/>
        <source>Ignore fuse error</source>
        <translation>Sicherungsfehler ignorieren</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="100"/>
        <source>Lets the station keep working despite a fuse error</source>
        <translation>Lässt die Station trotz Sicherungsfehler weiterarbeiten</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="101"/>
        <source>The station keeps heating although its fuse is reported missing or blown.</source>
        <translation>Die Station heizt weiter, obwohl ihre Sicherung als fehlend oder durchgebrannt gemeldet wird.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="102"/>
        <source>Dispensing mode</source>
        <translation>Dosiermodus</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="103"/>
        <source>How the built-in feed dispenses wire</source>
        <translation>Wie der eingebaute Vorschub den Draht dosiert</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="104"/>
        <source>Continuous</source>
        <translation>Kontinuierlich</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="105"/>
        <source>Discontinuous</source>
        <translation>Diskontinuierlich</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="106"/>
        <source>Program</source>
        <translation>Programm</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="107"/>
        <source>Tin reload</source>
        <translation>Lötzinn nachladen</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="108"/>
        <source>Dispensing length</source>
        <translation>Dosierlänge</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="109"/>
        <source>Wire length dispensed per cycle, in tenths of a millimetre</source>
        <translation>Pro Zyklus dosierte Drahtlänge, in Zehntelmillimetern</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="110"/>
        <source>Dispensing speed</source>
        <translation>Dosiergeschwindigkeit</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="111"/>
        <source>Wire speed, in tenths of a millimetre per second</source>
        <translation>Drahtgeschwindigkeit, in Zehntelmillimetern pro Sekunde</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="112"/>
        <source>Wire diameter</source>
        <translation>Drahtdurchmesser</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="113"/>
        <source>Solder wire diameter, in hundredths of a millimetre</source>
        <translation>Durchmesser des Lötdrahts, in Hundertstelmillimetern</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="114"/>
        <source>Backward length</source>
        <translation>Rückzuglänge</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="115"/>
        <source>Wire pulled back after each cycle, in tenths of a millimetre</source>
        <translation>Nach jedem Zyklus zurückgezogener Draht, in Zehntelmillimetern</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="116"/>
        <source>Wire clogging detection</source>
        <translation>Drahtstauerkennung</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="117"/>
        <source>Detects a clogged wire feed</source>
        <translation>Erkennt einen verstopften Drahtvorschub</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="118"/>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="119"/>
        <source>On</source>
        <translation>Ein</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="120"/>
        <source>Dispensing status</source>
        <translation>Dosierstatus</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="121"/>
        <source>Whether the dispensing motor is running</source>
        <translation>Ob der Dosiermotor läuft</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="122"/>
        <source>Stopped</source>
        <translation>Gestoppt</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="123"/>
        <source>Running</source>
        <translation>Läuft</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="124"/>
        <source>Start dispensing</source>
        <translation>Dosieren starten</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="125"/>
        <source>Starts the dispensing motor</source>
        <translation>Startet den Dosiermotor</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="126"/>
        <source>Stop dispensing</source>
        <translation>Dosieren stoppen</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="127"/>
        <source>Stops the dispensing motor</source>
        <translation>Stoppt den Dosiermotor</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="128"/>
        <source>Feeding mode</source>
        <translation>Vorschubmodus</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="129"/>
        <source>Continuous feeds until stopped; discontinuous feeds the set length</source>
        <translation>Kontinuierlich: Vorschub bis zum Stopp; diskontinuierlich: Vorschub um die eingestellte Länge</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="130"/>
        <source>Start feeding</source>
        <translation>Vorschub starten</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="131"/>
        <source>Starts feeding wire forward or backward</source>
        <translation>Startet den Drahtvorschub vorwärts oder rückwärts</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="132"/>
        <source>Forward</source>
        <translation>Vorwärts</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="133"/>
        <source>Backward</source>
        <translation>Rückwärts</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="134"/>
        <source>Stop feeding</source>
        <translation>Vorschub stoppen</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="135"/>
        <source>Stops feeding (continuous mode)</source>
        <translation>Stoppt den Vorschub (kontinuierlicher Modus)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="138"/>
        <source>Feeding length</source>
        <translation>Vorschublänge</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="139"/>
        <source>Length fed per start in discontinuous mode, in tenths of a millimetre</source>
        <translation>Vorschublänge pro Start im diskontinuierlichen Modus, in Zehntelmillimetern</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="136"/>
        <source>Feeding speed</source>
        <translation>Vorschubgeschwindigkeit</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="137"/>
        <source>Feeding speed, in tenths of a millimetre per second</source>
        <translation>Vorschubgeschwindigkeit, in Zehntelmillimetern pro Sekunde</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="140"/>
        <source>Wire thickness</source>
        <translation>Drahtstärke</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="141"/>
        <source>Diameter class of the solder wire</source>
        <translation>Durchmesserklasse des Lötdrahts</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="142"/>
        <source>≤ 0.8 mm</source>
        <translation>≤ 0,8 mm</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="143"/>
        <source>&gt; 0.8 mm and ≤ 1.2 mm</source>
        <translation>&gt; 0,8 mm und ≤ 1,2 mm</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="144"/>
        <source>&gt; 1.2 mm</source>
        <translation>&gt; 1,2 mm</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="145"/>
        <source>Switch input</source>
        <translation>Schaltereingang</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="146"/>
        <source>Whether the switch input can start feeding</source>
        <translation>Ob der Schaltereingang den Vorschub starten kann</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="147"/>
        <source>Disabled</source>
        <translation>Deaktiviert</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="148"/>
        <source>Enabled</source>
        <translation>Aktiviert</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="149"/>
        <source>Feeder error code</source>
        <translation>Vorschub-Fehlercode</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="150"/>
        <source>The feeder&apos;s last error code</source>
        <translation>Letzter Fehlercode des Lotdrahtvorschubs</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="151"/>
        <source>Reset feeder error</source>
        <translation>Vorschubfehler zurücksetzen</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="152"/>
        <source>Clears the feeder&apos;s last error code</source>
        <translation>Löscht den letzten Fehlercode des Lotdrahtvorschubs</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="153"/>
        <source>Feeding status</source>
        <translation>Vorschubstatus</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="154"/>
        <source>Whether the feeder is feeding</source>
        <translation>Ob der Lotdrahtvorschub gerade Draht fördert</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="155"/>
        <source>Idle</source>
        <translation>Bereit</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="156"/>
        <source>Feeding</source>
        <translation>Vorschub läuft</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="157"/>
        <source>Fed length</source>
        <translation>Vorgeschobene Länge</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="158"/>
        <source>Length fed since the last start, in tenths of a millimetre</source>
        <translation>Seit dem letzten Start vorgeschobene Länge, in Zehntelmillimetern</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="159"/>
        <source>Loading</source>
        <translation>Einfädeln</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="160"/>
        <source>Feeds wire ignoring feeding errors, for loading a new spool</source>
        <translation>Schiebt Draht ohne Prüfung auf Vorschubfehler vor, zum Einfädeln einer neuen Spule</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="161"/>
        <source>Start loading</source>
        <translation>Einfädeln starten</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="162"/>
        <source>End loading</source>
        <translation>Einfädeln beenden</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="163"/>
        <source>Plugged hours (total)</source>
        <translation>Einschaltstunden (gesamt)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="164"/>
        <source>Hours powered, total counter</source>
        <translation>Stunden eingeschaltet, Gesamtzähler</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="165"/>
        <source>Plugged hours (partial)</source>
        <translation>Einschaltstunden (Teilzähler)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="166"/>
        <source>Hours powered since the partial counter was reset</source>
        <translation>Stunden eingeschaltet seit dem Zurücksetzen des Teilzählers</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="167"/>
        <source>Reset plugged hours (partial)</source>
        <translation>Einschaltstunden (Teilzähler) zurücksetzen</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="168"/>
        <source>Resets the partial plugged-hours counter</source>
        <translation>Setzt den Teilzähler der Einschaltstunden zurück</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="169"/>
        <source>The partial plugged-hours counter goes back to zero; the old value cannot be recovered.</source>
        <translation>Der Teilzähler der Einschaltstunden wird auf null gesetzt; der alte Wert kann nicht wiederhergestellt werden.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="171"/>
        <source>Feeding hours (total)</source>
        <translation>Vorschubstunden (gesamt)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="172"/>
        <source>Hours feeding, total counter</source>
        <translation>Stunden mit Vorschub, Gesamtzähler</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="174"/>
        <source>Feeding hours (partial)</source>
        <translation>Vorschubstunden (Teilzähler)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="175"/>
        <source>Hours feeding since the partial counter was reset</source>
        <translation>Stunden mit Vorschub seit dem Zurücksetzen des Teilzählers</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="176"/>
        <source>Reset feeding hours (partial)</source>
        <translation>Vorschubstunden (Teilzähler) zurücksetzen</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="177"/>
        <source>Resets the partial feeding-hours counter</source>
        <translation>Setzt den Teilzähler der Vorschubstunden zurück</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="178"/>
        <source>The partial feeding-hours counter goes back to zero; the old value cannot be recovered.</source>
        <translation>Der Teilzähler der Vorschubstunden wird auf null gesetzt; der alte Wert kann nicht wiederhergestellt werden.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="180"/>
        <source>Fed length (total)</source>
        <translation>Vorgeschobene Länge (gesamt)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="181"/>
        <source>Metres of wire fed, total counter</source>
        <translation>Vorgeschobener Draht in Metern, Gesamtzähler</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="182"/>
        <source>Fed length (partial)</source>
        <translation>Vorgeschobene Länge (Teilzähler)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="183"/>
        <source>Metres of wire fed since the partial counter was reset</source>
        <translation>Vorgeschobener Draht in Metern seit dem Zurücksetzen des Teilzählers</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="184"/>
        <source>Reset fed length (partial)</source>
        <translation>Vorgeschobene Länge (Teilzähler) zurücksetzen</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="185"/>
        <source>Resets the partial fed-length counter</source>
        <translation>Setzt den Teilzähler der vorgeschobenen Länge zurück</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="186"/>
        <source>The partial fed-length counter goes back to zero; the old value cannot be recovered.</source>
        <translation>Der Teilzähler der vorgeschobenen Länge wird auf null gesetzt; der alte Wert kann nicht wiederhergestellt werden.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="188"/>
        <source>No tool</source>
        <translation>Kein Werkzeug</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="189"/>
        <source>BCC error: the frame failed the sum check</source>
        <translation>BCC-Fehler: das Telegramm hat die Prüfsummenkontrolle nicht bestanden</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="190"/>
        <source>Format error: the frame has the wrong size or layout</source>
        <translation>Formatfehler: das Telegramm hat die falsche Länge oder den falschen Aufbau</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="191"/>
        <source>Out of range: the value is outside the allowed limits or off-step</source>
        <translation>Außerhalb des Bereichs: der Wert liegt außerhalb der zulässigen Grenzen oder nicht im Schrittraster</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="192"/>
        <source>Control error: the command is not accepted by this device</source>
        <translation>Steuerungsfehler: dieses Gerät nimmt den Befehl nicht an</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="193"/>
        <source>Robot mode is off: switch &quot;Robot mode&quot; on in the station menu</source>
        <translation>Der Robotermodus ist aus: schalten Sie im Stationsmenü &quot;Robot mode&quot; ein</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="194"/>
        <source>Device model error: the device model is unknown</source>
        <translation>Gerätemodellfehler: das Gerätemodell ist unbekannt</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="195"/>
        <source>Undefined error</source>
        <translation>Undefinierter Fehler</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="196"/>
        <source>Stopped by transformer overload</source>
        <translation>Wegen Überlast des Transformators gestoppt</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="197"/>
        <source>Temperature sensor error</source>
        <translation>Fehler des Temperatursensors</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="198"/>
        <source>Memory error</source>
        <translation>Speicherfehler</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="199"/>
        <source>Mains frequency error</source>
        <translation>Netzfrequenzfehler</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="200"/>
        <source>Device model error</source>
        <translation>Gerätemodellfehler</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="201"/>
        <source>MCU tools not connected</source>
        <translation>Werkzeug-MCU nicht verbunden</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="202"/>
        <source>Warning: transformer overload</source>
        <translation>Warnung: Überlast des Transformators</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="203"/>
        <source>Short circuit</source>
        <translation>Kurzschluss</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="204"/>
        <source>Short circuit, not recoverable: restart the station</source>
        <translation>Kurzschluss, nicht behebbar: Station neu starten</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="205"/>
        <source>Open circuit</source>
        <translation>Leitungsunterbrechung</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="206"/>
        <source>Tool not accepted</source>
        <translation>Werkzeug nicht akzeptiert</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="207"/>
        <source>Detecting tool</source>
        <translation>Werkzeug wird erkannt</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="208"/>
        <source>Stopped at maximum power</source>
        <translation>Bei maximaler Leistung gestoppt</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="209"/>
        <source>Stopped by transistor (MOS) overload</source>
        <translation>Wegen Überlast des Transistors (MOS) gestoppt</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="210"/>
        <source>Warning: transistor (MOS) overload</source>
        <translation>Warnung: Überlast des Transistors (MOS)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="211"/>
        <source>No error</source>
        <translation>Kein Fehler</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="230"/>
        <source>Sleep</source>
        <translation>Ruhemodus</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="231"/>
        <source>Hibernation</source>
        <translation>Tiefschlaf</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="232"/>
        <source>Suction on</source>
        <translation>Absaugung ein</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="233"/>
        <source>Motor forward (dispensing)</source>
        <translation>Motor vorwärts (Dosieren)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="234"/>
        <source>Motor backward</source>
        <translation>Motor rückwärts</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="236"/>
        <source>unknown (%1)</source>
        <translation>unbekannt (%1)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="243"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="170"/>
        <source>Reset partial plugged hours</source>
        <translation>Teilzähler Einschaltstunden zurücksetzen</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="173"/>
        <source>Feeding hours</source>
        <translation>Vorschubstunden</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="179"/>
        <source>Reset partial feeding hours</source>
        <translation>Teilzähler Vorschubstunden zurücksetzen</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="187"/>
        <source>Reset partial fed length</source>
        <translation>Teilzähler vorgeschobene Länge zurücksetzen</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalog.cpp" line="214"/>
        <source>Feeder error %1 (not listed in the SFR guide)</source>
        <translation>Vorschubfehler %1 (nicht in der SFR-Anleitung aufgeführt)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="213"/>
        <source>The station switched off its power because the transformer was overloaded. Let it cool for a few minutes with the ventilation slots free, then switch it off and on. Check that the tools working at once do not need more than the station can give (large heat sinks, high temperatures, several ports at full power). If it stops again with one tool at normal work, the station needs JBC service.</source>
        <translation>Die Station hat ihre Leistung abgeschaltet, weil der Transformator überlastet war. Lassen Sie sie einige Minuten mit freien Lüftungsschlitzen abkühlen, dann aus- und wieder einschalten. Prüfen Sie, ob die gleichzeitig arbeitenden Werkzeuge mehr brauchen, als die Station liefern kann (große Wärmesenken, hohe Temperaturen, mehrere Ports mit voller Leistung). Schaltet sie mit einem Werkzeug bei normaler Arbeit wieder ab, muss die Station zum JBC-Service.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="214"/>
        <source>The station cannot read its internal temperature sensor. Switch it off and on; if the error stays, the control unit needs JBC service.</source>
        <translation>Die Station kann ihren internen Temperatursensor nicht lesen. Aus- und wieder einschalten; bleibt der Fehler, muss die Steuereinheit zum JBC-Service.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="215"/>
        <source>The station&apos;s memory failed its check. Switch it off and on. If the error stays, restore the factory settings and set the station up again (save a profile first if the settings can still be read); if it still stays, the control unit needs JBC service.</source>
        <translation>Der Speicher der Station hat seine Prüfung nicht bestanden. Aus- und wieder einschalten. Bleibt der Fehler, die Werkseinstellungen wiederherstellen und die Station neu einrichten (vorher ein Profil speichern, wenn sich die Einstellungen noch lesen lassen); bleibt er dann noch, muss die Steuereinheit zum JBC-Service.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="216"/>
        <source>The station does not accept the mains frequency. Check that the voltage and frequency on the station&apos;s label match the supply, and that no generator, UPS or long extension cord makes it unstable; then switch the station off and on.</source>
        <translation>Die Station akzeptiert die Netzfrequenz nicht. Prüfen Sie, ob Spannung und Frequenz auf dem Typenschild der Station zur Versorgung passen und ob kein Generator, keine USV und kein langes Verlängerungskabel sie instabil macht; dann die Station aus- und wieder einschalten.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="217"/>
        <source>The station does not recognise its own model: its configuration is damaged. Switch it off and on; if the error stays, the control unit needs JBC service.</source>
        <translation>Die Station erkennt ihr eigenes Modell nicht: Ihre Konfiguration ist beschädigt. Aus- und wieder einschalten; bleibt der Fehler, muss die Steuereinheit zum JBC-Service.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="218"/>
        <source>The station&apos;s tool control board does not answer. Switch the station off, wait ten seconds and switch it on; if the error stays, the control unit needs JBC service.</source>
        <translation>Die Werkzeug-Steuerplatine der Station antwortet nicht. Station ausschalten, zehn Sekunden warten und einschalten; bleibt der Fehler, muss die Steuereinheit zum JBC-Service.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="219"/>
        <source>The transformer is close to overload; the station stops if this goes on. Reduce the load: fewer tools heating at once, lower temperatures, no tip resting on a large heat sink; keep the ventilation slots free.</source>
        <translation>Der Transformator ist nahe an der Überlast; hält das an, schaltet die Station ab. Verringern Sie die Last: weniger Werkzeuge gleichzeitig heizen, niedrigere Temperaturen, keine Spitze auf einer großen Wärmesenke liegen lassen; Lüftungsschlitze frei halten.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="212"/>
        <source>The guide&apos;s table does not list this code. Note the code and the time, switch the station off and on, and give the code to JBC service if it comes back.</source>
        <translation>Die Tabelle der Anleitung führt diesen Code nicht. Notieren Sie Code und Uhrzeit, schalten Sie die Station aus und wieder ein, und geben Sie den Code an den JBC-Service, wenn er wiederkommt.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="220"/>
        <source>The heater circuit of the tool is short-circuited. Check that the cartridge is seated fully and is not damaged, then try another cartridge. If the error stays, check the tool&apos;s cable and connector for damage and try the tool on another port.</source>
        <translation>Der Heizkreis des Werkzeugs ist kurzgeschlossen. Prüfen Sie, ob die Kartusche ganz eingesetzt und unbeschädigt ist, und versuchen Sie dann eine andere Kartusche. Bleibt der Fehler, Kabel und Stecker des Werkzeugs auf Schäden prüfen und das Werkzeug an einem anderen Port versuchen.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="221"/>
        <source>The port was switched off after a short circuit and stays off until the station restarts. Switch the station off, change the cartridge, check the tool&apos;s cable and connector for damage, then switch it on again.</source>
        <translation>Der Port wurde nach einem Kurzschluss abgeschaltet und bleibt aus, bis die Station neu startet. Station ausschalten, Kartusche wechseln, Kabel und Stecker des Werkzeugs auf Schäden prüfen, dann wieder einschalten.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="222"/>
        <source>The station finds no heater in the tool. Check that the cartridge is seated fully in the handle, then try another cartridge. If the error stays, check the tool&apos;s cable and connector and try the tool on another port.</source>
        <translation>Die Station findet keine Heizung im Werkzeug. Prüfen Sie, ob die Kartusche ganz im Handgriff sitzt, und versuchen Sie dann eine andere Kartusche. Bleibt der Fehler, Kabel und Stecker des Werkzeugs prüfen und das Werkzeug an einem anderen Port versuchen.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="223"/>
        <source>No tool is connected to this port. If one is plugged in, push its connector fully home, then try it on another port.</source>
        <translation>An diesem Port ist kein Werkzeug angeschlossen. Ist eines eingesteckt, den Stecker ganz eindrücken, dann an einem anderen Port versuchen.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="224"/>
        <source>The station cannot drive the tool plugged into this port. Check the tool&apos;s model against the station&apos;s list of compatible tools and use a tool that is on it, or another station.</source>
        <translation>Die Station kann das an diesem Port eingesteckte Werkzeug nicht betreiben. Vergleichen Sie das Werkzeugmodell mit der Liste kompatibler Werkzeuge der Station und verwenden Sie ein Werkzeug daraus oder eine andere Station.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="225"/>
        <source>The station is identifying the tool; this takes a few seconds. If it does not end, unplug the tool, check its connector and plug it in again.</source>
        <translation>Die Station erkennt gerade das Werkzeug; das dauert einige Sekunden. Endet es nicht, das Werkzeug ausstecken, den Stecker prüfen und wieder einstecken.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="226"/>
        <source>The port stopped after giving its maximum power for too long. Check that the tip suits the work (a larger tip for large joints) and is not resting on a large heat sink; lower the load and restart the tool.</source>
        <translation>Der Port hat abgeschaltet, nachdem er zu lange seine Höchstleistung gab. Prüfen Sie, ob die Spitze zur Arbeit passt (eine größere Spitze für große Lötstellen) und nicht auf einer großen Wärmesenke liegt; Last verringern und das Werkzeug neu starten.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="227"/>
        <source>The port&apos;s power transistor overheated and the port stopped. Let the station cool with the ventilation slots free, then reduce the load on this port (a larger tip, a lower temperature, shorter contact with large heat sinks). If it happens at normal work, the station needs JBC service.</source>
        <translation>Der Leistungstransistor des Ports war überhitzt, und der Port hat abgeschaltet. Station mit freien Lüftungsschlitzen abkühlen lassen, dann die Last an diesem Port verringern (eine größere Spitze, eine niedrigere Temperatur, kürzerer Kontakt mit großen Wärmesenken). Geschieht das bei normaler Arbeit, muss die Station zum JBC-Service.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="228"/>
        <source>The port&apos;s power transistor is close to overload; the port stops if this goes on. Reduce the load on this port: a lower temperature, shorter contact with large heat sinks; keep the ventilation slots free.</source>
        <translation>Der Leistungstransistor des Ports ist nahe an der Überlast; hält das an, schaltet der Port ab. Verringern Sie die Last an diesem Port: eine niedrigere Temperatur, kürzerer Kontakt mit großen Wärmesenken; Lüftungsschlitze frei halten.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="229"/>
        <source>The SFR guide does not say what the feeder&apos;s error codes mean. Check that the solder wire is loaded and runs freely from the reel to the tool (no knot, no jam, the reel not empty) and that the wire thickness setting matches the wire; then reset the error. If it comes back at once, note the code and see the SFR manual.</source>
        <translation>Die SFR-Anleitung sagt nicht, was die Fehlercodes des Vorschubs bedeuten. Prüfen Sie, ob Lötdraht eingelegt ist und frei von der Rolle zum Werkzeug läuft (kein Knoten, kein Stau, die Rolle nicht leer) und ob die eingestellte Drahtstärke zum Draht passt; dann den Fehler zurücksetzen. Kommt er sofort wieder, den Code notieren und im SFR-Handbuch nachsehen.</translation>
    </message>
</context>
<context>
    <name>Cfx</name>
    <message>
        <location filename="../lib/cfx/amqpsender.cpp" line="212"/>
        <source>rejected by the broker</source>
        <translation>vom Broker abgelehnt</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpsender.cpp" line="215"/>
        <source>released by the broker</source>
        <translation>vom Broker freigegeben</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpsender.cpp" line="261"/>
        <source>the connection closed</source>
        <translation>die Verbindung wurde geschlossen</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxenvelope.cpp" line="26"/>
        <source>The CFX envelope&apos;s %1 is not a text.</source>
        <translation>%1 im CFX-Umschlag ist kein Text.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxenvelope.cpp" line="82"/>
        <source>A CFX message of %1 bytes is larger than the %2 accepted.</source>
        <translation>Eine CFX-Nachricht mit %1 Bytes ist größer als die zulässigen %2.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxenvelope.cpp" line="88"/>
        <source>A CFX message is not a JSON object: %1.</source>
        <translation>Eine CFX-Nachricht ist kein JSON-Objekt: %1.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxenvelope.cpp" line="89"/>
        <source>not an object</source>
        <translation>kein Objekt</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxenvelope.cpp" line="104"/>
        <source>A CFX message has no MessageName.</source>
        <translation>Einer CFX-Nachricht fehlt MessageName.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxenvelope.cpp" line="115"/>
        <source>The CFX envelope&apos;s MessageBody is not an object.</source>
        <translation>MessageBody im CFX-Umschlag ist kein Objekt.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxenvelope.cpp" line="170"/>
        <source>Cannot unpack a gzip CFX message.</source>
        <translation>Eine gzip-komprimierte CFX-Nachricht lässt sich nicht entpacken.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxenvelope.cpp" line="187"/>
        <source>A gzip CFX message is damaged or larger than %1 bytes.</source>
        <translation>Eine gzip-komprimierte CFX-Nachricht ist beschädigt oder größer als %1 Bytes.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxrequests.cpp" line="119"/>
        <source>A CFX request (%1) without a reply-to address: it cannot be answered.</source>
        <translation>Eine CFX-Anfrage (%1) ohne Antwortadresse (reply-to): sie kann nicht beantwortet werden.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxrequests.cpp" line="124"/>
        <source>A CFX request (%1) for &quot;%2&quot;, which is no endpoint here.</source>
        <translation>Eine CFX-Anfrage (%1) an „%2“, das hier kein Endpunkt ist.</translation>
    </message>
</context>
<context>
    <name>ChartCsv</name>
    <message>
        <location filename="../lib/model/recording/chartcsv.cpp" line="209"/>
        <source>the file could not be written whole: the disk is full or the file reached its size limit</source>
        <translation>die Datei konnte nicht vollständig geschrieben werden: der Datenträger ist voll oder die Datei hat ihre Größengrenze erreicht</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsv.cpp" line="213"/>
        <source>the file could not be written</source>
        <translation>die Datei konnte nicht geschrieben werden</translation>
    </message>
</context>
<context>
    <name>ChartCsvReader</name>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="99"/>
        <source>line %1: %2</source>
        <translation>Zeile %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="119"/>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="143"/>
        <source>the line is longer than %1 bytes (is this a chart CSV?)</source>
        <translation>die Zeile ist länger als %1 Bytes (ist das eine Diagramm-CSV-Datei?)</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="107"/>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="148"/>
        <source>the file holds binary data, not CSV text</source>
        <translation>die Datei enthält Binärdaten, keinen CSV-Text</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="154"/>
        <source>the text is not UTF-8 (save the file as &quot;CSV UTF-8&quot;)</source>
        <translation>der Text ist nicht UTF-8-kodiert (speichern Sie die Datei als &quot;CSV UTF-8&quot;)</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="158"/>
        <source>more than %1 comment lines (&quot;#&quot;); a recording has a few, and one per channel</source>
        <translation>mehr als %1 Kommentarzeilen („#“); eine Aufzeichnung hat wenige, und eine je Kanal</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="195"/>
        <source>the header row should start with &quot;time&quot; (is this a chart CSV written by TipScope?)</source>
        <translation>die Kopfzeile muss mit &quot;time&quot; beginnen (ist das eine von TipScope geschriebene Diagramm-CSV-Datei?)</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="198"/>
        <source>%1 columns; replay reads at most %2</source>
        <translation>%1 Spalten; die Wiedergabe liest höchstens %2</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="212"/>
        <source>column %1 &quot;%2&quot; is not &quot;port&lt;n&gt; &lt;series&gt; [unit]&quot; or &quot;feeder &lt;series&gt; [unit]&quot;</source>
        <translation>Spalte %1 &quot;%2&quot; ist weder &quot;port&lt;n&gt; &lt;Reihe&gt; [Einheit]&quot; noch &quot;feeder &lt;Reihe&gt; [Einheit]&quot;</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="225"/>
        <source>column %1 &quot;%2&quot;: the unit should be &quot;%3&quot;</source>
        <translation>Spalte %1 &quot;%2&quot;: die Einheit muss &quot;%3&quot; sein</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="228"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="258"/>
        <source>Feeder</source>
        <translation>Lotdrahtvorschub</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="259"/>
        <source>Port %1</source>
        <translation>Port %1</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="236"/>
        <source>column %1 &quot;%2&quot; appears twice</source>
        <translation>Spalte %1 &quot;%2&quot; kommt zweimal vor</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="244"/>
        <source>the header names no series columns</source>
        <translation>die Kopfzeile nennt keine Spalten mit Datenreihen</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="287"/>
        <source>column %1: &quot;%2&quot; is not a number</source>
        <translation>Spalte %1: &quot;%2&quot; ist keine Zahl</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="294"/>
        <source>%1 has values in some of its columns but not all</source>
        <translation>%1 hat nur in einem Teil seiner Spalten Werte</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="301"/>
        <source>%1 cells, but the header has %2 columns</source>
        <translation>%1 Zellen, aber die Kopfzeile hat %2 Spalten</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="306"/>
        <source>&quot;%1&quot; is not an ISO 8601 time</source>
        <translation>&quot;%1&quot; ist keine Zeitangabe nach ISO 8601</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="310"/>
        <source>the time %1 is earlier than the row before it (rows must be in time order)</source>
        <translation>die Zeit %1 liegt vor der der vorigen Zeile (die Zeilen müssen zeitlich geordnet sein)</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="322"/>
        <source>%1 has more than %2 samples, more than replay holds; split the file</source>
        <translation>%1 hat mehr als %2 Messwerte, mehr als die Wiedergabe fasst; teilen Sie die Datei auf</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="346"/>
        <source>the event &quot;%1&quot; is not &quot;&lt;channel&gt; &lt;kind&gt;: &lt;text&gt;&quot;</source>
        <translation>das Ereignis &quot;%1&quot; hat nicht die Form &quot;&lt;Kanal&gt; &lt;Art&gt;: &lt;Text&gt;&quot;</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="168"/>
        <source>a quoted cell is not closed</source>
        <translation>eine Zelle in Anführungszeichen ist nicht geschlossen</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="379"/>
        <source>the file has a header but no rows</source>
        <translation>die Datei hat eine Kopfzeile, aber keine Zeilen</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="377"/>
        <source>the file is empty or holds only comments</source>
        <translation>die Datei ist leer oder enthält nur Kommentare</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvreader.cpp" line="30"/>
        <source>the file is larger than %1 MB; replay reads files up to %1 MB</source>
        <translation>die Datei ist größer als %1 MB; die Wiedergabe liest Dateien bis %1 MB</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvreader.cpp" line="109"/>
        <source>its samples take %1 MB of memory after %2 MB read, more than replay allows (twice the file&apos;s size); a recording TipScope writes takes far less</source>
        <translation>ihre Messwerte belegen nach %2 MB Gelesenem %1 MB Speicher, mehr als die Wiedergabe erlaubt (das Doppelte der Dateigröße); eine von TipScope geschriebene Aufzeichnung braucht weit weniger</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvreader.cpp" line="146"/>
        <source>reading was cancelled</source>
        <translation>das Lesen wurde abgebrochen</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvreader.cpp" line="170"/>
        <source>the file is %1 MB; replay reads files up to %2 MB</source>
        <translation>die Datei ist %1 MB groß; die Wiedergabe liest Dateien bis %2 MB</translation>
    </message>
</context>
<context>
    <name>ChartRecorder</name>
    <message>
        <location filename="../lib/model/recording/chartrecorder.cpp" line="32"/>
        <source>nothing to record: no station or feeder is connected</source>
        <translation>nichts aufzuzeichnen: weder Station noch Lotdrahtvorschub verbunden</translation>
    </message>
</context>
<context>
    <name>ChartSeries</name>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="103"/>
        <source>Tip</source>
        <translation>Lötspitze</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="105"/>
        <source>Setpoint</source>
        <translation>Sollwert</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="107"/>
        <source>Power</source>
        <translation>Leistung</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="109"/>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="111"/>
        <source>Fed length</source>
        <translation>Vorgeschobene Länge</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="113"/>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="115"/>
        <source>Feeding</source>
        <translation>Vorschub</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="117"/>
        <source>Transistor</source>
        <translation>Transistor</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="119"/>
        <source>Transformer</source>
        <translation>Transformator</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="150"/>
        <source>Port %1</source>
        <translation>Port %1</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="165"/>
        <source>Feeder</source>
        <translation>Lotdrahtvorschub</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="44"/>
        <source>tip</source>
        <translation>Lötspitze</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="44"/>
        <source>P%1 tip</source>
        <translation>P%1 Lötspitze</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="45"/>
        <source>setpoint</source>
        <translation>Sollwert</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="46"/>
        <source>P%1 setpoint</source>
        <translation>P%1 Sollwert</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="47"/>
        <source>power</source>
        <translation>Leistung</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="48"/>
        <source>P%1 power</source>
        <translation>P%1 Leistung</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="49"/>
        <source>status</source>
        <translation>Status</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="50"/>
        <source>P%1 status</source>
        <translation>P%1 Status</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="51"/>
        <source>fed length</source>
        <translation>Vorgeschobene Länge</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="52"/>
        <source>speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="53"/>
        <source>feeding</source>
        <translation>Vorschub</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="54"/>
        <source>transistor</source>
        <translation>Transistor</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="55"/>
        <source>P%1 transistor</source>
        <translation>P%1 Transistor</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="56"/>
        <source>transformer</source>
        <translation>Transformator</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="131"/>
        <source>P%1 %2</source>
        <translation>P%1 %2</translation>
    </message>
</context>
<context>
    <name>CliBoard</name>
    <message>
        <location filename="../app/cli/cliboard.cpp" line="31"/>
        <source>give one of --json, --csv and --pdf FILE</source>
        <translation>nur eines von --json, --csv und --pdf DATEI angeben</translation>
    </message>
    <message>
        <location filename="../app/cli/cliboard.cpp" line="33"/>
        <source>board takes one board serial</source>
        <translation>board nimmt eine Platinen-Seriennummer</translation>
    </message>
    <message>
        <location filename="../app/cli/cliboard.cpp" line="57"/>
        <source>the journal has no board &apos;%1&apos;: no joint or event carries that serial</source>
        <translation>das Journal kennt keine Platine &apos;%1&apos;: keine Lötstelle und kein Ereignis trägt diese Seriennummer</translation>
    </message>
</context>
<context>
    <name>CliCommands</name>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="43"/>
        <source>tipscope-cli: %1: %2</source>
        <translation>tipscope-cli: %1: %2</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="67"/>
        <source>%1 unreadable data field &apos;%2&apos;</source>
        <translation>%1 unlesbares Datenfeld &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="106"/>
        <source>tipscope-cli: read needs at least one command code, e.g. read ST1</source>
        <translation>tipscope-cli: read braucht mindestens einen Befehlscode, z. B. read ST1</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="119"/>
        <source>tipscope-cli: no device here can read &apos;%1&apos;</source>
        <translation>tipscope-cli: kein Gerät an dieser Leitung kann &apos;%1&apos; lesen</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="144"/>
        <source>%1 written</source>
        <translation>%1 geschrieben</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="158"/>
        <source>tipscope-cli: %1 was accepted but could not be read back: %2</source>
        <translation>tipscope-cli: %1 wurde angenommen, konnte aber nicht zurückgelesen werden: %2</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="164"/>
        <source>tipscope-cli: verification failed: wrote %1, the device reports %2</source>
        <translation>tipscope-cli: Prüfung fehlgeschlagen: %1 geschrieben, das Gerät meldet %2</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="171"/>
        <source>%1 (verified)</source>
        <translation>%1 (geprüft)</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="187"/>
        <source>the device answered &apos;%1&apos;, which is no value</source>
        <translation>das Gerät antwortete &apos;%1&apos;, was kein Wert ist</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="208"/>
        <source>tipscope-cli: refused, nothing was sent: %1 is bounded by %2, which could not be read: %3</source>
        <translation>tipscope-cli: abgelehnt, nichts wurde gesendet: %1 ist durch %2 begrenzt, das nicht gelesen werden konnte: %3</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="239"/>
        <source>%1 (--force sends it anyway)</source>
        <translation>%1 (--force sendet es trotzdem)</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="250"/>
        <source>tipscope-cli: write takes CODE VALUE, e.g. write ST1 350</source>
        <translation>tipscope-cli: write erwartet CODE WERT, z. B. write ST1 350</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="259"/>
        <source>tipscope-cli: no device here accepts writes of &apos;%1&apos;</source>
        <translation>tipscope-cli: kein Gerät an dieser Leitung nimmt Schreibzugriffe auf &apos;%1&apos; an</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="232"/>
        <source>the data field must be printable ASCII</source>
        <translation>das Datenfeld darf nur druckbare ASCII-Zeichen enthalten</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="235"/>
        <source>the data field is longer than 32 characters</source>
        <translation>das Datenfeld ist länger als 32 Zeichen</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="216"/>
        <location filename="../app/cli/clicommands.cpp" line="289"/>
        <location filename="../app/cli/clicommands.cpp" line="315"/>
        <source>tipscope-cli: refused, nothing was sent: %1</source>
        <translation>tipscope-cli: abgelehnt, nichts wurde gesendet: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="306"/>
        <source>tipscope-cli: send takes the frame in hex, e.g. send 02 30 30 30 31 52 53 4D 4E 03 02</source>
        <translation>tipscope-cli: send erwartet das Telegramm hexadezimal, z. B. send 02 30 30 30 31 52 53 4D 4E 03 02</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="381"/>
        <source>tipscope-cli: unknown family &apos;%1&apos;; known: %2</source>
        <translation>tipscope-cli: unbekannte Familie &apos;%1&apos;; bekannt sind: %2</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="404"/>
        <source> [dangerous]</source>
        <translation> [gefährlich]</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="407"/>
        <source>values: %1</source>
        <translation>Werte: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="409"/>
        <source>families: %1</source>
        <translation>Familien: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/cli/clicommands.cpp" line="55"/>
        <source>%n raw byte(s), not a frame (%1)</source>
        <translation>
            <numerusform>%n Rohbyte, kein Telegramm (%1)</numerusform>
            <numerusform>%n Rohbytes, kein Telegramm (%1)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>CliContext</name>
    <message>
        <location filename="../app/cli/clicontext.cpp" line="44"/>
        <source>&apos;%1&apos; is not a context line: write work_order=W, board_serial=S or operator=O</source>
        <translation>„%1“ ist keine Kontextzeile: schreiben Sie work_order=W, board_serial=S oder operator=O</translation>
    </message>
    <message>
        <location filename="../app/cli/clicontext.cpp" line="60"/>
        <source>cannot read standard input</source>
        <translation>die Standardeingabe kann nicht gelesen werden</translation>
    </message>
    <message>
        <location filename="../app/cli/clicontext.cpp" line="95"/>
        <source>tipscope-cli: refused, nothing was changed: %1</source>
        <translation>tipscope-cli: abgelehnt, nichts wurde geändert: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/clicontext.cpp" line="100"/>
        <source>tipscope-cli: context takes show, set [--work-order W] [--serial S] [--operator O] [--stdin], or clear</source>
        <translation>tipscope-cli: context nimmt show, set [--work-order W] [--serial S] [--operator O] [--stdin] oder clear</translation>
    </message>
    <message>
        <location filename="../app/cli/clicontext.cpp" line="133"/>
        <source>tipscope-cli: limits takes show, set RULE (such as port=1,tool=C245,recovery=3.5,dip=60) or clear</source>
        <translation>tipscope-cli: limits nimmt show, set REGEL (etwa port=1,tool=C245,recovery=3.5,dip=60) oder clear</translation>
    </message>
</context>
<context>
    <name>CliJoints</name>
    <message>
        <location filename="../app/cli/clijoints.cpp" line="42"/>
        <source>&apos;%1&apos; is not a time: write 24h, 30m, 7d, 2026-12-01 or 2026-12-01T08:00</source>
        <translation>„%1“ ist keine Zeitangabe: schreiben Sie 24h, 30m, 7d, 2026-12-01 oder 2026-12-01T08:00</translation>
    </message>
    <message>
        <location filename="../app/cli/clijoints.cpp" line="67"/>
        <source>the journal has no device &apos;%1&apos;</source>
        <translation>das Journal kennt kein Gerät „%1“</translation>
    </message>
    <message>
        <location filename="../app/cli/clijoints.cpp" line="68"/>
        <source>&apos;%1&apos; names %2 devices; give one of:
  %3</source>
        <translation>„%1“ bezeichnet %2 Geräte; geben Sie eines davon an:
  %3</translation>
    </message>
    <message>
        <location filename="../app/cli/clijoints.cpp" line="96"/>
        <source>--port takes a port number from 1 to 4</source>
        <translation>--port nimmt eine Portnummer von 1 bis 4</translation>
    </message>
    <message>
        <location filename="../app/cli/clijoints.cpp" line="105"/>
        <source>--verdict takes ok, slow-recovery, too-deep or incomplete</source>
        <translation>--verdict nimmt ok, slow-recovery, too-deep oder incomplete</translation>
    </message>
    <message>
        <location filename="../app/cli/clijoints.cpp" line="156"/>
        <source>tipscope-cli: give --json or --csv, not both</source>
        <translation>tipscope-cli: geben Sie --json oder --csv an, nicht beides</translation>
    </message>
</context>
<context>
    <name>CliJournal</name>
    <message>
        <location filename="../app/cli/clijournal.cpp" line="75"/>
        <source>tipscope-cli: journal retention takes a number of days (0 keeps everything), for example: journal retention 90</source>
        <translation>tipscope-cli: journal retention erwartet eine Anzahl Tage (0 behält alles), zum Beispiel: journal retention 90</translation>
    </message>
    <message>
        <location filename="../app/cli/clijournal.cpp" line="94"/>
        <source>tipscope-cli: the retention could not be stored: %1</source>
        <translation>tipscope-cli: die Aufbewahrungsdauer konnte nicht gespeichert werden: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/clijournal.cpp" line="110"/>
        <source>tipscope-cli: journal takes show or retention DAYS</source>
        <translation>tipscope-cli: journal erwartet show oder retention TAGE</translation>
    </message>
</context>
<context>
    <name>CliMeasure</name>
    <message>
        <location filename="../app/cli/climeasure.cpp" line="70"/>
        <source>tipscope-cli: measure takes one FILE, a recording (record, or the Charts page&apos;s Record or CSV export)</source>
        <translation>tipscope-cli: measure erwartet eine DATEI, eine Aufzeichnung (von record oder von „Aufzeichnen“ bzw. dem CSV-Export der Diagrammseite)</translation>
    </message>
    <message>
        <location filename="../app/cli/climeasure.cpp" line="81"/>
        <source>%1 is a FIFO: waiting for what is written into it (Ctrl-C stops)</source>
        <translation>%1 ist ein FIFO: es wird gewartet, bis etwas hineingeschrieben wird (Strg+C beendet)</translation>
    </message>
</context>
<context>
    <name>CliMonitor</name>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="186"/>
        <source>tipscope-cli: --interval takes milliseconds (0: as fast as the line allows)</source>
        <translation>tipscope-cli: --interval erwartet Millisekunden (0: so schnell, wie die Leitung erlaubt)</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="312"/>
        <source>tipscope-cli: --duration takes seconds</source>
        <translation>tipscope-cli: --duration erwartet Sekunden</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="279"/>
        <source>tipscope-cli: monitor needs a station; none was found</source>
        <translation>tipscope-cli: monitor braucht eine Station; keine gefunden</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="237"/>
        <location filename="../app/cli/climonitorcsv.cpp" line="25"/>
        <source>tipscope-cli: cannot write %1: %2</source>
        <translation>tipscope-cli: %1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="78"/>
        <source>P%1 --</source>
        <translation>P%1 --</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="102"/>
        <source>tipscope-cli: writing %1 failed: %2; monitoring goes on without it</source>
        <translation>tipscope-cli: %1 zu schreiben ist fehlgeschlagen: %2; die Überwachung geht ohne die Datei weiter</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="169"/>
        <source>reconnected to %1</source>
        <translation>wieder verbunden mit %1</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="203"/>
        <source>tipscope-cli: the workspace %1 has no lines</source>
        <translation>tipscope-cli: der Arbeitsbereich %1 hat keine Linien</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="238"/>
        <source>permission denied</source>
        <translation>keine Berechtigung</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="239"/>
        <source>no such folder</source>
        <translation>diesen Ordner gibt es nicht</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="246"/>
        <source>tipscope-cli: lines %1 and %2 would both write %3; rename one</source>
        <translation>tipscope-cli: die Leitungen %1 und %2 würden beide %3 schreiben; benennen Sie eine um</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="411"/>
        <source>%1 records could not be kept in the journal %2: %3</source>
        <translation>%1 Einträge konnten nicht im Journal %2 gespeichert werden: %3</translation>
    </message>
</context>
<context>
    <name>CliMonitorMqtt</name>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="46"/>
        <source>--cfx takes the AMQP broker as amqp://HOST:PORT or amqps://HOST:PORT (the user with --cfx-user, the password from %1)</source>
        <translation>--cfx erwartet den AMQP-Broker als amqp://HOST:PORT oder amqps://HOST:PORT (den Benutzer mit --cfx-user, das Passwort aus %1)</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="58"/>
        <source>--cfx-address takes RabbitMQ&apos;s form: /exchange/NAME, /exchange/NAME/KEY or /queue/NAME</source>
        <translation>--cfx-address erwartet die Form von RabbitMQ: /exchange/NAME, /exchange/NAME/KEY oder /queue/NAME</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="64"/>
        <source>--cfx-requests takes a queue of the broker: /queue/NAME</source>
        <translation>--cfx-requests erwartet eine Warteschlange des Brokers: /queue/NAME</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="82"/>
        <source>--mqtt takes the broker as HOST:PORT</source>
        <translation>--mqtt erwartet den Broker als HOST:PORT</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="94"/>
        <source>--site takes the site&apos;s name</source>
        <translation>--site erwartet den Namen des Standorts</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="100"/>
        <source>--interval takes milliseconds from 100 to 3600000</source>
        <translation>--interval erwartet Millisekunden von 100 bis 3600000</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="130"/>
        <location filename="../app/cli/climonitormqtt.cpp" line="156"/>
        <source>Broker connected.</source>
        <translation>Broker verbunden.</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="132"/>
        <source>Broker disconnected.</source>
        <translation>Broker getrennt.</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="134"/>
        <location filename="../app/cli/climonitormqtt.cpp" line="157"/>
        <source>Connecting to the broker.</source>
        <translation>Verbindung zum Broker wird aufgebaut.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/cli/climonitormqtt.cpp" line="136"/>
        <source>%n device(s), %1 live messages, %2 joints and events forwarded, %3 waiting. %4</source>
        <translation>
            <numerusform>%n Gerät, %1 Live-Nachrichten, %2 Lötstellen und Ereignisse weitergeleitet, %3 wartend. %4</numerusform>
            <numerusform>%n Geräte, %1 Live-Nachrichten, %2 Lötstellen und Ereignisse weitergeleitet, %3 wartend. %4</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="153"/>
        <source>CFX: %1 messages from the journal accepted, %2 waiting. %3</source>
        <translation>CFX: %1 Nachrichten aus dem Journal angenommen, %2 warten. %3</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="184"/>
        <source>tipscope-cli: %1 is not set: connecting as %2 without a password</source>
        <translation>tipscope-cli: %1 ist nicht gesetzt: Verbindung als %2 ohne Passwort</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="192"/>
        <source>tipscope-cli: --duration takes seconds</source>
        <translation>tipscope-cli: --duration erwartet Sekunden</translation>
    </message>
</context>
<context>
    <name>CliParser</name>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="164"/>
        <source>unknown command &apos;%1&apos;</source>
        <translation>unbekannter Befehl &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="208"/>
        <source>give only one of --port, --tcp and --demo</source>
        <translation>geben Sie nur eine der Optionen --port, --tcp und --demo an</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="214"/>
        <source>--workspace takes a file, and only one of --port, --tcp, --demo, --workspace</source>
        <translation>--workspace erwartet eine Datei, und nur eines von --port, --tcp, --demo, --workspace</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="221"/>
        <source>--port takes a device, and only one of --port, --tcp, --demo</source>
        <translation>--port erwartet ein Gerät, und nur eine der Optionen --port, --tcp, --demo</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="229"/>
        <source>--tcp takes HOST:PORT, and only one of --port, --tcp, --demo</source>
        <translation>--tcp erwartet HOST:PORT, und nur eine der Optionen --port, --tcp, --demo</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="234"/>
        <source>--baud takes a rate such as 19200</source>
        <translation>--baud erwartet eine Baudrate wie 19200</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="241"/>
        <source>--parity takes none, even or odd</source>
        <translation>--parity erwartet none, even oder odd</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="245"/>
        <source>--stop-bits takes 1 or 2</source>
        <translation>--stop-bits erwartet 1 oder 2</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="254"/>
        <source>--addr takes SRC:TGT, two addresses from 00 to 99 (e.g. 00:01)</source>
        <translation>--addr erwartet QUELLE:ZIEL, zwei Adressen von 00 bis 99 (z. B. 00:01)</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="262"/>
        <source>--timeout takes milliseconds from 1 to 60000</source>
        <translation>--timeout erwartet Millisekunden von 1 bis 60000</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="265"/>
        <source>--retries takes a number from 0 to 10</source>
        <translation>--retries erwartet eine Zahl von 0 bis 10</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="193"/>
        <source>--%1 needs a value</source>
        <translation>--%1 braucht einen Wert</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="85"/>
        <source>Usage: tipscope-cli [--port DEVICE | --tcp HOST:PORT | --demo | --demo-activity |
                     --workspace FILE] [--baud N]
                    [--parity none|even|odd] [--stop-bits 1|2] [--addr SRC:TGT | --no-addr]
                    [--timeout MS] [--retries N] [--verbose] COMMAND ...

Commands:
  detect [--json] [--scan]  one line per device: &quot;&lt;address or --&gt; &lt;model&gt; &lt;family&gt; &lt;version&gt;&quot;
  read CODE... [--raw]      one line per code: &quot;&lt;CODE&gt; &lt;value&gt; &lt;unit&gt;&quot;
  write CODE VALUE [--raw [--force]]
                            validate (MIT and MAT read first), send, and read back;
                            --raw sends the data field, checked unless --force
  send HEX                  send a raw frame; print the answer in hex and decoded
  monitor [--interval MS] [--duration S] [--csv FILE [--csv-one-file]]
          [--limit RULE] [--journal FILE]
                            tip temperature, setpoint, power and status per port, and
                            a line per joint, each joint kept in the journal
  monitor --mqtt HOST:PORT [--mqtt-user U] [--site S] [--interval MS] [--duration S]
                            publish the lines to an MQTT broker as tipscope-agent does
                            (docs/mqtt.md); the password from TIPSCOPE_MQTT_PASSWORD
  monitor --cfx amqp[s]://HOST:PORT [--cfx-user U] [--cfx-address ADDRESS]
          [--cfx-requests /queue/NAME]
                            every station as an IPC-CFX endpoint (docs/cfx.md), beside
                            --mqtt or alone; the password from TIPSCOPE_CFX_PASSWORD
  dump [--json]             every readable parameter, counter and error
  commands [--family F]     the command catalog
  profile save FILE         every writable setting of the device to a JSON profile
  profile diff FILE         what applying the profile would change
  profile apply FILE [--dry-run] [--force]
                            write what differs, each value read back; --dry-run lists
                            the frames; --force applies a profile of another family
  record FILE [--duration S]
                            every port&apos;s and the feeder&apos;s curves and events to a chart
                            recording, as the Charts page records them
  measure FILE [--json]     the heat-ups and recoveries of a recording, one line each
  joints [--since T] [--until T] [--device D] [--port N] [--tool T]
         [--verdict V] [--work-order W] [--json | --csv] [--journal FILE]
                            the joints the journal keeps, newest first; T is 24h, 30m,
                            7d or an ISO date and time; V is ok, slow-recovery,
                            too-deep or incomplete
  context [show | clear | set [--work-order W] [--serial S] [--operator O] [--stdin]]
                            the work context stamped on every joint and event
  limits [show | clear | set RULE]
                            the joint limits; RULE is port=N,tool=T,recovery=S,dip=K,
                            wear=SHARE (any of them; the most specific rule wins)
  journal [show [--json] | retention DAYS] [--journal FILE]
                            what the journal holds, and how many days it keeps
                            records (0: all); every TipScope program shares it
  board SERIAL [--json | --csv | --pdf FILE] [--journal FILE]
                            one board&apos;s record: every joint stamped with the board
                            serial, its tools&apos; wear, the events while it was made;
                            --csv its joints as joints --csv; --pdf a document to sign

Without --addr or --no-addr the device is found automatically. --demo talks to the
built-in simulated DME station (address 01) and SFR feeder (address 10);
--demo-activity the same at work: joints on port 1 every 15 s, rests on port 2, feeds.
--timeout is the device turnaround added to the wire time of each request.
--workspace runs the command on every line of a workspace file at once, each output
line prefixed with the line&apos;s name; monitor --csv writes a file per line.

Exit codes: 0 ok; 1 usage, or a board serial the journal does not hold; 2 value
refused before sending (nothing was written); 3 the device answered NAK, or a
read-back or profile check failed; 4 no valid answer; 5 transport error; the journal
(joints, board, journal show): 6 missing, 7 damaged, 8 newer, 9 locked, 10 not
accessible, 11 disk full or failing.
</source>
        <translation>Aufruf: tipscope-cli [--port GERÄT | --tcp HOST:PORT | --demo | --demo-activity |
                      --workspace DATEI] [--baud N]
                     [--parity none|even|odd] [--stop-bits 1|2] [--addr QUELLE:ZIEL | --no-addr]
                     [--timeout MS] [--retries N] [--verbose] BEFEHL ...

Befehle:
  detect [--json] [--scan]  eine Zeile pro Gerät: &quot;&lt;Adresse oder --&gt; &lt;Modell&gt; &lt;Familie&gt; &lt;Version&gt;&quot;
  read CODE... [--raw]      eine Zeile pro Code: &quot;&lt;CODE&gt; &lt;Wert&gt; &lt;Einheit&gt;&quot;
  write CODE WERT [--raw [--force]]
                            prüfen (MIT und MAT zuerst gelesen), senden und zurücklesen;
                            --raw sendet das Datenfeld, geprüft außer mit --force
  send HEX                  ein Roh-Telegramm senden; die Antwort hexadezimal und dekodiert ausgeben
  monitor [--interval MS] [--duration S] [--csv DATEI [--csv-one-file]]
          [--limit REGEL] [--journal DATEI]
                            Spitzentemperatur, Sollwert, Leistung und Status pro Port und
                            eine Zeile je Lötstelle; jede Lötstelle kommt ins Journal
  monitor --mqtt HOST:PORT [--mqtt-user U] [--site S] [--interval MS] [--duration S]
                            veröffentlicht die Linien an einen MQTT-Broker wie
                            tipscope-agent (docs/mqtt.md); Passwort aus TIPSCOPE_MQTT_PASSWORD
  monitor --cfx amqp[s]://HOST:PORT [--cfx-user U] [--cfx-address ADRESSE]
          [--cfx-requests /queue/NAME]
                            jede Station als IPC-CFX-Endpunkt (docs/cfx.md), neben
                            --mqtt oder allein; Passwort aus TIPSCOPE_CFX_PASSWORD
  dump [--json]             alle lesbaren Parameter, Zähler und Fehler
  commands [--family F]     der Befehlskatalog
  profile save DATEI        alle beschreibbaren Einstellungen des Geräts in ein JSON-Profil
  profile diff DATEI        was das Anwenden des Profils ändern würde
  profile apply DATEI [--dry-run] [--force]
                            schreiben, was abweicht, jeden Wert zurücklesen; --dry-run
                            listet die Telegramme auf; --force wendet ein Profil einer
                            anderen Familie an
  record DATEI [--duration S]
                            die Kurven und Ereignisse aller Ports und des Vorschubs als
                            Diagrammaufzeichnung, wie die Diagrammseite sie aufzeichnet
  measure DATEI [--json]    Aufheiz- und Erholzeiten einer Aufzeichnung, eine pro Zeile
  joints [--since T] [--until T] [--device D] [--port N] [--tool T]
         [--verdict V] [--work-order W] [--json | --csv] [--journal DATEI]
                            die Lötstellen im Journal, die neuesten zuerst; T ist 24h, 30m,
                            7d oder ein ISO-Datum mit Uhrzeit; V ist ok, slow-recovery,
                            too-deep oder incomplete
  context [show | clear | set [--work-order W] [--serial S] [--operator O] [--stdin]]
                            der Arbeitskontext, der jeder Lötstelle und jedem Ereignis
                            mitgegeben wird
  limits [show | clear | set REGEL]
                            die Lötstellen-Grenzwerte; REGEL ist port=N,tool=T,recovery=S,
                            dip=K,wear=ANTEIL (beliebig davon; die genaueste Regel gilt)
  journal [show [--json] | retention TAGE] [--journal DATEI]
                            was das Journal enthält und wie viele Tage es
                            Einträge behält (0: alle); alle TipScope-Programme teilen es
  board SERIENNR [--json | --csv | --pdf DATEI] [--journal DATEI]
                            der Bericht einer Platine: jede Lötstelle mit ihrer Serien-
                            nummer, der Verschleiß ihrer Spitzen, die Ereignisse dabei;
                            --csv ihre Lötstellen wie joints --csv; --pdf ein Dokument
                            zum Unterschreiben

Ohne --addr oder --no-addr wird das Gerät automatisch gesucht. --demo spricht mit der
eingebauten simulierten DME-Station (Adresse 01) und dem SFR-Lotdrahtvorschub (Adresse 10);
--demo-activity dasselbe bei der Arbeit: Lötstellen an Port 1 alle 15 s, Pausen an Port 2, Vorschübe.
--timeout ist die Antwortzeit des Geräts, die zur Übertragungszeit jeder Anfrage addiert wird.
--workspace führt den Befehl auf jeder Leitung einer Arbeitsbereich-Datei zugleich aus,
jede Ausgabezeile mit dem Namen der Leitung davor; monitor --csv schreibt eine Datei pro Leitung.

Exit-Codes: 0 OK; 1 Aufruffehler, oder eine Platinen-Seriennummer, die das Journal nicht
kennt; 2 Wert vor dem Senden abgelehnt (nichts geschrieben); 3 das Gerät hat mit NAK
geantwortet, oder Zurücklesen oder Profilprüfung fehlgeschlagen; 4 keine gültige Antwort;
5 Übertragungsfehler; das Journal (joints, board, journal show): 6 fehlt, 7 beschädigt,
8 neuer, 9 gesperrt, 10 nicht zugänglich, 11 Datenträger voll oder fehlerhaft.
</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="197"/>
        <source>--%1 takes no value</source>
        <translation>--%1 nimmt keinen Wert an</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="269"/>
        <source>unknown option --%1</source>
        <translation>unbekannte Option --%1</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="270"/>
        <source>&apos;%1&apos; has no option --%2</source>
        <translation>&apos;%1&apos; hat keine Option --%2</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="276"/>
        <source>no command given</source>
        <translation>kein Befehl angegeben</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="279"/>
        <source>--workspace runs detect, monitor, dump or joints, not %1</source>
        <translation>--workspace führt detect, monitor, dump oder joints aus, nicht %1</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="282"/>
        <source>--csv-one-file goes with --workspace and --csv FILE</source>
        <translation>--csv-one-file gehört zu --workspace und --csv DATEI</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="285"/>
        <source>say where the device is: --port DEVICE, --tcp HOST:PORT or --demo</source>
        <translation>geben Sie an, wo das Gerät ist: --port GERÄT, --tcp HOST:PORT oder --demo</translation>
    </message>
</context>
<context>
    <name>CliProfile</name>
    <message>
        <location filename="../app/cli/cliprofile.cpp" line="43"/>
        <source>tipscope-cli: could not read %1; no profile written</source>
        <translation>tipscope-cli: %1 konnte nicht gelesen werden; kein Profil geschrieben</translation>
    </message>
    <message>
        <location filename="../app/cli/cliprofile.cpp" line="52"/>
        <source>saved %1 settings of %2 to %3</source>
        <translation>%1 Einstellungen von %2 in %3 gespeichert</translation>
    </message>
    <message>
        <location filename="../app/cli/cliprofile.cpp" line="66"/>
        <source>tipscope-cli: profile takes save FILE, diff FILE or apply FILE</source>
        <translation>tipscope-cli: profile erwartet save DATEI, diff DATEI oder apply DATEI</translation>
    </message>
    <message>
        <location filename="../app/cli/cliprofile.cpp" line="113"/>
        <source>tipscope-cli: applying this profile would be refused: %1</source>
        <translation>tipscope-cli: das Anwenden dieses Profils würde abgelehnt: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/cliprofile.cpp" line="119"/>
        <source>tipscope-cli: the line was dropped during the apply: %1. A slow station may need a longer --timeout (now %2 ms) or more --retries (now %3); apply the profile again once the line answers: what is already right is left alone</source>
        <translation>tipscope-cli: die Leitung wurde während des Anwendens getrennt: %1. Eine langsame Station braucht vielleicht ein längeres --timeout (jetzt %2 ms) oder mehr --retries (jetzt %3); wenden Sie das Profil erneut an, sobald die Leitung antwortet: was schon stimmt, bleibt unberührt</translation>
    </message>
</context>
<context>
    <name>CliRecord</name>
    <message>
        <location filename="../app/cli/clirecord.cpp" line="58"/>
        <source>tipscope-cli: interrupted before the recording started</source>
        <translation>tipscope-cli: abgebrochen, bevor die Aufzeichnung begann</translation>
    </message>
    <message>
        <location filename="../app/cli/clirecord.cpp" line="64"/>
        <source>tipscope-cli: cannot open %1: %2</source>
        <translation>tipscope-cli: %1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <location filename="../app/cli/clirecord.cpp" line="99"/>
        <source>tipscope-cli: record takes one FILE, e.g. record line3.csv --duration 60</source>
        <translation>tipscope-cli: record erwartet eine DATEI, z. B. record linie3.csv --duration 60</translation>
    </message>
    <message>
        <location filename="../app/cli/clirecord.cpp" line="108"/>
        <source>tipscope-cli: --duration takes seconds (0: until interrupted)</source>
        <translation>tipscope-cli: --duration erwartet Sekunden (0: bis zum Abbruch)</translation>
    </message>
    <message>
        <location filename="../app/cli/clirecord.cpp" line="116"/>
        <location filename="../app/cli/clirecord.cpp" line="143"/>
        <source>tipscope-cli: cannot record to %1: %2</source>
        <translation>tipscope-cli: in %1 kann nicht aufgezeichnet werden: %2</translation>
    </message>
    <message>
        <location filename="../app/cli/clirecord.cpp" line="117"/>
        <source>no such folder</source>
        <translation>Ordner nicht vorhanden</translation>
    </message>
    <message>
        <location filename="../app/cli/clirecord.cpp" line="118"/>
        <source>not writable</source>
        <translation>nicht beschreibbar</translation>
    </message>
    <message>
        <location filename="../app/cli/clirecord.cpp" line="165"/>
        <source># recording %1 of %2 to %3</source>
        <translation># zeichne %1 von %2 in %3 auf</translation>
    </message>
    <message>
        <location filename="../app/cli/clirecord.cpp" line="173"/>
        <source>tipscope-cli: writing %1 failed: %2</source>
        <translation>tipscope-cli: Schreiben von %1 fehlgeschlagen: %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/cli/clirecord.cpp" line="178"/>
        <source>recorded %n row(s) to %1</source>
        <translation>
            <numerusform>%n Zeile nach %1 aufgezeichnet</numerusform>
            <numerusform>%n Zeilen nach %1 aufgezeichnet</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>CliSession</name>
    <message>
        <location filename="../app/cli/clisession.cpp" line="78"/>
        <source>tipscope-cli: cannot open %1: %2</source>
        <translation>tipscope-cli: %1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <location filename="../app/cli/clisession.cpp" line="132"/>
        <source>tipscope-cli: %1</source>
        <translation>tipscope-cli: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/clisession.cpp" line="155"/>
        <source>tipscope-cli: the line was lost: %1</source>
        <translation>tipscope-cli: die Leitung ist verloren gegangen: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/clisession.cpp" line="161"/>
        <source>tipscope-cli: no device could be identified on %1 (checked addresses 01, 10, 20 and frames without addresses); what came back: %2. Check the baud rate, the addressing, and that robot mode is on.</source>
        <translation>tipscope-cli: an %1 ließ sich kein Gerät erkennen (geprüft: Adressen 01, 10, 20 und Rahmen ohne Adressen); zurück kam: %2. Prüfen Sie die Baudrate, die Adressierung und ob der Robotermodus eingeschaltet ist.</translation>
    </message>
    <message>
        <location filename="../app/cli/clisession.cpp" line="170"/>
        <source>tipscope-cli: no device answered on %1 (checked addresses 01, 10, 20 and frames without addresses). Check the cable, the baud rate, and that robot mode is on.</source>
        <translation>tipscope-cli: kein Gerät hat an %1 geantwortet (geprüft wurden die Adressen 01, 10, 20 und Telegramme ohne Adressen). Prüfen Sie das Kabel, die Baudrate und ob der Robotermodus eingeschaltet ist.</translation>
    </message>
</context>
<context>
    <name>CliWorkspace</name>
    <message>
        <location filename="../app/cli/cliworkspace.cpp" line="152"/>
        <source>tipscope-cli: the workspace %1 has no lines</source>
        <translation>tipscope-cli: der Arbeitsbereich %1 hat keine Leitungen</translation>
    </message>
</context>
<context>
    <name>ConsoleModel</name>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="102"/>
        <source>sent as typed (not a valid frame)</source>
        <translation>unverändert gesendet (kein gültiges Telegramm)</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="118"/>
        <source>stray: answers no pending request</source>
        <translation>verwaist: beantwortet keine offene Anfrage</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="250"/>
        <source>TX</source>
        <translation>TX</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="252"/>
        <source>RX chunk</source>
        <translation>RX-Block</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="254"/>
        <source>RX</source>
        <translation>RX</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="256"/>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="258"/>
        <source>note</source>
        <translation>Hinweis</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="266"/>
        <source>Read</source>
        <translation>Lesen</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="268"/>
        <source>Write</source>
        <translation>Schreiben</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="270"/>
        <source>Answer</source>
        <translation>Antwort</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="315"/>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="315"/>
        <source>bad</source>
        <translation>falsch</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="331"/>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="331"/>
        <source>Dir</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="332"/>
        <source>Addr</source>
        <translation>Adr.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="332"/>
        <source>Header</source>
        <translation>Kopf</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="333"/>
        <source>Cmd</source>
        <translation>Befehl</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="333"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="334"/>
        <source>Data</source>
        <translation>Daten</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="334"/>
        <source>BCC</source>
        <translation>BCC</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="335"/>
        <source>Hex</source>
        <translation>Hex</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="335"/>
        <source>ASCII</source>
        <translation>ASCII</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="336"/>
        <source>Remark</source>
        <translation>Bemerkung</translation>
    </message>
</context>
<context>
    <name>DeviceIdentity</name>
    <message>
        <location filename="../lib/model/context/deviceidentity.cpp" line="73"/>
        <source>%1 at %2</source>
        <translation>%1 an Adresse %2</translation>
    </message>
    <message>
        <location filename="../lib/model/context/deviceidentity.cpp" line="76"/>
        <source>software unknown</source>
        <translation>Software unbekannt</translation>
    </message>
    <message>
        <location filename="../lib/model/context/deviceidentity.cpp" line="77"/>
        <source>software %1</source>
        <translation>Software %1</translation>
    </message>
    <message>
        <location filename="../lib/model/context/deviceidentity.cpp" line="78"/>
        <source>%1 on %2, %3</source>
        <translation>%1 über %2, %3</translation>
    </message>
</context>
<context>
    <name>DeviceModel</name>
    <message>
        <location filename="../lib/model/device/devicemodel.cpp" line="69"/>
        <source>%1 at %2</source>
        <translation>%1, Adresse %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/devicemodel.cpp" line="70"/>
        <source>%1 (no address)</source>
        <translation>%1 (ohne Adresse)</translation>
    </message>
    <message>
        <location filename="../lib/model/device/devicemodel.cpp" line="74"/>
        <location filename="../lib/model/device/devicemodel.cpp" line="157"/>
        <source>%1, port %2</source>
        <translation>%1, Port %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/devicemodel.cpp" line="217"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/devicemodel.cpp" line="119"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../lib/model/device/devicemodel.cpp" line="143"/>
        <source>tool %1</source>
        <translation>Werkzeug %1</translation>
    </message>
    <message>
        <location filename="../lib/model/device/devicemodel.cpp" line="154"/>
        <source>%1, %2, port %3</source>
        <translation>%1, %2, Port %3</translation>
    </message>
    <message>
        <location filename="../lib/model/device/devicemodel.cpp" line="160"/>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/devicemodel.cpp" line="203"/>
        <source>Monitor-only mode is on: nothing is written.</source>
        <translation>Nur-Beobachten ist an: nichts wird geschrieben.</translation>
    </message>
    <message>
        <location filename="../lib/model/device/devicemodel.cpp" line="205"/>
        <source>Not connected: nothing can be sent until the line is back.</source>
        <translation>Nicht verbunden: nichts kann gesendet werden, bis die Leitung wieder da ist.</translation>
    </message>
</context>
<context>
    <name>DisplayUnits</name>
    <message>
        <location filename="../lib/model/device/displayunits.cpp" line="81"/>
        <source>&apos;%1&apos; is not a number</source>
        <translation>&apos;%1&apos; ist keine Zahl</translation>
    </message>
    <message>
        <location filename="../lib/model/device/displayunits.cpp" line="86"/>
        <source>&apos;%1&apos; is far outside what %2 can take</source>
        <translation>&apos;%1&apos; liegt weit außerhalb dessen, was %2 zulässt</translation>
    </message>
    <message>
        <location filename="../lib/model/device/displayunits.cpp" line="93"/>
        <source>%1 lies between the values %2 can take: %3 or %4</source>
        <translation>%1 liegt zwischen den Werten, die %2 annehmen kann: %3 oder %4</translation>
    </message>
</context>
<context>
    <name>Elide</name>
    <message>
        <location filename="../lib/protocol/elide.cpp" line="39"/>
        <source>%1… (%2 characters)</source>
        <translation>%1… (%2 Zeichen)</translation>
    </message>
</context>
<context>
    <name>Event</name>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="50"/>
        <source>Station error</source>
        <translation>Stationsfehler</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="52"/>
        <source>Port error</source>
        <translation>Portfehler</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="54"/>
        <source>Feeder error</source>
        <translation>Vorschubfehler</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="56"/>
        <source>Alarm</source>
        <translation>Alarm</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="58"/>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="60"/>
        <source>Write</source>
        <translation>Schreiben</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="62"/>
        <source>Communication</source>
        <translation>Kommunikation</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="64"/>
        <source>Connection</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="66"/>
        <source>Tool change</source>
        <translation>Werkzeugwechsel</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="68"/>
        <source>Joint</source>
        <translation>Lötstelle</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="70"/>
        <source>Profile apply</source>
        <translation>Profil angewendet</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="72"/>
        <source>Work context</source>
        <translation>Arbeitskontext</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="74"/>
        <source>Journal</source>
        <translation>Journal</translation>
    </message>
</context>
<context>
    <name>EventHistoryModel</name>
    <message>
        <location filename="../lib/model/events/eventhistorymodel.cpp" line="108"/>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventhistorymodel.cpp" line="110"/>
        <source>Severity</source>
        <translation>Schweregrad</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventhistorymodel.cpp" line="112"/>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventhistorymodel.cpp" line="114"/>
        <source>Source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventhistorymodel.cpp" line="116"/>
        <source>What happened</source>
        <translation>Ereignis</translation>
    </message>
</context>
<context>
    <name>EventText</name>
    <message numerus="yes">
        <location filename="../lib/model/events/eventtext.cpp" line="16"/>
        <source>%1 (%n times, until %2)</source>
        <translation>
            <numerusform>%1 (%n-mal, bis %2)</numerusform>
            <numerusform>%1 (%n-mal, bis %2)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>FeederModel</name>
    <message>
        <location filename="../lib/model/device/feedermodel.cpp" line="82"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../lib/model/device/feedermodel.cpp" line="100"/>
        <source>%1 has no command %2</source>
        <translation>%1 hat keinen Befehl %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/feedermodel.cpp" line="116"/>
        <source>error cleared</source>
        <translation>Fehler gelöscht</translation>
    </message>
</context>
<context>
    <name>FrameComposer</name>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="40"/>
        <source>%1 carries the data field %2.</source>
        <translation>%1 enthält das Datenfeld %2.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="43"/>
        <source>A write needs a data field: %1.</source>
        <translation>Ein Schreibbefehl braucht ein Datenfeld: %1.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="53"/>
        <source>On the wire this value is written %1.</source>
        <translation>Auf der Leitung wird dieser Wert als %1 geschrieben.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="70"/>
        <source>Unknown device family: the catalog cannot check this frame.</source>
        <translation>Unbekannte Gerätefamilie: der Katalog kann dieses Telegramm nicht prüfen.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="78"/>
        <source>%1 is not a %2 write command in the catalog.</source>
        <translation>%1 ist im Katalog kein Schreibbefehl für %2.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="79"/>
        <source>%1 is not a %2 read command in the catalog.</source>
        <translation>%1 ist im Katalog kein Lesebefehl für %2.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="82"/>
        <source>Did you mean %1?</source>
        <translation>Meinten Sie %1?</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="83"/>
        <source>It is sent as typed.</source>
        <translation>Es wird unverändert gesendet.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="88"/>
        <source>Reads carry no data field; the device may refuse this frame.</source>
        <translation>Lesebefehle haben kein Datenfeld; das Gerät kann dieses Telegramm ablehnen.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="95"/>
        <source>Dangerous: %1</source>
        <translation>Gefährlich: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="99"/>
        <source>Catalog check: %1</source>
        <translation>Katalogprüfung: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="113"/>
        <source>%1 (no address)</source>
        <translation>%1 (ohne Adresse)</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="156"/>
        <source>No device is known on this line: connect first, or send raw hex.</source>
        <translation>An dieser Leitung ist kein Gerät bekannt: zuerst verbinden oder Roh-Hex senden.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="173"/>
        <source>Not sendable: the command must be 3 printable characters, e.g. SMN.</source>
        <translation>Nicht sendbar: der Befehl muss aus 3 druckbaren Zeichen bestehen, z. B. SMN.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="179"/>
        <source>Not sendable: the data field may only hold printable ASCII.</source>
        <translation>Nicht sendbar: das Datenfeld darf nur druckbare ASCII-Zeichen enthalten.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="184"/>
        <source>Not sendable: addresses go from 00 to 99.</source>
        <translation>Nicht sendbar: Adressen gehen von 00 bis 99.</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/console/framecomposer.cpp" line="214"/>
        <source>%n byte(s), a valid frame: %1</source>
        <translation>
            <numerusform>%n Byte, ein gültiges Telegramm: %1</numerusform>
            <numerusform>%n Bytes, ein gültiges Telegramm: %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/console/framecomposer.cpp" line="216"/>
        <source>%n byte(s), not a valid frame (%1): sent as typed</source>
        <translation>
            <numerusform>%n Byte, kein gültiges Telegramm (%1): wird unverändert gesendet</numerusform>
            <numerusform>%n Bytes, kein gültiges Telegramm (%1): wird unverändert gesendet</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>FrameDecoder</name>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="19"/>
        <source>frame</source>
        <translation>Telegramm</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="21"/>
        <source>BCC error</source>
        <translation>BCC-Fehler</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="23"/>
        <source>format error</source>
        <translation>Formatfehler</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="25"/>
        <source>overflow</source>
        <translation>Überlauf</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="27"/>
        <source>garbage</source>
        <translation>Datenmüll</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="47"/>
        <source>not STX…ETX BCC or too short</source>
        <translation>kein STX…ETX BCC oder zu kurz</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="50"/>
        <source>BCC is %1, expected %2</source>
        <translation>BCC ist %1, erwartet %2</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="60"/>
        <source>malformed addresses</source>
        <translation>fehlerhafte Adressen</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="66"/>
        <source>too short for header and command</source>
        <translation>zu kurz für Kopf und Befehl</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="69"/>
        <source>unknown header</source>
        <translation>unbekannter Kopf</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="74"/>
        <source>command is not 3 letters or digits</source>
        <translation>Befehl besteht nicht aus 3 Buchstaben oder Ziffern</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="78"/>
        <source>data field is not printable ASCII</source>
        <translation>Datenfeld ist kein druckbares ASCII</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="110"/>
        <source>frame interrupted by a new STX</source>
        <translation>Telegramm durch ein neues STX unterbrochen</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="119"/>
        <source>no ETX within %1 bytes</source>
        <translation>kein ETX innerhalb von %1 Bytes</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/protocol/framedecoder.cpp" line="144"/>
        <source>%n byte(s) outside any frame</source>
        <translation>
            <numerusform>%n Byte außerhalb eines Telegramms</numerusform>
            <numerusform>%n Bytes außerhalb eines Telegramms</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>HexBytes</name>
    <message>
        <location filename="../lib/protocol/hexbytes.cpp" line="35"/>
        <source>odd number of hex digits before position %1</source>
        <translation>ungerade Anzahl von Hex-Ziffern vor Position %1</translation>
    </message>
    <message>
        <location filename="../lib/protocol/hexbytes.cpp" line="45"/>
        <source>&apos;%1&apos; at position %2 is not a hex digit</source>
        <translation>&apos;%1&apos; an Position %2 ist keine Hex-Ziffer</translation>
    </message>
    <message>
        <location filename="../lib/protocol/hexbytes.cpp" line="52"/>
        <source>more than %1 bytes</source>
        <translation>mehr als %1 Bytes</translation>
    </message>
    <message>
        <location filename="../lib/protocol/hexbytes.cpp" line="56"/>
        <source>odd number of hex digits</source>
        <translation>ungerade Anzahl von Hex-Ziffern</translation>
    </message>
    <message>
        <location filename="../lib/protocol/hexbytes.cpp" line="58"/>
        <source>no bytes given</source>
        <translation>keine Bytes angegeben</translation>
    </message>
</context>
<context>
    <name>JointLimitRules</name>
    <message>
        <location filename="../lib/model/joints/jointlimitrules.cpp" line="51"/>
        <source>the longest recovery must be more than 0 s and at most %1 s</source>
        <translation>die längste Erholzeit muss mehr als 0 s und höchstens %1 s betragen</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitrules.cpp" line="59"/>
        <source>the deepest dip must be a whole number of kelvin from 1 to %1</source>
        <translation>der tiefste Einbruch muss eine ganze Zahl von Kelvin zwischen 1 und %1 sein</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitrules.cpp" line="67"/>
        <source>the tip wear share must be more than 0 and at most 10</source>
        <translation>der Anteil für Spitzenverschleiß muss größer als 0 und höchstens 10 sein</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitrules.cpp" line="73"/>
        <source>a port is a number from 1 to 4</source>
        <translation>ein Port ist eine Zahl von 1 bis 4</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitrules.cpp" line="111"/>
        <source>%1 must be a number</source>
        <translation>%1 muss eine Zahl sein</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitrules.cpp" line="170"/>
        <source>joint limits: %1</source>
        <translation>Lötstellen-Grenzwerte: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitrules.cpp" line="177"/>
        <source>joint limit rule %1: %2</source>
        <translation>Lötstellen-Grenzwertregel %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitrules.cpp" line="204"/>
        <source>“%1” is not a limit: write port=N, tool=NAME, recovery=SECONDS, dip=KELVIN or wear=SHARE, joined by commas</source>
        <translation>„%1“ ist kein Grenzwert: schreiben Sie port=N, tool=NAME, recovery=SEKUNDEN, dip=KELVIN oder wear=ANTEIL, durch Kommas getrennt</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitrules.cpp" line="212"/>
        <source>“%1” sets no limit: give recovery=SECONDS, dip=KELVIN or wear=SHARE</source>
        <translation>„%1“ setzt keinen Grenzwert: geben Sie recovery=SEKUNDEN, dip=KELVIN oder wear=ANTEIL an</translation>
    </message>
</context>
<context>
    <name>JointLimitsFile</name>
    <message>
        <location filename="../lib/model/joints/jointlimitsfile.cpp" line="35"/>
        <source>cannot read the joint limits %1: %2</source>
        <translation>die Lötstellen-Grenzwerte %1 können nicht gelesen werden: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitsfile.cpp" line="39"/>
        <source>the joint limits %1 are too big</source>
        <translation>die Lötstellen-Grenzwerte %1 sind zu groß</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitsfile.cpp" line="42"/>
        <source>the joint limits %1 are not a JSON object: %2</source>
        <translation>die Lötstellen-Grenzwerte %1 sind kein JSON-Objekt: %2</translation>
    </message>
</context>
<context>
    <name>JointTableModel</name>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="159"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="165"/>
        <source>ok</source>
        <translation>in Ordnung</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="167"/>
        <source>slow recovery</source>
        <translation>langsame Erholung</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="169"/>
        <source>too deep</source>
        <translation>zu tief</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="171"/>
        <source>incomplete</source>
        <translation>unvollständig</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="198"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="202"/>
        <source>%1–%2 s</source>
        <translation>%1–%2 s</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="212"/>
        <source>%1 %·s</source>
        <translation>%1 %·s</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="229"/>
        <source>Began within ± %1 ms of this time</source>
        <translation>Begann innerhalb von ± %1 ms um diese Zeit</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="232"/>
        <source>Measured to ± %1 K</source>
        <translation>Gemessen auf ± %1 K</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="236"/>
        <source>The tip was not seen back within the band</source>
        <translation>Die Spitze kam nicht sichtbar in das Band zurück</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="238"/>
        <source>Only bounded: the readings around the tip&apos;s return were too far apart, or broke off, to say when within the interval shown</source>
        <translation>Nur eingegrenzt: die Messwerte um die Rückkehr der Spitze lagen zu weit auseinander oder brachen ab, um zu sagen, wann innerhalb des gezeigten Intervalls</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="241"/>
        <source>Measured to ± %1 ms</source>
        <translation>Gemessen auf ± %1 ms</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="250"/>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="252"/>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="254"/>
        <source>Port</source>
        <translation>Port</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="256"/>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="258"/>
        <source>Setpoint</source>
        <translation>Sollwert</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="260"/>
        <source>Lowest</source>
        <translation>Tiefstwert</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="262"/>
        <source>Dip</source>
        <translation>Einbruch</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="264"/>
        <source>Recovery</source>
        <translation>Erholung</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="266"/>
        <source>Duration</source>
        <translation>Dauer</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="268"/>
        <source>Power peak</source>
        <translation>Leistungsspitze</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="270"/>
        <source>Power·time</source>
        <translation>Leistung·Zeit</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="272"/>
        <source>Verdict</source>
        <translation>Bewertung</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="274"/>
        <source>Work order</source>
        <translation>Auftrag</translation>
    </message>
</context>
<context>
    <name>JointWatcher</name>
    <message>
        <location filename="../lib/model/joints/jointwatcher.cpp" line="115"/>
        <source>joint too deep: the tip fell %1 K below the setpoint (limit %2 K)</source>
        <translation>Lötstelle zu tief: die Lötspitze fiel %1 K unter den Sollwert (Grenze %2 K)</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointwatcher.cpp" line="121"/>
        <source>joint recovered slowly: %1 s (limit %2 s)</source>
        <translation>Lötstelle langsam erholt: %1 s (Grenze %2 s)</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointwatcher.cpp" line="123"/>
        <source>joint did not recover within %1 s</source>
        <translation>Lötstelle hat sich in %1 s nicht erholt</translation>
    </message>
</context>
<context>
    <name>Journal</name>
    <message>
        <location filename="../lib/journal/journalreader.cpp" line="32"/>
        <location filename="../lib/journal/journalreader.cpp" line="249"/>
        <source>No journal is open.</source>
        <translation>Kein Journal ist geöffnet.</translation>
    </message>
    <message>
        <location filename="../lib/journal/journalreader.cpp" line="91"/>
        <source>There is no journal at %1.</source>
        <translation>Unter %1 gibt es kein Journal.</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/journal/journalreader.cpp" line="122"/>
        <source>The journal %1 is damaged (%n finding(s), the first: %2).</source>
        <translation>
            <numerusform>Das Journal %1 ist beschädigt (%n Befund, der erste: %2).</numerusform>
            <numerusform>Das Journal %1 ist beschädigt (%n Befunde, der erste: %2).</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../lib/journal/journalschema.cpp" line="117"/>
        <source>The journal %1 was written by a newer TipScope (schema %2; this one knows up to %3). It was left untouched.</source>
        <translation>Das Journal %1 wurde von einem neueren TipScope geschrieben (Schema %2; dieses kennt bis %3). Es wurde nicht verändert.</translation>
    </message>
    <message>
        <location filename="../lib/journal/journalschema.cpp" line="132"/>
        <source>The file %1 is not a TipScope journal. It was left untouched.</source>
        <translation>Die Datei %1 ist kein TipScope-Journal. Sie wurde nicht verändert.</translation>
    </message>
    <message>
        <location filename="../lib/journal/journalschema.cpp" line="241"/>
        <source>Cannot create the folder %1 for the journal.</source>
        <translation>Der Ordner %1 für das Journal kann nicht angelegt werden.</translation>
    </message>
    <message>
        <location filename="../lib/journal/journalwriter.cpp" line="252"/>
        <source>Records lost: %1. Reason: %2</source>
        <translation>Verlorene Einträge: %1. Grund: %2</translation>
    </message>
    <message>
        <location filename="../lib/journal/journalwriter.cpp" line="341"/>
        <source>The journal was closed before it could write them: %1</source>
        <translation>Das Journal wurde geschlossen, bevor es sie schreiben konnte: %1</translation>
    </message>
    <message>
        <location filename="../lib/journal/sqlerror.cpp" line="71"/>
        <source>The journal %1 cannot grow: the disk is full or the journal reached its size limit.</source>
        <translation>Das Journal %1 kann nicht wachsen: Der Datenträger ist voll oder das Journal hat seine Größengrenze erreicht.</translation>
    </message>
    <message>
        <location filename="../lib/journal/sqlerror.cpp" line="82"/>
        <source>The journal %1 is damaged or is not a journal; it was left untouched.</source>
        <translation>Das Journal %1 ist beschädigt oder kein Journal; es wurde nicht verändert.</translation>
    </message>
    <message>
        <location filename="../lib/journal/sqlerror.cpp" line="87"/>
        <source>The journal %1 is locked by another program.</source>
        <translation>Das Journal %1 ist von einem anderen Programm gesperrt.</translation>
    </message>
    <message>
        <location filename="../lib/journal/sqlerror.cpp" line="89"/>
        <source>The disk holding the journal %1 reported an error.</source>
        <translation>Der Datenträger des Journals %1 hat einen Fehler gemeldet.</translation>
    </message>
    <message>
        <location filename="../lib/journal/sqlerror.cpp" line="91"/>
        <source>The journal %1 reported an error: %2</source>
        <translation>Das Journal %1 hat einen Fehler gemeldet: %2</translation>
    </message>
    <message>
        <location filename="../lib/journal/sqlerror.cpp" line="118"/>
        <source>The journal %1 cannot be written: its folder or the file is read-only or not accessible.</source>
        <translation>Das Journal %1 kann nicht geschrieben werden: Sein Ordner oder die Datei ist schreibgeschützt oder nicht zugänglich.</translation>
    </message>
    <message>
        <location filename="../lib/journal/journalsettings.cpp" line="55"/>
        <source>A retention of %1 days is not possible: give 0 (keep everything) up to %2 days.</source>
        <translation>Eine Aufbewahrung von %1 Tagen ist nicht möglich: erlaubt sind 0 (alles behalten) bis %2 Tage.</translation>
    </message>
</context>
<context>
    <name>LinkStats</name>
    <message>
        <location filename="../lib/link/linkstats.cpp" line="60"/>
        <source>%1 tx/s, latency %2 ms median (%3-%4), %5 sent, %6 answered, %7 timeouts, %8 corrupted, %9 NAKs, %10 stray, %11 retries</source>
        <translation>%1 tx/s, Latenz %2 ms Median (%3-%4), %5 gesendet, %6 beantwortet, %7 Zeitüberschreitungen, %8 beschädigt, %9 NAKs, %10 verwaist, %11 Wiederholungen</translation>
    </message>
</context>
<context>
    <name>MeasurementReport</name>
    <message>
        <location filename="../lib/model/analysis/measurementreport.cpp" line="32"/>
        <source>%1: min %2, max %3, mean %4</source>
        <translation>%1: Min. %2, Max. %3, Mittel %4</translation>
    </message>
    <message>
        <location filename="../lib/model/analysis/measurementreport.cpp" line="42"/>
        <source>wake</source>
        <translation>Aufwachen</translation>
    </message>
    <message>
        <location filename="../lib/model/analysis/measurementreport.cpp" line="42"/>
        <source>heat-up</source>
        <translation>Aufheizen</translation>
    </message>
    <message>
        <location filename="../lib/model/analysis/measurementreport.cpp" line="46"/>
        <source>%1 at %2 to %3: %4</source>
        <translation>%1 um %2 auf %3: %4</translation>
    </message>
    <message>
        <location filename="../lib/model/analysis/measurementreport.cpp" line="48"/>
        <source>%1 at %2 to %3: not reached in this window</source>
        <translation>%1 um %2 auf %3: in diesem Zeitfenster nicht erreicht</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/analysis/measurementreport.cpp" line="52"/>
        <source>… %n more heat-up(s)</source>
        <translation>
            <numerusform>… %n weiteres Aufheizen</numerusform>
            <numerusform>… %n weitere Aufheizvorgänge</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../lib/model/analysis/measurementreport.cpp" line="64"/>
        <source>recovery at %1: %2 (dip to %3)</source>
        <translation>Erholung um %1: %2 (Einbruch auf %3)</translation>
    </message>
    <message>
        <location filename="../lib/model/analysis/measurementreport.cpp" line="66"/>
        <source>dip at %1 to %2: not recovered in this window</source>
        <translation>Einbruch um %1 auf %2: in diesem Zeitfenster nicht erholt</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/analysis/measurementreport.cpp" line="70"/>
        <source>… %n more recovery(s)</source>
        <translation>
            <numerusform>… %n weitere Erholung</numerusform>
            <numerusform>… %n weitere Erholungen</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../lib/model/analysis/measurementreport.cpp" line="79"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location filename="../lib/model/analysis/measurementreport.cpp" line="81"/>
        <source>%1 min %2 s</source>
        <translation>%1 min %2 s</translation>
    </message>
    <message>
        <location filename="../lib/model/analysis/measurementreport.cpp" line="84"/>
        <source>%1 h %2 min</source>
        <translation>%1 h %2 min</translation>
    </message>
    <message>
        <location filename="../lib/model/analysis/measurementreport.cpp" line="112"/>
        <source>%1: no samples in this window</source>
        <translation>%1: keine Messwerte in diesem Zeitfenster</translation>
    </message>
</context>
<context>
    <name>MqttClient</name>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="240"/>
        <source>The broker %1 refused the message: %2.</source>
        <translation>Der Broker %1 hat die Nachricht abgelehnt: %2.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="293"/>
        <source>&apos;%1&apos; is not a topic a message can be published to.</source>
        <translation>„%1“ ist kein Topic, an das eine Nachricht veröffentlicht werden kann.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="295"/>
        <location filename="../lib/mqtt/mqttclient.cpp" line="322"/>
        <source>QoS %1 does not exist; MQTT has 0, 1 and 2.</source>
        <translation>QoS %1 gibt es nicht; MQTT kennt 0, 1 und 2.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="298"/>
        <source>Not connected to the broker %1: the message to %2 is dropped.</source>
        <translation>Nicht mit dem Broker %1 verbunden: die Nachricht an %2 wird verworfen.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="302"/>
        <source>%1 messages wait to be taken by the broker %2: the message to %3 is dropped.</source>
        <translation>%1 Nachrichten warten darauf, vom Broker %2 angenommen zu werden: die Nachricht an %3 wird verworfen.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="312"/>
        <source>The message to %1 was not sent: %2</source>
        <translation>Die Nachricht an %1 wurde nicht gesendet: %2</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="320"/>
        <source>&apos;%1&apos; is not a valid subscription filter.</source>
        <translation>„%1“ ist kein gültiger Abonnement-Filter.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="331"/>
        <source>The subscription to %1 was not sent: %2</source>
        <translation>Das Abonnement von %1 wurde nicht gesendet: %2</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="338"/>
        <source>There is no subscription to %1.</source>
        <translation>Es gibt kein Abonnement von %1.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="346"/>
        <source>The subscription to %1 was not ended: %2</source>
        <translation>Das Abonnement von %1 wurde nicht beendet: %2</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="27"/>
        <source>The broker %1 refused the connection: bad user name or password.</source>
        <translation>Der Broker %1 hat die Verbindung abgelehnt: falscher Benutzername oder falsches Passwort.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="33"/>
        <source>The broker %1 refused the connection: not authorised (wrong user name or password, or this user may not connect).</source>
        <translation>Der Broker %1 hat die Verbindung abgelehnt: nicht berechtigt (falscher Benutzername oder falsches Passwort, oder dieser Benutzer darf sich nicht verbinden).</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="41"/>
        <source>The broker %1 refused the connection: %2.</source>
        <translation>Der Broker %1 hat die Verbindung abgelehnt: %2.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="47"/>
        <source>it does not speak MQTT 3.1.1</source>
        <translation>er spricht kein MQTT 3.1.1</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="49"/>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="71"/>
        <source>it does not accept this client id</source>
        <translation>er akzeptiert diese Client-ID nicht</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="51"/>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="74"/>
        <source>the service is unavailable</source>
        <translation>der Dienst ist nicht verfügbar</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="57"/>
        <source>return code %1</source>
        <translation>Rückgabecode %1</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="69"/>
        <source>it does not speak MQTT 5</source>
        <translation>er spricht kein MQTT 5</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="76"/>
        <source>reason code %1</source>
        <translation>Grundcode %1</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="85"/>
        <source>No MQTT broker accepts connections at %1 (connection refused).</source>
        <translation>Unter %1 nimmt kein MQTT-Broker Verbindungen an (Verbindung abgelehnt).</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="90"/>
        <source>The broker %1 closed the connection (%2).</source>
        <translation>Der Broker %1 hat die Verbindung geschlossen (%2).</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="93"/>
        <source>The broker %1 cannot be reached: %2.</source>
        <translation>Der Broker %1 ist nicht erreichbar: %2.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="114"/>
        <source>The broker&apos;s address %1 cannot be resolved.</source>
        <translation>Die Adresse %1 des Brokers lässt sich nicht auflösen.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="118"/>
        <source>The TLS handshake with the broker %1 failed.</source>
        <translation>Der TLS-Verbindungsaufbau mit dem Broker %1 ist fehlgeschlagen.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="119"/>
        <source>The TLS handshake with the broker %1 failed: %2</source>
        <translation>Der TLS-Verbindungsaufbau mit dem Broker %1 ist fehlgeschlagen: %2</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="123"/>
        <source>The broker %1 stopped answering within the keep-alive time.</source>
        <translation>Der Broker %1 hat innerhalb der Keep-Alive-Zeit nicht mehr geantwortet.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="128"/>
        <source>The connection to the broker %1 was lost.</source>
        <translation>Die Verbindung zum Broker %1 ist abgebrochen.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="132"/>
        <source>The broker %1 sent data that is not valid MQTT.</source>
        <translation>Der Broker %1 hat Daten gesendet, die kein gültiges MQTT sind.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="135"/>
        <source>The connection to the broker %1 failed: %2.</source>
        <translation>Die Verbindung zum Broker %1 ist fehlgeschlagen: %2.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="143"/>
        <source>The broker %1 cannot be reached: the connection was refused or reset.</source>
        <translation>Der Broker %1 ist nicht erreichbar: die Verbindung wurde abgelehnt oder zurückgesetzt.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="150"/>
        <source>The broker&apos;s host name %1 cannot be resolved: %2</source>
        <translation>Der Hostname %1 des Brokers lässt sich nicht auflösen: %2</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="59"/>
        <source>A password is set but no user name: MQTT sends a password only with a user name.</source>
        <translation>Ein Passwort ist gesetzt, aber kein Benutzername: MQTT sendet ein Passwort nur mit einem Benutzernamen.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="66"/>
        <source>The user name %1 is not accepted: %2</source>
        <translation>Der Benutzername %1 wird nicht angenommen: %2</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="78"/>
        <source>The last will on %1 is not accepted: %2</source>
        <translation>Der letzte Wille auf %1 wird nicht angenommen: %2</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="116"/>
        <source>The CA certificate file %1 cannot be read.</source>
        <translation>Die CA-Zertifikatsdatei %1 kann nicht gelesen werden.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="122"/>
        <source>A client certificate needs both its certificate file and its key file.</source>
        <translation>Ein Client-Zertifikat braucht sowohl seine Zertifikatsdatei als auch seine Schlüsseldatei.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="126"/>
        <source>The file %1 cannot be read.</source>
        <translation>Die Datei %1 kann nicht gelesen werden.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="97"/>
        <source>TLS cannot be set up: %1</source>
        <translation>TLS kann nicht eingerichtet werden: %1</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="105"/>
        <source>The MQTT version cannot be set: %1</source>
        <translation>Die MQTT-Version kann nicht eingestellt werden: %1</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="118"/>
        <source>The CA certificate file %1 holds no PEM certificate (-----BEGIN CERTIFICATE-----).</source>
        <translation>Die CA-Zertifikatsdatei %1 enthält kein PEM-Zertifikat (-----BEGIN CERTIFICATE-----).</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="148"/>
        <source>The client id %1 is not accepted.</source>
        <translation>Die Client-ID %1 wird nicht angenommen.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="149"/>
        <source>Out of memory for an MQTT client.</source>
        <translation>Kein Speicher mehr für einen MQTT-Client.</translation>
    </message>
</context>
<context>
    <name>MqttSecret</name>
    <message>
        <location filename="../lib/mqtt/mqttsecret.cpp" line="34"/>
        <source>The password file %1 does not exist.</source>
        <translation>Die Passwortdatei %1 existiert nicht.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsecret.cpp" line="37"/>
        <source>The password file %1 is larger than %2 bytes; is it the right file?</source>
        <translation>Die Passwortdatei %1 ist größer als %2 Bytes; ist es die richtige Datei?</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsecret.cpp" line="42"/>
        <source>The password file %1 cannot be read: %2</source>
        <translation>Die Passwortdatei %1 kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsecret.cpp" line="46"/>
        <source>The password file %1 is empty.</source>
        <translation>Die Passwortdatei %1 ist leer.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsecret.cpp" line="54"/>
        <source>The environment variable %1 that should hold the password is not set or empty.</source>
        <translation>Die Umgebungsvariable %1, die das Passwort enthalten soll, ist nicht gesetzt oder leer.</translation>
    </message>
</context>
<context>
    <name>Parameter</name>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="62"/>
        <source>read-only</source>
        <translation>schreibgeschützt</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="67"/>
        <source>%1 to %2</source>
        <translation>%1 bis %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="71"/>
        <source> in steps of %1 %2</source>
        <translation> in Schritten von %1 %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="78"/>
        <source>, or %1</source>
        <translation>, oder %1</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="84"/>
        <location filename="../lib/model/device/parameter.cpp" line="120"/>
        <source>%1 cannot be written</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="93"/>
        <source>%1 is not allowed for %2: allowed is %3</source>
        <translation>%1 ist für %2 nicht zulässig: zulässig ist %3</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="99"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="105"/>
        <location filename="../lib/model/device/parameter.cpp" line="233"/>
        <source>monitor-only mode is on: nothing is written</source>
        <translation>der Modus „Nur beobachten“ ist aktiv: es wird nichts geschrieben</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="123"/>
        <source>%1: %2; allowed is %3</source>
        <translation>%1: %2; zulässig ist %3</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="183"/>
        <source>reading %1 (%2)</source>
        <translation>%1 wird gelesen (%2)</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="196"/>
        <source>reading %1</source>
        <translation>%1 wird gelesen</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="197"/>
        <source>unreadable data field &apos;%1&apos;</source>
        <translation>unlesbares Datenfeld &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="255"/>
        <source>not written: %1</source>
        <translation>nicht geschrieben: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="258"/>
        <source>perhaps not written, the answer was lost: %1</source>
        <translation>vielleicht nicht geschrieben, die Antwort ging verloren: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="280"/>
        <source>written, but the read-back failed: %1</source>
        <translation>geschrieben, aber das Zurücklesen ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="287"/>
        <source>the device reports %1 after %2 was written</source>
        <translation>das Gerät meldet %1, nachdem %2 geschrieben wurde</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="300"/>
        <source>%1 set to %2</source>
        <translation>%1 auf %2 gesetzt</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="318"/>
        <source>writing %1</source>
        <translation>%1 wird geschrieben</translation>
    </message>
</context>
<context>
    <name>PortDiagnostics</name>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="40"/>
        <source>this program</source>
        <translation>dieses Programm</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="41"/>
        <source>, this program</source>
        <translation>, dieses Programm</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="51"/>
        <source>run `sudo usermod -aG %1 $USER`, then log out and back in.</source>
        <translation>führen Sie `sudo usermod -aG %1 $USER` aus und melden Sie sich danach ab und wieder an.</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="53"/>
        <source>You are not allowed to open %1: %2</source>
        <translation>Sie haben keine Berechtigung, %1 zu öffnen: %2</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="56"/>
        <source>You are not allowed to open %1, and it belongs to group root rather than dialout, so joining a group will not help until a udev rule gives it GROUP=&quot;dialout&quot;. Then %2</source>
        <translation>Sie haben keine Berechtigung, %1 zu öffnen, und die Schnittstelle gehört zur Gruppe root statt zu dialout; ein Gruppenbeitritt hilft daher erst, wenn eine udev-Regel ihr GROUP=&quot;dialout&quot; zuweist. Dann %2</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="61"/>
        <source>You are not allowed to open %1, which belongs to group %2 (not dialout): %3</source>
        <translation>Sie haben keine Berechtigung, %1 zu öffnen; die Schnittstelle gehört zur Gruppe %2 (nicht dialout): %3</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="102"/>
        <source>There is no such port in %1: a port&apos;s name is never %2 characters long. The port name may be mistyped.</source>
        <translation>In %1 gibt es diesen Port nicht: der Name eines Ports ist nie %2 Zeichen lang. Der Portname ist vielleicht falsch geschrieben.</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="112"/>
        <source>%1 is busy: it is held by %2. Close that connection, then try again.</source>
        <translation>%1 wird bereits von %2 verwendet. Schließen Sie diese Verbindung und versuchen Sie es dann erneut.</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="118"/>
        <source>There is no such port: %1. The adapter may be unplugged, or the port name may be mistyped.</source>
        <translation>Diesen Port gibt es nicht: %1. Möglicherweise ist der Adapter abgezogen oder der Portname falsch geschrieben.</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="124"/>
        <source>%1 is already open in TipScope; close that connection first</source>
        <translation>%1 ist in TipScope bereits geöffnet; schließen Sie zuerst diese Verbindung</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="129"/>
        <source>%1 stopped working, perhaps because the adapter was unplugged</source>
        <translation>%1 funktioniert nicht mehr, vielleicht wurde der Adapter abgezogen</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="133"/>
        <source>Could not open %1</source>
        <translation>%1 konnte nicht geöffnet werden</translation>
    </message>
</context>
<context>
    <name>PortModel</name>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="29"/>
        <source>Working</source>
        <translation>In Betrieb</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="31"/>
        <source>Stand</source>
        <translation>In der Ablage</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="33"/>
        <source>Sleep</source>
        <translation>Ruhemodus</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="35"/>
        <source>Hibernation</source>
        <translation>Tiefschlaf</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="43"/>
        <source>Cooling</source>
        <translation>Abkühlen</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="45"/>
        <source>Suction</source>
        <translation>Absaugung</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="47"/>
        <source>Motor forward</source>
        <translation>Motor vorwärts</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="49"/>
        <source>Motor backward</source>
        <translation>Motor rückwärts</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="71"/>
        <source>the tip went above the high alarm limit: if the selected temperature was just lowered, wait for the tip to cool; check that the tip suits the tool and the high alarm limit (Settings, Alarms)</source>
        <translation>die Lötspitze lag über der oberen Alarmgrenze: wurde die gewählte Temperatur gerade gesenkt, abwarten, bis die Spitze abgekühlt ist; prüfen, ob die Spitze zum Werkzeug passt, und die obere Alarmgrenze (Einstellungen, Alarme)</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="76"/>
        <source>the tip fell below the low alarm limit: the joint may draw more heat than the tip gives (a larger tip), the tip may be worn or not tinned; check the low alarm limit (Settings, Alarms)</source>
        <translation>die Lötspitze fiel unter die untere Alarmgrenze: die Lötstelle braucht vielleicht mehr Wärme, als die Spitze liefert (eine größere Spitze), oder die Spitze ist verschlissen oder nicht verzinnt; die untere Alarmgrenze prüfen (Einstellungen, Alarme)</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="122"/>
        <location filename="../lib/model/device/portmodel.cpp" line="137"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="60"/>
        <source>High temperature</source>
        <translation>Übertemperatur</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="62"/>
        <source>Low temperature</source>
        <translation>Untertemperatur</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="63"/>
        <source>None</source>
        <translation>Keiner</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="198"/>
        <source>this port has no %1 command</source>
        <translation>dieser Port hat keinen Befehl %1</translation>
    </message>
</context>
<context>
    <name>ProblemLevel</name>
    <message>
        <location filename="../lib/model/events/problemlevel.cpp" line="44"/>
        <source>Not read yet</source>
        <translation>Noch nicht gelesen</translation>
    </message>
    <message>
        <location filename="../lib/model/events/problemlevel.cpp" line="46"/>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location filename="../lib/model/events/problemlevel.cpp" line="48"/>
        <source>Info</source>
        <translation>Info</translation>
    </message>
    <message>
        <location filename="../lib/model/events/problemlevel.cpp" line="50"/>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <location filename="../lib/model/events/problemlevel.cpp" line="52"/>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
</context>
<context>
    <name>Profile</name>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="113"/>
        <source>%1: not a setting of a %2</source>
        <translation>%1: keine Einstellung von %2</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="118"/>
        <source>%1: &apos;%2&apos; is not a valid data field</source>
        <translation>%1: &apos;%2&apos; ist kein gültiges Datenfeld</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="123"/>
        <location filename="../lib/model/profiles/profile.cpp" line="220"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="131"/>
        <source>%1 bytes; a profile is at most %2</source>
        <translation>%1 Bytes; ein Profil hat höchstens %2</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="145"/>
        <source>not a valid JSON file: %1 at byte %2</source>
        <translation>keine gültige JSON-Datei: %1 bei Byte %2</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="158"/>
        <source>not a TipScope profile (no &quot;format&quot;: &quot;tipscope-profile&quot;)</source>
        <translation>kein TipScope-Profil (&quot;format&quot;: &quot;tipscope-profile&quot; fehlt)</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="169"/>
        <source>unknown device family &apos;%1&apos;</source>
        <translation>unbekannte Gerätefamilie &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="177"/>
        <source>the profile has no values</source>
        <translation>das Profil enthält keine Werte</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="184"/>
        <source>%1: the value must be a data field in quotes, e.g. &quot;00350&quot;</source>
        <translation>%1: der Wert muss ein Datenfeld in Anführungszeichen sein, z. B. &quot;00350&quot;</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="199"/>
        <source>the profile is refused, nothing will be written:
%1</source>
        <translation>das Profil wird abgelehnt, es wird nichts geschrieben:
%1</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="211"/>
        <source>cannot read %1: %2</source>
        <translation>%1 kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="216"/>
        <source>%1 is %2</source>
        <translation>%1 hat %2</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="236"/>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="141"/>
        <source>not a valid JSON file: %1</source>
        <translation>keine gültige JSON-Datei: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="152"/>
        <source>given more than once, so which value is meant is unclear: %1; nothing will be written</source>
        <translation>mehr als einmal angegeben, daher ist unklar, welcher Wert gemeint ist: %1; es wird nichts geschrieben</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profilejson.cpp" line="129"/>
        <source>a NUL byte at byte %1</source>
        <translation>ein NUL-Byte bei Byte %1</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profilejson.cpp" line="130"/>
        <source>control character 0x%1 at byte %2</source>
        <translation>Steuerzeichen 0x%1 bei Byte %2</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="161"/>
        <source>profile schema %1 is not supported (this version reads schemas %2 to %3)</source>
        <translation>Profilschema %1 wird nicht unterstützt (diese Version liest die Schemas %2 bis %3)</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="188"/>
        <source>%1: the value must be a data field in quotes, e.g. &quot;00350&quot;, or an object with one in &quot;raw&quot; (and text in &quot;name&quot; and &quot;value&quot;)</source>
        <translation>%1: der Wert muss ein Datenfeld in Anführungszeichen sein, z. B. &quot;00350&quot;, oder ein Objekt mit einem in &quot;raw&quot; (und Text in &quot;name&quot; und &quot;value&quot;)</translation>
    </message>
</context>
<context>
    <name>ProfileApplier</name>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="33"/>
        <source>refused, nothing was written: %1</source>
        <translation>abgelehnt, nichts wurde geschrieben: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="37"/>
        <source>%1 %2: %3 → %4</source>
        <translation>%1 %2: %3 → %4</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="40"/>
        <source>changed %1 %2: %3 → %4</source>
        <translation>geändert %1 %2: %3 → %4</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="42"/>
        <source>FAILED %1 %2: %3</source>
        <translation>FEHLER %1 %2: %3</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="45"/>
        <source>would send %1</source>
        <translation>würde %1 senden</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="50"/>
        <source>cancelled: the remaining values were not written</source>
        <translation>abgebrochen: die übrigen Werte wurden nicht geschrieben</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/profiles/profileapplier.cpp" line="61"/>
        <source>%n difference(s)</source>
        <translation>
            <numerusform>%n Unterschied</numerusform>
            <numerusform>%n Unterschiede</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="62"/>
        <source>%1 would change, %2 already right</source>
        <translation>%1 würden geändert, %2 bereits richtig</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="65"/>
        <source>%1 changed, %2 already right, %3 failed</source>
        <translation>%1 geändert, %2 bereits richtig, %3 fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="113"/>
        <source>the profile is for a %1, this device is a %2 (force to apply the settings they share)</source>
        <translation>das Profil ist für %1, dieses Gerät ist %2 (erzwingen, um die gemeinsamen Einstellungen anzuwenden)</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="118"/>
        <source>monitor-only mode is on</source>
        <translation>der Modus „Nur beobachten“ ist aktiv</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="179"/>
        <source>reading the device</source>
        <translation>Gerät wird gelesen</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="241"/>
        <source>writing %1</source>
        <translation>%1 wird geschrieben</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="244"/>
        <source>unreadable value</source>
        <translation>unlesbarer Wert</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="303"/>
        <source>profile %1 applied: %2 changed, %3 failed, %4 already right%5</source>
        <translation>Profil %1 angewendet: %2 geändert, %3 fehlgeschlagen, %4 schon richtig%5</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="308"/>
        <source> (cancelled)</source>
        <translation> (abgebrochen)</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="85"/>
        <source>the profile would break the limits that bound its settings (MIT ≤ MAT, MIT ≤ selected temperature ≤ MAT):
%1</source>
        <translation>das Profil würde die Grenzen seiner Einstellungen verletzen (MIT ≤ MAT, MIT ≤ ausgewählte Temperatur ≤ MAT):
%1</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="106"/>
        <source>none of the profile&apos;s settings exists on this %1 (skipped: %2)</source>
        <translation>keine der Einstellungen des Profils gibt es an diesem %1 (übersprungen: %2)</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/profiles/profileapplier.cpp" line="53"/>
        <source>%n skipped</source>
        <translation>
            <numerusform>%n übersprungen</numerusform>
            <numerusform>%n übersprungen</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="134"/>
        <source>this %1 has no such setting</source>
        <translation>dieses %1 hat keine solche Einstellung</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="47"/>
        <source>skipped %1 %2: %3</source>
        <translation>übersprungen %1 %2: %3</translation>
    </message>
</context>
<context>
    <name>ProfileLimits</name>
    <message>
        <location filename="../lib/model/profiles/profilelimits.cpp" line="64"/>
        <source>in the profile</source>
        <translation>im Profil</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profilelimits.cpp" line="65"/>
        <source>on the device now</source>
        <translation>jetzt am Gerät</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profilelimits.cpp" line="66"/>
        <source>%1 %2 (%3)</source>
        <translation>%1 %2 (%3)</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profilelimits.cpp" line="84"/>
        <source>%1 is not known (the device did not answer), so %2 cannot be checked against it</source>
        <translation>%1 ist unbekannt (das Gerät hat nicht geantwortet), daher lässt sich %2 nicht dagegen prüfen</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profilelimits.cpp" line="92"/>
        <source>%1 is above %2</source>
        <translation>%1 liegt über %2</translation>
    </message>
</context>
<context>
    <name>ProfileRequest</name>
    <message>
        <location filename="../lib/model/profiles/profilerequest.cpp" line="37"/>
        <source>&quot;request_id&quot; must be text of at most %1 characters, without control characters</source>
        <translation>&quot;request_id&quot; muss Text mit höchstens %1 Zeichen sein, ohne Steuerzeichen</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profilerequest.cpp" line="53"/>
        <source>the request is %1; nothing will be written</source>
        <translation>die Anfrage hat %1; nichts wird geschrieben</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profilerequest.cpp" line="72"/>
        <source>given more than once, so which one is meant is unclear: %1; nothing will be written</source>
        <translation>mehr als einmal angegeben, daher ist unklar, welches gemeint ist: %1; nichts wird geschrieben</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profilerequest.cpp" line="79"/>
        <source>&quot;profile&quot; must be a profile: an object as tipscope-cli profile save writes it</source>
        <translation>&quot;profile&quot; muss ein Profil sein: ein Objekt, wie tipscope-cli profile save es schreibt</translation>
    </message>
</context>
<context>
    <name>RecordingPlayback</name>
    <message>
        <location filename="../lib/model/recording/recordingplayback.cpp" line="38"/>
        <source>the recording %1 cannot be played: %2</source>
        <translation>die Aufzeichnung %1 kann nicht abgespielt werden: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/recordingplayback.cpp" line="60"/>
        <source>the recording %1 holds no station port to play</source>
        <translation>die Aufzeichnung %1 enthält keinen Stationsport zum Abspielen</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/recordingplayback.cpp" line="67"/>
        <source>playing the recording %1</source>
        <translation>Aufzeichnung %1 wird abgespielt</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/recording/recordingplayback.cpp" line="105"/>
        <source>the recording %1 played: %n sample(s)</source>
        <translation>
            <numerusform>die Aufzeichnung %1 ist abgespielt: %n Messwert</numerusform>
            <numerusform>die Aufzeichnung %1 ist abgespielt: %n Messwerte</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RemoteApply</name>
    <message>
        <location filename="../lib/plant/remoteapply.cpp" line="76"/>
        <source>a retained command is not carried out: it would run again at every reconnect</source>
        <translation>ein gespeicherter (retained) Befehl wird nicht ausgeführt: er liefe bei jeder Wiederverbindung erneut</translation>
    </message>
    <message>
        <location filename="../lib/plant/remoteapply.cpp" line="79"/>
        <source>remote profile apply is off in this agent&apos;s configuration</source>
        <translation>das Anwenden von Profilen aus der Ferne ist in der Konfiguration dieses Agenten aus</translation>
    </message>
    <message>
        <location filename="../lib/plant/remoteapply.cpp" line="83"/>
        <source>publish the command under your user name: %1/%2/USER</source>
        <translation>den Befehl unter dem eigenen Benutzernamen veröffentlichen: %1/%2/BENUTZER</translation>
    </message>
    <message>
        <location filename="../lib/plant/remoteapply.cpp" line="89"/>
        <source>no device of this agent is published at %1</source>
        <translation>unter %1 veröffentlicht dieser Agent kein Gerät</translation>
    </message>
    <message>
        <location filename="../lib/plant/remoteapply.cpp" line="92"/>
        <source>another profile is being applied to this device</source>
        <translation>auf dieses Gerät wird gerade ein anderes Profil angewendet</translation>
    </message>
    <message>
        <location filename="../lib/plant/remoteapply.cpp" line="95"/>
        <source>profile refused: %1</source>
        <translation>Profil abgelehnt: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/plant/remoteapply.cpp" line="125"/>
        <source>%n setting(s) not taken</source>
        <translation>
            <numerusform>%n Einstellung nicht übernommen</numerusform>
            <numerusform>%n Einstellungen nicht übernommen</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../lib/plant/remoteapply.cpp" line="154"/>
        <source>Profile applied through MQTT for %1</source>
        <translation>Profil über MQTT für %1 angewendet</translation>
    </message>
    <message>
        <location filename="../lib/plant/remoteapply.cpp" line="155"/>
        <source>Profile through MQTT for %1 not applied: %2</source>
        <translation>Profil über MQTT für %1 nicht angewendet: %2</translation>
    </message>
    <message>
        <location filename="../lib/plant/remoteapply.cpp" line="156"/>
        <source>an unnamed client</source>
        <translation>einen unbenannten Client</translation>
    </message>
</context>
<context>
    <name>RemoteTile</name>
    <message>
        <location filename="../lib/plant/remotetile.cpp" line="27"/>
        <location filename="../lib/plant/remotetile.cpp" line="39"/>
        <location filename="../lib/plant/remotetile.cpp" line="50"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../lib/plant/remotetile.cpp" line="48"/>
        <source>Feeding</source>
        <translation>Zuführung läuft</translation>
    </message>
    <message>
        <location filename="../lib/plant/remotetile.cpp" line="49"/>
        <source>Not feeding</source>
        <translation>Keine Zuführung</translation>
    </message>
    <message>
        <location filename="../lib/plant/remotetile.cpp" line="54"/>
        <source>%1 · fed %2</source>
        <translation>%1 · vorgeschoben %2</translation>
    </message>
    <message>
        <location filename="../lib/plant/remotetile.cpp" line="64"/>
        <source>Port %1 alarm: %2</source>
        <translation>Port %1 Alarm: %2</translation>
    </message>
    <message>
        <location filename="../lib/plant/remotetile.cpp" line="65"/>
        <source>Port %1: %2</source>
        <translation>Port %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/plant/remotetile.cpp" line="80"/>
        <source>Agent offline</source>
        <translation>Agent offline</translation>
    </message>
    <message>
        <location filename="../lib/plant/remotetile.cpp" line="84"/>
        <source>Agent offline since %1</source>
        <translation>Agent offline seit %1</translation>
    </message>
    <message>
        <location filename="../lib/plant/remotetile.cpp" line="85"/>
        <source>Agent offline since %1 %2</source>
        <translation>Agent offline seit %1 %2</translation>
    </message>
</context>
<context>
    <name>SerialPortList</name>
    <message>
        <location filename="../lib/link/ports/serialportlist.cpp" line="161"/>
        <source>%1 is an FTDI adapter with a %2 ms latency timer (the kernel default is 16 ms), which holds back every short answer and throttles request/answer traffic.
Set it to 1 ms now with:
  echo 1 | sudo tee /sys/bus/usb-serial/devices/%1/latency_timer
Make it permanent with this udev rule:
  echo &apos;ACTION==&quot;add&quot;, SUBSYSTEM==&quot;usb-serial&quot;, DRIVER==&quot;ftdi_sio&quot;, ATTR{latency_timer}=&quot;1&quot;&apos; | sudo tee /etc/udev/rules.d/99-ftdi-latency.rules</source>
        <translation>%1 ist ein FTDI-Adapter mit einem Latenz-Timer von %2 ms (Kernel-Standard: 16 ms); dieser hält jede kurze Antwort zurück und bremst den Anfrage-Antwort-Verkehr.
Sofort auf 1 ms stellen mit:
  echo 1 | sudo tee /sys/bus/usb-serial/devices/%1/latency_timer
Dauerhaft mit dieser udev-Regel:
  echo &apos;ACTION==&quot;add&quot;, SUBSYSTEM==&quot;usb-serial&quot;, DRIVER==&quot;ftdi_sio&quot;, ATTR{latency_timer}=&quot;1&quot;&apos; | sudo tee /etc/udev/rules.d/99-ftdi-latency.rules</translation>
    </message>
</context>
<context>
    <name>Session</name>
    <message>
        <location filename="../lib/model/session.cpp" line="30"/>
        <location filename="../lib/model/session.cpp" line="129"/>
        <location filename="../lib/model/session.cpp" line="132"/>
        <source>disconnected</source>
        <translation>getrennt</translation>
    </message>
    <message>
        <location filename="../lib/model/session.cpp" line="90"/>
        <source>reading the recording %1</source>
        <translation>Aufzeichnung %1 wird gelesen</translation>
    </message>
    <message>
        <location filename="../lib/model/session.cpp" line="128"/>
        <location filename="../lib/model/session.cpp" line="141"/>
        <location filename="../lib/model/session.cpp" line="149"/>
        <source>line</source>
        <translation>Leitung</translation>
    </message>
    <message>
        <location filename="../lib/model/session.cpp" line="165"/>
        <source>looking for devices on %1</source>
        <translation>Geräte an %1 werden gesucht</translation>
    </message>
    <message>
        <location filename="../lib/model/session.cpp" line="216"/>
        <source>found %1, software %2</source>
        <translation>%1 gefunden, Software %2</translation>
    </message>
    <message>
        <location filename="../lib/model/session.cpp" line="217"/>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <location filename="../lib/model/session.cpp" line="228"/>
        <source>connected to %1, but no device could be identified; what came back: %2 (robot mode off? wrong addressing or baud rate?)</source>
        <translation>mit %1 verbunden, aber kein Gerät ließ sich erkennen; zurück kam: %2 (Robotermodus aus? falsche Adressierung oder Baudrate?)</translation>
    </message>
    <message>
        <location filename="../lib/model/session.cpp" line="233"/>
        <source>connected to %1, but no device answered (robot mode off? wrong addressing or baud rate?)</source>
        <translation>mit %1 verbunden, aber kein Gerät hat geantwortet (Robotermodus aus? Falsche Adressierung oder Baudrate?)</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/session.cpp" line="241"/>
        <source>%1, %n device(s)</source>
        <translation>
            <numerusform>%1, %n Gerät</numerusform>
            <numerusform>%1, %n Geräte</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../lib/model/session.cpp" line="223"/>
        <source>connected to %1, but %2</source>
        <translation>mit %1 verbunden, aber %2</translation>
    </message>
</context>
<context>
    <name>SettingName</name>
    <message>
        <location filename="../lib/model/device/settingname.cpp" line="22"/>
        <source>tool %1</source>
        <translation>Werkzeug %1</translation>
    </message>
    <message>
        <location filename="../lib/model/device/settingname.cpp" line="33"/>
        <source>port %1</source>
        <translation>Port %1</translation>
    </message>
</context>
<context>
    <name>StationModel</name>
    <message>
        <location filename="../lib/model/device/stationmodel.cpp" line="62"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../lib/model/device/stationmodel.cpp" line="81"/>
        <source>%1 does not support %2</source>
        <translation>%1 unterstützt %2 nicht</translation>
    </message>
    <message>
        <location filename="../lib/model/device/stationmodel.cpp" line="88"/>
        <source>%1 cannot save to memory</source>
        <translation>%1 kann nicht im Speicher sichern</translation>
    </message>
    <message>
        <location filename="../lib/model/device/stationmodel.cpp" line="126"/>
        <location filename="../lib/model/device/stationmodel.cpp" line="131"/>
        <source>%1 → %2</source>
        <translation>%1 → %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/stationmodel.cpp" line="146"/>
        <source>error cleared</source>
        <translation>Fehler gelöscht</translation>
    </message>
</context>
<context>
    <name>SupportReport</name>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="176"/>
        <source>TipScope support report, %1</source>
        <translation>TipScope-Supportbericht, %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="178"/>
        <source>TipScope %1, Qt %2, %3</source>
        <translation>TipScope %1, Qt %2, %3</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="117"/>
        <source>Line: %1</source>
        <translation>Leitung: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="118"/>
        <source>State: %1</source>
        <translation>Zustand: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="119"/>
        <source>Statistics: %1</source>
        <translation>Statistik: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="168"/>
        <source>Workspace line %1</source>
        <translation>Linie %1 des Arbeitsbereichs</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="169"/>
        <source>Workspace line %1 (%2)</source>
        <translation>Linie %1 des Arbeitsbereichs (%2)</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="192"/>
        <source>Recent events of %1:</source>
        <translation>Letzte Ereignisse von %1:</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="201"/>
        <source>Recent events:</source>
        <translation>Letzte Ereignisse:</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="32"/>
        <source>Device %1</source>
        <translation>Gerät %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="37"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="39"/>
        <source>, software %1</source>
        <translation>, Software %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="46"/>
        <source>Joints of the last 24 hours: not read: %1</source>
        <translation>Lötstellen der letzten 24 Stunden: nicht gelesen: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="48"/>
        <source>Joints from %1 to %2:</source>
        <translation>Lötstellen von %1 bis %2:</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="53"/>
        <source>  none</source>
        <translation>  keine</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="60"/>
        <source>  %1, port %2: %3 joints: %4 ok, %5 slow recovery, %6 too deep, %7 incomplete</source>
        <translation>  %1, Port %2: %3 Lötstellen: %4 in Ordnung, %5 langsame Erholung, %6 zu tief, %7 unvollständig</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="68"/>
        <source>; recovery median %1 ms, 95th percentile %2 ms</source>
        <translation>; Erholzeit Median %1 ms, 95. Perzentil %2 ms</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="81"/>
        <source>Journal: %1</source>
        <translation>Journal: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="83"/>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="84"/>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="86"/>
        <source>not yet, opening</source>
        <translation>noch nicht, wird geöffnet</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="87"/>
        <source>no, closed</source>
        <translation>nein, geschlossen</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="89"/>
        <source>  writing: %1</source>
        <translation>  schreibt: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="90"/>
        <source>  writing: %1: %2</source>
        <translation>  schreibt: %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="92"/>
        <source>  lost: %1 records (%2)</source>
        <translation>  verloren: %1 Einträge (%2)</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="95"/>
        <source>  not read: %1</source>
        <translation>  nicht gelesen: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="98"/>
        <source>  %1 joints and %2 events, %3 and %4 of them not yet published; %5 waiting in memory</source>
        <translation>  %1 Lötstellen und %2 Ereignisse, davon %3 und %4 noch nicht veröffentlicht; %5 warten im Speicher</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="104"/>
        <source>  from %1 to %2</source>
        <translation>  von %1 bis %2</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="107"/>
        <source>  kept without a time limit; %1 bytes on disk</source>
        <translation>  ohne Zeitgrenze aufbewahrt; %1 Byte auf der Festplatte</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="109"/>
        <source>  kept for %1 days; %2 bytes on disk</source>
        <translation>  %1 Tage aufbewahrt; %2 Byte auf der Festplatte</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="135"/>
        <source>  What to check:</source>
        <translation>  Was zu prüfen ist:</translation>
    </message>
</context>
<context>
    <name>TipWear</name>
    <message>
        <location filename="../lib/model/joints/tipwear.cpp" line="70"/>
        <source>tip wearing: %1 recovers in %2 s (median of the last %3 joints), %4 s when it was plugged in</source>
        <translation>Spitze verschleißt: %1 erholt sich in %2 s (Median der letzten %3 Lötstellen), %4 s nach dem Einstecken</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/tipwear.cpp" line="73"/>
        <source>the tool</source>
        <translation>das Werkzeug</translation>
    </message>
</context>
<context>
    <name>ValueCodec</name>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="43"/>
        <source>%1 to %2%3</source>
        <translation>%1 bis %2%3</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="47"/>
        <source> in steps of %1</source>
        <translation> in Schritten von %1</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="49"/>
        <source>, or %1</source>
        <translation>, oder %1</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="57"/>
        <source>one of %1</source>
        <translation>einer der Werte %1</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="60"/>
        <source>no value (the command carries %1)</source>
        <translation>kein Wert (der Befehl enthält %1)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="64"/>
        <source>nothing: it is read-only</source>
        <translation>nichts: schreibgeschützt</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="79"/>
        <location filename="../lib/protocol/valuecodec.cpp" line="85"/>
        <source>%1 cannot be written</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="70"/>
        <source>%1 refused for %2 (%3): allowed is %4</source>
        <translation>%1 für %2 (%3) abgelehnt: zulässig ist %4</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="108"/>
        <source>&apos;%1&apos; is no data field of %2 (%3): allowed is %4</source>
        <translation>&apos;%1&apos; ist kein Datenfeld von %2 (%3): erlaubt ist %4</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="193"/>
        <source>&apos;%1&apos; is not a delay in seconds such as 1.6 or 01.60</source>
        <translation>&apos;%1&apos; ist keine Verzögerung in Sekunden wie 1.6 oder 01.60</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="198"/>
        <source>&apos;%1&apos; is not a whole number; %2 takes %3</source>
        <translation>&apos;%1&apos; ist keine ganze Zahl; für %2 zulässig: %3</translation>
    </message>
</context>
<context>
    <name>WorkContextFile</name>
    <message>
        <location filename="../lib/journal/workcontextfile.cpp" line="40"/>
        <source>cannot read the work context %1: %2</source>
        <translation>der Arbeitskontext %1 kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <location filename="../lib/journal/workcontextfile.cpp" line="44"/>
        <source>the work context %1 is too big to be one</source>
        <translation>der Arbeitskontext %1 ist zu groß, um einer zu sein</translation>
    </message>
    <message>
        <location filename="../lib/journal/workcontextfile.cpp" line="46"/>
        <source>the work context %1 is not a JSON object: %2</source>
        <translation>der Arbeitskontext %1 ist kein JSON-Objekt: %2</translation>
    </message>
    <message>
        <location filename="../lib/journal/workcontextfile.cpp" line="52"/>
        <source>the work context %1: %2</source>
        <translation>der Arbeitskontext %1: %2</translation>
    </message>
</context>
<context>
    <name>WorkContextJson</name>
    <message>
        <location filename="../lib/model/context/workcontextjson.cpp" line="20"/>
        <source>%1 has %2 characters; at most %3 are kept</source>
        <translation>%1 hat %2 Zeichen; höchstens %3 werden gespeichert</translation>
    </message>
    <message>
        <location filename="../lib/model/context/workcontextjson.cpp" line="27"/>
        <source>%1 holds a control character (%2) at character %3</source>
        <translation>%1 enthält ein Steuerzeichen (%2) an Zeichen %3</translation>
    </message>
    <message>
        <location filename="../lib/model/context/workcontextjson.cpp" line="53"/>
        <source>%1 must be text</source>
        <translation>%1 muss Text sein</translation>
    </message>
</context>
<context>
    <name>WorkspaceFile</name>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="31"/>
        <source>not a TipScope workspace (&quot;format&quot; is not &quot;%1&quot;)</source>
        <translation>kein TipScope-Arbeitsbereich (&quot;format&quot; ist nicht &quot;%1&quot;)</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="36"/>
        <source>&quot;version&quot; must be a whole number from 1</source>
        <translation>&quot;version&quot; muss eine ganze Zahl ab 1 sein</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="38"/>
        <source>written by a later TipScope (workspace version %1); this one reads version %2 and older</source>
        <translation>von einem neueren TipScope geschrieben (Arbeitsbereich-Version %1); dieses liest Version %2 und ältere</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="67"/>
        <source>&quot;lines&quot; must be a list of lines</source>
        <translation>&quot;lines&quot; muss eine Liste von Leitungen sein</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="75"/>
        <source>line %1</source>
        <translation>Leitung %1</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="76"/>
        <source>line %1 (%2)</source>
        <translation>Leitung %1 (%2)</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="78"/>
        <source>%1: must be an object</source>
        <translation>%1: muss ein Objekt sein</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="83"/>
        <source>%1: the name is already another line&apos;s; each line needs its own</source>
        <translation>%1: der Name gehört schon einer anderen Leitung; jede Leitung braucht einen eigenen</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="100"/>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="103"/>
        <source>cannot read the workspace %1: %2</source>
        <translation>der Arbeitsbereich %1 kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="101"/>
        <source>there is no such file</source>
        <translation>diese Datei gibt es nicht</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="106"/>
        <source>the workspace %1 is too big to be one</source>
        <translation>der Arbeitsbereich %1 ist zu groß, um einer zu sein</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="108"/>
        <source>the workspace %1 is not a JSON object: %2</source>
        <translation>der Arbeitsbereich %1 ist kein JSON-Objekt: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="110"/>
        <source>it is a list</source>
        <translation>er ist eine Liste</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="49"/>
        <source>%1 must be text</source>
        <translation>%1 muss Text sein</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="57"/>
        <source>%1 must be a whole number from %2 to %3</source>
        <translation>%1 muss eine ganze Zahl von %2 bis %3 sein</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="65"/>
        <source>%1 must be true or false</source>
        <translation>%1 muss true oder false sein</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="74"/>
        <source>%1 must be one of %2</source>
        <translation>%1 muss eines von %2 sein</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="80"/>
        <source>%1 must be an object</source>
        <translation>%1 muss ein Objekt sein</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="103"/>
        <source>%1 must name the recording file</source>
        <translation>%1 muss die Aufzeichnungsdatei nennen</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="112"/>
        <source>%1 must name the serial port</source>
        <translation>%1 muss den seriellen Port nennen</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="125"/>
        <source>%1 must be HOST:PORT (for example 192.168.1.20:4001)</source>
        <translation>%1 muss HOST:PORT sein (zum Beispiel 192.168.1.20:4001)</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="157"/>
        <source>devices must be a list</source>
        <translation>devices muss eine Liste sein</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="163"/>
        <source>devices[%1] must be an object</source>
        <translation>devices[%1] muss ein Objekt sein</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="167"/>
        <source>%1 must be an address from 0 to 99, or null for the device without addresses</source>
        <translation>%1 muss eine Adresse von 0 bis 99 sein, oder null für das Gerät ohne Adressen</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="175"/>
        <source>%1 must not be empty</source>
        <translation>%1 darf nicht leer sein</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="180"/>
        <source>devices[%1] names a device named before</source>
        <translation>devices[%1] benennt ein schon benanntes Gerät</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="243"/>
        <source>every line needs a name</source>
        <translation>jede Leitung braucht einen Namen</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="250"/>
        <source>connection is missing</source>
        <translation>connection fehlt</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="46"/>
        <source>Configure and monitor JBC soldering stations and the SFR feeder.</source>
        <translation>JBC-Lötstationen und den SFR-Lotdrahtvorschub konfigurieren und überwachen.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="52"/>
        <source>Start on the built-in simulated DME station and SFR feeder.</source>
        <translation>Mit der eingebauten simulierten DME-Station und dem SFR-Lotdrahtvorschub starten.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="55"/>
        <source>Connect to this serial port.</source>
        <translation>Mit dieser seriellen Schnittstelle verbinden.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="58"/>
        <source>Connect to a TCP serial server.</source>
        <translation>Mit einem seriellen TCP-Server verbinden.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="62"/>
        <source>Open the lines of this workspace file.</source>
        <translation>Die Linien dieser Arbeitsbereichsdatei öffnen.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="66"/>
        <source>Save a PNG of every page into DIR, then quit.</source>
        <translation>Ein PNG jeder Seite in DIR speichern, dann beenden.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="70"/>
        <source>Watch the devices published to this MQTT broker on the fleet overview.</source>
        <translation>Die an diesen MQTT-Broker veröffentlichten Geräte in der Geräteübersicht verfolgen.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="75"/>
        <source>With --plant: only this site&apos;s devices.</source>
        <translation>Mit --plant: nur die Geräte dieses Standorts.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="80"/>
        <source>tipscope: there is no display (neither DISPLAY nor WAYLAND_DISPLAY is set); start it on a desktop, or use tipscope-cli</source>
        <translation>tipscope: es gibt keine Anzeige (weder DISPLAY noch WAYLAND_DISPLAY ist gesetzt); starten Sie es auf einem Desktop, oder verwenden Sie tipscope-cli</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="109"/>
        <source>tipscope: %1</source>
        <translation>tipscope: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="121"/>
        <source>tipscope: --plant takes the broker as HOST:PORT</source>
        <translation>tipscope: --plant erwartet den Broker als HOST:PORT</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::BoardReportDialog</name>
    <message>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="26"/>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="130"/>
        <source>Board report</source>
        <translation>Platinenbericht</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="35"/>
        <source>Every joint the journal keeps for the board, its result, its tools&apos; wear and the events while it was made, as a PDF to sign.</source>
        <translation>Jede Lötstelle, die das Journal für die Platine behält, ihr Ergebnis, der Verschleiß ihrer Spitzen und die Ereignisse während der Fertigung, als PDF zum Unterschreiben.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="41"/>
        <source>Board serial:</source>
        <translation>Platinen-Seriennummer:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="44"/>
        <source>Write PDF…</source>
        <translation>PDF schreiben…</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="61"/>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="125"/>
        <source>Give the serial of a board.</source>
        <translation>Die Seriennummer einer Platine angeben.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="82"/>
        <source>Reading the journal for board %1…</source>
        <translation>Das Journal wird für Platine %1 gelesen…</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="95"/>
        <source>The journal has no board %1: no joint or event carries that serial.</source>
        <translation>Das Journal kennt keine Platine %1: keine Lötstelle und kein Ereignis trägt diese Seriennummer.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="132"/>
        <source>PDF documents (*.pdf)</source>
        <translation>PDF-Dokumente (*.pdf)</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ChartPlotView</name>
    <message>
        <location filename="../app/gui/charts/chartplotview.cpp" line="46"/>
        <source>Time chart. Wheel or plus and minus keys zoom, drag or arrow keys pan, Shift+drag selects a range, double-click or Home resets.</source>
        <translation>Zeitdiagramm. Mausrad oder Plus- und Minustaste zoomen, Ziehen oder Pfeiltasten verschieben, Umschalt+Ziehen wählt einen Bereich, Doppelklick oder Pos1 setzt zurück.</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ChartWidget</name>
    <message numerus="yes">
        <location filename="../app/gui/charts/chartwidget.cpp" line="508"/>
        <source>… and %n more</source>
        <translation>
            <numerusform>… und %n weitere</numerusform>
            <numerusform>… und %n weitere</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ChartsPage</name>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="30"/>
        <location filename="../app/gui/charts/chartspage.h" line="70"/>
        <location filename="../app/gui/screenshots.cpp" line="231"/>
        <source>Charts</source>
        <translation>Diagramme</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="106"/>
        <source>Values under the cursor</source>
        <translation>Werte unter dem Mauszeiger</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="128"/>
        <source>&amp;Measurements</source>
        <translation>&amp;Messwerte</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="132"/>
        <source>Heat-ups, recoveries and min/max/mean of the visible window</source>
        <translation>Aufheizen, Erholungen und Min./Max./Mittel des sichtbaren Zeitfensters</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="137"/>
        <source>Heat-up and recovery &amp;band ±</source>
        <translation>Toleranzband für A&amp;ufheizen und Erholung ±</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="140"/>
        <source>Tolerance band around the setpoint</source>
        <translation>Toleranzband um den Sollwert</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="153"/>
        <source>Measurements of the visible window</source>
        <translation>Messungen im sichtbaren Zeitfenster</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="195"/>
        <source>Point at a chart to read every series at that instant.</source>
        <translation>Zeigen Sie auf ein Diagramm, um alle Reihen zu diesem Zeitpunkt abzulesen.</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="196"/>
        <source>Wheel: zoom · drag: pan · Shift+drag: zoom to a range · double-click: reset.</source>
        <translation>Mausrad: Zoom · Ziehen: Verschieben · Umschalt+Ziehen: auf einen Bereich zoomen · Doppelklick: Zurücksetzen.</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="175"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="178"/>
        <source>%1 at %2</source>
        <translation>%1, Adresse %2</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="181"/>
        <source>%1 — feeder</source>
        <translation>%1 — Lotdrahtvorschub</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="185"/>
        <source>%1 — all ports</source>
        <translation>%1 — alle Ports</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="186"/>
        <source>%1 — %2 %3</source>
        <translation>%1 — %2 %3</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="189"/>
        <source>Temperature (%1)</source>
        <translation>Temperatur (%1)</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="190"/>
        <source>Power (%)</source>
        <translation>Leistung (%)</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="190"/>
        <source>%</source>
        <translation>%</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="301"/>
        <source>No samples in this window</source>
        <translation>Keine Messwerte in diesem Zeitfenster</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="49"/>
        <source>device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="51"/>
        <source>%1 · %2 · %3: %4</source>
        <translation>%1 · %2 · %3: %4</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="64"/>
        <source>&amp;Window</source>
        <translation>&amp;Zeitfenster</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="69"/>
        <source>Time window</source>
        <translation>Zeitfenster</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="75"/>
        <source>30 s</source>
        <translation>30 s</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="75"/>
        <source>1 min</source>
        <translation>1 min</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="75"/>
        <source>5 min</source>
        <translation>5 min</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="76"/>
        <source>15 min</source>
        <translation>15 min</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="76"/>
        <source>1 h</source>
        <translation>1 h</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="76"/>
        <source>4 h</source>
        <translation>4 h</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="77"/>
        <source>12 h</source>
        <translation>12 h</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="77"/>
        <source>24 h</source>
        <translation>24 h</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="84"/>
        <source>&amp;Follow</source>
        <translation>&amp;Mitlaufen</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="87"/>
        <source>Keep the newest data at the right edge; uncheck to pause</source>
        <translation>Die neuesten Daten am rechten Rand halten; zum Anhalten abwählen</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="90"/>
        <source>&amp;Reset view</source>
        <translation>Ansicht zu&amp;rücksetzen</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="94"/>
        <source>Pane layout</source>
        <translation>Anordnung der Bereiche</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="95"/>
        <source>Ports overlaid</source>
        <translation>Ports überlagert</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="96"/>
        <source>One pane per port</source>
        <translation>Ein Bereich pro Port</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="100"/>
        <source>Trans&amp;istor, transformer</source>
        <translation>Trans&amp;istor, Transformator</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="102"/>
        <source>Also draw each port&apos;s transistor temperature and the station&apos;s transformer temperature (read every few seconds)</source>
        <translation>Auch die Transistortemperatur jedes Ports und die Transformatortemperatur der Station zeichnen (alle paar Sekunden gelesen)</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="106"/>
        <source>&amp;Export</source>
        <translation>E&amp;xportieren</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="109"/>
        <source>Visible window as &amp;PNG…</source>
        <translation>Sichtbares Zeitfenster als &amp;PNG…</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="110"/>
        <source>Visible window as &amp;CSV…</source>
        <translation>Sichtbares Zeitfenster als &amp;CSV…</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="112"/>
        <source>Re&amp;cord…</source>
        <translation>&amp;Aufzeichnen…</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="114"/>
        <source>Write every new sample and event to a CSV file until unchecked</source>
        <translation>Jeden neuen Messwert und jedes Ereignis in eine CSV-Datei schreiben, bis abgewählt</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="116"/>
        <source>&amp;Open recording…</source>
        <translation>Aufzeichnung ö&amp;ffnen…</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="118"/>
        <source>Back to &amp;live</source>
        <translation>Zurück zu &amp;Live</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="123"/>
        <source>Data shown</source>
        <translation>Angezeigte Daten</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="126"/>
        <source>Recording stopped</source>
        <translation>Aufzeichnung beendet</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="127"/>
        <source>Writing %1 failed: %2</source>
        <translation>Schreiben von %1 fehlgeschlagen: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="78"/>
        <source>P%1</source>
        <translation>P%1</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="94"/>
        <source>High alarm</source>
        <translation>Alarm hoch</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="97"/>
        <source>Low alarm</source>
        <translation>Alarm tief</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/charts/chartspageactions.cpp" line="158"/>
        <source>Replay: %1 (%Ln row(s))</source>
        <translation>
            <numerusform>Wiedergabe: %1 (%Ln Zeile)</numerusform>
            <numerusform>Wiedergabe: %1 (%Ln Zeilen)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="160"/>
        <source>Live</source>
        <translation>Live</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="176"/>
        <source> · recording to %1</source>
        <translation> · Aufzeichnung in %1</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="57"/>
        <source>there is no chart to export</source>
        <translation>es gibt kein Diagramm zum Exportieren</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="48"/>
        <source>%1 – %2 (%3)</source>
        <translation>%1 – %2 (%3)</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="111"/>
        <source>the image could not be encoded</source>
        <translation>das Bild konnte nicht erzeugt werden</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="135"/>
        <source>%1 × %2 (twice the charts on screen)</source>
        <translation>%1 × %2 (doppelte Größe der Diagramme am Bildschirm)</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="136"/>
        <source>%1 × %2</source>
        <translation>%1 × %2</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="139"/>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="151"/>
        <source>Export chart as PNG</source>
        <translation>Diagramm als PNG exportieren</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="139"/>
        <source>Image size in pixels:</source>
        <translation>Bildgröße in Pixeln:</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="151"/>
        <source>Export chart data as CSV</source>
        <translation>Diagrammdaten als CSV exportieren</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="153"/>
        <source>PNG image (*.png)</source>
        <translation>PNG-Bild (*.png)</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="166"/>
        <source>The file holds every sample from %1 on. The chart&apos;s older history is kept only as min and max per few seconds, which a file of samples cannot hold.</source>
        <translation>Die Datei enthält jeden Messwert ab %1. Der ältere Verlauf des Diagramms wird nur als Minimum und Maximum je einige Sekunden aufbewahrt, und das kann eine Datei von Messwerten nicht enthalten.</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="207"/>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="153"/>
        <source>CSV file (*.csv)</source>
        <translation>CSV-Datei (*.csv)</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="162"/>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="165"/>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="162"/>
        <source>Export failed: %1</source>
        <translation>Export fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="206"/>
        <source>Record to CSV file</source>
        <translation>In CSV-Datei aufzeichnen</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="210"/>
        <source>Record</source>
        <translation>Aufzeichnen</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="210"/>
        <source>Cannot record: %1</source>
        <translation>Aufzeichnung nicht möglich: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspagereplay.cpp" line="54"/>
        <source>Open recording</source>
        <translation>Aufzeichnung öffnen</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspagereplay.cpp" line="64"/>
        <source>Reading %1: %2 MB</source>
        <translation>Lese %1: %2 MB</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspagereplay.cpp" line="71"/>
        <source>Reading %1…</source>
        <translation>Lese %1 …</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspagereplay.cpp" line="118"/>
        <source>The charts hold no readings of %1 at %2: only this session&apos;s readings are kept.</source>
        <translation>Die Diagramme enthalten keine Messwerte von %1 um %2: nur die Messwerte dieser Sitzung werden behalten.</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspagereplay.cpp" line="128"/>
        <source>Open a chart recording</source>
        <translation>Diagrammaufzeichnung öffnen</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspagereplay.cpp" line="128"/>
        <source>CSV file (*.csv);;All files (*)</source>
        <translation>CSV-Datei (*.csv);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspagereplay.cpp" line="135"/>
        <source>Replay</source>
        <translation>Wiedergabe</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspagereplay.cpp" line="135"/>
        <source>Cannot replay %1</source>
        <translation>%1 kann nicht wiedergegeben werden</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ConnectionBar</name>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="35"/>
        <location filename="../app/gui/connectionbar.cpp" line="42"/>
        <source>Serial port</source>
        <translation>Serielle Schnittstelle</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="36"/>
        <location filename="../app/gui/connectionbar.cpp" line="46"/>
        <source>TCP serial server</source>
        <translation>Serieller TCP-Server</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="37"/>
        <source>Demo (simulated DME + SFR)</source>
        <translation>Demo (simulierte DME + SFR)</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="38"/>
        <source>Connection type</source>
        <translation>Verbindungsart</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="43"/>
        <source>Serial ports on this computer; you may also type a device path</source>
        <translation>Serielle Schnittstellen dieses Computers; Sie können auch einen Gerätepfad eingeben</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="45"/>
        <source>host:port</source>
        <translation>Host:Port</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="50"/>
        <source>Baud rate</source>
        <translation>Baudrate</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="52"/>
        <source>no parity</source>
        <translation>keine Parität</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="53"/>
        <source>even</source>
        <translation>gerade</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="54"/>
        <source>odd</source>
        <translation>ungerade</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="56"/>
        <source>1 stop bit</source>
        <translation>1 Stoppbit</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="57"/>
        <source>2 stop bits</source>
        <translation>2 Stoppbits</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="59"/>
        <source>Find devices</source>
        <translation>Geräte suchen</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="60"/>
        <source>With addresses</source>
        <translation>Mit Adressen</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="61"/>
        <source>Without addresses</source>
        <translation>Ohne Adressen</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="62"/>
        <source>Addressing</source>
        <translation>Adressierung</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="65"/>
        <source>robot </source>
        <translation>Roboter </translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="66"/>
        <source>Robot address</source>
        <translation>Roboteradresse</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="69"/>
        <source>device </source>
        <translation>Gerät </translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="70"/>
        <source>Device address</source>
        <translation>Geräteadresse</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="71"/>
        <location filename="../app/gui/connectionbar.cpp" line="186"/>
        <source>&amp;Connect</source>
        <translation>&amp;Verbinden</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="72"/>
        <source>&amp;Monitor only</source>
        <translation>Nur &amp;beobachten</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="73"/>
        <source>Block every write: watch a production line without risk</source>
        <translation>Sperrt jeden Schreibzugriff: eine Fertigungslinie ohne Risiko beobachten</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="105"/>
        <source>disconnected</source>
        <translation>getrennt</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="186"/>
        <source>&amp;Disconnect</source>
        <translation>&amp;Trennen</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="198"/>
        <source>Connected</source>
        <translation>Verbunden</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="203"/>
        <source>Connecting</source>
        <translation>Verbindung wird aufgebaut</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="203"/>
        <source>Detecting devices</source>
        <translation>Geräte werden erkannt</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="207"/>
        <source>Disconnected, retrying</source>
        <translation>Getrennt, neuer Versuch</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="211"/>
        <source>Cannot connect</source>
        <translation>Verbindung nicht möglich</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="214"/>
        <source>Disconnected</source>
        <translation>Getrennt</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="219"/>
        <source> (this bar&apos;s line only: %1)</source>
        <translation> (nur die Linie dieser Leiste: %1)</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ConsolePage</name>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="89"/>
        <source>Console tools</source>
        <translation>Konsolenwerkzeuge</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="98"/>
        <source>Older rows go as new ones come; Save… writes the rows kept to a file. While paused, new rows are held; they appear on resume.</source>
        <translation>Ältere Zeilen weichen den neuen; Speichern… schreibt die behaltenen Zeilen in eine Datei. Während der Pause werden neue Zeilen zurückgehalten; sie erscheinen beim Fortsetzen.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="139"/>
        <location filename="../app/gui/pages/consolepage.cpp" line="341"/>
        <source>Pause</source>
        <translation>Anhalten</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="144"/>
        <source>Hold new rows (Ctrl+P); nothing is lost, they appear on resume</source>
        <translation>Neue Zeilen zurückhalten (Strg+P); nichts geht verloren, sie erscheinen beim Fortsetzen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="148"/>
        <source>Relative time</source>
        <translation>Relative Zeit</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="151"/>
        <source>Show seconds since the first row instead of the clock time</source>
        <translation>Sekunden seit der ersten Zeile statt der Uhrzeit anzeigen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="166"/>
        <source>Show:</source>
        <translation>Anzeigen:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="167"/>
        <source>TX</source>
        <translation>TX</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="167"/>
        <source>Show bytes sent</source>
        <translation>Gesendete Bytes anzeigen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="170"/>
        <source>RX chunks</source>
        <translation>RX-Blöcke</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="171"/>
        <source>Show bytes as the driver delivered them, chunk by chunk (every received byte is also in a frame or error row)</source>
        <translation>Bytes so anzeigen, wie der Treiber sie geliefert hat, Block für Block (jedes empfangene Byte steht auch in einer Telegramm- oder Fehlerzeile)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="174"/>
        <source>Frames</source>
        <translation>Telegramme</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="174"/>
        <source>Show received frames, decoded</source>
        <translation>Empfangene Telegramme dekodiert anzeigen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="176"/>
        <source>Errors</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="176"/>
        <source>Show decode errors (BCC, format, garbage)</source>
        <translation>Dekodierfehler anzeigen (BCC, Format, Datenmüll)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="177"/>
        <source>Notes</source>
        <translation>Hinweise</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="177"/>
        <source>Show line notes (timeouts, line state)</source>
        <translation>Leitungshinweise anzeigen (Zeitüberschreitungen, Leitungszustand)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="180"/>
        <source>De&amp;vice:</source>
        <translation>&amp;Gerät:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="183"/>
        <source>Device address filter</source>
        <translation>Filter für Geräteadresse</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="184"/>
        <source>Only frames from or to this address; type any address 00-99</source>
        <translation>Nur Telegramme von oder an diese Adresse; beliebige Adresse 00-99 eingeben</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="193"/>
        <source>Co&amp;mmand:</source>
        <translation>Be&amp;fehl:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="196"/>
        <source>Command filter</source>
        <translation>Befehlsfilter</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="197"/>
        <source>e.g. ST1</source>
        <translation>z. B. ST1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="207"/>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="209"/>
        <source>Remove every row, held ones included</source>
        <translation>Alle Zeilen entfernen, auch die zurückgehaltenen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="210"/>
        <source>Save…</source>
        <translation>Speichern…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="212"/>
        <source>Save every row (not only the shown ones) to a text file</source>
        <translation>Alle Zeilen (nicht nur die angezeigten) in einer Textdatei speichern</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="218"/>
        <source>Traffic on the line</source>
        <translation>Verkehr auf der Leitung</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="264"/>
        <source>bad</source>
        <translation>falsch</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="278"/>
        <source>Copy rows</source>
        <translation>Zeilen kopieren</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="292"/>
        <location filename="../app/gui/pages/consolepage.cpp" line="302"/>
        <location filename="../app/gui/pages/consolepage.cpp" line="320"/>
        <source>All</source>
        <translation>Alle</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="341"/>
        <source>Resume</source>
        <translation>Fortsetzen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="354"/>
        <location filename="../app/gui/pages/consolepage.cpp" line="359"/>
        <source>Save console</source>
        <translation>Konsole speichern</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="355"/>
        <source>Text files (*.txt);;All files (*)</source>
        <translation>Textdateien (*.txt);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="378"/>
        <source>%1 of %2 rows shown; the newest %3 are kept</source>
        <translation>%1 von %2 Zeilen angezeigt; die neuesten %3 werden behalten</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pages/consolepage.cpp" line="383"/>
        <source>paused: %n held</source>
        <translation>
            <numerusform>angehalten: %n zurückgehalten</numerusform>
            <numerusform>angehalten: %n zurückgehalten</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.h" line="62"/>
        <source>Console</source>
        <translation>Konsole</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="360"/>
        <source>The console could not be saved:
%1</source>
        <translation>Die Konsole konnte nicht gespeichert werden:
%1</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::CountersPage</name>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="73"/>
        <source>When the counters were read</source>
        <translation>Zeitpunkt der Zählerabfrage</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="75"/>
        <source>Result of the last action</source>
        <translation>Ergebnis der letzten Aktion</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="77"/>
        <source>Re&amp;fresh</source>
        <translation>A&amp;ktualisieren</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="78"/>
        <source>Read every counter of every device now (they are otherwise read once a minute)</source>
        <translation>Alle Zähler aller Geräte jetzt lesen (sonst werden sie einmal pro Minute gelesen)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="80"/>
        <source>Refresh counters</source>
        <translation>Zähler aktualisieren</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="82"/>
        <source>&amp;Export CSV…</source>
        <translation>CSV e&amp;xportieren…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="83"/>
        <source>Save every counter of every device as a CSV file</source>
        <translation>Alle Zähler aller Geräte als CSV-Datei speichern</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="84"/>
        <source>Export counters as CSV</source>
        <translation>Zähler als CSV exportieren</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="94"/>
        <source>No device is connected. Connect to a line to read its counters.</source>
        <translation>Kein Gerät verbunden. Verbinden Sie sich mit einer Leitung, um die Zähler ihrer Geräte zu lesen.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="146"/>
        <source>Reading the counters…</source>
        <translation>Zähler werden gelesen…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="149"/>
        <source>Last reading at %1</source>
        <translation>Letzte Abfrage um %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="151"/>
        <source>Waiting for the first reading…</source>
        <translation>Warte auf die erste Abfrage…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="211"/>
        <source>Station %1</source>
        <translation>Station %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="213"/>
        <location filename="../app/gui/pages/counterspage.cpp" line="244"/>
        <source>Counters of %1</source>
        <translation>Zähler von %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="229"/>
        <source>Port %1</source>
        <translation>Port %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="242"/>
        <source>Solder feeder %1</source>
        <translation>Lotdrahtvorschub %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="248"/>
        <source>Total</source>
        <translation>Gesamt</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="248"/>
        <source>Partial</source>
        <translation>Teilzähler</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="290"/>
        <source>%1 (R-%2)</source>
        <translation>%1 (R-%2)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="292"/>
        <source>Last read failed: %1</source>
        <translation>Letzte Abfrage fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="295"/>
        <source>Read at %1</source>
        <translation>Gelesen: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="298"/>
        <source>Not read yet</source>
        <translation>Noch nicht gelesen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="324"/>
        <source>%1 Monitor-only mode is on: nothing is reset.</source>
        <translation>%1 Der Modus „Nur beobachten“ ist aktiv: es wird nichts zurückgesetzt.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="327"/>
        <source>Reset partial counter</source>
        <translation>Teilzähler zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="328"/>
        <source>Reset “%1” on %2?</source>
        <translation>„%1“ an %2 zurücksetzen?</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="330"/>
        <source>It now reads %1.</source>
        <translation>Er steht jetzt auf %1.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="332"/>
        <source>The total counter is not affected.</source>
        <translation>Der Gesamtzähler bleibt unverändert.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="333"/>
        <source>Reset counter</source>
        <translation>Zähler zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="338"/>
        <source>%1 Nothing was reset.</source>
        <translation>%1 Es wurde nichts zurückgesetzt.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="344"/>
        <source>%1 Not reset: %2</source>
        <translation>%1 Nicht zurückgesetzt: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="347"/>
        <source>%1 Resetting %2…</source>
        <translation>%1 %2 wird zurückgesetzt…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="353"/>
        <source>%1 %2 reset.</source>
        <translation>%1 %2 zurückgesetzt.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="354"/>
        <source>%1 %2 was not reset: %3</source>
        <translation>%1 %2 wurde nicht zurückgesetzt: %3</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="367"/>
        <source>Monitor-only mode is on: TipScope writes nothing to the devices. Turn it off to reset counters.</source>
        <translation>Der Modus „Nur beobachten“ ist aktiv: TipScope schreibt nichts auf die Geräte. Schalten Sie ihn aus, um Zähler zurückzusetzen.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="387"/>
        <location filename="../app/gui/pages/counterspage.cpp" line="393"/>
        <source>Export counters</source>
        <translation>Zähler exportieren</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="387"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="391"/>
        <source>%1 Counters saved to %2</source>
        <translation>%1 Zähler in %2 gespeichert</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="394"/>
        <source>The counters could not be saved: %1</source>
        <translation>Die Zähler konnten nicht gespeichert werden: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.h" line="44"/>
        <source>Counters</source>
        <translation>Zähler</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::DeviceTree</name>
    <message>
        <location filename="../app/gui/devicetree.cpp" line="24"/>
        <source>Devices</source>
        <translation>Geräte</translation>
    </message>
    <message>
        <location filename="../app/gui/devicetree.cpp" line="121"/>
        <source>Fleet overview</source>
        <translation>Geräteübersicht</translation>
    </message>
    <message>
        <location filename="../app/gui/devicetree.cpp" line="187"/>
        <source>recording %1</source>
        <translation>Aufzeichnung %1</translation>
    </message>
    <message>
        <location filename="../app/gui/devicetree.cpp" line="188"/>
        <source>No line</source>
        <translation>Keine Leitung</translation>
    </message>
    <message>
        <location filename="../app/gui/devicetree.cpp" line="194"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/devicetree.cpp" line="195"/>
        <source>%1: %2 (%3)</source>
        <translation>%1: %2 (%3)</translation>
    </message>
    <message>
        <location filename="../app/gui/devicetree.cpp" line="203"/>
        <source>feeder</source>
        <translation>Lotdrahtvorschub</translation>
    </message>
    <message>
        <location filename="../app/gui/devicetree.cpp" line="203"/>
        <source>station</source>
        <translation>Station</translation>
    </message>
    <message>
        <location filename="../app/gui/devicetree.cpp" line="209"/>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location filename="../app/gui/devicetree.cpp" line="214"/>
        <source>Port %1: %2</source>
        <translation>Port %1: %2</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::DispensingPage</name>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="47"/>
        <source>Only the ALE has a built-in wire feed.</source>
        <translation>Nur die ALE hat einen eingebauten Drahtvorschub.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="57"/>
        <source>&amp;Start dispensing</source>
        <translation>Dosieren &amp;starten</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="58"/>
        <source>S&amp;top dispensing</source>
        <translation>Dosieren sto&amp;ppen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="59"/>
        <source>Ignore fuse error…</source>
        <translation>Sicherungsfehler ignorieren…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="65"/>
        <source>

Continue?</source>
        <translation>

Fortfahren?</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="77"/>
        <source>Wire feed settings</source>
        <translation>Einstellungen des Drahtvorschubs</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="87"/>
        <source>&amp;Apply</source>
        <translation>&amp;Anwenden</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="112"/>
        <source>%1 · dispensed %2 in %3 cycles · %4</source>
        <translation>%1 · %2 in %3 Zyklen dosiert · %4</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="116"/>
        <source>fuse unknown</source>
        <translation>Sicherung unbekannt</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="117"/>
        <source>fuse present</source>
        <translation>Sicherung vorhanden</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="118"/>
        <source>fuse missing or blown</source>
        <translation>Sicherung fehlt oder ist durchgebrannt</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="124"/>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="132"/>
        <source>no ALE</source>
        <translation>keine ALE</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.h" line="21"/>
        <source>Dispensing</source>
        <translation>Dosierung</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ErrorStatePanel</name>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="62"/>
        <source>%1, port %2</source>
        <translation>%1, Port %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="80"/>
        <source>Current state</source>
        <translation>Aktueller Zustand</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="84"/>
        <source>Current errors and alarms</source>
        <translation>Aktuelle Fehler und Alarme</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="86"/>
        <source>Where</source>
        <translation>Ort</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="86"/>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="86"/>
        <source>Severity</source>
        <translation>Schweregrad</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="86"/>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="86"/>
        <source>Temperature alarm</source>
        <translation>Temperaturalarm</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="97"/>
        <source>&amp;Reset feeder error</source>
        <translation>Vorschubfehler &amp;zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="99"/>
        <source>Reset feeder error</source>
        <translation>Vorschubfehler zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="101"/>
        <source>Result of the last action</source>
        <translation>Ergebnis der letzten Aktion</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="160"/>
        <source>No device is connected.</source>
        <translation>Kein Gerät verbunden.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="191"/>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="196"/>
        <source>Not read yet</source>
        <translation>Noch nicht gelesen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="193"/>
        <source>Error code %1: %2</source>
        <translation>Fehlercode %1: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="207"/>
        <source>This device has no temperature alarm</source>
        <translation>Dieses Gerät hat keinen Temperaturalarm</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="216"/>
        <source>%1, %2 alarm: %3</source>
        <translation>%1, Alarm %2: %3</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="243"/>
        <source>Not reset: %1</source>
        <translation>Nicht zurückgesetzt: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="246"/>
        <source>Resetting the feeder error…</source>
        <translation>Vorschubfehler wird zurückgesetzt…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="253"/>
        <source>Feeder error reset.</source>
        <translation>Vorschubfehler zurückgesetzt.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="254"/>
        <source>The feeder error was not reset: %1</source>
        <translation>Der Vorschubfehler wurde nicht zurückgesetzt: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="267"/>
        <source>Monitor-only mode is on: TipScope writes nothing to the devices. Turn it off to reset the feeder error.</source>
        <translation>Der Modus „Nur beobachten“ ist aktiv: TipScope schreibt nichts auf die Geräte. Schalten Sie ihn aus, um den Vorschubfehler zurückzusetzen.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="270"/>
        <source>No feeder is connected</source>
        <translation>Kein Lotdrahtvorschub verbunden</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="273"/>
        <source>Clears the feeder&apos;s error code (W-ECV); the feeder does not feed while an error is set</source>
        <translation>Löscht den Fehlercode des Lotdrahtvorschubs (W-ECV); solange ein Fehler ansteht, fördert er keinen Draht</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="108"/>
        <source>What to check</source>
        <translation>Was zu prüfen ist</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="213"/>
        <source>%1, %2: %3</source>
        <translation>%1, %2: %3</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="232"/>
        <source>What to check:</source>
        <translation>Was zu prüfen ist:</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ErrorsPage</name>
    <message>
        <location filename="../app/gui/pages/errorspage.h" line="20"/>
        <source>Errors</source>
        <translation>Fehler</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::EventHistoryPanel</name>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="48"/>
        <source>History</source>
        <translation>Verlauf</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="89"/>
        <source>Show events of kind</source>
        <translation>Ereignisse dieser Art anzeigen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="90"/>
        <source>All kinds</source>
        <translation>Alle Arten</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="91"/>
        <source>Errors and alarms</source>
        <translation>Fehler und Alarme</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="93"/>
        <source>Station errors</source>
        <translation>Stationsfehler</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="94"/>
        <source>Port errors</source>
        <translation>Portfehler</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="95"/>
        <source>Feeder errors</source>
        <translation>Vorschubfehler</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="96"/>
        <source>Alarms</source>
        <translation>Alarme</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="97"/>
        <source>Status changes</source>
        <translation>Statuswechsel</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="98"/>
        <source>Writes</source>
        <translation>Schreibzugriffe</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="99"/>
        <source>Communication</source>
        <translation>Kommunikation</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="100"/>
        <source>Connection</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="101"/>
        <source>Tool changes</source>
        <translation>Werkzeugwechsel</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="102"/>
        <source>Joints</source>
        <translation>Lötstellen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="103"/>
        <source>Profile applies</source>
        <translation>Profilanwendungen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="108"/>
        <source>Show events of device</source>
        <translation>Ereignisse des Geräts anzeigen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="109"/>
        <source>Every device</source>
        <translation>Alle Geräte</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="115"/>
        <source>Show events of severity</source>
        <translation>Ereignisse dieses Schweregrads anzeigen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="116"/>
        <source>Any severity</source>
        <translation>Jeder Schweregrad</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="117"/>
        <source>Warnings and errors</source>
        <translation>Warnungen und Fehler</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="118"/>
        <source>Errors only</source>
        <translation>Nur Fehler</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="121"/>
        <source>Show events containing</source>
        <translation>Ereignisse mit diesem Text anzeigen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="122"/>
        <source>Text in any column</source>
        <translation>Text in beliebiger Spalte</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="124"/>
        <source>&amp;Device:</source>
        <translation>&amp;Gerät:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="126"/>
        <source>&amp;Kind:</source>
        <translation>&amp;Art:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="128"/>
        <source>Se&amp;verity:</source>
        <translation>&amp;Schweregrad:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="130"/>
        <source>&amp;Search:</source>
        <translation>S&amp;uchen:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="164"/>
        <source>Event history</source>
        <translation>Ereignisverlauf</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="188"/>
        <source>Copy</source>
        <translation>Kopieren</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="194"/>
        <source>Events shown</source>
        <translation>Angezeigte Ereignisse</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="195"/>
        <source>&amp;Copy</source>
        <translation>&amp;Kopieren</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="197"/>
        <source>Copy the selected events to the clipboard (Ctrl+C)</source>
        <translation>Die ausgewählten Ereignisse in die Zwischenablage kopieren (Strg+C)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="198"/>
        <source>Copy selected events</source>
        <translation>Ausgewählte Ereignisse kopieren</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="199"/>
        <source>E&amp;xport…</source>
        <translation>E&amp;xportieren…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="201"/>
        <source>Save the events shown as a tab-separated text file</source>
        <translation>Die angezeigten Ereignisse als tabulatorgetrennte Textdatei speichern</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="202"/>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="345"/>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="351"/>
        <source>Export events</source>
        <translation>Ereignisse exportieren</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="204"/>
        <source>Result of the last export</source>
        <translation>Ergebnis des letzten Exports</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="296"/>
        <source>%1 of %2 events shown</source>
        <translation>%1 von %2 Ereignissen angezeigt</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="298"/>
        <source>%n older events were dropped</source>
        <translation>
            <numerusform>%n älteres Ereignis wurde verworfen</numerusform>
            <numerusform>%n ältere Ereignisse wurden verworfen</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="345"/>
        <source>Text files (*.txt *.tsv)</source>
        <translation>Textdateien (*.txt *.tsv)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="349"/>
        <source>Saved to %1</source>
        <translation>Gespeichert in %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="352"/>
        <source>The events could not be saved: %1</source>
        <translation>Die Ereignisse konnten nicht gespeichert werden: %1</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::FeederPage</name>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="47"/>
        <source>No feeder on this line.</source>
        <translation>Kein Lotdrahtvorschub an dieser Leitung.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="71"/>
        <source>Feed &amp;forward</source>
        <translation>Draht vor&amp;wärts</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="71"/>
        <source>W-SFD 00001</source>
        <translation>W-SFD 00001</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="72"/>
        <source>Feed &amp;backward</source>
        <translation>Draht &amp;rückwärts</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="72"/>
        <source>W-SFD 00000</source>
        <translation>W-SFD 00000</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="73"/>
        <source>&amp;Stop</source>
        <translation>&amp;Stopp</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="73"/>
        <source>W-SSD</source>
        <translation>W-SSD</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="74"/>
        <source>Start &amp;loading</source>
        <translation>Ein&amp;fädeln starten</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="74"/>
        <source>W-SLD 00001: feed ignoring errors, for a new spool</source>
        <translation>W-SLD 00001: Vorschub ohne Fehlerprüfung, für eine neue Spule</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="76"/>
        <source>End loading</source>
        <translation>Einfädeln beenden</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="76"/>
        <source>W-SLD 00000</source>
        <translation>W-SLD 00000</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="82"/>
        <source>&amp;Reset error</source>
        <translation>Fehler &amp;zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="88"/>
        <source>Feeding settings</source>
        <translation>Vorschubeinstellungen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="99"/>
        <location filename="../app/gui/pages/feederpage.cpp" line="176"/>
        <source>&amp;Apply</source>
        <translation>&amp;Anwenden</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="100"/>
        <source>Re&amp;vert</source>
        <translation>Zurück&amp;nehmen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="101"/>
        <source>Discard the values typed here and show the feeder&apos;s own</source>
        <translation>Die hier eingegebenen Werte verwerfen und wieder die des Lotdrahtvorschubs zeigen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="102"/>
        <source>Save to feeder memory</source>
        <translation>Im Speicher des Lotdrahtvorschubs sichern</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="103"/>
        <source>W-NVS: mode, speed and length survive a restart</source>
        <translation>W-NVS: Modus, Geschwindigkeit und Länge bleiben nach einem Neustart erhalten</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="117"/>
        <source>Counters</source>
        <translation>Zähler</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="125"/>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="150"/>
        <source>Feeding</source>
        <translation>Vorschub läuft</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="150"/>
        <source>Idle</source>
        <translation>Bereit</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="150"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="151"/>
        <source>%1 · fed %2</source>
        <translation>%1 · vorgeschoben %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="153"/>
        <source>⚠ %1</source>
        <translation>⚠ %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="153"/>
        <source>No feeder error</source>
        <translation>Kein Vorschubfehler</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="163"/>
        <location filename="../app/gui/pages/feederpage.cpp" line="178"/>
        <source>Monitor-only mode is on: nothing is written</source>
        <translation>Der Modus „Nur beobachten“ ist aktiv: es wird nichts geschrieben</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="176"/>
        <source>&amp;Apply (%1)</source>
        <translation>&amp;Anwenden (%1)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="179"/>
        <source>A value typed is not allowed: correct it or Revert</source>
        <translation>Ein eingegebener Wert ist nicht zulässig: korrigieren oder zurücknehmen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="202"/>
        <location filename="../app/gui/pages/feederpage.cpp" line="208"/>
        <location filename="../app/gui/pages/feederpage.cpp" line="214"/>
        <location filename="../app/gui/pages/feederpage.cpp" line="220"/>
        <source>no feeder</source>
        <translation>kein Lotdrahtvorschub</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="229"/>
        <source>no such counter</source>
        <translation>diesen Zähler gibt es nicht</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="232"/>
        <source>

Reset it?</source>
        <translation>

Zurücksetzen?</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="235"/>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.h" line="25"/>
        <source>Feeder</source>
        <translation>Lotdrahtvorschub</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::FleetPage</name>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="32"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="33"/>
        <source>Line</source>
        <translation>Leitung</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="34"/>
        <source>State, worst first</source>
        <translation>Zustand, schlechtester zuerst</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="35"/>
        <source>Sort by:</source>
        <translation>Sortieren nach:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="37"/>
        <source>Needs attention only</source>
        <translation>Nur was Aufmerksamkeit braucht</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="131"/>
        <source>Devices: %1 · need attention: %2</source>
        <translation>Geräte: %1 · brauchen Aufmerksamkeit: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="132"/>
        <source>%1 · lines without a device: %2</source>
        <translation>%1 · Linien ohne Gerät: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="268"/>
        <source>No devices yet: nothing has come from the plant&apos;s broker.</source>
        <translation>Noch keine Geräte: vom Broker des Werks ist nichts gekommen.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="269"/>
        <source>No devices: the workspace&apos;s lines have found none yet.</source>
        <translation>Keine Geräte: die Leitungen des Arbeitsbereichs haben noch keine gefunden.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="267"/>
        <source>No device needs attention.</source>
        <translation>Kein Gerät braucht Aufmerksamkeit.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.h" line="58"/>
        <source>Fleet</source>
        <translation>Geräteübersicht</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::FleetTileWidget</name>
    <message>
        <location filename="../app/gui/pages/fleet/fleettilewidget.cpp" line="77"/>
        <source>P%1  %2 / %3  %4  %5</source>
        <translation>P%1  %2 / %3  %4  %5</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleettilewidget.cpp" line="102"/>
        <source>Last joint: %1 (port %2)</source>
        <translation>Letzte Lötstelle: %1 (Port %2)</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::FrameBuilder</name>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="35"/>
        <source>Send a frame</source>
        <translation>Telegramm senden</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="62"/>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="67"/>
        <source>Header</source>
        <translation>Kopf</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="68"/>
        <source>R (read)</source>
        <translation>R (lesen)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="69"/>
        <source>W (write)</source>
        <translation>W (schreiben)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="71"/>
        <source>Command</source>
        <translation>Befehl</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="83"/>
        <source>Data field</source>
        <translation>Datenfeld</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="89"/>
        <source>&amp;Send frame</source>
        <translation>Telegramm &amp;senden</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="90"/>
        <source>Send frame</source>
        <translation>Telegramm senden</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="92"/>
        <source>Frame to be sent</source>
        <translation>Zu sendendes Telegramm</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="96"/>
        <source>Catalog check</source>
        <translation>Katalogprüfung</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="99"/>
        <source>Raw bytes in hex</source>
        <translation>Rohbytes hexadezimal</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="103"/>
        <source>Send ra&amp;w hex</source>
        <translation>Roh-He&amp;x senden</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="104"/>
        <source>Send raw hex</source>
        <translation>Roh-Hex senden</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="106"/>
        <source>Raw bytes check</source>
        <translation>Prüfung der Rohbytes</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="107"/>
        <source>Nothing sent yet.</source>
        <translation>Noch nichts gesendet.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="108"/>
        <source>Outcome of the last send</source>
        <translation>Ergebnis des letzten Sendens</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="117"/>
        <source>&amp;Device</source>
        <translation>Ger&amp;ät</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="119"/>
        <source>&amp;Header</source>
        <translation>&amp;Kopf</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="121"/>
        <source>C&amp;ommand</source>
        <translation>Befeh&amp;l</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="123"/>
        <source>D&amp;ata</source>
        <translation>Date&amp;n</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="126"/>
        <source>Frame</source>
        <translation>Telegramm</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="129"/>
        <source>&amp;Raw hex</source>
        <translation>&amp;Roh-Hex</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="133"/>
        <source>Last send</source>
        <translation>Letztes Senden</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="242"/>
        <source>Send these bytes exactly as typed; the answer appears in the table.</source>
        <translation>Diese Bytes genau wie eingegeben senden; die Antwort erscheint in der Tabelle.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="213"/>
        <source>(nothing to send)</source>
        <translation>(nichts zu senden)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="88"/>
        <location filename="../app/gui/pages/framebuilder.cpp" line="217"/>
        <source>none for reads</source>
        <translation>keine (Lesen)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="88"/>
        <location filename="../app/gui/pages/framebuilder.cpp" line="217"/>
        <source>e.g. 00350</source>
        <translation>z. B. 00350</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="229"/>
        <source>Send this frame once, as shown (no retries; catalog warnings do not stop it). Its answer appears in the table.</source>
        <translation>Dieses Telegramm einmal wie angezeigt senden (ohne Wiederholungen; Katalogwarnungen halten es nicht auf). Die Antwort erscheint in der Tabelle.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="264"/>
        <source>Not sent: %1</source>
        <translation>Nicht gesendet: %1</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::JointLimitsDialog</name>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="42"/>
        <source>Joint limits</source>
        <translation>Lötstellen-Grenzwerte</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="48"/>
        <source> s</source>
        <translation> s</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="53"/>
        <source> K</source>
        <translation> K</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="58"/>
        <source> %</source>
        <translation> %</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="63"/>
        <source>Port</source>
        <translation>Port</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="63"/>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="63"/>
        <source>Longest recovery (s)</source>
        <translation>Längste Erholzeit (s)</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="64"/>
        <source>Deepest dip (K)</source>
        <translation>Tiefster Einbruch (K)</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="64"/>
        <source>Tip wear (%)</source>
        <translation>Spitzenverschleiß (%)</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="69"/>
        <source>Add rule</source>
        <translation>Regel hinzufügen</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="70"/>
        <source>Remove rule</source>
        <translation>Regel entfernen</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="82"/>
        <source>Longest recovery (back within 5 K of the setpoint):</source>
        <translation>Längste Erholzeit (zurück auf 5 K am Sollwert):</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="83"/>
        <source>Deepest dip below the setpoint:</source>
        <translation>Tiefster Einbruch unter den Sollwert:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="84"/>
        <source>Tip wearing when recoveries are slower than when new by:</source>
        <translation>Spitze verschleißt, wenn Erholungen langsamer sind als neu um:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="85"/>
        <source>Rules for a port, a tool or both override these; the most specific rule wins. An empty cell keeps the default.</source>
        <translation>Regeln für einen Port, ein Werkzeug oder beides haben Vorrang; die genaueste Regel gilt. Eine leere Zelle behält den Standardwert.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="116"/>
        <source>Any port</source>
        <translation>Jeder Port</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="118"/>
        <source>Port %1</source>
        <translation>Port %1</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="159"/>
        <source>Rule %1: %2</source>
        <translation>Regel %1: %2</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::JointsPage</name>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="98"/>
        <source>Double-click a joint, or press Enter, to see it on the Charts page</source>
        <translation>Doppelklick auf eine Lötstelle oder Eingabetaste zeigt sie auf der Seite Diagramme</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="138"/>
        <source>All devices</source>
        <translation>Alle Geräte</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="140"/>
        <source>All ports</source>
        <translation>Alle Ports</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="142"/>
        <source>Port %1</source>
        <translation>Port %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="144"/>
        <source>all tools</source>
        <translation>alle Werkzeuge</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="147"/>
        <source>All verdicts</source>
        <translation>Alle Bewertungen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="151"/>
        <source>Last hour</source>
        <translation>Letzte Stunde</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="151"/>
        <source>Last 24 hours</source>
        <translation>Letzte 24 Stunden</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="151"/>
        <source>Last 7 days</source>
        <translation>Letzte 7 Tage</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="152"/>
        <source>Last 30 days</source>
        <translation>Letzte 30 Tage</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="152"/>
        <source>All times</source>
        <translation>Gesamte Zeit</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="156"/>
        <source>all work orders</source>
        <translation>alle Aufträge</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="158"/>
        <source>Reload</source>
        <translation>Neu laden</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="159"/>
        <source>Read the journal again</source>
        <translation>Das Journal neu lesen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="160"/>
        <source>Export CSV…</source>
        <translation>CSV exportieren…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="161"/>
        <source>Save the listed joints as a CSV file</source>
        <translation>Die aufgeführten Lötstellen als CSV-Datei speichern</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="164"/>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="164"/>
        <source>Port</source>
        <translation>Port</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="165"/>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="165"/>
        <source>Verdict</source>
        <translation>Bewertung</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="166"/>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="166"/>
        <source>Work order</source>
        <translation>Auftrag</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pages/jointspage.cpp" line="272"/>
        <source>%n joint(s) listed.</source>
        <translation>
            <numerusform>%n Lötstelle aufgeführt.</numerusform>
            <numerusform>%n Lötstellen aufgeführt.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="274"/>
        <source>Only the newest %1 from the journal: narrow the filter to see older ones.</source>
        <translation>Nur die neuesten %1 aus dem Journal: schränken Sie den Filter ein, um ältere zu sehen.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="278"/>
        <source>The journal could not be read (%1): only this session&apos;s joints are listed.</source>
        <translation>Das Journal konnte nicht gelesen werden (%1): nur die Lötstellen dieser Sitzung sind aufgeführt.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="282"/>
        <source>No journal yet: this session&apos;s joints only.</source>
        <translation>Noch kein Journal: nur die Lötstellen dieser Sitzung.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pages/jointspage.cpp" line="362"/>
        <source>%n joint(s) written to %1.</source>
        <translation>
            <numerusform>%n Lötstelle in %1 geschrieben.</numerusform>
            <numerusform>%n Lötstellen in %1 geschrieben.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="374"/>
        <source>Export joints</source>
        <translation>Lötstellen exportieren</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="374"/>
        <source>CSV file (*.csv)</source>
        <translation>CSV-Datei (*.csv)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.h" line="48"/>
        <source>Joints</source>
        <translation>Lötstellen</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::JournalStatusButton</name>
    <message>
        <location filename="../app/gui/journalstatusbutton.cpp" line="11"/>
        <source>No work order</source>
        <translation>Kein Auftrag</translation>
    </message>
    <message>
        <location filename="../app/gui/journalstatusbutton.cpp" line="26"/>
        <source>Work context and journal</source>
        <translation>Arbeitskontext und Journal</translation>
    </message>
    <message>
        <location filename="../app/gui/journalstatusbutton.cpp" line="47"/>
        <source>Stamped on every joint and event: %1. Click to change it.</source>
        <translation>Wird jeder Lötstelle und jedem Ereignis mitgegeben: %1. Zum Ändern klicken.</translation>
    </message>
    <message>
        <location filename="../app/gui/journalstatusbutton.cpp" line="48"/>
        <source>Journal: %1</source>
        <translation>Journal: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/journalstatusbutton.cpp" line="51"/>
        <source>Journal not written</source>
        <translation>Journal wird nicht geschrieben</translation>
    </message>
    <message>
        <location filename="../app/gui/journalstatusbutton.cpp" line="54"/>
        <source>%1 records wait to be written; polling goes on.</source>
        <translation>%1 Einträge warten aufs Schreiben; die Abfrage läuft weiter.</translation>
    </message>
    <message>
        <location filename="../app/gui/journalstatusbutton.cpp" line="57"/>
        <source>%1 records lost</source>
        <translation>%1 Einträge verloren</translation>
    </message>
    <message>
        <location filename="../app/gui/journalstatusbutton.cpp" line="61"/>
        <source>Work context unreadable</source>
        <translation>Arbeitskontext unlesbar</translation>
    </message>
    <message>
        <location filename="../app/gui/journalstatusbutton.cpp" line="64"/>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::LinkStatusLabel</name>
    <message>
        <location filename="../app/gui/linkstatuslabel.cpp" line="10"/>
        <source>Line statistics</source>
        <translation>Leitungsstatistik</translation>
    </message>
    <message>
        <location filename="../app/gui/linkstatuslabel.cpp" line="27"/>
        <source>no line</source>
        <translation>keine Leitung</translation>
    </message>
    <message>
        <location filename="../app/gui/linkstatuslabel.cpp" line="33"/>
        <source>%L1 tx/s · %L2 ms · %3 timeouts · %4 BCC errors · %5 NAKs</source>
        <translation>%L1 tx/s · %L2 ms · %3 Zeitüberschreitungen · %4 BCC-Fehler · %5 NAKs</translation>
    </message>
    <message>
        <location filename="../app/gui/linkstatuslabel.cpp" line="41"/>
        <source>NAK %1 × %2: %3</source>
        <translation>NAK %1 × %2: %3</translation>
    </message>
    <message>
        <location filename="../app/gui/linkstatuslabel.cpp" line="46"/>
        <source>Reconnects: %1</source>
        <translation>Neuverbindungen: %1</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::MainWindow</name>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="63"/>
        <source>Connection</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="139"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="143"/>
        <source>Work &amp;context…</source>
        <translation>Arbeits&amp;kontext…</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="147"/>
        <source>Write &amp;support report…</source>
        <translation>&amp;Supportbericht schreiben…</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="148"/>
        <source>&amp;Board report…</source>
        <translation>&amp;Platinenbericht…</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="156"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="157"/>
        <source>&amp;Tools</source>
        <translation>&amp;Extras</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="158"/>
        <source>&amp;Preferences…</source>
        <translation>&amp;Optionen…</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="166"/>
        <source>&amp;Joint limits…</source>
        <translation>&amp;Lötstellen-Grenzwerte…</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="167"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="168"/>
        <source>&amp;About TipScope</source>
        <translation>&amp;Über TipScope</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="170"/>
        <source>About TipScope</source>
        <translation>Über TipScope</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="171"/>
        <source>&lt;b&gt;TipScope %1&lt;/b&gt;&lt;p&gt;Configures and monitors JBC soldering control units (UCR, ALE, NAE, DDE, DME, HDE, DDR, HDR) and the SFR solder feeder over their RS-232 robot protocol.&lt;/p&gt;</source>
        <translation>&lt;b&gt;TipScope %1&lt;/b&gt;&lt;p&gt;Konfiguriert und überwacht JBC-Lötsteuergeräte (UCR, ALE, NAE, DDE, DME, HDE, DDR, HDR) und den SFR-Lotdrahtvorschub über ihr RS-232-Roboterprotokoll.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="297"/>
        <source>new workspace</source>
        <translation>neuer Arbeitsbereich</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/mainwindow.cpp" line="299"/>
        <source>TipScope — %1 (%n line(s))</source>
        <translation>
            <numerusform>TipScope — %1 (%n Linie)</numerusform>
            <numerusform>TipScope — %1 (%n Linien)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="302"/>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="307"/>
        <source>TipScope — %1</source>
        <translation>TipScope — %1</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="312"/>
        <source>Folder for the support report</source>
        <translation>Ordner für den Supportbericht</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="326"/>
        <location filename="../app/gui/mainwindow.cpp" line="329"/>
        <source>Support report</source>
        <translation>Supportbericht</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="330"/>
        <source>Written:
%1

Attach both files to the support ticket.</source>
        <translation>Geschrieben:
%1

Hängen Sie beide Dateien an das Support-Ticket an.</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="343"/>
        <source>joint limits</source>
        <translation>Lötstellen-Grenzwerte</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="344"/>
        <source>%1; the default limits judge joints</source>
        <translation>%1; die Standard-Grenzwerte bewerten die Lötstellen</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="31"/>
        <source>&amp;Open workspace…</source>
        <translation>Arbeitsbereich ö&amp;ffnen…</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="33"/>
        <source>&amp;Save workspace</source>
        <translation>Arbeitsbereich &amp;speichern</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="35"/>
        <source>Save workspace &amp;as…</source>
        <translation>Arbeitsbereich speichern &amp;unter…</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="37"/>
        <source>&amp;Add this line to the workspace…</source>
        <translation>Diese Linie zum Arbeitsbereich &amp;hinzufügen…</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="40"/>
        <source>C&amp;lose workspace</source>
        <translation>Arbeitsbereich s&amp;chließen</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="61"/>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="73"/>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="121"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="103"/>
        <source>The last workspace was not reopened: %1</source>
        <translation>Der letzte Arbeitsbereich wurde nicht wieder geöffnet: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/mainwindowworkspace.cpp" line="123"/>
        <source>Workspace: %1 of %n line(s) connected</source>
        <translation>
            <numerusform>Arbeitsbereich: %1 von %n Linie verbunden</numerusform>
            <numerusform>Arbeitsbereich: %1 von %n Linien verbunden</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/mainwindowworkspace.cpp" line="133"/>
        <source>the workspace&apos;s %n line(s) are in the tree</source>
        <translation>
            <numerusform>die %n Linie des Arbeitsbereichs steht im Baum</numerusform>
            <numerusform>die %n Linien des Arbeitsbereichs stehen im Baum</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="135"/>
        <source>the plant&apos;s devices are on the fleet overview</source>
        <translation>die Geräte der Anlage sind in der Flottenübersicht</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="142"/>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="147"/>
        <source>Open workspace</source>
        <translation>Arbeitsbereich öffnen</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="143"/>
        <source>TipScope workspaces (*.json);;All files (*)</source>
        <translation>TipScope-Arbeitsbereiche (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="154"/>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="160"/>
        <source>Save workspace</source>
        <translation>Arbeitsbereich speichern</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="156"/>
        <source>TipScope workspaces (*.json)</source>
        <translation>TipScope-Arbeitsbereiche (*.json)</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="169"/>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="174"/>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="183"/>
        <source>Add this line to the workspace</source>
        <translation>Diese Linie zum Arbeitsbereich hinzufügen</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="174"/>
        <source>Name of the line (cell, station):</source>
        <translation>Name der Linie (Zelle, Station):</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="175"/>
        <source>line-%1</source>
        <translation>linie-%1</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowplant.cpp" line="18"/>
        <source>Connect to &amp;plant…</source>
        <translation>Mit dem &amp;Werk verbinden…</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowplant.cpp" line="24"/>
        <source>Disconnect from p&amp;lant</source>
        <translation>Vom W&amp;erk trennen</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowplant.cpp" line="64"/>
        <source>Plant: %1</source>
        <translation>Werk: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowplant.cpp" line="65"/>
        <source>Plant: %1 not connected</source>
        <translation>Werk: %1 nicht verbunden</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowplant.cpp" line="66"/>
        <source>Watching %1 on the plant&apos;s broker</source>
        <translation>Verfolgt %1 auf dem Broker des Werks</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::OverviewPage</name>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="132"/>
        <source>&lt;i&gt;No station. Connect to a line, or start the demo.&lt;/i&gt;</source>
        <translation>&lt;i&gt;Keine Station. Verbinden Sie sich mit einer Leitung oder starten Sie die Demo.&lt;/i&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="133"/>
        <source>&lt;i&gt;No station on this line.&lt;/i&gt;</source>
        <translation>&lt;i&gt;Keine Station an dieser Linie.&lt;/i&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="140"/>
        <source>family %1</source>
        <translation>Familie %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="141"/>
        <source>software %1</source>
        <translation>Software %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="142"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="144"/>
        <source>transformer %1</source>
        <translation>Transformator %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="146"/>
        <source>fuse present</source>
        <translation>Sicherung vorhanden</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="147"/>
        <source>&lt;span style=&apos;color:#c01c28&apos;&gt;fuse missing or blown&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c01c28&apos;&gt;Sicherung fehlt oder ist durchgebrannt&lt;/span&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="153"/>
        <source>⚠ Station error: %1</source>
        <translation>⚠ Stationsfehler: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="164"/>
        <source>feeding</source>
        <translation>Vorschub läuft</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="164"/>
        <source>idle</source>
        <translation>bereit</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="166"/>
        <source>fed %1</source>
        <translation>vorgeschoben %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="168"/>
        <source>speed %1</source>
        <translation>Geschwindigkeit %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.h" line="28"/>
        <source>Overview</source>
        <translation>Übersicht</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="173"/>
        <source>not connected, as last read</source>
        <translation>nicht verbunden, wie zuletzt gelesen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="194"/>
        <source>⚠ Not connected: nothing has been read yet. The robot controls are off until the line is back.</source>
        <translation>⚠ Nicht verbunden: noch nichts gelesen. Die Robotersteuerung ist aus, bis die Leitung wieder da ist.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="196"/>
        <source>⚠ Not connected: the greyed values are as last read at %1. The robot controls are off until the line is back.</source>
        <translation>⚠ Nicht verbunden: die grauen Werte sind wie zuletzt um %1 gelesen. Die Robotersteuerung ist aus, bis die Leitung wieder da ist.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="200"/>
        <source>Monitor-only mode is on: the robot controls are off.</source>
        <translation>Nur-Beobachten ist an: die Robotersteuerung ist aus.</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ParameterEditor</name>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="73"/>
        <source>Allowed: %1</source>
        <translation>Zulässig: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="74"/>
        <source>Command: %1</source>
        <translation>Befehl: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="98"/>
        <source>%1 disabled</source>
        <translation>%1 deaktiviert</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="184"/>
        <source>not read</source>
        <translation>nicht gelesen</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="187"/>
        <source>reading…</source>
        <translation>wird gelesen…</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="190"/>
        <source>✓ in sync</source>
        <translation>✓ synchron</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="194"/>
        <source>✓ in sync, not yet saved</source>
        <translation>✓ synchron, noch nicht gesichert</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="196"/>
        <source>Written and read back. The station forgets it when it restarts, unless it is saved to station memory.</source>
        <translation>Geschrieben und zurückgelesen. Die Station vergisst den Wert beim Neustart, wenn er nicht im Stationsspeicher gesichert wird.</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="204"/>
        <source>edited</source>
        <translation>geändert</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="208"/>
        <source>writing…</source>
        <translation>wird geschrieben…</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="211"/>
        <source>✗ failed</source>
        <translation>✗ fehlgeschlagen</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="216"/>
        <source>✗ refused</source>
        <translation>✗ abgelehnt</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="200"/>
        <source>last read %1</source>
        <translation>zuletzt gelesen %1</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::PlantDialog</name>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="24"/>
        <source>Connect to plant</source>
        <translation>Mit dem Werk verbinden</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="34"/>
        <source>every site</source>
        <translation>alle Standorte</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="35"/>
        <source>The fleet overview shows every device the line PCs publish there; their pages are read-only. This window publishes nothing.</source>
        <translation>Die Geräteübersicht zeigt jedes Gerät, das die Linien-PCs dort veröffentlichen; ihre Seiten sind schreibgeschützt. Dieses Fenster veröffentlicht nichts.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="40"/>
        <source>&amp;Broker:</source>
        <translation>&amp;Broker:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="41"/>
        <source>P&amp;ort:</source>
        <translation>P&amp;ort:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="42"/>
        <source>&amp;User name:</source>
        <translation>&amp;Benutzername:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="43"/>
        <source>&amp;Password:</source>
        <translation>&amp;Passwort:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="44"/>
        <source>&amp;Site:</source>
        <translation>&amp;Standort:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="46"/>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="74"/>
        <source>the broker&apos;s host name or address</source>
        <translation>Hostname oder Adresse des Brokers</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::PortCard</name>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="49"/>
        <source>Port %1</source>
        <translation>Port %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="63"/>
        <source>Tip temperature, port %1</source>
        <translation>Spitzentemperatur, Port %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="69"/>
        <source>Power, port %1</source>
        <translation>Leistung, Port %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="91"/>
        <source>Work</source>
        <translation>Arbeiten</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="92"/>
        <source>Stand</source>
        <translation>Ablage</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="93"/>
        <source>Cool</source>
        <translation>Abkühlen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="94"/>
        <source>W-PS%1 00000: heat to the selected temperature</source>
        <translation>W-PS%1 00000: auf die eingestellte Temperatur heizen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="95"/>
        <source>W-PS%1 00001: stand; sleep and hibernation follow after their delays</source>
        <translation>W-PS%1 00001: Ablage; Ruhemodus und Tiefschlaf folgen nach ihren Verzögerungen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="97"/>
        <source>W-PS%1 00010: cooling (extractor stand-by)</source>
        <translation>W-PS%1 00010: Abkühlen (Absaugung in Bereitschaft)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="101"/>
        <source>New selected temperature, port %1</source>
        <translation>Neue eingestellte Temperatur, Port %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="102"/>
        <source>Set</source>
        <translation>Setzen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="228"/>
        <source>no recovery</source>
        <translation>keine Erholung</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="230"/>
        <source>last joint %1, %2</source>
        <translation>letzte Lötstelle %1, %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="259"/>
        <source>Port %1 — %2</source>
        <translation>Port %1 — %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="260"/>
        <source>— °</source>
        <translation>— °</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="261"/>
        <source>set %1</source>
        <translation>Soll %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="263"/>
        <source>power %1</source>
        <translation>Leistung %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="289"/>
        <source>status unknown</source>
        <translation>Status unbekannt</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="267"/>
        <source>transistor %1</source>
        <translation>Transistor %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="269"/>
        <source>%1 until the next mode</source>
        <translation>%1 bis zum nächsten Modus</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="301"/>
        <location filename="../app/gui/pages/portcard.cpp" line="304"/>
        <source>⚠ Error: %1</source>
        <translation>⚠ Fehler: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="309"/>
        <source>status: %1</source>
        <translation>Zustand: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="311"/>
        <source>alarm: %1</source>
        <translation>Alarm: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="279"/>
        <source>Not connected: last read %1</source>
        <translation>Nicht verbunden: zuletzt gelesen %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="281"/>
        <source>Not connected: not read yet</source>
        <translation>Nicht verbunden: noch nicht gelesen</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::PreferencesDialog</name>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="33"/>
        <source>Preferences</source>
        <translation>Optionen</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="35"/>
        <source>Celsius (°C)</source>
        <translation>Celsius (°C)</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="36"/>
        <source>Fahrenheit (°F)</source>
        <translation>Fahrenheit (°F)</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="38"/>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="39"/>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="41"/>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="43"/>
        <source> min</source>
        <translation> min</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="44"/>
        <source> h</source>
        <translation> h</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="46"/>
        <source>Follow the system</source>
        <translation>Systemsprache</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="51"/>
        <source> days</source>
        <translation> Tage</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="52"/>
        <source>Keep everything</source>
        <translation>Alles behalten</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="54"/>
        <source>Joints and events older than this are deleted from the journal, a little at a time so polling never waits. Every TipScope program that keeps this journal uses the same retention.</source>
        <translation>Lötstellen und Ereignisse, die älter sind, werden nach und nach aus dem Journal gelöscht, sodass die Abfrage nie wartet. Jedes TipScope-Programm, das dieses Journal führt, verwendet dieselbe Aufbewahrungsdauer.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="58"/>
        <source>Temperature unit:</source>
        <translation>Temperatureinheit:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="59"/>
        <source>Live values (visible ports) every:</source>
        <translation>Live-Werte (sichtbare Ports) alle:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="60"/>
        <source>Errors, alarms and status every:</source>
        <translation>Fehler, Alarme und Status alle:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="61"/>
        <source>Counters every:</source>
        <translation>Zähler alle:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="62"/>
        <source>Device turnaround (added to the wire time):</source>
        <translation>Antwortzeit des Geräts (zur Übertragungszeit addiert):</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="63"/>
        <source>Retries after a lost or corrupted answer:</source>
        <translation>Wiederholungen nach verlorener oder beschädigter Antwort:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="64"/>
        <source>Chart history at full rate:</source>
        <translation>Diagrammverlauf in voller Rate:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="65"/>
        <source>Chart history in all:</source>
        <translation>Diagrammverlauf insgesamt:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="66"/>
        <source>Language (on the next start):</source>
        <translation>Sprache (beim nächsten Start):</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="67"/>
        <source>Keep journal records for:</source>
        <translation>Journaleinträge behalten für:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="69"/>
        <source>The wire always carries °C; the unit only changes what you see and type. The colours follow the desktop theme. Chart history older than the full-rate part keeps min, max and mean per 5 s (about 1.4 MB a port for a day); it applies to devices found from then on.</source>
        <translation>Auf der Leitung wird immer °C übertragen; die Einheit ändert nur, was Sie sehen und eingeben. Die Farben folgen dem Desktop-Design. Vom Diagrammverlauf, der älter ist als der Teil in voller Rate, bleiben Minimum, Maximum und Mittelwert je 5 s (etwa 1,4 MB je Port für einen Tag); das gilt für Geräte, die danach gefunden werden.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="40"/>
        <source> s</source>
        <translation> s</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ProfileDialog</name>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="23"/>
        <source>Profile for %1</source>
        <translation>Profil für %1</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="30"/>
        <source>Setting</source>
        <translation>Einstellung</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="30"/>
        <source>Device now</source>
        <translation>Gerät jetzt</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="30"/>
        <source>Profile</source>
        <translation>Profil</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="38"/>
        <source>The dry run&apos;s frames and the apply report appear here.</source>
        <translation>Hier erscheinen die Telegramme des Probelaufs und der Bericht der Übernahme.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="42"/>
        <source>Apply anyway: the profile is for a %1, this is a %2 (only the settings both have are written)</source>
        <translation>Trotzdem anwenden: das Profil ist für %1, dieses Gerät ist %2 (nur die Einstellungen, die beide haben, werden geschrieben)</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="48"/>
        <source>Compare again</source>
        <translation>Erneut vergleichen</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="49"/>
        <source>Dry run</source>
        <translation>Probelauf</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="50"/>
        <source>Apply to device</source>
        <translation>Auf Gerät anwenden</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="51"/>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="71"/>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="116"/>
        <source>Monitor-only mode is on: nothing is written</source>
        <translation>Der Modus „Nur beobachten“ ist aktiv: es wird nichts geschrieben</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="185"/>
        <source>Profile from %1 (%2, software %3), created %4: %n setting(s) differ from the device.</source>
        <translation>
            <numerusform>Profil von %1 (%2, Software %3), erstellt: %4. %n Einstellung weicht vom Gerät ab.</numerusform>
            <numerusform>Profil von %1 (%2, Software %3), erstellt: %4. %n Einstellungen weichen vom Gerät ab.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="176"/>
        <source>Dry run: %n frame(s) would be sent; nothing was written.</source>
        <translation>
            <numerusform>Probelauf: %n Telegramm würde gesendet; nichts wurde geschrieben.</numerusform>
            <numerusform>Probelauf: %n Telegramme würden gesendet; nichts wurde geschrieben.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="114"/>
        <source>The profile would break the device&apos;s limits; see above</source>
        <translation>Das Profil würde die Grenzen des Geräts verletzen; siehe oben</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="172"/>
        <source>&lt;b&gt;This profile cannot be applied to this device:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Dieses Profil lässt sich auf dieses Gerät nicht anwenden:&lt;/b&gt; %1</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="30"/>
        <source>Note</source>
        <translation>Hinweis</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="180"/>
        <source>&lt;b&gt;Applied.&lt;/b&gt; Every written value was read back and matches; the table shows the device as it now is.</source>
        <translation>&lt;b&gt;Angewendet.&lt;/b&gt; Jeder geschriebene Wert wurde zurückgelesen und stimmt; die Tabelle zeigt das Gerät, wie es jetzt ist.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="182"/>
        <source>&lt;b&gt;Not everything was applied.&lt;/b&gt; The table shows the device as it now is; see the report below.</source>
        <translation>&lt;b&gt;Nicht alles wurde angewendet.&lt;/b&gt; Die Tabelle zeigt das Gerät, wie es jetzt ist; siehe den Bericht unten.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="193"/>
        <source>Comment: %1</source>
        <translation>Kommentar: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="151"/>
        <source>✓ changed from %1</source>
        <translation>✓ geändert von %1</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="152"/>
        <source>✗ failed: %1</source>
        <translation>✗ fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="156"/>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="157"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="157"/>
        <source>skipped: %1</source>
        <translation>übersprungen: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="165"/>
        <source>%n setting(s) of the profile skipped: this device does not take them.</source>
        <translation>
            <numerusform>%n Einstellung des Profils übersprungen: dieses Gerät nimmt sie nicht an.</numerusform>
            <numerusform>%n Einstellungen des Profils übersprungen: dieses Gerät nimmt sie nicht an.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="168"/>
        <source>&lt;b&gt;Refused, nothing was written:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Abgelehnt, nichts wurde geschrieben:&lt;/b&gt; %1</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="170"/>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="174"/>
        <source>The table shows what the profile would change.</source>
        <translation>Die Tabelle zeigt, was das Profil ändern würde.</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::RecoveryHistogramView</name>
    <message>
        <location filename="../app/gui/pages/jointcharts.cpp" line="57"/>
        <source>Histogram of recovery times</source>
        <translation>Histogramm der Erholzeiten</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pages/jointcharts.cpp" line="70"/>
        <source>Recovery time of %n joint(s)</source>
        <translation>
            <numerusform>Erholzeit von %n Lötstelle</numerusform>
            <numerusform>Erholzeit von %n Lötstellen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pages/jointcharts.cpp" line="73"/>
        <source>%1 (%n did not recover)</source>
        <translation>
            <numerusform>%1 (%n nicht erholt)</numerusform>
            <numerusform>%1 (%n nicht erholt)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointcharts.cpp" line="86"/>
        <source>No recovered joints listed</source>
        <translation>Keine erholten Lötstellen aufgeführt</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::RecoveryTrendView</name>
    <message>
        <location filename="../app/gui/pages/jointcharts.cpp" line="117"/>
        <source>Daily median recovery time per tool</source>
        <translation>Täglicher Median der Erholzeit je Werkzeug</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointcharts.cpp" line="130"/>
        <source>Median recovery time per day</source>
        <translation>Median der Erholzeit je Tag</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointcharts.cpp" line="131"/>
        <location filename="../app/gui/pages/jointcharts.cpp" line="171"/>
        <source>Median recovery time per day:</source>
        <translation>Median der Erholzeit je Tag:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointcharts.cpp" line="145"/>
        <source>No recovered joints listed</source>
        <translation>Keine erholten Lötstellen aufgeführt</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::RemoteDevicePage</name>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="80"/>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="92"/>
        <source>Port</source>
        <translation>Port</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="80"/>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="92"/>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="80"/>
        <source>Tip</source>
        <translation>Spitze</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="80"/>
        <source>Setpoint</source>
        <translation>Sollwert</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="80"/>
        <source>Power</source>
        <translation>Leistung</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="80"/>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="83"/>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="104"/>
        <source>Tip, setpoint and power, last 10 minutes</source>
        <translation>Spitze, Sollwert und Leistung, letzte 10 Minuten</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="85"/>
        <source>Temperature (°C)</source>
        <translation>Temperatur (°C)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="86"/>
        <source>Power (%)</source>
        <translation>Leistung (%)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="92"/>
        <source>Ended</source>
        <translation>Ende</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="92"/>
        <source>Verdict</source>
        <translation>Bewertung</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="92"/>
        <source>Dip (K)</source>
        <translation>Einbruch (K)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="92"/>
        <source>Recovery (s)</source>
        <translation>Erholung (s)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="94"/>
        <source>‹ Fleet overview</source>
        <translation>‹ Geräteübersicht</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="102"/>
        <source>Live values</source>
        <translation>Live-Werte</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="107"/>
        <source>Recent joints, newest first</source>
        <translation>Letzte Lötstellen, neueste zuerst</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="126"/>
        <source>No such device on the plant&apos;s broker</source>
        <translation>Dieses Gerät gibt es auf dem Broker des Werks nicht</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="130"/>
        <source>%1 · %2 on %3 (%4)</source>
        <translation>%1 · %2 an %3 (%4)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="134"/>
        <source>Read-only: published by %1 %2 through the plant&apos;s broker; current.</source>
        <translation>Schreibgeschützt: veröffentlicht von %1 %2 über den Broker des Werks; aktuell.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="136"/>
        <source>Read-only, not current: %1. The values are the last published.</source>
        <translation>Schreibgeschützt, nicht aktuell: %1. Die Werte sind die zuletzt veröffentlichten.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="149"/>
        <source>No errors or alarms in force.</source>
        <translation>Keine Fehler oder Alarme aktiv.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="150"/>
        <source>In force: %1</source>
        <translation>Aktiv: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="166"/>
        <source>never</source>
        <translation>nie</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="202"/>
        <source>No live values received yet</source>
        <translation>Noch keine Live-Werte empfangen</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::SettingsPage</name>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="37"/>
        <source>Port</source>
        <translation>Port</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="40"/>
        <source>Re&amp;fresh</source>
        <translation>A&amp;ktualisieren</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="41"/>
        <location filename="../app/gui/pages/settingspage.cpp" line="242"/>
        <source>&amp;Apply</source>
        <translation>&amp;Anwenden</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="42"/>
        <source>Re&amp;vert</source>
        <translation>&amp;Zurücknehmen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="43"/>
        <source>Save to station &amp;memory</source>
        <translation>Im Stations&amp;speicher sichern</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="44"/>
        <source>The selected temperature is volatile: W-NVS stores it so that it survives a restart</source>
        <translation>Die eingestellte Temperatur ist flüchtig: W-NVS speichert sie, damit sie einen Neustart übersteht</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="47"/>
        <source>Station actions</source>
        <translation>Stationsaktionen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="50"/>
        <source>Profiles</source>
        <translation>Profile</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="53"/>
        <source>Save device settings to a profile…</source>
        <translation>Geräteeinstellungen in einem Profil speichern…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="55"/>
        <source>Open a profile (compare, dry run, apply)…</source>
        <translation>Profil öffnen (vergleichen, Probelauf, anwenden)…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="64"/>
        <source>Port:</source>
        <translation>Port:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="154"/>
        <source>Connect and select a device to see its settings.</source>
        <translation>Verbinden Sie sich und wählen Sie ein Gerät, um seine Einstellungen zu sehen.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="157"/>
        <source>Port %1 (%2)</source>
        <translation>Port %1 (%2)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="169"/>
        <source>Station</source>
        <translation>Station</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="176"/>
        <source>Port %1</source>
        <translation>Port %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="177"/>
        <source>Alarms, port %1</source>
        <translation>Alarme, Port %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="179"/>
        <source>Tool %1, port %2</source>
        <translation>Werkzeug %1, Port %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="181"/>
        <source> (connected)</source>
        <translation> (angeschlossen)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="185"/>
        <source>Dispensing (ALE wire feed)</source>
        <translation>Dosierung (Drahtvorschub der ALE)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="193"/>
        <source>Feeding</source>
        <translation>Vorschub</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="242"/>
        <source>&amp;Apply (%1)</source>
        <translation>&amp;Anwenden (%1)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="309"/>
        <source>Save to station memory</source>
        <translation>Im Stationsspeicher sichern</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="321"/>
        <source>New address (1-99), or 0 for frames without addresses:</source>
        <translation>Neue Adresse (1-99) oder 0 für Telegramme ohne Adressen:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="328"/>
        <source>%1

%2

Do you want to continue?</source>
        <translation>%1

%2

Möchten Sie fortfahren?</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="343"/>
        <location filename="../app/gui/pages/settingspage.cpp" line="349"/>
        <location filename="../app/gui/pages/settingspage.cpp" line="355"/>
        <location filename="../app/gui/pages/settingspage.cpp" line="361"/>
        <source>Save profile</source>
        <translation>Profil speichern</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="344"/>
        <source>Some settings have not been read yet (%1). Refresh and try again.</source>
        <translation>Einige Einstellungen wurden noch nicht gelesen (%1). Aktualisieren Sie und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="350"/>
        <location filename="../app/gui/pages/settingspage.cpp" line="385"/>
        <source>TipScope profiles (*.json)</source>
        <translation>TipScope-Profile (*.json)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="384"/>
        <location filename="../app/gui/pages/settingspage.cpp" line="390"/>
        <source>Open profile</source>
        <translation>Profil öffnen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.h" line="34"/>
        <source>Settings</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="251"/>
        <source>⚠ Not connected: the greyed values are as last read (the time is beside each). Apply, Save to station memory, Station actions and Profiles wait for the line.</source>
        <translation>⚠ Nicht verbunden: die grauen Werte sind wie zuletzt gelesen (die Zeit steht daneben). Anwenden, Im Stationsspeicher sichern, Stationsaktionen und Profile warten auf die Leitung.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="255"/>
        <source>Monitor-only mode is on: Apply, Save to station memory and Station actions are off, nothing is written.</source>
        <translation>Nur-Beobachten ist an: Anwenden, Im Stationsspeicher sichern und Stationsaktionen sind aus, nichts wird geschrieben.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="356"/>
        <source>A comment for the profile (optional), e.g. what it is for or who set it:</source>
        <translation>Ein Kommentar zum Profil (optional), z. B. wofür es ist oder wer es eingestellt hat:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="367"/>
        <source>no device is selected</source>
        <translation>kein Gerät ausgewählt</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pages/settingspage.cpp" line="372"/>
        <source>✓ Profile saved: %n setting(s) of %1 in %2</source>
        <translation>
            <numerusform>✓ Profil gespeichert: %n Einstellung von %1 in %2</numerusform>
            <numerusform>✓ Profil gespeichert: %n Einstellungen von %1 in %2</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tipscope::gui::Sparkline</name>
    <message>
        <location filename="../app/gui/widgets/sparkline.cpp" line="63"/>
        <source>Last minute of tip temperature and power</source>
        <translation>Letzte Minute von Spitzentemperatur und Leistung</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/sparkline.cpp" line="87"/>
        <location filename="../app/gui/widgets/sparkline.cpp" line="91"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/sparkline.cpp" line="92"/>
        <source>%1 to %2</source>
        <translation>%1 bis %2</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/sparkline.cpp" line="104"/>
        <source>no samples yet</source>
        <translation>noch keine Messwerte</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/sparkline.cpp" line="162"/>
        <source>1 min</source>
        <translation>1 min</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::WorkContextDialog</name>
    <message>
        <location filename="../app/gui/dialogs/workcontextdialog.cpp" line="27"/>
        <source>Work context</source>
        <translation>Arbeitskontext</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/workcontextdialog.cpp" line="37"/>
        <source>Stamped on every joint and event from now on, by every TipScope program on this computer, until it is changed.</source>
        <translation>Wird ab jetzt jeder Lötstelle und jedem Ereignis mitgegeben, von jedem TipScope-Programm auf diesem Rechner, bis er geändert wird.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/workcontextdialog.cpp" line="43"/>
        <source>Work order:</source>
        <translation>Auftrag:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/workcontextdialog.cpp" line="44"/>
        <source>Board serial:</source>
        <translation>Seriennummer der Platine:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/workcontextdialog.cpp" line="45"/>
        <source>Operator:</source>
        <translation>Bediener:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/workcontextdialog.cpp" line="48"/>
        <source>Clear</source>
        <translation>Leeren</translation>
    </message>
</context>
<context>
    <name>tipscope::journal::Journal</name>
    <message>
        <location filename="../lib/journal/journal.cpp" line="111"/>
        <location filename="../lib/journal/journal.cpp" line="125"/>
        <location filename="../lib/journal/journal.cpp" line="189"/>
        <source>The journal is closed.</source>
        <translation>Das Journal ist geschlossen.</translation>
    </message>
    <message>
        <location filename="../lib/journal/journal.cpp" line="115"/>
        <source>The journal cannot keep up: %1 records wait to be written.</source>
        <translation>Das Journal kommt nicht nach: %1 Einträge warten darauf, geschrieben zu werden.</translation>
    </message>
    <message>
        <location filename="../lib/journal/journal.cpp" line="168"/>
        <source>Work order: %1, board: %2, operator: %3</source>
        <translation>Auftrag: %1, Platine: %2, Bediener: %3</translation>
    </message>
</context>
<context>
    <name>tipscope::link::Discovery</name>
    <message>
        <location filename="../lib/link/discovery.cpp" line="29"/>
        <source>the catalog names no command that identifies a device</source>
        <translation>der Katalog nennt keinen Befehl, mit dem sich ein Gerät ausweist</translation>
    </message>
    <message>
        <location filename="../lib/link/discovery.cpp" line="31"/>
        <source>the device reports the model &apos;%1&apos;, which TipScope does not know</source>
        <translation>das Gerät meldet das Modell &apos;%1&apos;, das TipScope nicht kennt</translation>
    </message>
    <message>
        <location filename="../lib/link/discovery.cpp" line="38"/>
        <source>the device without addresses did not identify itself (%1): %2</source>
        <translation>das Gerät ohne Adressen hat sich nicht identifiziert (%1): %2</translation>
    </message>
    <message>
        <location filename="../lib/link/discovery.cpp" line="40"/>
        <source>the device at address %1 did not identify itself (%2): %3</source>
        <translation>das Gerät an Adresse %1 hat sich nicht identifiziert (%2): %3</translation>
    </message>
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
            <numerusform>%n Antwort mit falscher Prüfsumme oder falschem Format</numerusform>
            <numerusform>%n Antworten mit falscher Prüfsumme oder falschem Format</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/link/discovery.cpp" line="106"/>
        <source>%n frame(s) from an address not asked</source>
        <translation>
            <numerusform>%n Rahmen von einer nicht gefragten Adresse</numerusform>
            <numerusform>%n Rahmen von nicht gefragten Adressen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/link/discovery.cpp" line="108"/>
        <source>%n byte(s) that were no frame</source>
        <translation>
            <numerusform>%n Byte, das kein Rahmen war</numerusform>
            <numerusform>%n Bytes, die kein Rahmen waren</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tipscope::link::Line</name>
    <message>
        <location filename="../lib/link/line.cpp" line="24"/>
        <source>the line was closed</source>
        <translation>die Leitung wurde geschlossen</translation>
    </message>
    <message>
        <location filename="../lib/link/line.cpp" line="62"/>
        <source>disconnected</source>
        <translation>getrennt</translation>
    </message>
    <message>
        <location filename="../lib/link/line.cpp" line="64"/>
        <source>connecting to %1</source>
        <translation>Verbindung wird aufgebaut: %1</translation>
    </message>
    <message>
        <location filename="../lib/link/line.cpp" line="66"/>
        <source>connected: %1</source>
        <translation>verbunden: %1</translation>
    </message>
    <message>
        <location filename="../lib/link/line.cpp" line="70"/>
        <source>cannot open %1, retrying every %2 s: %3</source>
        <translation>%1 lässt sich nicht öffnen, neuer Versuch alle %2 s: %3</translation>
    </message>
    <message>
        <location filename="../lib/link/line.cpp" line="74"/>
        <source>disconnected, retrying every %1 s: %2</source>
        <translation>getrennt, neuer Versuch alle %1 s: %2</translation>
    </message>
    <message>
        <location filename="../lib/link/line.cpp" line="78"/>
        <source>cannot connect: %1</source>
        <translation>Verbindung nicht möglich: %1</translation>
    </message>
    <message>
        <location filename="../lib/link/line.cpp" line="99"/>
        <source>disconnected by the user</source>
        <translation>vom Benutzer getrennt</translation>
    </message>
    <message>
        <location filename="../lib/link/line.cpp" line="142"/>
        <source>no answer to %1 requests in a row (cable unplugged, device off, or wrong addressing?)</source>
        <translation>keine Antwort auf %1 Anfragen in Folge (Kabel abgezogen, Gerät aus oder falsche Adressierung?)</translation>
    </message>
</context>
<context>
    <name>tipscope::link::Reply</name>
    <message>
        <location filename="../lib/link/reply.cpp" line="10"/>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <location filename="../lib/link/reply.cpp" line="12"/>
        <source>no answer</source>
        <translation>keine Antwort</translation>
    </message>
    <message>
        <location filename="../lib/link/reply.cpp" line="14"/>
        <source>corrupted answer</source>
        <translation>beschädigte Antwort</translation>
    </message>
    <message>
        <location filename="../lib/link/reply.cpp" line="16"/>
        <source>refused (NAK)</source>
        <translation>abgelehnt (NAK)</translation>
    </message>
    <message>
        <location filename="../lib/link/reply.cpp" line="18"/>
        <source>disconnected</source>
        <translation>getrennt</translation>
    </message>
    <message>
        <location filename="../lib/link/reply.cpp" line="20"/>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <location filename="../lib/link/reply.cpp" line="22"/>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
</context>
<context>
    <name>tipscope::link::RequestQueue</name>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="72"/>
        <source>the connection was closed</source>
        <translation>die Verbindung wurde geschlossen</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="118"/>
        <source>the connection is closing</source>
        <translation>die Verbindung wird geschlossen</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="122"/>
        <source>not sent: the line is not connected</source>
        <translation>nicht gesendet: die Leitung ist nicht verbunden</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="221"/>
        <source>the answer was corrupted (%1)</source>
        <translation>die Antwort war beschädigt (%1)</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="255"/>
        <source>unreadable data field &apos;%1&apos; in the answer</source>
        <translation>unlesbares Datenfeld &apos;%1&apos; in der Antwort</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="264"/>
        <source>the request could not be written</source>
        <translation>die Anfrage konnte nicht geschrieben werden</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="268"/>
        <source>no answer</source>
        <translation>keine Antwort</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="287"/>
        <source>NAK %1: %2</source>
        <translation>NAK %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="318"/>
        <source>%1: %2 (attempt %3)</source>
        <translation>%1: %2 (Versuch %3)</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/link/requestqueue.cpp" line="334"/>
        <source>%1 after %n attempt(s)</source>
        <translation>
            <numerusform>%1 nach %n Versuch</numerusform>
            <numerusform>%1 nach %n Versuchen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/link/requestqueue.cpp" line="337"/>
        <source>%n byte(s) of garbage came instead</source>
        <translation>
            <numerusform>stattdessen kam %n Byte Datenmüll</numerusform>
            <numerusform>stattdessen kamen %n Bytes Datenmüll</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="340"/>
        <source>; the device may have carried it out: check before repeating</source>
        <translation>; das Gerät hat den Befehl möglicherweise ausgeführt: vor einer Wiederholung prüfen</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="412"/>
        <source>line lost: %1</source>
        <translation>Leitung verloren: %1</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="414"/>
        <source>the line was lost: %1</source>
        <translation>die Leitung ist verloren gegangen: %1</translation>
    </message>
</context>
<context>
    <name>tipscope::link::SerialTransport</name>
    <message>
        <location filename="../lib/link/serialtransport.cpp" line="82"/>
        <source>the port %1 disappeared (unplugged?)</source>
        <translation>der Port %1 ist verschwunden (ausgesteckt?)</translation>
    </message>
    <message>
        <location filename="../lib/link/serialtransport.cpp" line="84"/>
        <source>the port stopped responding (%1)</source>
        <translation>der Port reagiert nicht mehr (%1)</translation>
    </message>
</context>
<context>
    <name>tipscope::link::SimTransport</name>
    <message>
        <location filename="../lib/link/simtransport.cpp" line="26"/>
        <source>the simulated line is unplugged</source>
        <translation>die simulierte Leitung ist abgezogen</translation>
    </message>
    <message>
        <location filename="../lib/link/simtransport.cpp" line="53"/>
        <source>demo (simulated %1)</source>
        <translation>Demo (simulierte %1)</translation>
    </message>
    <message>
        <location filename="../lib/link/simtransport.cpp" line="64"/>
        <source>the simulated cable was pulled</source>
        <translation>das simulierte Kabel wurde abgezogen</translation>
    </message>
</context>
<context>
    <name>tipscope::link::TcpTransport</name>
    <message>
        <location filename="../lib/link/tcptransport.cpp" line="29"/>
        <source>the connection to %1 dropped (%2)</source>
        <translation>die Verbindung zu %1 ist abgebrochen (%2)</translation>
    </message>
    <message>
        <location filename="../lib/link/tcptransport.cpp" line="36"/>
        <source>cannot connect to %1: %2</source>
        <translation>Verbindung zu %1 nicht möglich: %2</translation>
    </message>
    <message>
        <location filename="../lib/link/tcptransport.cpp" line="65"/>
        <source>cannot connect to %1: no connection within %2 s</source>
        <translation>Verbindung zu %1 nicht möglich: keine Verbindung innerhalb von %2 s</translation>
    </message>
</context>
<context>
    <name>tipscope::model::ConsoleSender</name>
    <message>
        <location filename="../lib/model/console/consolesender.cpp" line="15"/>
        <source>%1: answered %2 after %L3 ms</source>
        <translation>%1: Antwort %2 nach %L3 ms</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolesender.cpp" line="19"/>
        <source>%1: refused, %2</source>
        <translation>%1: abgelehnt, %2</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolesender.cpp" line="21"/>
        <source>%1: no answer (timeout)</source>
        <translation>%1: keine Antwort (Zeitüberschreitung)</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolesender.cpp" line="23"/>
        <source>%1: %2 (%3)</source>
        <translation>%1: %2 (%3)</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolesender.cpp" line="52"/>
        <source>Monitor-only mode is on: W frames are not sent. Reads still are.</source>
        <translation>Der Modus „Nur beobachten“ ist aktiv: W-Telegramme werden nicht gesendet, Lesebefehle schon.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolesender.cpp" line="58"/>
        <source>Monitor-only mode is on: bytes that are not one valid R frame may be a write, so they are not sent.</source>
        <translation>Der Modus „Nur beobachten“ ist aktiv: Bytes, die kein gültiges R-Telegramm sind, könnten ein Schreibbefehl sein und werden daher nicht gesendet.</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/console/consolesender.cpp" line="69"/>
        <source>%n raw byte(s)</source>
        <translation>
            <numerusform>%n Rohbyte</numerusform>
            <numerusform>%n Rohbytes</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolesender.cpp" line="75"/>
        <source>%1: not sent, not connected</source>
        <translation>%1: nicht gesendet, nicht verbunden</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolesender.cpp" line="79"/>
        <source>%1: not sent, monitor-only mode is on</source>
        <translation>%1: nicht gesendet, der Modus „Nur beobachten“ ist aktiv</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolesender.cpp" line="91"/>
        <source>%1: sent, waiting for the answer…</source>
        <translation>%1: gesendet, warte auf Antwort…</translation>
    </message>
</context>
<context>
    <name>tipscope::model::FleetTile</name>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="39"/>
        <location filename="../lib/model/workspace/fleettile.cpp" line="53"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="45"/>
        <source>Port %1: %2</source>
        <translation>Port %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="48"/>
        <source>Port %1 alarm: %2</source>
        <translation>Port %1 Alarm: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="54"/>
        <source>Feeding</source>
        <translation>Vorschub läuft</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="55"/>
        <source>Not feeding</source>
        <translation>Kein Vorschub</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="56"/>
        <source>%1 · fed %2</source>
        <translation>%1 · vorgeschoben %2</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="195"/>
        <source>Line down</source>
        <translation>Leitung getrennt</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="200"/>
        <source>Line down since %1</source>
        <translation>Leitung getrennt seit %1</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="201"/>
        <source>Line down since %1 %2</source>
        <translation>Leitung getrennt seit %1 %2</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="219"/>
        <source>Station: %1</source>
        <translation>Station: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="231"/>
        <source>Feeder: %1</source>
        <translation>Lotdrahtvorschub: %1</translation>
    </message>
</context>
<context>
    <name>tipscope::model::LineTile</name>
    <message>
        <location filename="../lib/model/workspace/linetile.cpp" line="44"/>
        <source>No device</source>
        <translation>Kein Gerät</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/linetile.cpp" line="54"/>
        <source>Recording</source>
        <translation>Aufzeichnung</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/linetile.cpp" line="56"/>
        <source>Cannot be played</source>
        <translation>Nicht abspielbar</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/linetile.cpp" line="66"/>
        <source>No device answered</source>
        <translation>Kein Gerät hat geantwortet</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/linetile.cpp" line="67"/>
        <source>Connecting</source>
        <translation>Verbindung wird aufgebaut</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/linetile.cpp" line="68"/>
        <source>Looking for devices</source>
        <translation>Suche nach Geräten</translation>
    </message>
</context>
<context>
    <name>tipscope::model::Workspace</name>
    <message>
        <location filename="../lib/model/workspace/workspace.cpp" line="28"/>
        <source>a line needs a name</source>
        <translation>eine Linie braucht einen Namen</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspace.cpp" line="31"/>
        <source>the workspace already has a line named &quot;%1&quot;</source>
        <translation>der Arbeitsbereich hat schon eine Linie namens „%1“</translation>
    </message>
</context>
<context>
    <name>tipscope::plant::RemoteHistory</name>
    <message>
        <location filename="../lib/plant/remotehistory.cpp" line="100"/>
        <source>Port %1</source>
        <translation>Port %1</translation>
    </message>
</context>
</TS>
