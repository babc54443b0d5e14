<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>AtomicFile</name>
    <message>
        <location filename="../core/io/AtomicFile.cpp" line="+24"/>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>no file name given</source>
        <translation>kein Dateiname angegeben</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>the same file is to be written twice</source>
        <translation>dieselbe Datei soll zweimal geschrieben werden</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 (already written: %2)</source>
        <translation>%1 (bereits geschrieben: %2)</translation>
    </message>
    <message>
        <location line="+13"/>
        <location line="+5"/>
        <source>cannot read %1: %2</source>
        <translation>%1 kann nicht gelesen werden: %2</translation>
    </message>
</context>
<context>
    <name>BaseParameters</name>
    <message>
        <location filename="../core/model/BaseParameters.cpp" line="+22"/>
        <source>base parameters need finite regressor rows</source>
        <translation>die Basisparameter brauchen endliche Regressorzeilen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the torques depend on no parameter: every regressor column is 0</source>
        <translation>die Momente hängen von keinem Parameter ab: jede Regressorspalte ist 0</translation>
    </message>
</context>
<context>
    <name>BoundingVolume</name>
    <message>
        <location filename="../core/model/BoundingVolume.cpp" line="+55"/>
        <source>A bounding box needs its upper corner above its lower one.</source>
        <translation>Ein Hüllquader braucht seine obere Ecke über der unteren.</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>A link without positive mass has no inertia ellipsoid.</source>
        <translation>Ein Glied ohne positive Masse hat kein Trägheitsellipsoid.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The inertia ellipsoid&apos;s margin must be above 1.</source>
        <translation>Der Zuschlag des Trägheitsellipsoids muss über 1 liegen.</translation>
    </message>
</context>
<context>
    <name>BusLoad</name>
    <message>
        <location filename="../core/can/BusLoad.cpp" line="+41"/>
        <source>Bus load: joints and frames must not be negative, rates must be positive and a frame carries 0 to 8 bytes.</source>
        <translation>Buslast: Gelenke und Frames dürfen nicht negativ, Raten müssen positiv sein, und ein Frame trägt 0 bis 8 Bytes.</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Bus load: the time window and the bitrate must be positive.</source>
        <translation>Buslast: Zeitfenster und Bitrate müssen positiv sein.</translation>
    </message>
    <message>
        <location line="-38"/>
        <source>%1 % of %2 kbit/s (%3 frames/s)</source>
        <translation>%1 % von %2 kbit/s (%3 Frames/s)</translation>
    </message>
</context>
<context>
    <name>CanArmSimulator</name>
    <message>
        <location filename="../core/cansim/CanArmSimulator.cpp" line="+23"/>
        <source>The simulated arm has no robot model.</source>
        <translation>Der simulierte Arm hat kein Robotermodell.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--nodes: the %1 arm has %2 joints, so %2 node ids are needed, not %3.</source>
        <translation>--nodes: der Arm %1 hat %2 Gelenke, also werden %2 Knoten-IDs gebraucht, nicht %3.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--nodes: %1 is not a CANopen node id (1 to 127).</source>
        <translation>--nodes: %1 ist keine CANopen-Knoten-ID (1 bis 127).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>--nodes: node %1 is listed twice.</source>
        <translation>--nodes: Knoten %1 ist zweimal aufgeführt.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The simulated arm&apos;s parameters, torque limits, initial pose or gains do not fit the %1 model.</source>
        <translation>Parameter, Momentengrenzen, Anfangsstellung oder Verstärkungen des simulierten Arms passen nicht zum Modell %1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The SYNC period must be 1 to 100 ms, not %1 s.</source>
        <translation>Die SYNC-Periode muss 1 bis 100 ms betragen, nicht %1 s.</translation>
    </message>
</context>
<context>
    <name>CanBus</name>
    <message>
        <location filename="../core/can/CanBusErrors.cpp" line="+30"/>
        <location line="+51"/>
        <source>bus off</source>
        <translation>Bus aus (bus off)</translation>
    </message>
    <message>
        <location line="-47"/>
        <source>controller error passive (%1)</source>
        <translation>Controller fehlerpassiv (%1)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>controller buffer overflow: frames were lost</source>
        <translation>Pufferüberlauf im Controller: Frames gingen verloren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>controller error warning level</source>
        <translation>Controller an der Fehlerwarnschwelle</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>controller back to error active</source>
        <translation>Controller wieder fehleraktiv</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>controller problem (unspecified)</source>
        <translation>Controllerproblem (nicht näher bezeichnet)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>transmit timeout</source>
        <translation>Sende-Zeitüberschreitung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>protocol violation (type 0x%1, location 0x%2)</source>
        <translation>Protokollverletzung (Typ 0x%1, Ort 0x%2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>transceiver error (0x%1)</source>
        <translation>Transceiverfehler (0x%1)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no acknowledgement (no other node on the bus?)</source>
        <translation>keine Bestätigung (kein anderer Knoten am Bus?)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bus error</source>
        <translation>Busfehler</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>lost arbitration</source>
        <translation>Arbitrierung verloren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>controller restarted</source>
        <translation>Controller neu gestartet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>error class 0x%1</source>
        <translation>Fehlerklasse 0x%1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>error active</source>
        <translation>fehleraktiv</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>error warning</source>
        <translation>Fehlerwarnung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>error passive</source>
        <translation>fehlerpassiv</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>stopped</source>
        <translation>gestoppt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <location filename="../core/can/SocketCanInterface.cpp" line="+142"/>
        <source>the CAN interface %1 does not exist (ip link show: is the adapter plugged in, its driver loaded?)</source>
        <translation>die CAN-Schnittstelle %1 existiert nicht (ip link show: ist der Adapter eingesteckt, sein Treiber geladen?)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is not a CAN interface</source>
        <translation>%1 ist keine CAN-Schnittstelle</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the CAN interface %1 is down (as root: ip link set %1 type can bitrate 1000000 &amp;&amp; ip link set %1 up)</source>
        <translation>die CAN-Schnittstelle %1 ist nicht aktiv (als root: ip link set %1 type can bitrate 1000000 &amp;&amp; ip link set %1 up)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the CAN controller of %1 is %2 (as root: ip link set %1 down &amp;&amp; ip link set %1 up; check wiring and termination)</source>
        <translation>der CAN-Controller von %1 ist %2 (als root: ip link set %1 down &amp;&amp; ip link set %1 up; Verkabelung und Abschluss prüfen)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>CAN FD (mtu %1)</source>
        <translation>CAN FD (MTU %1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN (mtu %1)</source>
        <translation>CAN (MTU %1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bitrate %1 kbit/s</source>
        <translation>Bitrate %1 kbit/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bitrate not readable</source>
        <translation>Bitrate nicht lesbar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2, %3, %4</source>
        <translation>%1: %2, %3, %4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>up</source>
        <translation>aktiv</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>down</source>
        <translation>nicht aktiv</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, driver %1</source>
        <translation>, Treiber %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, controller %1</source>
        <translation>, Controller %1</translation>
    </message>
</context>
<context>
    <name>CanOpen</name>
    <message>
        <location filename="../core/can/CanOpen.cpp" line="+51"/>
        <source>Unknown CANopen data type 0x%1.</source>
        <translation>Unbekannter CANopen-Datentyp 0x%1.</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Unknown CANopen data type &quot;%1&quot;.</source>
        <translation>Unbekannter CANopen-Datentyp „%1“.</translation>
    </message>
    <message>
        <location line="+17"/>
        <location line="+40"/>
        <source>%1 is not a numeric type.</source>
        <translation>%1 ist kein numerischer Typ.</translation>
    </message>
    <message>
        <location line="-38"/>
        <source>The value %1 does not fit the type %2 (range %3 to %4%5).</source>
        <translation>Der Wert %1 passt nicht in den Typ %2 (Bereich %3 bis %4%5).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>, integers only</source>
        <translation>, nur ganze Zahlen</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>%1 needs %2 bytes at offset %3, but only %4 bytes are present.</source>
        <translation>%1 braucht %2 Bytes ab Offset %3, aber nur %4 Bytes sind vorhanden.</translation>
    </message>
</context>
<context>
    <name>CanRobot</name>
    <message>
        <location filename="../core/canrobot/ApplySteps.cpp" line="+27"/>
        <source>node %1, object %2: read back %3 after writing %4 (%5 %6): nothing was stored</source>
        <translation>Knoten %1, Objekt %2: nach dem Schreiben von %4 (%5 %6) %3 zurückgelesen: nichts wurde gespeichert</translation>
    </message>
    <message>
        <location filename="../core/canrobot/CanRobot.cpp" line="+58"/>
        <source>CAN %1/%2, nodes %3</source>
        <translation>CAN %1/%2, Knoten %3</translation>
    </message>
    <message>
        <location filename="../core/canrobot/CanRobotOptions.cpp" line="+43"/>
        <source>cannot create the CAN device %1/%2: %3</source>
        <translation>das CAN-Gerät %1/%2 kann nicht angelegt werden: %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unknown plugin or interface</source>
        <translation>unbekanntes Plugin oder unbekannte Schnittstelle</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>the configuration of %1 nodes at %2 Hz (SYNC every %3 ms) needs %4 of the bus, more than the %5 % the tool allows</source>
        <translation>die Konfiguration mit %1 Knoten bei %2 Hz (SYNC alle %3 ms) belegt den Bus zu %4, mehr als die %5 %, die das Werkzeug zulässt</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1; no SYNC period up to 255 ms fits: use a faster bus</source>
        <translation>%1; keine SYNC-Periode bis 255 ms passt: einen schnelleren Bus verwenden</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1; the shortest SYNC period that fits is %2 ms (%3): set the scenario&apos;s controller.samplePeriod to %4 s and the robot side&apos;s SYNC period to match</source>
        <translation>%1; die kürzeste passende SYNC-Periode ist %2 ms (%3): controller.samplePeriod des Szenarios auf %4 s und die SYNC-Periode auf der Roboterseite passend dazu einstellen</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>no CAN node given: one node per joint is needed</source>
        <translation>kein CAN-Knoten angegeben: ein Knoten pro Gelenk ist nötig</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is not a valid CANopen node id (1 to 127)</source>
        <translation>%1 ist keine gültige CANopen-Knoten-ID (1 bis 127)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+73"/>
        <source>node %1 is listed twice</source>
        <translation>Knoten %1 ist zweimal aufgeführt</translation>
    </message>
    <message>
        <location line="-66"/>
        <source>CAN timing options must be positive (heartbeat period at most 65535 ms)</source>
        <translation>CAN-Zeitoptionen müssen positiv sein (Heartbeat-Periode höchstens 65535 ms)</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>&apos;%1&apos; is not a CANopen node id (1 to 127)</source>
        <translation>&apos;%1&apos; ist keine CANopen-Knoten-ID (1 bis 127)</translation>
    </message>
    <message>
        <location filename="../core/canrobot/NodeConfiguration.cpp" line="+30"/>
        <source>node %1, object %2: the answer holds %3 bytes, UNSIGNED32 needs 4</source>
        <translation>Knoten %1, Objekt %2: die Antwort enthält %3 Bytes, UNSIGNED32 braucht 4</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>node %1, object %2 is 0: the drive&apos;s units are unusable</source>
        <translation>Knoten %1, Objekt %2 ist 0: die Einheiten des Antriebs sind unbrauchbar</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>the plan is for %1 joints but %2 CAN nodes are configured</source>
        <translation>der Plan ist für %1 Gelenke, aber %2 CAN-Knoten sind konfiguriert</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the sample period %1 ms cannot be sent to 0x60C2 (whole ms, 1 to 255)</source>
        <translation>die Abtastzeit %1 ms kann nicht an 0x60C2 gesendet werden (ganze ms, 1 bis 255)</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>node %1, object 0x1006:00: the robot&apos;s SYNC period is %2 us, the plan needs %3 us</source>
        <translation>Knoten %1, Objekt 0x1006:00: die SYNC-Periode des Roboters ist %2 us, der Plan braucht %3 us</translation>
    </message>
    <message>
        <location filename="../core/canrobot/TrialCollector.cpp" line="+41"/>
        <source>%1: the TPDO answering SYNC %2 (counter %3) did not arrive before the next SYNC: sample missing</source>
        <translation>%1: das TPDO als Antwort auf SYNC %2 (Zähler %3) kam nicht vor dem nächsten SYNC: Abtastwert fehlt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>joint %1</source>
        <translation>Gelenk %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>SYNC counter jumped from %1 to %2 after SYNC %3: %4 SYNC(s) lost</source>
        <translation>SYNC-Zähler sprang nach SYNC %3 von %1 auf %2: %4 SYNC verloren</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>joint %1: TPDO of %2 bytes, the mapping needs %3 (SYNC %4)</source>
        <translation>Gelenk %1: TPDO mit %2 Bytes, das Mapping braucht %3 (SYNC %4)</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>at SYNC %1 (counter %2), plan sample %3, t = %4 s</source>
        <translation>bei SYNC %1 (Zähler %2), Planabtastwert %3, t = %4 s</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>at SYNC %1 (counter %2), %3 s after NMT start</source>
        <translation>bei SYNC %1 (Zähler %2), %3 s nach NMT-Start</translation>
    </message>
    <message>
        <location filename="../core/canrobot/JointIdentityCheck.cpp" line="+23"/>
        <source>node %1, object %2: the answer holds %3 bytes, 1 to 4 expected</source>
        <translation>Knoten %1, Objekt %2: die Antwort enthält %3 Bytes, erwartet 1 bis 4</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>; the drives say --nodes %1</source>
        <translation>; die Antriebe sagen --nodes %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>node %1 is listed for joint %2 but is the drive of joint %3 of this robot (0x2400:02 = %3): the node list does not match the wiring%4</source>
        <translation>Knoten %1 ist für Gelenk %2 angegeben, ist aber der Antrieb von Gelenk %3 dieses Roboters (0x2400:02 = %3): die Knotenliste passt nicht zur Verdrahtung%4</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>node %1 (joint %2) is not the drive the parameter file records for joint %2: it reports %3 (0x1018), the file holds %4</source>
        <translation>Knoten %1 (Gelenk %2) ist nicht der Antrieb, den die Parameterdatei für Gelenk %2 verzeichnet: er meldet %3 (0x1018), die Datei enthält %4</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>node %1 (joint %2) has never been commissioned (0x2400 is 0), so learnid cannot check which joint it moves: make sure it is the drive of joint %2 (its identity: %3), then run with --commission (in the window: First commissioning); apply stores the joint identity</source>
        <translation>Knoten %1 (Gelenk %2) wurde nie in Betrieb genommen (0x2400 ist 0), daher kann learnid nicht prüfen, welches Gelenk er bewegt: stellen Sie sicher, dass er der Antrieb von Gelenk %2 ist (seine Identität: %3), und starten Sie dann mit --commission (im Fenster: Erstinbetriebnahme); Anwenden speichert die Gelenkidentität</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>node %1 (joint %2) was commissioned for another robot (0x2400:01 = %3, this robot is %4): make sure it is the drive of joint %2 (%5), then run with --commission (in the window: First commissioning)</source>
        <translation>Knoten %1 (Gelenk %2) wurde für einen anderen Roboter in Betrieb genommen (0x2400:01 = %3, dieser Roboter ist %4): stellen Sie sicher, dass er der Antrieb von Gelenk %2 ist (%5), und starten Sie dann mit --commission (im Fenster: Erstinbetriebnahme)</translation>
    </message>
</context>
<context>
    <name>CandumpLog</name>
    <message>
        <location filename="../core/can/CandumpLog.cpp" line="+52"/>
        <source>the line must start with a timestamp in parentheses, e.g. (1700000000.123456)</source>
        <translation>die Zeile muss mit einem Zeitstempel in Klammern beginnen, z. B. (1700000000.123456)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&quot;%1&quot; is not a timestamp of the form (seconds.microseconds)</source>
        <translation>„%1“ ist kein Zeitstempel der Form (Sekunden.Mikrosekunden)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&quot;%1&quot; has no &apos;#&apos; between identifier and data</source>
        <translation>„%1“ hat kein &apos;#&apos; zwischen Identifier und Daten</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>CAN FD frames are not supported</source>
        <translation>CAN-FD-Frames werden nicht unterstützt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&quot;%1&quot; is not an identifier of 3 (standard) or 8 (extended) hex digits</source>
        <translation>„%1“ ist kein Identifier aus 3 (Standard) oder 8 (erweitert) Hexadezimalziffern</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the standard identifier %1 exceeds 7FF</source>
        <translation>der Standard-Identifier %1 überschreitet 7FF</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the extended identifier %1 exceeds 1FFFFFFF</source>
        <translation>der erweiterte Identifier %1 überschreitet 1FFFFFFF</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&quot;%1&quot; is not a remote request (R, optionally with a length 0 to 8)</source>
        <translation>„%1“ ist keine Remote-Anfrage (R, wahlweise mit einer Länge 0 bis 8)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&quot;%1&quot; is not data of whole bytes in hex digits</source>
        <translation>„%1“ sind keine Daten aus ganzen Bytes in Hexadezimalziffern</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 data bytes; a classic CAN frame carries at most 8</source>
        <translation>%1 Datenbytes; ein klassischer CAN-Frame trägt höchstens 8</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>expected &quot;(timestamp) interface id#data&quot;, found %1 fields</source>
        <translation>erwartet „(Zeitstempel) Schnittstelle id#Daten“, gefunden: %1 Felder</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unexpected text after the frame: &quot;%1&quot;</source>
        <translation>unerwarteter Text nach dem Frame: „%1“</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Cannot open the candump log %1: %2</source>
        <translation>Das candump-Log %1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Writing the candump log failed: %1</source>
        <translation>Schreiben des candump-Logs fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Cannot write the candump log %1: %2</source>
        <translation>Das candump-Log %1 kann nicht geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>CartesianLine</name>
    <message>
        <location filename="../core/motion/CartesianLine.cpp" line="+53"/>
        <source>a planar line needs 2 joints</source>
        <translation>eine ebene Gerade braucht 2 Gelenke</translation>
    </message>
    <message>
        <location filename="../core/motion/MotionTiming.cpp" line="+16"/>
        <source>invalid timing: sample period and duration must be positive, rests non-negative, the sample offset within the period</source>
        <translation>ungültiger Zeitablauf: Abtastzeit und Dauer müssen positiv sein, Ruhezeiten nicht negativ, der Abtastversatz innerhalb der Abtastzeit</translation>
    </message>
</context>
<context>
    <name>ChainDynamics</name>
    <message>
        <location filename="../core/model/ChainDynamics.cpp" line="+48"/>
        <source>%1 has %2 moving joints: a chain needs 1 to %3</source>
        <translation>%1 hat %2 bewegliche Gelenke: eine Kette braucht 1 bis %3</translation>
    </message>
</context>
<context>
    <name>ChainModel</name>
    <message>
        <location filename="../core/model/ChainParameterInfo.cpp" line="+32"/>
        <source>link %1 (%2)</source>
        <translation>Glied %1 (%2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>mass of link %1</source>
        <translation>Masse des Glieds %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>first moment of mass of link %1 along its %2 axis</source>
        <translation>statisches Moment des Glieds %1 entlang seiner %2-Achse</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>inertia %1 of link %2 about its frame origin</source>
        <translation>Trägheit %1 des Glieds %2 um den Ursprung seines Koordinatensystems</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>rotor inertia at joint %1</source>
        <translation>Rotorträgheit am Gelenk %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>viscous friction of joint %1</source>
        <translation>viskose Reibung des Gelenks %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Coulomb friction of joint %1</source>
        <translation>Coulomb-Reibung des Gelenks %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>torque offset of joint %1</source>
        <translation>Drehmoment-Offset des Gelenks %1</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>joint %1 (%2)</source>
        <translation>Gelenk %1 (%2)</translation>
    </message>
    <message>
        <location filename="../core/model/ChainModel.cpp" line="+55"/>
        <source>the Coulomb friction&apos;s velocity scale must be positive (it is %1)</source>
        <translation>die Geschwindigkeitsskala der Coulomb-Reibung muss positiv sein (sie ist %1)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>a combination led by the %1</source>
        <translation>eine Kombination, angeführt von: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 has %2 moving joints, the model %3 has %4</source>
        <translation>%1 hat %2 bewegliche Gelenke, das Modell %3 hat %4</translation>
    </message>
</context>
<context>
    <name>Cia402</name>
    <message>
        <location filename="../core/can/Cia402.cpp" line="+34"/>
        <source>Not ready to switch on</source>
        <translation>Nicht einschaltbereit</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Switch on disabled</source>
        <translation>Einschaltsperre</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Ready to switch on</source>
        <translation>Einschaltbereit</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Switched on</source>
        <translation>Eingeschaltet</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Operation enabled</source>
        <translation>Betrieb freigegeben</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Quick stop active</source>
        <translation>Schnellhalt aktiv</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Fault reaction active</source>
        <translation>Fehlerreaktion aktiv</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Fault</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Unknown drive state</source>
        <translation>Unbekannter Antriebszustand</translation>
    </message>
</context>
<context>
    <name>CommissioningSession</name>
    <message>
        <location filename="../core/session/TrialPlanner.cpp" line="+119"/>
        <source>scenario does not fit the %1 model: it needs %2 parameters and %3 joint limits and gains</source>
        <translation>Szenario passt nicht zum Modell %1: es braucht %2 Parameter und %3 Gelenkgrenzen und Verstärkungen</translation>
    </message>
</context>
<context>
    <name>ControllerLogCsv</name>
    <message>
        <location filename="../core/io/ControllerLogCsv.cpp" line="+56"/>
        <source>&quot;# stopped-by:&quot; says %1; known: %2</source>
        <translation>&quot;# stopped-by:&quot; sagt %1; bekannt: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nothing</source>
        <translation>nichts</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: no &quot;# plan-id:&quot; comment line; the controller copies the plan&apos;s line &quot;# plan-id: %2&quot; into its log</source>
        <translation>%1: keine Kommentarzeile „# plan-id:“; der Regler übernimmt die Zeile „# plan-id: %2“ des Plans in sein Log</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the log is of plan %2, not of plan %3</source>
        <translation>%1: das Log gehört zu Plan %2, nicht zu Plan %3</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>sample %1 (t = %2 s) is beyond the plan&apos;s %3 samples, the last at t = %4 s</source>
        <translation>Abtastwert %1 (t = %2 s) liegt hinter den %3 Abtastwerten des Plans, deren letzter bei t = %4 s liegt</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>t = %1 s is off the plan&apos;s grid: sample %2 is planned at t = %3 s (+-%4 s); a log holds every sample of the plan, at the plan&apos;s times</source>
        <translation>t = %1 s liegt nicht im Zeitraster des Plans: Abtastwert %2 ist bei t = %3 s (+-%4 s) geplant; ein Log enthält jeden Abtastwert des Plans, zu den Zeiten des Plans</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>the log ends after %1 of the plan&apos;s %2 samples (t = %3 s of %4 s): the controller stopped the trial at its tracking limit</source>
        <translation>das Protokoll endet nach %1 der %2 Abtastwerte des Plans (t = %3 s von %4 s): die Steuerung hat den Versuch an ihrer Grenze des Folgefehlers angehalten</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the log ends after %1 of the plan&apos;s %2 samples (t = %3 s of %4 s): the trial ended early</source>
        <translation>das Log endet nach %1 der %2 Abtastwerte des Plans (t = %3 s von %4 s): der Versuch endete vorzeitig</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&quot;# stopped-by:&quot; in a log of all the plan&apos;s %1 samples: a trial that ran to its end was not stopped</source>
        <translation>&quot;# stopped-by:&quot; in einem Protokoll aller %1 Abtastwerte des Plans: ein Versuch, der bis zum Ende lief, wurde nicht angehalten</translation>
    </message>
</context>
<context>
    <name>CsvPlace</name>
    <message>
        <location filename="../core/io/CsvPlace.cpp" line="+21"/>
        <source>%1: line %2, column %3</source>
        <translation>%1: Zeile %2, Spalte %3</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: line %2: %3</source>
        <translation>%1: Zeile %2: %3</translation>
    </message>
</context>
<context>
    <name>EmcyConsumer</name>
    <message>
        <location filename="../core/can/EmcyConsumer.cpp" line="+26"/>
        <source>error reset or no error</source>
        <translation>Fehler zurückgesetzt oder kein Fehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>generic error</source>
        <translation>allgemeiner Fehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+45"/>
        <source>current</source>
        <translation>Strom</translation>
    </message>
    <message>
        <location line="-44"/>
        <source>current, device input side</source>
        <translation>Strom, Geräteeingangsseite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>current inside the device</source>
        <translation>Strom im Gerät</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>current, device output side</source>
        <translation>Strom, Geräteausgangsseite</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>continuous over-current</source>
        <translation>Dauerüberstrom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>short circuit or earth leakage</source>
        <translation>Kurzschluss oder Erdschluss</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+40"/>
        <source>voltage</source>
        <translation>Spannung</translation>
    </message>
    <message>
        <location line="-39"/>
        <source>mains voltage</source>
        <translation>Netzspannung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>voltage inside the device</source>
        <translation>Spannung im Gerät</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DC link over-voltage</source>
        <translation>Zwischenkreisüberspannung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DC link under-voltage</source>
        <translation>Zwischenkreisunterspannung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>output voltage</source>
        <translation>Ausgangsspannung</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+35"/>
        <source>temperature</source>
        <translation>Temperatur</translation>
    </message>
    <message>
        <location line="-34"/>
        <source>ambient temperature</source>
        <translation>Umgebungstemperatur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device temperature</source>
        <translation>Gerätetemperatur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>drive excess temperature</source>
        <translation>Übertemperatur des Antriebs</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device hardware</source>
        <translation>Gerätehardware</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device software</source>
        <translation>Gerätesoftware</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>internal software</source>
        <translation>interne Software</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>user software</source>
        <translation>Anwendersoftware</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data set</source>
        <translation>Datensatz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>additional modules</source>
        <translation>Zusatzmodule</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sensor</source>
        <translation>Sensor</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>incremental sensor 1 fault</source>
        <translation>Fehler Inkrementalgeber 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>monitoring</source>
        <translation>Überwachung</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+23"/>
        <source>communication</source>
        <translation>Kommunikation</translation>
    </message>
    <message>
        <location line="-22"/>
        <source>CAN overrun (objects lost)</source>
        <translation>CAN-Überlauf (Objekte verloren)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN in error passive mode</source>
        <translation>CAN im Zustand Error Passive</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>life guard or heartbeat error</source>
        <translation>Life-Guarding- oder Heartbeat-Fehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>recovered from bus off</source>
        <translation>von Bus-Off erholt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN-ID collision</source>
        <translation>CAN-ID-Kollision</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>protocol error</source>
        <translation>Protokollfehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDO not processed due to length error</source>
        <translation>PDO wegen Längenfehler nicht verarbeitet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDO length exceeded</source>
        <translation>PDO-Länge überschritten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unexpected SYNC data length</source>
        <translation>unerwartete SYNC-Datenlänge</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RPDO timeout</source>
        <translation>RPDO-Zeitüberschreitung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>positioning controller</source>
        <translation>Lageregler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>following error</source>
        <translation>Schleppfehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>external error</source>
        <translation>externer Fehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>additional functions</source>
        <translation>Zusatzfunktionen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device specific</source>
        <translation>gerätespezifisch</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>generic</source>
        <translation>allgemein</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>device profile</source>
        <translation>Geräteprofil</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reserved</source>
        <translation>reserviert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>manufacturer</source>
        <translation>herstellerspezifisch</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>unknown error code</source>
        <translation>unbekannter Fehlercode</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>no error</source>
        <translation>kein Fehler</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Node %1 emergency %2: %3; error register %4: %5; manufacturer data %6</source>
        <translation>Knoten %1 EMCY %2: %3; Fehlerregister %4: %5; Herstellerdaten %6</translation>
    </message>
</context>
<context>
    <name>EstimateConsistency</name>
    <message>
        <location filename="../core/session/EstimateConsistency.cpp" line="+148"/>
        <source>not physically consistent</source>
        <translation>physikalisch nicht konsistent</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>physically consistent (every link a real body) but not plausible</source>
        <translation>physikalisch konsistent (jedes Glied ein realer Körper), aber nicht plausibel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>physically consistent and plausible: every link a real body that a robot&apos;s link could be</source>
        <translation>physikalisch konsistent und plausibel: jedes Glied ein realer Körper, der das Glied eines Roboters sein könnte</translation>
    </message>
</context>
<context>
    <name>FileLoop</name>
    <message>
        <location filename="../core/service/FileLoop.cpp" line="+35"/>
        <source>unknown robot model &quot;%1&quot;</source>
        <translation>unbekanntes Robotermodell „%1“</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>cannot create the folder %1</source>
        <translation>Ordner %1 kann nicht angelegt werden</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>the history %1 is of robot %2 (%3 joints, %4 parameters), the scenario&apos;s robot is %5 (%6 joints, %7 parameters)</source>
        <translation>der Verlauf %1 gehört zum Roboter %2 (%3 Gelenke, %4 Parameter), der Roboter des Szenarios ist %5 (%6 Gelenke, %7 Parameter)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the history %1 was made by the arm&apos;s learning loop (a scenario without a payload section); the scenario learns a payload: give another --history for the payload&apos;s loop</source>
        <translation>der Verlauf %1 stammt aus der Lernschleife des Arms (ein Szenario ohne payload-Abschnitt); das Szenario lernt eine Nutzlast: für die Schleife der Nutzlast eine andere --history angeben</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the history %1 learns the payload on %2 (a scenario with a payload section); the scenario learns the arm: give another --history for the arm&apos;s loop</source>
        <translation>der Verlauf %1 lernt die Nutzlast an %2 (ein Szenario mit payload-Abschnitt); das Szenario lernt den Arm: für die Schleife des Arms eine andere --history angeben</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the history %1 learns with the law %2, the scenario with %3: a history keeps its law (start a new history for another)</source>
        <translation>der Verlauf %1 lernt mit dem Gesetz %2, das Szenario mit %3: ein Verlauf behält sein Gesetz (für ein anderes einen neuen Verlauf beginnen)</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>trial %1: check passed, the trial may run.</source>
        <translation>Versuch %1: Prüfung bestanden, der Versuch darf laufen.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>trial %1 refused: %2</source>
        <translation>Versuch %1 abgelehnt: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>feedforward built with: %1</source>
        <translation>Vorsteuerung berechnet mit: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>planned motion: %1 s, %2 s with rests, %3 samples of %4 s</source>
        <translation>geplante Bewegung: %1 s, %2 s mit Ruhezeiten, %3 Abtastwerte zu je %4 s</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>closed loop: estimate not physical (mass matrix not positive definite)</source>
        <translation>Regelkreis: Schätzung nicht physikalisch (Massenmatrix nicht positiv definit)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>closed loop: stable, max |z| = %1, decay rate %2 1/s</source>
        <translation>Regelkreis: stabil, max |z| = %1, Abklingrate %2 1/s</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>closed loop: UNSTABLE, max |z| = %1 at t = %2 s (growth %3 1/s)</source>
        <translation>Regelkreis: INSTABIL, max |z| = %1 bei t = %2 s (Anstieg %3 1/s)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>joint   peak [N m]  limit [N m]     use</source>
        <translation> Gel. Spitze [N m] Grenze [N m]   Ausl.</translation>
    </message>
    <message>
        <location filename="../core/service/FileLoopParts.cpp" line="+78"/>
        <source>%1: plan %2 is not the plan %3 that trial %4 of the history ran</source>
        <translation>%1: Plan %2 ist nicht der Plan %3, mit dem Versuch %4 des Verlaufs lief</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>%1 holds no learning history (no %2): plan the trial with `learnid-cli plan` into this history, or give its --history</source>
        <translation>%1 enthält keinen Lernverlauf (kein %2): den Versuch mit `learnid-cli plan` in diesen Verlauf planen oder dessen --history angeben</translation>
    </message>
    <message>
        <location line="-56"/>
        <source>%1: no &quot;# plan-id:&quot; comment line; the controller copies the plan&apos;s &quot;# plan-id:&quot; line into its log</source>
        <translation>%1: keine Kommentarzeile „# plan-id:“; der Regler übernimmt die Zeile „# plan-id:“ des Plans in sein Log</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 ran plan %2, %3 plan %4: the logs of one learning step are of one plan</source>
        <translation>%1 lief mit Plan %2, %3 mit Plan %4: die Logs eines Lernschritts gehören zu einem Plan</translation>
    </message>
    <message>
        <location filename="../core/service/FileLoopLearn.cpp" line="+42"/>
        <source>the scenario runs every trial %1 times (repetitions): give one --trial-log per run, %2 given</source>
        <translation>das Szenario führt jeden Versuch %1-mal aus (repetitions): ein --trial-log pro Durchlauf angeben, %2 angegeben</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 was made with another estimate than the history&apos;s newest (estimate %2): plan the next trial again</source>
        <translation>%1 wurde mit einer anderen Schätzung als der neuesten des Verlaufs (Schätzung %2) erstellt: den nächsten Versuch neu planen</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1: %2; nothing learned</source>
        <translation>%1: %2; nichts gelernt</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>the history %1 does not replay: trial %2: %3</source>
        <translation>der Verlauf %1 lässt sich nicht wiedergeben: Versuch %2: %3</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 is not the estimate %2 that the history&apos;s trials give with this scenario: is its estimator the history&apos;s?</source>
        <translation>%1 ist nicht die Schätzung %2, die die Versuche des Verlaufs mit diesem Szenario ergeben: ist sein Schätzer der des Verlaufs?</translation>
    </message>
    <message>
        <location filename="../core/service/FileLoopPlan.cpp" line="+31"/>
        <source>initial estimate of a learning loop through files</source>
        <translation>Anfangsschätzung einer Lernschleife über Dateien</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>--estimate: the history %1 has learned from %2 trials; its next trial runs with its newest estimate (leave out --estimate, or give another --history to start a new history)</source>
        <translation>--estimate: der Verlauf %1 hat aus %2 Versuchen gelernt; sein nächster Versuch läuft mit seiner neuesten Schätzung (--estimate weglassen oder ein anderes --history angeben, um einen neuen Verlauf zu beginnen)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>estimate %1 of %2</source>
        <translation>Schätzung %1 aus %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the scenario&apos;s initial estimate</source>
        <translation>die Anfangsschätzung des Szenarios</translation>
    </message>
    <message>
        <location filename="../core/service/FileLoopPayload.cpp" line="+39"/>
        <source>the history %1 learns the payload on %2, the scenario&apos;s payload.link is %3: a history keeps its link (give another --history for another)</source>
        <translation>der Verlauf %1 lernt die Nutzlast an %2, payload.link des Szenarios ist %3: ein Verlauf behält sein Glied (für ein anderes eine andere --history angeben)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the history %1 does not replay: %2</source>
        <translation>der Verlauf %1 lässt sich nicht wiedergeben: %2</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>the arm held fixed and the payload learned from the trials up to trial %1: estimate %2 of a payload&apos;s learning loop through files</source>
        <translation>der festgehaltene Arm und die aus den Versuchen bis Versuch %1 gelernte Nutzlast: Schätzung %2 einer Lernschleife der Nutzlast über Dateien</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the arm held fixed and the payload&apos;s prior: estimate %1 of a payload&apos;s learning loop through files</source>
        <translation>der festgehaltene Arm und die Vorgabe der Nutzlast: Schätzung %1 einer Lernschleife der Nutzlast über Dateien</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>%1 holds another arm model than the scenario&apos;s robot.initialParameters: a history keeps the arm it learns the payload on</source>
        <translation>%1 enthält ein anderes Armmodell als robot.initialParameters des Szenarios: ein Verlauf behält den Arm, an dem er die Nutzlast lernt</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 holds another payload prior than the scenario&apos;s payload section: a history keeps its prior</source>
        <translation>%1 enthält eine andere Vorgabe der Nutzlast als der payload-Abschnitt des Szenarios: ein Verlauf behält seine Vorgabe</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 is not the payload estimate %2 that the history&apos;s trials give with this scenario: are its payload section and estimator the history&apos;s?</source>
        <translation>%1 ist nicht die Nutzlastschätzung %2, die die Versuche des Verlaufs mit diesem Szenario ergeben: sind sein payload-Abschnitt und sein Schätzer die des Verlaufs?</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the path determines %1 of the payload&apos;s 10 parameters on %2</source>
        <translation>der Pfad bestimmt %1 der 10 Parameter der Nutzlast an %2</translation>
    </message>
    <message>
        <location filename="../core/service/FileLoopPayloadLearn.cpp" line="+33"/>
        <source>a payload&apos;s learning loop runs every trial once (estimator.repetitions does not apply to it): give one --trial-log, %1 given</source>
        <translation>die Lernschleife einer Nutzlast führt jeden Versuch einmal aus (estimator.repetitions gilt für sie nicht): ein --trial-log angeben, %1 angegeben</translation>
    </message>
    <message>
        <location filename="../core/service/FileLoopPayloadPlan.cpp" line="+23"/>
        <source>the arm&apos;s model held fixed (robot.initialParameters) alone: trial %1 is a baseline trial (payload.baselineTrials), run it WITHOUT the payload mounted</source>
        <translation>allein das festgehaltene Armmodell (robot.initialParameters): Versuch %1 ist eine Referenzfahrt (payload.baselineTrials), ihn OHNE montierte Nutzlast ausführen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the arm&apos;s model held fixed (robot.initialParameters) and the payload learned from the trials up to trial %1 (estimate %2 of %3)</source>
        <translation>das festgehaltene Armmodell (robot.initialParameters) und die aus den Versuchen bis Versuch %1 gelernte Nutzlast (Schätzung %2 aus %3)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the arm&apos;s model held fixed (robot.initialParameters) and the payload&apos;s prior (payload section)</source>
        <translation>das festgehaltene Armmodell (robot.initialParameters) und die Vorgabe der Nutzlast (payload-Abschnitt)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--estimate: a scenario with a payload section plans with the arm&apos;s model it holds fixed (robot.initialParameters) and the payload its history has learned, the prior (payload section) first: leave out --estimate</source>
        <translation>--estimate: ein Szenario mit payload-Abschnitt plant mit dem Armmodell, das es festhält (robot.initialParameters), und der Nutzlast, die sein Verlauf gelernt hat, zuerst der Vorgabe (payload-Abschnitt): --estimate weglassen</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 (give another --history to start anew)</source>
        <translation>%1 (für einen Neubeginn eine andere --history angeben)</translation>
    </message>
</context>
<context>
    <name>JointPath</name>
    <message>
        <location filename="../core/motion/JointPath.cpp" line="+38"/>
        <source>waypoint path: %1 waypoints; a path needs at least 2</source>
        <translation>Wegpunktbahn: %1 Wegpunkte; eine Bahn braucht mindestens 2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>waypoint path: waypoint 0 has no joints</source>
        <translation>Wegpunktbahn: Wegpunkt 0 hat keine Gelenke</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>waypoint path: waypoint %1 has %2 joints, waypoint 0 has %3</source>
        <translation>Wegpunktbahn: Wegpunkt %1 hat %2 Gelenke, Wegpunkt 0 hat %3</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>waypoint path: waypoint %1: joint %2 is %3, not a finite angle</source>
        <translation>Wegpunktbahn: Wegpunkt %1: Gelenk %2 ist %3, kein endlicher Winkel</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>waypoint path: waypoints %1 and %2 are equal or too close to tell apart (largest joint difference %3 rad); the path stops at every waypoint already, remove the repeat</source>
        <translation>Wegpunktbahn: die Wegpunkte %1 und %2 sind gleich oder zu nah beieinander, um sie zu unterscheiden (größte Gelenkdifferenz %3 rad); die Bahn hält ohnehin an jedem Wegpunkt, die Wiederholung entfernen</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>recorded path: %1 sample times but %2 samples of the joints</source>
        <translation>aufgezeichnete Bahn: %1 Abtastzeitpunkte, aber %2 Abtastwerte der Gelenke</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>recorded path: %1 samples; a path needs at least 4</source>
        <translation>aufgezeichnete Bahn: %1 Abtastwerte; eine Bahn braucht mindestens 4</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>recorded path: the samples have no joints</source>
        <translation>aufgezeichnete Bahn: die Abtastwerte haben keine Gelenke</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>recorded path: sample %1: the time is %2, not a finite number</source>
        <translation>aufgezeichnete Bahn: Abtastwert %1: die Zeit ist %2, keine endliche Zahl</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>recorded path: sample %1: the time %2 s does not increase from sample %3 (%4 s)</source>
        <translation>aufgezeichnete Bahn: Abtastwert %1: die Zeit %2 s ist nicht größer als bei Abtastwert %3 (%4 s)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>recorded path: sample %1: joint %2 is %3, not a finite angle</source>
        <translation>aufgezeichnete Bahn: Abtastwert %1: Gelenk %2 ist %3, kein endlicher Winkel</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>recorded path: the sample times are too close to fit a spline</source>
        <translation>aufgezeichnete Bahn: die Abtastzeitpunkte liegen zu nah beieinander, um einen Spline anzupassen</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>joint path: the duration must be positive and finite, the time finite, and the state have %1 joints</source>
        <translation>Gelenkbahn: die Dauer muss positiv und endlich sein, die Zeit endlich, und der Zustand muss %1 Gelenke haben</translation>
    </message>
</context>
<context>
    <name>JsonReader</name>
    <message>
        <location filename="../core/io/JsonReader.cpp" line="+90"/>
        <source>%1 (beyond the range of a double)</source>
        <translation>%1 (außerhalb des Wertebereichs von double)</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+45"/>
        <source>an array</source>
        <translation>ein Array</translation>
    </message>
    <message>
        <location line="-43"/>
        <source>an object</source>
        <translation>ein Objekt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>nothing</source>
        <translation>nichts</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>an integer from %1 to %2</source>
        <translation>eine ganze Zahl von %1 bis %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: the file is empty; expected a JSON object</source>
        <translation>%1: die Datei ist leer; erwartet wird ein JSON-Objekt</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1: invalid JSON at line %2, column %3 (byte offset %4): %5</source>
        <translation>%1: ungültiges JSON in Zeile %2, Spalte %3 (Byte-Offset %4): %5</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: the top level must be a JSON object, got %2</source>
        <translation>%1: die oberste Ebene muss ein JSON-Objekt sein, gefunden: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a single value</source>
        <translation>ein einzelner Wert</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>must be a finite number, got %1, which is beyond the range of a double</source>
        <translation>muss eine endliche Zahl sein, gefunden: %1, außerhalb des Wertebereichs von double</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>must be a number, got %1</source>
        <translation>muss eine Zahl sein, gefunden: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>must be a finite number, got %1</source>
        <translation>muss eine endliche Zahl sein, gefunden: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+32"/>
        <source>must be %1, got %2</source>
        <translation>muss %1 sein, gefunden: %2</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>must be a string, got %1</source>
        <translation>muss eine Zeichenkette sein, gefunden: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 or %2</source>
        <translation>%1 oder %2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>must be true or false, got %1</source>
        <translation>muss true oder false sein, gefunden: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>must be an array, got %1</source>
        <translation>muss ein Array sein, gefunden: %1</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>must be an object, got %1</source>
        <translation>muss ein Objekt sein, gefunden: %1</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>is missing; this key is required</source>
        <translation>fehlt; dieser Schlüssel ist erforderlich</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>unknown key; allowed here: %1</source>
        <translation>unbekannter Schlüssel; hier erlaubt: %1</translation>
    </message>
</context>
<context>
    <name>LearningLaw</name>
    <message>
        <location filename="../core/identify/ImprovedLaw.cpp" line="+61"/>
        <location filename="../core/identify/PaperLaw.cpp" line="+44"/>
        <source>trial record has only %1 samples to learn from</source>
        <translation>die Versuchsaufzeichnung hat nur %1 Abtastwerte zum Lernen</translation>
    </message>
    <message>
        <location line="+87"/>
        <location filename="../core/identify/PaperLaw.cpp" line="-26"/>
        <source>no completed trial to learn from</source>
        <translation>kein abgeschlossener Versuch, aus dem gelernt werden kann</translation>
    </message>
    <message>
        <location filename="../core/identify/LearningLaw.cpp" line="+87"/>
        <source>trial record does not match its plan: %1 of %2 samples, %3 joints recorded for a %4-joint model</source>
        <translation>Versuchsaufzeichnung passt nicht zu ihrem Plan: %1 von %2 Abtastwerten, %3 Gelenke aufgezeichnet für ein Modell mit %4 Gelenken</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>trial record has only %1 samples</source>
        <translation>Versuchsaufzeichnung hat nur %1 Abtastwerte</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>trial record has a non-finite %1 at sample %2, joint %3</source>
        <translation>Versuchsaufzeichnung hat einen nicht endlichen Wert (%1) bei Abtastwert %2, Gelenk %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>torque</source>
        <translation>Moment</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>angle</source>
        <translation>Winkel</translation>
    </message>
</context>
<context>
    <name>LinkVerdictTable</name>
    <message>
        <location filename="../core/session/LinkVerdictTable.cpp" line="+25"/>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Per link: physically consistent (a real body), and plausible (a body a robot&apos;s link could be: its smallest principal moment of inertia about the centre of mass I1 at least %1 % of the CAD link&apos;s, (I1 + I2) / I3 at least %2, the centre of mass inside the link&apos;s bounding volume).</source>
        <translation>Je Glied: physikalisch konsistent (ein realer Körper) und plausibel (ein Körper, der das Glied eines Roboters sein könnte: sein kleinstes Hauptträgheitsmoment um den Schwerpunkt I1 mindestens %1 % des kleinsten des CAD-Glieds, (I1 + I2) / I3 mindestens %2, der Schwerpunkt innerhalb des Hüllvolumens des Glieds).</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>link</source>
        <translation>Glied</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>I1 [kg m^2]</source>
        <translation>I1 [kg m^2]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CAD I1 [kg m^2]</source>
        <translation>CAD-I1 [kg m^2]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>(I1 + I2) / I3</source>
        <translation>(I1 + I2) / I3</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CoM in volume</source>
        <translation>Schwerpunkt im Volumen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>consistent</source>
        <translation>konsistent</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>plausible</source>
        <translation>plausibel</translation>
    </message>
</context>
<context>
    <name>LogFit</name>
    <message>
        <location filename="../core/identify/LogFit.cpp" line="+141"/>
        <source>%1 has %2 joints, the robot %3</source>
        <translation>%1 hat %2 Gelenke, der Roboter %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the filtered signals are not finite</source>
        <translation>%1: die gefilterten Signale sind nicht endlich</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no samples to fit</source>
        <translation>keine Abtastwerte für die Anpassung</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the prior share must lie between 0 and 1</source>
        <translation>der Prior-Anteil muss zwischen 0 und 1 liegen</translation>
    </message>
    <message>
        <location line="+98"/>
        <source>%1 does not fit the robot&apos;s joints or parameters</source>
        <translation>%1 passt nicht zu den Gelenken oder Parametern des Roboters</translation>
    </message>
</context>
<context>
    <name>LogIdentification</name>
    <message>
        <location filename="../core/service/LogIdentification.cpp" line="+81"/>
        <source>identification cancelled; nothing was produced</source>
        <translation>Identifikation abgebrochen; nichts wurde erzeugt</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>the robot &apos;%1&apos; is neither a URDF file nor a built-in robot (%2)</source>
        <translation>der Roboter &apos;%1&apos; ist weder eine URDF-Datei noch ein eingebauter Roboter (%2)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>built-in %1</source>
        <translation>eingebauter Roboter %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>no log to identify from: add a training log</source>
        <translation>kein Log zum Identifizieren: ein Trainings-Log hinzufügen</translation>
    </message>
    <message>
        <location filename="../core/service/LogIdentificationExport.cpp" line="+26"/>
        <source>%1 (%2), identified from the logs %3</source>
        <translation>%1 (%2), identifiziert aus den Logs %3</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>the controller gains the parameter file records are for %1 joints, the robot has %2</source>
        <translation>die Reglerverstärkungen, die die Parameterdatei festhält, gelten für %1 Gelenke, der Roboter hat %2</translation>
    </message>
</context>
<context>
    <name>LogIdentificationSummary</name>
    <message>
        <location filename="../core/service/LogIdentificationSummary.cpp" line="+21"/>
        <source>Of the %1 standard parameters, any data could determine at most %2 combinations (the base parameters); these logs determine all %2 (condition %3).</source>
        <translation>Von den %1 Standardparametern könnten beliebige Daten höchstens %2 Kombinationen bestimmen (die Basisparameter); diese Logs bestimmen alle %2 (Kondition %3).</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>Of the %1 standard parameters, any data could determine at most %2 combinations (the base parameters); these logs determine %3 of those %2 directions (condition %4), the other %n stay near the URDF&apos;s values.</source>
        <translation>
            <numerusform>Von den %1 Standardparametern könnten beliebige Daten höchstens %2 Kombinationen bestimmen (die Basisparameter); diese Logs bestimmen %3 dieser %2 Richtungen (Kondition %4), die übrige %n Richtung bleibt nahe den Werten des URDF.</numerusform>
            <numerusform>Von den %1 Standardparametern könnten beliebige Daten höchstens %2 Kombinationen bestimmen (die Basisparameter); diese Logs bestimmen %3 dieser %2 Richtungen (Kondition %4), die übrigen %n bleiben nahe den Werten des URDF.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>%n of the %1 base parameters are mostly undetermined by these logs (less than half determined) and kept near the URDF&apos;s values: %2.</source>
        <translation>
            <numerusform>%n der %1 Basisparameter ist durch diese Logs überwiegend unbestimmt (weniger als zur Hälfte bestimmt) und bleibt nahe den Werten des URDF: %2.</numerusform>
            <numerusform>%n der %1 Basisparameter sind durch diese Logs überwiegend unbestimmt (weniger als zur Hälfte bestimmt) und bleiben nahe den Werten des URDF: %2.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+6"/>
        <source>None of the %1 base parameters is mostly undetermined by these logs.</source>
        <translation>Keiner der %1 Basisparameter ist durch diese Logs überwiegend unbestimmt.</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>None of the %1 base parameters is mostly undetermined by these logs: the %n direction(s) they miss are shared among several.</source>
        <translation>
            <numerusform>Keiner der %1 Basisparameter ist durch diese Logs überwiegend unbestimmt: die %n Richtung, die sie nicht bestimmen, verteilt sich auf mehrere.</numerusform>
            <numerusform>Keiner der %1 Basisparameter ist durch diese Logs überwiegend unbestimmt: die %n Richtungen, die sie nicht bestimmen, verteilen sich auf mehrere.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>%n stale row(s) (values repeated under a new time stamp) treated as missing</source>
        <translation>
            <numerusform>%n veraltete Zeile (Werte unter neuem Zeitstempel wiederholt) als fehlend behandelt</numerusform>
            <numerusform>%n veraltete Zeilen (Werte unter neuem Zeitstempel wiederholt) als fehlend behandelt</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%n row(s) written twice (the same time stamp and values) dropped</source>
        <translation>
            <numerusform>%n doppelt geschriebene Zeile (gleicher Zeitstempel, gleiche Werte) verworfen</numerusform>
            <numerusform>%n doppelt geschriebene Zeilen (gleicher Zeitstempel, gleiche Werte) verworfen</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2.</source>
        <translation>%1: %2.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 (URDF robot &quot;%2&quot;)</source>
        <translation>%1 (URDF-Roboter „%2“)</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>%1 in %2, %n moving joint(s).</source>
        <translation>
            <numerusform>%1 in %2, %n bewegliches Gelenk.</numerusform>
            <numerusform>%1 in %2, %n bewegliche Gelenke.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%1 (built-in), %n moving joint(s).</source>
        <translation>
            <numerusform>%1 (eingebaut), %n bewegliches Gelenk.</numerusform>
            <numerusform>%1 (eingebaut), %n bewegliche Gelenke.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Fitted to %n log(s), %1 samples; %2.</source>
        <translation>
            <numerusform>An %n Log angepasst, %1 Abtastwerte; %2.</numerusform>
            <numerusform>An %n Logs angepasst, %1 Abtastwerte; %2.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the consistent fit converged</source>
        <translation>die konsistente Anpassung ist konvergiert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the consistent fit stopped at its step limit</source>
        <translation>die konsistente Anpassung hielt an ihrer Schrittgrenze an</translation>
    </message>
</context>
<context>
    <name>LogIdentificationText</name>
    <message>
        <location filename="../ui/LogIdentificationText.cpp" line="+56"/>
        <source>Reading the robot %1…</source>
        <translation>Roboter %1 wird gelesen…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reading training log %1 of %2: %3…</source>
        <translation>Trainings-Log %1 von %2 wird gelesen: %3…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reading validation log %1 of %2: %3…</source>
        <translation>Validierungs-Log %1 von %2 wird gelesen: %3…</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Fitting the parameters to %n log(s)…</source>
        <translation>
            <numerusform>Die Parameter werden an %n Log angepasst…</numerusform>
            <numerusform>Die Parameter werden an %n Logs angepasst…</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Predicting validation log %1 of %2: %3…</source>
        <translation>Validierungs-Log %1 von %2 wird vorhergesagt: %3…</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>&lt;p&gt;&lt;b&gt;Identified parameters:&lt;/b&gt; &lt;span style=&quot;color:%1&quot;&gt;%2&lt;/span&gt;&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Identifizierte Parameter:&lt;/b&gt; &lt;span style=&quot;color:%1&quot;&gt;%2&lt;/span&gt;&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&lt;p&gt;&lt;b&gt;Training residual&lt;/b&gt;, RMS per joint [N m]: %1&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Trainingsresiduum&lt;/b&gt;, RMS pro Gelenk [N m]: %1&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&lt;p style=&quot;color:#8a5300&quot;&gt;&lt;b&gt;Warning:&lt;/b&gt; the URDF as a real robot: %1&lt;/p&gt;</source>
        <translation>&lt;p style=&quot;color:#8a5300&quot;&gt;&lt;b&gt;Warnung:&lt;/b&gt; das URDF als realer Roboter: %1&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Identified; no validation log. Accept the result to export it.</source>
        <translation>Identifiziert; kein Validierungs-Log. Das Ergebnis akzeptieren, um es zu exportieren.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Identified: on %1 the torque error is %2 % of the measured torque (URDF as given: %3 %). Accept the result to export it.</source>
        <translation>Identifiziert: an %1 beträgt der Momentenfehler %2 % des gemessenen Moments (URDF wie gegeben: %3 %). Das Ergebnis akzeptieren, um es zu exportieren.</translation>
    </message>
</context>
<context>
    <name>LogSignals</name>
    <message>
        <location filename="../core/identify/LogSignals.cpp" line="+57"/>
        <source>the log filter needs positive bandwidths, a stride of 1 or more and a torque sensor lag of 0 s or more</source>
        <translation>der Log-Filter braucht positive Bandbreiten, eine Schrittweite von 1 oder mehr und eine Verzögerung der Drehmomentsensoren von 0 s oder mehr</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the log has no measured velocities (dq columns) to use</source>
        <translation>%1: das Log hat keine gemessenen Geschwindigkeiten (dq-Spalten), die verwendet werden könnten</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: %2 s of data is too short: the filter (bandwidth %3 rad/s) needs %4 s at each end to settle, and some data between</source>
        <translation>%1: %2 s Daten sind zu kurz: der Filter (Bandbreite %3 rad/s) braucht an jedem Ende %4 s zum Einschwingen, und dazwischen noch einige Daten</translation>
    </message>
</context>
<context>
    <name>LoopHistory</name>
    <message>
        <location filename="../core/io/LoopHistory.cpp" line="+33"/>
        <source>must be a plain file name in the history folder (letters, digits, &apos;.&apos;, &apos;_&apos;, &apos;-&apos;), got &quot;%1&quot;</source>
        <translation>muss ein einfacher Dateiname im Verlaufsordner sein (Buchstaben, Ziffern, &apos;.&apos;, &apos;_&apos;, &apos;-&apos;), gefunden: „%1“</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>must be 64 lower-case hex digits (SHA-256), got &quot;%1&quot;</source>
        <translation>muss aus 64 kleingeschriebenen Hexadezimalziffern bestehen (SHA-256), gefunden: „%1“</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+2"/>
        <location line="+66"/>
        <source>must not be empty</source>
        <translation>darf nicht leer sein</translation>
    </message>
    <message>
        <location line="-64"/>
        <source>one more than trials, the initial estimate first</source>
        <translation>einer mehr als Versuche, die Anfangsschätzung zuerst</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>one per joint</source>
        <translation>einer pro Gelenk</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>must name at least one log</source>
        <translation>muss mindestens ein Log nennen</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>is missing; this is not a learnid history index</source>
        <translation>fehlt; dies ist kein learnid-Verlaufsindex</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>this version of learnid reads &quot;%1&quot;, got %2</source>
        <translation>diese Version von learnid liest „%1“, gefunden: %2</translation>
    </message>
    <message>
        <location line="+92"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
</context>
<context>
    <name>ManufacturerObjects</name>
    <message>
        <location filename="../core/can/ManufacturerObjects.cpp" line="+121"/>
        <source>No node to write the parameters to.</source>
        <translation>Kein Knoten, in den die Parameter geschrieben werden können.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A parameter set holds 1 to %1 parameters, not %2.</source>
        <translation>Ein Parametersatz enthält 1 bis %1 Parameter, nicht %2.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 is not a valid CANopen node id (1 to 127).</source>
        <translation>%1 ist keine gültige CANopen-Knoten-ID (1 bis 127).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Node %1 is listed twice.</source>
        <translation>Knoten %1 ist zweimal aufgeführt.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Parameter %1 (%2) cannot be sent as REAL32.</source>
        <translation>Parameter %1 (%2) kann nicht als REAL32 gesendet werden.</translation>
    </message>
</context>
<context>
    <name>MeshBounds</name>
    <message>
        <location filename="../core/model/MeshBounds.cpp" line="+67"/>
        <source>not readable as a mesh (%1)</source>
        <translation>nicht als Netz lesbar (%1)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>has no vertices</source>
        <translation>hat keine Eckpunkte</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>names no package</source>
        <translation>nennt kein Paket</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>package &quot;%1&quot; not found (ROS_PACKAGE_PATH, the URDF&apos;s folder)</source>
        <translation>Paket „%1“ nicht gefunden (ROS_PACKAGE_PATH, Ordner des URDF)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a relative name without the URDF&apos;s folder</source>
        <translation>ein relativer Name ohne den Ordner des URDF</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+11"/>
        <source>no such file</source>
        <translation>keine solche Datei</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>empty</source>
        <translation>leer</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>larger than 256 MB, not read</source>
        <translation>größer als 256 MB, nicht gelesen</translation>
    </message>
</context>
<context>
    <name>ModelCheck</name>
    <message>
        <location filename="../core/model/ModelCheck.cpp" line="+27"/>
        <source>link %1 (%2)</source>
        <translation>Glied %1 (%2)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>joint %1 (%2)</source>
        <translation>Gelenk %1 (%2)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: its mass is %2 kg: not a real body</source>
        <translation>%1: seine Masse ist %2 kg: kein realer Körper</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: no mass distribution has its inertia (its pseudo-inertia has the negative eigenvalue %2): not a real body</source>
        <translation>%1: keine Massenverteilung hat seine Trägheit (seine Pseudo-Trägheit hat den negativen Eigenwert %2): kein realer Körper</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: %2 is %3, negative: friction and rotor inertia take energy, they do not give it</source>
        <translation>%1: %2 ist %3, negativ: Reibung und Rotorträgheit nehmen Energie auf, sie geben keine ab</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2 is %3, between 0 and %4: the underflow of a positive parametrisation where 0 is meant</source>
        <translation>%1: %2 ist %3, zwischen 0 und %4: der Unterlauf einer positiven Parametrisierung, wo 0 gemeint ist</translation>
    </message>
</context>
<context>
    <name>ModelFactory</name>
    <message>
        <location filename="../core/model/ModelFactory.cpp" line="+71"/>
        <source>robot.urdf.file: the &quot;urdf&quot; model needs a URDF file</source>
        <translation>robot.urdf.file: das Modell „urdf“ braucht eine URDF-Datei</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: cannot read the URDF: %2</source>
        <translation>%1: das URDF kann nicht gelesen werden: %2</translation>
    </message>
</context>
<context>
    <name>Nmt</name>
    <message>
        <location filename="../core/can/Nmt.cpp" line="+14"/>
        <source>boot-up</source>
        <translation>Boot-up</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stopped</source>
        <translation>Stopped</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>operational</source>
        <translation>Operational</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>pre-operational</source>
        <translation>Pre-Operational</translation>
    </message>
</context>
<context>
    <name>ObservableUpdate</name>
    <message>
        <location filename="../core/identify/GramBlock.cpp" line="+13"/>
        <source>least squares sizes do not match: %1 x %2 regressor, %3 targets, %4 joints, %5 parameters</source>
        <translation>Größen der kleinsten Quadrate passen nicht: %1 x %2 Regressor, %3 Zielwerte, %4 Gelenke, %5 Parameter</translation>
    </message>
    <message>
        <location filename="../core/identify/ObservableUpdate.cpp" line="+20"/>
        <source>the regressor or the torque contains non-finite values</source>
        <translation>der Regressor oder das Moment enthält nicht endliche Werte</translation>
    </message>
</context>
<context>
    <name>OutputPath</name>
    <message>
        <location filename="../core/io/OutputPath.cpp" line="+23"/>
        <source>%1: no path given</source>
        <translation>%1: kein Pfad angegeben</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: %2 is relative, and the folder it is taken from, %3, does not exist or is not a folder</source>
        <translation>%1: %2 ist relativ, und der Ordner, ab dem er gilt, %3, existiert nicht oder ist kein Ordner</translation>
    </message>
</context>
<context>
    <name>ParameterFile</name>
    <message>
        <location filename="../core/io/ParameterDcf.cpp" line="+35"/>
        <source>does not fit a REAL32 object entry, got %1</source>
        <translation>passt nicht in einen REAL32-Objekteintrag, gefunden: %1</translation>
    </message>
    <message>
        <location line="+109"/>
        <source>the payload object is written in part</source>
        <translation>das Nutzlast-Objekt wird nur teilweise geschrieben</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>DCF fragment: joint %1 does not exist; the robot has %2 joints</source>
        <translation>DCF-Fragment: Gelenk %1 existiert nicht; der Roboter hat %2 Gelenke</translation>
    </message>
    <message>
        <location filename="../core/io/ParameterFile.cpp" line="+179"/>
        <source>must be given for every parameter or for none</source>
        <translation>muss für jeden Parameter oder für keinen angegeben sein</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>must be &quot;%1&quot; for determined %2, got &quot;%3&quot;</source>
        <translation>muss für determined %2 „%1“ sein, gefunden: „%3“</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>must be an object index written as &quot;0x&quot; and four hex digits, got &quot;%1&quot;</source>
        <translation>muss ein Objektindex aus „0x“ und vier Hexadezimalziffern sein, gefunden: „%1“</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>must be the bytes written as pairs of hex digits, got &quot;%1&quot;</source>
        <translation>müssen die geschriebenen Bytes als Paare von Hexadezimalziffern sein, gefunden: „%1“</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>must be a date and time as in 2024-05-01T12:00:00.000Z, got &quot;%1&quot;</source>
        <translation>muss Datum und Uhrzeit wie 2024-05-01T12:00:00.000Z sein, gefunden: „%1“</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>is missing; this is not a learnid parameter file</source>
        <translation>fehlt; dies ist keine learnid-Parameterdatei</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>this version of learnid reads &quot;%1&quot; and &quot;%2&quot;, got %3</source>
        <translation>diese Version von learnid liest „%1“ und „%2“, gefunden: %3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>is missing; this key is required</source>
        <translation>fehlt; dieser Schlüssel ist erforderlich</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>does not match the content: the file was changed after learnid wrote it, or is damaged</source>
        <translation>passt nicht zum Inhalt: die Datei wurde nach dem Schreiben durch learnid geändert oder ist beschädigt</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../core/io/ParameterFileValidation.cpp" line="+78"/>
        <source>unknown model &quot;%1&quot;; known models: %2</source>
        <translation>unbekanntes Modell „%1“; bekannte Modelle: %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>one per joint of %1</source>
        <translation>einer pro Gelenk von %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>node %1 is given to two joints</source>
        <translation>Knoten %1 ist zwei Gelenken zugeordnet</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>must be a valid date and time</source>
        <translation>muss ein gültiges Datum mit Uhrzeit sein</translation>
    </message>
    <message>
        <location line="-73"/>
        <location line="+75"/>
        <location line="+15"/>
        <location line="+5"/>
        <source>must not be empty</source>
        <translation>darf nicht leer sein</translation>
    </message>
    <message>
        <location line="-105"/>
        <source>one per standard parameter</source>
        <translation>einer pro Standardparameter</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>determined shares, %1</source>
        <translation>bestimmte Anteile, %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>must be a share from 0 to 1 or null, got %1</source>
        <translation>muss ein Anteil von 0 bis 1 oder null sein, gefunden: %1</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>must give each joint&apos;s node when the file records no controller</source>
        <translation>muss den Knoten jedes Gelenks angeben, wenn die Datei keinen Regler festhält</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>unknown learning law &quot;%1&quot;; known laws: %2</source>
        <translation>unbekanntes Lerngesetz „%1“; bekannte Gesetze: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>must be a trial index or -1 (not recorded), got %1</source>
        <translation>muss ein Versuchsindex oder -1 (nicht aufgezeichnet) sein, gefunden: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>one per parameter of %1</source>
        <translation>einer pro Parameter von %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>must be &quot;%1&quot; (parameter %2 of %3), got &quot;%4&quot;</source>
        <translation>muss „%1“ sein (Parameter %2 von %3), gefunden: „%4“</translation>
    </message>
    <message>
        <location line="-105"/>
        <location line="+111"/>
        <source>values, %1</source>
        <translation>Werte, %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>standard deviations, %1</source>
        <translation>Standardabweichungen, %1</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>must name the CANopen data type</source>
        <translation>muss den CANopen-Datentyp nennen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>must hold the bytes written</source>
        <translation>muss die geschriebenen Bytes enthalten</translation>
    </message>
    <message>
        <location filename="../core/io/ParameterFilePayload.cpp" line="+49"/>
        <location line="+49"/>
        <source>the payload&apos;s values</source>
        <translation>die Werte der Nutzlast</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>must be &quot;data&quot; (identified) or &quot;prior&quot; (kept at the prior), got &quot;%1&quot;</source>
        <translation>muss „data“ (identifiziert) oder „prior“ (von der Vorgabe übernommen) sein, gefunden: „%1“</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>must name the link the payload is fixed to</source>
        <translation>muss das Glied nennen, an dem die Nutzlast befestigt ist</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the model %1 has no links to fix a payload to; a payload needs a URDF robot</source>
        <translation>das Modell %1 hat keine Glieder, an denen eine Nutzlast befestigt werden kann; eine Nutzlast braucht einen URDF-Roboter</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>is not a real body&apos;s inertia with this mass and centre of mass (its pseudo-inertia has the negative eigenvalue %1)</source>
        <translation>ist nicht die Trägheit eines realen Körpers mit dieser Masse und diesem Schwerpunkt (seine Pseudoträgheit hat den negativen Eigenwert %1)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>must be null for a value kept at the prior (source[%1] is &quot;prior&quot;), got %2</source>
        <translation>muss für einen von der Vorgabe übernommenen Wert null sein (source[%1] ist „prior“), gefunden: %2</translation>
    </message>
</context>
<context>
    <name>PathCsv</name>
    <message>
        <location filename="../core/io/PathCsv.cpp" line="+54"/>
        <source>the header must be %1 (the time, then one column per joint); expected %2, got %3</source>
        <translation>die Kopfzeile muss %1 lauten (die Zeit, dann eine Spalte pro Gelenk); erwartet: %2, gefunden: %3</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the header must be %1 (the time, then one column per joint); the joint columns are missing</source>
        <translation>die Kopfzeile muss %1 lauten (die Zeit, dann eine Spalte pro Gelenk); die Gelenkspalten fehlen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the header names the joints q1..q%1; the robot has %2 joints</source>
        <translation>die Kopfzeile nennt die Gelenke q1..q%1; der Roboter hat %2 Gelenke</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>expected %1 fields (%2), got %3</source>
        <translation>%1 Felder erwartet (%2), gefunden: %3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the field is empty; expected a number</source>
        <translation>das Feld ist leer; erwartet wird eine Zahl</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not a number: %1</source>
        <translation>keine Zahl: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the times must increase from sample to sample, got %1 after %2 on line %3</source>
        <translation>die Zeiten müssen von Abtastwert zu Abtastwert zunehmen, gefunden: %1 nach %2 in Zeile %3</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>the file holds no header line; expected %1</source>
        <translation>die Datei enthält keine Kopfzeile; erwartet: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 samples after the header on line %2; a path needs at least %3</source>
        <translation>%1 Abtastwerte nach der Kopfzeile in Zeile %2; eine Bahn braucht mindestens %3</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>path CSV: %1 sample times but %2 samples of the joints</source>
        <translation>Bahn-CSV: %1 Abtastzeitpunkte, aber %2 Abtastwerte der Gelenke</translation>
    </message>
</context>
<context>
    <name>PathIdentifiability</name>
    <message>
        <location filename="../core/session/PathIdentifiability.cpp" line="+32"/>
        <source>the path observes %1 of %2 parameter directions (condition %3)</source>
        <translation>die Bahn beobachtet %1 von %2 Parameterrichtungen (Kondition %3)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>it cannot see, and the trials keep: %1</source>
        <translation>sie sieht nicht, und die Versuche behalten: %1</translation>
    </message>
</context>
<context>
    <name>Payload</name>
    <message>
        <location filename="../core/model/Payload.cpp" line="+22"/>
        <source>the payload&apos;s inertial parameters are not finite</source>
        <translation>die Trägheitsparameter der Nutzlast sind nicht endlich</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the payload&apos;s mass must be positive (it is %1 kg)</source>
        <translation>die Masse der Nutzlast muss positiv sein (sie ist %1 kg)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 has no moving link to carry a payload</source>
        <translation>%1 hat kein bewegtes Glied, das eine Nutzlast tragen kann</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>payload link &apos;%1&apos; is not a moving link of %2 or a link fixed to one (its links: %3)</source>
        <translation>Nutzlast-Glied „%1“ ist weder ein bewegtes Glied von %2 noch ein daran befestigtes Glied (seine Glieder: %3)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>a payload needs the arm&apos;s model</source>
        <translation>eine Nutzlast braucht das Modell des Arms</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the arm&apos;s parameters for %1 must be %2 finite numbers</source>
        <translation>die Parameter des Arms für %1 müssen %2 endliche Zahlen sein</translation>
    </message>
</context>
<context>
    <name>PayloadArm</name>
    <message>
        <location filename="../core/service/PayloadArm.cpp" line="+42"/>
        <source>%1: standardParameters: is empty (robot.model %2): the arm&apos;s model for a payload is the whole model as standard parameters, as `learnid-cli identify --export` writes it for a URDF robot</source>
        <translation>%1: standardParameters: ist leer (robot.model %2): das Modell des Arms für eine Nutzlast ist das ganze Modell als Standardparameter, wie `learnid-cli identify --export` es für einen URDF-Roboter schreibt</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: robot.model is &quot;urdf&quot;: the file does not carry its URDF; give the URDF the arm was identified on with %2</source>
        <translation>%1: robot.model ist „urdf“: die Datei enthält ihr URDF nicht; geben Sie das URDF, an dem der Arm identifiziert wurde, mit %2 an</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: only for a parameter file of robot.model &quot;urdf&quot;; %2 is of the built-in %3, whose URDF is known</source>
        <translation>%1: nur für eine Parameterdatei mit robot.model „urdf“; %2 gehört zum eingebauten %3, dessen URDF bekannt ist</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: standardParameters: has %2 entries, the arm&apos;s model from %3 has %4: the file was not identified on this URDF (or with other base and tip links)</source>
        <translation>%1: standardParameters: hat %2 Einträge, das Modell des Arms aus %3 hat %4: die Datei wurde nicht an diesem URDF identifiziert (oder mit anderen Basis- und Endgliedern)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: standardParameters[%2].name: is &quot;%3&quot;, the arm&apos;s model from %4 has &quot;%5&quot; there: the file was not identified on this URDF</source>
        <translation>%1: standardParameters[%2].name: ist „%3“, das Modell des Arms aus %4 hat dort „%5“: die Datei wurde nicht an diesem URDF identifiziert</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1 holds a payload on %2; it is not part of the arm&apos;s model and is left out</source>
        <translation>%1 enthält eine Nutzlast an %2; sie gehört nicht zum Modell des Arms und bleibt außen vor</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1: only for a parameter file of robot.model &quot;urdf&quot; given as the arm; %2 is a URDF or a built-in robot</source>
        <translation>%1: nur für eine als Arm angegebene Parameterdatei mit robot.model „urdf“; %2 ist ein URDF oder ein eingebauter Roboter</translation>
    </message>
</context>
<context>
    <name>PayloadBaseline</name>
    <message>
        <location filename="../core/identify/PayloadBaseline.cpp" line="+63"/>
        <source>%1 covers less than %2 % of %3 within a shift of %4 s: a baseline runs the same timed path without the payload</source>
        <translation>%1 deckt innerhalb einer Verschiebung von %4 s weniger als %2 % von %3 ab: eine Referenzfahrt fährt dieselbe zeitlich geplante Bahn ohne die Nutzlast</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 (%2 joints, %3 samples of %4 s) is not a baseline of %5 (%6 joints, %7 samples of %8 s): a baseline runs the same timed path without the payload</source>
        <translation>%1 (%2 Gelenke, %3 Abtastwerte zu %4 s) ist keine Referenz zu %5 (%6 Gelenke, %7 Abtastwerte zu %8 s): eine Referenzfahrt fährt dieselbe zeitlich geplante Bahn ohne die Nutzlast</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: the filtered signals are not finite</source>
        <translation>%1: die gefilterten Signale sind nicht endlich</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 does not follow the path of %2: their joint angles differ by %3 deg RMS (at most %4 deg) after a shift of %5 s</source>
        <translation>%1 folgt nicht der Bahn von %2: ihre Gelenkwinkel weichen nach einer Verschiebung von %5 s um %3 Grad RMS ab (höchstens %4 Grad)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the baselines together cover less than %1 % of %2</source>
        <translation>die Referenzen decken zusammen weniger als %1 % von %2 ab</translation>
    </message>
</context>
<context>
    <name>PayloadEstimate</name>
    <message>
        <location filename="../core/identify/PayloadEstimate.cpp" line="+61"/>
        <source>the payload&apos;s rows (%1 x %2) and targets (%3) do not match</source>
        <translation>die Zeilen der Nutzlast (%1 x %2) und die Zielwerte (%3) passen nicht zusammen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the payload&apos;s rows or targets are not finite</source>
        <translation>die Zeilen oder Zielwerte der Nutzlast sind nicht endlich</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the variance factor must be positive</source>
        <translation>der Varianzfaktor muss positiv sein</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>no direction determined: the prior</source>
        <translation>keine Richtung bestimmt: die Vorgabe</translation>
    </message>
</context>
<context>
    <name>PayloadExport</name>
    <message>
        <location filename="../core/service/PayloadExport.cpp" line="+80"/>
        <source>%1 (%2) with a payload on %3 identified from the logs %4</source>
        <translation>%1 (%2) mit einer Nutzlast an %3, identifiziert aus den Logs %4</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>the controller gains the parameter file records are for %1 joints, the robot has %2</source>
        <translation>die Reglerverstärkungen, die die Parameterdatei festhält, gelten für %1 Gelenke, der Roboter hat %2</translation>
    </message>
</context>
<context>
    <name>PayloadFit</name>
    <message>
        <location filename="../core/identify/PayloadFit.cpp" line="+99"/>
        <source>%1 has %2 joints, the robot %3</source>
        <translation>%1 hat %2 Gelenke, der Roboter %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the filtered signals are not finite</source>
        <translation>%1: die gefilterten Signale sind nicht endlich</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no samples to fit the payload to</source>
        <translation>keine Abtastwerte, an die die Nutzlast angepasst werden kann</translation>
    </message>
</context>
<context>
    <name>PayloadIdentification</name>
    <message>
        <location filename="../core/service/PayloadIdentification.cpp" line="+40"/>
        <source>no log to identify the payload from</source>
        <translation>kein Log, aus dem die Nutzlast identifiziert werden kann</translation>
    </message>
</context>
<context>
    <name>PayloadObjects</name>
    <message>
        <location filename="../core/can/PayloadObjects.cpp" line="+66"/>
        <source>The payload&apos;s joint %1 is not one of the robot&apos;s joints 1 to %2.</source>
        <translation>Das Gelenk %1 der Nutzlast ist keines der Robotergelenke 1 bis %2.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A payload has 10 parameters, not %1.</source>
        <translation>Eine Nutzlast hat 10 Parameter, nicht %1.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Payload parameter %1 (%2) cannot be sent as REAL32.</source>
        <translation>Nutzlastparameter %1 (%2) kann nicht als REAL32 gesendet werden.</translation>
    </message>
</context>
<context>
    <name>PayloadObservability</name>
    <message>
        <location filename="../core/identify/PayloadObservability.cpp" line="+48"/>
        <source>the mass is not seen: the path must hold the payload against gravity in several orientations of %1, or accelerate it</source>
        <translation>die Masse ist nicht sichtbar: die Bahn muss die Nutzlast in mehreren Orientierungen von %1 gegen die Schwerkraft halten oder sie beschleunigen</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the centre of mass along the %1 axis of %2 is not seen: the mass and the centre of mass need changes of the wrist&apos;s orientation; tilt the wrist so that this axis turns away from the vertical</source>
        <translation>der Schwerpunkt entlang der %1-Achse von %2 ist nicht sichtbar: Masse und Schwerpunkt brauchen Änderungen der Orientierung des Handgelenks; neigen Sie das Handgelenk, sodass sich diese Achse aus der Senkrechten dreht</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the centre of mass along the %1 axes of %2 is not seen: the mass and the centre of mass need changes of the wrist&apos;s orientation; tilt the wrist so that these axes turn away from the vertical</source>
        <translation>der Schwerpunkt entlang der Achsen %1 von %2 ist nicht sichtbar: Masse und Schwerpunkt brauchen Änderungen der Orientierung des Handgelenks; neigen Sie das Handgelenk, sodass sich diese Achsen aus der Senkrechten drehen</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the inertia %1 is not seen: the full inertia needs rotations of the wrist about several axes, with accelerations</source>
        <translation>die Trägheit %1 ist nicht sichtbar: die volle Trägheit braucht Drehungen des Handgelenks um mehrere Achsen, mit Beschleunigungen</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the payload&apos;s regressor has 10 columns, not %1</source>
        <translation>der Regressor der Nutzlast hat 10 Spalten, nicht %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the share of the strongest direction must lie between 0 and 1</source>
        <translation>der Anteil der stärksten Richtung muss zwischen 0 und 1 liegen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the payload&apos;s regressor is not finite</source>
        <translation>der Regressor der Nutzlast ist nicht endlich</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>the path must give q, qd and qdd for the %1 joints at every sample</source>
        <translation>die Bahn muss q, qd und qdd für die %1 Gelenke bei jedem Abtastwert angeben</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the path has no samples</source>
        <translation>die Bahn hat keine Abtastwerte</translation>
    </message>
</context>
<context>
    <name>PayloadPathChange</name>
    <message>
        <location filename="../core/session/PayloadPathChange.cpp" line="+55"/>
        <source>moving %1 at waypoint %2 by %3 rad (to %4 rad, inside its limits) would let the trials measure %5</source>
        <translation>%1 an Wegpunkt %2 um %3 rad verschoben (auf %4 rad, innerhalb seiner Grenzen) ließe die Fahrten %5 messen</translation>
    </message>
</context>
<context>
    <name>PayloadPrior</name>
    <message>
        <location filename="../core/model/PayloadPrior.cpp" line="+53"/>
        <source>box %1 to %2 m</source>
        <translation>Quader %1 bis %2 m</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sphere of radius %1 m around %2 m</source>
        <translation>Kugel mit Radius %1 m um %2 m</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1: the payload&apos;s mass must be a positive number of kg, not %2</source>
        <translation>%1: die Masse der Nutzlast muss eine positive Zahl in kg sein, nicht %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the centre of mass must be finite, not %2</source>
        <translation>%1: der Schwerpunkt muss endlich sein, nicht %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the box&apos;s upper corner %2 must lie above its lower corner %3 in x, y and z</source>
        <translation>%1: die obere Ecke %2 des Quaders muss in x, y und z über seiner unteren Ecke %3 liegen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the bounding sphere needs a positive radius [m], not %2</source>
        <translation>%1: die Hüllkugel braucht einen positiven Radius [m], nicht %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: the prior centre of mass %2 m is not inside the bound (%3): give a bound that contains it</source>
        <translation>%1: der vorgegebene Schwerpunkt %2 m liegt nicht innerhalb der Grenze (%3): geben Sie eine Grenze an, die ihn enthält</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: the inertia must be finite and symmetric</source>
        <translation>%1: die Trägheit muss endlich und symmetrisch sein</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the inertia is not a real body&apos;s (principal moments %2 kg m^2 must be positive and each at most the sum of the others)</source>
        <translation>%1: die Trägheit ist nicht die eines realen Körpers (die Hauptmomente %2 kg m^2 müssen positiv und jedes höchstens die Summe der anderen sein)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: a body with this inertia does not fit in the bound (%2)</source>
        <translation>%1: ein Körper mit dieser Trägheit passt nicht in die Grenze (%2)</translation>
    </message>
</context>
<context>
    <name>PayloadRun</name>
    <message>
        <location filename="../core/service/PayloadRun.cpp" line="+32"/>
        <source>payload: the scenario has no payload section</source>
        <translation>payload: das Szenario hat keinen Abschnitt payload</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>robot.model: unknown robot model &quot;%1&quot;</source>
        <translation>robot.model: unbekanntes Robotermodell &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>no trial was learned from: the payload is not estimated</source>
        <translation>aus keinem Versuch wurde gelernt: die Nutzlast ist nicht geschätzt</translation>
    </message>
</context>
<context>
    <name>PayloadRunExport</name>
    <message numerus="yes">
        <location filename="../core/service/PayloadRunExport.cpp" line="+41"/>
        <source>%1 with a payload on %2 learned in %n trial(s) with the arm&apos;s model held fixed</source>
        <translation>
            <numerusform>%1 mit einer Nutzlast an %2, gelernt in %n Versuch mit festgehaltenem Modell des Arms</numerusform>
            <numerusform>%1 mit einer Nutzlast an %2, gelernt in %n Versuchen mit festgehaltenem Modell des Arms</numerusform>
        </translation>
    </message>
    <message>
        <location line="+81"/>
        <source>%1: the folder for the trial CSVs cannot be created</source>
        <translation>%1: der Ordner für die Versuchs-CSVs kann nicht angelegt werden</translation>
    </message>
</context>
<context>
    <name>PayloadSession</name>
    <message>
        <location filename="../core/session/PayloadSession.cpp" line="+24"/>
        <source>payload: only a URDF robot carries a payload (the model is %1)</source>
        <translation>payload: nur ein URDF-Roboter trägt eine Nutzlast (das Modell ist %1)</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>baseline trial %1</source>
        <translation>Referenzfahrt %1</translation>
    </message>
    <message>
        <location line="+101"/>
        <source>trial %1 refused before motion: %2</source>
        <translation>Versuch %1 vor der Bewegung abgelehnt: %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>trial %1 did not complete (%2): the payload estimate is unchanged</source>
        <translation>Versuch %1 wurde nicht vollständig ausgeführt (%2): die Schätzung der Nutzlast bleibt unverändert</translation>
    </message>
    <message>
        <location line="-113"/>
        <source>trial %1</source>
        <translation>Versuch %1</translation>
    </message>
    <message>
        <location line="+124"/>
        <source>baseline trial %1 not usable: %2</source>
        <translation>Referenzfahrt %1 nicht verwendbar: %2</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>the payload fit produced non-finite parameters</source>
        <translation>der Nutzlast-Fit ergab nicht endliche Parameter</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>trial %1 stopped at the tracking limit (%2): learned from the %3 s before the stop</source>
        <translation>Versuch %1 an der Bahnfehlergrenze gestoppt (%2): aus den %3 s vor dem Stopp gelernt</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>; the second stop in a row: the gains do not hold the payload, stiffen them (scenario --print --payload)</source>
        <translation>; der zweite Stopp in Folge: die Verstärkungen halten die Nutzlast nicht, erhöhen Sie sie (scenario --print --payload)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>trial %1 not learned from: %2</source>
        <translation>aus Versuch %1 nicht gelernt: %2</translation>
    </message>
</context>
<context>
    <name>PayloadText</name>
    <message>
        <location filename="../ui/PayloadText.cpp" line="+26"/>
        <source>seen</source>
        <translation>erfasst</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not seen: kept at the prior</source>
        <translation>nicht erfasst: bleibt beim Vorwissen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1; the payload on &lt;b&gt;%2&lt;/b&gt;, the arm&apos;s model held fixed.</source>
        <translation>%1; die Nutzlast an &lt;b&gt;%2&lt;/b&gt;, das Modell des Arms festgehalten.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The simulation carries %1 kg at %2 mm.</source>
        <translation>Die Simulation trägt %1 kg bei %2 mm.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 baseline trial(s) of the same timed path without the payload, then %2 payload trial(s).</source>
        <translation>%1 Basisversuch(e) auf derselben zeitlich geplanten Bahn ohne die Nutzlast, dann %2 Versuch(e) mit der Nutzlast.</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%n payload trial(s), no baseline trial.</source>
        <translation>
            <numerusform>%n Versuch mit der Nutzlast, kein Basisversuch.</numerusform>
            <numerusform>%n Versuche mit der Nutzlast, kein Basisversuch.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The path determines &lt;b&gt;%1 of the payload&apos;s 10 parameters&lt;/b&gt;: mass %2, centre of mass %3, inertia %4.</source>
        <translation>Die Bahn bestimmt &lt;b&gt;%1 der 10 Parameter der Nutzlast&lt;/b&gt;: Masse %2, Schwerpunkt %3, Trägheit %4.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>The first trial passes its check.</source>
        <translation>Der erste Versuch besteht seine Prüfung.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The first trial would be refused: %1</source>
        <translation>Der erste Versuch würde abgelehnt: %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The payload after trial %1: %2 of 10 directions determined (condition %3); bound: %4.</source>
        <translation>Die Nutzlast nach Versuch %1: %2 von 10 Richtungen bestimmt (Kondition %3); Schranke: %4.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Mass &lt;b&gt;%1 kg&lt;/b&gt; (standard error %2 kg), centre of mass &lt;b&gt;%3 mm&lt;/b&gt;.</source>
        <translation>Masse &lt;b&gt;%1 kg&lt;/b&gt; (Standardfehler %2 kg), Schwerpunkt &lt;b&gt;%3 mm&lt;/b&gt;.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Its centre of mass lies outside the bound.</source>
        <translation>Ihr Schwerpunkt liegt außerhalb der Schranke.</translation>
    </message>
</context>
<context>
    <name>Pdo</name>
    <message>
        <location filename="../core/can/Pdo.cpp" line="+24"/>
        <source>PDO %1 does not exist; learnid uses PDO 1 to 4.</source>
        <translation>PDO %1 existiert nicht; learnid nutzt PDO 1 bis 4.</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Object %1 of type %2 cannot be mapped into a PDO.</source>
        <translation>Objekt %1 vom Typ %2 kann nicht in ein PDO gemappt werden.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The mapped objects need %1 bits; a PDO holds at most %2 bits (8 bytes).</source>
        <translation>Die gemappten Objekte brauchen %1 Bit; ein PDO fasst höchstens %2 Bit (8 Bytes).</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The PDO maps %1 objects but %2 values were given.</source>
        <translation>Das PDO mappt %1 Objekte, aber %2 Werte wurden angegeben.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>PDO object %1: %2</source>
        <translation>PDO-Objekt %1: %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>The PDO carries %1 bytes; its mapping needs %2.</source>
        <translation>Das PDO trägt %1 Bytes; sein Mapping braucht %2.</translation>
    </message>
</context>
<context>
    <name>PlanCsv</name>
    <message>
        <location filename="../core/io/PlanCsv.cpp" line="+109"/>
        <source>a second &quot;# %1:&quot; line; the first is on line %2</source>
        <translation>eine zweite Zeile „# %1:“; die erste steht in Zeile %2</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>no &quot;# %1:&quot; line before the header</source>
        <translation>keine Zeile „# %1:“ vor der Kopfzeile</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+199"/>
        <source>the plan-id must be 64 hex digits (SHA-256), got %1</source>
        <translation>die plan-id muss aus 64 Hexadezimalziffern bestehen (SHA-256), gefunden: %1</translation>
    </message>
    <message>
        <location line="-191"/>
        <source>expected &quot;# robot: &lt;model&gt;, &lt;n&gt; joints&quot;, got %1</source>
        <translation>erwartet: „# robot: &lt;model&gt;, &lt;n&gt; joints“, gefunden: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the sample period must be a positive number [s], got %1</source>
        <translation>die Abtastperiode muss eine positive Zahl [s] sein, gefunden: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>estimate value %1 is not a finite number: %2</source>
        <translation>Schätzwert %1 ist keine endliche Zahl: %2</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>plan CSV: the plan (%1 joints, %2 samples, %3 feedforward columns) is empty, does not fit its feedforward or holds non-finite numbers</source>
        <translation>Plan-CSV: der Plan (%1 Gelenke, %2 Abtastwerte, %3 Vorsteuerungsspalten) ist leer, passt nicht zu seiner Vorsteuerung oder enthält nicht endliche Zahlen</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>plan CSV: the estimate the feedforward was built with is empty or not finite</source>
        <translation>Plan-CSV: die Schätzung, mit der die Vorsteuerung berechnet wurde, ist leer oder nicht endlich</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>not a plan file of this version: the first line must be &quot;%1&quot;</source>
        <translation>keine Plandatei dieser Version: die erste Zeile muss „%1“ lauten</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>no header line; expected %1</source>
        <translation>keine Kopfzeile; erwartet: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the header of a plan of %1 joints is %2</source>
        <translation>die Kopfzeile eines Plans mit %1 Gelenken lautet %2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>no samples after the header</source>
        <translation>keine Abtastwerte nach der Kopfzeile</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>a blank or comment line among the samples; comments go before the header</source>
        <translation>eine Leer- oder Kommentarzeile zwischen den Abtastwerten; Kommentare stehen vor der Kopfzeile</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>expected %1 fields, got %2</source>
        <translation>%1 Felder erwartet, gefunden: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>not a finite number: %1</source>
        <translation>keine endliche Zahl: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>sample %1 is at k Ts = %2 s, got %3 s</source>
        <translation>Abtastwert %1 liegt bei k Ts = %2 s, gefunden: %3 s</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the plan-id %1 is not that of the plan&apos;s numbers (%2): the plan was changed after learnid wrote it</source>
        <translation>die plan-id %1 ist nicht die der Zahlen des Plans (%2): der Plan wurde nach dem Schreiben durch learnid geändert</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>a second plan-id, %1, other than %2 on line %3; a log is of one plan</source>
        <translation>eine zweite plan-id, %1, anders als %2 in Zeile %3; ein Log gehört zu einem Plan</translation>
    </message>
</context>
<context>
    <name>Plausibility</name>
    <message>
        <location filename="../core/model/Plausibility.cpp" line="+45"/>
        <source>The CAD vector has %1 entries, too few for %2 links.</source>
        <translation>Der CAD-Vektor hat %1 Einträge, zu wenige für %2 Glieder.</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>The plausibility check needs 10 parameters and a volume per link (%1 links, %2 and %3 parameters, %4 volumes).</source>
        <translation>Die Plausibilitätsprüfung braucht 10 Parameter und ein Volumen pro Glied (%1 Glieder, %2 und %3 Parameter, %4 Volumina).</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The parameters to check are not finite.</source>
        <translation>Die zu prüfenden Parameter sind nicht endlich.</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>its mass is %1 kg: not a real body</source>
        <translation>seine Masse ist %1 kg: kein realer Körper</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>its smallest principal moment of inertia about the centre of mass, %1 kg m^2, is below %2 % of the CAD link&apos;s smallest (%3 kg m^2): a point mass or a needle, not a link</source>
        <translation>sein kleinstes Hauptträgheitsmoment um den Schwerpunkt, %1 kg m^2, liegt unter %2 % des kleinsten des CAD-Glieds (%3 kg m^2): eine Punktmasse oder Nadel, kein Glied</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>its principal moments %1, %2 and %3 kg m^2 give I1 + I2 = %4 I3, below %5 I3 (a flat plate at best)</source>
        <translation>seine Hauptträgheitsmomente %1, %2 und %3 kg m^2 ergeben I1 + I2 = %4 I3, unter %5 I3 (bestenfalls eine flache Platte)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>its centre of mass lies outside its bounding volume (%1)</source>
        <translation>sein Schwerpunkt liegt außerhalb seines Hüllvolumens (%1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the URDF&apos;s geometry: %1</source>
        <translation>die Geometrie des URDF: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the CAD body&apos;s inertia ellipsoid, enlarged %1 times</source>
        <translation>das Trägheitsellipsoid des CAD-Körpers, %1-fach vergrößert</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>its centre of mass lies outside its bounding volume</source>
        <translation>sein Schwerpunkt liegt außerhalb seines Hüllvolumens</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Index %1 is outside the %2 standard parameters.</source>
        <translation>Index %1 liegt außerhalb der %2 Standardparameter.</translation>
    </message>
</context>
<context>
    <name>PlausibleEstimate</name>
    <message>
        <location filename="../core/model/PlausibleEstimate.cpp" line="+30"/>
        <source>The estimation problem&apos;s sizes do not match: A is %1 x %2, b has %3 entries, the prior %4 for %5 links.</source>
        <translation>Die Größen des Schätzproblems passen nicht zusammen: A ist %1 x %2, b hat %3 Einträge, der Prior %4, für %5 Glieder.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The estimation problem has entries that are not finite.</source>
        <translation>Das Schätzproblem hat Einträge, die keine endlichen Zahlen sind.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The prior share must lie between 0 and 1, not %1.</source>
        <translation>Der Anteil des Priors muss zwischen 0 und 1 liegen, nicht %1.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 bounding volumes for %2 links.</source>
        <translation>%1 Hüllvolumina für %2 Glieder.</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+3"/>
        <source>Index %1 is not a joint term.</source>
        <translation>Index %1 ist kein Gelenkterm.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The prior&apos;s joint term %1 is negative (%2).</source>
        <translation>Der Gelenkterm %1 des Priors ist negativ (%2).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The prior&apos;s link %1 does not lie inside its bounding volume.</source>
        <translation>Das Glied %1 des Priors liegt nicht in seinem Hüllvolumen.</translation>
    </message>
    <message>
        <location line="+71"/>
        <source>The prior&apos;s link %1 is not strictly a real body (its pseudo-inertia is not positive definite).</source>
        <translation>Das Glied %1 des Priors ist nicht streng ein realer Körper (seine Pseudoträgheit ist nicht positiv definit).</translation>
    </message>
    <message numerus="yes">
        <location line="+61"/>
        <source>%n Newton step(s)</source>
        <translation>
            <numerusform>%n Newton-Schritt</numerusform>
            <numerusform>%n Newton-Schritte</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RecordedTrialRobot</name>
    <message>
        <location filename="../core/service/RecordedTrialRobot.cpp" line="+24"/>
        <source>the robot&apos;s own controller (plan and log files)</source>
        <translation>der eigene Regler des Roboters (Plan- und Log-Dateien)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>no logged trial is left for trial run %1</source>
        <translation>für Versuchslauf %1 ist kein aufgezeichneter Versuch mehr übrig</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 ran plan %2, but with this scenario the trial is planned as %3: the scenario is not the one the plan was made with</source>
        <translation>%1 lief mit Plan %2, aber mit diesem Szenario wird der Versuch als %3 geplant: das Szenario ist nicht das, mit dem der Plan erstellt wurde</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the robot&apos;s own controller takes its parameters its own way: give it the estimate&apos;s parameter file</source>
        <translation>der eigene Regler des Roboters übernimmt seine Parameter auf eigenem Weg: ihm die Parameterdatei der Schätzung geben</translation>
    </message>
</context>
<context>
    <name>Robot</name>
    <message>
        <location filename="../core/robot/Robot.h" line="+39"/>
        <source>this robot&apos;s controller takes no payload: give it the payload&apos;s parameter file</source>
        <translation>die Steuerung dieses Roboters nimmt keine Nutzlast an: geben Sie ihr die Parameterdatei der Nutzlast</translation>
    </message>
</context>
<context>
    <name>RobotLogCsv</name>
    <message>
        <location filename="../core/io/RobotLogCsv.cpp" line="+49"/>
        <source>, ... (%1 columns)</source>
        <translation>, ... (%1 Spalten)</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>the name repeats that of column %1; each column name may appear only once</source>
        <translation>der Name wiederholt den der Spalte %1; jeder Spaltenname darf nur einmal vorkommen</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>no column &quot;%1&quot; (%2); the header has: %3</source>
        <translation>keine Spalte „%1“ (%2); die Kopfzeile enthält: %3</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>the log has %1 joints (%2..%3), the robot %4</source>
        <translation>das Log hat %1 Gelenke (%2..%3), der Roboter %4</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the time [s]</source>
        <translation>die Zeit [s]</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the position of joint %1</source>
        <translation>die Position des Gelenks %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the velocity of joint %1, as the log has velocities of other joints</source>
        <translation>die Geschwindigkeit des Gelenks %1, da das Log Geschwindigkeiten anderer Gelenke enthält</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the torque of joint %1</source>
        <translation>das Moment des Gelenks %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: t= names no column; the time column is needed</source>
        <translation>%1: t= nennt keine Spalte; die Zeitspalte wird gebraucht</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: %2=%3 has no %4 where the joint number goes, e.g. %2=%3%4</source>
        <translation>%1: %2=%3 hat kein %4 an der Stelle der Gelenknummer, z. B. %2=%3%4</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1: &quot;%2&quot; has no &apos;=&apos;; expected key=pattern with the keys t, q, dq and tau, e.g. q=pos_meas%3</source>
        <translation>%1: „%2“ hat kein &apos;=&apos;; erwartet wird Schlüssel=Muster mit den Schlüsseln t, q, dq und tau, z. B. q=pos_meas%3</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: unknown key &quot;%2&quot;; the keys are t, q, dq and tau</source>
        <translation>%1: unbekannter Schlüssel „%2“; die Schlüssel sind t, q, dq und tau</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: the key %2 is given twice</source>
        <translation>%1: der Schlüssel %2 ist zweimal angegeben</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1: a log is read for 1 joint or more, not %2</source>
        <translation>%1: ein Log wird für 1 Gelenk oder mehr gelesen, nicht für %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: %2 joint kinds given for a robot of %3 joints</source>
        <translation>%1: %2 Gelenkarten für einen Roboter mit %3 Gelenken angegeben</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>expected %1 fields (%2), got %3</source>
        <translation>%1 Felder erwartet (%2), gefunden: %3</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the field is empty; expected a number</source>
        <translation>das Feld ist leer; erwartet wird eine Zahl</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not a number: %1</source>
        <translation>keine Zahl: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 rad/s is faster than any robot joint turns (at most %2 rad/s); the log looks like it holds degrees per second, radians per second are expected</source>
        <translation>%1 rad/s ist schneller, als sich irgendein Robotergelenk dreht (höchstens %2 rad/s); das Log scheint Grad pro Sekunde zu enthalten, erwartet wird Radiant pro Sekunde</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 rad is more than 1.05 turns (%2 rad); the log looks like it holds degrees, radians are expected</source>
        <translation>%1 rad ist mehr als 1,05 Umdrehungen (%2 rad); das Log scheint Grad zu enthalten, erwartet wird Radiant</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the times must increase from sample to sample, got %1 after %2 on line %3</source>
        <translation>die Zeiten müssen von Abtastwert zu Abtastwert zunehmen, gefunden: %1 nach %2 in Zeile %3</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>the time %1 repeats that of line %2 with other values (%3: %4 there, %5 here); only an exact repeat of a row is dropped</source>
        <translation>die Zeit %1 wiederholt die der Zeile %2 mit anderen Werten (%3: dort %4, hier %5); nur eine exakte Wiederholung einer Zeile wird verworfen</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>the file holds no header line; expected one naming the columns %1</source>
        <translation>die Datei enthält keine Kopfzeile; erwartet wird eine, die die Spalten %1 nennt</translation>
    </message>
    <message numerus="yes">
        <location line="+9"/>
        <source> (and %n stale row(s): values repeated under a new time stamp, treated as missing)</source>
        <translation>
            <numerusform> (und %n veraltete Zeile: Werte unter neuem Zeitstempel wiederholt, als fehlend behandelt)</numerusform>
            <numerusform> (und %n veraltete Zeilen: Werte unter neuem Zeitstempel wiederholt, als fehlend behandelt)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 samples after the header on line %2%3; a log needs at least %4</source>
        <translation>%1 Abtastwerte nach der Kopfzeile in Zeile %2%3; ein Log braucht mindestens %4</translation>
    </message>
</context>
<context>
    <name>RobotScenario</name>
    <message>
        <location filename="../core/session/RobotScenario.cpp" line="+99"/>
        <source>controller.samplePeriod: the starter&apos;s gains do not hold the arm in discrete time at %1 ms, even with the derivative gains lowered (a pole at |z| = %2)</source>
        <translation>controller.samplePeriod: die Verstärkungen des Startszenarios halten den Arm bei %1 ms zeitdiskret nicht, auch mit gesenkten D-Verstärkungen (ein Pol bei |z| = %2)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 deg</source>
        <translation>%1 deg</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>robot.model: unknown model &quot;%1&quot;</source>
        <translation>robot.model: unbekanntes Modell „%1“</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>payload: only a URDF robot carries a payload</source>
        <translation>payload: nur ein URDF-Roboter trägt eine Nutzlast</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>controller.samplePeriod: the paper scenario is the paper&apos;s, at %1 ms; pick a URDF robot for another clock</source>
        <translation>controller.samplePeriod: das Szenario des Artikels ist das des Artikels, bei %1 ms; für einen anderen Takt einen URDF-Roboter wählen</translation>
    </message>
    <message>
        <location line="+159"/>
        <source>unknown robot &quot;%1&quot;; known: %2, or a URDF file (FILE.urdf)</source>
        <translation>unbekannter Roboter „%1“; bekannt: %2 oder eine URDF-Datei (DATEI.urdf)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>path.waypoints[%1][%2]: %3 is %4 joint %5 (%6)&apos;s %7 limit %8</source>
        <translation>path.waypoints[%1][%2]: %3 liegt %4 der %7 Grenze %8 von Gelenk %5 (%6)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>below</source>
        <translation>unter</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>above</source>
        <translation>über</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>lower</source>
        <translation>unteren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>upper</source>
        <translation>oberen</translation>
    </message>
</context>
<context>
    <name>SafetyCheck</name>
    <message>
        <location filename="../core/session/SafetyCheck.cpp" line="+154"/>
        <source>joint %1 would reach %2 at t = %3 s, outside its limits %4 to %5</source>
        <translation>Gelenk %1 würde bei t = %3 s %2 erreichen, außerhalb seiner Grenzen %4 bis %5</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>joint %1 would move at %2 at t = %3 s, above its speed limit %4</source>
        <translation>Gelenk %1 würde sich bei t = %3 s mit %2 bewegen, über seiner Geschwindigkeitsgrenze %4</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>the estimate is not a physical robot: its mass matrix is not positive definite at t = %1 s</source>
        <translation>die Schätzung ist kein physikalischer Roboter: ihre Massenmatrix ist bei t = %1 s nicht positiv definit</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the closed loop would be unstable: linearised along the path with the current estimate, a pole has |z| = %1 (growth rate %2 1/s) at t = %3 s. Raise the derivative filter bandwidth lambda or lower the gains</source>
        <translation>der Regelkreis wäre instabil: entlang der Bahn mit der aktuellen Schätzung linearisiert, hat ein Pol bei t = %3 s |z| = %1 (Wachstumsrate %2 1/s). Die Bandbreite lambda des Differenzierfilters erhöhen oder die Verstärkungen senken</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>planned torque of joint %1 is %2 N m, above its limit of %3 N m</source>
        <translation>geplantes Moment von Gelenk %1 ist %2 N m, über seiner Grenze von %3 N m</translation>
    </message>
</context>
<context>
    <name>ScenarioFile</name>
    <message>
        <location filename="../core/io/ScenarioValidation.cpp" line="+234"/>
        <source>must be %1, got %2</source>
        <translation>muss %1 sein, gefunden: %2</translation>
    </message>
    <message>
        <location filename="../core/io/ScenarioFile.cpp" line="+299"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location filename="../core/io/ScenarioValidation.cpp" line="-157"/>
        <source>unknown model &quot;%1&quot;; known models: %2</source>
        <translation>unbekanntes Modell „%1“; bekannte Modelle: %2</translation>
    </message>
    <message>
        <location line="+24"/>
        <location line="+60"/>
        <source>one per joint of %1</source>
        <translation>einer pro Gelenk von %1</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>unknown learning law &quot;%1&quot;; known laws: %2</source>
        <translation>unbekanntes Lerngesetz „%1“; bekannte Gesetze: %2</translation>
    </message>
    <message>
        <location line="-28"/>
        <source>one per parameter of %1</source>
        <translation>einer pro Parameter von %1</translation>
    </message>
    <message>
        <location filename="../core/io/ScenarioFile.cpp" line="-265"/>
        <source>1 or -1</source>
        <translation>1 oder -1</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>must have 2 entries (x and y), got %1</source>
        <translation>muss 2 Einträge haben (x und y), gefunden: %1</translation>
    </message>
    <message>
        <location line="+90"/>
        <source>this version of learnid reads &quot;%1&quot; and &quot;%2&quot;, got %3</source>
        <translation>diese Version von learnid liest „%1“ und „%2“, gefunden: %3</translation>
    </message>
    <message>
        <location filename="../core/io/ScenarioValidation.cpp" line="-130"/>
        <source>one per joint</source>
        <translation>einer pro Gelenk</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>the &quot;urdf&quot; model needs a URDF file</source>
        <translation>das Modell „urdf“ braucht eine URDF-Datei</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>the Cartesian line is the paper-2link arm&apos;s path; a URDF robot runs &quot;waypoints&quot; or &quot;file&quot;</source>
        <translation>die kartesische Gerade ist die Bahn des Arms paper-2link; ein URDF-Roboter fährt „waypoints“ oder „file“</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the paper-2link arm runs the Cartesian &quot;line&quot;</source>
        <translation>der Arm paper-2link fährt die kartesische Gerade „line“</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>needs at least 2 waypoints, got %1</source>
        <translation>braucht mindestens 2 Wegpunkte, gefunden: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>a path of kind &quot;file&quot; needs a CSV file</source>
        <translation>eine Bahn der Art „file“ braucht eine CSV-Datei</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 has %2 joint columns, %3 has %4 joints</source>
        <translation>%1 hat %2 Gelenkspalten, %3 hat %4 Gelenke</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>must be 0 (off) or at least 1 (static friction is not below Coulomb friction), got %1</source>
        <translation>muss 0 (aus) oder mindestens 1 sein (Haftreibung liegt nicht unter der Coulomb-Reibung), ist %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>give static friction either as simulation.staticFriction or as this ratio, not both</source>
        <translation>Haftreibung entweder als simulation.staticFriction oder als dieses Verhältnis angeben, nicht beides</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>applies to elastic joints only: give simulation.jointStiffness</source>
        <translation>gilt nur für elastische Gelenke: simulation.jointStiffness angeben</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>must be 1 or -1, got %1</source>
        <translation>muss 1 oder -1 sein, gefunden: %1</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>needs the improved law (estimator.law &quot;improved&quot;), got &quot;%1&quot;</source>
        <translation>braucht das verbesserte Gesetz (estimator.law &quot;improved&quot;), erhalten &quot;%1&quot;</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>needs a URDF robot with robot.jointTerms.armature true: the rotor inertia the sensor does not see is learned as the armature term</source>
        <translation>braucht einen URDF-Roboter mit robot.jointTerms.armature true: die Rotorträgheit, die der Sensor nicht sieht, wird als Rotorträgheitsterm (armature) gelernt</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>must be 0 (an ideal encoder) or an integer from %1 to %2, got %3</source>
        <translation>muss 0 (idealer Encoder) oder eine ganze Zahl von %1 bis %2 sein, gefunden: %3</translation>
    </message>
    <message>
        <location filename="../core/io/ScenarioChain.cpp" line="+50"/>
        <source>must have 3 entries (x, y, z in the base link&apos;s frame), got %1</source>
        <translation>muss 3 Einträge haben (x, y, z im Koordinatensystem des Basisglieds), gefunden: %1</translation>
    </message>
    <message>
        <location filename="../core/io/ScenarioPayload.cpp" line="+41"/>
        <source>x, y and z</source>
        <translation>x, y und z</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Ixx, Ixy, Iyy, Ixz, Iyz and Izz</source>
        <translation>Ixx, Ixy, Iyy, Ixz, Iyz und Izz</translation>
    </message>
    <message>
        <location line="+18"/>
        <location line="+78"/>
        <source>x0, y0, z0, x1, y1 and z1</source>
        <translation>x0, y0, z0, x1, y1 und z1</translation>
    </message>
    <message>
        <location line="-74"/>
        <source>give the bound either as a sphere (radius) or as a box, not both</source>
        <translation>die Schranke entweder als Kugel (radius) oder als Quader (box) angeben, nicht beides</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>only a URDF robot carries a payload (the model is %1)</source>
        <translation>nur ein URDF-Roboter trägt eine Nutzlast (das Modell ist %1)</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>not a real body&apos;s inertia (principal moments %1, %2, %3 kg m^2 must not be negative and each at most the sum of the others)</source>
        <translation>nicht die Trägheit eines realen Körpers (die Hauptträgheitsmomente %1, %2, %3 kg m^2 dürfen nicht negativ sein, und jedes höchstens die Summe der anderen)</translation>
    </message>
</context>
<context>
    <name>ScenarioRobot</name>
    <message>
        <location filename="../core/session/ScenarioRobot.cpp" line="+73"/>
        <source>robot.torqueLimits: joint %1 (%2) has no effort limit in the URDF: give the torque limits in the scenario</source>
        <translation>robot.torqueLimits: Gelenk %1 (%2) hat im URDF keine Momentengrenze (effort): die Momentengrenzen im Szenario angeben</translation>
    </message>
    <message>
        <location filename="../core/session/ScenarioRobotJoints.cpp" line="+79"/>
        <source>must be at least the simulated robot&apos;s Coulomb friction of joint %1, %2 N m, got %3</source>
        <translation>muss mindestens die Coulomb-Reibung des simulierten Roboters in Gelenk %1 sein, %2 N m, ist %3</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>an elastic joint needs its motor&apos;s rotor inertia: give simulation.armature or simulation.armatureFactor above 0 for joint %1</source>
        <translation>ein elastisches Gelenk braucht die Rotorträgheit seines Motors: simulation.armature oder simulation.armatureFactor über 0 für Gelenk %1 angeben</translation>
    </message>
</context>
<context>
    <name>SdoAbortCode</name>
    <message>
        <location filename="../core/can/SdoAbortCode.cpp" line="+17"/>
        <source>Toggle bit not alternated.</source>
        <translation>Toggle-Bit nicht gewechselt.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO protocol timed out.</source>
        <translation>Zeitüberschreitung im SDO-Protokoll.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Client/server command specifier not valid or unknown.</source>
        <translation>Client/Server-Kommandokennung ungültig oder unbekannt.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Invalid block size (block mode only).</source>
        <translation>Ungültige Blockgröße (nur Blockmodus).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Invalid sequence number (block mode only).</source>
        <translation>Ungültige Sequenznummer (nur Blockmodus).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CRC error (block mode only).</source>
        <translation>CRC-Fehler (nur Blockmodus).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Out of memory.</source>
        <translation>Kein Speicher mehr.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unsupported access to an object.</source>
        <translation>Nicht unterstützter Zugriff auf ein Objekt.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attempt to read a write-only object.</source>
        <translation>Versuch, ein nur schreibbares Objekt zu lesen.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attempt to write a read-only object.</source>
        <translation>Versuch, ein nur lesbares Objekt zu schreiben.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Object does not exist in the object dictionary.</source>
        <translation>Objekt existiert nicht im Objektverzeichnis.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Object cannot be mapped to the PDO.</source>
        <translation>Objekt kann nicht in das PDO gemappt werden.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The number and length of the objects to be mapped would exceed the PDO length.</source>
        <translation>Anzahl und Länge der zu mappenden Objekte würden die PDO-Länge überschreiten.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>General parameter incompatibility.</source>
        <translation>Allgemeine Parameterunverträglichkeit.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>General internal incompatibility in the device.</source>
        <translation>Allgemeine interne Unverträglichkeit im Gerät.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Access failed due to a hardware error.</source>
        <translation>Zugriff wegen eines Hardwarefehlers fehlgeschlagen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Data type does not match: the length of the service parameter does not match.</source>
        <translation>Datentyp passt nicht: die Länge des Dienstparameters passt nicht.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Data type does not match: the length of the service parameter is too high.</source>
        <translation>Datentyp passt nicht: die Länge des Dienstparameters ist zu groß.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Data type does not match: the length of the service parameter is too low.</source>
        <translation>Datentyp passt nicht: die Länge des Dienstparameters ist zu klein.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Sub-index does not exist.</source>
        <translation>Subindex existiert nicht.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Invalid value for the parameter (download only).</source>
        <translation>Ungültiger Wert für den Parameter (nur Download).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Value of the parameter written too high (download only).</source>
        <translation>Geschriebener Parameterwert zu hoch (nur Download).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Value of the parameter written too low (download only).</source>
        <translation>Geschriebener Parameterwert zu niedrig (nur Download).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Maximum value is less than minimum value.</source>
        <translation>Maximalwert ist kleiner als Minimalwert.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Resource not available: SDO connection.</source>
        <translation>Ressource nicht verfügbar: SDO-Verbindung.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>General error.</source>
        <translation>Allgemeiner Fehler.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Data cannot be transferred or stored to the application.</source>
        <translation>Daten können nicht zur Anwendung übertragen oder dort gespeichert werden.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Data cannot be transferred or stored to the application because of local control.</source>
        <translation>Daten können wegen lokaler Steuerung nicht zur Anwendung übertragen oder dort gespeichert werden.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Data cannot be transferred or stored to the application because of the present device state.</source>
        <translation>Daten können wegen des aktuellen Gerätezustands nicht zur Anwendung übertragen oder dort gespeichert werden.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Object dictionary dynamic generation failed or no object dictionary is present.</source>
        <translation>Dynamisches Erzeugen des Objektverzeichnisses fehlgeschlagen oder kein Objektverzeichnis vorhanden.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>No data available.</source>
        <translation>Keine Daten verfügbar.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Unknown abort code %1.</source>
        <translation>Unbekannter Abbruchcode %1.</translation>
    </message>
</context>
<context>
    <name>SdoWrite</name>
    <message>
        <location filename="../core/can/SdoWrite.cpp" line="+14"/>
        <source>%1 is not a valid CANopen node id (1 to 127).</source>
        <translation>%1 ist keine gültige CANopen-Knoten-ID (1 bis 127).</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Node %1, object %2: %3</source>
        <translation>Knoten %1, Objekt %2: %3</translation>
    </message>
</context>
<context>
    <name>SessionExport</name>
    <message>
        <location filename="../core/service/SessionExport.cpp" line="+110"/>
        <source>only URDF robots have a URDF to export</source>
        <translation>nur URDF-Roboter haben ein URDF, das sich exportieren lässt</translation>
    </message>
    <message>
        <location line="-29"/>
        <source>no consistent estimate near estimate %1: %2</source>
        <translation>keine konsistente Schätzung nahe Schätzung %1: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>only URDF robots have standard parameters to make consistent</source>
        <translation>nur URDF-Roboter haben Standardparameter, die sich konsistent machen lassen</translation>
    </message>
    <message>
        <location line="+73"/>
        <source>cannot create the folder %1</source>
        <translation>Ordner %1 kann nicht angelegt werden</translation>
    </message>
</context>
<context>
    <name>SessionReport</name>
    <message>
        <location filename="../core/service/SessionReport.cpp" line="+131"/>
        <source>estimate %1 does not exist in this session</source>
        <translation>Schätzung %1 existiert in dieser Sitzung nicht</translation>
    </message>
</context>
<context>
    <name>SimulatedRobot</name>
    <message>
        <location filename="../core/robot/SimulatedRobot.cpp" line="+57"/>
        <source>simulated %1</source>
        <translation>Simulation %1</translation>
    </message>
    <message>
        <location line="+96"/>
        <source>tracking error of joint %1 reached %2 deg at t = %3 s (limit %4 deg): quick stop</source>
        <translation>Folgefehler von Gelenk %1 erreichte %2° bei t = %3 s (Grenze %4°): Schnellhalt</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>drive of joint 1 reported a fault at t = %1 s (injected)</source>
        <translation>Antrieb von Gelenk 1 meldete bei t = %1 s einen Fehler (eingespeist)</translation>
    </message>
    <message>
        <location line="-121"/>
        <source>stopped by the operator at t = %1 s</source>
        <translation>vom Bediener gestoppt bei t = %1 s</translation>
    </message>
    <message>
        <location line="+148"/>
        <source>the simulated controller refused the parameter write (injected fault); its stored parameters are unchanged</source>
        <translation>die simulierte Steuerung lehnte das Schreiben der Parameter ab (eingespeister Fehler); ihre gespeicherten Parameter sind unverändert</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>parameter set has %1 values, the model needs %2 finite values</source>
        <translation>der Parametersatz hat %1 Werte, das Modell braucht %2 endliche Werte</translation>
    </message>
</context>
<context>
    <name>StandardExport</name>
    <message>
        <location filename="../core/service/StandardExport.cpp" line="+38"/>
        <source>data</source>
        <translation>Daten</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>undetermined (kept near the prior)</source>
        <translation>unbestimmt (nahe am Prior gehalten)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 standard parameters given, the model has %2</source>
        <translation>%1 Standardparameter angegeben, das Modell hat %2</translation>
    </message>
</context>
<context>
    <name>Text</name>
    <message>
        <location filename="../core/model/UrdfChain.cpp" line="+55"/>
        <source>%1: not a valid URDF: %2</source>
        <translation>%1: kein gültiges URDF: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the parser gave no reason</source>
        <translation>der Parser nannte keinen Grund</translation>
    </message>
    <message>
        <location filename="../core/session/ScenarioRobot.cpp" line="-41"/>
        <source>simulation.realUrdf: %1 has %2 moving joints, the robot %3</source>
        <translation>simulation.realUrdf: %1 hat %2 bewegliche Gelenke, der Roboter %3</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>simulation.realUrdf: joint %1 (%2) is placed differently from the robot&apos;s URDF: the real robot may differ in inertia and friction only</source>
        <translation>simulation.realUrdf: Gelenk %1 (%2) sitzt anders als im URDF des Roboters: der reale Roboter darf nur in Trägheit und Reibung abweichen</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>simulation.realUrdf: %1 is not a robot that could be built: %2</source>
        <translation>simulation.realUrdf: %1 ist kein Roboter, der sich bauen ließe: %2</translation>
    </message>
    <message>
        <location filename="../core/identify/UniformLog.cpp" line="+145"/>
        <source>%1: the time stamps are off the nominal times t0 + k T (T = %2 ms) by %3 ms at %4 (t = %5 s) and by %6 ms at %7 (t = %8 s), more than half a step apart: the samples are not equidistant (one lost or added?), so the nominal times do not apply</source>
        <translation>%1: die Zeitstempel weichen von den Sollzeiten t0 + k T (T = %2 ms) um %3 ms bei %4 (t = %5 s) und um %6 ms bei %7 (t = %8 s) ab, mehr als einen halben Schritt auseinander: die Abtastwerte sind nicht äquidistant (einer verloren oder hinzugekommen?), also gelten die Sollzeiten nicht</translation>
    </message>
    <message>
        <location filename="../core/service/FileLoop.cpp" line="-45"/>
        <source>%1: %2 holds %3 parameters of robot %4; the scenario&apos;s robot %5 has %6</source>
        <translation>%1: %2 enthält %3 Parameter des Roboters %4; der Roboter des Szenarios, %5, hat %6</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: %2: parameter %3 is &quot;%4&quot;, the robot&apos;s is &quot;%5&quot;</source>
        <translation>%1: %2: Parameter %3 ist „%4“, der des Roboters ist „%5“</translation>
    </message>
    <message>
        <location filename="../core/session/ScenarioRobotJoints.cpp" line="-50"/>
        <source>needs a URDF robot (the link&apos;s inertia about its axis); %1 has none: give simulation.armature in kg m^2</source>
        <translation>braucht einen URDF-Roboter (die Trägheit des Glieds um seine Achse); %1 hat keinen: simulation.armature in kg m^2 angeben</translation>
    </message>
    <message>
        <location filename="../core/service/FileLoopParts.cpp" line="-52"/>
        <source>%1 ran plan %2, which the history %3 has learned from already as trial %4: plan the next trial and run that</source>
        <translation>%1 lief mit Plan %2, aus dem der Verlauf %3 bereits als Versuch %4 gelernt hat: den nächsten Versuch planen und diesen ausführen</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 ran plan %2, which the history %3 does not know; its plans to run are: %4</source>
        <translation>%1 lief mit Plan %2, den der Verlauf %3 nicht kennt; seine auszuführenden Pläne sind: %4</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>none (plan the next trial first)</source>
        <translation>keine (zuerst den nächsten Versuch planen)</translation>
    </message>
</context>
<context>
    <name>TorqueRule</name>
    <message>
        <location filename="../core/motion/TorqueRule.cpp" line="+23"/>
        <source>torque rule needs 2 grid points</source>
        <translation>die Momentenregel braucht 2 Stützstellen</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>torque rule: the path has %1 joints, the robot model %2</source>
        <translation>Momentenregel: die Bahn hat %1 Gelenke, das Robotermodell %2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>torque rule needs one positive limit per joint and a positive fraction</source>
        <translation>die Momentenregel braucht eine positive Grenze pro Gelenk und einen positiven Anteil</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>gravity alone needs %1 N m at joint %2 on this path, more than %3 % of its %4 N m limit: no duration can meet the torque rule</source>
        <translation>allein die Schwerkraft braucht auf dieser Bahn %1 N m an Gelenk %2, mehr als %3 % seiner Grenze von %4 N m: keine Dauer kann die Momentenregel erfüllen</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the path needs no torque: check its length and the parameters</source>
        <translation>die Bahn braucht kein Moment: Länge und Parameter prüfen</translation>
    </message>
</context>
<context>
    <name>TrialCsv</name>
    <message>
        <location filename="../core/io/TrialCsv.cpp" line="+55"/>
        <source>trial CSV: the record (%1 joints, %2 samples) does not fit its plan (%3 joints, %4 samples)</source>
        <translation>Versuchs-CSV: die Aufzeichnung (%1 Gelenke, %2 Abtastwerte) passt nicht zu ihrem Plan (%3 Gelenke, %4 Abtastwerte)</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>the file is empty; expected the header line</source>
        <translation>die Datei ist leer; erwartet wird die Kopfzeile</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the header must be %1 (for one or more joints), got %2</source>
        <translation>die Kopfzeile muss %1 lauten (für ein oder mehrere Gelenke), gefunden: %2</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>expected %1 fields, got %2</source>
        <translation>%1 Felder erwartet, gefunden: %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 is not a number: &quot;%2&quot;</source>
        <translation>%1 ist keine Zahl: „%2“</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>t_s must be finite and increase from line to line, got %1</source>
        <translation>t_s muss endlich sein und von Zeile zu Zeile zunehmen, gefunden: %1</translation>
    </message>
</context>
<context>
    <name>TrialPlanner</name>
    <message>
        <location filename="../core/session/TrialPlanner.cpp" line="-79"/>
        <source>the path has %1 joints, the robot %2</source>
        <translation>die Bahn hat %1 Gelenke, der Roboter %2</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>only planar 2-link arms have Cartesian line kinematics</source>
        <translation>nur ebene Zweigelenkarme haben eine kartesische Geradenkinematik</translation>
    </message>
</context>
<context>
    <name>TrialResult</name>
    <message numerus="yes">
        <location filename="../core/session/TrialResult.cpp" line="+36"/>
        <source>%n set-point(s) reached the drives after their SYNC (statusword bit 12): the drives held the previous one, so this trial&apos;s motion is not quite the plan&apos;s and neither is what it teaches; close other programs on this computer</source>
        <translation>
            <numerusform>%n Sollwert erreichte die Antriebe nach seinem SYNC (Statuswort Bit 12): Die Antriebe hielten den vorherigen, daher entspricht die Bewegung dieses Versuchs nicht ganz dem Plan und das daraus Gelernte ebenso wenig; schließen Sie andere Programme auf diesem Rechner</numerusform>
            <numerusform>%n Sollwerte erreichten die Antriebe nach ihrem SYNC (Statuswort Bit 12): Die Antriebe hielten jeweils den vorherigen, daher entspricht die Bewegung dieses Versuchs nicht ganz dem Plan und das daraus Gelernte ebenso wenig; schließen Sie andere Programme auf diesem Rechner</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>TrialSeries</name>
    <message>
        <location filename="../core/session/TrialSeries.cpp" line="+70"/>
        <source>Run all stops: %1 trials in a row stopped at the tracking limit, and trial %2 was no progress over trial %3 (stopped at t = %4 s with %5 deg, against t = %6 s with %7 deg)</source>
        <translation>„Alle starten“ hält an: %1 Versuche hintereinander stoppten an der Grenze des Folgefehlers, und Versuch %2 war kein Fortschritt gegenüber Versuch %3 (gestoppt bei t = %4 s mit %5 Grad, gegenüber t = %6 s mit %7 Grad)</translation>
    </message>
    <message>
        <location line="+82"/>
        <source>trial %1 tracked worse than trial %2 (max %3 deg against %4 deg)</source>
        <translation>Versuch %1 folgte schlechter als Versuch %2 (max. %3 Grad gegenüber %4 Grad)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1; Accept proposes estimate %2, which tracked best</source>
        <translation>%1; „Akzeptieren“ schlägt Schätzung %2 vor, die am besten folgte</translation>
    </message>
</context>
<context>
    <name>TrialStatus</name>
    <message>
        <location filename="../core/types/Trial.cpp" line="+11"/>
        <source>completed</source>
        <translation>abgeschlossen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>aborted</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>robot fault</source>
        <translation>Roboterfehler</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>cancelled</source>
        <translation>vom Bediener gestoppt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>refused</source>
        <translation>abgelehnt</translation>
    </message>
</context>
<context>
    <name>TwoLinkArm</name>
    <message>
        <location filename="../core/model/TwoLinkArm.cpp" line="+15"/>
        <source>inertia of the base axis</source>
        <translation>Trägheit der Basisachse</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>coupling inertia of the two links</source>
        <translation>Koppelträgheit der beiden Glieder</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>inertia of the second link</source>
        <translation>Trägheit des zweiten Glieds</translation>
    </message>
</context>
<context>
    <name>TwoLinkKinematics</name>
    <message>
        <location filename="../core/motion/TwoLinkKinematics.cpp" line="+39"/>
        <source>point (%1, %2) m is out of reach or at a singularity of the arm (link lengths %3 m and %4 m)</source>
        <translation>Punkt (%1, %2) m ist außer Reichweite oder in einer Singularität des Arms (Gliedlängen %3 m und %4 m)</translation>
    </message>
</context>
<context>
    <name>UniformLog</name>
    <message>
        <location filename="../core/identify/UniformLog.cpp" line="-99"/>
        <source>sample %1</source>
        <translation>Abtastwert %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>line %1</source>
        <translation>Zeile %1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source> (line %1 is stale: it repeated the values of line %2 under a new time stamp and counts as missing)</source>
        <translation> (Zeile %1 ist veraltet: sie wiederholte die Werte von Zeile %2 unter einem neuen Zeitstempel und zählt als fehlend)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source> (lines %1 to %2 are stale: %3 rows that repeated the values of line %4 under new time stamps and count as missing)</source>
        <translation> (Zeilen %1 bis %2 sind veraltet: %3 Zeilen, die die Werte von Zeile %4 unter neuen Zeitstempeln wiederholten und als fehlend zählen)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: a log of %2 times, %3 x %4 positions, %5 x %6 velocities, %7 x %8 torques and %9 line numbers; expected n x N for all</source>
        <translation>%1: ein Log mit %2 Zeiten, %3 x %4 Positionen, %5 x %6 Geschwindigkeiten, %7 x %8 Momenten und %9 Zeilennummern; erwartet wird n x N für alle</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: %2 samples; resampling needs at least 2</source>
        <translation>%1: %2 Abtastwerte; das Neuabtasten braucht mindestens 2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: a value is not a finite number</source>
        <translation>%1: ein Wert ist keine endliche Zahl</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: the times must increase from sample to sample, got %2 after %3</source>
        <translation>%1: die Zeiten müssen von Abtastwert zu Abtastwert zunehmen, gefunden: %2 nach %3</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: the log spans %2 to %3 s, too long to resample</source>
        <translation>%1: das Log reicht von %2 bis %3 s, zu lang zum Neuabtasten</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>%1: the period (%2 s) and the largest gap (%3 s) must be zero (the default) or positive</source>
        <translation>%1: die Periode (%2 s) und die größte Lücke (%3 s) müssen null (der Standard) oder positiv sein</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the fit&apos;s filter bandwidth rho (%2 rad/s) must be positive</source>
        <translation>%1: die Bandbreite rho des Filters der Anpassung (%2 rad/s) muss positiv sein</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 ms allowed (--max-gap)</source>
        <translation>erlaubten %1 ms (--max-gap)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 ms allowed (--max-gap; by default half the time constant 1/rho of the fit&apos;s filter, rho = %2 rad/s, and at least %3 of the log&apos;s steps)</source>
        <translation>erlaubten %1 ms (--max-gap; standardmäßig die halbe Zeitkonstante 1/rho des Filters der Anpassung, rho = %2 rad/s, und mindestens %3 Schritte des Logs)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: a gap of %2 ms after the sample at t = %3 s%4, more than the %5</source>
        <translation>%1: eine Lücke von %2 ms nach dem Abtastwert bei t = %3 s%4, mehr als die %5</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: a period of %2 ms over the log&apos;s %3 s gives %4 samples; expected 2 to %5 (100 per sample of the log)</source>
        <translation>%1: eine Periode von %2 ms über die %3 s des Logs ergibt %4 Abtastwerte; erwartet: 2 bis %5 (100 pro Abtastwert des Logs)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1: values this close to the largest double cannot be interpolated</source>
        <translation>%1: Werte so nahe am größten double-Wert lassen sich nicht interpolieren</translation>
    </message>
</context>
<context>
    <name>UrdfChain</name>
    <message>
        <location filename="../core/model/UrdfChain.cpp" line="+21"/>
        <source>%1: link &quot;%2&quot; has a negative mass (%3 kg)</source>
        <translation>%1: Glied „%2“ hat eine negative Masse (%3 kg)</translation>
    </message>
    <message>
        <location line="+51"/>
        <source>%1: the robot branches at link &quot;%2&quot; (children %3): name the tip link of the chain</source>
        <translation>%1: der Roboter verzweigt sich am Glied „%2“ (Kindglieder %3): das Endglied der Kette angeben</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1: joint &quot;%2&quot; has no axis (zero vector)</source>
        <translation>%1: Gelenk „%2“ hat keine Achse (Nullvektor)</translation>
    </message>
    <message>
        <location line="+32"/>
        <location line="+4"/>
        <source>%1: no link &quot;%2&quot;</source>
        <translation>%1: kein Glied „%2“</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: link &quot;%2&quot; is not below link &quot;%3&quot;</source>
        <translation>%1: Glied „%2“ liegt nicht unterhalb von Glied „%3“</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1: joint &quot;%2&quot; mimics another joint: mimic joints are not supported</source>
        <translation>%1: Gelenk „%2“ ahmt ein anderes Gelenk nach (mimic): Mimic-Gelenke werden nicht unterstützt</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1: joint &quot;%2&quot; is floating or planar: only revolute, continuous, prismatic and fixed joints form a serial arm</source>
        <translation>%1: Gelenk „%2“ ist frei (floating) oder eben (planar): nur Drehgelenke (revolute, continuous), Schubgelenke (prismatic) und feste Gelenke (fixed) bilden einen seriellen Arm</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: no moving joint between link &quot;%2&quot; and link &quot;%3&quot;</source>
        <translation>%1: kein bewegliches Gelenk zwischen Glied „%2“ und Glied „%3“</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1: cannot read the URDF: %2</source>
        <translation>%1: das URDF kann nicht gelesen werden: %2</translation>
    </message>
</context>
<context>
    <name>UrdfExport</name>
    <message>
        <location filename="../core/io/UrdfExport.cpp" line="+122"/>
        <source>%1: link &quot;%2&quot;: the identified body has an entry that is not a finite number</source>
        <translation>%1: Glied „%2“: der identifizierte Körper hat einen Eintrag, der keine endliche Zahl ist</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: link &quot;%2&quot;: the identified mass (%3 kg) is not positive</source>
        <translation>%1: Glied „%2“: die identifizierte Masse (%3 kg) ist nicht positiv</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: link &quot;%2&quot;: the identified inertia is not that of a physical body (its pseudo-inertia has the negative eigenvalue %3)</source>
        <translation>%1: Glied „%2“: die identifizierte Trägheit ist nicht die eines physikalischen Körpers (ihre Pseudoträgheit hat den negativen Eigenwert %3)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: joint &quot;%2&quot;: the friction must be finite and not negative, got viscous %3 and Coulomb %4</source>
        <translation>%1: Gelenk „%2“: die Reibung muss endlich und nicht negativ sein, gefunden: viskos %3 und Coulomb %4</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: joint &quot;%2&quot;: the armature must be finite and not negative and the offset finite, got armature %3 and offset %4</source>
        <translation>%1: Gelenk „%2“: die Rotorträgheit muss endlich und nicht negativ und der Offset endlich sein, gefunden: Rotorträgheit %3 und Offset %4</translation>
    </message>
    <message>
        <location line="+158"/>
        <source>%1: the identified URDF reads back with another body or friction at link &quot;%2&quot; than was written</source>
        <translation>%1: das identifizierte URDF ergibt beim Zurücklesen am Glied „%2“ einen anderen Körper oder eine andere Reibung, als geschrieben wurde</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1: bodies for %2 and friction for %3 joints given, the chain has %4 moving joints</source>
        <translation>%1: Körper für %2 und Reibung für %3 Gelenke angegeben, die Kette hat %4 bewegliche Gelenke</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: the chain&apos;s moving joints (%2) are not the URDF&apos;s from link &quot;%3&quot; to link &quot;%4&quot; (%5): the chain was not read from this URDF</source>
        <translation>%1: die beweglichen Gelenke der Kette (%2) sind nicht die des URDF von Glied „%3“ bis Glied „%4“ (%5): die Kette wurde nicht aus diesem URDF gelesen</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: line %2, column %3: not XML: %4</source>
        <translation>%1: Zeile %2, Spalte %3: kein XML: %4</translation>
    </message>
    <message>
        <location filename="../core/io/UrdfPayload.cpp" line="+98"/>
        <source>%1: the payload on link &quot;%2&quot; is not a real body (mass %3 kg)</source>
        <translation>%1: die Nutzlast am Glied „%2“ ist kein realer Körper (Masse %3 kg)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: no closing &lt;/robot&gt; to add the payload before</source>
        <translation>%1: kein schließendes &lt;/robot&gt;, vor dem die Nutzlast eingefügt werden kann</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: the URDF with the payload reads back with another body at link &quot;%2&quot; than was written</source>
        <translation>%1: das URDF mit der Nutzlast ergibt beim Zurücklesen am Glied „%2“ einen anderen Körper, als geschrieben wurde</translation>
    </message>
</context>
<context>
    <name>UrdfExtension</name>
    <message>
        <location filename="../core/model/UrdfExtension.cpp" line="+20"/>
        <source>%1: line %2, column %3: &lt;%4&gt;: %5</source>
        <translation>%1: Zeile %2, Spalte %3: &lt;%4&gt;: %5</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>unknown attribute &quot;%1&quot; (the attributes are armature and offset)</source>
        <translation>unbekanntes Attribut „%1“ (die Attribute sind armature und offset)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 must be a finite number, got &quot;%2&quot;</source>
        <translation>%1 muss eine endliche Zahl sein, gefunden: „%2“</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>given twice in joint &quot;%1&quot;</source>
        <translation>zweimal in Gelenk „%1“ angegeben</translation>
    </message>
</context>
<context>
    <name>UrdfGeometry</name>
    <message>
        <location filename="../core/model/UrdfGeometry.cpp" line="+85"/>
        <source>%1: link &quot;%2&quot;, &lt;%3&gt; %4: %5</source>
        <translation>%1: Glied „%2“, &lt;%3&gt; %4: %5</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the box&apos;s size is negative or not a number</source>
        <translation>die Größe des Quaders ist negativ oder keine Zahl</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the cylinder&apos;s radius or length is negative or not a number</source>
        <translation>Radius oder Länge des Zylinders ist negativ oder keine Zahl</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the sphere&apos;s radius is negative or not a number</source>
        <translation>der Radius der Kugel ist negativ oder keine Zahl</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the mesh&apos;s scale is not a number</source>
        <translation>der Maßstab des Netzes ist keine Zahl</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>mesh &quot;%1&quot; of link &quot;%2&quot; skipped: %3</source>
        <translation>Netz „%1“ von Glied „%2“ übersprungen: %3</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>1 box</source>
        <translation>1 Quader</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 boxes</source>
        <translation>%1 Quader</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1 cylinder</source>
        <translation>1 Zylinder</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 cylinders</source>
        <translation>%1 Zylinder</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1 sphere</source>
        <translation>1 Kugel</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 spheres</source>
        <translation>%1 Kugeln</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1 mesh</source>
        <translation>1 Netz</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 meshes</source>
        <translation>%1 Netze</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>visual shapes of %1 (no collision shape)</source>
        <translation>Sichtformen von %1 (keine Kollisionsform)</translation>
    </message>
</context>
<context>
    <name>UrdfJointTree</name>
    <message>
        <location filename="../core/model/UrdfJointTree.cpp" line="+69"/>
        <source>%1: line %2, column %3: not well-formed XML: %4</source>
        <translation>%1: Zeile %2, Spalte %3: kein wohlgeformtes XML: %4</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1: joint &quot;%2&quot; connects link &quot;%3&quot; to itself</source>
        <translation>%1: Gelenk „%2“ verbindet Glied „%3“ mit sich selbst</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: link &quot;%2&quot; is the child of two joints, &quot;%3&quot; and &quot;%4&quot;: the joints of a URDF form a tree</source>
        <translation>%1: Glied „%2“ ist Kind zweier Gelenke, „%3“ und „%4“: die Gelenke einer URDF bilden einen Baum</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1: the joints form a loop through links %2: the joints of a URDF form a tree</source>
        <translation>%1: die Gelenke bilden eine Schleife durch die Glieder %2: die Gelenke einer URDF bilden einen Baum</translation>
    </message>
</context>
<context>
    <name>ValueChecks</name>
    <message>
        <location filename="../core/io/ValueChecks.cpp" line="+23"/>
        <source>must be a finite number, got %1</source>
        <translation>muss eine endliche Zahl sein, gefunden: %1</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>must be %1, got %2</source>
        <translation>muss %1 sein, gefunden: %2</translation>
    </message>
    <message>
        <location line="-46"/>
        <source>must be a positive number, got %1</source>
        <translation>muss eine positive Zahl sein, gefunden: %1</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>the drives store it as REAL32, so it must be a finite number of at most %1 in magnitude, got %2</source>
        <translation>die Antriebe speichern den Wert als REAL32, er muss also eine endliche Zahl mit einem Betrag von höchstens %1 sein, erhalten: %2</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>must be zero or a positive number, got %1</source>
        <translation>muss null oder eine positive Zahl sein, gefunden: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>must be zero, a positive number or unbounded (null), got %1</source>
        <translation>muss null, eine positive Zahl oder unbegrenzt (null) sein, gefunden: %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>must be from %1 to %2</source>
        <translation>muss zwischen %1 und %2 liegen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>must be greater than %1 and at most %2</source>
        <translation>muss größer als %1 und höchstens %2 sein</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>must be greater than %1 and less than %2</source>
        <translation>muss größer als %1 und kleiner als %2 sein</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1, got %2</source>
        <translation>%1, gefunden: %2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>must have %1 entries (%2), got %3</source>
        <translation>muss %1 Einträge haben (%2), gefunden: %3</translation>
    </message>
</context>
<context>
    <name>learnid-cli</name>
    <message>
        <location filename="../app/cli/IdentifyCommand.cpp" line="+44"/>
        <source>--robot: &apos;%1&apos; is neither a URDF file nor a built-in robot (%2)</source>
        <translation>--robot: &apos;%1&apos; ist weder eine URDF-Datei noch ein eingebauter Roboter (%2)</translation>
    </message>
    <message>
        <location line="+58"/>
        <source>robot %1: %2, %3 moving joints</source>
        <translation>Roboter %1: %2, %3 bewegliche Gelenke</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>learnid-cli: reading %1</source>
        <translation>learnid-cli: %1 wird gelesen</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>fitting %1 standard parameters to %n log(s)</source>
        <translation>
            <numerusform>%1 Standardparameter werden an %n Log angepasst</numerusform>
            <numerusform>%1 Standardparameter werden an %n Logs angepasst</numerusform>
        </translation>
    </message>
    <message>
        <location line="+49"/>
        <source>identified by learnid-cli %1 identify on %2</source>
        <translation>identifiziert von learnid-cli %1 identify am %2</translation>
    </message>
    <message>
        <location line="-99"/>
        <source>%1: torque predicted and measured</source>
        <translation>%1: vorhergesagtes und gemessenes Moment</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>learnid: %1 identified from logs</source>
        <translation>learnid: %1 aus Logs identifiziert</translation>
    </message>
    <message>
        <location line="+66"/>
        <location line="+37"/>
        <location filename="../app/cli/LoopCommands.cpp" line="+19"/>
        <location filename="../app/cli/PayloadCommand.cpp" line="+215"/>
        <location filename="../app/cli/PayloadRunCommand.cpp" line="+137"/>
        <location line="+13"/>
        <location filename="../app/cli/RunCommand.cpp" line="+106"/>
        <location line="+9"/>
        <location line="+6"/>
        <location line="+13"/>
        <location line="+14"/>
        <location line="+69"/>
        <location line="+62"/>
        <location filename="../app/cli/main.cpp" line="+54"/>
        <source>learnid-cli: error: %1</source>
        <translation>learnid-cli: Fehler: %1</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>--plots: cannot create %1</source>
        <translation>--plots: %1 kann nicht angelegt werden</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>wrote %1</source>
        <translation>%1 geschrieben</translation>
    </message>
    <message>
        <location filename="../app/cli/CliOptions.cpp" line="+71"/>
        <source>Usage: learnid-cli %1 [options]

%2

%3</source>
        <translation>Aufruf: learnid-cli %1 [Optionen]

%2

%3</translation>
    </message>
    <message>
        <location filename="../app/cli/RunCommandLine.cpp" line="+25"/>
        <source>--robot: must be &apos;sim&apos; or &apos;can&apos;, got &apos;%1&apos;</source>
        <translation>--robot: muss &apos;sim&apos; oder &apos;can&apos; sein, gefunden: &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+7"/>
        <source>--%1 needs --robot can</source>
        <translation>--%1 braucht --robot can</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--robot can needs --can-plugin (e.g. socketcan, virtualcan)</source>
        <translation>--robot can braucht --can-plugin (z. B. socketcan, virtualcan)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>--robot can needs --can-interface (e.g. can0)</source>
        <translation>--robot can braucht --can-interface (z. B. can0)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>--can-drives: %1</source>
        <translation>--can-drives: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--can-drives: %1 records no drives (robot.drives): export it from a session on CAN drives</source>
        <translation>--can-drives: %1 verzeichnet keine Antriebe (robot.drives): exportieren Sie sie aus einer Sitzung mit CAN-Antrieben</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>--nodes: %1 in &apos;%2&apos;</source>
        <translation>--nodes: %1 in &apos;%2&apos;</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--can-sync-timeout: must be a whole number of ms from 1 to 60000, got &apos;%1&apos;</source>
        <translation>--can-sync-timeout: muss eine ganze Zahl von ms von 1 bis 60000 sein, gefunden: &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../app/cli/RunCommand.cpp" line="-207"/>
        <location filename="../app/cli/RunCommandLine.cpp" line="+9"/>
        <source>--nodes %1: %2</source>
        <translation>--nodes %1: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../app/cli/RunCommandLine.cpp" line="+2"/>
        <source>--robot %1: %2</source>
        <translation>--robot %1: %2</translation>
    </message>
    <message>
        <location filename="../app/cli/CliOptions.cpp" line="+97"/>
        <source>Show this command&apos;s options.</source>
        <translation>Die Optionen dieses Befehls anzeigen.</translation>
    </message>
    <message>
        <location line="-73"/>
        <source>Print the default scenario.</source>
        <translation>Standardszenario ausgeben.</translation>
    </message>
    <message>
        <location filename="../app/cli/LoopOptions.cpp" line="+44"/>
        <location filename="../app/cli/RunCommandLine.cpp" line="+14"/>
        <source>Scenario file (JSON, docs/scenario.md); default: the paper scenario.</source>
        <translation>Szenariodatei (JSON, docs/scenario.md); Standard: das Szenario des Artikels.</translation>
    </message>
    <message>
        <location filename="../app/cli/RunCommandLine.cpp" line="+4"/>
        <source>Learning law: paper or improved.</source>
        <translation>Lerngesetz: paper oder improved.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Learning trials, 1 to 100.</source>
        <translation>Lernversuche, 1 bis 100.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write the session report (JSON) to FILE.</source>
        <translation>Den Sitzungsbericht (JSON) nach FILE schreiben.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Write the parameter file (JSON and DCF) to FILE.</source>
        <translation>Die Parameterdatei (JSON und DCF) nach FILE schreiben.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Write each trial&apos;s samples as CSV into DIR.</source>
        <translation>Die Abtastwerte jedes Versuchs als CSV nach DIR schreiben.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Accept and apply the final estimate to the robot.</source>
        <translation>Die letzte Schätzung übernehmen und auf den Roboter übertragen.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Export and apply the nearest physically consistent estimate to the final one (URDF robots).</source>
        <translation>Die der letzten Schätzung nächste physikalisch konsistente Schätzung exportieren und übernehmen (URDF-Roboter).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Folder that relative output paths are taken from; default: the current directory.</source>
        <translation>Ordner, ab dem relative Ausgabepfade gelten; Standard: das aktuelle Verzeichnis.</translation>
    </message>
    <message>
        <location filename="../app/cli/IdentifyOptions.cpp" line="+229"/>
        <location filename="../app/cli/LoopOptions.cpp" line="+14"/>
        <location filename="../app/cli/RunCommandLine.cpp" line="+5"/>
        <source>No progress lines on stderr.</source>
        <translation>Keine Fortschrittszeilen auf stderr.</translation>
    </message>
    <message>
        <location filename="../app/cli/RunCommandLine.cpp" line="+2"/>
        <source>sim (default) or can.</source>
        <translation>sim (Standard) oder can.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>QCanBus plugin, e.g. socketcan or virtualcan.</source>
        <translation>QCanBus-Plugin, z. B. socketcan oder virtualcan.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CAN interface, e.g. can0.</source>
        <translation>CAN-Schnittstelle, z. B. can0.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>CANopen node id of each joint&apos;s drive, e.g. 1,2.</source>
        <translation>CANopen-Knotennummer des Antriebs jedes Gelenks, z. B. 1,2.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Longest SYNC gap in a trial [ms].</source>
        <translation>Längste SYNC-Lücke in einem Versuch [ms].</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Write each trial&apos;s CAN frames as a candump log into DIR.</source>
        <translation>Die CAN-Frames jedes Versuchs als candump-Log nach DIR schreiben.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>First commissioning: you confirmed that each node is the drive of its joint (docs/can-protocol.md 2.4).</source>
        <translation>Erstinbetriebnahme: Sie haben bestätigt, dass jeder Knoten der Antrieb seines Gelenks ist (docs/can-protocol.md 2.4).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A parameter file of this robot: its drives&apos; identities (0x1018) must match.</source>
        <translation>Eine Parameterdatei dieses Roboters: die Identitäten seiner Antriebe (0x1018) müssen übereinstimmen.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A recorded trial (candump log); once per trial, in order.</source>
        <translation>Ein aufgezeichneter Versuch (candump-Log); einmal pro Versuch, der Reihe nach.</translation>
    </message>
    <message>
        <location filename="../app/cli/CliOptions.cpp" line="-76"/>
        <source>Usage:
  learnid-cli scenario --print [--robot ROBOT]
      Print a complete scenario as JSON. ROBOT: paper (the default: the paper
      scenario), panda, puma560, double-pendulum or a URDF file; for a robot
      other than paper, the gains the window designs for it and a path of
      joint waypoints inside its limits. With --payload --payload-mass KG
      [--payload-com X,Y,Z] [--payload-link LINK] ...: a scenario that learns
      that payload, the gains designed for the arm carrying it. With
      --sample-period MS: gains that hold at the robot&apos;s clock (default 2 ms).
  learnid-cli run [--scenario FILE] [--estimator paper|improved] [--iterations N]
                  [--report FILE] [--export FILE] [--trial-csv DIR] [--apply]
                  [--consistent] [--workspace DIR] [--quiet]
      Run a commissioning session on the simulated robot. The table goes to
      stdout, progress to stderr. Relative output paths are taken from
      --workspace (default: the current directory). Files are written only
      when every trial completed.
      --robot can --can-plugin P --can-interface I [--nodes 1,2] [--can-log DIR]
      runs it on CiA 402 drives on a CAN bus instead (docs/can-protocol.md);
      --can-log writes every trial&apos;s frames as a candump log into DIR;
      --can-sync-timeout MS stops a trial when no SYNC comes for MS (default 20).
  learnid-cli replay --candump FILE [--candump FILE2 ...] [--scenario FILE]
                     [--estimator paper|improved] [--nodes 1,2] [--report FILE]
                     [--export FILE] [--trial-csv DIR] [--workspace DIR] [--quiet]
      Re-identify from recorded trials: the session runs again with each log
      (one per trial, in order) answering in place of the robot.
  learnid-cli identify --robot ROBOT --log FILE [--log FILE2 ...]
                       [--validate FILE ...] [--columns SPEC] [--joint-terms LIST]
                       [--rho R] [--prior-share S] [--velocity auto|measured|q]
                       [--max-gap MS] [--torque-sensor-lag MS] [--base-link L]
                       [--tip-link L] [--export FILE] [--urdf-out FILE] [--report FILE]
                       [--plots DIR] [--scenario FILE] [--workspace DIR] [--quiet]
      Identify a real robot&apos;s inertia and friction from its recorded logs (CSV)
      and compare the result with its URDF on the --validate logs.
  learnid-cli plan --out DIR [--scenario FILE] [--estimate FILE] [--history DIR]
                   [--workspace DIR] [--quiet]
      Plan the next trial for the robot&apos;s own controller: q_d(t) and tau_f(t)
      (DIR/plan.csv) and the pre-trial check (DIR/check.txt).
  learnid-cli learn --trial-log FILE [--scenario FILE] [--history DIR]
                    [--workspace DIR] [--quiet]
      Learn from the controller&apos;s log of a plan; the next plan uses the new
      estimate.
  learnid-cli COMMAND --help
      The options of one command.
</source>
        <translation>Aufruf:
  learnid-cli scenario --print [--robot ROBOT]
      Gibt ein vollständiges Szenario als JSON aus. ROBOT: paper (Standard: das
      Szenario des Artikels), panda, puma560, double-pendulum oder eine URDF-Datei;
      für einen anderen Roboter als paper die Verstärkungen, die das Fenster für ihn
      auslegt, und eine Bahn aus Gelenk-Stützpunkten innerhalb seiner Grenzen.
      Mit --payload --payload-mass KG [--payload-com X,Y,Z] [--payload-link LINK] ...:
      ein Szenario, das diese Nutzlast lernt, mit Verstärkungen für den Arm, der sie trägt.
      Mit --sample-period MS: Verstärkungen, die beim Takt des Roboters halten (Standard 2 ms).
  learnid-cli run [--scenario FILE] [--estimator paper|improved] [--iterations N]
                  [--report FILE] [--export FILE] [--trial-csv DIR] [--apply]
                  [--consistent] [--workspace DIR] [--quiet]
      Führt eine Inbetriebnahmesitzung am simulierten Roboter aus. Tabelle nach
      stdout, Fortschritt nach stderr. Relative Ausgabepfade gelten ab
      --workspace (Standard: aktuelles Verzeichnis). Dateien werden nur
      geschrieben, wenn jeder Versuch abgeschlossen wurde.
      --robot can --can-plugin P --can-interface I [--nodes 1,2] [--can-log DIR]
      führt sie stattdessen an CiA-402-Antrieben am CAN-Bus aus (docs/can-protocol.md);
      --can-log schreibt die Frames jedes Versuchs als candump-Log nach DIR;
      --can-sync-timeout MS beendet einen Versuch, wenn MS lang kein SYNC kommt (Standard 20).
  learnid-cli replay --candump FILE [--candump FILE2 ...] [--scenario FILE]
                     [--estimator paper|improved] [--nodes 1,2] [--report FILE]
                     [--export FILE] [--trial-csv DIR] [--workspace DIR] [--quiet]
      Identifiziert neu aus aufgezeichneten Versuchen: die Sitzung läuft erneut,
      und jedes Log (eines pro Versuch, der Reihe nach) antwortet statt des Roboters.
  learnid-cli identify --robot ROBOT --log FILE [--log FILE2 ...]
                       [--validate FILE ...] [--columns SPEC] [--joint-terms LIST]
                       [--rho R] [--prior-share S] [--velocity auto|measured|q]
                       [--max-gap MS] [--torque-sensor-lag MS] [--base-link L]
                       [--tip-link L] [--export FILE] [--urdf-out FILE] [--report FILE]
                       [--plots DIR] [--scenario FILE] [--workspace DIR] [--quiet]
      Identifiziert Trägheit und Reibung eines realen Roboters aus seinen
      aufgezeichneten Logs (CSV) und vergleicht das Ergebnis an den --validate-Logs
      mit seinem URDF.
  learnid-cli plan --out DIR [--scenario FILE] [--estimate FILE] [--history DIR]
                   [--workspace DIR] [--quiet]
      Plant den nächsten Versuch für den eigenen Regler des Roboters: q_d(t) und
      tau_f(t) (DIR/plan.csv) und die Prüfung vor dem Versuch (DIR/check.txt).
  learnid-cli learn --trial-log FILE [--scenario FILE] [--history DIR]
                    [--workspace DIR] [--quiet]
      Lernt aus dem Log des Reglers zu einem Plan; der nächste Plan verwendet
      die neue Schätzung.
  learnid-cli COMMAND --help
      Die Optionen eines Befehls.
</translation>
    </message>
    <message>
        <location line="+79"/>
        <source>The robot: paper (default), panda, puma560, double-pendulum, or a URDF file.</source>
        <translation>Der Roboter: paper (Standard), panda, puma560, double-pendulum oder eine URDF-Datei.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The robot&apos;s clock in ms (default 2): the gains are designed to hold in discrete time at it.</source>
        <translation>Der Takt des Roboters in ms (Standard 2): die Verstärkungen werden so ausgelegt, dass sie zeitdiskret bei ihm halten.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Print a complete scenario for a robot as JSON.</source>
        <translation>Ein vollständiges Szenario für einen Roboter als JSON ausgeben.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&apos;scenario&apos; needs --print</source>
        <translation>&apos;scenario&apos; braucht --print</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>--sample-period: the robot&apos;s clock must be a number of ms above 0 and at most 100, not &apos;%1&apos;</source>
        <translation>--sample-period: der Takt des Roboters muss eine Zahl von ms über 0 und höchstens 100 sein, nicht &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>no command given</source>
        <translation>kein Befehl angegeben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown command &apos;%1&apos;</source>
        <translation>unbekannter Befehl &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../app/cli/RunCommandLine.cpp" line="+18"/>
        <source>Re-identify from recorded trials: the session runs again with each log
answering in place of the robot.</source>
        <translation>Neu identifizieren aus aufgezeichneten Versuchen: die Sitzung läuft erneut,
und jedes Log antwortet statt des Roboters.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Run a commissioning session on the simulated robot, or with --robot can
on CiA 402 drives on a CAN bus (docs/can-protocol.md).</source>
        <translation>Eine Inbetriebnahmesitzung am simulierten Roboter ausführen, oder mit --robot can
an CiA-402-Antrieben am CAN-Bus (docs/can-protocol.md).</translation>
    </message>
    <message>
        <location filename="../app/cli/CliOptions.cpp" line="+38"/>
        <source>unexpected argument &apos;%1&apos;</source>
        <translation>unerwartetes Argument &apos;%1&apos;</translation>
    </message>
    <message>
        <location filename="../app/cli/RunCommandLine.cpp" line="+17"/>
        <source>--iterations: must be a whole number from 1 to 100, got &apos;%1&apos;</source>
        <translation>--iterations: muss eine ganze Zahl von 1 bis 100 sein, gefunden: &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>&apos;replay&apos; needs at least one --candump FILE</source>
        <translation>&apos;replay&apos; braucht mindestens ein --candump FILE</translation>
    </message>
    <message>
        <location filename="../app/cli/ResultTable.cpp" line="+39"/>
        <location line="+76"/>
        <source>trial</source>
        <translation>Vers.</translation>
    </message>
    <message>
        <location line="-75"/>
        <location line="+78"/>
        <source>change %</source>
        <translation>Änd. %</translation>
    </message>
    <message>
        <location line="-76"/>
        <location line="+78"/>
        <source>max|e|%1 deg</source>
        <translation>max|e|%1 °</translation>
    </message>
    <message>
        <location line="-77"/>
        <location line="+78"/>
        <source>T s</source>
        <translation>T s</translation>
    </message>
    <message>
        <location line="-77"/>
        <location line="+78"/>
        <source>cond</source>
        <translation>cond</translation>
    </message>
    <message>
        <location line="-77"/>
        <source>rank</source>
        <translation>Rang</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>path torque err %</source>
        <translation>Bahnmom.-Fehler %</translation>
    </message>
    <message>
        <location line="+29"/>
        <location line="+73"/>
        <source>learned from a partial trial</source>
        <translation>aus einem abgebrochenen Versuch gelernt</translation>
    </message>
    <message>
        <location line="-65"/>
        <source>unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>truth</source>
        <translation>wahr</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>est %1</source>
        <translation>Schätz. %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  parameter</source>
        <translation>  Parameter</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>vs truth %</source>
        <translation>vs. wahr %</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>(rank %1: unobservable kept)</source>
        <translation>(Rang %1: nicht beobachtbare beibehalten)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>trial %1: %2</source>
        <translation>Versuch %1: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>trial %1: %2, T = %3 s, no samples recorded</source>
        <translation>Versuch %1: %2, T = %3 s, keine Abtastwerte aufgezeichnet</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>trial %1: %2, T = %3 s, %4 samples, max tracking error %5 deg</source>
        <translation>Versuch %1: %2, T = %3 s, %4 Abtastwerte, max. Folgefehler %5°</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>; learned from its first %1 s (a partial trial)</source>
        <translation>; aus seinen ersten %1 s gelernt (ein abgebrochener Versuch)</translation>
    </message>
    <message>
        <location filename="../app/cli/RunCommand.cpp" line="-33"/>
        <source>--estimator: unknown law &apos;%1&apos; (known: %2)</source>
        <translation>--estimator: unbekanntes Gesetz &apos;%1&apos; (bekannt: %2)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>--nodes %1: %2 node ids for a robot of %3 joints: one node per joint is needed</source>
        <translation>--nodes %1: %2 Knoten-IDs für einen Roboter mit %3 Gelenken: ein Knoten pro Gelenk ist nötig</translation>
    </message>
    <message>
        <location line="+60"/>
        <source>--iterations: %1 trials need %1 recorded trials, the logs hold %2</source>
        <translation>--iterations: %1 Versuche brauchen %1 aufgezeichnete Versuche, die Logs enthalten %2</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>learnid-cli: %1, law %2, %3 learning trials</source>
        <translation>learnid-cli: %1, Gesetz %2, %3 Lernversuche</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>learnid-cli: warning: the URDF as a real robot: %1</source>
        <translation>learnid-cli: Warnung: das URDF als realer Roboter: %1</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>learnid-cli: estimate %1 tracked best: it is the one accepted, applied and exported</source>
        <translation>learnid-cli: Schätzung %1 folgte am besten: sie wird akzeptiert, angewendet und exportiert</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>learnid-cli: %1 not written: nothing was learned</source>
        <translation>learnid-cli: %1 nicht geschrieben: nichts wurde gelernt</translation>
    </message>
    <message>
        <location filename="../app/cli/PayloadRunCommand.cpp" line="-18"/>
        <location filename="../app/cli/RunCommand.cpp" line="+28"/>
        <source>learnid-cli: wrote %1 (the session ended early)</source>
        <translation>learnid-cli: %1 geschrieben (die Sitzung endete vorzeitig)</translation>
    </message>
    <message>
        <location filename="../app/cli/IdentifyCommand.cpp" line="-94"/>
        <location line="+93"/>
        <location filename="../app/cli/PayloadRunCommand.cpp" line="+80"/>
        <location filename="../app/cli/ResultTable.cpp" line="+7"/>
        <location filename="../app/cli/RunCommand.cpp" line="-112"/>
        <source>learnid-cli: %1</source>
        <translation>learnid-cli: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/RunCommand.cpp" line="+15"/>
        <source>estimate %1:</source>
        <translation>Schätzung %1:</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the nearest consistent estimate changes the torques on the path by %1 % (--consistent exports and applies it)</source>
        <translation>die nächste konsistente Schätzung ändert die Momente auf der Bahn um %1 % (--consistent exportiert und übernimmt sie)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>no consistent estimate found: %1</source>
        <translation>keine konsistente Schätzung gefunden: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/LoopCommands.cpp" line="+47"/>
        <source>trial %1 refused by the pre-trial check: %2</source>
        <translation>Versuch %1 von der Prüfung vor dem Versuch abgelehnt: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+44"/>
        <location filename="../app/cli/RunCommand.cpp" line="+66"/>
        <source>learnid-cli: no files written</source>
        <translation>learnid-cli: keine Dateien geschrieben</translation>
    </message>
    <message>
        <location line="-36"/>
        <source>plan-id: %1</source>
        <translation>plan-id: %1</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>learnid-cli: baseline trial %1 (plan %2) kept; the next trial is a baseline trial too, without the payload</source>
        <translation>learnid-cli: Referenzfahrt %1 (Plan %2) übernommen; der nächste Versuch ist ebenfalls eine Referenzfahrt, ohne die Nutzlast</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>learnid-cli: baseline trial %1 (plan %2) kept; mount the payload before the next trial</source>
        <translation>learnid-cli: Referenzfahrt %1 (Plan %2) übernommen; vor dem nächsten Versuch die Nutzlast montieren</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>learnid-cli: trial %1 (plan %2) learned; the next plan uses estimate %3</source>
        <translation>learnid-cli: aus Versuch %1 (Plan %2) gelernt; der nächste Plan verwendet Schätzung %3</translation>
    </message>
    <message>
        <location filename="../app/cli/RunCommand.cpp" line="-30"/>
        <source>learnid-cli: error: apply failed: %1</source>
        <translation>learnid-cli: Fehler: Übertragen fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>learnid-cli: estimate %1 applied to the robot</source>
        <translation>learnid-cli: Schätzung %1 auf den Roboter übertragen</translation>
    </message>
    <message>
        <location filename="../app/cli/LoopCommands.cpp" line="-101"/>
        <location filename="../app/cli/PayloadRunCommand.cpp" line="-81"/>
        <location filename="../app/cli/RunCommand.cpp" line="+42"/>
        <source>learnid-cli: wrote %1</source>
        <translation>learnid-cli: %1 geschrieben</translation>
    </message>
    <message>
        <location filename="../app/cli/IdentifyOptions.cpp" line="-184"/>
        <source>--joint-terms: unknown term &apos;%1&apos;; the terms are armature, viscous, coulomb and offset, or none</source>
        <translation>--joint-terms: unbekannter Term &apos;%1&apos;; die Terme sind armature, viscous, coulomb und offset, oder none</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>--rho: must be a positive number [rad/s], got &apos;%1&apos;</source>
        <translation>--rho: muss eine positive Zahl [rad/s] sein, gefunden: &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--prior-share: must be a number between 0 and 1, got &apos;%1&apos;</source>
        <translation>--prior-share: muss eine Zahl zwischen 0 und 1 sein, gefunden: &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>--velocity: must be auto, measured or q, got &apos;%1&apos;</source>
        <translation>--velocity: muss auto, measured oder q sein, gefunden: &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>--max-gap: must be a positive number of ms, got &apos;%1&apos;</source>
        <translation>--max-gap: muss eine positive Zahl von ms sein, gefunden: &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--torque-sensor-lag: must be a number of ms from 0 to 1000, got &apos;%1&apos;</source>
        <translation>--torque-sensor-lag: muss eine Zahl von 0 bis 1000 ms sein, erhalten: &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>--urdf-out: %1 is where --export writes</source>
        <translation>--urdf-out: nach %1 schreibt schon --export</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>A built-in URDF robot (e.g. double-pendulum) or a URDF file.</source>
        <translation>Ein eingebauter URDF-Roboter (z. B. double-pendulum) oder eine URDF-Datei.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A recorded log (CSV) to identify from; once per log.</source>
        <translation>Ein aufgezeichnetes Log (CSV), aus dem identifiziert wird; einmal pro Log.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A recorded log to check the result on; once per log.</source>
        <translation>Ein aufgezeichnetes Log, an dem das Ergebnis geprüft wird; einmal pro Log.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The log&apos;s column names, e.g. t=time,q=pos%1,dq=vel%1,tau=tau%1.</source>
        <translation>Die Spaltennamen des Logs, z. B. t=time,q=pos%1,dq=vel%1,tau=tau%1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Joint terms to identify: armature, viscous, coulomb, offset, or none; default: viscous,coulomb,offset.</source>
        <translation>Zu identifizierende Gelenkterme: armature, viscous, coulomb, offset oder none; Standard: viscous,coulomb,offset.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Bandwidth of the zero-phase log filter [rad/s]; default 50.</source>
        <translation>Bandbreite des nullphasigen Log-Filters [rad/s]; Standard 50.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Directions weaker than this share of the strongest keep the URDF&apos;s values; default 0.03.</source>
        <translation>Richtungen, die schwächer als dieser Anteil der stärksten sind, behalten die Werte des URDF; Standard 0.03.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Joint velocities: auto, measured or q (from positions).</source>
        <translation>Gelenkgeschwindigkeiten: auto, measured oder q (aus den Positionen).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Longest time step allowed in a log [ms]; default half the time constant 1/rho of the fit&apos;s filter (10 ms at rho 50), at least 2.5 sample periods.</source>
        <translation>Längster erlaubter Zeitschritt in einem Log [ms]; Standard: die halbe Zeitkonstante 1/rho des Filters der Anpassung (10 ms bei rho 50), mindestens 2,5 Abtastperioden.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>First-order lag of the torque sensors [ms], undone on the log&apos;s grid before the fit; default 0 (as measured).</source>
        <translation>Verzögerung erster Ordnung der Drehmomentsensoren [ms], vor dem Fit auf dem Raster des Logs rückgängig gemacht; Standard 0 (wie gemessen).</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The chain&apos;s base link; default: the URDF&apos;s root.</source>
        <translation>Basisglied der Kette; Standard: die Wurzel des URDF.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The chain&apos;s tip link; default: the one leaf below the base.</source>
        <translation>Endglied der Kette; Standard: das einzige Blatt unterhalb der Basis.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Write the identified model as a parameter file (and DCF); it records controller gains only with --scenario.</source>
        <translation>Das identifizierte Modell als Parameterdatei (und DCF) schreiben; Reglerverstärkungen hält sie nur mit --scenario fest.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Write the URDF with the identified inertia and friction.</source>
        <translation>Das URDF mit der identifizierten Trägheit und Reibung schreiben.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Write the report (PDF): the tables and the torque plots.</source>
        <translation>Den Bericht (PDF) schreiben: die Tabellen und die Momentendiagramme.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Write the predicted and measured torque of each validation log as PNG into this folder (made if missing).</source>
        <translation>Das vorhergesagte und gemessene Moment jedes Validierungs-Logs als PNG in diesen Ordner schreiben (wird bei Bedarf angelegt).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Scenario whose controller gains the parameter file records.</source>
        <translation>Szenario, dessen Reglerverstärkungen die Parameterdatei festhält.</translation>
    </message>
    <message>
        <location line="+5"/>
        <location filename="../app/cli/LoopOptions.cpp" line="-2"/>
        <source>Folder that relative output paths are taken from.</source>
        <translation>Ordner, ab dem relative Ausgabepfade gelten.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Usage: learnid-cli identify --robot ROBOT --log FILE [options]

Identify a robot&apos;s inertia and joint friction from its recorded logs,
and compare the result with the URDF as given on --validate logs.

%1</source>
        <translation>Aufruf: learnid-cli identify --robot ROBOT --log FILE [Optionen]

Trägheit und Gelenkreibung eines Roboters aus seinen aufgezeichneten Logs identifizieren
und das Ergebnis an --validate-Logs mit dem gegebenen URDF vergleichen.

%1</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&apos;identify&apos; needs --robot ROBOT</source>
        <translation>&apos;identify&apos; braucht --robot ROBOT</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&apos;identify&apos; needs at least one --log FILE</source>
        <translation>&apos;identify&apos; braucht mindestens ein --log FILE</translation>
    </message>
    <message>
        <location filename="../app/cli/IdentifyTable.cpp" line="+25"/>
        <location line="+16"/>
        <source>name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>joint</source>
        <translation>Gel.</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Identified parameters: %1.</source>
        <translation>Identifizierte Parameter: %1.</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>training logs: residual of the fit</source>
        <translation>Trainings-Logs: Residuum der Anpassung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RMS residual [N m]</source>
        <translation>RMS-Residuum [N m]</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>ratio %</source>
        <translation>Verh. %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RMS error [N m]</source>
        <translation>RMS-Fehler [N m]</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>validation on %1 (%2 samples)</source>
        <translation>Validierung an %1 (%2 Abtastwerte)</translation>
    </message>
    <message>
        <location line="+4"/>
        <location filename="../app/cli/TorquePlotPng.cpp" line="+154"/>
        <source>URDF as given</source>
        <translation>URDF wie gegeben</translation>
    </message>
    <message>
        <location filename="../app/cli/IdentifyParameters.cpp" line="+33"/>
        <source>standard parameters: the URDF&apos;s, the identified, and what the data determined (share of the parameter&apos;s direction; at least 0.5: the data&apos;s, below: undetermined, kept near the prior, which the data still move a little)</source>
        <translation>Standardparameter: die des URDF, die identifizierten und was die Daten bestimmt haben (Anteil der Richtung des Parameters; ab 0,5: der Daten, darunter: unbestimmt, nahe am Prior gehalten, den die Daten noch ein wenig verschieben)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>link or joint</source>
        <translation>Glied oder Gelenk</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>URDF</source>
        <translation>URDF</translation>
    </message>
    <message>
        <location line="+2"/>
        <location filename="../app/cli/IdentifyTable.cpp" line="+1"/>
        <location filename="../app/cli/TorquePlotPng.cpp" line="+2"/>
        <source>identified</source>
        <translation>identifiziert</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>determined</source>
        <translation>bestimmt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>source</source>
        <translation>Quelle</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>warning: the URDF as a real robot: %1</source>
        <translation>Warnung: das URDF als realer Roboter: %1</translation>
    </message>
    <message>
        <location filename="../app/cli/IdentifyTable.cpp" line="+2"/>
        <source>RMS measured [N m]</source>
        <translation>RMS gemessen [N m]</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>overall sqrt(sum e^2 / sum tau^2) %</source>
        <translation>gesamt sqrt(sum e^2 / sum tau^2) %</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>mean of the joint ratios %</source>
        <translation>Mittel der Gelenkverhältnisse %</translation>
    </message>
    <message>
        <location filename="../app/cli/LoopOptions.cpp" line="-37"/>
        <source>Usage: learnid-cli plan --out DIR [options]

Plan the next trial for the robot&apos;s own controller: q_d(t) and the
feedforward tau_f(t) per joint (DIR/plan.csv) and the pre-trial check
(DIR/check.txt). A plan that fails the check is not written.

%1</source>
        <translation>Aufruf: learnid-cli plan --out DIR [Optionen]

Den nächsten Versuch für den eigenen Regler des Roboters planen: q_d(t) und
die Vorsteuerung tau_f(t) je Gelenk (DIR/plan.csv) sowie die Prüfung vor dem
Versuch (DIR/check.txt). Ein Plan, der die Prüfung nicht besteht, wird nicht
geschrieben.

%1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Usage: learnid-cli learn --trial-log FILE [options]

Learn from the log the robot&apos;s own controller recorded while running a
plan: the new estimate joins the history, the convergence table goes to
stdout, and the next plan uses the new estimate.

%1</source>
        <translation>Aufruf: learnid-cli learn --trial-log FILE [Optionen]

Aus dem Log lernen, das der eigene Regler des Roboters beim Ausführen eines
Plans aufgezeichnet hat: die neue Schätzung kommt in den Verlauf, die
Konvergenztabelle geht nach stdout, und der nächste Plan verwendet die
neue Schätzung.

%1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>The learning history&apos;s folder; default: learnid-history beside plan.csv (plan) or the trial log (learn).</source>
        <translation>Ordner des Lernverlaufs; Standard: learnid-history neben plan.csv (plan) bzw. neben dem Versuchs-Log (learn).</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Folder to write plan.csv and check.txt into.</source>
        <translation>Ordner, in den plan.csv und check.txt geschrieben werden.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Parameter file of the estimate to plan with; default: the history&apos;s newest, or the scenario&apos;s initial estimate.</source>
        <translation>Parameterdatei der Schätzung, mit der geplant wird; Standard: die neueste des Verlaufs oder die Anfangsschätzung des Szenarios.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The controller&apos;s log of a run of the plan (CSV); once per repetition.</source>
        <translation>Das Log des Reglers von einem Lauf des Plans (CSV); einmal pro Wiederholung.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&apos;plan&apos; needs --out DIR</source>
        <translation>&apos;plan&apos; braucht --out DIR</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;learn&apos; needs --trial-log FILE</source>
        <translation>&apos;learn&apos; braucht --trial-log FILE</translation>
    </message>
    <message>
        <location filename="../app/cli/TorquePlotPng.cpp" line="-26"/>
        <source>joint %1 (%2) [N m]</source>
        <translation>Gelenk %1 (%2) [N m]</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>measured</source>
        <translation>gemessen</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <location filename="../app/cli/ScenarioCommand.cpp" line="+49"/>
        <source>learnid-cli: error: --robot %1: %2</source>
        <translation>learnid-cli: Fehler: --robot %1: %2</translation>
    </message>
    <message>
        <location filename="../app/cli/PayloadCommand.cpp" line="-168"/>
        <source>value</source>
        <translation>Größe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>estimate</source>
        <translation>Schätzung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>std. error</source>
        <translation>Std.-Fehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>prior</source>
        <translation>Vorgabe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>from</source>
        <translation>Herkunft</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>the logs</source>
        <translation>die Logs</translation>
    </message>
    <message>
        <location line="-45"/>
        <source>the prior (not identified)</source>
        <translation>die Vorgabe (nicht identifiziert)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 on %2</source>
        <translation>%1 auf %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Payload on %1 of %2; the arm&apos;s model (%3) held fixed.
</source>
        <translation>Nutzlast an %1 von %2; das Modell des Arms (%3) bleibt fest.
</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Warning: the arm&apos;s model is %1 as given (its CAD values), not one identified earlier: its errors go into the payload&apos;s estimate. Identify the arm first (identify --export or --urdf-out, without the payload) and give that file as --robot.</source>
        <translation>Warnung: das Modell des Arms ist %1 wie gegeben (seine CAD-Werte), nicht ein zuvor identifiziertes: seine Fehler gehen in die Schätzung der Nutzlast ein. Identifizieren Sie zuerst den Arm (identify --export oder --urdf-out, ohne die Nutzlast) und geben Sie diese Datei als --robot an.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Note: %1</source>
        <translation>Hinweis: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>Fitted to %n log(s), %1 samples: %2 of 10 directions determined (condition %3).
</source>
        <translation>
            <numerusform>An %n Log angepasst, %1 Abtastwerte: %2 von 10 Richtungen bestimmt (Kondition %3).
</numerusform>
            <numerusform>An %n Logs angepasst, %1 Abtastwerte: %2 von 10 Richtungen bestimmt (Kondition %3).
</numerusform>
        </translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Baseline %1 taken out of %2: shifted by %3 s, joint angles %4 deg RMS apart.
</source>
        <translation>Referenz %1 von %2 abgezogen: um %3 s verschoben, Gelenkwinkel %4 Grad RMS auseinander.
</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Warning: the plausible estimate did not converge (%1).
</source>
        <translation>Warnung: die plausible Schätzung ist nicht konvergiert (%1).
</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A real body whose mass lies in the bound (%1).
</source>
        <translation>Ein realer Körper, dessen Masse in der Grenze liegt (%1).
</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Warning: the centre of mass lies outside the bound (%1).
</source>
        <translation>Warnung: der Schwerpunkt liegt außerhalb der Grenze (%1).
</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>What the logs did not show (kept from the prior):
</source>
        <translation>Was die Logs nicht zeigten (aus der Vorgabe übernommen):
</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Torque residual per joint on the logs [N m]:</source>
        <translation>Drehmoment-Residuum je Gelenk auf den Logs [N m]:</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>learnid-cli: fitting the payload to %1</source>
        <translation>learnid-cli: passe die Nutzlast an %1 an</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>On the --validate logs: &quot;URDF as given&quot; is the arm without the payload, &quot;identified&quot; the arm with it.
</source>
        <translation>Auf den --validate-Logs: „URDF wie gegeben“ ist der Arm ohne die Nutzlast, „identifiziert“ der Arm mit ihr.
</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1: torque of the arm alone and with the payload</source>
        <translation>%1: Drehmoment des Arms allein und mit der Nutzlast</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>learnid: payload on %1 identified from logs</source>
        <translation>learnid: Nutzlast an %1 aus Logs identifiziert</translation>
    </message>
    <message>
        <location filename="../app/cli/PayloadOptions.cpp" line="+42"/>
        <source>Identify only a payload fixed to the arm, the --robot URDF or parameter file held fixed as the arm&apos;s model; needs --payload-mass.</source>
        <translation>Nur eine am Arm befestigte Nutzlast identifizieren, das --robot-URDF oder die Parameterdatei bleibt als Modell des Arms fest; braucht --payload-mass.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The link the payload is fixed to; default: the tip link.</source>
        <translation>Das Glied, an dem die Nutzlast befestigt ist; Standard: das Endglied.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Your estimate of the payload&apos;s mass [kg].</source>
        <translation>Ihre Schätzung der Masse der Nutzlast [kg].</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Your estimate of its centre of mass in the link frame [m]; default 0,0,0 (the flange).</source>
        <translation>Ihre Schätzung ihres Schwerpunkts im Gliedkoordinatensystem [m]; Standard 0,0,0 (der Flansch).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Your estimate of its inertia about the centre of mass [kg m^2]; default: a uniform sphere.</source>
        <translation>Ihre Schätzung ihrer Trägheit um den Schwerpunkt [kg m^2]; Standard: eine homogene Kugel.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The payload lies within this distance of the flange [m]; default 0.3.</source>
        <translation>Die Nutzlast liegt innerhalb dieses Abstands vom Flansch [m]; Standard 0,3.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Or within this box in the link frame [m], instead of the sphere.</source>
        <translation>Oder innerhalb dieses Quaders im Gliedkoordinatensystem [m], statt der Kugel.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>With --payload and a --robot parameter file of a URDF robot: the URDF the arm was identified on.</source>
        <translation>Mit --payload und einer --robot-Parameterdatei eines URDF-Roboters: das URDF, an dem der Arm identifiziert wurde.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>With --payload: a log of the same motion without the payload, whose torque residual is taken out of every --log (may be repeated; docs/payload.md).</source>
        <translation>Mit --payload: ein Log derselben Bewegung ohne die Nutzlast, dessen Momentenresiduum von jedem --log abgezogen wird (mehrfach möglich; docs/payload.md).</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>A scenario that learns a payload fixed to the arm, the gains designed for the arm carrying the prior; needs --payload-mass.</source>
        <translation>Ein Szenario, das eine am Arm befestigte Nutzlast lernt, mit Verstärkungen für den Arm, der die Annahme trägt; braucht --payload-mass.</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>--%1: needs --payload</source>
        <translation>--%1: braucht --payload</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--payload: needs --payload-mass KG, your estimate of the payload&apos;s mass</source>
        <translation>--payload: braucht --payload-mass KG, Ihre Schätzung der Masse der Nutzlast</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--payload-box: give either a bounding box or --payload-radius, not both</source>
        <translation>--payload-box: geben Sie entweder einen Hüllquader oder --payload-radius an, nicht beides</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>--payload-mass: must be a number of kg, got &apos;%1&apos;</source>
        <translation>--payload-mass: muss eine Zahl in kg sein, erhalten: „%1“</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--payload-com: must be three numbers X,Y,Z [m], got &apos;%1&apos;</source>
        <translation>--payload-com: muss aus drei Zahlen X,Y,Z [m] bestehen, erhalten: „%1“</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--payload-inertia: must be six numbers IXX,IXY,IYY,IXZ,IYZ,IZZ [kg m^2], got &apos;%1&apos;</source>
        <translation>--payload-inertia: muss aus sechs Zahlen IXX,IXY,IYY,IXZ,IYZ,IZZ [kg m^2] bestehen, erhalten: „%1“</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>--payload-radius: must be a number of m, got &apos;%1&apos;</source>
        <translation>--payload-radius: muss eine Zahl in m sein, erhalten: „%1“</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>--payload-box: must be six numbers X0,Y0,Z0,X1,Y1,Z1 [m], got &apos;%1&apos;</source>
        <translation>--payload-box: muss aus sechs Zahlen X0,Y0,Z0,X1,Y1,Z1 [m] bestehen, erhalten: „%1“</translation>
    </message>
    <message>
        <location filename="../app/cli/PayloadTrialTable.cpp" line="+20"/>
        <source>all</source>
        <translation>alle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>baseline: the same path without the payload</source>
        <translation>Referenz: dieselbe Bahn ohne die Nutzlast</translation>
    </message>
    <message>
        <location filename="../app/cli/PayloadRunCommand.cpp" line="-69"/>
        <source>learnid-cli: take the payload off %1 for the %2 baseline trial(s), then press Enter (Ctrl-C stops)</source>
        <translation>learnid-cli: nehmen Sie die Nutzlast für die %2 Referenzversuch(e) von %1 ab und drücken Sie dann die Eingabetaste (Strg-C bricht ab)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>learnid-cli: the baseline trials are done: mount the payload on %1, then press Enter (Ctrl-C stops)</source>
        <translation>learnid-cli: die Referenzversuche sind fertig: montieren Sie die Nutzlast an %1 und drücken Sie dann die Eingabetaste (Strg-C bricht ab)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>stopped (Ctrl-C) before trial %1</source>
        <translation>vor Versuch %1 abgebrochen (Strg-C)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>before trial %1: no answer on standard input, so the payload&apos;s state was not confirmed</source>
        <translation>vor Versuch %1: keine Antwort auf der Standardeingabe, der Zustand der Nutzlast wurde also nicht bestätigt</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>cannot create the folder %1</source>
        <translation>der Ordner %1 kann nicht angelegt werden</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>--apply: the simulated robot carries its payload already; --apply writes the payload to the drives of --robot can</source>
        <translation>--apply: der simulierte Roboter trägt seine Nutzlast bereits; --apply schreibt die Nutzlast in die Antriebe von --robot can</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: not available with a payload section yet (the payload is learned on the simulated or the CAN robot; --export, --report and --trial-csv write its files)</source>
        <translation>%1: mit einem payload-Abschnitt noch nicht verfügbar (die Nutzlast wird am simulierten oder am CAN-Roboter gelernt; --export, --report und --trial-csv schreiben ihre Dateien)</translation>
    </message>
    <message>
        <location line="+98"/>
        <source>trial %1 ended the run</source>
        <translation>Versuch %1 hat den Lauf beendet</translation>
    </message>
    <message>
        <location line="-75"/>
        <source>learnid-cli: %1, the payload on %2 learned in %3 trials; the arm&apos;s model is held fixed (robot.initialParameters)</source>
        <translation>learnid-cli: %1, die Nutzlast an %2 in %3 Versuchen gelernt; das Modell des Arms bleibt fest (robot.initialParameters)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>learnid-cli: first %1 baseline trial(s) of the same timed path without the payload, taken out of every payload trial (payload.baselineTrials)</source>
        <translation>learnid-cli: zuerst %1 Referenzfahrt(en) derselben zeitlich geplanten Bahn ohne die Nutzlast, von jeder Nutzlastfahrt abgezogen (payload.baselineTrials)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>learnid-cli: the path determines %1 of the payload&apos;s 10 parameters</source>
        <translation>learnid-cli: die Bahn bestimmt %1 der 10 Parameter der Nutzlast</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>apply failed: %1</source>
        <translation>Übertragen fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>learnid-cli: the payload applied to the robot (0x2500 on every node, stored)</source>
        <translation>learnid-cli: Nutzlast auf den Roboter übertragen (0x2500 auf jedem Knoten, gespeichert)</translation>
    </message>
    <message>
        <location line="-146"/>
        <source>learnid-cli: %1 not written: the session ended before its last trial</source>
        <translation>learnid-cli: %1 nicht geschrieben: die Sitzung endete vor ihrem letzten Versuch</translation>
    </message>
    <message>
        <location filename="../app/cli/PayloadTrialTable.cpp" line="-22"/>
        <source>trial  max error  RMS error  mass [kg]  centre of mass [mm]    update  identified</source>
        <translation>Vers.  max. Fehl.  RMS-Fehl.  Masse[kg]  Schwerpunkt [mm]       Update  identifiziert</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>          [deg]      [deg]                                       [ms]</source>
        <translation>          [°]        [°]                                          [ms]</translation>
    </message>
    <message>
        <location line="+32"/>
        <source> (stopped at the limit: learned up to the stop)</source>
        <translation> (an der Grenze gestoppt: bis zum Stopp gelernt)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The payload after trial %1 (bound: %2):</source>
        <translation>Die Nutzlast nach Versuch %1 (Schranke: %2):</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the trials</source>
        <translation>die Versuche</translation>
    </message>
</context>
<context>
    <name>learnid-robot-sim</name>
    <message>
        <location filename="../app/robot-sim/StopRequests.cpp" line="+67"/>
        <source>SIGINT</source>
        <translation>SIGINT</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SIGTERM</source>
        <translation>SIGTERM</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>stdin closed</source>
        <translation>stdin geschlossen</translation>
    </message>
    <message>
        <location filename="../app/robot-sim/main.cpp" line="+34"/>
        <source>learnid-robot-sim: error: %1</source>
        <translation>learnid-robot-sim: Fehler: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Try &apos;learnid-robot-sim --help&apos; for the options.</source>
        <translation>Die Optionen zeigt &apos;learnid-robot-sim --help&apos;.</translation>
    </message>
    <message>
        <location filename="../app/robot-sim/SimOptions.cpp" line="+22"/>
        <source>--nodes: &apos;%1&apos; is not a CANopen node id (1 to 127) in &apos;%2&apos;</source>
        <translation>--nodes: &apos;%1&apos; ist keine CANopen-Knoten-ID (1 bis 127) in &apos;%2&apos;</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--nodes: node %1 is listed twice in &apos;%2&apos;</source>
        <translation>--nodes: Knoten %1 ist in &apos;%2&apos; zweimal aufgeführt</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>--refuse-sdo: &apos;%1&apos; is not an object address INDEX:SUB such as 0x2200:1 (index in hex, sub-index 0 to 255)</source>
        <translation>--refuse-sdo: &apos;%1&apos; ist keine Objektadresse INDEX:SUB wie 0x2200:1 (Index hexadezimal, Subindex 0 bis 255)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>--%1: &apos;%2&apos; is not a whole number of at least %3</source>
        <translation>--%1: &apos;%2&apos; ist keine ganze Zahl von mindestens %3</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The robot on a CAN bus: one simulated CiA 402 drive per joint, the SYNC producer and the scenario&apos;s simulated arm. Prints &quot;ready&quot; once connected; runs until SIGINT, SIGTERM or stdin closes.</source>
        <translation>Der Roboter an einem CAN-Bus: ein simulierter CiA-402-Antrieb pro Gelenk, der SYNC-Erzeuger und der simulierte Arm des Szenarios. Gibt „ready“ aus, sobald verbunden; läuft bis SIGINT, SIGTERM oder bis stdin geschlossen wird.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Show this help.</source>
        <translation>Diese Hilfe anzeigen.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Show the version.</source>
        <translation>Die Version anzeigen.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>QCanBus plugin, e.g. socketcan or virtualcan.</source>
        <translation>QCanBus-Plugin, z. B. socketcan oder virtualcan.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>plugin</source>
        <translation>Plugin</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>CAN interface, e.g. can0 or tcp://127.0.0.1:35468/can0.</source>
        <translation>CAN-Schnittstelle, z. B. can0 oder tcp://127.0.0.1:35468/can0.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>interface</source>
        <translation>Schnittstelle</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Node ids of joint 1, 2, ..., up to 127 (default: joint j is node j).</source>
        <translation>Knoten-IDs von Gelenk 1, 2, ..., jeweils bis 127 (Standard: Gelenk j ist Knoten j).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>ids</source>
        <translation>IDs</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Scenario file (default: the paper scenario).</source>
        <translation>Szenariodatei (Standard: das Szenario des Artikels).</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+6"/>
        <source>file</source>
        <translation>Datei</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>JSON file of the nodes&apos; stored parameters, written at start and after every store.</source>
        <translation>JSON-Datei der gespeicherten Parameter der Knoten, geschrieben beim Start und nach jedem Speichern.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Fault: lose this fraction (0 to 1) of the TPDOs.</source>
        <translation>Fehler: diesen Anteil (0 bis 1) der TPDOs verlieren.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>F</source>
        <translation>F</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Fault: send nothing at all after N frames.</source>
        <translation>Fehler: nach N Frames gar nichts mehr senden.</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+18"/>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <location line="-15"/>
        <source>Fault: the first node faults with EMCY 0x8611 at the K-th SYNC in Operation enabled.</source>
        <translation>Fehler: der erste Knoten geht beim K-ten SYNC in Betrieb freigegeben mit EMCY 0x8611 in Fehler.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>K</source>
        <translation>K</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Fault: SDO writes to this object abort with 0x08000020.</source>
        <translation>Fehler: SDO-Schreibzugriffe auf dieses Objekt brechen mit 0x08000020 ab.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>IDX:SUB</source>
        <translation>IDX:SUB</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>SYNC periods in Operation enabled without a set-point before a drive faults with EMCY 0x8100 (default: 3 periods, at least 50 ms).</source>
        <translation>SYNC-Perioden in Operation enabled ohne Sollwert, bevor ein Antrieb mit EMCY 0x8100 in Fehler geht (Standard: 3 Perioden, mindestens 50 ms).</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Drives that were never commissioned: 0x2400 is 0 (by default joint j&apos;s drive holds the robot&apos;s identity and j).</source>
        <translation>Antriebe, die nie in Betrieb genommen wurden: 0x2400 ist 0 (standardmäßig enthält der Antrieb von Gelenk j die Identität des Roboters und j).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The arm starts without the scenario&apos;s payload. A line &apos;mount&apos; on stdin mounts it, &apos;unmount&apos; takes it off (as a technician does around a payload session&apos;s baseline trials).</source>
        <translation>Der Arm startet ohne die Nutzlast des Szenarios. Eine Zeile &apos;mount&apos; auf stdin montiert sie, &apos;unmount&apos; nimmt sie ab (wie ein Techniker um die Referenzversuche einer Nutzlastsitzung).</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>unexpected argument &apos;%1&apos;</source>
        <translation>unerwartetes Argument &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--can-plugin is required (available: %1)</source>
        <translation>--can-plugin ist erforderlich (verfügbar: %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--can-plugin: unknown plugin &apos;%1&apos; (available: %2)</source>
        <translation>--can-plugin: unbekanntes Plugin &apos;%1&apos; (verfügbar: %2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--can-interface is required, e.g. can0 or tcp://127.0.0.1:35468/can0</source>
        <translation>--can-interface ist erforderlich, z. B. can0 oder tcp://127.0.0.1:35468/can0</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--drop-fraction: &apos;%1&apos; is not a fraction from 0 to 1</source>
        <translation>--drop-fraction: &apos;%1&apos; ist kein Anteil von 0 bis 1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>--emcy-at-sample: &apos;%1&apos; is too large</source>
        <translation>--emcy-at-sample: &apos;%1&apos; ist zu groß</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>--setpoint-timeout: &apos;%1&apos; is too large (at most 100000)</source>
        <translation>--setpoint-timeout: &apos;%1&apos; ist zu groß (höchstens 100000)</translation>
    </message>
</context>
<context>
    <name>learnid::ApplyConfirmDialog</name>
    <message>
        <location filename="../ui/ApplyConfirmDialog.cpp" line="+16"/>
        <source>Apply parameters to the robot</source>
        <translation>Parameter auf den Roboter übertragen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write estimate %1 to the robot controller? The controller&apos;s feedforward changes at once.</source>
        <translation>Schätzung %1 in die Robotersteuerung schreiben? Die Vorsteuerung der Steuerung ändert sich sofort.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>On robot</source>
        <translation>Auf dem Roboter</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>New</source>
        <translation>Neu</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Change</source>
        <translation>Änderung</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Apply to robot</source>
        <translation>Auf Roboter übertragen</translation>
    </message>
</context>
<context>
    <name>learnid::ApplyPanel</name>
    <message>
        <location filename="../ui/ApplyPanel.cpp" line="+23"/>
        <source>estimate </source>
        <translation>Schätzung </translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Choose:</source>
        <translation>Auswahl:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Accepted:</source>
        <translation>Akzeptiert:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Robot holds:</source>
        <translation>Roboter hat:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>nothing applied yet</source>
        <translation>noch nichts übertragen</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>estimate %1</source>
        <translation>Schätzung %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
</context>
<context>
    <name>learnid::CanConnection</name>
    <message>
        <location filename="../core/canrobot/CanConnection.cpp" line="+34"/>
        <source>the CAN device %1 did not connect within %2 ms (is the bus or the robot side running?)</source>
        <translation>das CAN-Gerät %1 hat sich nicht innerhalb von %2 ms verbunden (läuft der Bus oder die Roboterseite?)</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>no CAN device for %1</source>
        <translation>kein CAN-Gerät für %1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>cannot connect the CAN device %1: %2</source>
        <translation>das CAN-Gerät %1 kann nicht verbunden werden: %2</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>no error reported (the other side may have exited)</source>
        <translation>kein Fehler gemeldet (die Gegenseite wurde vielleicht beendet)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the CAN device %1 went unconnected: %2</source>
        <translation>das CAN-Gerät %1 ist nicht mehr verbunden: %2</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>the CAN device %1 reported an error frame: %2</source>
        <translation>das CAN-Gerät %1 meldete einen Fehlerframe: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the CAN device %1 reported %2 (error frame 0x%3 %4)</source>
        <translation>das CAN-Gerät %1 meldete %2 (Fehlerframe 0x%3 %4)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>the CAN interface %1 of %2 disappeared</source>
        <translation>die CAN-Schnittstelle %1 von %2 ist verschwunden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the CAN interface %1 of %2 went down (ip link set %1 up brings it back)</source>
        <translation>die CAN-Schnittstelle %1 von %2 wurde deaktiviert (ip link set %1 up aktiviert sie wieder)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the CAN controller of %1 (%2) is %3</source>
        <translation>der CAN-Controller von %1 (%2) ist %3</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the CAN device %1 reports bus off</source>
        <translation>das CAN-Gerät %1 meldet Bus aus (bus off)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the CAN device %1 reports error passive</source>
        <translation>das CAN-Gerät %1 meldet fehlerpassiv</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>the CAN device %1 reported a %2 error: %3</source>
        <translation>das CAN-Gerät %1 meldete einen %2fehler: %3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read</source>
        <translation>Lese</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>write</source>
        <translation>Schreib</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the CAN device %1 reported a connection error: %2</source>
        <translation>das CAN-Gerät %1 meldete einen Verbindungsfehler: %2</translation>
    </message>
</context>
<context>
    <name>learnid::CanLink</name>
    <message>
        <location filename="../core/can/CanLink.cpp" line="+24"/>
        <source>The CAN device no longer exists.</source>
        <translation>Das CAN-Gerät existiert nicht mehr.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The CAN device %1 is not connected.</source>
        <translation>Das CAN-Gerät %1 ist nicht verbunden.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The CAN device refused the frame: %1</source>
        <translation>Das CAN-Gerät hat den Frame abgelehnt: %1</translation>
    </message>
</context>
<context>
    <name>learnid::CanRobotWorker</name>
    <message>
        <location filename="../core/canrobot/CanRobotWorker.cpp" line="+111"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the model has %1 joints but %2 CAN nodes are configured, or the plan is empty</source>
        <translation>das Modell hat %1 Gelenke, aber %2 CAN-Knoten sind konfiguriert, oder der Plan ist leer</translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+57"/>
        <source>stopped by the operator before the drives moved</source>
        <translation>vom Bediener gestoppt, bevor sich die Antriebe bewegten</translation>
    </message>
    <message>
        <location line="-52"/>
        <source>refused before any motion: %1</source>
        <translation>vor jeder Bewegung abgelehnt: %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>reading the drives&apos; identity failed: %1</source>
        <translation>das Lesen der Antriebsidentität schlug fehl: %1</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>configuring the drives failed, nothing moved: %1</source>
        <translation>Konfigurieren der Antriebe fehlgeschlagen, nichts hat sich bewegt: %1</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>the trial&apos;s candump log could not be written: %1</source>
        <translation>das candump-Log des Versuchs konnte nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>%1; the stored parameters are unchanged</source>
        <translation>%1; die gespeicherten Parameter sind unverändert</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1; nothing was stored (%2 not written)</source>
        <translation>%1; nichts wurde gespeichert (%2 nicht geschrieben)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1; nothing was stored (0x1010 not written)</source>
        <translation>%1; nichts wurde gespeichert (0x1010 nicht geschrieben)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1; storing stopped at node %2 of the list</source>
        <translation>%1; das Speichern stoppte bei Knoten %2 der Liste</translation>
    </message>
</context>
<context>
    <name>learnid::CandumpReplayDevice</name>
    <message>
        <location filename="../core/canrobot/CandumpReplayDevice.cpp" line="+88"/>
        <source>Cannot write a frame: the replay is not connected.</source>
        <translation>Frame kann nicht geschrieben werden: die Wiedergabe ist nicht verbunden.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The master wrote %1 after the end of the log.</source>
        <translation>Der Master schrieb %1 nach dem Ende des Logs.</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The master wrote %1 where the log holds %2 (log frame %3): the replayed trial differs from the recorded one.</source>
        <translation>Der Master schrieb %1, wo das Log %2 enthält (Log-Frame %3): der wiedergegebene Versuch weicht vom aufgezeichneten ab.</translation>
    </message>
</context>
<context>
    <name>learnid::CommissioningSession</name>
    <message>
        <location filename="../core/session/CommissioningSession.cpp" line="+23"/>
        <source>unknown estimator law &apos;%1&apos; (known: %2)</source>
        <translation>unbekanntes Schätzgesetz &apos;%1&apos; (bekannt: %2)</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>trial %1 refused before motion: %2</source>
        <translation>Versuch %1 vor der Bewegung abgelehnt: %2</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>repetition %1 of %2: %3</source>
        <translation>Wiederholung %1 von %2: %3</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>trial %1 stopped at the tracking limit after %2 s: too short to learn from once the filter has settled (%3 s); the estimate is unchanged</source>
        <translation>Versuch %1 stoppte nach %2 s an der Grenze des Folgefehlers: zu kurz, um nach dem Einschwingen des Filters (%3 s) daraus zu lernen; die Schätzung bleibt unverändert</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>trial %1 stopped at the tracking limit: its %2 s before the stop observe no parameter; the estimate is unchanged</source>
        <translation>Versuch %1 stoppte an der Grenze des Folgefehlers: seine %2 s vor dem Halt beobachten keinen Parameter; die Schätzung bleibt unverändert</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>the update produced non-finite parameters</source>
        <translation>die Aktualisierung ergab nicht endliche Parameter</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>trial %1 not learned from: %2</source>
        <translation>aus Versuch %1 nicht gelernt: %2</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>there is no learned estimate to accept yet: run a trial first</source>
        <translation>es gibt noch keine gelernte Schätzung zum Akzeptieren: zuerst einen Versuch ausführen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>estimate %1 does not exist: choose 1 to %2</source>
        <translation>Schätzung %1 existiert nicht: 1 bis %2 wählen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>only URDF robots have standard parameters to make consistent</source>
        <translation>nur URDF-Roboter haben Standardparameter, die sich konsistent machen lassen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no consistent estimate near estimate %1: %2</source>
        <translation>keine konsistente Schätzung nahe Schätzung %1: %2</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>nothing accepted: accept an estimate before applying it</source>
        <translation>nichts akzeptiert: eine Schätzung akzeptieren, bevor sie übertragen wird</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>nothing to revert: no parameter set has been applied in this session</source>
        <translation>nichts zurückzunehmen: in dieser Sitzung wurde kein Parametersatz übertragen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the robot held no parameter set before the first apply; there is nothing to restore</source>
        <translation>der Roboter hatte vor dem ersten Übertragen keinen Parametersatz; es gibt nichts wiederherzustellen</translation>
    </message>
</context>
<context>
    <name>learnid::ConvergenceChart</name>
    <message>
        <location filename="../ui/ConvergenceChart.cpp" line="+32"/>
        <source>Estimate k</source>
        <translation>Schätzung k</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>|error| [%]</source>
        <translation>|Fehler| [%]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>change [%]</source>
        <translation>Änderung [%]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>path torque [%]</source>
        <translation>Bahnmoment [%]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Convergence to the truth</source>
        <translation>Konvergenz zum wahren Wert</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Convergence</source>
        <translation>Konvergenz</translation>
    </message>
    <message>
        <location line="+62"/>
        <source>vs truth</source>
        <translation>ggü. wahrem Wert</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>vs newest estimate</source>
        <translation>ggü. neuester Schätzung</translation>
    </message>
</context>
<context>
    <name>learnid::ConvergencePanel</name>
    <message>
        <location filename="../ui/ConvergencePanel.cpp" line="+41"/>
        <source>Estimates</source>
        <translation>Schätzungen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
</context>
<context>
    <name>learnid::ConvergenceTableModel</name>
    <message>
        <location filename="../ui/ConvergenceTableModel.cpp" line="+195"/>
        <source>all (rank %1)</source>
        <translation>alle (Rang %1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>⚠ kept %1 of %2</source>
        <translation>⚠ %1 von %2 beibehalten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>⚠ kept: %1</source>
        <translation>⚠ beibehalten: %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 (learned from a partial trial)</source>
        <translation>%1 (aus einem abgebrochenen Versuch gelernt)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>accepted</source>
        <translation>akzeptiert</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>on robot</source>
        <translation>auf dem Roboter</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>%1 = %2 ± %3 (1 sigma)</source>
        <translation>%1 = %2 ± %3 (1 Sigma)</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Estimate</source>
        <translation>Schätzung</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Rel. change [%]</source>
        <translation>Rel. Änderung [%]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Max |e| [deg]</source>
        <translation>Max. |e| [°]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>cond(WᵀW)</source>
        <translation>cond(WᵀW)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Observable</source>
        <translation>Beobachtbar</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 vs truth [%]</source>
        <translation>%1 ggü. wahrem Wert [%]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Path torque vs truth [%]</source>
        <translation>Bahnmoment ggü. wahrem Wert [%]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Trials run</source>
        <translation>Versuche</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>State</source>
        <translation>Status</translation>
    </message>
</context>
<context>
    <name>learnid::FileController</name>
    <message>
        <location filename="../ui/FileController.cpp" line="+39"/>
        <source>Parameter file written: %1</source>
        <translation>Parameterdatei geschrieben: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Parameter file not written: %1</source>
        <translation>Parameterdatei nicht geschrieben: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Identified URDF written: %1</source>
        <translation>Identifiziertes URDF geschrieben: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>URDF not written: %1</source>
        <translation>URDF nicht geschrieben: %1</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Open scenario</source>
        <translation>Szenario öffnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scenario files (*.json);;All files (*)</source>
        <translation>Szenariodateien (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save scenario</source>
        <translation>Szenario speichern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scenario files (*.json)</source>
        <translation>Szenariodateien (*.json)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export parameter file</source>
        <translation>Parameterdatei exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter files (*.json)</source>
        <translation>Parameterdateien (*.json)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Folder for the trial CSV files</source>
        <translation>Ordner für die CSV-Dateien der Versuche</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export plot</source>
        <translation>Diagramm exportieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>PNG image (*.png);;SVG drawing (*.svg)</source>
        <translation>PNG-Bild (*.png);;SVG-Zeichnung (*.svg)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNG image (*.png)</source>
        <translation>PNG-Bild (*.png)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export commissioning report</source>
        <translation>Inbetriebnahmebericht exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <location line="+84"/>
        <source>Scenario loaded: %1</source>
        <translation>Szenario geladen: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Scenario not loaded: %1</source>
        <translation>Szenario nicht geladen: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+8"/>
        <source>Scenario not saved: %1</source>
        <translation>Szenario nicht gespeichert: %1</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>Scenario saved: %1</source>
        <translation>Szenario gespeichert: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Parameter file not written: accept an estimate first</source>
        <translation>Parameterdatei nicht geschrieben: zuerst eine Schätzung akzeptieren</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>No trial CSV written: no trial has run yet</source>
        <translation>Keine Versuchs-CSV geschrieben: noch kein Versuch gelaufen</translation>
    </message>
    <message numerus="yes">
        <location line="-156"/>
        <source>%n trial CSV file(s) written to %1</source>
        <translation>
            <numerusform>%n Versuchs-CSV-Datei nach %1 geschrieben</numerusform>
            <numerusform>%n Versuchs-CSV-Dateien nach %1 geschrieben</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Trial CSV not written: %1</source>
        <translation>Versuchs-CSV nicht geschrieben: %1</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Export identified URDF</source>
        <translation>Identifiziertes URDF exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>URDF (*.urdf)</source>
        <translation>URDF (*.urdf)</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>URDF not written: accept an estimate first</source>
        <translation>URDF nicht geschrieben: zuerst eine Schätzung akzeptieren</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>identified by learnid %1 (estimate %2 of a commissioning session) on %3</source>
        <translation>identifiziert von learnid %1 (Schätzung %2 einer Inbetriebnahmesitzung) am %3</translation>
    </message>
    <message>
        <location line="+79"/>
        <source>Plot not written: this build has no SVG support (Qt6::Svg); export as PNG instead</source>
        <translation>Diagramm nicht geschrieben: diese Version kann kein SVG (Qt6::Svg); bitte als PNG exportieren</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Tracking error</source>
        <translation>Folgefehler</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Plot written: %1</source>
        <translation>Diagramm geschrieben: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Plot not written: %1</source>
        <translation>Diagramm nicht geschrieben: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Report not written: no session</source>
        <translation>Bericht nicht geschrieben: keine Sitzung</translation>
    </message>
    <message>
        <location filename="../ui/ReportContent.cpp" line="+36"/>
        <source>Path: from (%1, %2) m, %3 m at %4 deg</source>
        <translation>Bahn: ab (%1, %2) m, %3 m unter %4°</translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>Path: %n joint waypoint(s)</source>
        <translation>
            <numerusform>Bahn: %n Gelenk-Wegpunkt</numerusform>
            <numerusform>Bahn: %n Gelenk-Wegpunkte</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Path: %1</source>
        <translation>Bahn: %1</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>Torque limits: %1 N m, planning fraction %2</source>
        <translation>Momentengrenzen: %1 N m, Planungsanteil %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>kp: %1 N m/rad; ki: %2</source>
        <translation>kp: %1 N m/rad; ki: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>kd: %1 N m s/rad; lambda %2 rad/s</source>
        <translation>kd: %1 N m s/rad; lambda %2 rad/s</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Feedforward: model torque at the middle of each %1 ms sample</source>
        <translation>Vorsteuerung: Modellmoment in der Mitte jedes %1-ms-Abtastschritts</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Feedforward: model torque at each %1 ms sample&apos;s instant</source>
        <translation>Vorsteuerung: Modellmoment zum Zeitpunkt jedes %1-ms-Abtastschritts</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Estimator: %1, rho %2 rad/s, %3 trials</source>
        <translation>Schätzer: %1, rho %2 rad/s, %3 Versuche</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Initial parameters: %1</source>
        <translation>Anfangsparameter: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>none (nothing applied in this session)</source>
        <translation>keine (in dieser Sitzung nichts übertragen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (estimate %2)</source>
        <translation>%1 (Schätzung %2)</translation>
    </message>
    <message>
        <location filename="../ui/FileController.cpp" line="+8"/>
        <source>Report written: %1</source>
        <translation>Bericht geschrieben: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Report not written: %1</source>
        <translation>Bericht nicht geschrieben: %1</translation>
    </message>
</context>
<context>
    <name>learnid::LogExportController</name>
    <message>
        <location filename="../ui/LogExportController.cpp" line="+75"/>
        <source>identify and accept a result first</source>
        <translation>zuerst ein Ergebnis identifizieren und akzeptieren</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+6"/>
        <source>Parameter file not written: %1</source>
        <translation>Parameterdatei nicht geschrieben: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Parameter file written: %1</source>
        <translation>Parameterdatei geschrieben: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>URDF not written: identify and accept a result first</source>
        <translation>URDF nicht geschrieben: zuerst ein Ergebnis identifizieren und akzeptieren</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>identified by learnid %1 (Identify from recorded data) on %2</source>
        <translation>identifiziert von learnid %1 (Aus aufgezeichneten Daten identifizieren) am %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>URDF written: %1</source>
        <translation>URDF geschrieben: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>URDF not written: %1</source>
        <translation>URDF nicht geschrieben: %1</translation>
    </message>
</context>
<context>
    <name>learnid::LogValidationTableModel</name>
    <message>
        <location filename="../ui/LogValidationTableModel.cpp" line="+101"/>
        <source>sqrt(sum e^2 / sum tau^2) over the joints and samples, in %</source>
        <translation>sqrt(sum e^2 / sum tau^2) über die Gelenke und Abtastwerte, in %</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The mean over the joints of RMS error / RMS measured, in %</source>
        <translation>Der Mittelwert über die Gelenke von RMS-Fehler / RMS gemessen, in %</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>overall %</source>
        <translation>gesamt %</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>mean ratio %</source>
        <translation>mittl. Verhältnis %</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Joint</source>
        <translation>Gelenk</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RMS measured
[N m]</source>
        <translation>RMS gemessen
[N m]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>URDF as given
RMS error [N m]</source>
        <translation>URDF wie gegeben
RMS-Fehler [N m]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>URDF as given
ratio %</source>
        <translation>URDF wie gegeben
Verhältnis %</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Identified
RMS error [N m]</source>
        <translation>Identifiziert
RMS-Fehler [N m]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Identified
ratio %</source>
        <translation>Identifiziert
Verhältnis %</translation>
    </message>
</context>
<context>
    <name>learnid::MainActions</name>
    <message>
        <location filename="../ui/MainActions.cpp" line="+37"/>
        <source>&amp;Connect robot</source>
        <translation>Roboter &amp;verbinden</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+K</source>
        <translation>Ctrl+K</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connect to the chosen robot and plan the first trial</source>
        <translation>Mit dem gewählten Roboter verbinden und den ersten Versuch planen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;New session</source>
        <translation>&amp;Neue Sitzung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start a new session with the settings of the form (the history is discarded)</source>
        <translation>Neue Sitzung mit den Einstellungen des Formulars beginnen (der Verlauf wird verworfen)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Identify from recorded &amp;data…</source>
        <translation>Aus aufgezeichneten &amp;Daten identifizieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Identify a robot&apos;s parameters from logs its controller recorded</source>
        <translation>Die Parameter eines Roboters aus Logs identifizieren, die sein Regler aufgezeichnet hat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Learn a &amp;payload…</source>
        <translation>&amp;Nutzlast lernen…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Learn the payload the robot carries with the arm&apos;s model held fixed (simulated robot)</source>
        <translation>Die Nutzlast lernen, die der Roboter trägt, mit festgehaltenem Modell des Arms (simulierter Roboter)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Open scenario...</source>
        <translation>Szenario ö&amp;ffnen...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load a scenario file into the form</source>
        <translation>Eine Szenariodatei in das Formular laden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Save scenario...</source>
        <translation>Szenario &amp;speichern...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the form&apos;s scenario to a file</source>
        <translation>Das Szenario des Formulars in eine Datei speichern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export &amp;parameter file...</source>
        <translation>&amp;Parameterdatei exportieren...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the accepted estimate as a parameter file (JSON and DCF)</source>
        <translation>Die akzeptierte Schätzung als Parameterdatei schreiben (JSON und DCF)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export identified &amp;URDF...</source>
        <translation>Identifiziertes &amp;URDF exportieren...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the robot&apos;s URDF with the accepted estimate as real bodies and its friction (URDF robots)</source>
        <translation>Das URDF des Roboters schreiben, mit der akzeptierten Schätzung als realen Körpern samt ihrer Reibung (URDF-Roboter)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export trial &amp;CSV...</source>
        <translation>Versuchs-&amp;CSV exportieren...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ctrl+Shift+E</source>
        <translation>Ctrl+Shift+E</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Write one CSV file per trial</source>
        <translation>Eine CSV-Datei je Versuch schreiben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export p&amp;lot...</source>
        <translation>&amp;Diagramm exportieren...</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Shift+P</source>
        <translation>Ctrl+Shift+P</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the tracking-error plot as PNG or SVG</source>
        <translation>Das Folgefehler-Diagramm als PNG oder SVG speichern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the tracking-error plot as PNG (SVG needs Qt6::Svg)</source>
        <translation>Das Folgefehler-Diagramm als PNG speichern (SVG braucht Qt6::Svg)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export &amp;report (PDF)...</source>
        <translation>&amp;Bericht exportieren (PDF)...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the one-page commissioning report</source>
        <translation>Den einseitigen Inbetriebnahmebericht schreiben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Quit learnid</source>
        <translation>learnid beenden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Run trial</source>
        <translation>Versuch &amp;starten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run the next trial and learn from it</source>
        <translation>Den nächsten Versuch fahren und daraus lernen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run &amp;all</source>
        <translation>&amp;Alle starten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+F5</source>
        <translation>Ctrl+F5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run the scenario&apos;s number of trials</source>
        <translation>Die im Szenario festgelegte Zahl von Versuchen fahren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Stop</source>
        <translation>&amp;Stopp</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Shift+F5</source>
        <translation>Shift+F5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop the running trial safely at the next sample</source>
        <translation>Den laufenden Versuch beim nächsten Abtastschritt sicher anhalten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A&amp;ccept</source>
        <translation>A&amp;kzeptieren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Return</source>
        <translation>Ctrl+Return</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Accept the chosen estimate for apply</source>
        <translation>Die gewählte Schätzung zum Übertragen akzeptieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A&amp;pply...</source>
        <translation>Ü&amp;bertragen...</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Shift+A</source>
        <translation>Ctrl+Shift+A</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write the accepted estimate to the robot controller</source>
        <translation>Die akzeptierte Schätzung in die Robotersteuerung schreiben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Re&amp;vert</source>
        <translation>&amp;Zurücksetzen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Ctrl+Shift+Z</source>
        <translation>Ctrl+Shift+Z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restore the parameter set the robot held before the last apply</source>
        <translation>Den Parametersatz vor der letzten Übertragung wiederherstellen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;About learnid</source>
        <translation>Ü&amp;ber learnid</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Version and licence</source>
        <translation>Version und Lizenz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Qt version</source>
        <translation>Qt-Version</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>System language</source>
        <translation>Systemsprache</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Robot</source>
        <translation>&amp;Roboter</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Trials</source>
        <translation>&amp;Versuche</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Parameters</source>
        <translation>&amp;Parameter</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
</context>
<context>
    <name>learnid::MainWindow</name>
    <message>
        <location filename="../ui/MainWindow.cpp" line="+72"/>
        <source>learnid – commissioning</source>
        <translation>learnid – Inbetriebnahme</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Main</source>
        <translation>Haupt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Pre-trial check</source>
        <translation>Prüfung vor dem Versuch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Run</source>
        <translation>Ausführen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Accept / apply</source>
        <translation>Akzeptieren / übertragen</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Robot</source>
        <translation>Roboter</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Scenario</source>
        <translation>Szenario</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setup</source>
        <translation>Einrichtung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Parameter convergence</source>
        <translation>Parameterkonvergenz</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>The language changes when learnid is started again.</source>
        <translation>Die Sprache wechselt beim nächsten Start von learnid.</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>Dis&amp;connect robot</source>
        <translation>Roboter &amp;trennen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Connect robot</source>
        <translation>Roboter &amp;verbinden</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Run disabled: %1</source>
        <translation>Start gesperrt: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no robot</source>
        <translation>kein Roboter</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Robot: %1 – %2</source>
        <translation>Roboter: %1 – %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>busy</source>
        <translation>beschäftigt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>idle</source>
        <translation>bereit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Cannot connect: %1</source>
        <translation>Verbindung nicht möglich: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>connecting to %1/%2…</source>
        <translation>verbinde mit %1/%2…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Correct the scenario first: %1</source>
        <translation>Zuerst das Szenario korrigieren: %1</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Apply cancelled; the robot is unchanged.</source>
        <translation>Übertragen abgebrochen; der Roboter ist unverändert.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>About learnid</source>
        <translation>Über learnid</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;h3&gt;learnid %1&lt;/h3&gt;&lt;p&gt;Learning identification of robot dynamics: a commissioning tool.&lt;/p&gt;&lt;p&gt;Built with Qt %2.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;learnid %1&lt;/h3&gt;&lt;p&gt;Lernende Identifikation der Roboterdynamik: ein Inbetriebnahmewerkzeug.&lt;/p&gt;&lt;p&gt;Erstellt mit Qt %2.&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>The payload step needs the CAN bus: disconnect the arm&apos;s session first.</source>
        <translation>Der Nutzlastschritt braucht den CAN-Bus: trennen Sie zuerst die Sitzung des Arms.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The robot panel&apos;s choice cannot be used (%1): the payload step runs on the simulated robot.</source>
        <translation>Die Auswahl im Roboterbereich ist nicht verwendbar (%1): der Nutzlastschritt läuft am simulierten Roboter.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The scenario has a payload section: its payload is learned here, in the payload step; the arm&apos;s session is not opened with it.</source>
        <translation>Das Szenario hat einen Abschnitt payload: seine Nutzlast wird hier gelernt, im Nutzlast-Schritt; die Sitzung des Arms wird damit nicht geöffnet.</translation>
    </message>
</context>
<context>
    <name>learnid::MemoryCanDevice</name>
    <message>
        <location filename="../core/can/MemoryCanDevice.cpp" line="+27"/>
        <source>The memory CAN device %1 is not attached to a bus.</source>
        <translation>Das Speicher-CAN-Gerät %1 hängt an keinem Bus.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The memory CAN device %1 refused to connect.</source>
        <translation>Das Speicher-CAN-Gerät %1 hat die Verbindung abgelehnt.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Cannot write a frame: the device %1 is not connected.</source>
        <translation>Frame kann nicht geschrieben werden: das Gerät %1 ist nicht verbunden.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cannot write an invalid or CAN FD frame: %1.</source>
        <translation>Ein ungültiger oder CAN-FD-Frame kann nicht geschrieben werden: %1.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Only data and remote request frames can be written.</source>
        <translation>Nur Daten- und Remote-Frames können geschrieben werden.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The memory CAN device %1 failed to write the frame.</source>
        <translation>Das Speicher-CAN-Gerät %1 konnte den Frame nicht schreiben.</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>CAN error frame, error classes 0x%1.</source>
        <translation>CAN-Fehlerframe, Fehlerklassen 0x%1.</translation>
    </message>
</context>
<context>
    <name>learnid::MessageBar</name>
    <message>
        <location filename="../ui/MessageBar.cpp" line="+20"/>
        <source>Dismiss</source>
        <translation>Schließen</translation>
    </message>
</context>
<context>
    <name>learnid::ObjectDictionary</name>
    <message>
        <location filename="../core/can/ObjectDictionary.cpp" line="+18"/>
        <source>Object %1: %2 is not numeric; use addBytes().</source>
        <translation>Objekt %1: %2 ist nicht numerisch; addBytes() verwenden.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Object %1: %2 is numeric; use add().</source>
        <translation>Objekt %1: %2 ist numerisch; add() verwenden.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Object %1 is defined twice.</source>
        <translation>Objekt %1 ist zweimal definiert.</translation>
    </message>
    <message>
        <location line="+87"/>
        <source>Object %1 holds %2 bytes, not %3.</source>
        <translation>Objekt %1 enthält %2 Bytes, nicht %3.</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Object %1 is not in the object dictionary.</source>
        <translation>Objekt %1 ist nicht im Objektverzeichnis.</translation>
    </message>
</context>
<context>
    <name>learnid::ParameterTableModel</name>
    <message>
        <location filename="../ui/ParameterTableModel.cpp" line="+129"/>
        <source>kept</source>
        <translation>beibehalten</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>⚠ kept</source>
        <translation>⚠ beibehalten</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>✗ no</source>
        <translation>✗ nein</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>⚠ not plausible</source>
        <translation>⚠ nicht plausibel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>✓</source>
        <translation>✓</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>Link / joint</source>
        <translation>Glied / Gelenk</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Estimate %1</source>
        <translation>Schätzung %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>σ / |φ| [%]</source>
        <translation>σ / |φ| [%]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Observed</source>
        <translation>Beobachtet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Real body</source>
        <translation>Realer Körper</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Truth</source>
        <translation>Wahrer Wert</translation>
    </message>
</context>
<context>
    <name>learnid::PayloadDialog</name>
    <message>
        <location filename="../ui/PayloadDialog.cpp" line="+50"/>
        <source>&amp;Run trials</source>
        <translation>Versuche &amp;ausführen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Stop</source>
        <translation>&amp;Stopp</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Continue</source>
        <translation>&amp;Weiter</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&amp;Accept</source>
        <translation>&amp;Übernehmen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export &amp;parameter file…</source>
        <translation>&amp;Parameterdatei exportieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export &amp;URDF…</source>
        <translation>&amp;URDF exportieren…</translation>
    </message>
    <message>
        <location filename="../ui/PayloadDialogExport.cpp" line="+48"/>
        <source>Learn a payload (simulated robot)</source>
        <translation>Nutzlast lernen (simulierter Roboter)</translation>
    </message>
    <message>
        <location filename="../ui/PayloadDialog.cpp" line="+1"/>
        <source>A&amp;pply to the robot…</source>
        <translation>Auf den Roboter über&amp;tragen…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sa&amp;ve scenario…</source>
        <translation>Szenario spei&amp;chern…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Design &amp;gains for this payload</source>
        <translation>&amp;Verstärkungen für diese Nutzlast auslegen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save report and &amp;trials…</source>
        <translation>&amp;Bericht und Versuche speichern…</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Payload and prior</source>
        <translation>Nutzlast und Vorwissen</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>What the path lets the trials see</source>
        <translation>Was die Bahn die Versuche erfassen lässt</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Trials</source>
        <translation>Versuche</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Payload estimate</source>
        <translation>Schätzung der Nutzlast</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Tracking error</source>
        <translation>Folgefehler</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>The CAN robot %1/%2</source>
        <translation>Der CAN-Roboter %1/%2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The run asks you to take the payload off before the baseline trials and to mount it after them.</source>
        <translation>Der Lauf fordert Sie auf, die Nutzlast vor den Basisversuchen abzunehmen und danach zu montieren.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The trials cannot be planned: %1</source>
        <translation>Die Versuche lassen sich nicht planen: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Trial %1 of %2 running: baseline, without the payload…</source>
        <translation>Versuch %1 von %2 läuft: Basisversuch, ohne die Nutzlast…</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Trial %1 of %2 running with the payload…</source>
        <translation>Versuch %1 von %2 läuft mit der Nutzlast…</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Payload learned: check the estimate, then accept it to apply it to the robot or export it.</source>
        <translation>Nutzlast gelernt: prüfen Sie die Schätzung und nehmen Sie sie an, um sie auf den Roboter zu übertragen oder zu exportieren.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Payload learned: check the estimate, then accept it to export.</source>
        <translation>Nutzlast gelernt: die Schätzung prüfen, dann zum Exportieren übernehmen.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Payload not learned: %1. The report and trials of the run can be saved (Save report and trials).</source>
        <translation>Nutzlast nicht gelernt: %1. Bericht und Versuche des Laufs lassen sich speichern (Bericht und Versuche speichern).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Payload not learned: %1</source>
        <translation>Nutzlast nicht gelernt: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Stopped; no payload is kept from this run. Its report and trials can be saved (Save report and trials).</source>
        <translation>Gestoppt; von diesem Lauf wird keine Nutzlast behalten. Sein Bericht und seine Versuche lassen sich speichern (Bericht und Versuche speichern).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stopped; nothing of this run is kept or written.</source>
        <translation>Gestoppt; von diesem Lauf wird nichts behalten oder geschrieben.</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>Run the trials to learn the payload.</source>
        <translation>Die Versuche ausführen, um die Nutzlast zu lernen.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Planning the first trial…</source>
        <translation>Der erste Versuch wird geplant…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Correct the payload first: %1</source>
        <translation>Zuerst die Nutzlast korrigieren: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cannot run: %1</source>
        <translation>Ausführen nicht möglich: %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Stopping the running trial…</source>
        <translation>Der laufende Versuch wird gestoppt…</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The baseline trials are done: mount the payload on %1, then press Continue.</source>
        <translation>Die Basisversuche sind fertig: montieren Sie die Nutzlast an %1 und drücken Sie dann Weiter.</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Take the payload off %1 for the %n baseline trial(s), then press Continue.</source>
        <translation>
            <numerusform>Nehmen Sie die Nutzlast für den %n Basisversuch von %1 ab und drücken Sie dann Weiter.</numerusform>
            <numerusform>Nehmen Sie die Nutzlast für die %n Basisversuche von %1 ab und drücken Sie dann Weiter.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Starting the next trial…</source>
        <translation>Der nächste Versuch beginnt…</translation>
    </message>
    <message>
        <location filename="../ui/PayloadDialogExport.cpp" line="-15"/>
        <source>Payload accepted: apply it to the robot&apos;s drives, or export the parameter file or the URDF.</source>
        <translation>Nutzlast angenommen: übertragen Sie sie auf die Antriebe des Roboters, oder exportieren Sie die Parameterdatei oder die URDF.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Payload accepted: export the parameter file or the URDF. It is not applied to a robot (the simulated robot carries it already).</source>
        <translation>Nutzlast übernommen: die Parameterdatei oder das URDF exportieren. Sie wird auf keinen Roboter angewendet (der simulierte Roboter trägt sie bereits).</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Learn a payload (CAN robot %1/%2)</source>
        <translation>Eine Nutzlast lernen (CAN-Roboter %1/%2)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Write the payload on %1 (%2 kg, centre of mass (%3, %4, %5) mm) to every drive of %6/%7 (object 0x2500), read it back and store it?</source>
        <translation>Die Nutzlast an %1 (%2 kg, Schwerpunkt (%3, %4, %5) mm) in jeden Antrieb von %6/%7 schreiben (Objekt 0x2500), zurücklesen und speichern?</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Apply the payload</source>
        <translation>Nutzlast übertragen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Apply cancelled; the robot is unchanged.</source>
        <translation>Übertragen abgebrochen; der Roboter ist unverändert.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Writing the payload to the drives…</source>
        <translation>Die Nutzlast wird in die Antriebe geschrieben…</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Applied: every drive stored the payload (0x2500).</source>
        <translation>Übertragen: jeder Antrieb hat die Nutzlast gespeichert (0x2500).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Not applied: %1</source>
        <translation>Nicht übertragen: %1</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Export parameter file</source>
        <translation>Parameterdatei exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter files (*.json)</source>
        <translation>Parameterdateien (*.json)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export URDF with the payload</source>
        <translation>URDF mit der Nutzlast exportieren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>URDF (*.urdf)</source>
        <translation>URDF (*.urdf)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>learnid %1, %2</source>
        <translation>learnid %1, %2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Written: %1</source>
        <translation>Geschrieben: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+56"/>
        <source>Not written: %1</source>
        <translation>Nicht geschrieben: %1</translation>
    </message>
    <message>
        <location line="-35"/>
        <source>Gains designed for the arm carrying %1 kg on %2 (planning fraction %3); the preview checks the first trial with them.</source>
        <translation>Verstärkungen für den Arm mit %1 kg an %2 ausgelegt (Planungsanteil %3); die Vorschau prüft den ersten Versuch damit.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the tip link</source>
        <translation>das Endglied</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Gains not designed: %1</source>
        <translation>Verstärkungen nicht ausgelegt: %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Save the run&apos;s report and trials</source>
        <translation>Bericht und Versuche des Laufs speichern</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Payload reports (*.json)</source>
        <translation>Nutzlastberichte (*.json)</translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>Written: %1 and %n trial CSV(s) in %2</source>
        <translation>
            <numerusform>Geschrieben: %1 und %n Versuchs-CSV in %2</numerusform>
            <numerusform>Geschrieben: %1 und %n Versuchs-CSVs in %2</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Written: %1 and %n trial CSV(s) in %2, of a run that ended early: %3</source>
        <translation>
            <numerusform>Geschrieben: %1 und %n Versuchs-CSV in %2, aus einem vorzeitig beendeten Lauf: %3</numerusform>
            <numerusform>Geschrieben: %1 und %n Versuchs-CSVs in %2, aus einem vorzeitig beendeten Lauf: %3</numerusform>
        </translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Save scenario</source>
        <translation>Szenario speichern</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Scenario files (*.json)</source>
        <translation>Szenariodateien (*.json)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Scenario saved: %1</source>
        <translation>Szenario gespeichert: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Scenario not saved: %1</source>
        <translation>Szenario nicht gespeichert: %1</translation>
    </message>
</context>
<context>
    <name>learnid::PayloadEstimateTableModel</name>
    <message>
        <location filename="../ui/PayloadEstimateTableModel.cpp" line="+86"/>
        <source>data (the trials)</source>
        <translation>Daten (die Versuche)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>prior (not identified)</source>
        <translation>Vorwissen (nicht identifiziert)</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Estimate</source>
        <translation>Schätzung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Std. error</source>
        <translation>Std.-Fehler</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Prior</source>
        <translation>Vorwissen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>From</source>
        <translation>Aus</translation>
    </message>
</context>
<context>
    <name>learnid::PayloadForm</name>
    <message>
        <location filename="../ui/PayloadForm.cpp" line="+42"/>
        <location line="+91"/>
        <source>Scenario key %1</source>
        <translation>Szenario-Schlüssel %1</translation>
    </message>
    <message>
        <location line="-85"/>
        <source>Mounted on link</source>
        <translation>Montiert an Glied</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Mass (prior)</source>
        <translation>Masse (Vorwissen)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>the technician&apos;s estimate</source>
        <translation>die Schätzung des Technikers</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Centre of mass (prior) x, y, z</source>
        <translation>Schwerpunkt (Vorwissen) x, y, z</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Inertia about it (prior) Ixx, Ixy, Iyy, Ixz, Iyz, Izz</source>
        <translation>Trägheit um ihn (Vorwissen) Ixx, Ixy, Iyy, Ixz, Iyz, Izz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>empty: a solid sphere</source>
        <translation>leer: eine Vollkugel</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Bound: sphere around the flange, radius</source>
        <translation>Schranke: Kugel um den Flansch, Radius</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>or a box x0, y0, z0, x1, y1, z1</source>
        <translation>oder ein Quader x0, y0, z0, x1, y1, z1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>empty: the sphere</source>
        <translation>leer: die Kugel</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Baseline trials without the payload</source>
        <translation>Basisversuche ohne die Nutzlast</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Payload trials</source>
        <translation>Versuche mit der Nutzlast</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>the tip (%1)</source>
        <translation>die Spitze (%1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 (on %2)</source>
        <translation>%1 (an %2)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 is fixed to %2 and moves with it</source>
        <translation>%1 ist fest mit %2 verbunden und bewegt sich mit ihm</translation>
    </message>
    <message>
        <location line="+71"/>
        <location line="+3"/>
        <source>enter one number</source>
        <translation>eine Zahl eingeben</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>enter %1 numbers, got %2</source>
        <translation>%1 Zahlen eingeben, erhalten: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>enter %1 numbers</source>
        <translation>%1 Zahlen eingeben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>enter a whole number</source>
        <translation>eine ganze Zahl eingeben</translation>
    </message>
</context>
<context>
    <name>learnid::PayloadRunJob</name>
    <message>
        <location filename="../core/service/PayloadRunJob.cpp" line="+92"/>
        <source>the run&apos;s robot is no longer connected: run again</source>
        <translation>der Roboter des Laufs ist nicht mehr verbunden: erneut ausführen</translation>
    </message>
    <message>
        <location line="+96"/>
        <source>stopped (Stop) by the technician</source>
        <translation>vom Techniker gestoppt (Stopp)</translation>
    </message>
</context>
<context>
    <name>learnid::PayloadTrialTableModel</name>
    <message>
        <location filename="../ui/PayloadTrialTableModel.cpp" line="+68"/>
        <source>kept for the payload trials</source>
        <translation>behalten, wird abgezogen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>all</source>
        <translation>alle</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>none (the prior)</source>
        <translation>keine (das Vorwissen)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>all but %1</source>
        <translation>alle außer %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>baseline</source>
        <translation>Basis</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>payload, stopped</source>
        <translation>Nutzlast, gestoppt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>payload</source>
        <translation>Nutzlast</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>A baseline trial runs the same timed path without the payload</source>
        <translation>Ein Basisversuch fährt dieselbe zeitlich geplante Bahn ohne die Nutzlast</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The worst joint&apos;s maximum tracking error</source>
        <translation>Der maximale Folgefehler des schlechtesten Gelenks</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The worst joint&apos;s RMS tracking error</source>
        <translation>Der RMS-Folgefehler des schlechtesten Gelenks</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The payload fitted to the trials so far</source>
        <translation>Die an die bisherigen Versuche angepasste Nutzlast</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CPU time of the payload&apos;s update</source>
        <translation>CPU-Zeit der Aktualisierung der Nutzlast</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The payload&apos;s values the trials so far identified; the others keep the prior</source>
        <translation>Die Werte der Nutzlast, die die bisherigen Versuche identifiziert haben; die übrigen behalten das Vorwissen</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Trial</source>
        <translation>Versuch</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Max [deg]</source>
        <translation>Max [°]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>RMS [deg]</source>
        <translation>RMS [°]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mass [kg]</source>
        <translation>Masse [kg]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CoM [mm]</source>
        <translation>Schwerpunkt [mm]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Update [ms]</source>
        <translation>Rechenzeit [ms]</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Identified</source>
        <translation>Identifiziert</translation>
    </message>
</context>
<context>
    <name>learnid::PreTrialCheckView</name>
    <message>
        <location filename="../ui/PreTrialCheckView.cpp" line="+38"/>
        <source>Joint</source>
        <translation>Gelenk</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Peak [N m]</source>
        <translation>Spitze [N m]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Limit [N m]</source>
        <translation>Grenze [N m]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Use</source>
        <translation>Auslastung</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The largest torque holding the arm against gravity takes on this path, as a share of the limit</source>
        <translation>Das größte Moment, das das Halten des Arms gegen die Schwerkraft auf dieser Bahn erfordert, als Anteil der Grenze</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Planned motion:</source>
        <translation>Geplante Bewegung:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Closed loop:</source>
        <translation>Regelkreis:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Connect a robot to plan the first trial.</source>
        <translation>Einen Roboter verbinden, um den ersten Versuch zu planen.</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Trial %1: check passed, the trial may run.</source>
        <translation>Versuch %1: Prüfung bestanden, der Versuch darf laufen.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Trial %1 refused: %2</source>
        <translation>Versuch %1 abgelehnt: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no plan</source>
        <translation>kein Plan</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 s motion, %2 s with rests, %3 samples</source>
        <translation>%1 s Bewegung, %2 s mit Ruhezeiten, %3 Abtastwerte</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>estimate not physical (mass matrix not positive definite)</source>
        <translation>Schätzung nicht physikalisch (Massenmatrix nicht positiv definit)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>stable: max |z| = %1, decay rate %2 1/s</source>
        <translation>stabil: max |z| = %1, Abklingrate %2 1/s</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>UNSTABLE: max |z| = %1 at t = %2 s (growth %3 1/s)</source>
        <translation>INSTABIL: max |z| = %1 bei t = %2 s (Anstieg %3 1/s)</translation>
    </message>
</context>
<context>
    <name>learnid::RecordedDataDialog</name>
    <message>
        <location filename="../ui/RecordedDataDialog.cpp" line="+46"/>
        <source>&amp;Identify</source>
        <translation>&amp;Identifizieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;Accept</source>
        <translation>&amp;Akzeptieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export &amp;parameter file…</source>
        <translation>&amp;Parameterdatei exportieren…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export &amp;URDF…</source>
        <translation>&amp;URDF exportieren…</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Identify from recorded data</source>
        <translation>Aus aufgezeichneten Daten identifizieren</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Not identified: %1</source>
        <translation>Nicht identifiziert: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Identification cancelled; nothing was identified or written.</source>
        <translation>Identifikation abgebrochen; nichts wurde identifiziert oder geschrieben.</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Robot and logs</source>
        <translation>Roboter und Logs</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Fit</source>
        <translation>Anpassung</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Validation on:</source>
        <translation>Validierung an:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Validation</source>
        <translation>Validierung</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Predicted against measured torque (validation log)</source>
        <translation>Vorhergesagtes gegenüber gemessenem Moment (Validierungs-Log)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Close</source>
        <translation>Schließen</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Add the robot&apos;s logs and press Identify.</source>
        <translation>Die Logs des Roboters hinzufügen und auf „Identifizieren“ drücken.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Cannot identify: %1</source>
        <translation>Identifikation nicht möglich: %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Cancelling after the current step…</source>
        <translation>Abbruch nach dem aktuellen Schritt…</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Result accepted: export the parameter file or the URDF.</source>
        <translation>Ergebnis akzeptiert: die Parameterdatei oder das URDF exportieren.</translation>
    </message>
</context>
<context>
    <name>learnid::RecordedDataForm</name>
    <message>
        <location filename="../ui/RecordedDataForm.cpp" line="+42"/>
        <source>Robot logs (*.csv);;All files (*)</source>
        <translation>Roboter-Logs (*.csv);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Robot URDF</source>
        <translation>Roboter-URDF</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>URDF (*.urdf);;All files (*)</source>
        <translation>URDF (*.urdf);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Logs to identify from</source>
        <translation>Logs, aus denen identifiziert wird</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Logs to validate on</source>
        <translation>Logs, an denen validiert wird</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Scenario with the controller gains</source>
        <translation>Szenario mit den Reglerverstärkungen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scenario files (*.json);;All files (*)</source>
        <translation>Szenariodateien (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Export parameter file</source>
        <translation>Parameterdatei exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter files (*.json)</source>
        <translation>Parameterdateien (*.json)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Export URDF</source>
        <translation>URDF exportieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>URDF (*.urdf)</source>
        <translation>URDF (*.urdf)</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+5"/>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 (built-in URDF)</source>
        <translation>%1 (eingebautes URDF)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>URDF file…</source>
        <translation>URDF-Datei…</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the robot&apos;s URDF file</source>
        <translation>die URDF-Datei des Roboters</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The logs&apos; column names as learnid-cli identify --columns takes them: t=, q=, dq=, tau= with %1 for the joint number. Empty: t, q%1, dq%1, tau%1.</source>
        <translation>Die Spaltennamen der Logs, wie learnid-cli identify --columns sie nimmt: t=, q=, dq=, tau= mit %1 für die Gelenknummer. Leer: t, q%1, dq%1, tau%1.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>none: the parameter file holds the model alone</source>
        <translation>keine: die Parameterdatei enthält nur das Modell</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A scenario of this robot whose controller gains the parameter file records; the logs do not say which gains they were recorded with.</source>
        <translation>Ein Szenario dieses Roboters, dessen Reglerverstärkungen die Parameterdatei festhält; die Logs sagen nicht, mit welchen Verstärkungen sie aufgezeichnet wurden.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>armature</source>
        <translation>Rotorträgheit</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>viscous</source>
        <translation>viskos</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Coulomb</source>
        <translation>Coulomb</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>offset</source>
        <translation>Offset</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>Robot:</source>
        <translation>Roboter:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Training logs:</source>
        <translation>Trainings-Logs:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Validation logs:</source>
        <translation>Validierungs-Logs:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Columns:</source>
        <translation>Spalten:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Joint terms:</source>
        <translation>Gelenkterme:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gains from:</source>
        <translation>Verstärkungen aus:</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Add…</source>
        <translation>Hinzufügen…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <location line="+109"/>
        <source>choose the robot&apos;s URDF file</source>
        <translation>die URDF-Datei des Roboters wählen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>add at least one training log (the logs to identify from)</source>
        <translation>mindestens ein Trainings-Log hinzufügen (die Logs, aus denen identifiziert wird)</translation>
    </message>
</context>
<context>
    <name>learnid::ReportWriter</name>
    <message>
        <location filename="../ui/ReportWriter.cpp" line="+56"/>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>learnid commissioning report</source>
        <translation>learnid-Inbetriebnahmebericht</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Commissioning report</source>
        <translation>Inbetriebnahmebericht</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Robot: %1</source>
        <translation>Roboter: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Scenario</source>
        <translation>Szenario</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Parameter convergence</source>
        <translation>Parameterkonvergenz</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Applied set: %1</source>
        <translation>Übertragener Satz: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>learnid %1</source>
        <translation>learnid %1</translation>
    </message>
</context>
<context>
    <name>learnid::RobotChooser</name>
    <message>
        <location filename="../ui/RobotChooser.cpp" line="+36"/>
        <source>Robot model</source>
        <translation>Robotermodell</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Open URDF…</source>
        <translation>URDF öffnen…</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>The paper&apos;s 2-link arm (closed form)</source>
        <translation>2-Glied-Arm aus dem Artikel (geschlossene Form)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (built-in URDF)</source>
        <translation>%1 (eingebautes URDF)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>URDF file…</source>
        <translation>URDF-Datei…</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Joint</source>
        <translation>Gelenk</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Lower</source>
        <translation>Untergrenze</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Upper</source>
        <translation>Obergrenze</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Effort</source>
        <translation>Max. Moment/Kraft</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Mass [kg]</source>
        <translation>Masse [kg]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Position limits in deg (revolute) or m (prismatic), effort in N m or N, as the URDF gives them; the mass of the link the joint moves</source>
        <translation>Positionsgrenzen in deg (Drehgelenk) oder m (Schubgelenk), maximales Moment bzw. maximale Kraft (effort) in N m oder N, wie im URDF angegeben; die Masse des Glieds, das das Gelenk bewegt</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Open the robot&apos;s URDF</source>
        <translation>URDF des Roboters öffnen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>URDF (*.urdf);;All files (*)</source>
        <translation>URDF (*.urdf);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>Cannot use this robot: %1</source>
        <translation>Dieser Roboter ist nicht verwendbar: %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>2 revolute joints in the horizontal plane, no gravity or friction; %1 parameters (the paper&apos;s a, b, c)</source>
        <translation>2 Drehgelenke in der horizontalen Ebene, keine Schwerkraft oder Reibung; %1 Parameter (a, b, c des Artikels)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 (prismatic)</source>
        <translation>%1 (Schubgelenk)</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>rotor inertia</source>
        <translation>Rotorträgheit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>viscous</source>
        <translation>viskos</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Coulomb</source>
        <translation>Coulomb</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>offset</source>
        <translation>Offset</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n revolute joint(s)</source>
        <translation>
            <numerusform>%n Drehgelenk</numerusform>
            <numerusform>%n Drehgelenke</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n joint(s) (%1 prismatic)</source>
        <translation>
            <numerusform>%n Gelenk (%1 prismatisch)</numerusform>
            <numerusform>%n Gelenke (%1 prismatisch)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1, %2 kg moving; joint terms: %3; %4 base parameters (of %5 standard)</source>
        <translation>%1, %2 kg bewegt; Gelenkterme: %3; %4 Basisparameter (von %5 Standardparametern)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
</context>
<context>
    <name>learnid::RobotPanel</name>
    <message>
        <location filename="../ui/RobotPanel.cpp" line="+24"/>
        <source>First commissioning: I confirmed each node&apos;s joint on the arm</source>
        <translation>Erstinbetriebnahme: Ich habe das Gelenk jedes Knotens am Arm geprüft</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+109"/>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <location line="-99"/>
        <source>Simulated (the scenario&apos;s robot)</source>
        <translation>Simuliert (der Roboter des Szenarios)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN (CANopen / CiA 402)</source>
        <translation>CAN (CANopen / CiA 402)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>QCanBus plugin: socketcan for a CAN adapter on Linux; virtualcan to try learnid-robot-sim first</source>
        <translation>QCanBus-Plugin: socketcan für einen CAN-Adapter unter Linux; virtualcan, um zuerst learnid-robot-sim auszuprobieren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>e.g. can0 (socketcan) or tcp://127.0.0.1:35468/can0 (virtualcan)</source>
        <translation>z. B. can0 (socketcan) oder tcp://127.0.0.1:35468/can0 (virtualcan)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CANopen node id of joint 1, 2, ... (docs/can-protocol.md)</source>
        <translation>CANopen-Knoten-ID von Gelenk 1, 2, ... (docs/can-protocol.md)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>10 SYNC periods, at least 50 ms</source>
        <translation>10 SYNC-Perioden, mindestens 50 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A trial stops when no SYNC arrives for this long</source>
        <translation>Ein Versuch endet, wenn so lange kein SYNC eintrifft</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Only for drives never commissioned (or taken from another robot): tick it after checking on the arm that the drive of each node (its serial number on the type plate) moves the joint the node is listed for. Apply then stores the joint identity in the drives, and later sessions check it without this (docs/can-protocol.md 2.4).</source>
        <translation>Nur für Antriebe, die nie in Betrieb genommen wurden (oder aus einem anderen Roboter stammen): erst ankreuzen, nachdem Sie am Arm geprüft haben, dass der Antrieb jedes Knotens (seine Seriennummer auf dem Typenschild) das Gelenk bewegt, für das der Knoten eingetragen ist. Anwenden speichert dann die Gelenkidentität in den Antrieben, und spätere Sitzungen prüfen sie ohne dieses Häkchen (docs/can-protocol.md 2.4).</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Plugin:</source>
        <translation>Plugin:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Interface:</source>
        <translation>Schnittstelle:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nodes:</source>
        <translation>Knoten:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SYNC timeout:</source>
        <translation>SYNC-Zeitlimit:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drives:</source>
        <translation>Antriebe:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Robot:</source>
        <translation>Roboter:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>State:</source>
        <translation>Zustand:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>CAN nodes: %1</source>
        <translation>CAN-Knoten: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CAN nodes: %1 node ids for a robot of %2 joints: one node per joint</source>
        <translation>CAN-Knoten: %1 Knoten-IDs für einen Roboter mit %2 Gelenken: ein Knoten pro Gelenk</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>CAN interface: enter one, e.g. can0</source>
        <translation>CAN-Schnittstelle: bitte eine eingeben, z. B. can0</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Disconnect</source>
        <translation>Trennen</translation>
    </message>
</context>
<context>
    <name>learnid::RunPanel</name>
    <message>
        <location filename="../ui/RunPanel.cpp" line="+27"/>
        <source>%p %</source>
        <translation>%p %</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%v of %m trials</source>
        <translation>%v von %m Versuchen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Trial:</source>
        <translation>Versuch:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Series:</source>
        <translation>Serie:</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>trial %1: %p %</source>
        <translation>Versuch %1: %p %</translation>
    </message>
</context>
<context>
    <name>learnid::ScenarioFields</name>
    <message>
        <location filename="../ui/ScenarioFields.cpp" line="+82"/>
        <source>Start (x, y)</source>
        <translation>Start (x, y)</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>Number of trials</source>
        <translation>Anzahl Versuche</translation>
    </message>
    <message>
        <location line="-26"/>
        <source>Length</source>
        <translation>Länge</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Rest before the motion</source>
        <translation>Ruhezeit vor der Bewegung</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Rest after the motion</source>
        <translation>Ruhezeit nach der Bewegung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Torque limits</source>
        <translation>Momentengrenzen</translation>
    </message>
    <message>
        <location line="-28"/>
        <source>Limit per joint</source>
        <translation>Grenze je Gelenk</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Path</source>
        <translation>Bahn</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Planning fraction</source>
        <translation>Planungsanteil</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Gentle first trials</source>
        <translation>Sanfte erste Versuche</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Gentle trials&apos; speed</source>
        <translation>Geschwindigkeit sanfter Versuche</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Controller</source>
        <translation>Regler</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>lambda (derivative filter)</source>
        <translation>lambda (D-Filter)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Estimator</source>
        <translation>Schätzer</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>rho (filter F)</source>
        <translation>rho (Filter F)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Rank tolerance</source>
        <translation>Rangtoleranz</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Repetitions per trial</source>
        <translation>Wiederholungen pro Versuch</translation>
    </message>
    <message>
        <location line="-56"/>
        <source>Initial parameters</source>
        <translation>Anfangsparameter</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>Safety</source>
        <translation>Sicherheit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Abort at tracking error</source>
        <translation>Abbruch bei Folgefehler</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Required stability margin</source>
        <translation>Geforderte Stabilitätsreserve</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Simulated robot</source>
        <translation>Simulierter Roboter</translation>
    </message>
    <message>
        <location line="-67"/>
        <source>True parameters</source>
        <translation>Wahre Parameter</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>Torque sensor lag</source>
        <translation>Verzögerung des Momentsensors</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>CAD perturbation (URDF robots)</source>
        <translation>CAD-Abweichung (URDF-Roboter)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Encoder counts per revolution (0: ideal)</source>
        <translation>Encoder-Inkremente pro Umdrehung (0: ideal)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Torque noise (fraction of limit)</source>
        <translation>Momentenrauschen (Anteil der Grenze)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Noise seed</source>
        <translation>Startwert des Rauschens</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>RK4 steps per sample</source>
        <translation>RK4-Schritte pro Abtastwert</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>enter a value</source>
        <translation>einen Wert eingeben</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&quot;%1&quot; is not a number</source>
        <translation>„%1“ ist keine Zahl</translation>
    </message>
</context>
<context>
    <name>learnid::ScenarioForm</name>
    <message>
        <location filename="../ui/ScenarioForm.cpp" line="+64"/>
        <location line="+30"/>
        <source>Scenario key %1</source>
        <translation>Szenario-Schlüssel %1</translation>
    </message>
    <message>
        <location line="-28"/>
        <source>URDF robots: empty takes the robot&apos;s</source>
        <translation>URDF-Roboter: leer übernimmt die Werte des Roboters</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>values separated by commas</source>
        <translation>Werte durch Kommas getrennt</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>paper-consistent</source>
        <translation>artikelkonsistent</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>improved (zero-phase, WLS)</source>
        <translation>verbessert (nullphasig, WLS)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Estimator law</source>
        <translation>Lerngesetz</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the drives (motor current)</source>
        <translation>die Antriebe (Motorstrom)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>joint torque sensors behind the gears</source>
        <translation>Gelenkmomentsensoren hinter den Getrieben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Torque measured by</source>
        <translation>Drehmoment gemessen von</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>unknown model &quot;%1&quot;</source>
        <translation>unbekanntes Modell „%1“</translation>
    </message>
    <message numerus="yes">
        <location line="+32"/>
        <source>Initial parameters (%n base parameter(s))</source>
        <translation>
            <numerusform>Anfangsparameter (%n Basisparameter)</numerusform>
            <numerusform>Anfangsparameter (%n Basisparameter)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Initial parameters (%1)</source>
        <translation>Anfangsparameter (%1)</translation>
    </message>
    <message>
        <location line="+13"/>
        <location line="+112"/>
        <source>robot.model: %1</source>
        <translation>robot.model: %1</translation>
    </message>
    <message>
        <location line="-78"/>
        <source>path.file: %1</source>
        <translation>path.file: %1</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>enter one number</source>
        <translation>eine Zahl eingeben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>enter %1 numbers, got %2</source>
        <translation>%1 Zahlen eingeben, erhalten: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>enter a whole number</source>
        <translation>eine ganze Zahl eingeben</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>enter a whole number from %1 to %2</source>
        <translation>eine ganze Zahl von %1 bis %2 eingeben</translation>
    </message>
</context>
<context>
    <name>learnid::SdoClient</name>
    <message>
        <location filename="../core/can/SdoClient.cpp" line="+132"/>
        <source>%1 is not a valid CANopen node id (1 to 127).</source>
        <translation>%1 ist keine gültige CANopen-Knoten-ID (1 bis 127).</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>There are no data to write.</source>
        <translation>Es gibt keine Daten zum Schreiben.</translation>
    </message>
    <message>
        <location line="+34"/>
        <location line="+23"/>
        <source>The answer names another object.</source>
        <translation>Die Antwort nennt ein anderes Objekt.</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>The node announced %1 bytes but sent %2%3.</source>
        <translation>Der Knoten kündigte %1 Bytes an, sandte aber %2%3.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> or more</source>
        <translation> oder mehr</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>SDO read of %1 from node %2</source>
        <translation>SDO-Lesen von %1 aus Knoten %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO write of %1 to node %2</source>
        <translation>SDO-Schreiben von %1 in Knoten %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> (abort code %1)</source>
        <translation> (Abbruchcode %1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The %1 was refused by the node%2: %3</source>
        <translation>%1 wurde vom Knoten abgelehnt%2: %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The %1 was aborted%2: %3</source>
        <translation>%1 wurde abgebrochen%2: %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The %1 failed: %2</source>
        <translation>%1 ist fehlgeschlagen: %2</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>node %1 did not answer within %2 ms.</source>
        <translation>Knoten %1 hat nicht innerhalb von %2 ms geantwortet.</translation>
    </message>
</context>
<context>
    <name>learnid::SessionPresenter</name>
    <message>
        <location filename="../ui/SessionPresenter.cpp" line="+35"/>
        <source>connected: %1</source>
        <translation>verbunden: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+5"/>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>Cannot start the session: %1</source>
        <translation>Sitzung kann nicht gestartet werden: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Connect a robot to plan the first trial.</source>
        <translation>Einen Roboter verbinden, um den ersten Versuch zu planen.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Trial %1 running…</source>
        <translation>Versuch %1 läuft…</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Trial %1 stopped: %2. Learned from its first %3 s (a partial trial); the next trial runs with the new estimate.</source>
        <translation>Versuch %1 gestoppt: %2. Aus seinen ersten %3 s gelernt (ein abgebrochener Versuch); der nächste Versuch läuft mit der neuen Schätzung.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Trial %1: %2.</source>
        <translation>Versuch %1: %2.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Trial %1 %2: %3. Its data are kept.</source>
        <translation>Versuch %1 %2: %3. Seine Daten bleiben erhalten.</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Finished; %1 estimate(s) learned.</source>
        <translation>Fertig; %1 Schätzung(en) gelernt.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stopped; see the message above.</source>
        <translation>Angehalten; siehe Meldung oben.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Estimate %1 accepted.</source>
        <translation>Schätzung %1 akzeptiert.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Parameters written to the robot and read back.</source>
        <translation>Parameter in den Roboter geschrieben und zurückgelesen.</translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/ApplyPreview.cpp" line="+21"/>
        <source>%n parameter(s)</source>
        <translation>
            <numerusform>%n Parameter</numerusform>
            <numerusform>%n Parameter</numerusform>
        </translation>
    </message>
    <message>
        <location filename="../ui/SessionPresenter.cpp" line="+26"/>
        <source>nothing applied yet</source>
        <translation>noch nichts übertragen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (estimate %2)</source>
        <translation>%1 (Schätzung %2)</translation>
    </message>
</context>
<context>
    <name>learnid::SessionWorker</name>
    <message>
        <location filename="../core/service/SessionWorker.cpp" line="+46"/>
        <source>payload: the arm&apos;s session does not learn a payload; learn it in the payload step (Robot &gt; Learn a payload) or with learnid-cli run --scenario FILE</source>
        <translation>payload: die Sitzung des Arms lernt keine Nutzlast; sie im Nutzlast-Schritt lernen (Roboter &gt; Nutzlast lernen) oder mit learnid-cli run --scenario DATEI</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>unknown robot model &quot;%1&quot;</source>
        <translation>unbekanntes Robotermodell „%1“</translation>
    </message>
    <message>
        <location line="+111"/>
        <location line="+26"/>
        <source>no robot connected</source>
        <translation>kein Roboter verbunden</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>no session to export</source>
        <translation>keine Sitzung zum Exportieren</translation>
    </message>
</context>
<context>
    <name>learnid::TorqueFitPlot</name>
    <message>
        <location filename="../ui/TorqueFitPlot.cpp" line="+93"/>
        <source>Identify to see the predicted against the measured torque.</source>
        <translation>Identifizieren, um das vorhergesagte gegenüber dem gemessenen Moment zu sehen.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Time [s]</source>
        <translation>Zeit [s]</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>measured</source>
        <translation>gemessen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>identified</source>
        <translation>identifiziert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>URDF as given</source>
        <translation>URDF wie gegeben</translation>
    </message>
    <message>
        <location line="+83"/>
        <source>All joints</source>
        <translation>Alle Gelenke</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Joint %1 [N m]</source>
        <translation>Gelenk %1 [N m]</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Joint %1</source>
        <translation>Gelenk %1</translation>
    </message>
</context>
<context>
    <name>learnid::TrackingErrorPlot</name>
    <message>
        <location filename="../ui/TrackingErrorPlot.cpp" line="+31"/>
        <source>Auto-scale</source>
        <translation>Automatisch skalieren</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The joint whose tracking error is shown</source>
        <translation>Das Gelenk, dessen Folgefehler angezeigt wird</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Off: symmetric axis on a 0.02 deg grid, as in the paper</source>
        <translation>Aus: symmetrische Achse mit 0,02°-Raster wie im Artikel</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Time [s]</source>
        <translation>Zeit [s]</translation>
    </message>
    <message>
        <location line="+1"/>
        <location filename="../ui/TrackingErrorStyle.cpp" line="+94"/>
        <source>Tracking error [deg]</source>
        <translation>Folgefehler [°]</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Show:</source>
        <translation>Anzeigen:</translation>
    </message>
    <message>
        <location line="+26"/>
        <location line="+63"/>
        <source>All trials (overlay)</source>
        <translation>Alle Versuche (überlagert)</translation>
    </message>
    <message>
        <location line="-39"/>
        <source>All joints</source>
        <translation>Alle Gelenke</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Trial %1</source>
        <translation>Versuch %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Trial %1 (%2)</source>
        <translation>Versuch %1 (%2)</translation>
    </message>
    <message>
        <location line="+97"/>
        <source>Tracking error</source>
        <translation>Folgefehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tracking error of %1</source>
        <translation>Folgefehler von %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1, all trials (darker: later)</source>
        <translation>%1, alle Versuche (dunkler: später)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
    <message>
        <location filename="../ui/TrackingErrorStyle.cpp" line="-41"/>
        <location line="+18"/>
        <source>Joint %1</source>
        <translation>Gelenk %1</translation>
    </message>
    <message>
        <location line="-17"/>
        <source>Joint %1 (%2)</source>
        <translation>Gelenk %1 (%2)</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Error [deg]</source>
        <translation>Fehler [°]</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>[deg]</source>
        <translation>[°]</translation>
    </message>
</context>
<context>
    <name>learnid::TrialStreamer</name>
    <message>
        <location filename="../core/canrobot/TrialStreamer.cpp" line="+32"/>
        <location line="+94"/>
        <location line="+68"/>
        <location filename="../core/canrobot/TrialStreamerSteps.cpp" line="+49"/>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <location line="-149"/>
        <source>%1 did not reach Operation enabled within %2 ms: it reports %3 (statusword 0x%4)</source>
        <translation>%1 erreichte Betrieb freigegeben nicht innerhalb von %2 ms: meldet %3 (Statuswort 0x%4)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no TPDO</source>
        <translation>kein TPDO</translation>
    </message>
    <message>
        <location line="+80"/>
        <source>stopped by the operator %1</source>
        <translation>vom Bediener gestoppt %1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>%1: %2 %3</source>
        <translation>%1: %2 %3</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>%1 left Operation enabled: it reports %2 (0x6041 = 0x%3) %4</source>
        <translation>%1 hat Betrieb freigegeben verlassen: meldet %2 (0x6041 = 0x%3) %4</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>tracking error of %1 reached %2 deg (limit %3 deg) %4: quick stop</source>
        <translation>Folgefehler von %1 erreichte %2° (Grenze %3°) %4: Schnellhalt</translation>
    </message>
    <message>
        <location line="+71"/>
        <source>only %1 of %2 samples were recorded</source>
        <translation>nur %1 von %2 Abtastwerten wurden aufgezeichnet</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>an unknown node</source>
        <translation>ein unbekannter Knoten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>node %1 (joint %2)</source>
        <translation>Knoten %1 (Gelenk %2)</translation>
    </message>
</context>
<context>
    <name>learnid::TrialWatchdog</name>
    <message>
        <location filename="../core/canrobot/TrialWatchdog.cpp" line="+25"/>
        <source>no SYNC for %1 ms: the robot side stopped sending</source>
        <translation>kein SYNC seit %1 ms: die Roboterseite sendet nicht mehr</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>heartbeat of %1 lost: none for %2 ms (timeout %3 ms)</source>
        <translation>Heartbeat von %1 verloren: keiner seit %2 ms (Zeitgrenze %3 ms)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 restarted on its own (boot-up message 0x%2)</source>
        <translation>%1 hat selbst neu gestartet (Boot-up-Nachricht 0x%2)</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>node %1 (joint %2)</source>
        <translation>Knoten %1 (Gelenk %2)</translation>
    </message>
</context>
<context>
    <name>learnid::WaypointEditor</name>
    <message>
        <location filename="../ui/WaypointEditor.cpp" line="+19"/>
        <source>Add waypoint</source>
        <translation>Wegpunkt hinzufügen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove waypoint</source>
        <translation>Wegpunkt entfernen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Path CSV…</source>
        <translation>Bahn-CSV…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Waypoints</source>
        <translation>Wegpunkte</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Run a recorded joint path instead: CSV t, q1..qn [s, rad]</source>
        <translation>Stattdessen eine aufgezeichnete Gelenkbahn fahren: CSV t, q1..qn [s, rad]</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Open a joint path</source>
        <translation>Gelenkbahn öffnen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV (*.csv);;All files (*)</source>
        <translation>CSV (*.csv);;Alle Dateien (*)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Joint positions the path passes through, in order: degrees for revolute joints, metres for prismatic ones</source>
        <translation>Gelenkstellungen, die die Bahn der Reihe nach durchläuft: Grad für Drehgelenke, Meter für Schubgelenke</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>q%1 [%2]</source>
        <translation>q%1 [%2]</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>deg</source>
        <translation>deg</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Path: %1 (%2 samples)</source>
        <translation>Bahn: %1 (%2 Abtastwerte)</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>waypoint %1, %2: &quot;%3&quot; is not a number</source>
        <translation>Wegpunkt %1, %2: „%3“ ist keine Zahl</translation>
    </message>
</context>
<context>
    <name>learnid::robotsim::SimProcess</name>
    <message>
        <location filename="../app/robot-sim/SimProcess.cpp" line="+44"/>
        <source>learnid-robot-sim: stopping (%1)</source>
        <translation>learnid-robot-sim: wird beendet (%1)</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+101"/>
        <source>cannot connect the CAN interface %1 with plugin %2: %3</source>
        <translation>die CAN-Schnittstelle %1 mit Plugin %2 kann nicht verbunden werden: %3</translation>
    </message>
    <message>
        <location line="-67"/>
        <location line="+17"/>
        <location line="+80"/>
        <source>learnid-robot-sim: error: %1</source>
        <translation>learnid-robot-sim: Fehler: %1</translation>
    </message>
    <message>
        <location line="-90"/>
        <source>learnid-robot-sim: error: cannot create the CAN device %1 with plugin %2: %3</source>
        <translation>learnid-robot-sim: Fehler: das CAN-Gerät %1 mit Plugin %2 kann nicht angelegt werden: %3</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>learnid-robot-sim: error: --payload-off: the scenario has no payload section</source>
        <translation>learnid-robot-sim: Fehler: --payload-off: das Szenario hat keinen payload-Abschnitt</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+58"/>
        <source>learnid-robot-sim: error: --state: %1</source>
        <translation>learnid-robot-sim: Fehler: --state: %1</translation>
    </message>
    <message>
        <location line="-51"/>
        <source>learnid-robot-sim: silent after %1 frames (injected fault)</source>
        <translation>learnid-robot-sim: still nach %1 Frames (eingespeister Fehler)</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>the CAN device %1 disconnected</source>
        <translation>das CAN-Gerät %1 hat die Verbindung getrennt</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>learnid-robot-sim: CAN device error: %1</source>
        <translation>learnid-robot-sim: Fehler des CAN-Geräts: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the CAN interface %1 with plugin %2 did not connect within %3 s</source>
        <translation>die CAN-Schnittstelle %1 mit Plugin %2 hat sich nicht innerhalb von %3 s verbunden</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>learnid-robot-sim: unknown command &apos;%1&apos; on stdin (mount, unmount)</source>
        <translation>learnid-robot-sim: unbekannter Befehl &apos;%1&apos; auf stdin (mount, unmount)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>learnid-robot-sim: %1: the scenario has no payload section</source>
        <translation>learnid-robot-sim: %1: das Szenario hat keinen payload-Abschnitt</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/StartOptions.cpp" line="+67"/>
        <source>Commissioning tool: learning identification of robot dynamics.</source>
        <translation>Inbetriebnahmewerkzeug: lernende Identifikation der Roboterdynamik.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The window needs a display; learnid-cli works without one.</source>
        <translation>Das Fenster braucht einen Bildschirm; learnid-cli arbeitet ohne.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Run a simulated session, save the window as PNG to &lt;file&gt; and exit.</source>
        <translation>Eine simulierte Sitzung ausführen, das Fenster als PNG nach &lt;file&gt; speichern und beenden.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>User interface language, e.g. de or zh_CN (default: as chosen in the app, else the system&apos;s).</source>
        <translation>Sprache der Oberfläche, z. B. de oder zh_CN (Standard: wie in der Anwendung gewählt, sonst die des Systems).</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>What --screenshot shows: %1 (default: main).</source>
        <translation>Was --screenshot zeigt: %1 (Standard: main).</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Open the scenario &lt;file&gt; at start.</source>
        <translation>Das Szenario &lt;file&gt; beim Start öffnen.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A scenario file to open at start (as --scenario).</source>
        <translation>Eine Szenariodatei, die beim Start geöffnet wird (wie --scenario).</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>learnid: unknown --screenshot-view &apos;%1&apos;; known: %2</source>
        <translation>learnid: unbekannte --screenshot-view &apos;%1&apos;; bekannt: %2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>learnid: one scenario at a time, got %1: %2</source>
        <translation>learnid: nur ein Szenario auf einmal, erhalten %1: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>learnid: the window needs a display, and none is set (DISPLAY, WAYLAND_DISPLAY); learnid --help lists the options, learnid-cli works without a display.</source>
        <translation>learnid: Das Fenster braucht einen Bildschirm, und keiner ist gesetzt (DISPLAY, WAYLAND_DISPLAY); learnid --help listet die Optionen, learnid-cli arbeitet ohne Bildschirm.</translation>
    </message>
</context>
</TS>
