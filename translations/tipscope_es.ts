<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es_ES" sourcelanguage="en">
<context>
    <name>Action</name>
    <message>
        <location filename="../lib/model/device/action.cpp" line="28"/>
        <source>monitor-only mode is on: nothing is written</source>
        <translation>el modo solo supervisión está activado: no se escribe nada</translation>
    </message>
    <message>
        <location filename="../lib/model/device/action.cpp" line="30"/>
        <source>%1 needs an explicit confirmation: %2</source>
        <translation>%1 necesita una confirmación explícita: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/action.cpp" line="32"/>
        <source>%1 is already running</source>
        <translation>%1 ya está en curso</translation>
    </message>
    <message>
        <location filename="../lib/model/device/action.cpp" line="43"/>
        <source>%1 done</source>
        <translation>%1 completado</translation>
    </message>
</context>
<context>
    <name>AgentConfig</name>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="38"/>
        <source>%1 must be text</source>
        <translation>%1 debe ser un texto</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="47"/>
        <source>%1 must be a whole number from %2 to %3</source>
        <translation>%1 debe ser un número entero de %2 a %3</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="58"/>
        <source>%1 must be true or false</source>
        <translation>%1 debe ser true o false</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="64"/>
        <source>%1 must be an object</source>
        <translation>%1 debe ser un objeto</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="82"/>
        <source>not a TipScope agent configuration (&quot;format&quot; is not &quot;%1&quot;)</source>
        <translation>no es una configuración del agente de TipScope (&quot;format&quot; no es &quot;%1&quot;)</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="87"/>
        <source>&quot;version&quot; must be a whole number from 1</source>
        <translation>&quot;version&quot; debe ser un número entero desde 1</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="90"/>
        <source>written for a later TipScope (version %1); this one reads version %2 and older</source>
        <translation>escrita para un TipScope más reciente (versión %1); este lee la versión %2 y anteriores</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="118"/>
        <source>broker.protocol must be &quot;3.1.1&quot; or &quot;5&quot;</source>
        <translation>broker.protocol debe ser &quot;3.1.1&quot; o &quot;5&quot;</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="130"/>
        <source>broker.host must name the broker</source>
        <translation>broker.host debe indicar el broker</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="133"/>
        <source>broker.password_file and broker.password_env: give one of them</source>
        <translation>broker.password_file y broker.password_env: indique solo uno de los dos</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="148"/>
        <source>file %1</source>
        <translation>archivo %1</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="154"/>
        <source>environment variable %1</source>
        <translation>variable de entorno %1</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="188"/>
        <source>cfx.host must name the AMQP broker</source>
        <translation>cfx.host debe nombrar el broker AMQP</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="190"/>
        <source>cfx.address must be /exchange/NAME, /exchange/NAME/KEY or /queue/NAME, not &quot;%1&quot;</source>
        <translation>cfx.address debe ser /exchange/NOMBRE, /exchange/NOMBRE/CLAVE o /queue/NOMBRE, no «%1»</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="194"/>
        <source>cfx.request_address must be a queue, /queue/NAME, not &quot;%1&quot;</source>
        <translation>cfx.request_address debe ser una cola, /queue/NOMBRE, no «%1»</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="197"/>
        <source>cfx.vendor must be a name of at most %1 characters</source>
        <translation>cfx.vendor debe ser un nombre de %1 caracteres como máximo</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="200"/>
        <source>cfx.tls.cert_file and cfx.tls.key_file: give both or neither</source>
        <translation>cfx.tls.cert_file y cfx.tls.key_file: indique los dos o ninguno</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="202"/>
        <source>cfx.password_file and cfx.password_env: give one of them</source>
        <translation>cfx.password_file y cfx.password_env: indique solo uno de ellos</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="230"/>
        <source>broker is false: then a cfx section must say where the lines are published</source>
        <translation>broker es false: entonces una sección cfx debe indicar dónde se publican las líneas</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="233"/>
        <source>site must name the site</source>
        <translation>site debe indicar la planta</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="235"/>
        <source>site must be at most %1 characters long, not %2</source>
        <translation>site admite como máximo %1 caracteres, no %2</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="240"/>
        <source>site must not hold control characters</source>
        <translation>site no puede contener caracteres de control</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="242"/>
        <source>workspace must name the workspace file of the lines to run</source>
        <translation>workspace debe indicar el archivo de espacio de trabajo de las líneas que se ejecutan</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="271"/>
        <source>cannot read the configuration %1: there is no such file</source>
        <translation>no se puede leer la configuración %1: no existe ese archivo</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="274"/>
        <source>cannot read the configuration %1: %2</source>
        <translation>no se puede leer la configuración %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="278"/>
        <source>the configuration %1 is too big to be one</source>
        <translation>la configuración %1 es demasiado grande para serlo</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="280"/>
        <source>the configuration %1 is not a JSON object: %2</source>
        <translation>la configuración %1 no es un objeto JSON: %2</translation>
    </message>
    <message>
        <location filename="../lib/plant/agentconfig.cpp" line="282"/>
        <source>it is a list</source>
        <translation>es una lista</translation>
    </message>
</context>
<context>
    <name>AgentMain</name>
    <message>
        <location filename="../app/agent/main.cpp" line="33"/>
        <source>without a user name</source>
        <translation>sin nombre de usuario</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="35"/>
        <source>as %1, without a password</source>
        <translation>como %1, sin contraseña</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="36"/>
        <source>as %1, password from the %2</source>
        <translation>como %1, contraseña de %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/agent/main.cpp" line="42"/>
        <source>site %1, %n line(s) (%2), no MQTT broker: CFX only</source>
        <translation>
            <numerusform>planta %1, %n línea (%2), sin broker MQTT: solo CFX</numerusform>
            <numerusform>planta %1, %n líneas (%2), sin broker MQTT: solo CFX</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/agent/main.cpp" line="45"/>
        <source>site %1, %n line(s) (%2), broker %3:%4%5 %6</source>
        <translation>
            <numerusform>planta %1, %n línea (%2), broker %3:%4%5 %6</numerusform>
            <numerusform>planta %1, %n líneas (%2), broker %3:%4%5 %6</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="49"/>
        <source> with TLS</source>
        <translation> con TLS</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="64"/>
        <source>Runs the lines of a workspace without a screen, keeps their joints and events in the journal and publishes them to an MQTT broker.</source>
        <translation>Ejecuta las líneas de un espacio de trabajo sin pantalla, guarda sus soldaduras y eventos en el diario y los publica en un broker MQTT.</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="71"/>
        <source>The agent&apos;s configuration (default %1).</source>
        <translation>La configuración del agente (por omisión %1).</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="72"/>
        <source>file</source>
        <translation>archivo</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="75"/>
        <source>Reads the configuration and its workspace, says what is wrong, and exits.</source>
        <translation>Lee la configuración y su espacio de trabajo, indica lo que está mal y termina.</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="82"/>
        <source>unexpected argument %1</source>
        <translation>argumento inesperado %1</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="98"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="102"/>
        <source>%1 is good: %2</source>
        <translation>%1 es correcta: %2</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="114"/>
        <source>configuration refused, the running one stays: %1</source>
        <translation>configuración rechazada, se mantiene la actual: %1</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="118"/>
        <source>reloading: %1</source>
        <translation>recargando: %1</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="122"/>
        <source>tipscope-agent %1 starting: %2</source>
        <translation>tipscope-agent %1 arrancando: %2</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="127"/>
        <source>stopped: %1</source>
        <translation>detenido: %1</translation>
    </message>
    <message>
        <location filename="../app/agent/main.cpp" line="130"/>
        <source>stopped</source>
        <translation>detenido</translation>
    </message>
</context>
<context>
    <name>AmqpProblem</name>
    <message>
        <location filename="../lib/cfx/amqpproblem.cpp" line="20"/>
        <source>The broker refused the login: check the user and the password (file or environment variable).</source>
        <translation>El broker rechazó el inicio de sesión: compruebe el usuario y la contraseña (archivo o variable de entorno).</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpproblem.cpp" line="23"/>
        <source>The broker does not speak AMQP 1.0: enable its plugin (rabbitmq-plugins enable rabbitmq_amqp1_0).</source>
        <translation>El broker no habla AMQP 1.0: active su plugin (rabbitmq-plugins enable rabbitmq_amqp1_0).</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpproblem.cpp" line="26"/>
        <source>The broker does not know the address %1: RabbitMQ wants /exchange/NAME, /exchange/NAME/KEY or /queue/NAME.</source>
        <translation>El broker no conoce la dirección %1: RabbitMQ espera /exchange/NOMBRE, /exchange/NOMBRE/CLAVE o /queue/NOMBRE.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpproblem.cpp" line="30"/>
        <source>The exchange or queue of %1 does not exist on the broker: declare it there, or fix the address.</source>
        <translation>El exchange o la cola de %1 no existe en el broker: declárelo allí o corrija la dirección.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpproblem.cpp" line="34"/>
        <source>TLS failed: check the CA file, the client certificate and that the host name matches the broker&apos;s certificate.</source>
        <translation>TLS falló: compruebe el archivo de la CA, el certificado de cliente y que el nombre de host coincide con el certificado del broker.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpproblem.cpp" line="37"/>
        <source>Nothing accepts connections there: check the host and port, and that the broker runs.</source>
        <translation>Nada acepta conexiones ahí: compruebe el host y el puerto, y que el broker esté en marcha.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpproblem.cpp" line="41"/>
        <source>The broker&apos;s host name cannot be found: check it.</source>
        <translation>No se encuentra el nombre de host del broker: compruébelo.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpproblem.cpp" line="51"/>
        <source>The broker said: %1.</source>
        <translation>El broker respondió: %1.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpproblem.cpp" line="52"/>
        <source>%1 (The broker said: %2)</source>
        <translation>%1 (El broker respondió: %2)</translation>
    </message>
</context>
<context>
    <name>AppSettings</name>
    <message>
        <location filename="../lib/model/appsettings.cpp" line="116"/>
        <source>choose a serial port</source>
        <translation>elija un puerto serie</translation>
    </message>
    <message>
        <location filename="../lib/model/appsettings.cpp" line="124"/>
        <source>&apos;%1&apos; is not HOST:PORT (for example 192.168.1.20:4001)</source>
        <translation>&apos;%1&apos; no tiene la forma HOST:PUERTO (por ejemplo 192.168.1.20:4001)</translation>
    </message>
</context>
<context>
    <name>AtomicSave</name>
    <message>
        <location filename="../lib/model/io/atomicsave.cpp" line="27"/>
        <source>cannot write %1: %2</source>
        <translation>no se puede escribir %1: %2</translation>
    </message>
</context>
<context>
    <name>BoardReport</name>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="66"/>
        <source>PASS: every joint within its limits</source>
        <translation>APROBADA: cada soldadura dentro de sus límites</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="68"/>
        <source>FAIL: joints outside their limits</source>
        <translation>RECHAZADA: soldaduras fuera de sus límites</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="70"/>
        <source>NOT JUDGED: no joint failed, but some could not be judged</source>
        <translation>SIN JUICIO: ninguna soldadura falló, pero algunas no se pudieron juzgar</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="74"/>
        <source>NO JOINTS: the journal holds events of this board only</source>
        <translation>SIN SOLDADURAS: el diario solo tiene eventos de esta placa</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="106"/>
        <source>%1 ± %2</source>
        <translation>%1 ± %2</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="115"/>
        <source>%1 (bounded)</source>
        <translation>%1 (acotada)</translation>
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
        <translation>Registro de la placa: %1</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="176"/>
        <source>Made: %1 to %2</source>
        <translation>Fabricada: %1 a %2</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="179"/>
        <source>Work order: %1</source>
        <translation>Orden de trabajo: %1</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="182"/>
        <source>Operator: %1</source>
        <translation>Operario: %1</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="185"/>
        <source>Joints: %1 (%2)</source>
        <translation>Soldaduras: %1 (%2)</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="200"/>
        <location filename="../lib/report/boardpdf.cpp" line="268"/>
        <location filename="../lib/report/boardpdf.cpp" line="295"/>
        <source>Station</source>
        <translation>Estación</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="203"/>
        <source>Operator</source>
        <translation>Operario</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="209"/>
        <source>Limits (dip, recovery)</source>
        <translation>Límites (caída, recuperación)</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="211"/>
        <location filename="../lib/report/boardpdf.cpp" line="269"/>
        <source>Joints</source>
        <translation>Soldaduras</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="214"/>
        <source>Judged by: a dip of at most %1 K, back within %2 K of the setpoint in at most %3 s.</source>
        <translation>Juzgadas con: una caída de %1 K como máximo, de vuelta a %2 K de la consigna en %3 s como máximo.</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="231"/>
        <source>#%1 %2, port %3: dip %4, recovery %5, %6</source>
        <translation>#%1 %2, puerto %3: caída %4, recuperación %5, %6</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="238"/>
        <source>Worst joints</source>
        <translation>Peores soldaduras</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="239"/>
        <source>No curves: the journal keeps each joint&apos;s figures, not the tip&apos;s readings during it.</source>
        <translation>Sin curvas: el diario guarda las cifras de cada soldadura, no las lecturas de la punta durante ella.</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="246"/>
        <source>not yet known: %1 joints of this tip; its first %2 recovered ones are the baseline</source>
        <translation>aún no se sabe: %1 soldaduras de esta punta; sus primeras %2 recuperadas son la referencia</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="251"/>
        <source>%1 s when plugged in; no joint since</source>
        <translation>%1 s al conectarla; ninguna soldadura desde entonces</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="252"/>
        <source>recovers in %1 s now, %2 s when plugged in (%3)</source>
        <translation>se recupera en %1 s ahora, %2 s al conectarla (%3)</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="268"/>
        <source>Port</source>
        <translation>Puerto</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="269"/>
        <source>Tool</source>
        <translation>Herramienta</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="270"/>
        <source>Setpoints</source>
        <translation>Consignas</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="270"/>
        <source>Plugged in</source>
        <translation>Conectada</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="271"/>
        <source>Tip wear</source>
        <translation>Desgaste de la punta</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="272"/>
        <source>Tools and settings</source>
        <translation>Herramientas y ajustes</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="282"/>
        <source>, port %1</source>
        <translation>, puerto %1</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="295"/>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="296"/>
        <source>What happened</source>
        <translation>Qué pasó</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="298"/>
        <source>None in the journal.</source>
        <translation>Ninguno en el diario.</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="303"/>
        <source>Profile applied before</source>
        <translation>Perfil aplicado antes</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="304"/>
        <source>Faults and events while it was made</source>
        <translation>Fallos y eventos mientras se fabricaba</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="310"/>
        <source>The limits %1 of the %2 joints were judged by: they were journaled before the journal kept them; a failed joint&apos;s warning among the events names the limit it broke.</source>
        <translation>Los límites con que se juzgaron %1 de las %2 soldaduras: se registraron antes de que el diario guardara los límites; el aviso de una soldadura rechazada entre los eventos nombra el límite que superó.</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="316"/>
        <source>The station&apos;s settings as they stood: the journal keeps only changes made through TipScope (writes and profiles), not those made at the station.</source>
        <translation>Los ajustes de la estación tal como estaban: el diario solo guarda los cambios hechos con TipScope (escrituras y perfiles), no los hechos en la estación.</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="319"/>
        <source>Curves of the joints: the journal keeps each joint&apos;s figures, not the tip&apos;s readings.</source>
        <translation>Curvas de las soldaduras: el diario guarda las cifras de cada soldadura, no las lecturas de la punta.</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="322"/>
        <source>Not in the journal</source>
        <translation>No está en el diario</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="327"/>
        <source>Written by TipScope %1 on %2 from the journal %3</source>
        <translation>Escrito por TipScope %1 el %2 a partir del diario %3</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="329"/>
        <source>Times are local; figures as measured from the station&apos;s readings, each with how sure it is.</source>
        <translation>Horas locales; cifras medidas a partir de las lecturas de la estación, cada una con su incertidumbre.</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="331"/>
        <source>Checked by: ______________________   Date: ____________   Signature: ______________________</source>
        <translation>Revisado por: ______________________   Fecha: ____________   Firma: ______________________</translation>
    </message>
    <message>
        <location filename="../lib/report/boardpdf.cpp" line="348"/>
        <source>cannot write %1: a PDF needs fonts, which need a graphical application (QGuiApplication)</source>
        <translation>no se puede escribir %1: un PDF necesita fuentes, y estas una aplicación gráfica (QGuiApplication)</translation>
    </message>
</context>
<context>
    <name>Catalog</name>
    <message>
        <location filename="../lib/protocol/catalog.cpp" line="195"/>
        <source>Unknown NAK code %1</source>
        <translation>Código NAK desconocido %1</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalog.cpp" line="200"/>
        <source>Unknown station error %1</source>
        <translation>Error de estación desconocido %1</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalog.cpp" line="209"/>
        <source>Unknown port error %1</source>
        <translation>Error de puerto desconocido %1</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="13"/>
        <source>Port status</source>
        <translation>Estado del puerto</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="14"/>
        <source>Tool operating status: working, stand, sleep, hibernation, with cooling, suction and motor flags</source>
        <translation>Estado de funcionamiento de la herramienta: trabajando, soporte, reposo, hibernación, con indicadores de enfriamiento, succión y motor</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="15"/>
        <source>Working</source>
        <translation>Trabajando</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="16"/>
        <source>Stand</source>
        <translation>En soporte</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="17"/>
        <source>Cooling</source>
        <translation>Enfriando</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="18"/>
        <source>Tool operating status: no stand (working), stand, sleep, hibernation, with extractor and suction flags</source>
        <translation>Estado de funcionamiento de la herramienta: sin soporte (trabajando), soporte, reposo, hibernación, con indicadores de extractor y succión</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="19"/>
        <source>Selected temperature</source>
        <translation>Temperatura seleccionada</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="20"/>
        <source>Tip working temperature, in steps of 5 °C between the station&apos;s minimum and maximum; volatile until saved</source>
        <translation>Temperatura de trabajo de la punta, en pasos de 5 °C entre la mínima y la máxima de la estación; volátil hasta que se guarde</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="21"/>
        <source>Tip temperature</source>
        <translation>Temperatura de la punta</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="22"/>
        <source>Current tip temperature</source>
        <translation>Temperatura actual de la punta</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="23"/>
        <source>Power</source>
        <translation>Potencia</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="24"/>
        <source>Power delivered to the tip, in thousandths of the station&apos;s maximum</source>
        <translation>Potencia entregada a la punta, en milésimas de la máxima de la estación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="25"/>
        <source>Time to sleep/hibernation</source>
        <translation>Tiempo hasta reposo/hibernación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="26"/>
        <source>Seconds left before the tool enters sleep or hibernation</source>
        <translation>Segundos que faltan para que la herramienta entre en reposo o hibernación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="27"/>
        <source>Transistor temperature</source>
        <translation>Temperatura del transistor</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="28"/>
        <source>Temperature of the port&apos;s power transistor</source>
        <translation>Temperatura del transistor de potencia del puerto</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="29"/>
        <source>Connected tool</source>
        <translation>Herramienta conectada</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="30"/>
        <source>Tool connected to the port</source>
        <translation>Herramienta conectada al puerto</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="31"/>
        <source>Port error</source>
        <translation>Error de puerto</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="32"/>
        <source>Current error of the port</source>
        <translation>Error actual del puerto</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="33"/>
        <source>High temperature alarm</source>
        <translation>Alarma de temperatura alta</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="34"/>
        <source>Upper tip temperature alarm limit, in steps of 5 °C</source>
        <translation>Límite superior de alarma de temperatura de la punta, en pasos de 5 °C</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="35"/>
        <source>Low temperature alarm</source>
        <translation>Alarma de temperatura baja</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="36"/>
        <source>Lower tip temperature alarm limit, in steps of 5 °C</source>
        <translation>Límite inferior de alarma de temperatura de la punta, en pasos de 5 °C</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="37"/>
        <source>High alarm delay</source>
        <translation>Retardo de alarma alta</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="38"/>
        <source>How long the tip must stay above the high alarm limit before the alarm is set (ss.cc)</source>
        <translation>Tiempo que la punta debe permanecer por encima del límite de alarma alta antes de que se active la alarma (ss.cc)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="39"/>
        <source>disabled</source>
        <translation>desactivado</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="40"/>
        <source>Low alarm delay</source>
        <translation>Retardo de alarma baja</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="41"/>
        <source>How long the tip must stay below the low alarm limit before the alarm is set (ss.cc)</source>
        <translation>Tiempo que la punta debe permanecer por debajo del límite de alarma baja antes de que se active la alarma (ss.cc)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="42"/>
        <source>Temperature alarm</source>
        <translation>Alarma de temperatura</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="43"/>
        <source>Alarm flags: units digit high alarm, tens digit low alarm (DDR/HDR clear them when read)</source>
        <translation>Indicadores de alarma: dígito de las unidades, alarma alta; dígito de las decenas, alarma baja (en DDR/HDR se borran al leerlos)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="44"/>
        <source>Plugged hours</source>
        <translation>Horas conectado</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="45"/>
        <source>Hours with a tool plugged into the port</source>
        <translation>Horas con una herramienta conectada al puerto</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="52"/>
        <source>No-tool hours</source>
        <translation>Horas sin herramienta</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="53"/>
        <source>Hours the port was powered with no tool</source>
        <translation>Horas que el puerto estuvo con tensión sin herramienta</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="48"/>
        <source>Sleep hours</source>
        <translation>Horas en reposo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="49"/>
        <source>Hours in sleep</source>
        <translation>Horas en modo reposo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="50"/>
        <source>Hibernation hours</source>
        <translation>Horas en hibernación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="51"/>
        <source>Hours in hibernation</source>
        <translation>Horas en modo hibernación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="46"/>
        <source>Work hours</source>
        <translation>Horas de trabajo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="47"/>
        <source>Hours working</source>
        <translation>Horas trabajando</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="54"/>
        <source>Sleep cycles</source>
        <translation>Ciclos de reposo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="55"/>
        <source>Number of times the tool went into sleep</source>
        <translation>Número de veces que la herramienta entró en reposo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="56"/>
        <source>Desoldering cycles</source>
        <translation>Ciclos de desoldadura</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="57"/>
        <source>Number of times the desoldering tool was activated</source>
        <translation>Número de veces que se activó la herramienta de desoldadura</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="58"/>
        <source>Dispensed cycles</source>
        <translation>Ciclos de dispensado</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="59"/>
        <source>Number of dispensing cycles of the built-in wire feed</source>
        <translation>Número de ciclos de dispensado de la alimentación de hilo integrada</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="60"/>
        <source>Dispensed length</source>
        <translation>Longitud dispensada</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="61"/>
        <source>Total wire length dispensed (hexadecimal on the wire)</source>
        <translation>Longitud total de hilo dispensada (hexadecimal en la línea)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="62"/>
        <source>Temperature adjust</source>
        <translation>Ajuste de temperatura</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="63"/>
        <source>Offset added to the tool&apos;s temperature, ±50 °C in steps of 1</source>
        <translation>Desviación sumada a la temperatura de la herramienta, ±50 °C en pasos de 1</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="64"/>
        <source>Sleep temperature</source>
        <translation>Temperatura de reposo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="65"/>
        <source>Tip temperature in sleep, in steps of 5 °C</source>
        <translation>Temperatura de la punta en reposo, en pasos de 5 °C</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="66"/>
        <source>Sleep delay</source>
        <translation>Retardo de reposo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="67"/>
        <source>Minutes in the stand before sleep, 0 to 9, or disabled</source>
        <translation>Minutos en el soporte antes del reposo, de 0 a 9, o desactivado</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="68"/>
        <source>Hibernation delay</source>
        <translation>Retardo de hibernación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="69"/>
        <source>Minutes in sleep before hibernation, 0 to 60 in steps of 5, or disabled</source>
        <translation>Minutos en reposo antes de la hibernación, de 0 a 60 en pasos de 5, o desactivado</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="70"/>
        <source>Maximum temperature</source>
        <translation>Temperatura máxima</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="71"/>
        <source>Highest temperature selectable with the selected temperature</source>
        <translation>Temperatura más alta que se puede elegir como temperatura seleccionada</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="72"/>
        <source>Minimum temperature</source>
        <translation>Temperatura mínima</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="73"/>
        <source>Lowest temperature selectable with the selected temperature</source>
        <translation>Temperatura más baja que se puede elegir como temperatura seleccionada</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="74"/>
        <source>Power limit</source>
        <translation>Límite de potencia</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="75"/>
        <source>Maximum power delivered to a tool, in thousandths of the station&apos;s maximum</source>
        <translation>Potencia máxima entregada a una herramienta, en milésimas de la máxima de la estación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="76"/>
        <source>Transformer temperature</source>
        <translation>Temperatura del transformador</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="77"/>
        <source>Temperature of the power supply transformer (R-TT; see protocol notes)</source>
        <translation>Temperatura del transformador de alimentación (R-TT; véanse las notas del protocolo)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="78"/>
        <source>Station error</source>
        <translation>Error de estación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="79"/>
        <source>Current error of the station</source>
        <translation>Error actual de la estación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="80"/>
        <source>Fuse status</source>
        <translation>Estado del fusible</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="81"/>
        <source>Whether the station&apos;s fuse is in place</source>
        <translation>Indica si el fusible de la estación está colocado</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="82"/>
        <source>No fuse (blown or missing)</source>
        <translation>Sin fusible (fundido o ausente)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="83"/>
        <source>Fuse present</source>
        <translation>Fusible presente</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="84"/>
        <source>Model name</source>
        <translation>Nombre del modelo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="85"/>
        <source>The device&apos;s model name</source>
        <translation>Nombre del modelo del equipo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="86"/>
        <source>Software version</source>
        <translation>Versión de software</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="87"/>
        <source>The device&apos;s software version</source>
        <translation>Versión de software del equipo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="88"/>
        <source>Save to station memory</source>
        <translation>Guardar en la memoria de la estación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="89"/>
        <source>Stores the volatile settings (selected temperature; feeder mode, speed, length) in non-volatile memory</source>
        <translation>Guarda los ajustes volátiles (temperatura seleccionada; modo, velocidad y longitud del alimentador) en la memoria no volátil</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="90"/>
        <source>Factory reset</source>
        <translation>Restablecer valores de fábrica</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="91"/>
        <source>Resets every parameter of the device to its factory value</source>
        <translation>Restablece todos los parámetros del equipo a su valor de fábrica</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="92"/>
        <source>Every setting of the device returns to its factory value; the feeder restarts and goes back to address 10 in addressed mode.</source>
        <translation>Todos los ajustes del equipo vuelven a su valor de fábrica; el alimentador se reinicia y vuelve a la dirección 10 en modo con direcciones.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="93"/>
        <source>Restart station</source>
        <translation>Reiniciar estación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="94"/>
        <source>Restarts the control unit</source>
        <translation>Reinicia la unidad de control</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="95"/>
        <source>The control unit restarts: tools cool down and the station does not answer until it is back.</source>
        <translation>La unidad de control se reinicia: las herramientas se enfrían y la estación no responde hasta que vuelve a estar operativa.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="96"/>
        <source>Device address</source>
        <translation>Dirección del equipo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="97"/>
        <source>Sets the device&apos;s own address (1-99); 0 switches it to frames without addresses</source>
        <translation>Fija la dirección propia del equipo (1-99); 0 lo cambia a tramas sin direcciones</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="98"/>
        <source>The device answers only at the new address (or only without addresses for 0); TipScope must reconnect with the new setting.</source>
        <translation>El equipo solo responde en la nueva dirección (o solo sin direcciones si es 0); TipScope debe volver a conectarse con el nuevo ajuste.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="99"/>
        <source>Ignore fuse error</source>
        <translation>Ignorar error de fusible</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="100"/>
        <source>Lets the station keep working despite a fuse error</source>
        <translation>Permite que la estación siga funcionando pese a un error de fusible</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="101"/>
        <source>The station keeps heating although its fuse is reported missing or blown.</source>
        <translation>La estación sigue calentando aunque se indique que su fusible falta o está fundido.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="102"/>
        <source>Dispensing mode</source>
        <translation>Modo de dispensado</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="103"/>
        <source>How the built-in feed dispenses wire</source>
        <translation>Cómo dispensa el hilo la alimentación integrada</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="104"/>
        <source>Continuous</source>
        <translation>Continuo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="105"/>
        <source>Discontinuous</source>
        <translation>Discontinuo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="106"/>
        <source>Program</source>
        <translation>Programa</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="107"/>
        <source>Tin reload</source>
        <translation>Recarga de estaño</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="108"/>
        <source>Dispensing length</source>
        <translation>Longitud de dispensado</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="109"/>
        <source>Wire length dispensed per cycle, in tenths of a millimetre</source>
        <translation>Longitud de hilo dispensada por ciclo, en décimas de milímetro</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="110"/>
        <source>Dispensing speed</source>
        <translation>Velocidad de dispensado</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="111"/>
        <source>Wire speed, in tenths of a millimetre per second</source>
        <translation>Velocidad del hilo, en décimas de milímetro por segundo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="112"/>
        <source>Wire diameter</source>
        <translation>Diámetro del hilo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="113"/>
        <source>Solder wire diameter, in hundredths of a millimetre</source>
        <translation>Diámetro del hilo de soldadura, en centésimas de milímetro</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="114"/>
        <source>Backward length</source>
        <translation>Longitud de retroceso</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="115"/>
        <source>Wire pulled back after each cycle, in tenths of a millimetre</source>
        <translation>Hilo que se retrae tras cada ciclo, en décimas de milímetro</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="116"/>
        <source>Wire clogging detection</source>
        <translation>Detección de atasco del hilo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="117"/>
        <source>Detects a clogged wire feed</source>
        <translation>Detecta un atasco en la alimentación de hilo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="118"/>
        <source>Off</source>
        <translation>Desactivada</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="119"/>
        <source>On</source>
        <translation>Activada</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="120"/>
        <source>Dispensing status</source>
        <translation>Estado del dispensado</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="121"/>
        <source>Whether the dispensing motor is running</source>
        <translation>Indica si el motor de dispensado está en marcha</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="122"/>
        <source>Stopped</source>
        <translation>Detenido</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="123"/>
        <source>Running</source>
        <translation>En marcha</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="124"/>
        <source>Start dispensing</source>
        <translation>Iniciar dispensado</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="125"/>
        <source>Starts the dispensing motor</source>
        <translation>Pone en marcha el motor de dispensado</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="126"/>
        <source>Stop dispensing</source>
        <translation>Detener dispensado</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="127"/>
        <source>Stops the dispensing motor</source>
        <translation>Detiene el motor de dispensado</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="128"/>
        <source>Feeding mode</source>
        <translation>Modo de alimentación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="129"/>
        <source>Continuous feeds until stopped; discontinuous feeds the set length</source>
        <translation>Continuo alimenta hasta que se detiene; discontinuo alimenta la longitud ajustada</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="130"/>
        <source>Start feeding</source>
        <translation>Iniciar alimentación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="131"/>
        <source>Starts feeding wire forward or backward</source>
        <translation>Inicia la alimentación de hilo hacia delante o hacia atrás</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="132"/>
        <source>Forward</source>
        <translation>Adelante</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="133"/>
        <source>Backward</source>
        <translation>Atrás</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="134"/>
        <source>Stop feeding</source>
        <translation>Detener alimentación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="135"/>
        <source>Stops feeding (continuous mode)</source>
        <translation>Detiene la alimentación (modo continuo)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="138"/>
        <source>Feeding length</source>
        <translation>Longitud de alimentación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="139"/>
        <source>Length fed per start in discontinuous mode, in tenths of a millimetre</source>
        <translation>Longitud alimentada en cada inicio en modo discontinuo, en décimas de milímetro</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="136"/>
        <source>Feeding speed</source>
        <translation>Velocidad de alimentación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="137"/>
        <source>Feeding speed, in tenths of a millimetre per second</source>
        <translation>Velocidad de alimentación, en décimas de milímetro por segundo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="140"/>
        <source>Wire thickness</source>
        <translation>Grosor del hilo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="141"/>
        <source>Diameter class of the solder wire</source>
        <translation>Clase de diámetro del hilo de soldadura</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="142"/>
        <source>≤ 0.8 mm</source>
        <translation>≤ 0,8 mm</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="143"/>
        <source>&gt; 0.8 mm and ≤ 1.2 mm</source>
        <translation>&gt; 0,8 mm y ≤ 1,2 mm</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="144"/>
        <source>&gt; 1.2 mm</source>
        <translation>&gt; 1,2 mm</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="145"/>
        <source>Switch input</source>
        <translation>Entrada de interruptor</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="146"/>
        <source>Whether the switch input can start feeding</source>
        <translation>Indica si la entrada de interruptor puede iniciar la alimentación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="147"/>
        <source>Disabled</source>
        <translation>Desactivada</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="148"/>
        <source>Enabled</source>
        <translation>Activada</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="149"/>
        <source>Feeder error code</source>
        <translation>Código de error del alimentador</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="150"/>
        <source>The feeder&apos;s last error code</source>
        <translation>Último código de error del alimentador</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="151"/>
        <source>Reset feeder error</source>
        <translation>Borrar error del alimentador</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="152"/>
        <source>Clears the feeder&apos;s last error code</source>
        <translation>Borra el último código de error del alimentador</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="153"/>
        <source>Feeding status</source>
        <translation>Estado de alimentación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="154"/>
        <source>Whether the feeder is feeding</source>
        <translation>Indica si el alimentador está alimentando</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="155"/>
        <source>Idle</source>
        <translation>En espera</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="156"/>
        <source>Feeding</source>
        <translation>Alimentando</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="157"/>
        <source>Fed length</source>
        <translation>Longitud alimentada</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="158"/>
        <source>Length fed since the last start, in tenths of a millimetre</source>
        <translation>Longitud alimentada desde el último inicio, en décimas de milímetro</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="159"/>
        <source>Loading</source>
        <translation>Carga</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="160"/>
        <source>Feeds wire ignoring feeding errors, for loading a new spool</source>
        <translation>Alimenta hilo ignorando los errores de alimentación, para cargar una bobina nueva</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="161"/>
        <source>Start loading</source>
        <translation>Iniciar carga</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="162"/>
        <source>End loading</source>
        <translation>Terminar carga</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="163"/>
        <source>Plugged hours (total)</source>
        <translation>Horas conectado (total)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="164"/>
        <source>Hours powered, total counter</source>
        <translation>Horas con tensión, contador total</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="165"/>
        <source>Plugged hours (partial)</source>
        <translation>Horas conectado (parcial)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="166"/>
        <source>Hours powered since the partial counter was reset</source>
        <translation>Horas con tensión desde la última puesta a cero del contador parcial</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="167"/>
        <source>Reset plugged hours (partial)</source>
        <translation>Poner a cero horas conectado (parcial)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="168"/>
        <source>Resets the partial plugged-hours counter</source>
        <translation>Pone a cero el contador parcial de horas conectado</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="169"/>
        <source>The partial plugged-hours counter goes back to zero; the old value cannot be recovered.</source>
        <translation>El contador parcial de horas conectado vuelve a cero; el valor anterior no se puede recuperar.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="171"/>
        <source>Feeding hours (total)</source>
        <translation>Horas de alimentación (total)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="172"/>
        <source>Hours feeding, total counter</source>
        <translation>Horas alimentando, contador total</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="174"/>
        <source>Feeding hours (partial)</source>
        <translation>Horas de alimentación (parcial)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="175"/>
        <source>Hours feeding since the partial counter was reset</source>
        <translation>Horas alimentando desde la última puesta a cero del contador parcial</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="176"/>
        <source>Reset feeding hours (partial)</source>
        <translation>Poner a cero horas de alimentación (parcial)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="177"/>
        <source>Resets the partial feeding-hours counter</source>
        <translation>Pone a cero el contador parcial de horas de alimentación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="178"/>
        <source>The partial feeding-hours counter goes back to zero; the old value cannot be recovered.</source>
        <translation>El contador parcial de horas de alimentación vuelve a cero; el valor anterior no se puede recuperar.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="180"/>
        <source>Fed length (total)</source>
        <translation>Longitud alimentada (total)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="181"/>
        <source>Metres of wire fed, total counter</source>
        <translation>Metros de hilo alimentados, contador total</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="182"/>
        <source>Fed length (partial)</source>
        <translation>Longitud alimentada (parcial)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="183"/>
        <source>Metres of wire fed since the partial counter was reset</source>
        <translation>Metros de hilo alimentados desde la última puesta a cero del contador parcial</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="184"/>
        <source>Reset fed length (partial)</source>
        <translation>Poner a cero longitud alimentada (parcial)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="185"/>
        <source>Resets the partial fed-length counter</source>
        <translation>Pone a cero el contador parcial de longitud alimentada</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="186"/>
        <source>The partial fed-length counter goes back to zero; the old value cannot be recovered.</source>
        <translation>El contador parcial de longitud alimentada vuelve a cero; el valor anterior no se puede recuperar.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="188"/>
        <source>No tool</source>
        <translation>Sin herramienta</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="189"/>
        <source>BCC error: the frame failed the sum check</source>
        <translation>Error de BCC: la trama no superó la comprobación de suma</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="190"/>
        <source>Format error: the frame has the wrong size or layout</source>
        <translation>Error de formato: la trama tiene un tamaño o una estructura incorrectos</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="191"/>
        <source>Out of range: the value is outside the allowed limits or off-step</source>
        <translation>Fuera de rango: el valor está fuera de los límites permitidos o no respeta el paso</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="192"/>
        <source>Control error: the command is not accepted by this device</source>
        <translation>Error de control: este equipo no acepta el comando</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="193"/>
        <source>Robot mode is off: switch &quot;Robot mode&quot; on in the station menu</source>
        <translation>El modo robot está desactivado: active &quot;Robot mode&quot; en el menú de la estación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="194"/>
        <source>Device model error: the device model is unknown</source>
        <translation>Error de modelo de equipo: el modelo del equipo es desconocido</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="195"/>
        <source>Undefined error</source>
        <translation>Error no definido</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="196"/>
        <source>Stopped by transformer overload</source>
        <translation>Detenido por sobrecarga del transformador</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="197"/>
        <source>Temperature sensor error</source>
        <translation>Error del sensor de temperatura</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="198"/>
        <source>Memory error</source>
        <translation>Error de memoria</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="199"/>
        <source>Mains frequency error</source>
        <translation>Error de frecuencia de red</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="200"/>
        <source>Device model error</source>
        <translation>Error de modelo de equipo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="201"/>
        <source>MCU tools not connected</source>
        <translation>Herramientas MCU no conectadas</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="202"/>
        <source>Warning: transformer overload</source>
        <translation>Advertencia: sobrecarga del transformador</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="203"/>
        <source>Short circuit</source>
        <translation>Cortocircuito</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="204"/>
        <source>Short circuit, not recoverable: restart the station</source>
        <translation>Cortocircuito no recuperable: reinicie la estación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="205"/>
        <source>Open circuit</source>
        <translation>Circuito abierto</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="206"/>
        <source>Tool not accepted</source>
        <translation>Herramienta no aceptada</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="207"/>
        <source>Detecting tool</source>
        <translation>Detectando herramienta</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="208"/>
        <source>Stopped at maximum power</source>
        <translation>Detenido a potencia máxima</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="209"/>
        <source>Stopped by transistor (MOS) overload</source>
        <translation>Detenido por sobrecarga del transistor (MOS)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="210"/>
        <source>Warning: transistor (MOS) overload</source>
        <translation>Advertencia: sobrecarga del transistor (MOS)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="211"/>
        <source>No error</source>
        <translation>Sin error</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="230"/>
        <source>Sleep</source>
        <translation>Reposo</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="231"/>
        <source>Hibernation</source>
        <translation>Hibernación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="232"/>
        <source>Suction on</source>
        <translation>Succión activada</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="233"/>
        <source>Motor forward (dispensing)</source>
        <translation>Motor adelante (dispensado)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="234"/>
        <source>Motor backward</source>
        <translation>Motor atrás</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="236"/>
        <source>unknown (%1)</source>
        <translation>desconocido (%1)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="243"/>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="170"/>
        <source>Reset partial plugged hours</source>
        <translation>Poner a cero las horas conectado parciales</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="173"/>
        <source>Feeding hours</source>
        <translation>Horas de alimentación</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="179"/>
        <source>Reset partial feeding hours</source>
        <translation>Poner a cero las horas de alimentación parciales</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="187"/>
        <source>Reset partial fed length</source>
        <translation>Poner a cero la longitud alimentada parcial</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalog.cpp" line="214"/>
        <source>Feeder error %1 (not listed in the SFR guide)</source>
        <translation>Error del alimentador %1 (no figura en la guía del SFR)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="213"/>
        <source>The station switched off its power because the transformer was overloaded. Let it cool for a few minutes with the ventilation slots free, then switch it off and on. Check that the tools working at once do not need more than the station can give (large heat sinks, high temperatures, several ports at full power). If it stops again with one tool at normal work, the station needs JBC service.</source>
        <translation>La estación cortó su potencia porque el transformador se sobrecargó. Déjela enfriar unos minutos con las rejillas de ventilación libres y luego apáguela y enciéndala. Compruebe que las herramientas que trabajan a la vez no necesitan más de lo que la estación puede dar (disipadores grandes, temperaturas altas, varios puertos a plena potencia). Si vuelve a pararse con una herramienta en trabajo normal, la estación necesita el servicio técnico de JBC.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="214"/>
        <source>The station cannot read its internal temperature sensor. Switch it off and on; if the error stays, the control unit needs JBC service.</source>
        <translation>La estación no puede leer su sensor de temperatura interno. Apáguela y enciéndala; si el error sigue, la unidad de control necesita el servicio técnico de JBC.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="215"/>
        <source>The station&apos;s memory failed its check. Switch it off and on. If the error stays, restore the factory settings and set the station up again (save a profile first if the settings can still be read); if it still stays, the control unit needs JBC service.</source>
        <translation>La memoria de la estación no superó su comprobación. Apáguela y enciéndala. Si el error sigue, restaure los ajustes de fábrica y vuelva a configurar la estación (guarde antes un perfil si aún se pueden leer los ajustes); si aun así sigue, la unidad de control necesita el servicio técnico de JBC.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="216"/>
        <source>The station does not accept the mains frequency. Check that the voltage and frequency on the station&apos;s label match the supply, and that no generator, UPS or long extension cord makes it unstable; then switch the station off and on.</source>
        <translation>La estación no acepta la frecuencia de la red. Compruebe que la tensión y la frecuencia de la etiqueta de la estación coinciden con la alimentación y que ningún generador, SAI o alargador largo la vuelve inestable; luego apague y encienda la estación.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="217"/>
        <source>The station does not recognise its own model: its configuration is damaged. Switch it off and on; if the error stays, the control unit needs JBC service.</source>
        <translation>La estación no reconoce su propio modelo: su configuración está dañada. Apáguela y enciéndala; si el error sigue, la unidad de control necesita el servicio técnico de JBC.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="218"/>
        <source>The station&apos;s tool control board does not answer. Switch the station off, wait ten seconds and switch it on; if the error stays, the control unit needs JBC service.</source>
        <translation>La placa de control de herramientas de la estación no responde. Apague la estación, espere diez segundos y enciéndala; si el error sigue, la unidad de control necesita el servicio técnico de JBC.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="219"/>
        <source>The transformer is close to overload; the station stops if this goes on. Reduce the load: fewer tools heating at once, lower temperatures, no tip resting on a large heat sink; keep the ventilation slots free.</source>
        <translation>El transformador está cerca de la sobrecarga; la estación se parará si esto continúa. Reduzca la carga: menos herramientas calentando a la vez, temperaturas más bajas, ninguna punta apoyada en un disipador grande; mantenga libres las rejillas de ventilación.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="212"/>
        <source>The guide&apos;s table does not list this code. Note the code and the time, switch the station off and on, and give the code to JBC service if it comes back.</source>
        <translation>La tabla de la guía no incluye este código. Anote el código y la hora, apague y encienda la estación y, si vuelve a aparecer, comunique el código al servicio técnico de JBC.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="220"/>
        <source>The heater circuit of the tool is short-circuited. Check that the cartridge is seated fully and is not damaged, then try another cartridge. If the error stays, check the tool&apos;s cable and connector for damage and try the tool on another port.</source>
        <translation>El circuito calefactor de la herramienta está en cortocircuito. Compruebe que el cartucho está bien insertado y no está dañado, y pruebe otro cartucho. Si el error sigue, revise si el cable y el conector de la herramienta están dañados y pruebe la herramienta en otro puerto.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="221"/>
        <source>The port was switched off after a short circuit and stays off until the station restarts. Switch the station off, change the cartridge, check the tool&apos;s cable and connector for damage, then switch it on again.</source>
        <translation>El puerto se apagó tras un cortocircuito y sigue apagado hasta que la estación se reinicie. Apague la estación, cambie el cartucho, revise si el cable y el conector de la herramienta están dañados y vuelva a encenderla.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="222"/>
        <source>The station finds no heater in the tool. Check that the cartridge is seated fully in the handle, then try another cartridge. If the error stays, check the tool&apos;s cable and connector and try the tool on another port.</source>
        <translation>La estación no encuentra calefactor en la herramienta. Compruebe que el cartucho está bien insertado en el mango y pruebe otro cartucho. Si el error sigue, revise el cable y el conector de la herramienta y pruébela en otro puerto.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="223"/>
        <source>No tool is connected to this port. If one is plugged in, push its connector fully home, then try it on another port.</source>
        <translation>No hay ninguna herramienta conectada a este puerto. Si hay una enchufada, introduzca su conector hasta el fondo y luego pruébela en otro puerto.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="224"/>
        <source>The station cannot drive the tool plugged into this port. Check the tool&apos;s model against the station&apos;s list of compatible tools and use a tool that is on it, or another station.</source>
        <translation>La estación no puede controlar la herramienta enchufada en este puerto. Compare el modelo de la herramienta con la lista de herramientas compatibles de la estación y use una que figure en ella, u otra estación.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="225"/>
        <source>The station is identifying the tool; this takes a few seconds. If it does not end, unplug the tool, check its connector and plug it in again.</source>
        <translation>La estación está identificando la herramienta; tarda unos segundos. Si no termina, desenchufe la herramienta, revise su conector y vuelva a enchufarla.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="226"/>
        <source>The port stopped after giving its maximum power for too long. Check that the tip suits the work (a larger tip for large joints) and is not resting on a large heat sink; lower the load and restart the tool.</source>
        <translation>El puerto se paró tras dar su potencia máxima demasiado tiempo. Compruebe que la punta es adecuada para el trabajo (una punta mayor para soldaduras grandes) y que no está apoyada en un disipador grande; reduzca la carga y reinicie la herramienta.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="227"/>
        <source>The port&apos;s power transistor overheated and the port stopped. Let the station cool with the ventilation slots free, then reduce the load on this port (a larger tip, a lower temperature, shorter contact with large heat sinks). If it happens at normal work, the station needs JBC service.</source>
        <translation>El transistor de potencia del puerto se sobrecalentó y el puerto se paró. Deje enfriar la estación con las rejillas de ventilación libres y luego reduzca la carga de este puerto (una punta mayor, una temperatura más baja, menos contacto con disipadores grandes). Si ocurre en trabajo normal, la estación necesita el servicio técnico de JBC.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="228"/>
        <source>The port&apos;s power transistor is close to overload; the port stops if this goes on. Reduce the load on this port: a lower temperature, shorter contact with large heat sinks; keep the ventilation slots free.</source>
        <translation>El transistor de potencia del puerto está cerca de la sobrecarga; el puerto se parará si esto continúa. Reduzca la carga de este puerto: una temperatura más baja, menos contacto con disipadores grandes; mantenga libres las rejillas de ventilación.</translation>
    </message>
    <message>
        <location filename="../lib/protocol/catalogstrings.cpp" line="229"/>
        <source>The SFR guide does not say what the feeder&apos;s error codes mean. Check that the solder wire is loaded and runs freely from the reel to the tool (no knot, no jam, the reel not empty) and that the wire thickness setting matches the wire; then reset the error. If it comes back at once, note the code and see the SFR manual.</source>
        <translation>La guía del SFR no dice qué significan los códigos de error del alimentador. Compruebe que el hilo de soldadura está cargado y corre libremente del carrete a la herramienta (sin nudos, sin atascos, el carrete no vacío) y que el grosor de hilo ajustado coincide con el hilo; luego restablezca el error. Si vuelve enseguida, anote el código y consulte el manual del SFR.</translation>
    </message>
</context>
<context>
    <name>Cfx</name>
    <message>
        <location filename="../lib/cfx/amqpsender.cpp" line="212"/>
        <source>rejected by the broker</source>
        <translation>rechazado por el broker</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpsender.cpp" line="215"/>
        <source>released by the broker</source>
        <translation>liberado por el broker</translation>
    </message>
    <message>
        <location filename="../lib/cfx/amqpsender.cpp" line="261"/>
        <source>the connection closed</source>
        <translation>la conexión se cerró</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxenvelope.cpp" line="26"/>
        <source>The CFX envelope&apos;s %1 is not a text.</source>
        <translation>%1 del sobre CFX no es un texto.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxenvelope.cpp" line="82"/>
        <source>A CFX message of %1 bytes is larger than the %2 accepted.</source>
        <translation>Un mensaje CFX de %1 bytes supera los %2 admitidos.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxenvelope.cpp" line="88"/>
        <source>A CFX message is not a JSON object: %1.</source>
        <translation>Un mensaje CFX no es un objeto JSON: %1.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxenvelope.cpp" line="89"/>
        <source>not an object</source>
        <translation>no es un objeto</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxenvelope.cpp" line="104"/>
        <source>A CFX message has no MessageName.</source>
        <translation>A un mensaje CFX le falta MessageName.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxenvelope.cpp" line="115"/>
        <source>The CFX envelope&apos;s MessageBody is not an object.</source>
        <translation>MessageBody del sobre CFX no es un objeto.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxenvelope.cpp" line="170"/>
        <source>Cannot unpack a gzip CFX message.</source>
        <translation>No se puede descomprimir un mensaje CFX con gzip.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxenvelope.cpp" line="187"/>
        <source>A gzip CFX message is damaged or larger than %1 bytes.</source>
        <translation>Un mensaje CFX con gzip está dañado o supera los %1 bytes.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxrequests.cpp" line="119"/>
        <source>A CFX request (%1) without a reply-to address: it cannot be answered.</source>
        <translation>Una petición CFX (%1) sin dirección de respuesta (reply-to): no se puede responder.</translation>
    </message>
    <message>
        <location filename="../lib/cfx/cfxrequests.cpp" line="124"/>
        <source>A CFX request (%1) for &quot;%2&quot;, which is no endpoint here.</source>
        <translation>Una petición CFX (%1) para «%2», que aquí no es ningún punto final.</translation>
    </message>
</context>
<context>
    <name>ChartCsv</name>
    <message>
        <location filename="../lib/model/recording/chartcsv.cpp" line="209"/>
        <source>the file could not be written whole: the disk is full or the file reached its size limit</source>
        <translation>no se pudo escribir el archivo completo: el disco está lleno o el archivo alcanzó su límite de tamaño</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsv.cpp" line="213"/>
        <source>the file could not be written</source>
        <translation>no se pudo escribir el archivo</translation>
    </message>
</context>
<context>
    <name>ChartCsvReader</name>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="99"/>
        <source>line %1: %2</source>
        <translation>línea %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="119"/>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="143"/>
        <source>the line is longer than %1 bytes (is this a chart CSV?)</source>
        <translation>la línea supera los %1 bytes (¿es un CSV de gráficos?)</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="107"/>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="148"/>
        <source>the file holds binary data, not CSV text</source>
        <translation>el archivo contiene datos binarios, no texto CSV</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="154"/>
        <source>the text is not UTF-8 (save the file as &quot;CSV UTF-8&quot;)</source>
        <translation>el texto no está en UTF-8 (guarde el archivo como &quot;CSV UTF-8&quot;)</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="158"/>
        <source>more than %1 comment lines (&quot;#&quot;); a recording has a few, and one per channel</source>
        <translation>más de %1 líneas de comentario («#»); una grabación tiene unas pocas, y una por canal</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="195"/>
        <source>the header row should start with &quot;time&quot; (is this a chart CSV written by TipScope?)</source>
        <translation>la fila de cabecera debe empezar por &quot;time&quot; (¿es un CSV de gráficos escrito por TipScope?)</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="198"/>
        <source>%1 columns; replay reads at most %2</source>
        <translation>%1 columnas; la reproducción lee como máximo %2</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="212"/>
        <source>column %1 &quot;%2&quot; is not &quot;port&lt;n&gt; &lt;series&gt; [unit]&quot; or &quot;feeder &lt;series&gt; [unit]&quot;</source>
        <translation>la columna %1 &quot;%2&quot; no es &quot;port&lt;n&gt; &lt;serie&gt; [unidad]&quot; ni &quot;feeder &lt;serie&gt; [unidad]&quot;</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="225"/>
        <source>column %1 &quot;%2&quot;: the unit should be &quot;%3&quot;</source>
        <translation>columna %1 &quot;%2&quot;: la unidad debería ser &quot;%3&quot;</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="228"/>
        <source>none</source>
        <translation>ninguna</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="258"/>
        <source>Feeder</source>
        <translation>Alimentador</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="259"/>
        <source>Port %1</source>
        <translation>Puerto %1</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="236"/>
        <source>column %1 &quot;%2&quot; appears twice</source>
        <translation>la columna %1 &quot;%2&quot; aparece dos veces</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="244"/>
        <source>the header names no series columns</source>
        <translation>la cabecera no nombra ninguna columna de serie</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="287"/>
        <source>column %1: &quot;%2&quot; is not a number</source>
        <translation>columna %1: &quot;%2&quot; no es un número</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="294"/>
        <source>%1 has values in some of its columns but not all</source>
        <translation>%1 tiene valores en algunas de sus columnas, pero no en todas</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="301"/>
        <source>%1 cells, but the header has %2 columns</source>
        <translation>%1 celdas, pero la cabecera tiene %2 columnas</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="306"/>
        <source>&quot;%1&quot; is not an ISO 8601 time</source>
        <translation>&quot;%1&quot; no es una hora ISO 8601</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="310"/>
        <source>the time %1 is earlier than the row before it (rows must be in time order)</source>
        <translation>la hora %1 es anterior a la de la fila precedente (las filas deben estar en orden cronológico)</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="322"/>
        <source>%1 has more than %2 samples, more than replay holds; split the file</source>
        <translation>%1 tiene más de %2 muestras, más de las que admite la reproducción; divida el archivo</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="346"/>
        <source>the event &quot;%1&quot; is not &quot;&lt;channel&gt; &lt;kind&gt;: &lt;text&gt;&quot;</source>
        <translation>el evento &quot;%1&quot; no tiene la forma &quot;&lt;canal&gt; &lt;tipo&gt;: &lt;texto&gt;&quot;</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="168"/>
        <source>a quoted cell is not closed</source>
        <translation>una celda entre comillas no está cerrada</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="379"/>
        <source>the file has a header but no rows</source>
        <translation>el archivo tiene cabecera pero ninguna fila</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvparser.cpp" line="377"/>
        <source>the file is empty or holds only comments</source>
        <translation>el archivo está vacío o solo contiene comentarios</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvreader.cpp" line="30"/>
        <source>the file is larger than %1 MB; replay reads files up to %1 MB</source>
        <translation>el archivo ocupa más de %1 MB; la reproducción lee archivos de hasta %1 MB</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvreader.cpp" line="109"/>
        <source>its samples take %1 MB of memory after %2 MB read, more than replay allows (twice the file&apos;s size); a recording TipScope writes takes far less</source>
        <translation>sus muestras ocupan %1 MB de memoria tras leer %2 MB, más de lo que permite la reproducción (el doble del tamaño del archivo); una grabación escrita por TipScope ocupa mucho menos</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvreader.cpp" line="146"/>
        <source>reading was cancelled</source>
        <translation>se canceló la lectura</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/chartcsvreader.cpp" line="170"/>
        <source>the file is %1 MB; replay reads files up to %2 MB</source>
        <translation>el archivo ocupa %1 MB; la reproducción lee archivos de hasta %2 MB</translation>
    </message>
</context>
<context>
    <name>ChartRecorder</name>
    <message>
        <location filename="../lib/model/recording/chartrecorder.cpp" line="32"/>
        <source>nothing to record: no station or feeder is connected</source>
        <translation>nada que grabar: no hay ninguna estación ni alimentador conectados</translation>
    </message>
</context>
<context>
    <name>ChartSeries</name>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="103"/>
        <source>Tip</source>
        <translation>Punta</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="105"/>
        <source>Setpoint</source>
        <translation>Consigna</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="107"/>
        <source>Power</source>
        <translation>Potencia</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="109"/>
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="111"/>
        <source>Fed length</source>
        <translation>Longitud alimentada</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="113"/>
        <source>Speed</source>
        <translation>Velocidad</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="115"/>
        <source>Feeding</source>
        <translation>Alimentando</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="117"/>
        <source>Transistor</source>
        <translation>Transistor</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="119"/>
        <source>Transformer</source>
        <translation>Transformador</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="150"/>
        <source>Port %1</source>
        <translation>Puerto %1</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="165"/>
        <source>Feeder</source>
        <translation>Alimentador</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="44"/>
        <source>tip</source>
        <translation>punta</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="44"/>
        <source>P%1 tip</source>
        <translation>P%1 punta</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="45"/>
        <source>setpoint</source>
        <translation>consigna</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="46"/>
        <source>P%1 setpoint</source>
        <translation>P%1 consigna</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="47"/>
        <source>power</source>
        <translation>potencia</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="48"/>
        <source>P%1 power</source>
        <translation>P%1 potencia</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="49"/>
        <source>status</source>
        <translation>estado</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="50"/>
        <source>P%1 status</source>
        <translation>P%1 estado</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="51"/>
        <source>fed length</source>
        <translation>longitud alimentada</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="52"/>
        <source>speed</source>
        <translation>velocidad</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="53"/>
        <source>feeding</source>
        <translation>alimentando</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="54"/>
        <source>transistor</source>
        <translation>transistor</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="55"/>
        <source>P%1 transistor</source>
        <translation>P%1 transistor</translation>
    </message>
    <message>
        <location filename="../lib/model/chart/chartseries.cpp" line="56"/>
        <source>transformer</source>
        <translation>transformador</translation>
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
        <translation>indique solo uno de --json, --csv y --pdf ARCHIVO</translation>
    </message>
    <message>
        <location filename="../app/cli/cliboard.cpp" line="33"/>
        <source>board takes one board serial</source>
        <translation>board recibe un número de serie de placa</translation>
    </message>
    <message>
        <location filename="../app/cli/cliboard.cpp" line="57"/>
        <source>the journal has no board &apos;%1&apos;: no joint or event carries that serial</source>
        <translation>el diario no tiene la placa &apos;%1&apos;: ninguna soldadura ni evento lleva ese número de serie</translation>
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
        <translation>%1 campo de datos ilegible &apos;%2&apos;</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="106"/>
        <source>tipscope-cli: read needs at least one command code, e.g. read ST1</source>
        <translation>tipscope-cli: read necesita al menos un código de comando, p. ej. read ST1</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="119"/>
        <source>tipscope-cli: no device here can read &apos;%1&apos;</source>
        <translation>tipscope-cli: ningún equipo de esta línea puede leer &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="144"/>
        <source>%1 written</source>
        <translation>%1 escrito</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="158"/>
        <source>tipscope-cli: %1 was accepted but could not be read back: %2</source>
        <translation>tipscope-cli: %1 se aceptó, pero no se pudo volver a leer: %2</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="164"/>
        <source>tipscope-cli: verification failed: wrote %1, the device reports %2</source>
        <translation>tipscope-cli: la verificación falló: se escribió %1 y el equipo indica %2</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="171"/>
        <source>%1 (verified)</source>
        <translation>%1 (verificado)</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="187"/>
        <source>the device answered &apos;%1&apos;, which is no value</source>
        <translation>el equipo respondió &apos;%1&apos;, que no es un valor</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="208"/>
        <source>tipscope-cli: refused, nothing was sent: %1 is bounded by %2, which could not be read: %3</source>
        <translation>tipscope-cli: rechazado, no se envió nada: %1 está limitado por %2, que no se pudo leer: %3</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="239"/>
        <source>%1 (--force sends it anyway)</source>
        <translation>%1 (--force lo envía de todos modos)</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="250"/>
        <source>tipscope-cli: write takes CODE VALUE, e.g. write ST1 350</source>
        <translation>tipscope-cli: write requiere CÓDIGO VALOR, p. ej. write ST1 350</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="259"/>
        <source>tipscope-cli: no device here accepts writes of &apos;%1&apos;</source>
        <translation>tipscope-cli: ningún equipo de esta línea admite escrituras de &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="232"/>
        <source>the data field must be printable ASCII</source>
        <translation>el campo de datos debe ser ASCII imprimible</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="235"/>
        <source>the data field is longer than 32 characters</source>
        <translation>el campo de datos tiene más de 32 caracteres</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="216"/>
        <location filename="../app/cli/clicommands.cpp" line="289"/>
        <location filename="../app/cli/clicommands.cpp" line="315"/>
        <source>tipscope-cli: refused, nothing was sent: %1</source>
        <translation>tipscope-cli: rechazado, no se envió nada: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="306"/>
        <source>tipscope-cli: send takes the frame in hex, e.g. send 02 30 30 30 31 52 53 4D 4E 03 02</source>
        <translation>tipscope-cli: send requiere la trama en hexadecimal, p. ej. send 02 30 30 30 31 52 53 4D 4E 03 02</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="381"/>
        <source>tipscope-cli: unknown family &apos;%1&apos;; known: %2</source>
        <translation>tipscope-cli: familia desconocida &apos;%1&apos;; conocidas: %2</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="404"/>
        <source> [dangerous]</source>
        <translation> [peligroso]</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="407"/>
        <source>values: %1</source>
        <translation>valores: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/clicommands.cpp" line="409"/>
        <source>families: %1</source>
        <translation>familias: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/cli/clicommands.cpp" line="55"/>
        <source>%n raw byte(s), not a frame (%1)</source>
        <translation>
            <numerusform>%n byte en bruto, no es una trama (%1)</numerusform>
            <numerusform>%n bytes en bruto, no es una trama (%1)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>CliContext</name>
    <message>
        <location filename="../app/cli/clicontext.cpp" line="44"/>
        <source>&apos;%1&apos; is not a context line: write work_order=W, board_serial=S or operator=O</source>
        <translation>«%1» no es una línea de contexto: escriba work_order=W, board_serial=S u operator=O</translation>
    </message>
    <message>
        <location filename="../app/cli/clicontext.cpp" line="60"/>
        <source>cannot read standard input</source>
        <translation>no se puede leer la entrada estándar</translation>
    </message>
    <message>
        <location filename="../app/cli/clicontext.cpp" line="95"/>
        <source>tipscope-cli: refused, nothing was changed: %1</source>
        <translation>tipscope-cli: rechazado, no se cambió nada: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/clicontext.cpp" line="100"/>
        <source>tipscope-cli: context takes show, set [--work-order W] [--serial S] [--operator O] [--stdin], or clear</source>
        <translation>tipscope-cli: context admite show, set [--work-order W] [--serial S] [--operator O] [--stdin] o clear</translation>
    </message>
    <message>
        <location filename="../app/cli/clicontext.cpp" line="133"/>
        <source>tipscope-cli: limits takes show, set RULE (such as port=1,tool=C245,recovery=3.5,dip=60) or clear</source>
        <translation>tipscope-cli: limits admite show, set REGLA (por ejemplo port=1,tool=C245,recovery=3.5,dip=60) o clear</translation>
    </message>
</context>
<context>
    <name>CliJoints</name>
    <message>
        <location filename="../app/cli/clijoints.cpp" line="42"/>
        <source>&apos;%1&apos; is not a time: write 24h, 30m, 7d, 2026-12-01 or 2026-12-01T08:00</source>
        <translation>«%1» no es una hora: escriba 24h, 30m, 7d, 2026-12-01 o 2026-12-01T08:00</translation>
    </message>
    <message>
        <location filename="../app/cli/clijoints.cpp" line="67"/>
        <source>the journal has no device &apos;%1&apos;</source>
        <translation>el diario no tiene ningún dispositivo «%1»</translation>
    </message>
    <message>
        <location filename="../app/cli/clijoints.cpp" line="68"/>
        <source>&apos;%1&apos; names %2 devices; give one of:
  %3</source>
        <translation>«%1» designa %2 dispositivos; indique uno de ellos:
  %3</translation>
    </message>
    <message>
        <location filename="../app/cli/clijoints.cpp" line="96"/>
        <source>--port takes a port number from 1 to 4</source>
        <translation>--port admite un número de puerto del 1 al 4</translation>
    </message>
    <message>
        <location filename="../app/cli/clijoints.cpp" line="105"/>
        <source>--verdict takes ok, slow-recovery, too-deep or incomplete</source>
        <translation>--verdict admite ok, slow-recovery, too-deep o incomplete</translation>
    </message>
    <message>
        <location filename="../app/cli/clijoints.cpp" line="156"/>
        <source>tipscope-cli: give --json or --csv, not both</source>
        <translation>tipscope-cli: indique --json o --csv, no ambos</translation>
    </message>
</context>
<context>
    <name>CliJournal</name>
    <message>
        <location filename="../app/cli/clijournal.cpp" line="75"/>
        <source>tipscope-cli: journal retention takes a number of days (0 keeps everything), for example: journal retention 90</source>
        <translation>tipscope-cli: journal retention espera un número de días (0 lo conserva todo), por ejemplo: journal retention 90</translation>
    </message>
    <message>
        <location filename="../app/cli/clijournal.cpp" line="94"/>
        <source>tipscope-cli: the retention could not be stored: %1</source>
        <translation>tipscope-cli: no se pudo guardar el tiempo de conservación: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/clijournal.cpp" line="110"/>
        <source>tipscope-cli: journal takes show or retention DAYS</source>
        <translation>tipscope-cli: journal espera show o retention DÍAS</translation>
    </message>
</context>
<context>
    <name>CliMeasure</name>
    <message>
        <location filename="../app/cli/climeasure.cpp" line="70"/>
        <source>tipscope-cli: measure takes one FILE, a recording (record, or the Charts page&apos;s Record or CSV export)</source>
        <translation>tipscope-cli: measure espera un ARCHIVO, una grabación (de record, o de «Grabar» o la exportación CSV de la página de gráficos)</translation>
    </message>
    <message>
        <location filename="../app/cli/climeasure.cpp" line="81"/>
        <source>%1 is a FIFO: waiting for what is written into it (Ctrl-C stops)</source>
        <translation>%1 es un FIFO: se espera a lo que se escriba en él (Ctrl-C detiene)</translation>
    </message>
</context>
<context>
    <name>CliMonitor</name>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="186"/>
        <source>tipscope-cli: --interval takes milliseconds (0: as fast as the line allows)</source>
        <translation>tipscope-cli: --interval requiere milisegundos (0: tan rápido como permita la línea)</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="312"/>
        <source>tipscope-cli: --duration takes seconds</source>
        <translation>tipscope-cli: --duration requiere segundos</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="279"/>
        <source>tipscope-cli: monitor needs a station; none was found</source>
        <translation>tipscope-cli: monitor necesita una estación; no se encontró ninguna</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="237"/>
        <location filename="../app/cli/climonitorcsv.cpp" line="25"/>
        <source>tipscope-cli: cannot write %1: %2</source>
        <translation>tipscope-cli: no se puede escribir %1: %2</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="78"/>
        <source>P%1 --</source>
        <translation>P%1 --</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="102"/>
        <source>tipscope-cli: writing %1 failed: %2; monitoring goes on without it</source>
        <translation>tipscope-cli: no se pudo escribir %1: %2; la monitorización sigue sin el archivo</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="169"/>
        <source>reconnected to %1</source>
        <translation>reconectado a %1</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="203"/>
        <source>tipscope-cli: the workspace %1 has no lines</source>
        <translation>tipscope-cli: el espacio de trabajo %1 no tiene líneas</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="238"/>
        <source>permission denied</source>
        <translation>permiso denegado</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="239"/>
        <source>no such folder</source>
        <translation>no existe esa carpeta</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="246"/>
        <source>tipscope-cli: lines %1 and %2 would both write %3; rename one</source>
        <translation>tipscope-cli: las líneas %1 y %2 escribirían ambas %3; cambie el nombre de una</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitor.cpp" line="411"/>
        <source>%1 records could not be kept in the journal %2: %3</source>
        <translation>%1 registros no se pudieron guardar en el diario %2: %3</translation>
    </message>
</context>
<context>
    <name>CliMonitorMqtt</name>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="46"/>
        <source>--cfx takes the AMQP broker as amqp://HOST:PORT or amqps://HOST:PORT (the user with --cfx-user, the password from %1)</source>
        <translation>--cfx espera el broker AMQP como amqp://HOST:PUERTO o amqps://HOST:PUERTO (el usuario con --cfx-user, la contraseña de %1)</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="58"/>
        <source>--cfx-address takes RabbitMQ&apos;s form: /exchange/NAME, /exchange/NAME/KEY or /queue/NAME</source>
        <translation>--cfx-address espera la forma de RabbitMQ: /exchange/NOMBRE, /exchange/NOMBRE/CLAVE o /queue/NOMBRE</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="64"/>
        <source>--cfx-requests takes a queue of the broker: /queue/NAME</source>
        <translation>--cfx-requests espera una cola del broker: /queue/NOMBRE</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="82"/>
        <source>--mqtt takes the broker as HOST:PORT</source>
        <translation>--mqtt espera el broker como HOST:PUERTO</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="94"/>
        <source>--site takes the site&apos;s name</source>
        <translation>--site espera el nombre de la planta</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="100"/>
        <source>--interval takes milliseconds from 100 to 3600000</source>
        <translation>--interval espera milisegundos de 100 a 3600000</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="130"/>
        <location filename="../app/cli/climonitormqtt.cpp" line="156"/>
        <source>Broker connected.</source>
        <translation>Broker conectado.</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="132"/>
        <source>Broker disconnected.</source>
        <translation>Broker desconectado.</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="134"/>
        <location filename="../app/cli/climonitormqtt.cpp" line="157"/>
        <source>Connecting to the broker.</source>
        <translation>Conectando con el broker.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/cli/climonitormqtt.cpp" line="136"/>
        <source>%n device(s), %1 live messages, %2 joints and events forwarded, %3 waiting. %4</source>
        <translation>
            <numerusform>%n dispositivo, %1 mensajes en vivo, %2 soldaduras y eventos reenviados, %3 en espera. %4</numerusform>
            <numerusform>%n dispositivos, %1 mensajes en vivo, %2 soldaduras y eventos reenviados, %3 en espera. %4</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="153"/>
        <source>CFX: %1 messages from the journal accepted, %2 waiting. %3</source>
        <translation>CFX: %1 mensajes del diario aceptados, %2 en espera. %3</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="184"/>
        <source>tipscope-cli: %1 is not set: connecting as %2 without a password</source>
        <translation>tipscope-cli: %1 no está definida: se conecta como %2 sin contraseña</translation>
    </message>
    <message>
        <location filename="../app/cli/climonitormqtt.cpp" line="192"/>
        <source>tipscope-cli: --duration takes seconds</source>
        <translation>tipscope-cli: --duration espera segundos</translation>
    </message>
</context>
<context>
    <name>CliParser</name>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="164"/>
        <source>unknown command &apos;%1&apos;</source>
        <translation>comando desconocido &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="208"/>
        <source>give only one of --port, --tcp and --demo</source>
        <translation>indique solo una de --port, --tcp y --demo</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="214"/>
        <source>--workspace takes a file, and only one of --port, --tcp, --demo, --workspace</source>
        <translation>--workspace requiere un archivo, y solo uno de --port, --tcp, --demo, --workspace</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="221"/>
        <source>--port takes a device, and only one of --port, --tcp, --demo</source>
        <translation>--port requiere un dispositivo, y solo una de --port, --tcp, --demo</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="229"/>
        <source>--tcp takes HOST:PORT, and only one of --port, --tcp, --demo</source>
        <translation>--tcp requiere HOST:PUERTO, y solo una de --port, --tcp, --demo</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="234"/>
        <source>--baud takes a rate such as 19200</source>
        <translation>--baud requiere una velocidad como 19200</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="241"/>
        <source>--parity takes none, even or odd</source>
        <translation>--parity admite none, even u odd</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="245"/>
        <source>--stop-bits takes 1 or 2</source>
        <translation>--stop-bits admite 1 o 2</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="254"/>
        <source>--addr takes SRC:TGT, two addresses from 00 to 99 (e.g. 00:01)</source>
        <translation>--addr requiere ORIG:DEST, dos direcciones de 00 a 99 (p. ej. 00:01)</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="262"/>
        <source>--timeout takes milliseconds from 1 to 60000</source>
        <translation>--timeout requiere milisegundos de 1 a 60000</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="265"/>
        <source>--retries takes a number from 0 to 10</source>
        <translation>--retries requiere un número de 0 a 10</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="193"/>
        <source>--%1 needs a value</source>
        <translation>--%1 necesita un valor</translation>
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
        <translation>Uso: tipscope-cli [--port DISPOSITIVO | --tcp HOST:PUERTO | --demo | --demo-activity |
                   --workspace ARCHIVO] [--baud N]
                  [--parity none|even|odd] [--stop-bits 1|2] [--addr ORIG:DEST | --no-addr]
                  [--timeout MS] [--retries N] [--verbose] COMANDO ...

Comandos:
  detect [--json] [--scan]  una línea por equipo: &quot;&lt;dirección o --&gt; &lt;modelo&gt; &lt;familia&gt; &lt;versión&gt;&quot;
  read CÓDIGO... [--raw]    una línea por código: &quot;&lt;CÓDIGO&gt; &lt;valor&gt; &lt;unidad&gt;&quot;
  write CÓDIGO VALOR [--raw [--force]]
                            valida (MIT y MAT leídos antes), envía y vuelve a leer;
                            --raw envía el campo de datos, comprobado salvo con --force
  send HEX                  envía una trama en bruto; muestra la respuesta en hex y decodificada
  monitor [--interval MS] [--duration S] [--csv ARCHIVO [--csv-one-file]]
          [--limit REGLA] [--journal ARCHIVO]
                            temperatura de la punta, consigna, potencia y estado por
                            puerto, y una línea por soldadura, cada una guardada en el diario
  monitor --mqtt HOST:PORT [--mqtt-user U] [--site S] [--interval MS] [--duration S]
                            publica las líneas en un broker MQTT como tipscope-agent
                            (docs/mqtt.md); la contraseña, de TIPSCOPE_MQTT_PASSWORD
  monitor --cfx amqp[s]://HOST:PUERTO [--cfx-user U] [--cfx-address DIRECCIÓN]
          [--cfx-requests /queue/NOMBRE]
                            cada estación como punto final IPC-CFX (docs/cfx.md), junto
                            a --mqtt o sola; la contraseña, de TIPSCOPE_CFX_PASSWORD
  dump [--json]             todos los parámetros legibles, contadores y errores
  commands [--family F]     el catálogo de comandos
  profile save ARCHIVO      todos los ajustes escribibles del equipo en un perfil JSON
  profile diff ARCHIVO      lo que cambiaría al aplicar el perfil
  profile apply ARCHIVO [--dry-run] [--force]
                            escribe lo que difiere y vuelve a leer cada valor; --dry-run
                            lista las tramas; --force aplica un perfil de otra familia
  record ARCHIVO [--duration S]
                            las curvas y eventos de todos los puertos y del alimentador en una
                            grabación de gráficos, como la graba la página de gráficos
  measure ARCHIVO [--json]  los calentamientos y recuperaciones de una grabación, uno por línea
  joints [--since T] [--until T] [--device D] [--port N] [--tool T]
         [--verdict V] [--work-order W] [--json | --csv] [--journal ARCHIVO]
                            las soldaduras que guarda el diario, las más recientes primero;
                            T es 24h, 30m, 7d o una fecha y hora ISO; V es ok,
                            slow-recovery, too-deep o incomplete
  context [show | clear | set [--work-order W] [--serial S] [--operator O] [--stdin]]
                            el contexto de trabajo que llevan cada soldadura y cada evento
  limits [show | clear | set REGLA]
                            los límites de soldadura; REGLA es port=N,tool=T,recovery=S,
                            dip=K,wear=PROPORCIÓN (cualquiera; gana la regla más concreta)
  journal [show [--json] | retention DÍAS] [--journal ARCHIVO]
                            lo que guarda el diario y cuántos días conserva
                            los registros (0: todos); lo comparten todos los programas
  board SERIE [--json | --csv | --pdf ARCHIVO] [--journal ARCHIVO]
                            el registro de una placa: cada soldadura con su número de
                            serie, el desgaste de sus puntas, los eventos mientras se hizo;
                            --csv sus soldaduras como joints --csv; --pdf un documento
                            para firmar

Sin --addr ni --no-addr, el equipo se busca automáticamente. --demo habla con la
estación DME simulada integrada (dirección 01) y el alimentador SFR (dirección 10);
--demo-activity lo mismo en funcionamiento: soldaduras en el puerto 1 cada 15 s, pausas en el
puerto 2, alimentaciones.
--timeout es el tiempo de respuesta del equipo, que se suma al tiempo de transmisión
de cada petición.
--workspace ejecuta el comando en cada línea de un archivo de espacio de trabajo a la vez,
cada línea de salida precedida del nombre de la línea; monitor --csv escribe un archivo por línea.

Códigos de salida: 0 correcto; 1 error de uso, o un número de serie de placa que el diario
no tiene; 2 valor rechazado antes de enviar (no se escribió nada); 3 el equipo respondió NAK,
o falló una relectura o la comprobación del perfil; 4 ninguna respuesta válida; 5 error de
transporte; el diario (joints, board, journal show): 6 no existe, 7 dañado, 8 más nuevo,
9 bloqueado, 10 no accesible, 11 disco lleno o con fallos.
</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="197"/>
        <source>--%1 takes no value</source>
        <translation>--%1 no admite ningún valor</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="269"/>
        <source>unknown option --%1</source>
        <translation>opción desconocida --%1</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="270"/>
        <source>&apos;%1&apos; has no option --%2</source>
        <translation>&apos;%1&apos; no tiene la opción --%2</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="276"/>
        <source>no command given</source>
        <translation>no se indicó ningún comando</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="279"/>
        <source>--workspace runs detect, monitor, dump or joints, not %1</source>
        <translation>--workspace ejecuta detect, monitor, dump o joints, no %1</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="282"/>
        <source>--csv-one-file goes with --workspace and --csv FILE</source>
        <translation>--csv-one-file va con --workspace y --csv ARCHIVO</translation>
    </message>
    <message>
        <location filename="../app/cli/clioptions.cpp" line="285"/>
        <source>say where the device is: --port DEVICE, --tcp HOST:PORT or --demo</source>
        <translation>indique dónde está el equipo: --port DISPOSITIVO, --tcp HOST:PUERTO o --demo</translation>
    </message>
</context>
<context>
    <name>CliProfile</name>
    <message>
        <location filename="../app/cli/cliprofile.cpp" line="43"/>
        <source>tipscope-cli: could not read %1; no profile written</source>
        <translation>tipscope-cli: no se pudo leer %1; no se escribió ningún perfil</translation>
    </message>
    <message>
        <location filename="../app/cli/cliprofile.cpp" line="52"/>
        <source>saved %1 settings of %2 to %3</source>
        <translation>se guardaron %1 ajustes de %2 en %3</translation>
    </message>
    <message>
        <location filename="../app/cli/cliprofile.cpp" line="66"/>
        <source>tipscope-cli: profile takes save FILE, diff FILE or apply FILE</source>
        <translation>tipscope-cli: profile requiere save ARCHIVO, diff ARCHIVO o apply ARCHIVO</translation>
    </message>
    <message>
        <location filename="../app/cli/cliprofile.cpp" line="113"/>
        <source>tipscope-cli: applying this profile would be refused: %1</source>
        <translation>tipscope-cli: aplicar este perfil se rechazaría: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/cliprofile.cpp" line="119"/>
        <source>tipscope-cli: the line was dropped during the apply: %1. A slow station may need a longer --timeout (now %2 ms) or more --retries (now %3); apply the profile again once the line answers: what is already right is left alone</source>
        <translation>tipscope-cli: la línea se cortó durante la aplicación: %1. Una estación lenta puede necesitar un --timeout más largo (ahora %2 ms) o más --retries (ahora %3); vuelva a aplicar el perfil cuando la línea responda: lo que ya es correcto no se toca</translation>
    </message>
</context>
<context>
    <name>CliRecord</name>
    <message>
        <location filename="../app/cli/clirecord.cpp" line="58"/>
        <source>tipscope-cli: interrupted before the recording started</source>
        <translation>tipscope-cli: interrumpido antes de que empezara la grabación</translation>
    </message>
    <message>
        <location filename="../app/cli/clirecord.cpp" line="64"/>
        <source>tipscope-cli: cannot open %1: %2</source>
        <translation>tipscope-cli: no se puede abrir %1: %2</translation>
    </message>
    <message>
        <location filename="../app/cli/clirecord.cpp" line="99"/>
        <source>tipscope-cli: record takes one FILE, e.g. record line3.csv --duration 60</source>
        <translation>tipscope-cli: record espera un ARCHIVO, p. ej. record linea3.csv --duration 60</translation>
    </message>
    <message>
        <location filename="../app/cli/clirecord.cpp" line="108"/>
        <source>tipscope-cli: --duration takes seconds (0: until interrupted)</source>
        <translation>tipscope-cli: --duration espera segundos (0: hasta que se interrumpa)</translation>
    </message>
    <message>
        <location filename="../app/cli/clirecord.cpp" line="116"/>
        <location filename="../app/cli/clirecord.cpp" line="143"/>
        <source>tipscope-cli: cannot record to %1: %2</source>
        <translation>tipscope-cli: no se puede grabar en %1: %2</translation>
    </message>
    <message>
        <location filename="../app/cli/clirecord.cpp" line="117"/>
        <source>no such folder</source>
        <translation>la carpeta no existe</translation>
    </message>
    <message>
        <location filename="../app/cli/clirecord.cpp" line="118"/>
        <source>not writable</source>
        <translation>sin permiso de escritura</translation>
    </message>
    <message>
        <location filename="../app/cli/clirecord.cpp" line="165"/>
        <source># recording %1 of %2 to %3</source>
        <translation># grabando %1 de %2 en %3</translation>
    </message>
    <message>
        <location filename="../app/cli/clirecord.cpp" line="173"/>
        <source>tipscope-cli: writing %1 failed: %2</source>
        <translation>tipscope-cli: falló la escritura de %1: %2</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/cli/clirecord.cpp" line="178"/>
        <source>recorded %n row(s) to %1</source>
        <translation>
            <numerusform>%n fila grabada en %1</numerusform>
            <numerusform>%n filas grabadas en %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>CliSession</name>
    <message>
        <location filename="../app/cli/clisession.cpp" line="78"/>
        <source>tipscope-cli: cannot open %1: %2</source>
        <translation>tipscope-cli: no se puede abrir %1: %2</translation>
    </message>
    <message>
        <location filename="../app/cli/clisession.cpp" line="132"/>
        <source>tipscope-cli: %1</source>
        <translation>tipscope-cli: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/clisession.cpp" line="155"/>
        <source>tipscope-cli: the line was lost: %1</source>
        <translation>tipscope-cli: se perdió la línea: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/clisession.cpp" line="161"/>
        <source>tipscope-cli: no device could be identified on %1 (checked addresses 01, 10, 20 and frames without addresses); what came back: %2. Check the baud rate, the addressing, and that robot mode is on.</source>
        <translation>tipscope-cli: no se pudo identificar ningún equipo en %1 (se comprobaron las direcciones 01, 10, 20 y las tramas sin direcciones); lo que volvió: %2. Compruebe la velocidad en baudios, el direccionamiento y que el modo robot esté activado.</translation>
    </message>
    <message>
        <location filename="../app/cli/clisession.cpp" line="170"/>
        <source>tipscope-cli: no device answered on %1 (checked addresses 01, 10, 20 and frames without addresses). Check the cable, the baud rate, and that robot mode is on.</source>
        <translation>tipscope-cli: ningún equipo respondió en %1 (se comprobaron las direcciones 01, 10, 20 y las tramas sin direcciones). Compruebe el cable, la velocidad en baudios y que el modo robot esté activado.</translation>
    </message>
</context>
<context>
    <name>CliWorkspace</name>
    <message>
        <location filename="../app/cli/cliworkspace.cpp" line="152"/>
        <source>tipscope-cli: the workspace %1 has no lines</source>
        <translation>tipscope-cli: el espacio de trabajo %1 no tiene líneas</translation>
    </message>
</context>
<context>
    <name>ConsoleModel</name>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="102"/>
        <source>sent as typed (not a valid frame)</source>
        <translation>enviado tal cual (no es una trama válida)</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="118"/>
        <source>stray: answers no pending request</source>
        <translation>huérfana: no responde a ninguna petición pendiente</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="250"/>
        <source>TX</source>
        <translation>TX</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="252"/>
        <source>RX chunk</source>
        <translation>Bloque RX</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="254"/>
        <source>RX</source>
        <translation>RX</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="256"/>
        <source>error</source>
        <translation>error</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="258"/>
        <source>note</source>
        <translation>nota</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="266"/>
        <source>Read</source>
        <translation>Lectura</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="268"/>
        <source>Write</source>
        <translation>Escritura</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="270"/>
        <source>Answer</source>
        <translation>Respuesta</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="315"/>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="315"/>
        <source>bad</source>
        <translation>erróneo</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="331"/>
        <source>Time</source>
        <translation>Hora</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="331"/>
        <source>Dir</source>
        <translation>Sentido</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="332"/>
        <source>Addr</source>
        <translation>Dir.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="332"/>
        <source>Header</source>
        <translation>Cabecera</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="333"/>
        <source>Cmd</source>
        <translation>Comando</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="333"/>
        <source>Name</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolemodel.cpp" line="334"/>
        <source>Data</source>
        <translation>Datos</translation>
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
        <translation>Observación</translation>
    </message>
</context>
<context>
    <name>DeviceIdentity</name>
    <message>
        <location filename="../lib/model/context/deviceidentity.cpp" line="73"/>
        <source>%1 at %2</source>
        <translation>%1 en la dirección %2</translation>
    </message>
    <message>
        <location filename="../lib/model/context/deviceidentity.cpp" line="76"/>
        <source>software unknown</source>
        <translation>software desconocido</translation>
    </message>
    <message>
        <location filename="../lib/model/context/deviceidentity.cpp" line="77"/>
        <source>software %1</source>
        <translation>software %1</translation>
    </message>
    <message>
        <location filename="../lib/model/context/deviceidentity.cpp" line="78"/>
        <source>%1 on %2, %3</source>
        <translation>%1 en %2, %3</translation>
    </message>
</context>
<context>
    <name>DeviceModel</name>
    <message>
        <location filename="../lib/model/device/devicemodel.cpp" line="69"/>
        <source>%1 at %2</source>
        <translation>%1, dirección %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/devicemodel.cpp" line="70"/>
        <source>%1 (no address)</source>
        <translation>%1 (sin dirección)</translation>
    </message>
    <message>
        <location filename="../lib/model/device/devicemodel.cpp" line="74"/>
        <location filename="../lib/model/device/devicemodel.cpp" line="157"/>
        <source>%1, port %2</source>
        <translation>%1, puerto %2</translation>
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
        <translation>herramienta %1</translation>
    </message>
    <message>
        <location filename="../lib/model/device/devicemodel.cpp" line="154"/>
        <source>%1, %2, port %3</source>
        <translation>%1, %2, puerto %3</translation>
    </message>
    <message>
        <location filename="../lib/model/device/devicemodel.cpp" line="160"/>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/devicemodel.cpp" line="203"/>
        <source>Monitor-only mode is on: nothing is written.</source>
        <translation>El modo solo monitorización está activo: no se escribe nada.</translation>
    </message>
    <message>
        <location filename="../lib/model/device/devicemodel.cpp" line="205"/>
        <source>Not connected: nothing can be sent until the line is back.</source>
        <translation>No conectado: no se puede enviar nada hasta que vuelva la línea.</translation>
    </message>
</context>
<context>
    <name>DisplayUnits</name>
    <message>
        <location filename="../lib/model/device/displayunits.cpp" line="81"/>
        <source>&apos;%1&apos; is not a number</source>
        <translation>&apos;%1&apos; no es un número</translation>
    </message>
    <message>
        <location filename="../lib/model/device/displayunits.cpp" line="86"/>
        <source>&apos;%1&apos; is far outside what %2 can take</source>
        <translation>&apos;%1&apos; está muy fuera de lo que admite %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/displayunits.cpp" line="93"/>
        <source>%1 lies between the values %2 can take: %3 or %4</source>
        <translation>%1 está entre los valores que admite %2: %3 o %4</translation>
    </message>
</context>
<context>
    <name>Elide</name>
    <message>
        <location filename="../lib/protocol/elide.cpp" line="39"/>
        <source>%1… (%2 characters)</source>
        <translation>%1… (%2 caracteres)</translation>
    </message>
</context>
<context>
    <name>Event</name>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="50"/>
        <source>Station error</source>
        <translation>Error de estación</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="52"/>
        <source>Port error</source>
        <translation>Error de puerto</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="54"/>
        <source>Feeder error</source>
        <translation>Error del alimentador</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="56"/>
        <source>Alarm</source>
        <translation>Alarma</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="58"/>
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="60"/>
        <source>Write</source>
        <translation>Escritura</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="62"/>
        <source>Communication</source>
        <translation>Comunicación</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="64"/>
        <source>Connection</source>
        <translation>Conexión</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="66"/>
        <source>Tool change</source>
        <translation>Cambio de herramienta</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="68"/>
        <source>Joint</source>
        <translation>Soldadura</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="70"/>
        <source>Profile apply</source>
        <translation>Aplicación de perfil</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="72"/>
        <source>Work context</source>
        <translation>Contexto de trabajo</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventlog.cpp" line="74"/>
        <source>Journal</source>
        <translation>Diario</translation>
    </message>
</context>
<context>
    <name>EventHistoryModel</name>
    <message>
        <location filename="../lib/model/events/eventhistorymodel.cpp" line="108"/>
        <source>Time</source>
        <translation>Hora</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventhistorymodel.cpp" line="110"/>
        <source>Severity</source>
        <translation>Gravedad</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventhistorymodel.cpp" line="112"/>
        <source>Kind</source>
        <translation>Tipo</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventhistorymodel.cpp" line="114"/>
        <source>Source</source>
        <translation>Origen</translation>
    </message>
    <message>
        <location filename="../lib/model/events/eventhistorymodel.cpp" line="116"/>
        <source>What happened</source>
        <translation>Qué ocurrió</translation>
    </message>
</context>
<context>
    <name>EventText</name>
    <message numerus="yes">
        <location filename="../lib/model/events/eventtext.cpp" line="16"/>
        <source>%1 (%n times, until %2)</source>
        <translation>
            <numerusform>%1 (%n vez, hasta %2)</numerusform>
            <numerusform>%1 (%n veces, hasta %2)</numerusform>
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
        <translation>%1 no tiene el comando %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/feedermodel.cpp" line="116"/>
        <source>error cleared</source>
        <translation>error borrado</translation>
    </message>
</context>
<context>
    <name>FrameComposer</name>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="40"/>
        <source>%1 carries the data field %2.</source>
        <translation>%1 lleva el campo de datos %2.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="43"/>
        <source>A write needs a data field: %1.</source>
        <translation>Una escritura necesita un campo de datos: %1.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="53"/>
        <source>On the wire this value is written %1.</source>
        <translation>En la línea este valor se escribe %1.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="70"/>
        <source>Unknown device family: the catalog cannot check this frame.</source>
        <translation>Familia de equipo desconocida: el catálogo no puede comprobar esta trama.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="78"/>
        <source>%1 is not a %2 write command in the catalog.</source>
        <translation>%1 no es un comando de escritura de %2 en el catálogo.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="79"/>
        <source>%1 is not a %2 read command in the catalog.</source>
        <translation>%1 no es un comando de lectura de %2 en el catálogo.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="82"/>
        <source>Did you mean %1?</source>
        <translation>¿Quería decir %1?</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="83"/>
        <source>It is sent as typed.</source>
        <translation>Se envía tal cual.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="88"/>
        <source>Reads carry no data field; the device may refuse this frame.</source>
        <translation>Las lecturas no llevan campo de datos; el equipo puede rechazar esta trama.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="95"/>
        <source>Dangerous: %1</source>
        <translation>Peligroso: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="99"/>
        <source>Catalog check: %1</source>
        <translation>Comprobación del catálogo: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="113"/>
        <source>%1 (no address)</source>
        <translation>%1 (sin dirección)</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="156"/>
        <source>No device is known on this line: connect first, or send raw hex.</source>
        <translation>No se conoce ningún equipo en esta línea: conéctese primero o envíe hex en bruto.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="173"/>
        <source>Not sendable: the command must be 3 printable characters, e.g. SMN.</source>
        <translation>No se puede enviar: el comando debe tener 3 caracteres imprimibles, p. ej. SMN.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="179"/>
        <source>Not sendable: the data field may only hold printable ASCII.</source>
        <translation>No se puede enviar: el campo de datos solo puede contener ASCII imprimible.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/framecomposer.cpp" line="184"/>
        <source>Not sendable: addresses go from 00 to 99.</source>
        <translation>No se puede enviar: las direcciones van de 00 a 99.</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/console/framecomposer.cpp" line="214"/>
        <source>%n byte(s), a valid frame: %1</source>
        <translation>
            <numerusform>%n byte, una trama válida: %1</numerusform>
            <numerusform>%n bytes, una trama válida: %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/console/framecomposer.cpp" line="216"/>
        <source>%n byte(s), not a valid frame (%1): sent as typed</source>
        <translation>
            <numerusform>%n byte, no es una trama válida (%1): se envía tal cual</numerusform>
            <numerusform>%n bytes, no es una trama válida (%1): se envía tal cual</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>FrameDecoder</name>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="19"/>
        <source>frame</source>
        <translation>trama</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="21"/>
        <source>BCC error</source>
        <translation>error de BCC</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="23"/>
        <source>format error</source>
        <translation>error de formato</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="25"/>
        <source>overflow</source>
        <translation>desbordamiento</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="27"/>
        <source>garbage</source>
        <translation>basura</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="47"/>
        <source>not STX…ETX BCC or too short</source>
        <translation>no es STX…ETX BCC o es demasiado corta</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="50"/>
        <source>BCC is %1, expected %2</source>
        <translation>el BCC es %1, se esperaba %2</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="60"/>
        <source>malformed addresses</source>
        <translation>direcciones mal formadas</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="66"/>
        <source>too short for header and command</source>
        <translation>demasiado corta para cabecera y comando</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="69"/>
        <source>unknown header</source>
        <translation>cabecera desconocida</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="74"/>
        <source>command is not 3 letters or digits</source>
        <translation>el comando no son 3 letras o dígitos</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="78"/>
        <source>data field is not printable ASCII</source>
        <translation>el campo de datos no es ASCII imprimible</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="110"/>
        <source>frame interrupted by a new STX</source>
        <translation>trama interrumpida por un nuevo STX</translation>
    </message>
    <message>
        <location filename="../lib/protocol/framedecoder.cpp" line="119"/>
        <source>no ETX within %1 bytes</source>
        <translation>ningún ETX en %1 bytes</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/protocol/framedecoder.cpp" line="144"/>
        <source>%n byte(s) outside any frame</source>
        <translation>
            <numerusform>%n byte fuera de toda trama</numerusform>
            <numerusform>%n bytes fuera de toda trama</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>HexBytes</name>
    <message>
        <location filename="../lib/protocol/hexbytes.cpp" line="35"/>
        <source>odd number of hex digits before position %1</source>
        <translation>número impar de dígitos hexadecimales antes de la posición %1</translation>
    </message>
    <message>
        <location filename="../lib/protocol/hexbytes.cpp" line="45"/>
        <source>&apos;%1&apos; at position %2 is not a hex digit</source>
        <translation>&apos;%1&apos; en la posición %2 no es un dígito hexadecimal</translation>
    </message>
    <message>
        <location filename="../lib/protocol/hexbytes.cpp" line="52"/>
        <source>more than %1 bytes</source>
        <translation>más de %1 bytes</translation>
    </message>
    <message>
        <location filename="../lib/protocol/hexbytes.cpp" line="56"/>
        <source>odd number of hex digits</source>
        <translation>número impar de dígitos hexadecimales</translation>
    </message>
    <message>
        <location filename="../lib/protocol/hexbytes.cpp" line="58"/>
        <source>no bytes given</source>
        <translation>no se indicó ningún byte</translation>
    </message>
</context>
<context>
    <name>JointLimitRules</name>
    <message>
        <location filename="../lib/model/joints/jointlimitrules.cpp" line="51"/>
        <source>the longest recovery must be more than 0 s and at most %1 s</source>
        <translation>la recuperación más larga debe ser de más de 0 s y como máximo %1 s</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitrules.cpp" line="59"/>
        <source>the deepest dip must be a whole number of kelvin from 1 to %1</source>
        <translation>la caída más profunda debe ser un número entero de kelvin entre 1 y %1</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitrules.cpp" line="67"/>
        <source>the tip wear share must be more than 0 and at most 10</source>
        <translation>la proporción de desgaste de la punta debe ser mayor que 0 y como máximo 10</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitrules.cpp" line="73"/>
        <source>a port is a number from 1 to 4</source>
        <translation>un puerto es un número del 1 al 4</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitrules.cpp" line="111"/>
        <source>%1 must be a number</source>
        <translation>%1 debe ser un número</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitrules.cpp" line="170"/>
        <source>joint limits: %1</source>
        <translation>límites de soldadura: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitrules.cpp" line="177"/>
        <source>joint limit rule %1: %2</source>
        <translation>regla de límites de soldadura %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitrules.cpp" line="204"/>
        <source>“%1” is not a limit: write port=N, tool=NAME, recovery=SECONDS, dip=KELVIN or wear=SHARE, joined by commas</source>
        <translation>«%1» no es un límite: escriba port=N, tool=NOMBRE, recovery=SEGUNDOS, dip=KELVIN o wear=PROPORCIÓN, separados por comas</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitrules.cpp" line="212"/>
        <source>“%1” sets no limit: give recovery=SECONDS, dip=KELVIN or wear=SHARE</source>
        <translation>«%1» no fija ningún límite: indique recovery=SEGUNDOS, dip=KELVIN o wear=PROPORCIÓN</translation>
    </message>
</context>
<context>
    <name>JointLimitsFile</name>
    <message>
        <location filename="../lib/model/joints/jointlimitsfile.cpp" line="35"/>
        <source>cannot read the joint limits %1: %2</source>
        <translation>no se pueden leer los límites de soldadura %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitsfile.cpp" line="39"/>
        <source>the joint limits %1 are too big</source>
        <translation>los límites de soldadura %1 son demasiado grandes</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointlimitsfile.cpp" line="42"/>
        <source>the joint limits %1 are not a JSON object: %2</source>
        <translation>los límites de soldadura %1 no son un objeto JSON: %2</translation>
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
        <translation>correcta</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="167"/>
        <source>slow recovery</source>
        <translation>recuperación lenta</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="169"/>
        <source>too deep</source>
        <translation>demasiado profunda</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="171"/>
        <source>incomplete</source>
        <translation>incompleta</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="198"/>
        <source>none</source>
        <translation>ninguna</translation>
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
        <translation>Empezó a ± %1 ms de esta hora</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="232"/>
        <source>Measured to ± %1 K</source>
        <translation>Medido con ± %1 K</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="236"/>
        <source>The tip was not seen back within the band</source>
        <translation>No se vio la punta volver a la banda</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="238"/>
        <source>Only bounded: the readings around the tip&apos;s return were too far apart, or broke off, to say when within the interval shown</source>
        <translation>Solo acotado: las lecturas en torno a la vuelta de la punta estaban demasiado separadas, o se interrumpieron, para decir cuándo dentro del intervalo mostrado</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="241"/>
        <source>Measured to ± %1 ms</source>
        <translation>Medido con ± %1 ms</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="250"/>
        <source>Time</source>
        <translation>Hora</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="252"/>
        <source>Device</source>
        <translation>Equipo</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="254"/>
        <source>Port</source>
        <translation>Puerto</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="256"/>
        <source>Tool</source>
        <translation>Herramienta</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="258"/>
        <source>Setpoint</source>
        <translation>Consigna</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="260"/>
        <source>Lowest</source>
        <translation>Mínima</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="262"/>
        <source>Dip</source>
        <translation>Caída</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="264"/>
        <source>Recovery</source>
        <translation>Recuperación</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="266"/>
        <source>Duration</source>
        <translation>Duración</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="268"/>
        <source>Power peak</source>
        <translation>Potencia máx.</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="270"/>
        <source>Power·time</source>
        <translation>Potencia·tiempo</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="272"/>
        <source>Verdict</source>
        <translation>Veredicto</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointtable.cpp" line="274"/>
        <source>Work order</source>
        <translation>Orden de trabajo</translation>
    </message>
</context>
<context>
    <name>JointWatcher</name>
    <message>
        <location filename="../lib/model/joints/jointwatcher.cpp" line="115"/>
        <source>joint too deep: the tip fell %1 K below the setpoint (limit %2 K)</source>
        <translation>soldadura demasiado profunda: la punta bajó %1 K por debajo de la consigna (límite %2 K)</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointwatcher.cpp" line="121"/>
        <source>joint recovered slowly: %1 s (limit %2 s)</source>
        <translation>soldadura con recuperación lenta: %1 s (límite %2 s)</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/jointwatcher.cpp" line="123"/>
        <source>joint did not recover within %1 s</source>
        <translation>la soldadura no se recuperó en %1 s</translation>
    </message>
</context>
<context>
    <name>Journal</name>
    <message>
        <location filename="../lib/journal/journalreader.cpp" line="32"/>
        <location filename="../lib/journal/journalreader.cpp" line="249"/>
        <source>No journal is open.</source>
        <translation>No hay ningún diario abierto.</translation>
    </message>
    <message>
        <location filename="../lib/journal/journalreader.cpp" line="91"/>
        <source>There is no journal at %1.</source>
        <translation>No hay ningún diario en %1.</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/journal/journalreader.cpp" line="122"/>
        <source>The journal %1 is damaged (%n finding(s), the first: %2).</source>
        <translation>
            <numerusform>El diario %1 está dañado (%n hallazgo, el primero: %2).</numerusform>
            <numerusform>El diario %1 está dañado (%n hallazgos, el primero: %2).</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../lib/journal/journalschema.cpp" line="117"/>
        <source>The journal %1 was written by a newer TipScope (schema %2; this one knows up to %3). It was left untouched.</source>
        <translation>El diario %1 lo escribió un TipScope más reciente (esquema %2; este conoce hasta el %3). No se ha modificado.</translation>
    </message>
    <message>
        <location filename="../lib/journal/journalschema.cpp" line="132"/>
        <source>The file %1 is not a TipScope journal. It was left untouched.</source>
        <translation>El archivo %1 no es un diario de TipScope. No se ha modificado.</translation>
    </message>
    <message>
        <location filename="../lib/journal/journalschema.cpp" line="241"/>
        <source>Cannot create the folder %1 for the journal.</source>
        <translation>No se puede crear la carpeta %1 para el diario.</translation>
    </message>
    <message>
        <location filename="../lib/journal/journalwriter.cpp" line="252"/>
        <source>Records lost: %1. Reason: %2</source>
        <translation>Registros perdidos: %1. Motivo: %2</translation>
    </message>
    <message>
        <location filename="../lib/journal/journalwriter.cpp" line="341"/>
        <source>The journal was closed before it could write them: %1</source>
        <translation>El diario se cerró antes de poder escribirlos: %1</translation>
    </message>
    <message>
        <location filename="../lib/journal/sqlerror.cpp" line="71"/>
        <source>The journal %1 cannot grow: the disk is full or the journal reached its size limit.</source>
        <translation>El diario %1 no puede crecer: el disco está lleno o el diario alcanzó su tamaño máximo.</translation>
    </message>
    <message>
        <location filename="../lib/journal/sqlerror.cpp" line="82"/>
        <source>The journal %1 is damaged or is not a journal; it was left untouched.</source>
        <translation>El diario %1 está dañado o no es un diario; no se ha modificado.</translation>
    </message>
    <message>
        <location filename="../lib/journal/sqlerror.cpp" line="87"/>
        <source>The journal %1 is locked by another program.</source>
        <translation>Otro programa tiene bloqueado el diario %1.</translation>
    </message>
    <message>
        <location filename="../lib/journal/sqlerror.cpp" line="89"/>
        <source>The disk holding the journal %1 reported an error.</source>
        <translation>El disco del diario %1 ha informado de un error.</translation>
    </message>
    <message>
        <location filename="../lib/journal/sqlerror.cpp" line="91"/>
        <source>The journal %1 reported an error: %2</source>
        <translation>El diario %1 ha informado de un error: %2</translation>
    </message>
    <message>
        <location filename="../lib/journal/sqlerror.cpp" line="118"/>
        <source>The journal %1 cannot be written: its folder or the file is read-only or not accessible.</source>
        <translation>No se puede escribir el diario %1: su carpeta o el archivo es de solo lectura o no es accesible.</translation>
    </message>
    <message>
        <location filename="../lib/journal/journalsettings.cpp" line="55"/>
        <source>A retention of %1 days is not possible: give 0 (keep everything) up to %2 days.</source>
        <translation>No se puede conservar %1 días: indique de 0 (conservarlo todo) a %2 días.</translation>
    </message>
</context>
<context>
    <name>LinkStats</name>
    <message>
        <location filename="../lib/link/linkstats.cpp" line="60"/>
        <source>%1 tx/s, latency %2 ms median (%3-%4), %5 sent, %6 answered, %7 timeouts, %8 corrupted, %9 NAKs, %10 stray, %11 retries</source>
        <translation>%1 tx/s, latencia %2 ms de mediana (%3-%4), %5 enviadas, %6 respondidas, %7 tiempos agotados, %8 dañadas, %9 NAK, %10 huérfanas, %11 reintentos</translation>
    </message>
</context>
<context>
    <name>MeasurementReport</name>
    <message>
        <location filename="../lib/model/analysis/measurementreport.cpp" line="32"/>
        <source>%1: min %2, max %3, mean %4</source>
        <translation>%1: mín. %2, máx. %3, media %4</translation>
    </message>
    <message>
        <location filename="../lib/model/analysis/measurementreport.cpp" line="42"/>
        <source>wake</source>
        <translation>salida del reposo</translation>
    </message>
    <message>
        <location filename="../lib/model/analysis/measurementreport.cpp" line="42"/>
        <source>heat-up</source>
        <translation>calentamiento</translation>
    </message>
    <message>
        <location filename="../lib/model/analysis/measurementreport.cpp" line="46"/>
        <source>%1 at %2 to %3: %4</source>
        <translation>%1 a las %2 hasta %3: %4</translation>
    </message>
    <message>
        <location filename="../lib/model/analysis/measurementreport.cpp" line="48"/>
        <source>%1 at %2 to %3: not reached in this window</source>
        <translation>%1 a las %2 hasta %3: no alcanzado en esta ventana</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/analysis/measurementreport.cpp" line="52"/>
        <source>… %n more heat-up(s)</source>
        <translation>
            <numerusform>… %n calentamiento más</numerusform>
            <numerusform>… %n calentamientos más</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../lib/model/analysis/measurementreport.cpp" line="64"/>
        <source>recovery at %1: %2 (dip to %3)</source>
        <translation>recuperación a las %1: %2 (caída hasta %3)</translation>
    </message>
    <message>
        <location filename="../lib/model/analysis/measurementreport.cpp" line="66"/>
        <source>dip at %1 to %2: not recovered in this window</source>
        <translation>caída a las %1 hasta %2: sin recuperar en esta ventana</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/analysis/measurementreport.cpp" line="70"/>
        <source>… %n more recovery(s)</source>
        <translation>
            <numerusform>… %n recuperación más</numerusform>
            <numerusform>… %n recuperaciones más</numerusform>
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
        <translation>%1: sin muestras en esta ventana</translation>
    </message>
</context>
<context>
    <name>MqttClient</name>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="240"/>
        <source>The broker %1 refused the message: %2.</source>
        <translation>El broker %1 rechazó el mensaje: %2.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="293"/>
        <source>&apos;%1&apos; is not a topic a message can be published to.</source>
        <translation>«%1» no es un tema en el que se pueda publicar un mensaje.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="295"/>
        <location filename="../lib/mqtt/mqttclient.cpp" line="322"/>
        <source>QoS %1 does not exist; MQTT has 0, 1 and 2.</source>
        <translation>QoS %1 no existe; MQTT tiene 0, 1 y 2.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="298"/>
        <source>Not connected to the broker %1: the message to %2 is dropped.</source>
        <translation>Sin conexión con el broker %1: se descarta el mensaje a %2.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="302"/>
        <source>%1 messages wait to be taken by the broker %2: the message to %3 is dropped.</source>
        <translation>%1 mensajes esperan a que el broker %2 los acepte: se descarta el mensaje a %3.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="312"/>
        <source>The message to %1 was not sent: %2</source>
        <translation>No se envió el mensaje a %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="320"/>
        <source>&apos;%1&apos; is not a valid subscription filter.</source>
        <translation>«%1» no es un filtro de suscripción válido.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="331"/>
        <source>The subscription to %1 was not sent: %2</source>
        <translation>No se envió la suscripción a %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="338"/>
        <source>There is no subscription to %1.</source>
        <translation>No hay ninguna suscripción a %1.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="346"/>
        <source>The subscription to %1 was not ended: %2</source>
        <translation>No se terminó la suscripción a %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="27"/>
        <source>The broker %1 refused the connection: bad user name or password.</source>
        <translation>El broker %1 rechazó la conexión: nombre de usuario o contraseña incorrectos.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="33"/>
        <source>The broker %1 refused the connection: not authorised (wrong user name or password, or this user may not connect).</source>
        <translation>El broker %1 rechazó la conexión: no autorizado (nombre de usuario o contraseña incorrectos, o este usuario no puede conectarse).</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="41"/>
        <source>The broker %1 refused the connection: %2.</source>
        <translation>El broker %1 rechazó la conexión: %2.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="47"/>
        <source>it does not speak MQTT 3.1.1</source>
        <translation>no habla MQTT 3.1.1</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="49"/>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="71"/>
        <source>it does not accept this client id</source>
        <translation>no acepta este identificador de cliente</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="51"/>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="74"/>
        <source>the service is unavailable</source>
        <translation>el servicio no está disponible</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="57"/>
        <source>return code %1</source>
        <translation>código de retorno %1</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="69"/>
        <source>it does not speak MQTT 5</source>
        <translation>no habla MQTT 5</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="76"/>
        <source>reason code %1</source>
        <translation>código de motivo %1</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="85"/>
        <source>No MQTT broker accepts connections at %1 (connection refused).</source>
        <translation>Ningún broker MQTT acepta conexiones en %1 (conexión rechazada).</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="90"/>
        <source>The broker %1 closed the connection (%2).</source>
        <translation>El broker %1 cerró la conexión (%2).</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="93"/>
        <source>The broker %1 cannot be reached: %2.</source>
        <translation>No se puede llegar al broker %1: %2.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="114"/>
        <source>The broker&apos;s address %1 cannot be resolved.</source>
        <translation>No se puede resolver la dirección %1 del broker.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="118"/>
        <source>The TLS handshake with the broker %1 failed.</source>
        <translation>Falló el establecimiento de TLS con el broker %1.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="119"/>
        <source>The TLS handshake with the broker %1 failed: %2</source>
        <translation>Falló el establecimiento de TLS con el broker %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="123"/>
        <source>The broker %1 stopped answering within the keep-alive time.</source>
        <translation>El broker %1 dejó de responder dentro del tiempo de keep-alive.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="128"/>
        <source>The connection to the broker %1 was lost.</source>
        <translation>Se perdió la conexión con el broker %1.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="132"/>
        <source>The broker %1 sent data that is not valid MQTT.</source>
        <translation>El broker %1 envió datos que no son MQTT válido.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="135"/>
        <source>The connection to the broker %1 failed: %2.</source>
        <translation>Falló la conexión con el broker %1: %2.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="143"/>
        <source>The broker %1 cannot be reached: the connection was refused or reset.</source>
        <translation>No se puede llegar al broker %1: la conexión fue rechazada o restablecida.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttproblem.cpp" line="150"/>
        <source>The broker&apos;s host name %1 cannot be resolved: %2</source>
        <translation>No se puede resolver el nombre de host %1 del broker: %2</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="59"/>
        <source>A password is set but no user name: MQTT sends a password only with a user name.</source>
        <translation>Hay una contraseña pero ningún nombre de usuario: MQTT solo envía una contraseña con un nombre de usuario.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="66"/>
        <source>The user name %1 is not accepted: %2</source>
        <translation>No se acepta el nombre de usuario %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="78"/>
        <source>The last will on %1 is not accepted: %2</source>
        <translation>No se acepta la última voluntad en %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="116"/>
        <source>The CA certificate file %1 cannot be read.</source>
        <translation>No se puede leer el archivo de certificado de la CA %1.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="122"/>
        <source>A client certificate needs both its certificate file and its key file.</source>
        <translation>Un certificado de cliente necesita tanto su archivo de certificado como su archivo de clave.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="126"/>
        <source>The file %1 cannot be read.</source>
        <translation>No se puede leer el archivo %1.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="97"/>
        <source>TLS cannot be set up: %1</source>
        <translation>No se puede configurar TLS: %1</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="105"/>
        <source>The MQTT version cannot be set: %1</source>
        <translation>No se puede fijar la versión de MQTT: %1</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="118"/>
        <source>The CA certificate file %1 holds no PEM certificate (-----BEGIN CERTIFICATE-----).</source>
        <translation>El archivo de certificado de CA %1 no contiene ningún certificado PEM (-----BEGIN CERTIFICATE-----).</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="148"/>
        <source>The client id %1 is not accepted.</source>
        <translation>No se acepta el identificador de cliente %1.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsetup.cpp" line="149"/>
        <source>Out of memory for an MQTT client.</source>
        <translation>Sin memoria para un cliente MQTT.</translation>
    </message>
</context>
<context>
    <name>MqttSecret</name>
    <message>
        <location filename="../lib/mqtt/mqttsecret.cpp" line="34"/>
        <source>The password file %1 does not exist.</source>
        <translation>El archivo de contraseña %1 no existe.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsecret.cpp" line="37"/>
        <source>The password file %1 is larger than %2 bytes; is it the right file?</source>
        <translation>El archivo de contraseña %1 tiene más de %2 bytes; ¿es el archivo correcto?</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsecret.cpp" line="42"/>
        <source>The password file %1 cannot be read: %2</source>
        <translation>No se puede leer el archivo de contraseña %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsecret.cpp" line="46"/>
        <source>The password file %1 is empty.</source>
        <translation>El archivo de contraseña %1 está vacío.</translation>
    </message>
    <message>
        <location filename="../lib/mqtt/mqttsecret.cpp" line="54"/>
        <source>The environment variable %1 that should hold the password is not set or empty.</source>
        <translation>La variable de entorno %1, que debería contener la contraseña, no está definida o está vacía.</translation>
    </message>
</context>
<context>
    <name>Parameter</name>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="62"/>
        <source>read-only</source>
        <translation>solo lectura</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="67"/>
        <source>%1 to %2</source>
        <translation>de %1 a %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="71"/>
        <source> in steps of %1 %2</source>
        <translation> en pasos de %1 %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="78"/>
        <source>, or %1</source>
        <translation>, o %1</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="84"/>
        <location filename="../lib/model/device/parameter.cpp" line="120"/>
        <source>%1 cannot be written</source>
        <translation>%1 no se puede escribir</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="93"/>
        <source>%1 is not allowed for %2: allowed is %3</source>
        <translation>%1 no está permitido para %2: se permite %3</translation>
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
        <translation>el modo solo supervisión está activado: no se escribe nada</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="123"/>
        <source>%1: %2; allowed is %3</source>
        <translation>%1: %2; se permite %3</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="183"/>
        <source>reading %1 (%2)</source>
        <translation>leyendo %1 (%2)</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="196"/>
        <source>reading %1</source>
        <translation>leyendo %1</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="197"/>
        <source>unreadable data field &apos;%1&apos;</source>
        <translation>campo de datos ilegible &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="255"/>
        <source>not written: %1</source>
        <translation>no escrito: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="258"/>
        <source>perhaps not written, the answer was lost: %1</source>
        <translation>quizá no escrito, se perdió la respuesta: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="280"/>
        <source>written, but the read-back failed: %1</source>
        <translation>escrito, pero la relectura falló: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="287"/>
        <source>the device reports %1 after %2 was written</source>
        <translation>el equipo indica %1 tras escribir %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="300"/>
        <source>%1 set to %2</source>
        <translation>%1 ajustado a %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/parameter.cpp" line="318"/>
        <source>writing %1</source>
        <translation>escribiendo %1</translation>
    </message>
</context>
<context>
    <name>PortDiagnostics</name>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="40"/>
        <source>this program</source>
        <translation>este programa</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="41"/>
        <source>, this program</source>
        <translation>, este programa</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="51"/>
        <source>run `sudo usermod -aG %1 $USER`, then log out and back in.</source>
        <translation>ejecute `sudo usermod -aG %1 $USER` y después cierre la sesión y vuelva a iniciarla.</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="53"/>
        <source>You are not allowed to open %1: %2</source>
        <translation>No tiene permiso para abrir %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="56"/>
        <source>You are not allowed to open %1, and it belongs to group root rather than dialout, so joining a group will not help until a udev rule gives it GROUP=&quot;dialout&quot;. Then %2</source>
        <translation>No tiene permiso para abrir %1, y pertenece al grupo root en lugar de dialout, así que unirse a un grupo no servirá hasta que una regla de udev le asigne GROUP=&quot;dialout&quot;. Después, %2</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="61"/>
        <source>You are not allowed to open %1, which belongs to group %2 (not dialout): %3</source>
        <translation>No tiene permiso para abrir %1, que pertenece al grupo %2 (no a dialout): %3</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="102"/>
        <source>There is no such port in %1: a port&apos;s name is never %2 characters long. The port name may be mistyped.</source>
        <translation>No existe ese puerto en %1: el nombre de un puerto nunca tiene %2 caracteres. Puede que el nombre del puerto esté mal escrito.</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="112"/>
        <source>%1 is busy: it is held by %2. Close that connection, then try again.</source>
        <translation>%1 está ocupado: lo tiene abierto %2. Cierre esa conexión e inténtelo de nuevo.</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="118"/>
        <source>There is no such port: %1. The adapter may be unplugged, or the port name may be mistyped.</source>
        <translation>No existe el puerto %1. Puede que el adaptador esté desenchufado o que el nombre del puerto esté mal escrito.</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="124"/>
        <source>%1 is already open in TipScope; close that connection first</source>
        <translation>%1 ya está abierto en TipScope; cierre primero esa conexión</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="129"/>
        <source>%1 stopped working, perhaps because the adapter was unplugged</source>
        <translation>%1 dejó de funcionar, quizá porque se desenchufó el adaptador</translation>
    </message>
    <message>
        <location filename="../lib/link/ports/portdiagnostics.cpp" line="133"/>
        <source>Could not open %1</source>
        <translation>No se pudo abrir %1</translation>
    </message>
</context>
<context>
    <name>PortModel</name>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="29"/>
        <source>Working</source>
        <translation>Trabajando</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="31"/>
        <source>Stand</source>
        <translation>En soporte</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="33"/>
        <source>Sleep</source>
        <translation>Reposo</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="35"/>
        <source>Hibernation</source>
        <translation>Hibernación</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="43"/>
        <source>Cooling</source>
        <translation>Enfriando</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="45"/>
        <source>Suction</source>
        <translation>Succión</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="47"/>
        <source>Motor forward</source>
        <translation>Motor adelante</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="49"/>
        <source>Motor backward</source>
        <translation>Motor atrás</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="71"/>
        <source>the tip went above the high alarm limit: if the selected temperature was just lowered, wait for the tip to cool; check that the tip suits the tool and the high alarm limit (Settings, Alarms)</source>
        <translation>la punta superó el límite de alarma alto: si se acaba de bajar la temperatura seleccionada, espere a que la punta se enfríe; compruebe que la punta corresponde a la herramienta y el límite de alarma alto (Ajustes, Alarmas)</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="76"/>
        <source>the tip fell below the low alarm limit: the joint may draw more heat than the tip gives (a larger tip), the tip may be worn or not tinned; check the low alarm limit (Settings, Alarms)</source>
        <translation>la punta bajó del límite de alarma bajo: la soldadura puede pedir más calor del que da la punta (una punta mayor), o la punta puede estar gastada o sin estañar; compruebe el límite de alarma bajo (Ajustes, Alarmas)</translation>
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
        <translation>Temperatura alta</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="62"/>
        <source>Low temperature</source>
        <translation>Temperatura baja</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="63"/>
        <source>None</source>
        <translation>Ninguna</translation>
    </message>
    <message>
        <location filename="../lib/model/device/portmodel.cpp" line="198"/>
        <source>this port has no %1 command</source>
        <translation>este puerto no tiene el comando %1</translation>
    </message>
</context>
<context>
    <name>ProblemLevel</name>
    <message>
        <location filename="../lib/model/events/problemlevel.cpp" line="44"/>
        <source>Not read yet</source>
        <translation>Aún no leído</translation>
    </message>
    <message>
        <location filename="../lib/model/events/problemlevel.cpp" line="46"/>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location filename="../lib/model/events/problemlevel.cpp" line="48"/>
        <source>Info</source>
        <translation>Información</translation>
    </message>
    <message>
        <location filename="../lib/model/events/problemlevel.cpp" line="50"/>
        <source>Warning</source>
        <translation>Advertencia</translation>
    </message>
    <message>
        <location filename="../lib/model/events/problemlevel.cpp" line="52"/>
        <source>Error</source>
        <translation>Error</translation>
    </message>
</context>
<context>
    <name>Profile</name>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="113"/>
        <source>%1: not a setting of a %2</source>
        <translation>%1: no es un ajuste de %2</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="118"/>
        <source>%1: &apos;%2&apos; is not a valid data field</source>
        <translation>%1: &apos;%2&apos; no es un campo de datos válido</translation>
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
        <translation>%1 bytes; un perfil tiene como máximo %2</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="145"/>
        <source>not a valid JSON file: %1 at byte %2</source>
        <translation>no es un archivo JSON válido: %1 en el byte %2</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="158"/>
        <source>not a TipScope profile (no &quot;format&quot;: &quot;tipscope-profile&quot;)</source>
        <translation>no es un perfil de TipScope (falta &quot;format&quot;: &quot;tipscope-profile&quot;)</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="169"/>
        <source>unknown device family &apos;%1&apos;</source>
        <translation>familia de equipo desconocida &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="177"/>
        <source>the profile has no values</source>
        <translation>el perfil no tiene valores</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="184"/>
        <source>%1: the value must be a data field in quotes, e.g. &quot;00350&quot;</source>
        <translation>%1: el valor debe ser un campo de datos entre comillas, p. ej. &quot;00350&quot;</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="199"/>
        <source>the profile is refused, nothing will be written:
%1</source>
        <translation>el perfil se rechaza, no se escribirá nada:
%1</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="211"/>
        <source>cannot read %1: %2</source>
        <translation>no se puede leer %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="216"/>
        <source>%1 is %2</source>
        <translation>%1 tiene %2</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="236"/>
        <source>unknown</source>
        <translation>desconocido</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="141"/>
        <source>not a valid JSON file: %1</source>
        <translation>no es un archivo JSON válido: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="152"/>
        <source>given more than once, so which value is meant is unclear: %1; nothing will be written</source>
        <translation>indicado más de una vez, así que no está claro qué valor se quiere: %1; no se escribirá nada</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profilejson.cpp" line="129"/>
        <source>a NUL byte at byte %1</source>
        <translation>un byte NUL en el byte %1</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profilejson.cpp" line="130"/>
        <source>control character 0x%1 at byte %2</source>
        <translation>carácter de control 0x%1 en el byte %2</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="161"/>
        <source>profile schema %1 is not supported (this version reads schemas %2 to %3)</source>
        <translation>el esquema de perfil %1 no es compatible (esta versión lee los esquemas %2 a %3)</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profile.cpp" line="188"/>
        <source>%1: the value must be a data field in quotes, e.g. &quot;00350&quot;, or an object with one in &quot;raw&quot; (and text in &quot;name&quot; and &quot;value&quot;)</source>
        <translation>%1: el valor debe ser un campo de datos entre comillas, p. ej. &quot;00350&quot;, o un objeto con uno en &quot;raw&quot; (y texto en &quot;name&quot; y &quot;value&quot;)</translation>
    </message>
</context>
<context>
    <name>ProfileApplier</name>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="33"/>
        <source>refused, nothing was written: %1</source>
        <translation>rechazado, no se escribió nada: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="37"/>
        <source>%1 %2: %3 → %4</source>
        <translation>%1 %2: %3 → %4</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="40"/>
        <source>changed %1 %2: %3 → %4</source>
        <translation>cambiado %1 %2: %3 → %4</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="42"/>
        <source>FAILED %1 %2: %3</source>
        <translation>FALLÓ %1 %2: %3</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="45"/>
        <source>would send %1</source>
        <translation>se enviaría %1</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="50"/>
        <source>cancelled: the remaining values were not written</source>
        <translation>cancelado: los valores restantes no se escribieron</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/profiles/profileapplier.cpp" line="61"/>
        <source>%n difference(s)</source>
        <translation>
            <numerusform>%n diferencia</numerusform>
            <numerusform>%n diferencias</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="62"/>
        <source>%1 would change, %2 already right</source>
        <translation>%1 cambiarían, %2 ya correctos</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="65"/>
        <source>%1 changed, %2 already right, %3 failed</source>
        <translation>%1 cambiados, %2 ya correctos, %3 fallidos</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="113"/>
        <source>the profile is for a %1, this device is a %2 (force to apply the settings they share)</source>
        <translation>el perfil es para %1 y este equipo es %2 (fuerce la aplicación para escribir los ajustes que comparten)</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="118"/>
        <source>monitor-only mode is on</source>
        <translation>el modo solo supervisión está activado</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="179"/>
        <source>reading the device</source>
        <translation>leyendo el equipo</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="241"/>
        <source>writing %1</source>
        <translation>escribiendo %1</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="244"/>
        <source>unreadable value</source>
        <translation>valor ilegible</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="303"/>
        <source>profile %1 applied: %2 changed, %3 failed, %4 already right%5</source>
        <translation>perfil %1 aplicado: %2 cambiados, %3 fallidos, %4 ya correctos%5</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="308"/>
        <source> (cancelled)</source>
        <translation> (cancelado)</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="85"/>
        <source>the profile would break the limits that bound its settings (MIT ≤ MAT, MIT ≤ selected temperature ≤ MAT):
%1</source>
        <translation>el perfil rompería los límites de sus ajustes (MIT ≤ MAT, MIT ≤ temperatura seleccionada ≤ MAT):
%1</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="106"/>
        <source>none of the profile&apos;s settings exists on this %1 (skipped: %2)</source>
        <translation>ninguno de los ajustes del perfil existe en este %1 (omitidos: %2)</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/profiles/profileapplier.cpp" line="53"/>
        <source>%n skipped</source>
        <translation>
            <numerusform>%n omitido</numerusform>
            <numerusform>%n omitidos</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="134"/>
        <source>this %1 has no such setting</source>
        <translation>este %1 no tiene ese ajuste</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profileapplier.cpp" line="47"/>
        <source>skipped %1 %2: %3</source>
        <translation>omitido %1 %2: %3</translation>
    </message>
</context>
<context>
    <name>ProfileLimits</name>
    <message>
        <location filename="../lib/model/profiles/profilelimits.cpp" line="64"/>
        <source>in the profile</source>
        <translation>en el perfil</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profilelimits.cpp" line="65"/>
        <source>on the device now</source>
        <translation>ahora en el equipo</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profilelimits.cpp" line="66"/>
        <source>%1 %2 (%3)</source>
        <translation>%1 %2 (%3)</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profilelimits.cpp" line="84"/>
        <source>%1 is not known (the device did not answer), so %2 cannot be checked against it</source>
        <translation>%1 es desconocido (el equipo no respondió), así que %2 no se puede comprobar con él</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profilelimits.cpp" line="92"/>
        <source>%1 is above %2</source>
        <translation>%1 está por encima de %2</translation>
    </message>
</context>
<context>
    <name>ProfileRequest</name>
    <message>
        <location filename="../lib/model/profiles/profilerequest.cpp" line="37"/>
        <source>&quot;request_id&quot; must be text of at most %1 characters, without control characters</source>
        <translation>&quot;request_id&quot; debe ser un texto de como máximo %1 caracteres, sin caracteres de control</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profilerequest.cpp" line="53"/>
        <source>the request is %1; nothing will be written</source>
        <translation>la solicitud tiene %1; no se escribirá nada</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profilerequest.cpp" line="72"/>
        <source>given more than once, so which one is meant is unclear: %1; nothing will be written</source>
        <translation>indicado más de una vez, así que no está claro cuál se quiere decir: %1; no se escribirá nada</translation>
    </message>
    <message>
        <location filename="../lib/model/profiles/profilerequest.cpp" line="79"/>
        <source>&quot;profile&quot; must be a profile: an object as tipscope-cli profile save writes it</source>
        <translation>&quot;profile&quot; debe ser un perfil: un objeto como lo escribe tipscope-cli profile save</translation>
    </message>
</context>
<context>
    <name>RecordingPlayback</name>
    <message>
        <location filename="../lib/model/recording/recordingplayback.cpp" line="38"/>
        <source>the recording %1 cannot be played: %2</source>
        <translation>la grabación %1 no se puede reproducir: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/recordingplayback.cpp" line="60"/>
        <source>the recording %1 holds no station port to play</source>
        <translation>la grabación %1 no contiene ningún puerto de estación que reproducir</translation>
    </message>
    <message>
        <location filename="../lib/model/recording/recordingplayback.cpp" line="67"/>
        <source>playing the recording %1</source>
        <translation>reproduciendo la grabación %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/recording/recordingplayback.cpp" line="105"/>
        <source>the recording %1 played: %n sample(s)</source>
        <translation>
            <numerusform>la grabación %1 se ha reproducido: %n muestra</numerusform>
            <numerusform>la grabación %1 se ha reproducido: %n muestras</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RemoteApply</name>
    <message>
        <location filename="../lib/plant/remoteapply.cpp" line="76"/>
        <source>a retained command is not carried out: it would run again at every reconnect</source>
        <translation>una orden retenida (retained) no se ejecuta: se repetiría en cada reconexión</translation>
    </message>
    <message>
        <location filename="../lib/plant/remoteapply.cpp" line="79"/>
        <source>remote profile apply is off in this agent&apos;s configuration</source>
        <translation>la aplicación remota de perfiles está desactivada en la configuración de este agente</translation>
    </message>
    <message>
        <location filename="../lib/plant/remoteapply.cpp" line="83"/>
        <source>publish the command under your user name: %1/%2/USER</source>
        <translation>publique la orden bajo su nombre de usuario: %1/%2/USUARIO</translation>
    </message>
    <message>
        <location filename="../lib/plant/remoteapply.cpp" line="89"/>
        <source>no device of this agent is published at %1</source>
        <translation>este agente no publica ningún dispositivo en %1</translation>
    </message>
    <message>
        <location filename="../lib/plant/remoteapply.cpp" line="92"/>
        <source>another profile is being applied to this device</source>
        <translation>ya se está aplicando otro perfil a este dispositivo</translation>
    </message>
    <message>
        <location filename="../lib/plant/remoteapply.cpp" line="95"/>
        <source>profile refused: %1</source>
        <translation>perfil rechazado: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/plant/remoteapply.cpp" line="125"/>
        <source>%n setting(s) not taken</source>
        <translation>
            <numerusform>%n ajuste no aceptado</numerusform>
            <numerusform>%n ajustes no aceptados</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../lib/plant/remoteapply.cpp" line="154"/>
        <source>Profile applied through MQTT for %1</source>
        <translation>Perfil aplicado por MQTT para %1</translation>
    </message>
    <message>
        <location filename="../lib/plant/remoteapply.cpp" line="155"/>
        <source>Profile through MQTT for %1 not applied: %2</source>
        <translation>Perfil por MQTT para %1 no aplicado: %2</translation>
    </message>
    <message>
        <location filename="../lib/plant/remoteapply.cpp" line="156"/>
        <source>an unnamed client</source>
        <translation>un cliente sin nombre</translation>
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
        <translation>Alimentando</translation>
    </message>
    <message>
        <location filename="../lib/plant/remotetile.cpp" line="49"/>
        <source>Not feeding</source>
        <translation>Sin alimentar</translation>
    </message>
    <message>
        <location filename="../lib/plant/remotetile.cpp" line="54"/>
        <source>%1 · fed %2</source>
        <translation>%1 · alimentado %2</translation>
    </message>
    <message>
        <location filename="../lib/plant/remotetile.cpp" line="64"/>
        <source>Port %1 alarm: %2</source>
        <translation>Puerto %1 alarma: %2</translation>
    </message>
    <message>
        <location filename="../lib/plant/remotetile.cpp" line="65"/>
        <source>Port %1: %2</source>
        <translation>Puerto %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/plant/remotetile.cpp" line="80"/>
        <source>Agent offline</source>
        <translation>Agente desconectado</translation>
    </message>
    <message>
        <location filename="../lib/plant/remotetile.cpp" line="84"/>
        <source>Agent offline since %1</source>
        <translation>Agente desconectado desde las %1</translation>
    </message>
    <message>
        <location filename="../lib/plant/remotetile.cpp" line="85"/>
        <source>Agent offline since %1 %2</source>
        <translation>Agente desconectado desde el %1 a las %2</translation>
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
        <translation>%1 es un adaptador FTDI con un temporizador de latencia de %2 ms (el valor por defecto del kernel es 16 ms), que retiene cada respuesta corta y frena el tráfico de peticiones y respuestas.
Ajústelo ahora a 1 ms con:
  echo 1 | sudo tee /sys/bus/usb-serial/devices/%1/latency_timer
Hágalo permanente con esta regla de udev:
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
        <translation>desconectado</translation>
    </message>
    <message>
        <location filename="../lib/model/session.cpp" line="90"/>
        <source>reading the recording %1</source>
        <translation>leyendo la grabación %1</translation>
    </message>
    <message>
        <location filename="../lib/model/session.cpp" line="128"/>
        <location filename="../lib/model/session.cpp" line="141"/>
        <location filename="../lib/model/session.cpp" line="149"/>
        <source>line</source>
        <translation>línea</translation>
    </message>
    <message>
        <location filename="../lib/model/session.cpp" line="165"/>
        <source>looking for devices on %1</source>
        <translation>buscando equipos en %1</translation>
    </message>
    <message>
        <location filename="../lib/model/session.cpp" line="216"/>
        <source>found %1, software %2</source>
        <translation>se encontró %1, software %2</translation>
    </message>
    <message>
        <location filename="../lib/model/session.cpp" line="217"/>
        <source>unknown</source>
        <translation>desconocido</translation>
    </message>
    <message>
        <location filename="../lib/model/session.cpp" line="228"/>
        <source>connected to %1, but no device could be identified; what came back: %2 (robot mode off? wrong addressing or baud rate?)</source>
        <translation>conectado a %1, pero no se pudo identificar ningún equipo; lo que volvió: %2 (¿modo robot desactivado? ¿direccionamiento o velocidad en baudios incorrectos?)</translation>
    </message>
    <message>
        <location filename="../lib/model/session.cpp" line="233"/>
        <source>connected to %1, but no device answered (robot mode off? wrong addressing or baud rate?)</source>
        <translation>conectado a %1, pero ningún equipo respondió (¿modo robot desactivado? ¿direccionamiento o velocidad en baudios incorrectos?)</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/session.cpp" line="241"/>
        <source>%1, %n device(s)</source>
        <translation>
            <numerusform>%1, %n equipo</numerusform>
            <numerusform>%1, %n equipos</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../lib/model/session.cpp" line="223"/>
        <source>connected to %1, but %2</source>
        <translation>conectado a %1, pero %2</translation>
    </message>
</context>
<context>
    <name>SettingName</name>
    <message>
        <location filename="../lib/model/device/settingname.cpp" line="22"/>
        <source>tool %1</source>
        <translation>herramienta %1</translation>
    </message>
    <message>
        <location filename="../lib/model/device/settingname.cpp" line="33"/>
        <source>port %1</source>
        <translation>puerto %1</translation>
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
        <translation>%1 no admite %2</translation>
    </message>
    <message>
        <location filename="../lib/model/device/stationmodel.cpp" line="88"/>
        <source>%1 cannot save to memory</source>
        <translation>%1 no puede guardar en memoria</translation>
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
        <translation>error borrado</translation>
    </message>
</context>
<context>
    <name>SupportReport</name>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="176"/>
        <source>TipScope support report, %1</source>
        <translation>Informe de soporte de TipScope, %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="178"/>
        <source>TipScope %1, Qt %2, %3</source>
        <translation>TipScope %1, Qt %2, %3</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="117"/>
        <source>Line: %1</source>
        <translation>Línea: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="118"/>
        <source>State: %1</source>
        <translation>Estado: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="119"/>
        <source>Statistics: %1</source>
        <translation>Estadísticas: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="168"/>
        <source>Workspace line %1</source>
        <translation>Línea %1 del espacio de trabajo</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="169"/>
        <source>Workspace line %1 (%2)</source>
        <translation>Línea %1 del espacio de trabajo (%2)</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="192"/>
        <source>Recent events of %1:</source>
        <translation>Eventos recientes de %1:</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="201"/>
        <source>Recent events:</source>
        <translation>Eventos recientes:</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="32"/>
        <source>Device %1</source>
        <translation>Equipo %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="37"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="39"/>
        <source>, software %1</source>
        <translation>, software %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="46"/>
        <source>Joints of the last 24 hours: not read: %1</source>
        <translation>Soldaduras de las últimas 24 horas: no leídas: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="48"/>
        <source>Joints from %1 to %2:</source>
        <translation>Soldaduras de %1 a %2:</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="53"/>
        <source>  none</source>
        <translation>  ninguna</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="60"/>
        <source>  %1, port %2: %3 joints: %4 ok, %5 slow recovery, %6 too deep, %7 incomplete</source>
        <translation>  %1, puerto %2: %3 soldaduras: %4 correctas, %5 recuperación lenta, %6 demasiado profundas, %7 incompletas</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="68"/>
        <source>; recovery median %1 ms, 95th percentile %2 ms</source>
        <translation>; recuperación mediana %1 ms, percentil 95 %2 ms</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="81"/>
        <source>Journal: %1</source>
        <translation>Diario: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="83"/>
        <source>yes</source>
        <translation>sí</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="84"/>
        <source>no</source>
        <translation>no</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="86"/>
        <source>not yet, opening</source>
        <translation>todavía no, abriéndose</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="87"/>
        <source>no, closed</source>
        <translation>no, cerrado</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="89"/>
        <source>  writing: %1</source>
        <translation>  escribe: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="90"/>
        <source>  writing: %1: %2</source>
        <translation>  escribe: %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="92"/>
        <source>  lost: %1 records (%2)</source>
        <translation>  perdidos: %1 registros (%2)</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="95"/>
        <source>  not read: %1</source>
        <translation>  no leído: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="98"/>
        <source>  %1 joints and %2 events, %3 and %4 of them not yet published; %5 waiting in memory</source>
        <translation>  %1 soldaduras y %2 eventos, de ellos %3 y %4 aún sin publicar; %5 esperando en memoria</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="104"/>
        <source>  from %1 to %2</source>
        <translation>  de %1 a %2</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="107"/>
        <source>  kept without a time limit; %1 bytes on disk</source>
        <translation>  conservado sin límite de tiempo; %1 bytes en disco</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="109"/>
        <source>  kept for %1 days; %2 bytes on disk</source>
        <translation>  conservado %1 días; %2 bytes en disco</translation>
    </message>
    <message>
        <location filename="../lib/model/report/supportreporttext.cpp" line="135"/>
        <source>  What to check:</source>
        <translation>  Qué comprobar:</translation>
    </message>
</context>
<context>
    <name>TipWear</name>
    <message>
        <location filename="../lib/model/joints/tipwear.cpp" line="70"/>
        <source>tip wearing: %1 recovers in %2 s (median of the last %3 joints), %4 s when it was plugged in</source>
        <translation>punta desgastándose: %1 se recupera en %2 s (mediana de las últimas %3 soldaduras), %4 s al conectarla</translation>
    </message>
    <message>
        <location filename="../lib/model/joints/tipwear.cpp" line="73"/>
        <source>the tool</source>
        <translation>la herramienta</translation>
    </message>
</context>
<context>
    <name>ValueCodec</name>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="43"/>
        <source>%1 to %2%3</source>
        <translation>de %1 a %2%3</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="47"/>
        <source> in steps of %1</source>
        <translation> en pasos de %1</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="49"/>
        <source>, or %1</source>
        <translation>, o %1</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="57"/>
        <source>one of %1</source>
        <translation>uno de %1</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="60"/>
        <source>no value (the command carries %1)</source>
        <translation>ningún valor (el comando lleva %1)</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="64"/>
        <source>nothing: it is read-only</source>
        <translation>nada: es de solo lectura</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="79"/>
        <location filename="../lib/protocol/valuecodec.cpp" line="85"/>
        <source>%1 cannot be written</source>
        <translation>%1 no se puede escribir</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="70"/>
        <source>%1 refused for %2 (%3): allowed is %4</source>
        <translation>%1 rechazado para %2 (%3): se permite %4</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="108"/>
        <source>&apos;%1&apos; is no data field of %2 (%3): allowed is %4</source>
        <translation>&apos;%1&apos; no es un campo de datos de %2 (%3): se permite %4</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="193"/>
        <source>&apos;%1&apos; is not a delay in seconds such as 1.6 or 01.60</source>
        <translation>&apos;%1&apos; no es un retardo en segundos como 1.6 o 01.60</translation>
    </message>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="198"/>
        <source>&apos;%1&apos; is not a whole number; %2 takes %3</source>
        <translation>&apos;%1&apos; no es un número entero; %2 admite %3</translation>
    </message>
</context>
<context>
    <name>WorkContextFile</name>
    <message>
        <location filename="../lib/journal/workcontextfile.cpp" line="40"/>
        <source>cannot read the work context %1: %2</source>
        <translation>no se puede leer el contexto de trabajo %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/journal/workcontextfile.cpp" line="44"/>
        <source>the work context %1 is too big to be one</source>
        <translation>el contexto de trabajo %1 es demasiado grande para serlo</translation>
    </message>
    <message>
        <location filename="../lib/journal/workcontextfile.cpp" line="46"/>
        <source>the work context %1 is not a JSON object: %2</source>
        <translation>el contexto de trabajo %1 no es un objeto JSON: %2</translation>
    </message>
    <message>
        <location filename="../lib/journal/workcontextfile.cpp" line="52"/>
        <source>the work context %1: %2</source>
        <translation>el contexto de trabajo %1: %2</translation>
    </message>
</context>
<context>
    <name>WorkContextJson</name>
    <message>
        <location filename="../lib/model/context/workcontextjson.cpp" line="20"/>
        <source>%1 has %2 characters; at most %3 are kept</source>
        <translation>%1 tiene %2 caracteres; se guardan como máximo %3</translation>
    </message>
    <message>
        <location filename="../lib/model/context/workcontextjson.cpp" line="27"/>
        <source>%1 holds a control character (%2) at character %3</source>
        <translation>%1 contiene un carácter de control (%2) en el carácter %3</translation>
    </message>
    <message>
        <location filename="../lib/model/context/workcontextjson.cpp" line="53"/>
        <source>%1 must be text</source>
        <translation>%1 debe ser texto</translation>
    </message>
</context>
<context>
    <name>WorkspaceFile</name>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="31"/>
        <source>not a TipScope workspace (&quot;format&quot; is not &quot;%1&quot;)</source>
        <translation>no es un espacio de trabajo de TipScope (&quot;format&quot; no es &quot;%1&quot;)</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="36"/>
        <source>&quot;version&quot; must be a whole number from 1</source>
        <translation>&quot;version&quot; debe ser un número entero desde 1</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="38"/>
        <source>written by a later TipScope (workspace version %1); this one reads version %2 and older</source>
        <translation>escrito por un TipScope posterior (versión de espacio de trabajo %1); este lee la versión %2 y anteriores</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="67"/>
        <source>&quot;lines&quot; must be a list of lines</source>
        <translation>&quot;lines&quot; debe ser una lista de líneas</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="75"/>
        <source>line %1</source>
        <translation>línea %1</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="76"/>
        <source>line %1 (%2)</source>
        <translation>línea %1 (%2)</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="78"/>
        <source>%1: must be an object</source>
        <translation>%1: debe ser un objeto</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="83"/>
        <source>%1: the name is already another line&apos;s; each line needs its own</source>
        <translation>%1: el nombre ya es de otra línea; cada línea necesita el suyo</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="100"/>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="103"/>
        <source>cannot read the workspace %1: %2</source>
        <translation>no se puede leer el espacio de trabajo %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="101"/>
        <source>there is no such file</source>
        <translation>no existe ese archivo</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="106"/>
        <source>the workspace %1 is too big to be one</source>
        <translation>el espacio de trabajo %1 es demasiado grande para ser uno</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="108"/>
        <source>the workspace %1 is not a JSON object: %2</source>
        <translation>el espacio de trabajo %1 no es un objeto JSON: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacefile.cpp" line="110"/>
        <source>it is a list</source>
        <translation>es una lista</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="49"/>
        <source>%1 must be text</source>
        <translation>%1 debe ser texto</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="57"/>
        <source>%1 must be a whole number from %2 to %3</source>
        <translation>%1 debe ser un número entero de %2 a %3</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="65"/>
        <source>%1 must be true or false</source>
        <translation>%1 debe ser true o false</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="74"/>
        <source>%1 must be one of %2</source>
        <translation>%1 debe ser uno de %2</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="80"/>
        <source>%1 must be an object</source>
        <translation>%1 debe ser un objeto</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="103"/>
        <source>%1 must name the recording file</source>
        <translation>%1 debe indicar el archivo de la grabación</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="112"/>
        <source>%1 must name the serial port</source>
        <translation>%1 debe nombrar el puerto serie</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="125"/>
        <source>%1 must be HOST:PORT (for example 192.168.1.20:4001)</source>
        <translation>%1 debe ser HOST:PUERTO (por ejemplo 192.168.1.20:4001)</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="157"/>
        <source>devices must be a list</source>
        <translation>devices debe ser una lista</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="163"/>
        <source>devices[%1] must be an object</source>
        <translation>devices[%1] debe ser un objeto</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="167"/>
        <source>%1 must be an address from 0 to 99, or null for the device without addresses</source>
        <translation>%1 debe ser una dirección de 0 a 99, o null para el dispositivo sin direcciones</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="175"/>
        <source>%1 must not be empty</source>
        <translation>%1 no debe estar vacío</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="180"/>
        <source>devices[%1] names a device named before</source>
        <translation>devices[%1] nombra un dispositivo ya nombrado</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="243"/>
        <source>every line needs a name</source>
        <translation>cada línea necesita un nombre</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspacelinejson.cpp" line="250"/>
        <source>connection is missing</source>
        <translation>falta connection</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="46"/>
        <source>Configure and monitor JBC soldering stations and the SFR feeder.</source>
        <translation>Configure y supervise estaciones de soldadura JBC y el alimentador SFR.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="52"/>
        <source>Start on the built-in simulated DME station and SFR feeder.</source>
        <translation>Iniciar con la estación DME y el alimentador SFR simulados integrados.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="55"/>
        <source>Connect to this serial port.</source>
        <translation>Conectar a este puerto serie.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="58"/>
        <source>Connect to a TCP serial server.</source>
        <translation>Conectar a un servidor serie TCP.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="62"/>
        <source>Open the lines of this workspace file.</source>
        <translation>Abrir las líneas de este archivo de espacio de trabajo.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="66"/>
        <source>Save a PNG of every page into DIR, then quit.</source>
        <translation>Guardar un PNG de cada página en DIR y salir.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="70"/>
        <source>Watch the devices published to this MQTT broker on the fleet overview.</source>
        <translation>Seguir en la vista de la flota los dispositivos publicados en este broker MQTT.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="75"/>
        <source>With --plant: only this site&apos;s devices.</source>
        <translation>Con --plant: solo los dispositivos de esta planta.</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="80"/>
        <source>tipscope: there is no display (neither DISPLAY nor WAYLAND_DISPLAY is set); start it on a desktop, or use tipscope-cli</source>
        <translation>tipscope: no hay pantalla (no están definidas DISPLAY ni WAYLAND_DISPLAY); inícielo en un escritorio, o use tipscope-cli</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="109"/>
        <source>tipscope: %1</source>
        <translation>tipscope: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/main.cpp" line="121"/>
        <source>tipscope: --plant takes the broker as HOST:PORT</source>
        <translation>tipscope: --plant espera el broker como HOST:PUERTO</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::BoardReportDialog</name>
    <message>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="26"/>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="130"/>
        <source>Board report</source>
        <translation>Informe de placa</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="35"/>
        <source>Every joint the journal keeps for the board, its result, its tools&apos; wear and the events while it was made, as a PDF to sign.</source>
        <translation>Cada soldadura que el diario guarda de la placa, su resultado, el desgaste de sus puntas y los eventos mientras se fabricaba, como PDF para firmar.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="41"/>
        <source>Board serial:</source>
        <translation>Número de serie de la placa:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="44"/>
        <source>Write PDF…</source>
        <translation>Escribir PDF…</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="61"/>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="125"/>
        <source>Give the serial of a board.</source>
        <translation>Indique el número de serie de una placa.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="82"/>
        <source>Reading the journal for board %1…</source>
        <translation>Leyendo el diario para la placa %1…</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="95"/>
        <source>The journal has no board %1: no joint or event carries that serial.</source>
        <translation>El diario no tiene la placa %1: ninguna soldadura ni evento lleva ese número de serie.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/boardreportdialog.cpp" line="132"/>
        <source>PDF documents (*.pdf)</source>
        <translation>Documentos PDF (*.pdf)</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ChartPlotView</name>
    <message>
        <location filename="../app/gui/charts/chartplotview.cpp" line="46"/>
        <source>Time chart. Wheel or plus and minus keys zoom, drag or arrow keys pan, Shift+drag selects a range, double-click or Home resets.</source>
        <translation>Gráfico temporal. La rueda o las teclas más y menos hacen zoom, arrastrar o las flechas desplazan, Mayús+arrastrar selecciona un intervalo, doble clic o Inicio restablece.</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ChartWidget</name>
    <message numerus="yes">
        <location filename="../app/gui/charts/chartwidget.cpp" line="508"/>
        <source>… and %n more</source>
        <translation>
            <numerusform>… y %n más</numerusform>
            <numerusform>… y %n más</numerusform>
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
        <translation>Gráficos</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="106"/>
        <source>Values under the cursor</source>
        <translation>Valores bajo el cursor</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="128"/>
        <source>&amp;Measurements</source>
        <translation>&amp;Mediciones</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="132"/>
        <source>Heat-ups, recoveries and min/max/mean of the visible window</source>
        <translation>Calentamientos, recuperaciones y mín./máx./media de la ventana visible</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="137"/>
        <source>Heat-up and recovery &amp;band ±</source>
        <translation>&amp;Banda de calentamiento y recuperación ±</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="140"/>
        <source>Tolerance band around the setpoint</source>
        <translation>Banda de tolerancia alrededor de la consigna</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="153"/>
        <source>Measurements of the visible window</source>
        <translation>Mediciones de la ventana visible</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="195"/>
        <source>Point at a chart to read every series at that instant.</source>
        <translation>Señale un gráfico para leer todas las series en ese instante.</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="196"/>
        <source>Wheel: zoom · drag: pan · Shift+drag: zoom to a range · double-click: reset.</source>
        <translation>Rueda: zoom · arrastrar: desplazar · Mayús+arrastrar: zoom a un intervalo · doble clic: restablecer.</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="175"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="178"/>
        <source>%1 at %2</source>
        <translation>%1, dirección %2</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="181"/>
        <source>%1 — feeder</source>
        <translation>%1 — alimentador</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="185"/>
        <source>%1 — all ports</source>
        <translation>%1 — todos los puertos</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="186"/>
        <source>%1 — %2 %3</source>
        <translation>%1 — %2 %3</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="189"/>
        <source>Temperature (%1)</source>
        <translation>Temperatura (%1)</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="190"/>
        <source>Power (%)</source>
        <translation>Potencia (%)</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="190"/>
        <source>%</source>
        <translation>%</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspage.cpp" line="301"/>
        <source>No samples in this window</source>
        <translation>No hay muestras en esta ventana</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="49"/>
        <source>device</source>
        <translation>equipo</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="51"/>
        <source>%1 · %2 · %3: %4</source>
        <translation>%1 · %2 · %3: %4</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="64"/>
        <source>&amp;Window</source>
        <translation>&amp;Ventana</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="69"/>
        <source>Time window</source>
        <translation>Ventana de tiempo</translation>
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
        <translation>Segu&amp;ir</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="87"/>
        <source>Keep the newest data at the right edge; uncheck to pause</source>
        <translation>Mantener los datos más recientes en el borde derecho; desmarque para pausar</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="90"/>
        <source>&amp;Reset view</source>
        <translation>&amp;Restablecer vista</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="94"/>
        <source>Pane layout</source>
        <translation>Disposición de los paneles</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="95"/>
        <source>Ports overlaid</source>
        <translation>Puertos superpuestos</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="96"/>
        <source>One pane per port</source>
        <translation>Un panel por puerto</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="100"/>
        <source>Trans&amp;istor, transformer</source>
        <translation>Trans&amp;istor, transformador</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="102"/>
        <source>Also draw each port&apos;s transistor temperature and the station&apos;s transformer temperature (read every few seconds)</source>
        <translation>Dibujar también la temperatura del transistor de cada puerto y la del transformador de la estación (leídas cada pocos segundos)</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="106"/>
        <source>&amp;Export</source>
        <translation>E&amp;xportar</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="109"/>
        <source>Visible window as &amp;PNG…</source>
        <translation>Ventana visible como &amp;PNG…</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="110"/>
        <source>Visible window as &amp;CSV…</source>
        <translation>Ventana visible como &amp;CSV…</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="112"/>
        <source>Re&amp;cord…</source>
        <translation>&amp;Grabar…</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="114"/>
        <source>Write every new sample and event to a CSV file until unchecked</source>
        <translation>Escribir cada nueva muestra y evento en un archivo CSV hasta desmarcarlo</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="116"/>
        <source>&amp;Open recording…</source>
        <translation>Abrir grabació&amp;n…</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="118"/>
        <source>Back to &amp;live</source>
        <translation>Volver a &amp;tiempo real</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="123"/>
        <source>Data shown</source>
        <translation>Datos mostrados</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="126"/>
        <source>Recording stopped</source>
        <translation>Grabación detenida</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="127"/>
        <source>Writing %1 failed: %2</source>
        <translation>Falló la escritura de %1: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="78"/>
        <source>P%1</source>
        <translation>P%1</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="94"/>
        <source>High alarm</source>
        <translation>Alarma alta</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageoverlays.cpp" line="97"/>
        <source>Low alarm</source>
        <translation>Alarma baja</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/charts/chartspageactions.cpp" line="158"/>
        <source>Replay: %1 (%Ln row(s))</source>
        <translation>
            <numerusform>Reproducción: %1 (%Ln fila)</numerusform>
            <numerusform>Reproducción: %1 (%Ln filas)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="160"/>
        <source>Live</source>
        <translation>Tiempo real</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="176"/>
        <source> · recording to %1</source>
        <translation> · grabando en %1</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="57"/>
        <source>there is no chart to export</source>
        <translation>no hay ningún gráfico que exportar</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="48"/>
        <source>%1 – %2 (%3)</source>
        <translation>%1 – %2 (%3)</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="111"/>
        <source>the image could not be encoded</source>
        <translation>no se pudo generar la imagen</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="135"/>
        <source>%1 × %2 (twice the charts on screen)</source>
        <translation>%1 × %2 (el doble de los gráficos en pantalla)</translation>
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
        <translation>Exportar gráfico como PNG</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="139"/>
        <source>Image size in pixels:</source>
        <translation>Tamaño de la imagen en píxeles:</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="151"/>
        <source>Export chart data as CSV</source>
        <translation>Exportar datos del gráfico como CSV</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="153"/>
        <source>PNG image (*.png)</source>
        <translation>Imagen PNG (*.png)</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="166"/>
        <source>The file holds every sample from %1 on. The chart&apos;s older history is kept only as min and max per few seconds, which a file of samples cannot hold.</source>
        <translation>El archivo contiene cada muestra a partir de %1. El historial más antiguo del gráfico solo se guarda como mínimo y máximo cada pocos segundos, y eso no cabe en un archivo de muestras.</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="207"/>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="153"/>
        <source>CSV file (*.csv)</source>
        <translation>Archivo CSV (*.csv)</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="162"/>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="165"/>
        <source>Export</source>
        <translation>Exportar</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageexport.cpp" line="162"/>
        <source>Export failed: %1</source>
        <translation>Falló la exportación: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="206"/>
        <source>Record to CSV file</source>
        <translation>Grabar en un archivo CSV</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="210"/>
        <source>Record</source>
        <translation>Grabar</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspageactions.cpp" line="210"/>
        <source>Cannot record: %1</source>
        <translation>No se puede grabar: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspagereplay.cpp" line="54"/>
        <source>Open recording</source>
        <translation>Abrir grabación</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspagereplay.cpp" line="64"/>
        <source>Reading %1: %2 MB</source>
        <translation>Leyendo %1: %2 MB</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspagereplay.cpp" line="71"/>
        <source>Reading %1…</source>
        <translation>Leyendo %1…</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspagereplay.cpp" line="118"/>
        <source>The charts hold no readings of %1 at %2: only this session&apos;s readings are kept.</source>
        <translation>Los gráficos no tienen lecturas de %1 a las %2: solo se guardan las lecturas de esta sesión.</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspagereplay.cpp" line="128"/>
        <source>Open a chart recording</source>
        <translation>Abrir una grabación de gráficos</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspagereplay.cpp" line="128"/>
        <source>CSV file (*.csv);;All files (*)</source>
        <translation>Archivo CSV (*.csv);;Todos los archivos (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspagereplay.cpp" line="135"/>
        <source>Replay</source>
        <translation>Reproducción</translation>
    </message>
    <message>
        <location filename="../app/gui/charts/chartspagereplay.cpp" line="135"/>
        <source>Cannot replay %1</source>
        <translation>No se puede reproducir %1</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ConnectionBar</name>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="35"/>
        <location filename="../app/gui/connectionbar.cpp" line="42"/>
        <source>Serial port</source>
        <translation>Puerto serie</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="36"/>
        <location filename="../app/gui/connectionbar.cpp" line="46"/>
        <source>TCP serial server</source>
        <translation>Servidor serie TCP</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="37"/>
        <source>Demo (simulated DME + SFR)</source>
        <translation>Demo (DME + SFR simulados)</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="38"/>
        <source>Connection type</source>
        <translation>Tipo de conexión</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="43"/>
        <source>Serial ports on this computer; you may also type a device path</source>
        <translation>Puertos serie de este ordenador; también puede escribir la ruta de un dispositivo</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="45"/>
        <source>host:port</source>
        <translation>host:puerto</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="50"/>
        <source>Baud rate</source>
        <translation>Velocidad en baudios</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="52"/>
        <source>no parity</source>
        <translation>sin paridad</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="53"/>
        <source>even</source>
        <translation>par</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="54"/>
        <source>odd</source>
        <translation>impar</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="56"/>
        <source>1 stop bit</source>
        <translation>1 bit de parada</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="57"/>
        <source>2 stop bits</source>
        <translation>2 bits de parada</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="59"/>
        <source>Find devices</source>
        <translation>Buscar equipos</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="60"/>
        <source>With addresses</source>
        <translation>Con direcciones</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="61"/>
        <source>Without addresses</source>
        <translation>Sin direcciones</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="62"/>
        <source>Addressing</source>
        <translation>Direccionamiento</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="65"/>
        <source>robot </source>
        <translation>robot </translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="66"/>
        <source>Robot address</source>
        <translation>Dirección del robot</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="69"/>
        <source>device </source>
        <translation>equipo </translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="70"/>
        <source>Device address</source>
        <translation>Dirección del equipo</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="71"/>
        <location filename="../app/gui/connectionbar.cpp" line="186"/>
        <source>&amp;Connect</source>
        <translation>&amp;Conectar</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="72"/>
        <source>&amp;Monitor only</source>
        <translation>Solo &amp;supervisión</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="73"/>
        <source>Block every write: watch a production line without risk</source>
        <translation>Bloquea toda escritura: supervise una línea de producción sin riesgo</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="105"/>
        <source>disconnected</source>
        <translation>desconectado</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="186"/>
        <source>&amp;Disconnect</source>
        <translation>&amp;Desconectar</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="198"/>
        <source>Connected</source>
        <translation>Conectado</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="203"/>
        <source>Connecting</source>
        <translation>Conectando</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="203"/>
        <source>Detecting devices</source>
        <translation>Detectando equipos</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="207"/>
        <source>Disconnected, retrying</source>
        <translation>Desconectado, reintentando</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="211"/>
        <source>Cannot connect</source>
        <translation>No se puede conectar</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="214"/>
        <source>Disconnected</source>
        <translation>Desconectado</translation>
    </message>
    <message>
        <location filename="../app/gui/connectionbar.cpp" line="219"/>
        <source> (this bar&apos;s line only: %1)</source>
        <translation> (solo la línea de esta barra: %1)</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ConsolePage</name>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="89"/>
        <source>Console tools</source>
        <translation>Herramientas de la consola</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="98"/>
        <source>Older rows go as new ones come; Save… writes the rows kept to a file. While paused, new rows are held; they appear on resume.</source>
        <translation>Las filas antiguas se descartan a medida que llegan otras nuevas; Guardar… escribe en un archivo las filas conservadas. En pausa, las filas nuevas se retienen; aparecen al reanudar.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="139"/>
        <location filename="../app/gui/pages/consolepage.cpp" line="341"/>
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="144"/>
        <source>Hold new rows (Ctrl+P); nothing is lost, they appear on resume</source>
        <translation>Retener las filas nuevas (Ctrl+P); no se pierde nada, aparecen al reanudar</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="148"/>
        <source>Relative time</source>
        <translation>Tiempo relativo</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="151"/>
        <source>Show seconds since the first row instead of the clock time</source>
        <translation>Mostrar los segundos desde la primera fila en lugar de la hora</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="166"/>
        <source>Show:</source>
        <translation>Mostrar:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="167"/>
        <source>TX</source>
        <translation>TX</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="167"/>
        <source>Show bytes sent</source>
        <translation>Mostrar los bytes enviados</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="170"/>
        <source>RX chunks</source>
        <translation>Bloques RX</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="171"/>
        <source>Show bytes as the driver delivered them, chunk by chunk (every received byte is also in a frame or error row)</source>
        <translation>Mostrar los bytes tal como los entregó el controlador, bloque a bloque (cada byte recibido también está en una fila de trama o de error)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="174"/>
        <source>Frames</source>
        <translation>Tramas</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="174"/>
        <source>Show received frames, decoded</source>
        <translation>Mostrar las tramas recibidas, decodificadas</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="176"/>
        <source>Errors</source>
        <translation>Errores</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="176"/>
        <source>Show decode errors (BCC, format, garbage)</source>
        <translation>Mostrar los errores de decodificación (BCC, formato, basura)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="177"/>
        <source>Notes</source>
        <translation>Notas</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="177"/>
        <source>Show line notes (timeouts, line state)</source>
        <translation>Mostrar las notas de la línea (tiempos agotados, estado de la línea)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="180"/>
        <source>De&amp;vice:</source>
        <translation>Equi&amp;po:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="183"/>
        <source>Device address filter</source>
        <translation>Filtro de dirección de equipo</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="184"/>
        <source>Only frames from or to this address; type any address 00-99</source>
        <translation>Solo tramas desde o hacia esta dirección; escriba cualquier dirección 00-99</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="193"/>
        <source>Co&amp;mmand:</source>
        <translation>Co&amp;mando:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="196"/>
        <source>Command filter</source>
        <translation>Filtro de comando</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="197"/>
        <source>e.g. ST1</source>
        <translation>p. ej. ST1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="207"/>
        <source>Clear</source>
        <translation>Borrar</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="209"/>
        <source>Remove every row, held ones included</source>
        <translation>Quitar todas las filas, incluidas las retenidas</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="210"/>
        <source>Save…</source>
        <translation>Guardar…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="212"/>
        <source>Save every row (not only the shown ones) to a text file</source>
        <translation>Guardar todas las filas (no solo las mostradas) en un archivo de texto</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="218"/>
        <source>Traffic on the line</source>
        <translation>Tráfico en la línea</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="264"/>
        <source>bad</source>
        <translation>erróneo</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="278"/>
        <source>Copy rows</source>
        <translation>Copiar filas</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="292"/>
        <location filename="../app/gui/pages/consolepage.cpp" line="302"/>
        <location filename="../app/gui/pages/consolepage.cpp" line="320"/>
        <source>All</source>
        <translation>Todos</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="341"/>
        <source>Resume</source>
        <translation>Reanudar</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="354"/>
        <location filename="../app/gui/pages/consolepage.cpp" line="359"/>
        <source>Save console</source>
        <translation>Guardar la consola</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="355"/>
        <source>Text files (*.txt);;All files (*)</source>
        <translation>Archivos de texto (*.txt);;Todos los archivos (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="378"/>
        <source>%1 of %2 rows shown; the newest %3 are kept</source>
        <translation>%1 de %2 filas mostradas; se conservan las %3 más recientes</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pages/consolepage.cpp" line="383"/>
        <source>paused: %n held</source>
        <translation>
            <numerusform>en pausa: %n retenida</numerusform>
            <numerusform>en pausa: %n retenidas</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.h" line="62"/>
        <source>Console</source>
        <translation>Consola</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/consolepage.cpp" line="360"/>
        <source>The console could not be saved:
%1</source>
        <translation>No se pudo guardar la consola:
%1</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::CountersPage</name>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="73"/>
        <source>When the counters were read</source>
        <translation>Cuándo se leyeron los contadores</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="75"/>
        <source>Result of the last action</source>
        <translation>Resultado de la última acción</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="77"/>
        <source>Re&amp;fresh</source>
        <translation>Ac&amp;tualizar</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="78"/>
        <source>Read every counter of every device now (they are otherwise read once a minute)</source>
        <translation>Leer ahora todos los contadores de todos los equipos (si no, se leen una vez por minuto)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="80"/>
        <source>Refresh counters</source>
        <translation>Actualizar contadores</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="82"/>
        <source>&amp;Export CSV…</source>
        <translation>E&amp;xportar CSV…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="83"/>
        <source>Save every counter of every device as a CSV file</source>
        <translation>Guardar todos los contadores de todos los equipos en un archivo CSV</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="84"/>
        <source>Export counters as CSV</source>
        <translation>Exportar contadores como CSV</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="94"/>
        <source>No device is connected. Connect to a line to read its counters.</source>
        <translation>No hay ningún equipo conectado. Conéctese a una línea para leer sus contadores.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="146"/>
        <source>Reading the counters…</source>
        <translation>Leyendo los contadores…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="149"/>
        <source>Last reading at %1</source>
        <translation>Última lectura a las %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="151"/>
        <source>Waiting for the first reading…</source>
        <translation>Esperando la primera lectura…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="211"/>
        <source>Station %1</source>
        <translation>Estación %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="213"/>
        <location filename="../app/gui/pages/counterspage.cpp" line="244"/>
        <source>Counters of %1</source>
        <translation>Contadores de %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="229"/>
        <source>Port %1</source>
        <translation>Puerto %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="242"/>
        <source>Solder feeder %1</source>
        <translation>Alimentador de estaño %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="248"/>
        <source>Total</source>
        <translation>Total</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="248"/>
        <source>Partial</source>
        <translation>Parcial</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="290"/>
        <source>%1 (R-%2)</source>
        <translation>%1 (R-%2)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="292"/>
        <source>Last read failed: %1</source>
        <translation>Falló la última lectura: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="295"/>
        <source>Read at %1</source>
        <translation>Leído: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="298"/>
        <source>Not read yet</source>
        <translation>Aún no leído</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="324"/>
        <source>%1 Monitor-only mode is on: nothing is reset.</source>
        <translation>%1 El modo solo supervisión está activado: no se pone nada a cero.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="327"/>
        <source>Reset partial counter</source>
        <translation>Poner a cero el contador parcial</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="328"/>
        <source>Reset “%1” on %2?</source>
        <translation>¿Poner a cero «%1» en %2?</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="330"/>
        <source>It now reads %1.</source>
        <translation>Ahora marca %1.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="332"/>
        <source>The total counter is not affected.</source>
        <translation>El contador total no se ve afectado.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="333"/>
        <source>Reset counter</source>
        <translation>Poner a cero</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="338"/>
        <source>%1 Nothing was reset.</source>
        <translation>%1 No se puso nada a cero.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="344"/>
        <source>%1 Not reset: %2</source>
        <translation>%1 No se puso a cero: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="347"/>
        <source>%1 Resetting %2…</source>
        <translation>%1 Poniendo a cero %2…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="353"/>
        <source>%1 %2 reset.</source>
        <translation>%1 %2 puesto a cero.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="354"/>
        <source>%1 %2 was not reset: %3</source>
        <translation>%1 %2 no se puso a cero: %3</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="367"/>
        <source>Monitor-only mode is on: TipScope writes nothing to the devices. Turn it off to reset counters.</source>
        <translation>El modo solo supervisión está activado: TipScope no escribe nada en los equipos. Desactívelo para poner a cero los contadores.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="387"/>
        <location filename="../app/gui/pages/counterspage.cpp" line="393"/>
        <source>Export counters</source>
        <translation>Exportar contadores</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="387"/>
        <source>CSV files (*.csv)</source>
        <translation>Archivos CSV (*.csv)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="391"/>
        <source>%1 Counters saved to %2</source>
        <translation>%1 Contadores guardados en %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.cpp" line="394"/>
        <source>The counters could not be saved: %1</source>
        <translation>No se pudieron guardar los contadores: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/counterspage.h" line="44"/>
        <source>Counters</source>
        <translation>Contadores</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::DeviceTree</name>
    <message>
        <location filename="../app/gui/devicetree.cpp" line="24"/>
        <source>Devices</source>
        <translation>Equipos</translation>
    </message>
    <message>
        <location filename="../app/gui/devicetree.cpp" line="121"/>
        <source>Fleet overview</source>
        <translation>Vista de la flota</translation>
    </message>
    <message>
        <location filename="../app/gui/devicetree.cpp" line="187"/>
        <source>recording %1</source>
        <translation>grabación %1</translation>
    </message>
    <message>
        <location filename="../app/gui/devicetree.cpp" line="188"/>
        <source>No line</source>
        <translation>Sin línea</translation>
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
        <translation>alimentador</translation>
    </message>
    <message>
        <location filename="../app/gui/devicetree.cpp" line="203"/>
        <source>station</source>
        <translation>estación</translation>
    </message>
    <message>
        <location filename="../app/gui/devicetree.cpp" line="209"/>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location filename="../app/gui/devicetree.cpp" line="214"/>
        <source>Port %1: %2</source>
        <translation>Puerto %1: %2</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::DispensingPage</name>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="47"/>
        <source>Only the ALE has a built-in wire feed.</source>
        <translation>Solo la ALE tiene alimentación de hilo integrada.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="57"/>
        <source>&amp;Start dispensing</source>
        <translation>&amp;Iniciar dispensado</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="58"/>
        <source>S&amp;top dispensing</source>
        <translation>De&amp;tener dispensado</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="59"/>
        <source>Ignore fuse error…</source>
        <translation>Ignorar error de fusible…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="65"/>
        <source>

Continue?</source>
        <translation>

¿Continuar?</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="77"/>
        <source>Wire feed settings</source>
        <translation>Ajustes de alimentación de hilo</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="87"/>
        <source>&amp;Apply</source>
        <translation>A&amp;plicar</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="112"/>
        <source>%1 · dispensed %2 in %3 cycles · %4</source>
        <translation>%1 · dispensado %2 en %3 ciclos · %4</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="116"/>
        <source>fuse unknown</source>
        <translation>fusible desconocido</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="117"/>
        <source>fuse present</source>
        <translation>fusible presente</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="118"/>
        <source>fuse missing or blown</source>
        <translation>fusible ausente o fundido</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="124"/>
        <location filename="../app/gui/pages/dispensingpage.cpp" line="132"/>
        <source>no ALE</source>
        <translation>sin ALE</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/dispensingpage.h" line="21"/>
        <source>Dispensing</source>
        <translation>Dispensado</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ErrorStatePanel</name>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="62"/>
        <source>%1, port %2</source>
        <translation>%1, puerto %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="80"/>
        <source>Current state</source>
        <translation>Estado actual</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="84"/>
        <source>Current errors and alarms</source>
        <translation>Errores y alarmas actuales</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="86"/>
        <source>Where</source>
        <translation>Dónde</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="86"/>
        <source>Tool</source>
        <translation>Herramienta</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="86"/>
        <source>Severity</source>
        <translation>Gravedad</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="86"/>
        <source>Error</source>
        <translation>Error</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="86"/>
        <source>Temperature alarm</source>
        <translation>Alarma de temperatura</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="97"/>
        <source>&amp;Reset feeder error</source>
        <translation>&amp;Borrar error del alimentador</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="99"/>
        <source>Reset feeder error</source>
        <translation>Borrar error del alimentador</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="101"/>
        <source>Result of the last action</source>
        <translation>Resultado de la última acción</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="160"/>
        <source>No device is connected.</source>
        <translation>No hay ningún equipo conectado.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="191"/>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="196"/>
        <source>Not read yet</source>
        <translation>Aún no leído</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="193"/>
        <source>Error code %1: %2</source>
        <translation>Código de error %1: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="207"/>
        <source>This device has no temperature alarm</source>
        <translation>Este equipo no tiene alarma de temperatura</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="216"/>
        <source>%1, %2 alarm: %3</source>
        <translation>%1, alarma «%2»: %3</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="243"/>
        <source>Not reset: %1</source>
        <translation>No se borró: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="246"/>
        <source>Resetting the feeder error…</source>
        <translation>Borrando el error del alimentador…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="253"/>
        <source>Feeder error reset.</source>
        <translation>Error del alimentador borrado.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="254"/>
        <source>The feeder error was not reset: %1</source>
        <translation>El error del alimentador no se borró: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="267"/>
        <source>Monitor-only mode is on: TipScope writes nothing to the devices. Turn it off to reset the feeder error.</source>
        <translation>El modo solo supervisión está activado: TipScope no escribe nada en los equipos. Desactívelo para borrar el error del alimentador.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="270"/>
        <source>No feeder is connected</source>
        <translation>No hay ningún alimentador conectado</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="273"/>
        <source>Clears the feeder&apos;s error code (W-ECV); the feeder does not feed while an error is set</source>
        <translation>Borra el código de error del alimentador (W-ECV); el alimentador no alimenta mientras haya un error</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="108"/>
        <source>What to check</source>
        <translation>Qué comprobar</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="213"/>
        <source>%1, %2: %3</source>
        <translation>%1, %2: %3</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/errorstatepanel.cpp" line="232"/>
        <source>What to check:</source>
        <translation>Qué comprobar:</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ErrorsPage</name>
    <message>
        <location filename="../app/gui/pages/errorspage.h" line="20"/>
        <source>Errors</source>
        <translation>Errores</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::EventHistoryPanel</name>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="48"/>
        <source>History</source>
        <translation>Historial</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="89"/>
        <source>Show events of kind</source>
        <translation>Mostrar eventos del tipo</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="90"/>
        <source>All kinds</source>
        <translation>Todos los tipos</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="91"/>
        <source>Errors and alarms</source>
        <translation>Errores y alarmas</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="93"/>
        <source>Station errors</source>
        <translation>Errores de estación</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="94"/>
        <source>Port errors</source>
        <translation>Errores de puerto</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="95"/>
        <source>Feeder errors</source>
        <translation>Errores del alimentador</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="96"/>
        <source>Alarms</source>
        <translation>Alarmas</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="97"/>
        <source>Status changes</source>
        <translation>Cambios de estado</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="98"/>
        <source>Writes</source>
        <translation>Escrituras</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="99"/>
        <source>Communication</source>
        <translation>Comunicación</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="100"/>
        <source>Connection</source>
        <translation>Conexión</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="101"/>
        <source>Tool changes</source>
        <translation>Cambios de herramienta</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="102"/>
        <source>Joints</source>
        <translation>Soldaduras</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="103"/>
        <source>Profile applies</source>
        <translation>Aplicaciones de perfil</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="108"/>
        <source>Show events of device</source>
        <translation>Mostrar eventos del equipo</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="109"/>
        <source>Every device</source>
        <translation>Todos los equipos</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="115"/>
        <source>Show events of severity</source>
        <translation>Mostrar eventos de la gravedad</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="116"/>
        <source>Any severity</source>
        <translation>Cualquier gravedad</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="117"/>
        <source>Warnings and errors</source>
        <translation>Advertencias y errores</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="118"/>
        <source>Errors only</source>
        <translation>Solo errores</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="121"/>
        <source>Show events containing</source>
        <translation>Mostrar eventos que contengan</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="122"/>
        <source>Text in any column</source>
        <translation>Texto en cualquier columna</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="124"/>
        <source>&amp;Device:</source>
        <translation>&amp;Equipo:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="126"/>
        <source>&amp;Kind:</source>
        <translation>&amp;Tipo:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="128"/>
        <source>Se&amp;verity:</source>
        <translation>&amp;Gravedad:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="130"/>
        <source>&amp;Search:</source>
        <translation>B&amp;uscar:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="164"/>
        <source>Event history</source>
        <translation>Historial de eventos</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="188"/>
        <source>Copy</source>
        <translation>Copiar</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="194"/>
        <source>Events shown</source>
        <translation>Eventos mostrados</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="195"/>
        <source>&amp;Copy</source>
        <translation>Co&amp;piar</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="197"/>
        <source>Copy the selected events to the clipboard (Ctrl+C)</source>
        <translation>Copiar los eventos seleccionados al portapapeles (Ctrl+C)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="198"/>
        <source>Copy selected events</source>
        <translation>Copiar eventos seleccionados</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="199"/>
        <source>E&amp;xport…</source>
        <translation>E&amp;xportar…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="201"/>
        <source>Save the events shown as a tab-separated text file</source>
        <translation>Guardar los eventos mostrados como archivo de texto separado por tabulaciones</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="202"/>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="345"/>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="351"/>
        <source>Export events</source>
        <translation>Exportar eventos</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="204"/>
        <source>Result of the last export</source>
        <translation>Resultado de la última exportación</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="296"/>
        <source>%1 of %2 events shown</source>
        <translation>%1 de %2 eventos mostrados</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="298"/>
        <source>%n older events were dropped</source>
        <translation>
            <numerusform>se descartó %n evento antiguo</numerusform>
            <numerusform>se descartaron %n eventos antiguos</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="345"/>
        <source>Text files (*.txt *.tsv)</source>
        <translation>Archivos de texto (*.txt *.tsv)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="349"/>
        <source>Saved to %1</source>
        <translation>Guardado en %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/eventhistorypanel.cpp" line="352"/>
        <source>The events could not be saved: %1</source>
        <translation>No se pudieron guardar los eventos: %1</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::FeederPage</name>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="47"/>
        <source>No feeder on this line.</source>
        <translation>No hay alimentador en esta línea.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="71"/>
        <source>Feed &amp;forward</source>
        <translation>A&amp;vanzar hilo</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="71"/>
        <source>W-SFD 00001</source>
        <translation>W-SFD 00001</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="72"/>
        <source>Feed &amp;backward</source>
        <translation>Re&amp;troceder hilo</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="72"/>
        <source>W-SFD 00000</source>
        <translation>W-SFD 00000</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="73"/>
        <source>&amp;Stop</source>
        <translation>&amp;Parar</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="73"/>
        <source>W-SSD</source>
        <translation>W-SSD</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="74"/>
        <source>Start &amp;loading</source>
        <translation>Iniciar car&amp;ga</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="74"/>
        <source>W-SLD 00001: feed ignoring errors, for a new spool</source>
        <translation>W-SLD 00001: alimentar ignorando los errores, para una bobina nueva</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="76"/>
        <source>End loading</source>
        <translation>Terminar carga</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="76"/>
        <source>W-SLD 00000</source>
        <translation>W-SLD 00000</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="82"/>
        <source>&amp;Reset error</source>
        <translation>&amp;Borrar error</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="88"/>
        <source>Feeding settings</source>
        <translation>Ajustes de alimentación</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="99"/>
        <location filename="../app/gui/pages/feederpage.cpp" line="176"/>
        <source>&amp;Apply</source>
        <translation>Ap&amp;licar</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="100"/>
        <source>Re&amp;vert</source>
        <translation>&amp;Revertir</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="101"/>
        <source>Discard the values typed here and show the feeder&apos;s own</source>
        <translation>Descarta los valores escritos aquí y vuelve a mostrar los del alimentador</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="102"/>
        <source>Save to feeder memory</source>
        <translation>Guardar en la memoria del alimentador</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="103"/>
        <source>W-NVS: mode, speed and length survive a restart</source>
        <translation>W-NVS: el modo, la velocidad y la longitud se conservan tras reiniciar</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="117"/>
        <source>Counters</source>
        <translation>Contadores</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="125"/>
        <source>Reset</source>
        <translation>Poner a cero</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="150"/>
        <source>Feeding</source>
        <translation>Alimentando</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="150"/>
        <source>Idle</source>
        <translation>En espera</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="150"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="151"/>
        <source>%1 · fed %2</source>
        <translation>%1 · alimentado %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="153"/>
        <source>⚠ %1</source>
        <translation>⚠ %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="153"/>
        <source>No feeder error</source>
        <translation>Sin error del alimentador</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="163"/>
        <location filename="../app/gui/pages/feederpage.cpp" line="178"/>
        <source>Monitor-only mode is on: nothing is written</source>
        <translation>El modo solo supervisión está activado: no se escribe nada</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="176"/>
        <source>&amp;Apply (%1)</source>
        <translation>A&amp;plicar (%1)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="179"/>
        <source>A value typed is not allowed: correct it or Revert</source>
        <translation>Un valor escrito no está permitido: corríjalo o use Revertir</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="202"/>
        <location filename="../app/gui/pages/feederpage.cpp" line="208"/>
        <location filename="../app/gui/pages/feederpage.cpp" line="214"/>
        <location filename="../app/gui/pages/feederpage.cpp" line="220"/>
        <source>no feeder</source>
        <translation>sin alimentador</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="229"/>
        <source>no such counter</source>
        <translation>no existe ese contador</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="232"/>
        <source>

Reset it?</source>
        <translation>

¿Ponerlo a cero?</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.cpp" line="235"/>
        <source>cancelled</source>
        <translation>cancelado</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/feederpage.h" line="25"/>
        <source>Feeder</source>
        <translation>Alimentador</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::FleetPage</name>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="32"/>
        <source>Name</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="33"/>
        <source>Line</source>
        <translation>Línea</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="34"/>
        <source>State, worst first</source>
        <translation>Estado, el peor primero</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="35"/>
        <source>Sort by:</source>
        <translation>Ordenar por:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="37"/>
        <source>Needs attention only</source>
        <translation>Solo lo que requiere atención</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="131"/>
        <source>Devices: %1 · need attention: %2</source>
        <translation>Equipos: %1 · requieren atención: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="132"/>
        <source>%1 · lines without a device: %2</source>
        <translation>%1 · líneas sin equipo: %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="268"/>
        <source>No devices yet: nothing has come from the plant&apos;s broker.</source>
        <translation>Aún no hay dispositivos: no ha llegado nada del broker de la planta.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="269"/>
        <source>No devices: the workspace&apos;s lines have found none yet.</source>
        <translation>Sin equipos: las líneas del espacio de trabajo aún no han encontrado ninguno.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.cpp" line="267"/>
        <source>No device needs attention.</source>
        <translation>Ningún equipo requiere atención.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/fleetpage.h" line="58"/>
        <source>Fleet</source>
        <translation>Flota</translation>
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
        <translation>Última soldadura: %1 (puerto %2)</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::FrameBuilder</name>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="35"/>
        <source>Send a frame</source>
        <translation>Enviar una trama</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="62"/>
        <source>Device</source>
        <translation>Equipo</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="67"/>
        <source>Header</source>
        <translation>Cabecera</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="68"/>
        <source>R (read)</source>
        <translation>R (lectura)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="69"/>
        <source>W (write)</source>
        <translation>W (escritura)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="71"/>
        <source>Command</source>
        <translation>Comando</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="83"/>
        <source>Data field</source>
        <translation>Campo de datos</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="89"/>
        <source>&amp;Send frame</source>
        <translation>&amp;Enviar trama</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="90"/>
        <source>Send frame</source>
        <translation>Enviar trama</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="92"/>
        <source>Frame to be sent</source>
        <translation>Trama que se enviará</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="96"/>
        <source>Catalog check</source>
        <translation>Comprobación del catálogo</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="99"/>
        <source>Raw bytes in hex</source>
        <translation>Bytes en bruto en hexadecimal</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="103"/>
        <source>Send ra&amp;w hex</source>
        <translation>Enviar he&amp;x en bruto</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="104"/>
        <source>Send raw hex</source>
        <translation>Enviar hex en bruto</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="106"/>
        <source>Raw bytes check</source>
        <translation>Comprobación de los bytes en bruto</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="107"/>
        <source>Nothing sent yet.</source>
        <translation>Aún no se ha enviado nada.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="108"/>
        <source>Outcome of the last send</source>
        <translation>Resultado del último envío</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="117"/>
        <source>&amp;Device</source>
        <translation>E&amp;quipo</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="119"/>
        <source>&amp;Header</source>
        <translation>Ca&amp;becera</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="121"/>
        <source>C&amp;ommand</source>
        <translation>C&amp;omando</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="123"/>
        <source>D&amp;ata</source>
        <translation>Da&amp;tos</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="126"/>
        <source>Frame</source>
        <translation>Trama</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="129"/>
        <source>&amp;Raw hex</source>
        <translation>Hex en b&amp;ruto</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="133"/>
        <source>Last send</source>
        <translation>Último envío</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="242"/>
        <source>Send these bytes exactly as typed; the answer appears in the table.</source>
        <translation>Enviar estos bytes exactamente como se han escrito; la respuesta aparece en la tabla.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="213"/>
        <source>(nothing to send)</source>
        <translation>(nada que enviar)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="88"/>
        <location filename="../app/gui/pages/framebuilder.cpp" line="217"/>
        <source>none for reads</source>
        <translation>nada al leer</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="88"/>
        <location filename="../app/gui/pages/framebuilder.cpp" line="217"/>
        <source>e.g. 00350</source>
        <translation>p. ej. 00350</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="229"/>
        <source>Send this frame once, as shown (no retries; catalog warnings do not stop it). Its answer appears in the table.</source>
        <translation>Enviar esta trama una vez, tal como se muestra (sin reintentos; los avisos del catálogo no la detienen). Su respuesta aparece en la tabla.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/framebuilder.cpp" line="264"/>
        <source>Not sent: %1</source>
        <translation>No enviado: %1</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::JointLimitsDialog</name>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="42"/>
        <source>Joint limits</source>
        <translation>Límites de soldadura</translation>
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
        <translation>Puerto</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="63"/>
        <source>Tool</source>
        <translation>Herramienta</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="63"/>
        <source>Longest recovery (s)</source>
        <translation>Recuperación más larga (s)</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="64"/>
        <source>Deepest dip (K)</source>
        <translation>Caída más profunda (K)</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="64"/>
        <source>Tip wear (%)</source>
        <translation>Desgaste de la punta (%)</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="69"/>
        <source>Add rule</source>
        <translation>Añadir regla</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="70"/>
        <source>Remove rule</source>
        <translation>Quitar regla</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="82"/>
        <source>Longest recovery (back within 5 K of the setpoint):</source>
        <translation>Recuperación más larga (de vuelta a 5 K de la consigna):</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="83"/>
        <source>Deepest dip below the setpoint:</source>
        <translation>Caída más profunda bajo la consigna:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="84"/>
        <source>Tip wearing when recoveries are slower than when new by:</source>
        <translation>Punta desgastada cuando las recuperaciones son más lentas que en nuevo en:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="85"/>
        <source>Rules for a port, a tool or both override these; the most specific rule wins. An empty cell keeps the default.</source>
        <translation>Las reglas para un puerto, una herramienta o ambos prevalecen; gana la regla más concreta. Una celda vacía conserva el valor por defecto.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="116"/>
        <source>Any port</source>
        <translation>Cualquier puerto</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="118"/>
        <source>Port %1</source>
        <translation>Puerto %1</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/jointlimitsdialog.cpp" line="159"/>
        <source>Rule %1: %2</source>
        <translation>Regla %1: %2</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::JointsPage</name>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="98"/>
        <source>Double-click a joint, or press Enter, to see it on the Charts page</source>
        <translation>Doble clic en una soldadura, o Intro, para verla en la página Gráficos</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="138"/>
        <source>All devices</source>
        <translation>Todos los equipos</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="140"/>
        <source>All ports</source>
        <translation>Todos los puertos</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="142"/>
        <source>Port %1</source>
        <translation>Puerto %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="144"/>
        <source>all tools</source>
        <translation>todas las herramientas</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="147"/>
        <source>All verdicts</source>
        <translation>Todos los veredictos</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="151"/>
        <source>Last hour</source>
        <translation>Última hora</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="151"/>
        <source>Last 24 hours</source>
        <translation>Últimas 24 horas</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="151"/>
        <source>Last 7 days</source>
        <translation>Últimos 7 días</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="152"/>
        <source>Last 30 days</source>
        <translation>Últimos 30 días</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="152"/>
        <source>All times</source>
        <translation>Todo el tiempo</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="156"/>
        <source>all work orders</source>
        <translation>todas las órdenes</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="158"/>
        <source>Reload</source>
        <translation>Recargar</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="159"/>
        <source>Read the journal again</source>
        <translation>Volver a leer el registro</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="160"/>
        <source>Export CSV…</source>
        <translation>Exportar CSV…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="161"/>
        <source>Save the listed joints as a CSV file</source>
        <translation>Guardar las soldaduras de la lista como archivo CSV</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="164"/>
        <source>Device</source>
        <translation>Equipo</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="164"/>
        <source>Port</source>
        <translation>Puerto</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="165"/>
        <source>Tool</source>
        <translation>Herramienta</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="165"/>
        <source>Verdict</source>
        <translation>Veredicto</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="166"/>
        <source>Time</source>
        <translation>Hora</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="166"/>
        <source>Work order</source>
        <translation>Orden de trabajo</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pages/jointspage.cpp" line="272"/>
        <source>%n joint(s) listed.</source>
        <translation>
            <numerusform>%n soldadura en la lista.</numerusform>
            <numerusform>%n soldaduras en la lista.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="274"/>
        <source>Only the newest %1 from the journal: narrow the filter to see older ones.</source>
        <translation>Solo las %1 más recientes del registro: acote el filtro para ver las anteriores.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="278"/>
        <source>The journal could not be read (%1): only this session&apos;s joints are listed.</source>
        <translation>No se pudo leer el registro (%1): solo se listan las soldaduras de esta sesión.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="282"/>
        <source>No journal yet: this session&apos;s joints only.</source>
        <translation>Aún no hay registro: solo las soldaduras de esta sesión.</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pages/jointspage.cpp" line="362"/>
        <source>%n joint(s) written to %1.</source>
        <translation>
            <numerusform>%n soldadura escrita en %1.</numerusform>
            <numerusform>%n soldaduras escritas en %1.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="374"/>
        <source>Export joints</source>
        <translation>Exportar soldaduras</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.cpp" line="374"/>
        <source>CSV file (*.csv)</source>
        <translation>Archivo CSV (*.csv)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointspage.h" line="48"/>
        <source>Joints</source>
        <translation>Soldaduras</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::JournalStatusButton</name>
    <message>
        <location filename="../app/gui/journalstatusbutton.cpp" line="11"/>
        <source>No work order</source>
        <translation>Sin orden de trabajo</translation>
    </message>
    <message>
        <location filename="../app/gui/journalstatusbutton.cpp" line="26"/>
        <source>Work context and journal</source>
        <translation>Contexto de trabajo y diario</translation>
    </message>
    <message>
        <location filename="../app/gui/journalstatusbutton.cpp" line="47"/>
        <source>Stamped on every joint and event: %1. Click to change it.</source>
        <translation>Se registra con cada soldadura y cada evento: %1. Haga clic para cambiarlo.</translation>
    </message>
    <message>
        <location filename="../app/gui/journalstatusbutton.cpp" line="48"/>
        <source>Journal: %1</source>
        <translation>Diario: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/journalstatusbutton.cpp" line="51"/>
        <source>Journal not written</source>
        <translation>El diario no se escribe</translation>
    </message>
    <message>
        <location filename="../app/gui/journalstatusbutton.cpp" line="54"/>
        <source>%1 records wait to be written; polling goes on.</source>
        <translation>%1 registros esperan a ser escritos; el sondeo continúa.</translation>
    </message>
    <message>
        <location filename="../app/gui/journalstatusbutton.cpp" line="57"/>
        <source>%1 records lost</source>
        <translation>%1 registros perdidos</translation>
    </message>
    <message>
        <location filename="../app/gui/journalstatusbutton.cpp" line="61"/>
        <source>Work context unreadable</source>
        <translation>Contexto de trabajo ilegible</translation>
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
        <translation>Estadísticas de la línea</translation>
    </message>
    <message>
        <location filename="../app/gui/linkstatuslabel.cpp" line="27"/>
        <source>no line</source>
        <translation>sin línea</translation>
    </message>
    <message>
        <location filename="../app/gui/linkstatuslabel.cpp" line="33"/>
        <source>%L1 tx/s · %L2 ms · %3 timeouts · %4 BCC errors · %5 NAKs</source>
        <translation>%L1 tx/s · %L2 ms · %3 tiempos agotados · %4 errores BCC · %5 NAK</translation>
    </message>
    <message>
        <location filename="../app/gui/linkstatuslabel.cpp" line="41"/>
        <source>NAK %1 × %2: %3</source>
        <translation>NAK %1 × %2: %3</translation>
    </message>
    <message>
        <location filename="../app/gui/linkstatuslabel.cpp" line="46"/>
        <source>Reconnects: %1</source>
        <translation>Reconexiones: %1</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::MainWindow</name>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="63"/>
        <source>Connection</source>
        <translation>Conexión</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="139"/>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="143"/>
        <source>Work &amp;context…</source>
        <translation>&amp;Contexto de trabajo…</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="147"/>
        <source>Write &amp;support report…</source>
        <translation>Escribir &amp;informe de soporte…</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="148"/>
        <source>&amp;Board report…</source>
        <translation>Informe de &amp;placa…</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="156"/>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="157"/>
        <source>&amp;Tools</source>
        <translation>&amp;Herramientas</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="158"/>
        <source>&amp;Preferences…</source>
        <translation>&amp;Preferencias…</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="166"/>
        <source>&amp;Joint limits…</source>
        <translation>&amp;Límites de soldadura…</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="167"/>
        <source>&amp;Help</source>
        <translation>A&amp;yuda</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="168"/>
        <source>&amp;About TipScope</source>
        <translation>&amp;Acerca de TipScope</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="170"/>
        <source>About TipScope</source>
        <translation>Acerca de TipScope</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="171"/>
        <source>&lt;b&gt;TipScope %1&lt;/b&gt;&lt;p&gt;Configures and monitors JBC soldering control units (UCR, ALE, NAE, DDE, DME, HDE, DDR, HDR) and the SFR solder feeder over their RS-232 robot protocol.&lt;/p&gt;</source>
        <translation>&lt;b&gt;TipScope %1&lt;/b&gt;&lt;p&gt;Configura y supervisa unidades de control de soldadura JBC (UCR, ALE, NAE, DDE, DME, HDE, DDR, HDR) y el alimentador de estaño SFR mediante su protocolo de robot RS-232.&lt;/p&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="297"/>
        <source>new workspace</source>
        <translation>espacio de trabajo nuevo</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/mainwindow.cpp" line="299"/>
        <source>TipScope — %1 (%n line(s))</source>
        <translation>
            <numerusform>TipScope — %1 (%n línea)</numerusform>
            <numerusform>TipScope — %1 (%n líneas)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="302"/>
        <source>not connected</source>
        <translation>sin conexión</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="307"/>
        <source>TipScope — %1</source>
        <translation>TipScope — %1</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="312"/>
        <source>Folder for the support report</source>
        <translation>Carpeta para el informe de soporte</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="326"/>
        <location filename="../app/gui/mainwindow.cpp" line="329"/>
        <source>Support report</source>
        <translation>Informe de soporte</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="330"/>
        <source>Written:
%1

Attach both files to the support ticket.</source>
        <translation>Escrito:
%1

Adjunte ambos archivos a la solicitud de soporte.</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="343"/>
        <source>joint limits</source>
        <translation>límites de soldadura</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindow.cpp" line="344"/>
        <source>%1; the default limits judge joints</source>
        <translation>%1; los límites por defecto juzgan las soldaduras</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="31"/>
        <source>&amp;Open workspace…</source>
        <translation>&amp;Abrir espacio de trabajo…</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="33"/>
        <source>&amp;Save workspace</source>
        <translation>&amp;Guardar espacio de trabajo</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="35"/>
        <source>Save workspace &amp;as…</source>
        <translation>Guardar espacio de trabajo &amp;como…</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="37"/>
        <source>&amp;Add this line to the workspace…</source>
        <translation>Añadir esta &amp;línea al espacio de trabajo…</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="40"/>
        <source>C&amp;lose workspace</source>
        <translation>Ce&amp;rrar espacio de trabajo</translation>
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
        <translation>El último espacio de trabajo no se volvió a abrir: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/mainwindowworkspace.cpp" line="123"/>
        <source>Workspace: %1 of %n line(s) connected</source>
        <translation>
            <numerusform>Espacio de trabajo: %1 de %n línea conectada</numerusform>
            <numerusform>Espacio de trabajo: %1 de %n líneas conectadas</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/mainwindowworkspace.cpp" line="133"/>
        <source>the workspace&apos;s %n line(s) are in the tree</source>
        <translation>
            <numerusform>la %n línea del espacio de trabajo está en el árbol</numerusform>
            <numerusform>las %n líneas del espacio de trabajo están en el árbol</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="135"/>
        <source>the plant&apos;s devices are on the fleet overview</source>
        <translation>los equipos de la planta están en la vista de flota</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="142"/>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="147"/>
        <source>Open workspace</source>
        <translation>Abrir espacio de trabajo</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="143"/>
        <source>TipScope workspaces (*.json);;All files (*)</source>
        <translation>Espacios de trabajo de TipScope (*.json);;Todos los archivos (*)</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="154"/>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="160"/>
        <source>Save workspace</source>
        <translation>Guardar espacio de trabajo</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="156"/>
        <source>TipScope workspaces (*.json)</source>
        <translation>Espacios de trabajo de TipScope (*.json)</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="169"/>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="174"/>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="183"/>
        <source>Add this line to the workspace</source>
        <translation>Añadir esta línea al espacio de trabajo</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="174"/>
        <source>Name of the line (cell, station):</source>
        <translation>Nombre de la línea (celda, estación):</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowworkspace.cpp" line="175"/>
        <source>line-%1</source>
        <translation>linea-%1</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowplant.cpp" line="18"/>
        <source>Connect to &amp;plant…</source>
        <translation>Conectar con la &amp;planta…</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowplant.cpp" line="24"/>
        <source>Disconnect from p&amp;lant</source>
        <translation>Desconectar de la p&amp;lanta</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowplant.cpp" line="64"/>
        <source>Plant: %1</source>
        <translation>Planta: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowplant.cpp" line="65"/>
        <source>Plant: %1 not connected</source>
        <translation>Planta: %1 sin conexión</translation>
    </message>
    <message>
        <location filename="../app/gui/mainwindowplant.cpp" line="66"/>
        <source>Watching %1 on the plant&apos;s broker</source>
        <translation>Siguiendo %1 en el broker de la planta</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::OverviewPage</name>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="132"/>
        <source>&lt;i&gt;No station. Connect to a line, or start the demo.&lt;/i&gt;</source>
        <translation>&lt;i&gt;No hay ninguna estación. Conéctese a una línea o inicie la demo.&lt;/i&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="133"/>
        <source>&lt;i&gt;No station on this line.&lt;/i&gt;</source>
        <translation>&lt;i&gt;No hay ninguna estación en esta línea.&lt;/i&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="140"/>
        <source>family %1</source>
        <translation>familia %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="141"/>
        <source>software %1</source>
        <translation>software %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="142"/>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="144"/>
        <source>transformer %1</source>
        <translation>transformador %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="146"/>
        <source>fuse present</source>
        <translation>fusible presente</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="147"/>
        <source>&lt;span style=&apos;color:#c01c28&apos;&gt;fuse missing or blown&lt;/span&gt;</source>
        <translation>&lt;span style=&apos;color:#c01c28&apos;&gt;fusible ausente o fundido&lt;/span&gt;</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="153"/>
        <source>⚠ Station error: %1</source>
        <translation>⚠ Error de estación: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="164"/>
        <source>feeding</source>
        <translation>alimentando</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="164"/>
        <source>idle</source>
        <translation>en espera</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="166"/>
        <source>fed %1</source>
        <translation>alimentado %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="168"/>
        <source>speed %1</source>
        <translation>velocidad %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.h" line="28"/>
        <source>Overview</source>
        <translation>Vista general</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="173"/>
        <source>not connected, as last read</source>
        <translation>no conectado, según la última lectura</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="194"/>
        <source>⚠ Not connected: nothing has been read yet. The robot controls are off until the line is back.</source>
        <translation>⚠ No conectado: aún no se ha leído nada. Los mandos del robot están desactivados hasta que vuelva la línea.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="196"/>
        <source>⚠ Not connected: the greyed values are as last read at %1. The robot controls are off until the line is back.</source>
        <translation>⚠ No conectado: los valores en gris son los de la última lectura a las %1. Los mandos del robot están desactivados hasta que vuelva la línea.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/overviewpage.cpp" line="200"/>
        <source>Monitor-only mode is on: the robot controls are off.</source>
        <translation>El modo solo monitorización está activo: los mandos del robot están desactivados.</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::ParameterEditor</name>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="73"/>
        <source>Allowed: %1</source>
        <translation>Permitido: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="74"/>
        <source>Command: %1</source>
        <translation>Comando: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="98"/>
        <source>%1 disabled</source>
        <translation>%1 desactivado</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="184"/>
        <source>not read</source>
        <translation>no leído</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="187"/>
        <source>reading…</source>
        <translation>leyendo…</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="190"/>
        <source>✓ in sync</source>
        <translation>✓ sincronizado</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="194"/>
        <source>✓ in sync, not yet saved</source>
        <translation>✓ sincronizado, aún sin guardar</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="196"/>
        <source>Written and read back. The station forgets it when it restarts, unless it is saved to station memory.</source>
        <translation>Escrito y releído. La estación lo olvida al reiniciarse, salvo que se guarde en la memoria de la estación.</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="204"/>
        <source>edited</source>
        <translation>editado</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="208"/>
        <source>writing…</source>
        <translation>escribiendo…</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="211"/>
        <source>✗ failed</source>
        <translation>✗ falló</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="216"/>
        <source>✗ refused</source>
        <translation>✗ rechazado</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/parametereditor.cpp" line="200"/>
        <source>last read %1</source>
        <translation>última lectura %1</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::PlantDialog</name>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="24"/>
        <source>Connect to plant</source>
        <translation>Conectar con la planta</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="34"/>
        <source>every site</source>
        <translation>todas las plantas</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="35"/>
        <source>The fleet overview shows every device the line PCs publish there; their pages are read-only. This window publishes nothing.</source>
        <translation>La vista de la flota muestra cada dispositivo que los PC de línea publican allí; sus páginas son de solo lectura. Esta ventana no publica nada.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="40"/>
        <source>&amp;Broker:</source>
        <translation>&amp;Broker:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="41"/>
        <source>P&amp;ort:</source>
        <translation>P&amp;uerto:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="42"/>
        <source>&amp;User name:</source>
        <translation>&amp;Usuario:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="43"/>
        <source>&amp;Password:</source>
        <translation>&amp;Contraseña:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="44"/>
        <source>&amp;Site:</source>
        <translation>P&amp;lanta:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="46"/>
        <source>Connect</source>
        <translation>Conectar</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/plantdialog.cpp" line="74"/>
        <source>the broker&apos;s host name or address</source>
        <translation>nombre o dirección del broker</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::PortCard</name>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="49"/>
        <source>Port %1</source>
        <translation>Puerto %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="63"/>
        <source>Tip temperature, port %1</source>
        <translation>Temperatura de la punta, puerto %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="69"/>
        <source>Power, port %1</source>
        <translation>Potencia, puerto %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="91"/>
        <source>Work</source>
        <translation>Trabajo</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="92"/>
        <source>Stand</source>
        <translation>Soporte</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="93"/>
        <source>Cool</source>
        <translation>Enfriar</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="94"/>
        <source>W-PS%1 00000: heat to the selected temperature</source>
        <translation>W-PS%1 00000: calentar a la temperatura seleccionada</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="95"/>
        <source>W-PS%1 00001: stand; sleep and hibernation follow after their delays</source>
        <translation>W-PS%1 00001: soporte; el reposo y la hibernación siguen tras sus retardos</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="97"/>
        <source>W-PS%1 00010: cooling (extractor stand-by)</source>
        <translation>W-PS%1 00010: enfriamiento (extractor en espera)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="101"/>
        <source>New selected temperature, port %1</source>
        <translation>Nueva temperatura seleccionada, puerto %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="102"/>
        <source>Set</source>
        <translation>Fijar</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="228"/>
        <source>no recovery</source>
        <translation>sin recuperación</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="230"/>
        <source>last joint %1, %2</source>
        <translation>última soldadura %1, %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="259"/>
        <source>Port %1 — %2</source>
        <translation>Puerto %1 — %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="260"/>
        <source>— °</source>
        <translation>— °</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="261"/>
        <source>set %1</source>
        <translation>consigna %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="263"/>
        <source>power %1</source>
        <translation>potencia %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="289"/>
        <source>status unknown</source>
        <translation>estado desconocido</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="267"/>
        <source>transistor %1</source>
        <translation>transistor %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="269"/>
        <source>%1 until the next mode</source>
        <translation>%1 hasta el siguiente modo</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="301"/>
        <location filename="../app/gui/pages/portcard.cpp" line="304"/>
        <source>⚠ Error: %1</source>
        <translation>⚠ Error: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="309"/>
        <source>status: %1</source>
        <translation>estado: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="311"/>
        <source>alarm: %1</source>
        <translation>alarma: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="279"/>
        <source>Not connected: last read %1</source>
        <translation>No conectado: última lectura %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/portcard.cpp" line="281"/>
        <source>Not connected: not read yet</source>
        <translation>No conectado: aún sin leer</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::PreferencesDialog</name>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="33"/>
        <source>Preferences</source>
        <translation>Preferencias</translation>
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
        <translation>Idioma del sistema</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="51"/>
        <source> days</source>
        <translation> días</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="52"/>
        <source>Keep everything</source>
        <translation>Conservarlo todo</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="54"/>
        <source>Joints and events older than this are deleted from the journal, a little at a time so polling never waits. Every TipScope program that keeps this journal uses the same retention.</source>
        <translation>Las soldaduras y los eventos más antiguos se borran del diario poco a poco, sin hacer esperar nunca a la consulta. Todos los programas de TipScope que llevan este diario usan el mismo tiempo de conservación.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="58"/>
        <source>Temperature unit:</source>
        <translation>Unidad de temperatura:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="59"/>
        <source>Live values (visible ports) every:</source>
        <translation>Valores en tiempo real (puertos visibles) cada:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="60"/>
        <source>Errors, alarms and status every:</source>
        <translation>Errores, alarmas y estado cada:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="61"/>
        <source>Counters every:</source>
        <translation>Contadores cada:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="62"/>
        <source>Device turnaround (added to the wire time):</source>
        <translation>Tiempo de respuesta del equipo (se suma al tiempo de transmisión):</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="63"/>
        <source>Retries after a lost or corrupted answer:</source>
        <translation>Reintentos tras una respuesta perdida o dañada:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="64"/>
        <source>Chart history at full rate:</source>
        <translation>Historial de gráficos a frecuencia completa:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="65"/>
        <source>Chart history in all:</source>
        <translation>Historial de gráficos en total:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="66"/>
        <source>Language (on the next start):</source>
        <translation>Idioma (en el próximo inicio):</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="67"/>
        <source>Keep journal records for:</source>
        <translation>Conservar los registros del diario durante:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/preferencesdialog.cpp" line="69"/>
        <source>The wire always carries °C; the unit only changes what you see and type. The colours follow the desktop theme. Chart history older than the full-rate part keeps min, max and mean per 5 s (about 1.4 MB a port for a day); it applies to devices found from then on.</source>
        <translation>En la línea siempre viaja °C; la unidad solo cambia lo que ve y escribe. Los colores siguen el tema del escritorio. Del historial de gráficos más antiguo que la parte a frecuencia completa se guardan mínimo, máximo y media cada 5 s (unos 1,4 MB por puerto y día); se aplica a los dispositivos encontrados a partir de entonces.</translation>
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
        <translation>Perfil para %1</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="30"/>
        <source>Setting</source>
        <translation>Ajuste</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="30"/>
        <source>Device now</source>
        <translation>Equipo ahora</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="30"/>
        <source>Profile</source>
        <translation>Perfil</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="38"/>
        <source>The dry run&apos;s frames and the apply report appear here.</source>
        <translation>Aquí aparecen las tramas de la simulación y el informe de la aplicación.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="42"/>
        <source>Apply anyway: the profile is for a %1, this is a %2 (only the settings both have are written)</source>
        <translation>Aplicar de todos modos: el perfil es para %1 y este equipo es %2 (solo se escriben los ajustes que tienen ambos)</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="48"/>
        <source>Compare again</source>
        <translation>Comparar de nuevo</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="49"/>
        <source>Dry run</source>
        <translation>Simulación</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="50"/>
        <source>Apply to device</source>
        <translation>Aplicar al equipo</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="51"/>
        <source>Stop</source>
        <translation>Detener</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="71"/>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="116"/>
        <source>Monitor-only mode is on: nothing is written</source>
        <translation>El modo solo supervisión está activado: no se escribe nada</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="185"/>
        <source>Profile from %1 (%2, software %3), created %4: %n setting(s) differ from the device.</source>
        <translation>
            <numerusform>Perfil de %1 (%2, software %3), creado: %4. %n ajuste difiere del equipo.</numerusform>
            <numerusform>Perfil de %1 (%2, software %3), creado: %4. %n ajustes difieren del equipo.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="176"/>
        <source>Dry run: %n frame(s) would be sent; nothing was written.</source>
        <translation>
            <numerusform>Simulación: se enviaría %n trama; no se escribió nada.</numerusform>
            <numerusform>Simulación: se enviarían %n tramas; no se escribió nada.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="114"/>
        <source>The profile would break the device&apos;s limits; see above</source>
        <translation>El perfil rompería los límites del equipo; véase arriba</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="172"/>
        <source>&lt;b&gt;This profile cannot be applied to this device:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Este perfil no se puede aplicar a este equipo:&lt;/b&gt; %1</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="30"/>
        <source>Note</source>
        <translation>Nota</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="180"/>
        <source>&lt;b&gt;Applied.&lt;/b&gt; Every written value was read back and matches; the table shows the device as it now is.</source>
        <translation>&lt;b&gt;Aplicado.&lt;/b&gt; Cada valor escrito se ha releído y coincide; la tabla muestra el equipo tal como está ahora.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="182"/>
        <source>&lt;b&gt;Not everything was applied.&lt;/b&gt; The table shows the device as it now is; see the report below.</source>
        <translation>&lt;b&gt;No se ha aplicado todo.&lt;/b&gt; La tabla muestra el equipo tal como está ahora; vea el informe abajo.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="193"/>
        <source>Comment: %1</source>
        <translation>Comentario: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="151"/>
        <source>✓ changed from %1</source>
        <translation>✓ cambiado desde %1</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="152"/>
        <source>✗ failed: %1</source>
        <translation>✗ fallido: %1</translation>
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
        <translation>omitido: %1</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="165"/>
        <source>%n setting(s) of the profile skipped: this device does not take them.</source>
        <translation>
            <numerusform>%n ajuste del perfil omitido: este equipo no lo admite.</numerusform>
            <numerusform>%n ajustes del perfil omitidos: este equipo no los admite.</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="168"/>
        <source>&lt;b&gt;Refused, nothing was written:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Rechazado, no se ha escrito nada:&lt;/b&gt; %1</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="170"/>
        <location filename="../app/gui/dialogs/profiledialog.cpp" line="174"/>
        <source>The table shows what the profile would change.</source>
        <translation>La tabla muestra lo que el perfil cambiaría.</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::RecoveryHistogramView</name>
    <message>
        <location filename="../app/gui/pages/jointcharts.cpp" line="57"/>
        <source>Histogram of recovery times</source>
        <translation>Histograma de tiempos de recuperación</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pages/jointcharts.cpp" line="70"/>
        <source>Recovery time of %n joint(s)</source>
        <translation>
            <numerusform>Recuperación de %n soldadura</numerusform>
            <numerusform>Recuperación de %n soldaduras</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pages/jointcharts.cpp" line="73"/>
        <source>%1 (%n did not recover)</source>
        <translation>
            <numerusform>%1 (%n sin recuperar)</numerusform>
            <numerusform>%1 (%n sin recuperar)</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointcharts.cpp" line="86"/>
        <source>No recovered joints listed</source>
        <translation>Ninguna soldadura recuperada en la lista</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::RecoveryTrendView</name>
    <message>
        <location filename="../app/gui/pages/jointcharts.cpp" line="117"/>
        <source>Daily median recovery time per tool</source>
        <translation>Mediana diaria de recuperación por herramienta</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointcharts.cpp" line="130"/>
        <source>Median recovery time per day</source>
        <translation>Mediana de recuperación por día</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointcharts.cpp" line="131"/>
        <location filename="../app/gui/pages/jointcharts.cpp" line="171"/>
        <source>Median recovery time per day:</source>
        <translation>Mediana de recuperación por día:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/jointcharts.cpp" line="145"/>
        <source>No recovered joints listed</source>
        <translation>Ninguna soldadura recuperada en la lista</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::RemoteDevicePage</name>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="80"/>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="92"/>
        <source>Port</source>
        <translation>Puerto</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="80"/>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="92"/>
        <source>Tool</source>
        <translation>Herramienta</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="80"/>
        <source>Tip</source>
        <translation>Punta</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="80"/>
        <source>Setpoint</source>
        <translation>Consigna</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="80"/>
        <source>Power</source>
        <translation>Potencia</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="80"/>
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="83"/>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="104"/>
        <source>Tip, setpoint and power, last 10 minutes</source>
        <translation>Punta, consigna y potencia, últimos 10 minutos</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="85"/>
        <source>Temperature (°C)</source>
        <translation>Temperatura (°C)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="86"/>
        <source>Power (%)</source>
        <translation>Potencia (%)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="92"/>
        <source>Ended</source>
        <translation>Fin</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="92"/>
        <source>Verdict</source>
        <translation>Veredicto</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="92"/>
        <source>Dip (K)</source>
        <translation>Caída (K)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="92"/>
        <source>Recovery (s)</source>
        <translation>Recuperación (s)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="94"/>
        <source>‹ Fleet overview</source>
        <translation>‹ Vista de la flota</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="102"/>
        <source>Live values</source>
        <translation>Valores en vivo</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="107"/>
        <source>Recent joints, newest first</source>
        <translation>Soldaduras recientes, la más nueva primero</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="126"/>
        <source>No such device on the plant&apos;s broker</source>
        <translation>Ese dispositivo no está en el broker de la planta</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="130"/>
        <source>%1 · %2 on %3 (%4)</source>
        <translation>%1 · %2 en %3 (%4)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="134"/>
        <source>Read-only: published by %1 %2 through the plant&apos;s broker; current.</source>
        <translation>Solo lectura: publicado por %1 %2 a través del broker de la planta; actual.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="136"/>
        <source>Read-only, not current: %1. The values are the last published.</source>
        <translation>Solo lectura, no actual: %1. Los valores son los últimos publicados.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="149"/>
        <source>No errors or alarms in force.</source>
        <translation>Ningún error ni alarma activos.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="150"/>
        <source>In force: %1</source>
        <translation>Activos: %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="166"/>
        <source>never</source>
        <translation>nunca</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/fleet/remotedevicepage.cpp" line="202"/>
        <source>No live values received yet</source>
        <translation>Aún no se han recibido valores en vivo</translation>
    </message>
</context>
<context>
    <name>tipscope::gui::SettingsPage</name>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="37"/>
        <source>Port</source>
        <translation>Puerto</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="40"/>
        <source>Re&amp;fresh</source>
        <translation>Ac&amp;tualizar</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="41"/>
        <location filename="../app/gui/pages/settingspage.cpp" line="242"/>
        <source>&amp;Apply</source>
        <translation>A&amp;plicar</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="42"/>
        <source>Re&amp;vert</source>
        <translation>&amp;Revertir</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="43"/>
        <source>Save to station &amp;memory</source>
        <translation>Guardar en la &amp;memoria de la estación</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="44"/>
        <source>The selected temperature is volatile: W-NVS stores it so that it survives a restart</source>
        <translation>La temperatura seleccionada es volátil: W-NVS la guarda para que se conserve tras reiniciar</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="47"/>
        <source>Station actions</source>
        <translation>Acciones de la estación</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="50"/>
        <source>Profiles</source>
        <translation>Perfiles</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="53"/>
        <source>Save device settings to a profile…</source>
        <translation>Guardar los ajustes del equipo en un perfil…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="55"/>
        <source>Open a profile (compare, dry run, apply)…</source>
        <translation>Abrir un perfil (comparar, simular, aplicar)…</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="64"/>
        <source>Port:</source>
        <translation>Puerto:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="154"/>
        <source>Connect and select a device to see its settings.</source>
        <translation>Conéctese y seleccione un equipo para ver sus ajustes.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="157"/>
        <source>Port %1 (%2)</source>
        <translation>Puerto %1 (%2)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="169"/>
        <source>Station</source>
        <translation>Estación</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="176"/>
        <source>Port %1</source>
        <translation>Puerto %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="177"/>
        <source>Alarms, port %1</source>
        <translation>Alarmas, puerto %1</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="179"/>
        <source>Tool %1, port %2</source>
        <translation>Herramienta %1, puerto %2</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="181"/>
        <source> (connected)</source>
        <translation> (conectada)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="185"/>
        <source>Dispensing (ALE wire feed)</source>
        <translation>Dispensado (alimentación de hilo de la ALE)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="193"/>
        <source>Feeding</source>
        <translation>Alimentación</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="242"/>
        <source>&amp;Apply (%1)</source>
        <translation>A&amp;plicar (%1)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="309"/>
        <source>Save to station memory</source>
        <translation>Guardar en la memoria de la estación</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="321"/>
        <source>New address (1-99), or 0 for frames without addresses:</source>
        <translation>Nueva dirección (1-99), o 0 para tramas sin direcciones:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="328"/>
        <source>%1

%2

Do you want to continue?</source>
        <translation>%1

%2

¿Desea continuar?</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="343"/>
        <location filename="../app/gui/pages/settingspage.cpp" line="349"/>
        <location filename="../app/gui/pages/settingspage.cpp" line="355"/>
        <location filename="../app/gui/pages/settingspage.cpp" line="361"/>
        <source>Save profile</source>
        <translation>Guardar perfil</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="344"/>
        <source>Some settings have not been read yet (%1). Refresh and try again.</source>
        <translation>Algunos ajustes aún no se han leído (%1). Actualice y vuelva a intentarlo.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="350"/>
        <location filename="../app/gui/pages/settingspage.cpp" line="385"/>
        <source>TipScope profiles (*.json)</source>
        <translation>Perfiles de TipScope (*.json)</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="384"/>
        <location filename="../app/gui/pages/settingspage.cpp" line="390"/>
        <source>Open profile</source>
        <translation>Abrir perfil</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.h" line="34"/>
        <source>Settings</source>
        <translation>Ajustes</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="251"/>
        <source>⚠ Not connected: the greyed values are as last read (the time is beside each). Apply, Save to station memory, Station actions and Profiles wait for the line.</source>
        <translation>⚠ No conectado: los valores en gris son los de la última lectura (la hora está al lado). Aplicar, Guardar en la memoria de la estación, Acciones de la estación y Perfiles esperan a la línea.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="255"/>
        <source>Monitor-only mode is on: Apply, Save to station memory and Station actions are off, nothing is written.</source>
        <translation>El modo solo monitorización está activo: Aplicar, Guardar en la memoria de la estación y Acciones de la estación están desactivados, no se escribe nada.</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="356"/>
        <source>A comment for the profile (optional), e.g. what it is for or who set it:</source>
        <translation>Un comentario para el perfil (opcional), p. ej. para qué es o quién lo configuró:</translation>
    </message>
    <message>
        <location filename="../app/gui/pages/settingspage.cpp" line="367"/>
        <source>no device is selected</source>
        <translation>no hay ningún equipo seleccionado</translation>
    </message>
    <message numerus="yes">
        <location filename="../app/gui/pages/settingspage.cpp" line="372"/>
        <source>✓ Profile saved: %n setting(s) of %1 in %2</source>
        <translation>
            <numerusform>✓ Perfil guardado: %n ajuste de %1 en %2</numerusform>
            <numerusform>✓ Perfil guardado: %n ajustes de %1 en %2</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tipscope::gui::Sparkline</name>
    <message>
        <location filename="../app/gui/widgets/sparkline.cpp" line="63"/>
        <source>Last minute of tip temperature and power</source>
        <translation>Último minuto de temperatura de punta y potencia</translation>
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
        <translation>de %1 a %2</translation>
    </message>
    <message>
        <location filename="../app/gui/widgets/sparkline.cpp" line="104"/>
        <source>no samples yet</source>
        <translation>aún no hay muestras</translation>
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
        <translation>Contexto de trabajo</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/workcontextdialog.cpp" line="37"/>
        <source>Stamped on every joint and event from now on, by every TipScope program on this computer, until it is changed.</source>
        <translation>A partir de ahora se registra con cada soldadura y cada evento, en todos los programas TipScope de este equipo, hasta que se cambie.</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/workcontextdialog.cpp" line="43"/>
        <source>Work order:</source>
        <translation>Orden de trabajo:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/workcontextdialog.cpp" line="44"/>
        <source>Board serial:</source>
        <translation>Número de serie de la placa:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/workcontextdialog.cpp" line="45"/>
        <source>Operator:</source>
        <translation>Operario:</translation>
    </message>
    <message>
        <location filename="../app/gui/dialogs/workcontextdialog.cpp" line="48"/>
        <source>Clear</source>
        <translation>Borrar</translation>
    </message>
</context>
<context>
    <name>tipscope::journal::Journal</name>
    <message>
        <location filename="../lib/journal/journal.cpp" line="111"/>
        <location filename="../lib/journal/journal.cpp" line="125"/>
        <location filename="../lib/journal/journal.cpp" line="189"/>
        <source>The journal is closed.</source>
        <translation>El diario está cerrado.</translation>
    </message>
    <message>
        <location filename="../lib/journal/journal.cpp" line="115"/>
        <source>The journal cannot keep up: %1 records wait to be written.</source>
        <translation>El diario no da abasto: %1 registros esperan a ser escritos.</translation>
    </message>
    <message>
        <location filename="../lib/journal/journal.cpp" line="168"/>
        <source>Work order: %1, board: %2, operator: %3</source>
        <translation>Orden de trabajo: %1, placa: %2, operario: %3</translation>
    </message>
</context>
<context>
    <name>tipscope::link::Discovery</name>
    <message>
        <location filename="../lib/link/discovery.cpp" line="29"/>
        <source>the catalog names no command that identifies a device</source>
        <translation>el catálogo no indica ningún comando que identifique un equipo</translation>
    </message>
    <message>
        <location filename="../lib/link/discovery.cpp" line="31"/>
        <source>the device reports the model &apos;%1&apos;, which TipScope does not know</source>
        <translation>el equipo informa del modelo &apos;%1&apos;, que TipScope no conoce</translation>
    </message>
    <message>
        <location filename="../lib/link/discovery.cpp" line="38"/>
        <source>the device without addresses did not identify itself (%1): %2</source>
        <translation>el equipo sin direcciones no se identificó (%1): %2</translation>
    </message>
    <message>
        <location filename="../lib/link/discovery.cpp" line="40"/>
        <source>the device at address %1 did not identify itself (%2): %3</source>
        <translation>el equipo en la dirección %1 no se identificó (%2): %3</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/link/discovery.cpp" line="100"/>
        <source>%n NAK(s) %1 (%2)</source>
        <translation>
            <numerusform>%n NAK %1 (%2)</numerusform>
            <numerusform>%n NAK %1 (%2)</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/link/discovery.cpp" line="104"/>
        <source>%n answer(s) with a bad block check or format</source>
        <translation>
            <numerusform>%n respuesta con una suma de control o un formato incorrectos</numerusform>
            <numerusform>%n respuestas con una suma de control o un formato incorrectos</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/link/discovery.cpp" line="106"/>
        <source>%n frame(s) from an address not asked</source>
        <translation>
            <numerusform>%n trama de una dirección no consultada</numerusform>
            <numerusform>%n tramas de direcciones no consultadas</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/link/discovery.cpp" line="108"/>
        <source>%n byte(s) that were no frame</source>
        <translation>
            <numerusform>%n byte que no era una trama</numerusform>
            <numerusform>%n bytes que no eran una trama</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tipscope::link::Line</name>
    <message>
        <location filename="../lib/link/line.cpp" line="24"/>
        <source>the line was closed</source>
        <translation>se cerró la línea</translation>
    </message>
    <message>
        <location filename="../lib/link/line.cpp" line="62"/>
        <source>disconnected</source>
        <translation>desconectado</translation>
    </message>
    <message>
        <location filename="../lib/link/line.cpp" line="64"/>
        <source>connecting to %1</source>
        <translation>conectando con %1</translation>
    </message>
    <message>
        <location filename="../lib/link/line.cpp" line="66"/>
        <source>connected: %1</source>
        <translation>conectado: %1</translation>
    </message>
    <message>
        <location filename="../lib/link/line.cpp" line="70"/>
        <source>cannot open %1, retrying every %2 s: %3</source>
        <translation>no se puede abrir %1, reintentando cada %2 s: %3</translation>
    </message>
    <message>
        <location filename="../lib/link/line.cpp" line="74"/>
        <source>disconnected, retrying every %1 s: %2</source>
        <translation>desconectado, reintentando cada %1 s: %2</translation>
    </message>
    <message>
        <location filename="../lib/link/line.cpp" line="78"/>
        <source>cannot connect: %1</source>
        <translation>no se puede conectar: %1</translation>
    </message>
    <message>
        <location filename="../lib/link/line.cpp" line="99"/>
        <source>disconnected by the user</source>
        <translation>desconectado por el usuario</translation>
    </message>
    <message>
        <location filename="../lib/link/line.cpp" line="142"/>
        <source>no answer to %1 requests in a row (cable unplugged, device off, or wrong addressing?)</source>
        <translation>sin respuesta a %1 peticiones seguidas (¿cable desenchufado, equipo apagado o direccionamiento incorrecto?)</translation>
    </message>
</context>
<context>
    <name>tipscope::link::Reply</name>
    <message>
        <location filename="../lib/link/reply.cpp" line="10"/>
        <source>ok</source>
        <translation>correcto</translation>
    </message>
    <message>
        <location filename="../lib/link/reply.cpp" line="12"/>
        <source>no answer</source>
        <translation>sin respuesta</translation>
    </message>
    <message>
        <location filename="../lib/link/reply.cpp" line="14"/>
        <source>corrupted answer</source>
        <translation>respuesta dañada</translation>
    </message>
    <message>
        <location filename="../lib/link/reply.cpp" line="16"/>
        <source>refused (NAK)</source>
        <translation>rechazado (NAK)</translation>
    </message>
    <message>
        <location filename="../lib/link/reply.cpp" line="18"/>
        <source>disconnected</source>
        <translation>desconectado</translation>
    </message>
    <message>
        <location filename="../lib/link/reply.cpp" line="20"/>
        <source>cancelled</source>
        <translation>cancelado</translation>
    </message>
    <message>
        <location filename="../lib/link/reply.cpp" line="22"/>
        <source>not connected</source>
        <translation>sin conexión</translation>
    </message>
</context>
<context>
    <name>tipscope::link::RequestQueue</name>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="72"/>
        <source>the connection was closed</source>
        <translation>se cerró la conexión</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="118"/>
        <source>the connection is closing</source>
        <translation>la conexión se está cerrando</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="122"/>
        <source>not sent: the line is not connected</source>
        <translation>no enviado: la línea no está conectada</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="221"/>
        <source>the answer was corrupted (%1)</source>
        <translation>la respuesta llegó dañada (%1)</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="255"/>
        <source>unreadable data field &apos;%1&apos; in the answer</source>
        <translation>campo de datos ilegible &apos;%1&apos; en la respuesta</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="264"/>
        <source>the request could not be written</source>
        <translation>no se pudo escribir la petición</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="268"/>
        <source>no answer</source>
        <translation>sin respuesta</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="287"/>
        <source>NAK %1: %2</source>
        <translation>NAK %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="318"/>
        <source>%1: %2 (attempt %3)</source>
        <translation>%1: %2 (intento %3)</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/link/requestqueue.cpp" line="334"/>
        <source>%1 after %n attempt(s)</source>
        <translation>
            <numerusform>%1 tras %n intento</numerusform>
            <numerusform>%1 tras %n intentos</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/link/requestqueue.cpp" line="337"/>
        <source>%n byte(s) of garbage came instead</source>
        <translation>
            <numerusform>en su lugar llegó %n byte de basura</numerusform>
            <numerusform>en su lugar llegaron %n bytes de basura</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="340"/>
        <source>; the device may have carried it out: check before repeating</source>
        <translation>; puede que el equipo la haya ejecutado: compruébelo antes de repetir</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="412"/>
        <source>line lost: %1</source>
        <translation>línea perdida: %1</translation>
    </message>
    <message>
        <location filename="../lib/link/requestqueue.cpp" line="414"/>
        <source>the line was lost: %1</source>
        <translation>se perdió la línea: %1</translation>
    </message>
</context>
<context>
    <name>tipscope::link::SerialTransport</name>
    <message>
        <location filename="../lib/link/serialtransport.cpp" line="82"/>
        <source>the port %1 disappeared (unplugged?)</source>
        <translation>el puerto %1 ha desaparecido (¿desconectado?)</translation>
    </message>
    <message>
        <location filename="../lib/link/serialtransport.cpp" line="84"/>
        <source>the port stopped responding (%1)</source>
        <translation>el puerto dejó de responder (%1)</translation>
    </message>
</context>
<context>
    <name>tipscope::link::SimTransport</name>
    <message>
        <location filename="../lib/link/simtransport.cpp" line="26"/>
        <source>the simulated line is unplugged</source>
        <translation>la línea simulada está desenchufada</translation>
    </message>
    <message>
        <location filename="../lib/link/simtransport.cpp" line="53"/>
        <source>demo (simulated %1)</source>
        <translation>demo (%1 simulado)</translation>
    </message>
    <message>
        <location filename="../lib/link/simtransport.cpp" line="64"/>
        <source>the simulated cable was pulled</source>
        <translation>se desenchufó el cable simulado</translation>
    </message>
</context>
<context>
    <name>tipscope::link::TcpTransport</name>
    <message>
        <location filename="../lib/link/tcptransport.cpp" line="29"/>
        <source>the connection to %1 dropped (%2)</source>
        <translation>se cortó la conexión con %1 (%2)</translation>
    </message>
    <message>
        <location filename="../lib/link/tcptransport.cpp" line="36"/>
        <source>cannot connect to %1: %2</source>
        <translation>no se puede conectar con %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/link/tcptransport.cpp" line="65"/>
        <source>cannot connect to %1: no connection within %2 s</source>
        <translation>no se puede conectar con %1: sin conexión en %2 s</translation>
    </message>
</context>
<context>
    <name>tipscope::model::ConsoleSender</name>
    <message>
        <location filename="../lib/model/console/consolesender.cpp" line="15"/>
        <source>%1: answered %2 after %L3 ms</source>
        <translation>%1: respondió %2 tras %L3 ms</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolesender.cpp" line="19"/>
        <source>%1: refused, %2</source>
        <translation>%1: rechazado, %2</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolesender.cpp" line="21"/>
        <source>%1: no answer (timeout)</source>
        <translation>%1: sin respuesta (tiempo agotado)</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolesender.cpp" line="23"/>
        <source>%1: %2 (%3)</source>
        <translation>%1: %2 (%3)</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolesender.cpp" line="52"/>
        <source>Monitor-only mode is on: W frames are not sent. Reads still are.</source>
        <translation>El modo solo supervisión está activado: las tramas W no se envían. Las lecturas sí.</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolesender.cpp" line="58"/>
        <source>Monitor-only mode is on: bytes that are not one valid R frame may be a write, so they are not sent.</source>
        <translation>El modo solo supervisión está activado: los bytes que no forman una trama R válida podrían ser una escritura, así que no se envían.</translation>
    </message>
    <message numerus="yes">
        <location filename="../lib/model/console/consolesender.cpp" line="69"/>
        <source>%n raw byte(s)</source>
        <translation>
            <numerusform>%n byte en bruto</numerusform>
            <numerusform>%n bytes en bruto</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolesender.cpp" line="75"/>
        <source>%1: not sent, not connected</source>
        <translation>%1: no enviado, sin conexión</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolesender.cpp" line="79"/>
        <source>%1: not sent, monitor-only mode is on</source>
        <translation>%1: no enviado, el modo solo supervisión está activado</translation>
    </message>
    <message>
        <location filename="../lib/model/console/consolesender.cpp" line="91"/>
        <source>%1: sent, waiting for the answer…</source>
        <translation>%1: enviado, esperando la respuesta…</translation>
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
        <translation>Puerto %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="48"/>
        <source>Port %1 alarm: %2</source>
        <translation>Alarma del puerto %1: %2</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="54"/>
        <source>Feeding</source>
        <translation>Alimentando</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="55"/>
        <source>Not feeding</source>
        <translation>Sin alimentar</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="56"/>
        <source>%1 · fed %2</source>
        <translation>%1 · alimentado %2</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="195"/>
        <source>Line down</source>
        <translation>Línea caída</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="200"/>
        <source>Line down since %1</source>
        <translation>Línea caída desde las %1</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="201"/>
        <source>Line down since %1 %2</source>
        <translation>Línea caída desde el %1 a las %2</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="219"/>
        <source>Station: %1</source>
        <translation>Estación: %1</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/fleettile.cpp" line="231"/>
        <source>Feeder: %1</source>
        <translation>Alimentador: %1</translation>
    </message>
</context>
<context>
    <name>tipscope::model::LineTile</name>
    <message>
        <location filename="../lib/model/workspace/linetile.cpp" line="44"/>
        <source>No device</source>
        <translation>Ningún equipo</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/linetile.cpp" line="54"/>
        <source>Recording</source>
        <translation>Grabación</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/linetile.cpp" line="56"/>
        <source>Cannot be played</source>
        <translation>No se puede reproducir</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/linetile.cpp" line="66"/>
        <source>No device answered</source>
        <translation>Ningún equipo ha respondido</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/linetile.cpp" line="67"/>
        <source>Connecting</source>
        <translation>Conectando</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/linetile.cpp" line="68"/>
        <source>Looking for devices</source>
        <translation>Buscando equipos</translation>
    </message>
</context>
<context>
    <name>tipscope::model::Workspace</name>
    <message>
        <location filename="../lib/model/workspace/workspace.cpp" line="28"/>
        <source>a line needs a name</source>
        <translation>una línea necesita un nombre</translation>
    </message>
    <message>
        <location filename="../lib/model/workspace/workspace.cpp" line="31"/>
        <source>the workspace already has a line named &quot;%1&quot;</source>
        <translation>el espacio de trabajo ya tiene una línea llamada «%1»</translation>
    </message>
</context>
<context>
    <name>tipscope::plant::RemoteHistory</name>
    <message>
        <location filename="../lib/plant/remotehistory.cpp" line="100"/>
        <source>Port %1</source>
        <translation>Puerto %1</translation>
    </message>
</context>
</TS>
