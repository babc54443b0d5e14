<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>learnid::ApplyConfirmDialog</name>
    <message>
        <source>Apply parameters to the robot</source>
        <translation>Parameter auf den Roboter übertragen</translation>
    </message>
    <message>
        <source>Write estimate %1 to the robot controller? The controller's feedforward changes at once.</source>
        <translation>Schätzung %1 in die Robotersteuerung schreiben? Die Vorsteuerung der Steuerung ändert sich sofort.</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>On robot</source>
        <translation>Auf dem Roboter</translation>
    </message>
    <message>
        <source>New</source>
        <translation>Neu</translation>
    </message>
    <message>
        <source>Change</source>
        <translation>Änderung</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Apply to robot</source>
        <translation>Auf Roboter übertragen</translation>
    </message>
</context>
<context>
    <name>learnid::ApplyPanel</name>
    <message>
        <source>estimate </source>
        <translation>Schätzung </translation>
    </message>
    <message>
        <source>Choose:</source>
        <translation>Auswahl:</translation>
    </message>
    <message>
        <source>Accepted:</source>
        <translation>Akzeptiert:</translation>
    </message>
    <message>
        <source>Robot holds:</source>
        <translation>Roboter hat:</translation>
    </message>
    <message>
        <source>nothing applied yet</source>
        <translation>noch nichts übertragen</translation>
    </message>
    <message>
        <source>estimate %1</source>
        <translation>Schätzung %1</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
</context>
<context>
    <name>learnid::ConvergenceChart</name>
    <message>
        <source>Estimate k</source>
        <translation>Schätzung k</translation>
    </message>
    <message>
        <source>|error| [%]</source>
        <translation>|Fehler| [%]</translation>
    </message>
    <message>
        <source>change [%]</source>
        <translation>Änderung [%]</translation>
    </message>
    <message>
        <source>Convergence to the truth</source>
        <translation>Konvergenz zum wahren Wert</translation>
    </message>
    <message>
        <source>Convergence</source>
        <translation>Konvergenz</translation>
    </message>
</context>
<context>
    <name>learnid::ConvergenceTableModel</name>
    <message>
        <source>all (rank %1)</source>
        <translation>alle (Rang %1)</translation>
    </message>
    <message>
        <source>⚠ kept: %1</source>
        <translation>⚠ beibehalten: %1</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>accepted</source>
        <translation>akzeptiert</translation>
    </message>
    <message>
        <source>on robot</source>
        <translation>auf dem Roboter</translation>
    </message>
    <message>
        <source>%1 = %2 ± %3 (1 sigma)</source>
        <translation>%1 = %2 ± %3 (1 Sigma)</translation>
    </message>
    <message>
        <source>Estimate</source>
        <translation>Schätzung</translation>
    </message>
    <message>
        <source>Rel. change [%]</source>
        <translation>Rel. Änderung [%]</translation>
    </message>
    <message>
        <source>Max |e| [deg]</source>
        <translation>Max. |e| [°]</translation>
    </message>
    <message>
        <source>cond(WᵀW)</source>
        <translation>cond(WᵀW)</translation>
    </message>
    <message>
        <source>Observable</source>
        <translation>Beobachtbar</translation>
    </message>
    <message>
        <source>%1 vs truth [%]</source>
        <translation>%1 ggü. wahrem Wert [%]</translation>
    </message>
    <message>
        <source>Trials run</source>
        <translation>Versuche</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Status</translation>
    </message>
</context>
<context>
    <name>learnid::FileController</name>
    <message>
        <source>Parameter file written: %1</source>
        <translation>Parameterdatei geschrieben: %1</translation>
    </message>
    <message>
        <source>Parameter file not written: %1</source>
        <translation>Parameterdatei nicht geschrieben: %1</translation>
    </message>
    <message>
        <source>Open scenario</source>
        <translation>Szenario öffnen</translation>
    </message>
    <message>
        <source>Scenario files (*.json);;All files (*)</source>
        <translation>Szenariodateien (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Save scenario</source>
        <translation>Szenario speichern</translation>
    </message>
    <message>
        <source>Scenario files (*.json)</source>
        <translation>Szenariodateien (*.json)</translation>
    </message>
    <message>
        <source>Export parameter file</source>
        <translation>Parameterdatei exportieren</translation>
    </message>
    <message>
        <source>Parameter files (*.json)</source>
        <translation>Parameterdateien (*.json)</translation>
    </message>
    <message>
        <source>Folder for the trial CSV files</source>
        <translation>Ordner für die CSV-Dateien der Versuche</translation>
    </message>
    <message>
        <source>Export plot</source>
        <translation>Diagramm exportieren</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg)</source>
        <translation>PNG-Bild (*.png);;SVG-Zeichnung (*.svg)</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>PNG-Bild (*.png)</translation>
    </message>
    <message>
        <source>Export commissioning report</source>
        <translation>Inbetriebnahmebericht exportieren</translation>
    </message>
    <message>
        <source>PDF (*.pdf)</source>
        <translation>PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Scenario loaded: %1</source>
        <translation>Szenario geladen: %1</translation>
    </message>
    <message>
        <source>Scenario not loaded: %1</source>
        <translation>Szenario nicht geladen: %1</translation>
    </message>
    <message>
        <source>Scenario not saved: %1</source>
        <translation>Szenario nicht gespeichert: %1</translation>
    </message>
    <message>
        <source>Scenario saved: %1</source>
        <translation>Szenario gespeichert: %1</translation>
    </message>
    <message>
        <source>Parameter file not written: accept an estimate first</source>
        <translation>Parameterdatei nicht geschrieben: zuerst eine Schätzung akzeptieren</translation>
    </message>
    <message>
        <source>No trial CSV written: no trial has run yet</source>
        <translation>Keine Versuchs-CSV geschrieben: noch kein Versuch gelaufen</translation>
    </message>
    <message>
        <source>cannot create the folder %1</source>
        <translation>Ordner %1 kann nicht angelegt werden</translation>
    </message>
    <message numerus="yes">
        <source>%n trial CSV file(s) written to %1</source>
        <translation>
            <numerusform>%n Versuchs-CSV-Datei nach %1 geschrieben</numerusform><numerusform>%n Versuchs-CSV-Dateien nach %1 geschrieben</numerusform></translation>
    </message>
    <message>
        <source>Trial CSV not written: %1</source>
        <translation>Versuchs-CSV nicht geschrieben: %1</translation>
    </message>
    <message>
        <source>Plot not written: this build has no SVG support (Qt6::Svg); export as PNG instead</source>
        <translation>Diagramm nicht geschrieben: diese Version kann kein SVG (Qt6::Svg); bitte als PNG exportieren</translation>
    </message>
    <message>
        <source>Tracking error</source>
        <translation>Folgefehler</translation>
    </message>
    <message>
        <source>Plot written: %1</source>
        <translation>Diagramm geschrieben: %1</translation>
    </message>
    <message>
        <source>Plot not written: %1</source>
        <translation>Diagramm nicht geschrieben: %1</translation>
    </message>
    <message>
        <source>Report not written: no session</source>
        <translation>Bericht nicht geschrieben: keine Sitzung</translation>
    </message>
    <message>
        <source>Path: from (%1, %2) m, %3 m at %4 deg</source>
        <translation>Bahn: ab (%1, %2) m, %3 m unter %4°</translation>
    </message>
    <message>
        <source>Torque limits: %1 N m, planning fraction %2</source>
        <translation>Momentengrenzen: %1 N m, Planungsanteil %2</translation>
    </message>
    <message>
        <source>kp: %1 N m/rad; ki: %2</source>
        <translation>kp: %1 N m/rad; ki: %2</translation>
    </message>
    <message>
        <source>kd: %1 N m s/rad; lambda %2 rad/s</source>
        <translation>kd: %1 N m s/rad; lambda %2 rad/s</translation>
    </message>
    <message>
        <source>Estimator: %1, rho %2 rad/s, %3 trials</source>
        <translation>Schätzer: %1, rho %2 rad/s, %3 Versuche</translation>
    </message>
    <message>
        <source>Initial parameters: %1</source>
        <translation>Anfangsparameter: %1</translation>
    </message>
    <message>
        <source>none (nothing applied in this session)</source>
        <translation>keine (in dieser Sitzung nichts übertragen)</translation>
    </message>
    <message>
        <source>%1 (estimate %2)</source>
        <translation>%1 (Schätzung %2)</translation>
    </message>
    <message>
        <source>Report written: %1</source>
        <translation>Bericht geschrieben: %1</translation>
    </message>
    <message>
        <source>Report not written: %1</source>
        <translation>Bericht nicht geschrieben: %1</translation>
    </message>
</context>
<context>
    <name>learnid::MainActions</name>
    <message>
        <source>&amp;Connect robot</source>
        <translation>Roboter &amp;verbinden</translation>
    </message>
    <message>
        <source>Ctrl+K</source>
        <translation>Ctrl+K</translation>
    </message>
    <message>
        <source>Connect to the chosen robot and plan the first trial</source>
        <translation>Mit dem gewählten Roboter verbinden und den ersten Versuch planen</translation>
    </message>
    <message>
        <source>&amp;New session</source>
        <translation>&amp;Neue Sitzung</translation>
    </message>
    <message>
        <source>Start a new session with the settings of the form (the history is discarded)</source>
        <translation>Neue Sitzung mit den Einstellungen des Formulars beginnen (der Verlauf wird verworfen)</translation>
    </message>
    <message>
        <source>&amp;Open scenario...</source>
        <translation>Szenario ö&amp;ffnen...</translation>
    </message>
    <message>
        <source>Load a scenario file into the form</source>
        <translation>Eine Szenariodatei in das Formular laden</translation>
    </message>
    <message>
        <source>&amp;Save scenario...</source>
        <translation>Szenario &amp;speichern...</translation>
    </message>
    <message>
        <source>Save the form's scenario to a file</source>
        <translation>Das Szenario des Formulars in eine Datei speichern</translation>
    </message>
    <message>
        <source>Export &amp;parameter file...</source>
        <translation>&amp;Parameterdatei exportieren...</translation>
    </message>
    <message>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <source>Write the accepted estimate as a parameter file (JSON and DCF)</source>
        <translation>Die akzeptierte Schätzung als Parameterdatei schreiben (JSON und DCF)</translation>
    </message>
    <message>
        <source>Export trial &amp;CSV...</source>
        <translation>Versuchs-&amp;CSV exportieren...</translation>
    </message>
    <message>
        <source>Ctrl+Shift+E</source>
        <translation>Ctrl+Shift+E</translation>
    </message>
    <message>
        <source>Write one CSV file per trial</source>
        <translation>Eine CSV-Datei je Versuch schreiben</translation>
    </message>
    <message>
        <source>Export p&amp;lot...</source>
        <translation>&amp;Diagramm exportieren...</translation>
    </message>
    <message>
        <source>Ctrl+Shift+P</source>
        <translation>Ctrl+Shift+P</translation>
    </message>
    <message>
        <source>Save the tracking-error plot as PNG or SVG</source>
        <translation>Das Folgefehler-Diagramm als PNG oder SVG speichern</translation>
    </message>
    <message>
        <source>Save the tracking-error plot as PNG (SVG needs Qt6::Svg)</source>
        <translation>Das Folgefehler-Diagramm als PNG speichern (SVG braucht Qt6::Svg)</translation>
    </message>
    <message>
        <source>Export &amp;report (PDF)...</source>
        <translation>&amp;Bericht exportieren (PDF)...</translation>
    </message>
    <message>
        <source>Write the one-page commissioning report</source>
        <translation>Den einseitigen Inbetriebnahmebericht schreiben</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>Quit learnid</source>
        <translation>learnid beenden</translation>
    </message>
    <message>
        <source>&amp;Run trial</source>
        <translation>Versuch &amp;starten</translation>
    </message>
    <message>
        <source>Run the next trial and learn from it</source>
        <translation>Den nächsten Versuch fahren und daraus lernen</translation>
    </message>
    <message>
        <source>Run &amp;all</source>
        <translation>&amp;Alle starten</translation>
    </message>
    <message>
        <source>Ctrl+F5</source>
        <translation>Ctrl+F5</translation>
    </message>
    <message>
        <source>Run the scenario's number of trials</source>
        <translation>Die im Szenario festgelegte Zahl von Versuchen fahren</translation>
    </message>
    <message>
        <source>&amp;Stop</source>
        <translation>&amp;Stopp</translation>
    </message>
    <message>
        <source>Shift+F5</source>
        <translation>Shift+F5</translation>
    </message>
    <message>
        <source>Stop the running trial safely at the next sample</source>
        <translation>Den laufenden Versuch beim nächsten Abtastschritt sicher anhalten</translation>
    </message>
    <message>
        <source>A&amp;ccept</source>
        <translation>A&amp;kzeptieren</translation>
    </message>
    <message>
        <source>Ctrl+Return</source>
        <translation>Ctrl+Return</translation>
    </message>
    <message>
        <source>Accept the chosen estimate for apply</source>
        <translation>Die gewählte Schätzung zum Übertragen akzeptieren</translation>
    </message>
    <message>
        <source>A&amp;pply...</source>
        <translation>Ü&amp;bertragen...</translation>
    </message>
    <message>
        <source>Ctrl+Shift+A</source>
        <translation>Ctrl+Shift+A</translation>
    </message>
    <message>
        <source>Write the accepted estimate to the robot controller</source>
        <translation>Die akzeptierte Schätzung in die Robotersteuerung schreiben</translation>
    </message>
    <message>
        <source>Re&amp;vert</source>
        <translation>&amp;Zurücksetzen</translation>
    </message>
    <message>
        <source>Ctrl+Shift+Z</source>
        <translation>Ctrl+Shift+Z</translation>
    </message>
    <message>
        <source>Restore the parameter set the robot held before the last apply</source>
        <translation>Den Parametersatz vor der letzten Übertragung wiederherstellen</translation>
    </message>
    <message>
        <source>&amp;About learnid</source>
        <translation>Ü&amp;ber learnid</translation>
    </message>
    <message>
        <source>Version and licence</source>
        <translation>Version und Lizenz</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>Über &amp;Qt</translation>
    </message>
    <message>
        <source>Qt version</source>
        <translation>Qt-Version</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>Systemsprache</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Robot</source>
        <translation>&amp;Roboter</translation>
    </message>
    <message>
        <source>&amp;Trials</source>
        <translation>&amp;Versuche</translation>
    </message>
    <message>
        <source>&amp;Parameters</source>
        <translation>&amp;Parameter</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
</context>
<context>
    <name>learnid::MainWindow</name>
    <message>
        <source>learnid – commissioning</source>
        <translation>learnid – Inbetriebnahme</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>Haupt</translation>
    </message>
    <message>
        <source>Pre-trial check</source>
        <translation>Prüfung vor dem Versuch</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Ausführen</translation>
    </message>
    <message>
        <source>Accept / apply</source>
        <translation>Akzeptieren / übertragen</translation>
    </message>
    <message>
        <source>Robot</source>
        <translation>Roboter</translation>
    </message>
    <message>
        <source>Scenario</source>
        <translation>Szenario</translation>
    </message>
    <message>
        <source>Setup</source>
        <translation>Einrichtung</translation>
    </message>
    <message>
        <source>Parameter convergence</source>
        <translation>Parameterkonvergenz</translation>
    </message>
    <message>
        <source>The language changes when learnid is started again.</source>
        <translation>Die Sprache wechselt beim nächsten Start von learnid.</translation>
    </message>
    <message>
        <source>Dis&amp;connect robot</source>
        <translation>Roboter &amp;trennen</translation>
    </message>
    <message>
        <source>&amp;Connect robot</source>
        <translation>Roboter &amp;verbinden</translation>
    </message>
    <message>
        <source>Run disabled: %1</source>
        <translation>Start gesperrt: %1</translation>
    </message>
    <message>
        <source>no robot</source>
        <translation>kein Roboter</translation>
    </message>
    <message>
        <source>Robot: %1 – %2</source>
        <translation>Roboter: %1 – %2</translation>
    </message>
    <message>
        <source>busy</source>
        <translation>beschäftigt</translation>
    </message>
    <message>
        <source>idle</source>
        <translation>bereit</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
    <message>
        <source>Correct the scenario first: %1</source>
        <translation>Zuerst das Szenario korrigieren: %1</translation>
    </message>
    <message>
        <source>Apply cancelled; the robot is unchanged.</source>
        <translation>Übertragen abgebrochen; der Roboter ist unverändert.</translation>
    </message>
    <message>
        <source>About learnid</source>
        <translation>Über learnid</translation>
    </message>
    <message>
        <source>&lt;h3&gt;learnid %1&lt;/h3&gt;&lt;p&gt;Learning identification of robot dynamics: a commissioning tool.&lt;/p&gt;&lt;p&gt;Built with Qt %2.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;learnid %1&lt;/h3&gt;&lt;p&gt;Lernende Identifikation der Roboterdynamik: ein Inbetriebnahmewerkzeug.&lt;/p&gt;&lt;p&gt;Erstellt mit Qt %2.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>learnid::MessageBar</name>
    <message>
        <source>Dismiss</source>
        <translation>Schließen</translation>
    </message>
</context>
<context>
    <name>learnid::PreTrialCheckView</name>
    <message>
        <source>Joint</source>
        <translation>Gelenk</translation>
    </message>
    <message>
        <source>Peak [N m]</source>
        <translation>Spitze [N m]</translation>
    </message>
    <message>
        <source>Limit [N m]</source>
        <translation>Grenze [N m]</translation>
    </message>
    <message>
        <source>Use</source>
        <translation>Auslastung</translation>
    </message>
    <message>
        <source>Planned motion:</source>
        <translation>Geplante Bewegung:</translation>
    </message>
    <message>
        <source>Closed loop:</source>
        <translation>Regelkreis:</translation>
    </message>
    <message>
        <source>Connect a robot to plan the first trial.</source>
        <translation>Einen Roboter verbinden, um den ersten Versuch zu planen.</translation>
    </message>
    <message>
        <source>Trial %1: check passed, the trial may run.</source>
        <translation>Versuch %1: Prüfung bestanden, der Versuch darf laufen.</translation>
    </message>
    <message>
        <source>Trial %1 refused: %2</source>
        <translation>Versuch %1 abgelehnt: %2</translation>
    </message>
    <message>
        <source>no plan</source>
        <translation>kein Plan</translation>
    </message>
    <message>
        <source>%1 s motion, %2 s with rests, %3 samples</source>
        <translation>%1 s Bewegung, %2 s mit Ruhezeiten, %3 Abtastwerte</translation>
    </message>
    <message>
        <source>estimate not physical (mass matrix not positive definite)</source>
        <translation>Schätzung nicht physikalisch (Massenmatrix nicht positiv definit)</translation>
    </message>
    <message>
        <source>stable: max |z| = %1, decay rate %2 1/s</source>
        <translation>stabil: max |z| = %1, Abklingrate %2 1/s</translation>
    </message>
    <message>
        <source>UNSTABLE: max |z| = %1 at t = %2 s (growth %3 1/s)</source>
        <translation>INSTABIL: max |z| = %1 bei t = %2 s (Anstieg %3 1/s)</translation>
    </message>
</context>
<context>
    <name>learnid::ReportWriter</name>
    <message>
        <source>learnid commissioning report</source>
        <translation>learnid-Inbetriebnahmebericht</translation>
    </message>
    <message>
        <source>Commissioning report</source>
        <translation>Inbetriebnahmebericht</translation>
    </message>
    <message>
        <source>Robot: %1</source>
        <translation>Roboter: %1</translation>
    </message>
    <message>
        <source>Scenario</source>
        <translation>Szenario</translation>
    </message>
    <message>
        <source>Parameter convergence</source>
        <translation>Parameterkonvergenz</translation>
    </message>
    <message>
        <source>Applied set: %1</source>
        <translation>Übertragener Satz: %1</translation>
    </message>
    <message>
        <source>learnid %1</source>
        <translation>learnid %1</translation>
    </message>
</context>
<context>
    <name>learnid::RobotPanel</name>
    <message>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <source>Simulated (paper 2-link arm)</source>
        <translation>Simuliert (2-Glied-Arm aus dem Artikel)</translation>
    </message>
    <message>
        <source>CAN (CANopen / CiA 402)</source>
        <translation>CAN (CANopen / CiA 402)</translation>
    </message>
    <message>
        <source>available when the CAN link lands</source>
        <translation>verfügbar, sobald die CAN-Anbindung fertig ist</translation>
    </message>
    <message>
        <source>Simulated robot; CAN: %1</source>
        <translation>Simulierter Roboter; CAN: %1</translation>
    </message>
    <message>
        <source>Robot:</source>
        <translation>Roboter:</translation>
    </message>
    <message>
        <source>State:</source>
        <translation>Zustand:</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Trennen</translation>
    </message>
</context>
<context>
    <name>learnid::RunPanel</name>
    <message>
        <source>%p %</source>
        <translation>%p %</translation>
    </message>
    <message>
        <source>%v of %m trials</source>
        <translation>%v von %m Versuchen</translation>
    </message>
    <message>
        <source>Trial:</source>
        <translation>Versuch:</translation>
    </message>
    <message>
        <source>Series:</source>
        <translation>Serie:</translation>
    </message>
    <message>
        <source>trial %1: %p %</source>
        <translation>Versuch %1: %p %</translation>
    </message>
</context>
<context>
    <name>learnid::ScenarioFields</name>
    <message>
        <source>Start (x, y)</source>
        <translation>Start (x, y)</translation>
    </message>
    <message>
        <source>Number of trials</source>
        <translation>Anzahl Versuche</translation>
    </message>
    <message>
        <source>Path (straight line)</source>
        <translation>Bahn (Gerade)</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Länge</translation>
    </message>
    <message>
        <source>Direction</source>
        <translation>Richtung</translation>
    </message>
    <message>
        <source>Torque limits</source>
        <translation>Momentengrenzen</translation>
    </message>
    <message>
        <source>Limit per joint</source>
        <translation>Grenze je Gelenk</translation>
    </message>
    <message>
        <source>Planning fraction</source>
        <translation>Planungsanteil</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>Regler</translation>
    </message>
    <message>
        <source>lambda (derivative filter)</source>
        <translation>lambda (D-Filter)</translation>
    </message>
    <message>
        <source>Estimator</source>
        <translation>Schätzer</translation>
    </message>
    <message>
        <source>rho (filter F)</source>
        <translation>rho (Filter F)</translation>
    </message>
    <message>
        <source>Initial parameters</source>
        <translation>Anfangsparameter</translation>
    </message>
    <message>
        <source>enter a value</source>
        <translation>einen Wert eingeben</translation>
    </message>
    <message>
        <source>"%1" is not a number</source>
        <translation>„%1“ ist keine Zahl</translation>
    </message>
</context>
<context>
    <name>learnid::ScenarioForm</name>
    <message>
        <source>Scenario key %1</source>
        <translation>Szenario-Schlüssel %1</translation>
    </message>
    <message>
        <source>values separated by commas</source>
        <translation>Werte durch Kommas getrennt</translation>
    </message>
    <message>
        <source>paper-consistent</source>
        <translation>artikelkonsistent</translation>
    </message>
    <message>
        <source>improved (zero-phase, WLS)</source>
        <translation>verbessert (nullphasig, WLS)</translation>
    </message>
    <message>
        <source>Estimator law</source>
        <translation>Lerngesetz</translation>
    </message>
    <message>
        <source>Initial parameters (%1)</source>
        <translation>Anfangsparameter (%1)</translation>
    </message>
    <message>
        <source>enter one number</source>
        <translation>eine Zahl eingeben</translation>
    </message>
    <message>
        <source>enter %1 numbers, got %2</source>
        <translation>%1 Zahlen eingeben, erhalten: %2</translation>
    </message>
    <message>
        <source>enter a whole number</source>
        <translation>eine ganze Zahl eingeben</translation>
    </message>
</context>
<context>
    <name>learnid::SessionPresenter</name>
    <message>
        <source>connected: %1</source>
        <translation>verbunden: %1</translation>
    </message>
    <message>
        <source>not connected</source>
        <translation>nicht verbunden</translation>
    </message>
    <message>
        <source>Cannot start the session: %1</source>
        <translation>Sitzung kann nicht gestartet werden: %1</translation>
    </message>
    <message>
        <source>Connect a robot to plan the first trial.</source>
        <translation>Einen Roboter verbinden, um den ersten Versuch zu planen.</translation>
    </message>
    <message>
        <source>Trial %1 running…</source>
        <translation>Versuch %1 läuft…</translation>
    </message>
    <message>
        <source>Trial %1 %2: %3. Its data are kept.</source>
        <translation>Versuch %1 %2: %3. Seine Daten bleiben erhalten.</translation>
    </message>
    <message>
        <source>Finished; %1 estimate(s) learned.</source>
        <translation>Fertig; %1 Schätzung(en) gelernt.</translation>
    </message>
    <message>
        <source>Stopped; see the message above.</source>
        <translation>Angehalten; siehe Meldung oben.</translation>
    </message>
    <message>
        <source>Estimate %1 accepted.</source>
        <translation>Schätzung %1 akzeptiert.</translation>
    </message>
    <message>
        <source>Parameters written to the robot and read back.</source>
        <translation>Parameter in den Roboter geschrieben und zurückgelesen.</translation>
    </message>
    <message>
        <source>nothing applied yet</source>
        <translation>noch nichts übertragen</translation>
    </message>
    <message>
        <source>%1 (estimate %2)</source>
        <translation>%1 (Schätzung %2)</translation>
    </message>
</context>
<context>
    <name>learnid::SessionWorker</name>
    <message>
        <source>unknown robot model "%1"</source>
        <translation>unbekanntes Robotermodell „%1“</translation>
    </message>
    <message>
        <source>no robot connected</source>
        <translation>kein Roboter verbunden</translation>
    </message>
    <message>
        <source>no session to export</source>
        <translation>keine Sitzung zum Exportieren</translation>
    </message>
</context>
<context>
    <name>learnid::TrackingErrorPlot</name>
    <message>
        <source>Auto-scale</source>
        <translation>Automatisch skalieren</translation>
    </message>
    <message>
        <source>Off: symmetric axis on a 0.02 deg grid, as in the paper</source>
        <translation>Aus: symmetrische Achse mit 0,02°-Raster wie im Artikel</translation>
    </message>
    <message>
        <source>Time [s]</source>
        <translation>Zeit [s]</translation>
    </message>
    <message>
        <source>Tracking error [deg]</source>
        <translation>Folgefehler [°]</translation>
    </message>
    <message>
        <source>Show:</source>
        <translation>Anzeigen:</translation>
    </message>
    <message>
        <source>All trials (overlay)</source>
        <translation>Alle Versuche (überlagert)</translation>
    </message>
    <message>
        <source>Trial %1</source>
        <translation>Versuch %1</translation>
    </message>
    <message>
        <source>Trial %1 (%2)</source>
        <translation>Versuch %1 (%2)</translation>
    </message>
    <message>
        <source>Tracking error, all trials (solid: joint 1, dashed: joint 2; darker: later)</source>
        <translation>Folgefehler, alle Versuche (durchgezogen: Gelenk 1, gestrichelt: Gelenk 2; dunkler: später)</translation>
    </message>
    <message>
        <source>Tracking error, %1</source>
        <translation>Folgefehler, %1</translation>
    </message>
    <message>
        <source>trial %1, joint %2</source>
        <translation>Versuch %1, Gelenk %2</translation>
    </message>
    <message>
        <source>joint %1</source>
        <translation>Gelenk %1</translation>
    </message>
</context>
</TS>
