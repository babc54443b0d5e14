#include "cli/PayloadOptions.h"

#include "cli/CliOptions.h"
#include "model/Error.h"

#include <QCoreApplication>
#include <QStringList>
#include <iterator>
#include <vector>

namespace learnid::cli {

namespace {

// "a,b,c": exactly `count` numbers (NaN is read as a number and refused by the checks later).
std::optional<std::vector<double>> numbers(const QString &text, int count)
{
    const QStringList parts = text.split(QLatin1Char(','));
    if (parts.size() != count)
        return std::nullopt;
    std::vector<double> out;
    for (const QString &part : parts) {
        bool ok = false;
        out.push_back(part.trimmed().toDouble(&ok));
        if (!ok)
            return std::nullopt;
    }
    return out;
}

const char *const payloadOptions[] = {"payload-link",    "payload-mass",   "payload-com",
                                      "payload-inertia", "payload-radius", "payload-box",
                                      "arm-urdf",        "baseline-log"};
constexpr int identifyOnly = 2; // the last two: identify's alone

} // namespace

QList<QCommandLineOption> payloadCliOptions(bool identify)
{
    QList<QCommandLineOption> options{
        cliOption("payload",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "Identify only a payload fixed to the arm, the --robot URDF "
                                    "or parameter file held fixed as the arm's model; needs "
                                    "--payload-mass.")),
        cliOption("payload-link",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "The link the payload is fixed to; default: the tip link."),
                  "LINK"),
        cliOption("payload-mass",
                  QT_TRANSLATE_NOOP("learnid-cli", "Your estimate of the payload's mass [kg]."),
                  "KG"),
        cliOption("payload-com",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "Your estimate of its centre of mass in the link frame [m]; "
                                    "default 0,0,0 (the flange)."),
                  "X,Y,Z"),
        cliOption("payload-inertia",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "Your estimate of its inertia about the centre of mass "
                                    "[kg m^2]; default: a uniform sphere."),
                  "IXX,IXY,IYY,IXZ,IYZ,IZZ"),
        cliOption("payload-radius",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "The payload lies within this distance of the flange [m]; "
                                    "default 0.3."),
                  "M"),
        cliOption("payload-box",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "Or within this box in the link frame [m], instead of the "
                                    "sphere."),
                  "X0,Y0,Z0,X1,Y1,Z1"),
        cliOption("arm-urdf",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "With --payload and a --robot parameter file of a URDF robot: "
                                    "the URDF the arm was identified on."),
                  "FILE"),
        cliOption("baseline-log",
                  QT_TRANSLATE_NOOP("learnid-cli",
                                    "With --payload: a log of the same motion without the payload, "
                                    "whose torque residual is taken out of every --log (may be "
                                    "repeated; docs/payload.md)."),
                  "FILE"),
    };
    if (!identify) {
        options.removeLast();
        options.removeLast();
        options.first() = cliOption(
            "payload", QT_TRANSLATE_NOOP("learnid-cli",
                                         "A scenario that learns a payload fixed to the arm, the "
                                         "gains designed for the arm carrying the prior; needs "
                                         "--payload-mass."));
    }
    return options;
}

PayloadFieldNames payloadOptionNames()
{
    PayloadFieldNames names;
    names.mass = QStringLiteral("--payload-mass");
    names.com = QStringLiteral("--payload-com");
    names.inertia = QStringLiteral("--payload-inertia");
    names.radius = QStringLiteral("--payload-radius");
    names.box = QStringLiteral("--payload-box");
    names.link = QStringLiteral("--payload-link");
    return names;
}

QString readPayloadOptions(const QCommandLineParser &parser, std::optional<PayloadOptions> *payload,
                           bool identify)
{
    const int known = int(std::size(payloadOptions)) - (identify ? 0 : identifyOnly);
    const auto value = [&parser](const char *name) {
        return parser.value(QLatin1String(name));
    };
    const auto isSet = [&parser](const char *name) {
        return parser.isSet(QLatin1String(name));
    };
    if (!isSet("payload")) {
        for (int i = 0; i < known; ++i)
            if (const char *name = payloadOptions[i]; isSet(name))
                return QCoreApplication::translate("learnid-cli", "--%1: needs --payload")
                    .arg(QLatin1String(name));
        return {};
    }
    if (!isSet("payload-mass"))
        return QCoreApplication::translate(
            "learnid-cli",
            "--payload: needs --payload-mass KG, your estimate of the payload's mass");
    if (isSet("payload-radius") && isSet("payload-box"))
        return QCoreApplication::translate(
            "learnid-cli",
            "--payload-box: give either a bounding box or --payload-radius, not both");
    PayloadOptions o;
    o.link = value("payload-link");
    if (identify) {
        o.armUrdf = value("arm-urdf");
        o.baselineLogs = parser.values(QStringLiteral("baseline-log"));
    }
    bool ok = false;
    o.prior.mass = value("payload-mass").trimmed().toDouble(&ok);
    if (!ok)
        return QCoreApplication::translate("learnid-cli",
                                           "--payload-mass: must be a number of kg, got '%1'")
            .arg(value("payload-mass"));
    if (isSet("payload-com")) {
        const auto c = numbers(value("payload-com"), 3);
        if (!c)
            return QCoreApplication::translate(
                       "learnid-cli", "--payload-com: must be three numbers X,Y,Z [m], got '%1'")
                .arg(value("payload-com"));
        o.prior.com = Eigen::Vector3d((*c)[0], (*c)[1], (*c)[2]);
    }
    if (isSet("payload-inertia")) {
        const auto i = numbers(value("payload-inertia"), 6);
        if (!i)
            return QCoreApplication::translate(
                       "learnid-cli",
                       "--payload-inertia: must be six numbers IXX,IXY,IYY,IXZ,IYZ,IZZ [kg m^2], "
                       "got '%1'")
                .arg(value("payload-inertia"));
        Eigen::Matrix3d m;
        m << (*i)[0], (*i)[1], (*i)[3], (*i)[1], (*i)[2], (*i)[4], (*i)[3], (*i)[4], (*i)[5];
        o.prior.inertiaAtCom = m;
    }
    if (isSet("payload-radius")) {
        o.prior.bound.radius = value("payload-radius").trimmed().toDouble(&ok);
        if (!ok)
            return QCoreApplication::translate("learnid-cli",
                                               "--payload-radius: must be a number of m, got '%1'")
                .arg(value("payload-radius"));
    }
    if (isSet("payload-box")) {
        const auto b = numbers(value("payload-box"), 6);
        if (!b)
            return QCoreApplication::translate(
                       "learnid-cli",
                       "--payload-box: must be six numbers X0,Y0,Z0,X1,Y1,Z1 [m], got '%1'")
                .arg(value("payload-box"));
        o.prior.bound.box = true;
        o.prior.bound.lower = Eigen::Vector3d((*b)[0], (*b)[1], (*b)[2]);
        o.prior.bound.upper = Eigen::Vector3d((*b)[3], (*b)[4], (*b)[5]);
    }
    try {
        validatePayloadPrior(o.prior, payloadOptionNames());
    } catch (const Error &e) {
        return e.message();
    }
    *payload = o;
    return {};
}

} // namespace learnid::cli
