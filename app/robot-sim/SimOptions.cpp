#include "robot-sim/SimOptions.h"

#include <QCanBus>
#include <QCommandLineParser>
#include <QCoreApplication>
#include <QSet>
#include <limits>

namespace learnid::robotsim {

namespace {

// Each returns an empty string or the error naming the option and its value.
QString parseNodes(const QString &text, QList<int> *nodes)
{
    nodes->clear();
    QSet<int> seen;
    for (const QString &part : text.split(QLatin1Char(','))) {
        bool ok = false;
        const int id = part.trimmed().toInt(&ok);
        if (!ok || id < 1 || id > 127)
            return QCoreApplication::translate(
                       "learnid-robot-sim",
                       "--nodes: '%1' is not a CANopen node id (1 to 127) in '%2'")
                .arg(part, text);
        if (seen.contains(id))
            return QCoreApplication::translate("learnid-robot-sim",
                                               "--nodes: node %1 is listed twice in '%2'")
                .arg(id)
                .arg(text);
        seen.insert(id);
        nodes->append(id);
    }
    return {};
}

QString parseRefusal(const QString &text, CanSimFaults *faults)
{
    const QStringList parts = text.split(QLatin1Char(':'));
    bool okIndex = false;
    bool okSub = false;
    uint index = 0;
    uint sub = 0;
    if (parts.size() == 2) {
        QString idx = parts[0].trimmed();
        if (idx.startsWith(QLatin1String("0x"), Qt::CaseInsensitive))
            idx = idx.mid(2);
        index = idx.toUInt(&okIndex, 16);
        sub = parts[1].trimmed().toUInt(&okSub, 0);
    }
    if (!okIndex || !okSub || index > 0xFFFF || sub > 0xFF)
        return QCoreApplication::translate(
                   "learnid-robot-sim",
                   "--refuse-sdo: '%1' is not an object address INDEX:SUB such as 0x2200:1 "
                   "(index in hex, sub-index 0 to 255)")
            .arg(text);
    faults->refusedWrite = qMakePair(quint16(index), quint8(sub));
    return {};
}

QString parseInteger(const QString &option, const QString &text, qint64 min, qint64 *out)
{
    bool ok = false;
    const qint64 v = text.trimmed().toLongLong(&ok);
    if (!ok || v < min)
        return QCoreApplication::translate("learnid-robot-sim",
                                           "--%1: '%2' is not a whole number of at least %3")
            .arg(option, text)
            .arg(min);
    *out = v;
    return {};
}

} // namespace

SimCommandLine parseSimCommandLine(const QStringList &arguments)
{
    SimCommandLine cl;
    QCommandLineParser parser;
    parser.setApplicationDescription(QCoreApplication::translate(
        "learnid-robot-sim",
        "The robot on a CAN bus: one simulated CiA 402 drive per joint, the SYNC producer and "
        "the scenario's simulated arm. Prints \"ready\" once connected; runs until SIGINT, "
        "SIGTERM or stdin closes."));
    const QCommandLineOption help(
        QStringList{QStringLiteral("h"), QStringLiteral("help")},
        QCoreApplication::translate("learnid-robot-sim", "Show this help."));
    const QCommandLineOption version(
        QStringLiteral("version"),
        QCoreApplication::translate("learnid-robot-sim", "Show the version."));
    const QCommandLineOption plugin(
        QStringLiteral("can-plugin"),
        QCoreApplication::translate("learnid-robot-sim",
                                    "QCanBus plugin, e.g. socketcan or virtualcan."),
        QCoreApplication::translate("learnid-robot-sim", "plugin"));
    const QCommandLineOption interface(
        QStringLiteral("can-interface"),
        QCoreApplication::translate("learnid-robot-sim",
                                    "CAN interface, e.g. can0 or tcp://127.0.0.1:35468/can0."),
        QCoreApplication::translate("learnid-robot-sim", "interface"));
    const QCommandLineOption nodes(
        QStringLiteral("nodes"),
        QCoreApplication::translate(
            "learnid-robot-sim",
            "Node ids of joint 1, 2, ..., up to 127 (default: joint j is node j)."),
        QCoreApplication::translate("learnid-robot-sim", "ids"));
    const QCommandLineOption scenario(
        QStringLiteral("scenario"),
        QCoreApplication::translate("learnid-robot-sim",
                                    "Scenario file (default: the paper scenario)."),
        QCoreApplication::translate("learnid-robot-sim", "file"));
    const QCommandLineOption state(
        QStringLiteral("state"),
        QCoreApplication::translate("learnid-robot-sim",
                                    "JSON file of the nodes' stored parameters, written at start "
                                    "and after every store."),
        QCoreApplication::translate("learnid-robot-sim", "file"));
    const QCommandLineOption drop(
        QStringLiteral("drop-fraction"),
        QCoreApplication::translate("learnid-robot-sim",
                                    "Fault: lose this fraction (0 to 1) of the TPDOs."),
        QCoreApplication::translate("learnid-robot-sim", "F"));
    const QCommandLineOption silent(
        QStringLiteral("silent-after"),
        QCoreApplication::translate("learnid-robot-sim",
                                    "Fault: send nothing at all after N frames."),
        QCoreApplication::translate("learnid-robot-sim", "N"));
    const QCommandLineOption emcy(
        QStringLiteral("emcy-at-sample"),
        QCoreApplication::translate("learnid-robot-sim",
                                    "Fault: the first node faults with EMCY 0x8611 at the K-th "
                                    "SYNC in Operation enabled."),
        QCoreApplication::translate("learnid-robot-sim", "K"));
    const QCommandLineOption refuse(
        QStringLiteral("refuse-sdo"),
        QCoreApplication::translate("learnid-robot-sim",
                                    "Fault: SDO writes to this object abort with 0x08000020."),
        QCoreApplication::translate("learnid-robot-sim", "IDX:SUB"));
    const QCommandLineOption setPointTimeout(
        QStringLiteral("setpoint-timeout"),
        QCoreApplication::translate(
            "learnid-robot-sim",
            "SYNC periods in Operation enabled without a set-point before a drive faults with "
            "EMCY 0x8100 (default: 3 periods, at least 50 ms)."),
        QCoreApplication::translate("learnid-robot-sim", "N"));
    const QCommandLineOption uncommissioned(
        QStringLiteral("uncommissioned"),
        QCoreApplication::translate("learnid-robot-sim",
                                    "Drives that were never commissioned: 0x2400 is 0 (by default "
                                    "joint j's drive holds the robot's identity and j)."));
    const QCommandLineOption payloadOff(
        QStringLiteral("payload-off"),
        QCoreApplication::translate("learnid-robot-sim",
                                    "The arm starts without the scenario's payload. A line "
                                    "'mount' on stdin mounts it, 'unmount' takes it off (as a "
                                    "technician does around a payload session's baseline "
                                    "trials)."));
    parser.addOptions({help, version, plugin, interface, nodes, scenario, state, drop, silent, emcy,
                       refuse, setPointTimeout, uncommissioned, payloadOff});
    cl.usage = parser.helpText();

    if (!parser.parse(arguments)) {
        cl.error = parser.errorText();
        return cl;
    }
    if (parser.isSet(help)) {
        cl.command = SimCommandLine::Command::Help;
        return cl;
    }
    if (parser.isSet(version)) {
        cl.command = SimCommandLine::Command::Version;
        return cl;
    }
    if (!parser.positionalArguments().isEmpty()) {
        cl.error = QCoreApplication::translate("learnid-robot-sim", "unexpected argument '%1'")
                       .arg(parser.positionalArguments().first());
        return cl;
    }
    SimOptions &o = cl.options;
    o.plugin = parser.value(plugin);
    o.interface = parser.value(interface);
    QString error;
    if (o.plugin.isEmpty())
        error = QCoreApplication::translate("learnid-robot-sim",
                                            "--can-plugin is required (available: %1)")
                    .arg(QCanBus::instance()->plugins().join(QStringLiteral(", ")));
    else if (!QCanBus::instance()->plugins().contains(o.plugin))
        error = QCoreApplication::translate("learnid-robot-sim",
                                            "--can-plugin: unknown plugin '%1' (available: %2)")
                    .arg(o.plugin, QCanBus::instance()->plugins().join(QStringLiteral(", ")));
    else if (o.interface.isEmpty())
        error = QCoreApplication::translate(
            "learnid-robot-sim",
            "--can-interface is required, e.g. can0 or tcp://127.0.0.1:35468/can0");
    if (error.isEmpty() && parser.isSet(nodes))
        error = parseNodes(parser.value(nodes), &o.nodes);
    if (error.isEmpty() && parser.isSet(drop)) {
        bool ok = false;
        const double f = parser.value(drop).trimmed().toDouble(&ok);
        if (!ok || !(f >= 0.0 && f <= 1.0))
            error = QCoreApplication::translate(
                        "learnid-robot-sim", "--drop-fraction: '%1' is not a fraction from 0 to 1")
                        .arg(parser.value(drop));
        o.faults.dropFraction = f;
    }
    if (error.isEmpty() && parser.isSet(silent))
        error = parseInteger(QStringLiteral("silent-after"), parser.value(silent), 0,
                             &o.faults.silentAfterFrames);
    if (error.isEmpty() && parser.isSet(emcy)) {
        qint64 k = 0;
        error = parseInteger(QStringLiteral("emcy-at-sample"), parser.value(emcy), 1, &k);
        if (error.isEmpty() && k > std::numeric_limits<int>::max())
            error = QCoreApplication::translate("learnid-robot-sim",
                                                "--emcy-at-sample: '%1' is too large")
                        .arg(parser.value(emcy));
        o.faults.emcyAtSample = int(k);
    }
    if (error.isEmpty() && parser.isSet(setPointTimeout)) {
        qint64 n = 0;
        error =
            parseInteger(QStringLiteral("setpoint-timeout"), parser.value(setPointTimeout), 1, &n);
        if (error.isEmpty() && n > 100000)
            error =
                QCoreApplication::translate(
                    "learnid-robot-sim", "--setpoint-timeout: '%1' is too large (at most 100000)")
                    .arg(parser.value(setPointTimeout));
        o.setPointTimeoutSyncs = int(n);
    }
    if (error.isEmpty() && parser.isSet(refuse))
        error = parseRefusal(parser.value(refuse), &o.faults);
    o.scenarioPath = parser.value(scenario);
    o.uncommissioned = parser.isSet(uncommissioned);
    o.payloadOff = parser.isSet(payloadOff);
    o.statePath = parser.value(state);
    if (!error.isEmpty()) {
        cl.error = error;
        return cl;
    }
    cl.command = SimCommandLine::Command::Run;
    return cl;
}

} // namespace learnid::robotsim
