<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en">
<context>
    <name>LogIdentificationSummary</name>
    <message numerus="yes">
        <location filename="../core/service/LogIdentificationSummary.cpp" line="+26"/>
        <source>Of the %1 standard parameters, any data could determine at most %2 combinations (the base parameters); these logs determine %3 of those %2 directions (condition %4), the other %n stay near the URDF&apos;s values.</source>
        <translation>
            <numerusform>Of the %1 standard parameters, any data could determine at most %2 combinations (the base parameters); these logs determine %3 of those %2 directions (condition %4), the other %n direction stays near the URDF&apos;s values.</numerusform>
            <numerusform>Of the %1 standard parameters, any data could determine at most %2 combinations (the base parameters); these logs determine %3 of those %2 directions (condition %4), the other %n stay near the URDF&apos;s values.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>%n of the %1 base parameters are mostly undetermined by these logs (less than half determined) and kept near the URDF&apos;s values: %2.</source>
        <translation>
            <numerusform>%n of the %1 base parameters is mostly undetermined by these logs (less than half determined) and kept near the URDF&apos;s values: %2.</numerusform>
            <numerusform>%n of the %1 base parameters are mostly undetermined by these logs (less than half determined) and kept near the URDF&apos;s values: %2.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+9"/>
        <source>None of the %1 base parameters is mostly undetermined by these logs: the %n direction(s) they miss are shared among several.</source>
        <translation>
            <numerusform>None of the %1 base parameters is mostly undetermined by these logs: the %n direction they miss is shared among several.</numerusform>
            <numerusform>None of the %1 base parameters is mostly undetermined by these logs: the %n directions they miss are shared among several.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>%n stale row(s) (values repeated under a new time stamp) treated as missing</source>
        <translation>
            <numerusform>%n stale row (values repeated under a new time stamp) treated as missing</numerusform>
            <numerusform>%n stale rows (values repeated under a new time stamp) treated as missing</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%n row(s) written twice (the same time stamp and values) dropped</source>
        <translation>
            <numerusform>%n row written twice (the same time stamp and values) dropped</numerusform>
            <numerusform>%n rows written twice (the same time stamp and values) dropped</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+24"/>
        <source>%1 in %2, %n moving joint(s).</source>
        <translation>
            <numerusform>%1 in %2, %n moving joint.</numerusform>
            <numerusform>%1 in %2, %n moving joints.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%1 (built-in), %n moving joint(s).</source>
        <translation>
            <numerusform>%1 (built-in), %n moving joint.</numerusform>
            <numerusform>%1 (built-in), %n moving joints.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Fitted to %n log(s), %1 samples; %2.</source>
        <translation>
            <numerusform>Fitted to %n log, %1 samples; %2.</numerusform>
            <numerusform>Fitted to %n logs, %1 samples; %2.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>LogIdentificationText</name>
    <message numerus="yes">
        <location filename="../ui/LogIdentificationText.cpp" line="+62"/>
        <source>Fitting the parameters to %n log(s)…</source>
        <translation>
            <numerusform>Fitting the parameters to %n log…</numerusform>
            <numerusform>Fitting the parameters to %n logs…</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>PayloadRunExport</name>
    <message numerus="yes">
        <location filename="../core/service/PayloadRunExport.cpp" line="+41"/>
        <source>%1 with a payload on %2 learned in %n trial(s) with the arm&apos;s model held fixed</source>
        <translation>
            <numerusform>%1 with a payload on %2 learned in %n trial with the arm&apos;s model held fixed</numerusform>
            <numerusform>%1 with a payload on %2 learned in %n trials with the arm&apos;s model held fixed</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>PayloadText</name>
    <message numerus="yes">
        <location filename="../ui/PayloadText.cpp" line="+47"/>
        <source>%n payload trial(s), no baseline trial.</source>
        <translation>
            <numerusform>%n payload trial, no baseline trial.</numerusform>
            <numerusform>%n payload trials, no baseline trial.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>PlausibleEstimate</name>
    <message numerus="yes">
        <location filename="../core/model/PlausibleEstimate.cpp" line="+190"/>
        <source>%n Newton step(s)</source>
        <translation>
            <numerusform>%n Newton step</numerusform>
            <numerusform>%n Newton steps</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>RobotLogCsv</name>
    <message numerus="yes">
        <location filename="../core/io/RobotLogCsv.cpp" line="+342"/>
        <source> (and %n stale row(s): values repeated under a new time stamp, treated as missing)</source>
        <translation>
            <numerusform> (and %n stale row: values repeated under a new time stamp, treated as missing)</numerusform>
            <numerusform> (and %n stale rows: values repeated under a new time stamp, treated as missing)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>TrialResult</name>
    <message numerus="yes">
        <location filename="../core/session/TrialResult.cpp" line="+36"/>
        <source>%n set-point(s) reached the drives after their SYNC (statusword bit 12): the drives held the previous one, so this trial&apos;s motion is not quite the plan&apos;s and neither is what it teaches; close other programs on this computer</source>
        <translation>
            <numerusform>%n set-point reached the drives after their SYNC (statusword bit 12): the drives held the previous one, so this trial&apos;s motion is not quite the plan&apos;s and neither is what it teaches; close other programs on this computer</numerusform>
            <numerusform>%n set-points reached the drives after their SYNC (statusword bit 12): the drives held the previous one, so this trial&apos;s motion is not quite the plan&apos;s and neither is what it teaches; close other programs on this computer</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>learnid-cli</name>
    <message numerus="yes">
        <location filename="../app/cli/IdentifyCommand.cpp" line="+116"/>
        <source>fitting %1 standard parameters to %n log(s)</source>
        <translation>
            <numerusform>fitting %1 standard parameters to %n log</numerusform>
            <numerusform>fitting %1 standard parameters to %n logs</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../app/cli/PayloadCommand.cpp" line="+93"/>
        <source>Fitted to %n log(s), %1 samples: %2 of 10 directions determined (condition %3).
</source>
        <translation>
            <numerusform>Fitted to %n log, %1 samples: %2 of 10 directions determined (condition %3).
</numerusform>
            <numerusform>Fitted to %n logs, %1 samples: %2 of 10 directions determined (condition %3).
</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>learnid::FileController</name>
    <message numerus="yes">
        <location filename="../ui/FileController.cpp" line="+59"/>
        <source>%n trial CSV file(s) written to %1</source>
        <translation>
            <numerusform>%n trial CSV file written to %1</numerusform>
            <numerusform>%n trial CSV files written to %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/ReportContent.cpp" line="+42"/>
        <source>Path: %n joint waypoint(s)</source>
        <translation>
            <numerusform>Path: %n joint waypoint</numerusform>
            <numerusform>Path: %n joint waypoints</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>learnid::PayloadDialog</name>
    <message numerus="yes">
        <location filename="../ui/PayloadDialog.cpp" line="+361"/>
        <source>Take the payload off %1 for the %n baseline trial(s), then press Continue.</source>
        <translation>
            <numerusform>Take the payload off %1 for the %n baseline trial, then press Continue.</numerusform>
            <numerusform>Take the payload off %1 for the %n baseline trials, then press Continue.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../ui/PayloadDialogExport.cpp" line="+192"/>
        <source>Written: %1 and %n trial CSV(s) in %2</source>
        <translation>
            <numerusform>Written: %1 and %n trial CSV in %2</numerusform>
            <numerusform>Written: %1 and %n trial CSVs in %2</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>Written: %1 and %n trial CSV(s) in %2, of a run that ended early: %3</source>
        <translation>
            <numerusform>Written: %1 and %n trial CSV in %2, of a run that ended early: %3</numerusform>
            <numerusform>Written: %1 and %n trial CSVs in %2, of a run that ended early: %3</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>learnid::RobotChooser</name>
    <message numerus="yes">
        <location filename="../ui/RobotChooser.cpp" line="+174"/>
        <source>%n revolute joint(s)</source>
        <translation>
            <numerusform>%n revolute joint</numerusform>
            <numerusform>%n revolute joints</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n joint(s) (%1 prismatic)</source>
        <translation>
            <numerusform>%n joint (%1 prismatic)</numerusform>
            <numerusform>%n joints (%1 prismatic)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>learnid::ScenarioForm</name>
    <message numerus="yes">
        <location filename="../ui/ScenarioForm.cpp" line="+148"/>
        <source>Initial parameters (%n base parameter(s))</source>
        <translation>
            <numerusform>Initial parameters (%n base parameter)</numerusform>
            <numerusform>Initial parameters (%n base parameters)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>learnid::SessionPresenter</name>
    <message numerus="yes">
        <location filename="../ui/ApplyPreview.cpp" line="+21"/>
        <source>%n parameter(s)</source>
        <translation>
            <numerusform>%n parameter</numerusform>
            <numerusform>%n parameters</numerusform>
        </translation>
    </message>
</context>
</TS>
